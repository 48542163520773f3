// The material editor, the generated field panel, picking objects (volumes included) and the
// RTVR drag that changes an active object's opacity and contrast.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <volsg/editors/ActiveObjectDrag.h>
#include <volsg/editors/EditHistory.h>
#include <volsg/editors/FieldPanelModel.h>
#include <volsg/editors/MaterialEditor.h>
#include <volsg/editors/ScenePicker.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/BoxClip.h>
#include <volsg/nodes/Cube.h>
#include <volsg/nodes/Material.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/Volume.h>
#include <volsg/volume/TransferFunction1D.h>

using namespace volsg;

namespace {
// A 2-unit cube at x = -3 and a 16^3 volume (spacing 1/8: a 2-unit box) at x = +3.
const char* twoObjects = "#Inventor V2.1 ascii\n"
                         "Separator {\n"
                         "  Separator {\n"
                         "    Transform { translation -3 0 0 }\n"
                         "    DEF cubeMaterial Material { transparency 0.2 }\n"
                         "    DEF cube Cube { }\n"
                         "  }\n"
                         "  Separator {\n"
                         "    Transform { translation 3 0 0 }\n"
                         "    VolumeData { generator SOFT_SPHERE dimensions 16 16 16 "
                         "spacing 0.125 0.125 0.125 }\n"
                         "    DEF tf TransferFunction { }\n"
                         "    DEF volume Volume { }\n"
                         "  }\n"
                         "}\n";

Node* named(Node& root, const char* name) {
    std::vector<Node*> stack{&root};
    while (!stack.empty()) {
        Node* n = stack.back();
        stack.pop_back();
        if (n->getName() == name) return n;
        if (auto* c = n->children())
            for (auto& child : *c)
                stack.push_back(child.get());
    }
    return nullptr;
}
} // namespace

TEST_CASE("the material editor edits a Material's colours and a BoxClip's inside and outside") {
    EditHistory history;
    MaterialEditor editor(history);
    auto material = Material::create();
    REQUIRE(editor.setNode(material.get()));
    CHECK(editor.properties().size() == 6);
    editor.setColor(1, {0.1f, 0.2f, 0.3f}); // diffuse
    CHECK(material->diffuseColor[0] == glm::vec3(0.1f, 0.2f, 0.3f));
    editor.beginChange(5); // a transparency slider held down
    editor.setScalar(5, 0.3f);
    editor.setScalar(5, 0.6f);
    editor.endChange();
    CHECK(material->transparency[0] == doctest::Approx(0.6f));
    CHECK(history.size() == 2);
    history.undo();
    CHECK(material->transparency[0] == 0.0f);

    auto box = BoxClip::create();
    REQUIRE(editor.setNode(box.get()));
    editor.setColor(0, {1.0f, 0.0f, 0.0f});
    editor.setScalar(1, 0.5f);
    editor.setScalar(5, 7.0f); // outside opacity: clamped to the editor's range
    CHECK(box->insideColor() == glm::vec3(1.0f, 0.0f, 0.0f));
    CHECK(box->insideColorWeight() == 0.5f);
    CHECK(box->outsideOpacity() == 4.0f);
    CHECK_FALSE(editor.setNode(Cube::create().get()));
    CHECK(editor.properties().empty());
}

