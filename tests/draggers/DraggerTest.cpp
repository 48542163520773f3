// Inventor's draggers drawn at rest (nodes/volsg/nodes/Dragger.h): Coin's default geometry
// reads with our reader, every dragger type keeps and writes back its fields, the motion
// matrix places the parts, bounding boxes and picks go through the parts, and a
// Translate1Dragger's pixels land where a closed form says. The comparison of every dragger
// type's image with Coin3D's is the ctest DraggersAgreeWithCoin (tests/draggers/*.iv).
#include <doctest/doctest.h>

#include "support/Offscreen.h"

#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/actions/PickAction.h>
#include <volsg/context/OSMesaContext.h>
#include <volsg/gl/GlDebug.h>
#include <volsg/image/Image.h>
#include <volsg/io/GraphCompare.h>
#include <volsg/io/InventorTypes.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/SceneWriter.h>
#include <volsg/nodes/BuiltinNodes.h>
#include <volsg/nodes/Dragger.h>
#include <volsg/nodes/DraggerCatalog.h>
#include <volsg/nodes/Separator.h>
#include <volsg/render/Renderer.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <string>

using namespace volsg;

namespace {

ref_ptr<Node> read(const std::string& body) {
    return readSceneFromString("#Inventor V2.1 ascii\n" + body, "<string>");
}

/// The names DEF'd in one of the embedded resource files.
std::set<std::string> resourceNames(const std::string& file) {
    std::set<std::string> names;
    std::istringstream words{std::string(draggerDefaultFile(file))};
    for (std::string word, last; words >> word; last = word)
        if (last == "DEF") names.insert(word);
    return names;
}

bool boxNear(const Box3& b, glm::dvec3 lo, glm::dvec3 hi, double eps = 1e-5) {
    return glm::all(glm::lessThanEqual(glm::abs(b.min - lo), glm::dvec3(eps))) &&
           glm::all(glm::lessThanEqual(glm::abs(b.max - hi), glm::dvec3(eps)));
}

} // namespace

TEST_CASE("every embedded file of Coin's dragger geometry reads with our reader") {
    const auto folder =
        std::filesystem::path(VOLSG_SOURCE_DIR) / "nodes/volsg/nodes/draggerDefaults";
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        if (entry.path().extension() != ".iv") continue;
        const std::string name = entry.path().filename().string();
        CAPTURE(name);
        std::ifstream in(entry.path(), std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        CHECK(draggerDefaultFile(name) == text.str());
        CHECK_NOTHROW(readSceneFromString(draggerDefaultFile(name), name));
        ++files;
    }
    CHECK(files == 21);
}

TEST_CASE("a Translate1Dragger at rest: its arrow's box, moved by translation") {
    CHECK(boxNear(computeBoundingBox(*read("Translate1Dragger { }")), {-1.5, -0.25, -0.25},
                  {1.5, 0.25, 0.25}));
    CHECK(boxNear(computeBoundingBox(*read("Translate1Dragger { translation 2 1 0 }")),
                  {0.5, 0.75, -0.25}, {3.5, 1.25, 0.25}));
}

TEST_CASE("the catalogs name real parts, resources and child dragger types") {
    const auto& catalogs = draggerCatalogs();
    CHECK(catalogs.size() == 21);
    for (const DraggerCatalog& catalog : catalogs) {
        CAPTURE(catalog.typeName);
        const InventorType* type = findInventorType(catalog.typeName);
        REQUIRE(type);
        std::set<std::string> fields;
        for (const auto& [name, fieldType] : type->fields)
            if (fieldType == "SFNode") fields.insert(name);
        const std::set<std::string> resources = resourceNames(catalog.resourceFile);
        CHECK(catalog.parts.front().name == "topSeparator");
        for (const DraggerPart& part : catalog.parts) {
            CAPTURE(part.name);
            // Every catalog entry is one of the type's parts (an SFNode field of that name).
            CHECK(fields.count(part.name) == 1);
            if (part.kind == DraggerPart::Kind::Resource) CHECK(resources.count(part.value) == 1);
            if (part.kind == DraggerPart::Kind::ChildDragger) {
                CHECK(Dragger::createOfType(part.value));
                for (const auto& [path, value] : part.childDefaults)
                    CHECK((value == "{}" || resources.count(value.substr(1)) == 1));
            }
        }
    }
}

