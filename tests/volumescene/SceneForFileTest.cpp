// Opening data files as scenes: which files are what, the scene built for a volume (camera,
// placement, data read once, the transfer function from its histogram) and for a glTF model,
// where a viewer saves it, and what that scene shows: a ball of tissue in air, rendered by GL
// and by the reference ray caster, visible in the middle and transparent air around it.

#include "support/TempDir.h"
#include <doctest/doctest.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <unistd.h>

#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/context/Context.h>
#include <volsg/core/Error.h>
#include <volsg/image/Image.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/GltfModel.h>
#include <volsg/nodes/Group.h>
#include <volsg/nodes/MatrixTransform.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/Volume.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/render/Renderer.h>
#include <volsg/volumescene/ReferenceScene.h>
#include <volsg/volumescene/SceneForFile.h>

using namespace volsg;
namespace fs = std::filesystem;

namespace {

const std::string data = VOLSG_DATA_DIR;

/// This file's temporary folders.
class TempDir : public volsg::test::TempDir {
public:
    TempDir() : volsg::test::TempDir("volsg-open") {}
};

template <class T> T* child(Node& root) {
    for (const auto& c : *root.children())
        if (auto* t = dynamic_cast<T*>(c.get())) return t;
    return nullptr;
}

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

// A 32^3 uint8 raw file: air (10) everywhere, a ball of radius 8 voxels of tissue (200).
std::string writeBallInAir(const TempDir& dir) {
    const std::string path = dir.file("ball.raw");
    std::ofstream out(path, std::ios::binary);
    for (int k = 0; k < 32; ++k)
        for (int j = 0; j < 32; ++j)
            for (int i = 0; i < 32; ++i) {
                const double r = std::hypot(i - 15.5, j - 15.5, k - 15.5);
                out.put(char(r < 8.0 ? 200 : 10));
            }
    return path;
}

double difference(const glm::vec4& a, const glm::vec3& b) {
    return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

} // namespace

TEST_CASE("file kinds come from names and magic bytes, binary bytes never reach a message") {
    CHECK(fileKindOf(data + "/derived/headsq_32x32x24_int16.nii.gz") == FileKind::Volume);
    CHECK(fileKindOf(data + "/derived/headsq_dicom") == FileKind::Volume);
    CHECK(fileKindOf(data + "/vtkjs-lidc2/lidc2_chest.nhdr") == FileKind::Volume);
    CHECK(fileKindOf(data + "/gltf/Duck/glTF-Binary/Duck.glb") == FileKind::Gltf);
    CHECK(fileKindOf(std::string(VOLSG_SOURCE_DIR) + "/viewer/view/showcase.iv") ==
          FileKind::Scene);

    const std::string gz = data + "/vtkjs-lidc2/lidc2_256x256x133_uint8.raw.gz";
    std::string message = errorOf([&] { readSceneForFile(gz); });
    CHECK(message.find("--dims X Y Z --type") != std::string::npos);
    OpenFileOptions raw;
    raw.raw = RawVolumeLayout{{256, 256, 133}};
    CHECK(fileKindOf(gz, raw) == FileKind::Volume);

    TempDir dir;
    const std::string binary = dir.file("noise.bin");
    std::ofstream(binary, std::ios::binary) << std::string("\x1f\x8b\x08\x00\xff\xfe\x01\x80", 8);
    message = errorOf([&] { readSceneForFile(binary); });
    CAPTURE(message);
    CHECK(message.find("noise.bin") != std::string::npos);
    CHECK(message.find("not a file volsg opens") != std::string::npos);
    for (const unsigned char c : message)
        CHECK((c >= 0x20 && c < 0x7f));
}

TEST_CASE("the scene for a NIfTI file: placed in patient space, data read once, range used") {
    const std::string path = data + "/derived/headsq_32x32x24_int16.nii.gz";
    ref_ptr<Node> root = readSceneForFile(path);
    REQUIRE(root->children());
    auto* camera = child<PerspectiveCamera>(*root);
    auto* placement = child<MatrixTransform>(*root);
    auto* volumeData = child<VolumeData>(*root);
    auto* transfer = child<TransferFunction>(*root);
    REQUIRE(camera);
    REQUIRE(placement);
    REQUIRE(volumeData);
    REQUIRE(transfer);
    CHECK(child<Volume>(*root));
    CHECK(volumeData->fileName() == "headsq_32x32x24_int16.nii.gz");

    const ref_ptr<const VolumeGrid> grid = volumeData->grid();
    const glm::dmat4 expected =
        grid->geometry().localToPatient(grid->dimensions(), grid->spacing());
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            CHECK(placement->matrix()[c][r] == doctest::Approx(expected[c][r]).epsilon(1e-6));
    // The voxel (0,0,0) centre lands at the file's origin, (-100, -80, 20) mm.
    const glm::dvec3 first =
        glm::dvec3(glm::dmat4(placement->matrix()) * glm::dvec4(grid->voxelCenter(0, 0, 0), 1.0));
    CHECK(glm::length(first - glm::dvec3(-100, -80, 20)) < 1e-3);

    const auto [lo, hi] = grid->minMax();
    CHECK(transfer->dataRange() == glm::vec2(float(lo), float(hi))); // the fields say what is used
    CHECK(lo == 0.0);
    CHECK(hi > 2000.0);

    // The camera looks along +y (from the patient's front) with +z up, at the whole box.
    const glm::dquat q = camera->orientation().quat();
    CHECK(glm::length(q * glm::dvec3(0, 0, -1) - glm::dvec3(0, 1, 0)) < 1e-6);
    CHECK(glm::length(q * glm::dvec3(0, 1, 0) - glm::dvec3(0, 0, 1)) < 1e-6);
    const Box3 box = computeBoundingBox(*root);
    CHECK(glm::length(box.center() - glm::dvec3(camera->position())) > glm::length(box.size()) / 2);
}

TEST_CASE("the scene for a glTF model has a camera, a light and the model") {
    ref_ptr<Node> root = readSceneForFile(data + "/gltf/Box/glTF-Embedded/Box.gltf");
    REQUIRE(child<PerspectiveCamera>(*root));
    CHECK(child<GltfModel>(*root));
    CHECK(child<PerspectiveCamera>(*root)->position().z > 0.5f);
}

TEST_CASE("a data file's scene is saved as an .iv beside it") {
    CHECK(scenePathForSaving(data + "/derived/headsq_32x32x24_int16.nii.gz") ==
          data + "/derived/headsq_32x32x24_int16.iv");
    CHECK(scenePathForSaving(data + "/derived/headsq_dicom") == data + "/derived/headsq_dicom.iv");
    CHECK(scenePathForSaving(data + "/derived/headsq_dicom/") == data + "/derived/headsq_dicom.iv");
    const std::string scene = std::string(VOLSG_SOURCE_DIR) + "/viewer/view/showcase.iv";
    CHECK(scenePathForSaving(scene) == scene);
}

TEST_CASE("a ball of tissue in air opened raw: visible in the middle, air transparent (GL and "
          "reference)") {
    TempDir dir;
    OpenFileOptions options;
    options.raw = RawVolumeLayout{{32, 32, 32}};
    ref_ptr<Node> root = readSceneForFile(writeBallInAir(dir), options);
    auto context = Context::createOffscreen();
    RenderOptions render;
    render.width = render.height = 48;
    render.background = glm::vec3(0.0f, 0.0f, 0.5f);
    Renderer renderer;
    const Image gl = renderer.render(*root, render);
    const Image reference = renderReference(*root, render);
    for (const Image* image : {&gl, &reference}) {
        // The middle: through 16 voxels of tissue, far from the background (more than half way
        // to opaque orange).
        const glm::vec4 middle = image->at(24, 24);
        INFO("middle ", middle.r, " ", middle.g, " ", middle.b);
        CHECK(difference(middle, render.background) > 0.4);
        CHECK(middle.r > 0.4);
        // A corner ray crosses only air: the background to within 1/255.
        CHECK(difference(image->at(1, 1), render.background) < 1.0 / 255.0);
        CHECK(difference(image->at(46, 46), render.background) < 1.0 / 255.0);
    }
    // GL agrees with the reference in the middle (the slicer's documented error is a few %).
    CHECK(difference(gl.at(24, 24), glm::vec3(reference.at(24, 24))) < 0.05);
}

TEST_CASE("a missing data file: the render error names the scene file, the VolumeData's line and "
          "the data file") {
    TempDir dir;
    const std::string scenePath = dir.file("scene.iv");
    std::ofstream(scenePath) << "#Inventor V2.1 ascii\nSeparator {\n  TransferFunction { }\n"
                                "  VolumeData { fileName \"gone.nii.gz\" }\n  Volume { }\n}\n";
    ref_ptr<Node> root = readSceneForFile(scenePath);
    auto context = Context::createOffscreen();
    Renderer renderer;
    RenderOptions options;
    options.width = options.height = 16;
    const std::string message = errorOf([&] { renderer.render(*root, options); });
    CAPTURE(message);
    CHECK(message.find(scenePath + ":4:3:") != std::string::npos); // the VolumeData's place
    CHECK(message.find("VolumeData") != std::string::npos);
    CHECK(message.find("gone.nii.gz") != std::string::npos);
    CHECK(message.find("No such file") != std::string::npos);
    CHECK(message.find('\n') == std::string::npos);
}

TEST_CASE("a scene's VolumeData reads NIfTI files and DICOM folders by fileName") {
    for (const std::string name : {"headsq_32x32x24_int16.nii.gz", "headsq_dicom"}) {
        CAPTURE(name);
        ref_ptr<Node> root =
            readSceneFromString("#Inventor V2.1 ascii\nVolumeData { fileName \"" + name + "\" }\n",
                                data + "/derived/scene.iv");
        auto* volumeData = dynamic_cast<VolumeData*>(root.get());
        REQUIRE(volumeData);
        const ref_ptr<const VolumeGrid> grid = volumeData->grid();
        CHECK(grid->dimensions() == glm::ivec3(32, 32, 24));
        CHECK(grid->spacing().z == doctest::Approx(6.0));
        CHECK(grid->geometry().known);
    }
}