TEST_CASE("the field panel lists every field with its widget and sets values from text") {
    EditHistory history;
    FieldPanelModel panel(history);
    auto volume = Volume::create();
    panel.setNode(volume.get());
    REQUIRE(panel.entries().size() == volume->fieldCount());
    // By name, so that a field added to Volume does not move the checks.
    auto entryOf = [&](const std::string& name) {
        for (std::size_t i = 0; i < panel.entries().size(); ++i)
            if (panel.entries()[i].field->name() == name) return i;
        FAIL("no entry for " << name);
        return std::size_t(0);
    };
    CHECK(panel.entries()[0].kind == FieldPanelModel::Kind::Enum); // renderMode
    const std::size_t numPlanes = entryOf("numPlanes");
    CHECK(panel.entries()[numPlanes].kind == FieldPanelModel::Kind::Int);
    CHECK(panel.entries()[entryOf("preIntegrated")].kind == FieldPanelModel::Kind::Bool);
    const std::size_t planeOpacity = entryOf("planeOpacity");
    CHECK(panel.entries()[planeOpacity].kind == FieldPanelModel::Kind::Text); // MFVec2f
    std::string error;
    CHECK(panel.setText(planeOpacity, "[ 0 0.5, 1 2 ]", &error));
    CHECK(volume->planeOpacity.getValues() == std::vector<glm::vec2>{{0, 0.5f}, {1, 2}});
    CHECK_FALSE(panel.setText(numPlanes, "many", &error));
    CHECK(error.find("numPlanes") != std::string::npos);
    CHECK(volume->numPlanes.isDefault());
    panel.change(numPlanes, [&] { volume->numPlanes = 64; });
    CHECK(volume->numPlanes() == 64);
    CHECK(history.size() == 2);
    history.undo();
    history.undo();
    CHECK(volume->planeOpacity.isDefault());
}

TEST_CASE("picking finds the shape or the volume content under the ray") {
    ref_ptr<Node> root = readSceneFromString(twoObjects);
    const auto cube = pickScene(*root, Ray{{-3.0, 0.0, 10.0}, {0.0, 0.0, -1.0}});
    REQUIRE(cube.has_value());
    CHECK(cube->node == named(*root, "cube"));
    CHECK_FALSE(cube->isVolume);
    CHECK(cube->distance == doctest::Approx(9.0).epsilon(1e-9));
    const auto volume = pickScene(*root, Ray{{3.5, 0.5, 10.0}, {0.0, 0.0, -2.0}});
    REQUIRE(volume.has_value());
    CHECK(volume->node == named(*root, "volume"));
    CHECK(volume->isVolume);
    // Not the box face at z = 1 but the content: the soft sphere's value 1 - r / 0.9 (radius
    // 0.45 of the box) reaches the identity ramp's alpha 0.02 at r = 0.882, so at
    // z = sqrt(0.882^2 - 0.5) = 0.546 on this ray (within half a voxel, 1/16).
    const double z = std::sqrt(0.882 * 0.882 - 0.5);
    CHECK(std::abs(volume->distance - (10.0 - z)) < 0.0625);
    CHECK(std::abs(volume->point.z - z) < 0.0625);
    CHECK_FALSE(pickScene(*root, Ray{{0.0, 0.0, 10.0}, {0.0, 0.0, -1.0}}).has_value());
    // The transfer function in the volume's scope is the one a drag edits.
    CHECK(nearestInScope(*root, *volume->node, TransferFunction::classType()) ==
          named(*root, "tf"));
}