TEST_CASE("every dragger type is registered, keeps the table's fields and writes back unchanged") {
    const std::vector<const NodeType*> types = Dragger::draggerTypes();
    CHECK(types.size() == 21);
    for (const NodeType* type : types) {
        CAPTURE(type->name());
        CHECK(nodeTypes().find(type->name()) == type);
        ref_ptr<Node> node = type->create();
        REQUIRE(node);
        CHECK(node->isA<Dragger>());
        CHECK(node->children() == nullptr);
        const InventorType* table = findInventorType(type->name());
        REQUIRE(table);
        REQUIRE(node->fieldCount() == table->fields.size());
        for (std::size_t i = 0; i < node->fieldCount(); ++i) {
            CHECK(std::string(node->fieldAt(i)->name()) == table->fields[i].first);
            CHECK(std::string(node->fieldAt(i)->typeName()) == table->fields[i].second);
        }
        // At rest with nothing set: written with no field, drawn from its defaults.
        const std::string text = writeSceneToString(*node);
        CHECK(text.find(std::string(type->name()) + " {\n}") != std::string::npos);
        CHECK_FALSE(computeBoundingBox(*node).isEmpty());
        ref_ptr<Node> again = readSceneFromString(text, "<written>");
        std::string why;
        CHECK_MESSAGE(graphsEqual(*node, *again, &why), why);
    }
    // A dragger has parts, not children.
    CHECK_THROWS(read("Translate1Dragger { Cube { } }"));
}

TEST_CASE("a part the file sets is drawn instead of the default, and written back") {
    ref_ptr<Node> node = read(R"(Translate1Dragger {
        translator Separator { Sphere { radius 0.7 } }
        translation 0 1 0
    })");
    // The sphere (moved up 1) replaces the arrow; the feedback switch's default is empty.
    CHECK(boxNear(computeBoundingBox(*node), {-0.7, 0.3, -0.7}, {0.7, 1.7, 0.7}));
    ref_ptr<Node> again = readSceneFromString(writeSceneToString(*node), "<written>");
    std::string why;
    CHECK_MESSAGE(graphsEqual(*node, *again, &why), why);
}

TEST_CASE("composite draggers place their child draggers as Coin does") {
    // TransformBoxDragger: six Translate2Draggers on the faces of the [-1, 1] cube, three
    // rotators on its edges; its ScaleUniformDragger's 0.1 cubes sit at the corners of the
    // [-1.1, 1.1] box (transformBoxDragger.iv's TRANSFORMBOX_SCALEDRAGPOINTS).
    const Box3 box = computeBoundingBox(*read("TransformBoxDragger { }"));
    CHECK(box.min.x == doctest::Approx(-1.15));
    CHECK(box.max.z == doctest::Approx(1.15));
    // A DragPointDragger moved: all its child draggers go with its motion matrix.
    const Box3 still = computeBoundingBox(*read("DragPointDragger { }"));
    const Box3 moved = computeBoundingBox(*read("DragPointDragger { translation 0.5 -1 0.25 }"));
    CHECK(boxNear(moved, still.min + glm::dvec3(0.5, -1, 0.25),
                  still.max + glm::dvec3(0.5, -1, 0.25)));
}

TEST_CASE("TransformBoxDragger ignores the values a file gives, as Coin, until one changes") {
    ref_ptr<Node> node = read("TransformBoxDragger { translation 3 0 0 }");
    const Box3 rest = computeBoundingBox(*read("TransformBoxDragger { }"));
    CHECK(boxNear(computeBoundingBox(*node), rest.min, rest.max));
    auto* translation = dynamic_cast<SFVec3f*>(node->field("translation"));
    REQUIRE(translation);
    translation->setValue(glm::vec3(3, 0, 0));
    CHECK(boxNear(computeBoundingBox(*node), rest.min + glm::dvec3(3, 0, 0),
                  rest.max + glm::dvec3(3, 0, 0)));
}

TEST_CASE("a ray picks a dragger's part, with the dragger on the picked path") {
    ref_ptr<Node> root = read("Separator { Translate1Dragger { translation 0 2 0 } }");
    PickAction pick;
    pick.setRay({{0.0, 2.0, 10.0}, {0.0, 0.0, -1.0}});
    pick.apply(*root);
    const auto hit = pick.picked();
    REQUIRE(hit);
    // The shaft: a 2 x 0.1 x 0.1 cube.
    CHECK(hit->point.z == doctest::Approx(0.05));
    bool throughDragger = false;
    for (const Node* n : hit->path)
        throughDragger = throughDragger || n->isA<Dragger>();
    CHECK(throughDragger);
    PickAction miss;
    miss.setRay({{0.0, 0.0, 10.0}, {0.0, 0.0, -1.0}});
    miss.apply(*root);
    CHECK_FALSE(miss.picked());
}

