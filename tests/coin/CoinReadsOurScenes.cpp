// Coin3D (the Inventor original) reads our scene files with the nodes of issue 10:
// LightModel and ResetTransform as its own SoLightModel and SoResetTransform, OrthoSlice and
// ObliqueSlice as unknown nodes described by their fields declarations. Headless: SoDB only.
// Built only where CMake finds Coin (tests/CMakeLists.txt).
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/SoOutput.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/actions/SoWriteAction.h>
#include <Inventor/fields/SoField.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoResetTransform.h>
#include <Inventor/nodes/SoSeparator.h>

#include <volsg/io/SceneWriter.h>
#include <volsg/nodes/LightModel.h>
#include <volsg/nodes/ObliqueSlice.h>
#include <volsg/nodes/OrthoSlice.h>
#include <volsg/nodes/ResetTransform.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/Transform.h>
#include <volsg/nodes/VolumeData.h>

namespace {

/// Every node under `root` (depth first), as Coin sees them.
std::vector<SoNode*> allNodes(SoNode* root) {
    SoSearchAction search;
    search.setType(SoNode::getClassTypeId());
    search.setInterest(SoSearchAction::ALL);
    search.setSearchingAll(TRUE);
    search.apply(root);
    std::vector<SoNode*> out;
    const SoPathList& paths = search.getPaths();
    for (int i = 0; i < paths.getLength(); ++i)
        out.push_back(paths[i]->getTail());
    return out;
}

std::string fieldText(SoNode* node, const char* name) {
    SoField* field = node->getField(name);
    if (!field) return "<missing>";
    SbString value;
    field->get(value);
    return value.getString();
}

/// Coin's write of a graph, to see the names unknown nodes keep.
std::string writtenByCoin(SoNode* root) {
    SoOutput out;
    out.setBuffer(nullptr, 1, [](void* p, size_t size) { return realloc(p, size); });
    SoWriteAction write(&out);
    write.apply(root);
    void* buffer = nullptr;
    size_t size = 0;
    out.getBuffer(buffer, size);
    std::string text(static_cast<const char*>(buffer), size);
    free(buffer);
    return text;
}

} // namespace

TEST_CASE(
    "Coin reads LightModel and ResetTransform as Inventor nodes and slices as unknown nodes") {
    using namespace volsg;
    auto root = Separator::create();
    auto lightModel = LightModel::create();
    lightModel->model = LightModel::BASE_COLOR;
    auto reset = ResetTransform::create();
    reset->whatToReset.setValue(ResetTransform::TRANSFORM | ResetTransform::BBOX);
    auto data = VolumeData::create();
    data->generator = VolumeData::SOFT_SPHERE;
    auto ortho = OrthoSlice::create();
    ortho->sliceNumber = 17;
    ortho->axis = OrthoSlice::X;
    ortho->clipping = true;
    auto oblique = ObliqueSlice::create();
    oblique->plane = Plane{glm::vec3(0.0f, 0.6f, 0.8f), -0.25f};
    oblique->interpolation = OrthoSlice::NEAREST;
    root->addChild(lightModel);
    root->addChild(reset);
    root->addChild(Transform::create());
    root->addChild(data);
    root->addChild(ortho);
    root->addChild(oblique);
    const std::string text = writeSceneToString(*root);

    SoDB::init();
    SoSeparator* coinRoot = nullptr;
    {
        SoInput input; // gone before SoDB::finish()
        input.setBuffer(text.data(), text.size());
        coinRoot = SoDB::readAll(&input);
    }
    REQUIRE_MESSAGE(coinRoot != nullptr, text);
    coinRoot->ref();

    int lightModels = 0, resets = 0, unknown = 0;
    SoNode* coinOrtho = nullptr;
    SoNode* coinOblique = nullptr;
    for (SoNode* node : allNodes(coinRoot)) {
        if (node->isOfType(SoLightModel::getClassTypeId())) {
            ++lightModels;
            CHECK(static_cast<SoLightModel*>(node)->model.getValue() == SoLightModel::BASE_COLOR);
        } else if (node->isOfType(SoResetTransform::getClassTypeId())) {
            ++resets;
            CHECK(static_cast<SoResetTransform*>(node)->whatToReset.getValue() ==
                  (SoResetTransform::TRANSFORM | SoResetTransform::BBOX));
        } else if (std::string(node->getTypeId().getName().getString()) == "UnknownNode") {
            ++unknown;
            if (node->getField("sliceNumber")) coinOrtho = node;
            if (node->getField("plane")) coinOblique = node;
        }
    }
    CHECK(lightModels == 1);
    CHECK(resets == 1);
    CHECK(unknown >= 2); // and VolumeData, which is ours too
    REQUIRE(coinOrtho != nullptr);
    REQUIRE(coinOblique != nullptr);
    CHECK(fieldText(coinOrtho, "sliceNumber") == "17");
    CHECK(fieldText(coinOrtho, "axis") == "X");
    CHECK(fieldText(coinOrtho, "clipping") == "TRUE");
    CHECK(fieldText(coinOblique, "interpolation") == "NEAREST");
    CHECK(fieldText(coinOblique, "plane").find("0.6") != std::string::npos);

    // Coin keeps the unknown nodes' names when it writes them back.
    const std::string again = writtenByCoin(coinRoot);
    CHECK(again.find("OrthoSlice") != std::string::npos);
    CHECK(again.find("ObliqueSlice") != std::string::npos);
    CHECK(again.find("LightModel") != std::string::npos);
    coinRoot->unref();
    SoDB::finish(); // frees Coin's global state, so LeakSanitizer sees no leak
}