namespace {
// A 32^3 UByte volume (spacing 1/16: a 2-unit box about the origin) holding 255 in the voxels
// whose centres lie within 0.5 of the centre and 0 elsewhere (tag 1 within 0.75, so that the
// data's whole rise from 0 to 1 lies in tag-1 cells; tags are nearest-neighbour), with
// an alpha step at v = 0.5: the visible surface is the sphere of radius 0.5 to within the
// voxel sampling. `extra` goes before the VolumeData; `behind` after the volume's Separator.
struct OpaqueSphere {
    std::filesystem::path dir;
    OpaqueSphere() {
        dir = std::filesystem::temp_directory_path() / ("volsg-pick-" + std::to_string(getpid()));
        std::filesystem::create_directories(dir);
        std::vector<std::uint8_t> data(32 * 32 * 32), tags(data.size());
        for (int k = 0; k < 32; ++k)
            for (int j = 0; j < 32; ++j)
                for (int i = 0; i < 32; ++i) {
                    const glm::dvec3 c = (glm::dvec3(i, j, k) + 0.5) / 16.0 - 1.0;
                    const bool inside = glm::length(c) <= 0.5;
                    data[std::size_t(i + 32 * (j + 32 * k))] = inside ? 255 : 0;
                    tags[std::size_t(i + 32 * (j + 32 * k))] = glm::length(c) <= 0.75 ? 1 : 0;
                }
        std::ofstream((dir / "sphere.raw").string(), std::ios::binary)
            .write(reinterpret_cast<const char*>(data.data()), std::streamsize(data.size()));
        std::ofstream((dir / "tags.raw").string(), std::ios::binary)
            .write(reinterpret_cast<const char*>(tags.data()), std::streamsize(tags.size()));
    }
    ~OpaqueSphere() { std::filesystem::remove_all(dir); }
    ref_ptr<Node> scene(const std::string& extra, const std::string& behind = "",
                        const std::string& tagLine = "") const {
        return readSceneFromString("#Inventor V2.1 ascii\nSeparator {\n  Separator {\n" + extra +
                                   "    VolumeData { fileName \"" + (dir / "sphere.raw").string() +
                                   "\" dimensions 32 32 32 spacing 0.0625 0.0625 0.0625 " +
                                   tagLine + "}\n" +
                                   "    TransferFunction { alpha [ 0 0, 0.49 0, 0.51 1 ] }\n" +
                                   "    DEF volume Volume { }\n  }\n" + behind + "}\n");
    }
    std::string tagFile() const { return "tagFileName \"" + (dir / "tags.raw").string() + "\" "; }
};
const char* cubeBehind = "  Separator { Transform { translation 0 0 -3 } DEF cube Cube { } }\n";
const Ray down{{0.0, 0.0, 10.0}, {0.0, 0.0, -1.0}};
const Ray corner{{0.9, 0.9, 10.0}, {0.0, 0.0, -1.0}}; // through the box, outside the sphere
constexpr double halfVoxel = 1.0 / 32.0;
} // namespace

TEST_CASE("a volume is picked where its content becomes visible, not at its box") {
    const OpaqueSphere sphere;
    ref_ptr<Node> root = sphere.scene("");
    // Through the box's corner only transparent voxels: no hit at all.
    CHECK_FALSE(pickScene(*root, corner).has_value());
    // Through the centre: the sphere's surface at z = 0.5, to half a voxel.
    const auto hit = pickScene(*root, down);
    REQUIRE(hit.has_value());
    CHECK(hit->node == named(*root, "volume"));
    CHECK(hit->isVolume);
    CHECK(std::abs(hit->distance - 9.5) < halfVoxel);
    CHECK(std::abs(hit->point.z - 0.5) < halfVoxel);
    // From the side, through the transformed volume: the same surface, in world coordinates.
    ref_ptr<Node> moved = sphere.scene("    Transform { translation 5 0 0 }\n");
    const auto side = pickScene(*moved, Ray{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}});
    REQUIRE(side.has_value());
    CHECK(std::abs(side->point.x - 4.5) < halfVoxel);
}

TEST_CASE("a clipped part of a volume is not picked: ClipPlane and BoxClip") {
    const OpaqueSphere sphere;
    // Only z <= 0 is kept: the ray meets the opaque inside at the cut, z = 0, exactly.
    ref_ptr<Node> planes = sphere.scene("    ClipPlane { plane 0 0 -1 0 }\n");
    const auto clipped = pickScene(*planes, down);
    REQUIRE(clipped.has_value());
    CHECK(clipped->distance == doctest::Approx(10.0).epsilon(1e-9));
    ref_ptr<Node> box =
        sphere.scene("    BoxClip { origin -1 -1 -1 extent 2 2 1 outsideOpacity 0 }\n");
    const auto boxed = pickScene(*box, down);
    REQUIRE(boxed.has_value());
    CHECK(boxed->distance == doctest::Approx(10.0).epsilon(1e-9));
    // Cutting away the whole sphere leaves nothing to pick.
    ref_ptr<Node> gone = sphere.scene("    ClipPlane { plane 0 0 1 0.6 }\n");
    CHECK_FALSE(pickScene(*gone, down).has_value());
}