namespace {

using volsg::test::Offscreen;

/// Covered columns and rows: min x, min y, max x, max y.
glm::ivec4 coveredRect(const Image& image) {
    glm::ivec4 r(image.width, image.height, -1, -1);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (glm::vec3(image.at(x, y)) != glm::vec3(0.0f))
                r = {std::min(r.x, x), std::min(r.y, y), std::max(r.z, x), std::max(r.w, y)};
    return r;
}

} // namespace

TEST_CASE("Translate1Dragger: translation 2 0 0 moves its silhouette 2 x 10 pixels") {
    // An OrthographicCamera 10 units high over 100 pixels: 10 pixels per unit, x = -5 at the
    // left edge. The arrow spans x in [-1.5, 1.5] (cone tips) and y, z in [-0.25, 0.25].
    Offscreen gl;
    RenderOptions options;
    options.width = options.height = 100;
    const std::string camera =
        "OrthographicCamera { position 0 0 5 height 10 nearDistance 1 farDistance 20 }\n";
    const Image still =
        gl.renderer.render(*read("Separator { " + camera + "Translate1Dragger { } }"), options);
    const Image moved = gl.renderer.render(
        *read("Separator { " + camera + "Translate1Dragger { translation 2 0 0 } }"), options);
    const glm::ivec4 a = coveredRect(still), b = coveredRect(moved);
    // Columns 35..64 (x from -1.5 to 1.5), rows 47..52 (y from 0.25 down to -0.25), each edge
    // within a pixel (the cone tips and the edge pixels' coverage).
    CHECK(std::abs(a.x - 35) <= 1);
    CHECK(std::abs(a.z - 64) <= 1);
    CHECK(std::abs(a.y - 47) <= 1);
    CHECK(std::abs(a.w - 52) <= 1);
    // Moved by exactly 20 pixels: the same pixels, shifted.
    CHECK(b == a + glm::ivec4(20, 0, 20, 0));
}

TEST_CASE("non-finite values: a dragger's box and pick stay bounded, nothing hangs") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    for (const char* type : {"Translate1Dragger", "TrackballDragger", "TransformBoxDragger",
                             "CenterballDragger", "SpotLightDragger", "TabBoxDragger"}) {
        for (const float bad : {nan, inf}) {
            CAPTURE(type);
            ref_ptr<Dragger> d = Dragger::createOfType(type);
            REQUIRE(d);
            for (const char* name : {"translation", "scaleFactor", "center"})
                if (auto* f = dynamic_cast<SFVec3f*>(d->field(name)))
                    f->setValue(glm::vec3(bad, 1.0f, 0.0f));
            if (auto* f = dynamic_cast<SFRotation*>(d->field("rotation")))
                f->setValue(Rotation{glm::vec3(bad, 0.0f, 1.0f), bad});
            if (auto* f = dynamic_cast<SFFloat*>(d->field("angle"))) f->setValue(bad);
            CHECK_NOTHROW(computeBoundingBox(*d));
            PickAction pick;
            pick.setRay({{0.0, 0.0, 10.0}, {0.0, 0.0, -1.0}});
            CHECK_NOTHROW(pick.apply(*d));
        }
    }
}

TEST_CASE("a dragger's parts see Coin's dragger state: solid faces, back faces culled") {
    // A square seen from its back (clockwise from the camera), drawn as lines: outside a
    // dragger every edge shows; as a dragger's part, Coin's SoDragger::updateElements makes
    // faces SOLID and COUNTERCLOCKWISE, so the back face is culled, its edges too.
    Offscreen gl;
    RenderOptions options;
    options.width = options.height = 100;
    const std::string camera =
        "OrthographicCamera { position 0 0 5 height 10 nearDistance 1 farDistance 20 }\n";
    const std::string square = "Separator { DrawStyle { style LINES } "
                               "Coordinate3 { point [ -1 -1 0, 1 -1 0, 1 1 0, -1 1 0 ] } "
                               "IndexedFaceSet { coordIndex [ 0, 3, 2, 1, -1 ] } }";
    const Image plain = gl.renderer.render(*read("Separator { " + camera + square + " }"), options);
    CHECK(coveredRect(plain).z >= 0);
    const Image inDragger = gl.renderer.render(
        *read("Separator { " + camera + "Translate1Dragger { translator " + square + " } }"),
        options);
    CHECK(coveredRect(inDragger).z < 0);
}