TEST_CASE("the shape behind a transparent part of a volume is picked instead of the volume") {
    const OpaqueSphere sphere;
    ref_ptr<Node> root = sphere.scene("", cubeBehind);
    // Through the box's corner: the volume is transparent there, the cube (front face z = -2)
    // is what the click selects.
    const auto behind = pickScene(*root, corner);
    REQUIRE(behind.has_value());
    CHECK(behind->node == named(*root, "cube"));
    CHECK_FALSE(behind->isVolume);
    CHECK(behind->distance == doctest::Approx(12.0).epsilon(1e-9));
    // Through the centre the sphere is in front of the cube.
    const auto front = pickScene(*root, down);
    REQUIRE(front.has_value());
    CHECK(front->node == named(*root, "volume"));
    // Tags are honoured: a transfer function making tag 1 (the sphere) transparent leaves only
    // the cube.
    ref_ptr<Node> tagged = sphere.scene("    TransferFunction { tag 1 alpha [ 0 0, 1 0 ] }\n",
                                        cubeBehind, sphere.tagFile());
    const auto through = pickScene(*tagged, down);
    REQUIRE(through.has_value());
    CHECK(through->node == named(*tagged, "cube"));
}

TEST_CASE("dragging a volume up makes it more opaque and right raises its contrast") {
    EditHistory history;
    ActiveObjectDrag drag(history);
    ref_ptr<Node> root = readSceneFromString(twoObjects);
    auto* tf = static_cast<TransferFunction*>(named(*root, "tf"));
    REQUIRE(drag.begin(*root, *named(*root, "volume")));
    CHECK(drag.target() == tf);
    // 100 px up: opacity times 2 (clamped to 1); the ramp 0..1 reaches 1 at v = 0.5.
    drag.update({0.0, -ActiveObjectDrag::pixelsPerDoubling});
    CHECK(tf->function().evaluate(TransferFunction1D::Alpha, 0.25) ==
          doctest::Approx(0.5).epsilon(1e-6));
    CHECK(tf->function().evaluate(TransferFunction1D::Alpha, 0.75) ==
          doctest::Approx(1.0).epsilon(1e-6));
    // Instead 100 px right: contrast times 2 about v = 0.5: the ramp runs over [0.25, 0.75].
    drag.update({ActiveObjectDrag::pixelsPerDoubling, 0.0});
    CHECK(tf->function().evaluate(TransferFunction1D::Alpha, 0.25) ==
          doctest::Approx(0.0).epsilon(1e-6));
    CHECK(tf->function().evaluate(TransferFunction1D::Alpha, 0.625) ==
          doctest::Approx(0.75).epsilon(1e-6));
    drag.end();
    CHECK(history.size() == 1);
    history.undo();
    CHECK(tf->alpha.isDefault());
}

TEST_CASE("lower contrast keeps the curve's values at the ends of the range") {
    const auto gentler =
        ActiveObjectDrag::scaleContrast({{0.25f, 0.0f}, {0.75f, 1.0f}}, 0.5); // over [0, 1]
    REQUIRE(gentler.size() >= 2);
    CHECK(gentler.front() == glm::vec2(0.0f, 0.0f));
    CHECK(gentler.back() == glm::vec2(1.0f, 1.0f));
    const auto widest = ActiveObjectDrag::scaleContrast({{0.0f, 0.0f}, {1.0f, 1.0f}}, 0.5);
    // The ramp now spans [-0.5, 1.5]: at the range ends it reaches 0.25 and 0.75.
    CHECK(widest.front().y == doctest::Approx(0.25f).epsilon(1e-6));
    CHECK(widest.back().y == doctest::Approx(0.75f).epsilon(1e-6));
}

TEST_CASE("dragging a shape down makes its material more transparent") {
    EditHistory history;
    ActiveObjectDrag drag(history);
    ref_ptr<Node> root = readSceneFromString(twoObjects);
    auto* material = static_cast<Material*>(named(*root, "cubeMaterial"));
    REQUIRE(drag.begin(*root, *named(*root, "cube")));
    drag.update({0.0, ActiveObjectDrag::pixelsPerDoubling}); // opacity 0.8 -> 0.4
    CHECK(material->transparency[0] == doctest::Approx(0.6f).epsilon(1e-6));
    drag.end();
}
