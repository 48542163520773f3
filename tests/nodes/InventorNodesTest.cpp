// The Inventor transform, grouping, kit, file and information nodes without GL: their fields
// (names, types, order and defaults as Coin's), reading and writing, bounding boxes, picking,
// searching, and File's includes with their errors and limits.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/actions/PickAction.h>
#include <volsg/actions/SearchAction.h>
#include <volsg/core/Error.h>
#include <volsg/core/Limits.h>
#include <volsg/io/GraphCompare.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/SceneWriter.h>
#include <volsg/nodes/BuiltinNodes.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/Cube.h>
#include <volsg/nodes/File.h>
#include <volsg/nodes/LOD.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/ShapeKit.h>
#include <volsg/nodes/Sphere.h>
#include <volsg/nodes/Transform.h>

using namespace volsg;

namespace {

ref_ptr<Node> read(const std::string& body, const std::string& fileName = "<string>") {
    return readSceneFromString("#Inventor V2.1 ascii\n" + body, fileName);
}

/// A field's value as the writer writes it.
std::string valueText(const Field& field) {
    struct Out final : FieldOutput {
        std::ostringstream s;
        std::ostream& stream() override { return s; }
        void writeNode(const Node* node) override {
            s << (node ? std::string(node->type().name()) + " {}" : std::string("NULL"));
        }
        void newline() override { s << ' '; }
    } out;
    field.write(out);
    return out.s.str();
}

/// "type name = value" for every field of a new node of the type, in order.
std::vector<std::string> fieldsOf(const char* typeName) {
    const NodeType* type = nodeTypes().find(typeName);
    REQUIRE_MESSAGE(type, typeName);
    ref_ptr<Node> node = type->create();
    std::vector<std::string> out;
    for (std::size_t i = 0; i < node->fieldCount(); ++i) {
        const Field* f = node->fieldAt(i);
        out.push_back(std::string(f->typeName()) + " " + f->name() + " = " + valueText(*f));
        CHECK_MESSAGE(f->isDefault(), typeName, ".", f->name(), " is set in a new node");
    }
    return out;
}

std::filesystem::path freshFolder(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / ("volsg-inventor-nodes-" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

void writeText(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "<no error>";
}

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

std::optional<PickedPoint> pickRay(Node& root, glm::dvec3 origin, glm::dvec3 direction) {
    PickAction pick;
    pick.setRay({origin, direction});
    pick.apply(root);
    return pick.picked();
}

bool boxNear(const Box3& b, glm::dvec3 lo, glm::dvec3 hi, double eps = 1e-6) {
    return glm::all(glm::lessThanEqual(glm::abs(b.min - lo), glm::dvec3(eps))) &&
           glm::all(glm::lessThanEqual(glm::abs(b.max - hi), glm::dvec3(eps)));
}

} // namespace

TEST_CASE("the new node types have Coin's fields in Coin's order with Coin's defaults") {
    // From Coin 4.0's SoFieldData of each class (SFShort, SFName and MFName are SFInt32,
    // SFString and MFString here). Coin's default parts hold their nodes (a Cube, a
    // DirectionalLight, a PerspectiveCamera, NodeKitListPart's Group); here the fields are NULL
    // and the kits traverse those nodes while the parts are unset (BaseKit.h).
    using V = std::vector<std::string>;
    CHECK(fieldsOf("Translation") == V{"SFVec3f translation = 0 0 0"});
    CHECK(fieldsOf("Rotation") == V{"SFRotation rotation = 0 0 1 0"});
    CHECK(fieldsOf("RotationXYZ") == V{"SFFloat angle = 0", "SFEnum axis = X"});
    CHECK(fieldsOf("Scale") == V{"SFVec3f scaleFactor = 1 1 1"});
    CHECK(fieldsOf("TransformSeparator").empty());
    CHECK(fieldsOf("Units") == V{"SFEnum units = METERS"});
    CHECK(fieldsOf("LOD") == V{"SFVec3f center = 0 0 0", "MFFloat range = [ ]"});
    CHECK(fieldsOf("LevelOfDetail") == V{"MFFloat screenArea = [ 0 ]"});
    CHECK(fieldsOf("Array") == V{"SFEnum origin = FIRST", "SFInt32 numElements1 = 1",
                                 "SFInt32 numElements2 = 1", "SFInt32 numElements3 = 1",
                                 "SFVec3f separation1 = 1 0 0", "SFVec3f separation2 = 0 1 0",
                                 "SFVec3f separation3 = 0 0 1"});
    CHECK(fieldsOf("MultipleCopy").size() == 1);
    const V separator{"SFEnum renderCaching = AUTO", "SFEnum boundingBoxCaching = AUTO",
                      "SFEnum renderCulling = AUTO", "SFEnum pickCulling = AUTO"};
    V selection = separator;
    selection.push_back("SFEnum policy = SHIFT");
    CHECK(fieldsOf("Selection") == selection);
    CHECK(fieldsOf("Annotation") == separator);
    CHECK(fieldsOf("File") == V{"SFString name = \"<Undefined file>\""});
    CHECK(fieldsOf("Info") == V{"SFString string = \"<Undefined info>\""});
    CHECK(fieldsOf("Label") == V{"SFString label = \"<Undefined label>\""});
    CHECK(fieldsOf("PickStyle") == V{"SFEnum style = SHAPE"});
    CHECK(fieldsOf("NodeKitListPart") == V{"SFString containerTypeName = \"Group\"",
                                           "MFString childTypeNames = [ \"Node\" ]",
                                           "SFNode containerNode = NULL"});
    CHECK(fieldsOf("BaseKit") == V{"SFNode callbackList = NULL"});
    CHECK(fieldsOf("AppearanceKit") == V{"SFNode callbackList = NULL", "SFNode lightModel = NULL",
                                         "SFNode environment = NULL", "SFNode drawStyle = NULL",
                                         "SFNode material = NULL", "SFNode complexity = NULL",
                                         "SFNode texture2 = NULL", "SFNode font = NULL"});
    V separatorKit{"SFNode callbackList = NULL"};
    separatorKit.insert(separatorKit.end(), separator.begin(), separator.end());
    for (const char* part : {"topSeparator", "pickStyle", "appearance", "units", "transform",
                             "texture2Transform", "childList"})
        separatorKit.push_back(std::string("SFNode ") + part + " = NULL");
    CHECK(fieldsOf("SeparatorKit") == separatorKit);
    V shapeKit = separatorKit;
    for (const char* part :
         {"materialBinding", "normalBinding", "textureCoordinateBinding", "shapeHints",
          "coordinate3", "coordinate4", "normal", "textureCoordinate2", "textureCoordinateFunction",
          "profileCoordinate2", "profileCoordinate3", "profileList", "localTransform",
          "shapeSeparator"})
        shapeKit.push_back(std::string("SFNode ") + part + " = NULL");
    shapeKit.push_back("SFNode shape = NULL"); // a Cube when traversed
    CHECK(fieldsOf("ShapeKit") == shapeKit);
    V wrapperKit = separatorKit;
    wrapperKit.push_back("SFNode localTransform = NULL");
    wrapperKit.push_back("SFNode contents = NULL");
    CHECK(fieldsOf("WrapperKit") == wrapperKit);
    CHECK(fieldsOf("LightKit") == V{"SFNode callbackList = NULL", "SFNode transformGroup = NULL",
                                    "SFNode transform = NULL", "SFNode light = NULL",
                                    "SFNode iconSeparator = NULL", "SFNode icon = NULL"});
    CHECK(fieldsOf("CameraKit") == V{"SFNode callbackList = NULL", "SFNode transformGroup = NULL",
                                     "SFNode transform = NULL", "SFNode camera = NULL"});
    CHECK(fieldsOf("SceneKit") == V{"SFNode callbackList = NULL", "SFNode topSeparator = NULL",
                                    "SFNode cameraList = NULL", "SFNode lightList = NULL",
                                    "SFNode childList = NULL"});
}

TEST_CASE("the enums have Coin's names") {
    const auto names = [](const char* type, const char* field) {
        ref_ptr<Node> node = nodeTypes().find(type)->create();
        std::string s;
        for (const auto& [name, value] : dynamic_cast<SFEnum&>(*node->field(field)).names().entries)
            s += (s.empty() ? "" : " ") + std::string(name) + "=" + std::to_string(value);
        return s;
    };
    CHECK(names("Units", "units") ==
          "METERS=0 CENTIMETERS=1 MILLIMETERS=2 MICROMETERS=3 MICRONS=4 NANOMETERS=5 "
          "ANGSTROMS=6 KILOMETERS=7 FEET=8 INCHES=9 POINTS=10 YARDS=11 MILES=12 "
          "NAUTICAL_MILES=13");
    CHECK(names("RotationXYZ", "axis") == "X=0 Y=1 Z=2");
    CHECK(names("Array", "origin") == "FIRST=0 CENTER=1 LAST=2");
    CHECK(names("Selection", "policy") == "SINGLE=0 TOGGLE=1 SHIFT=2 DISABLE=3");
    CHECK(names("PickStyle", "style") == "SHAPE=0 BOUNDING_BOX=1 UNPICKABLE=2 SHAPE_ON_TOP=3 "
                                         "BOUNDING_BOX_ON_TOP=4 SHAPE_FRONTFACES=5");
    CHECK(names("SeparatorKit", "renderCaching") == "OFF=0 ON=1 AUTO=2");
}

TEST_CASE("every new node type reads and writes back its fields") {
    const std::string text = R"(#Inventor V2.1 ascii

Separator {
  Translation {
    translation 1 2 3
  }
  Rotation {
    rotation 0 1 0 0.5
  }
  RotationXYZ {
    angle 1.25
    axis Z
  }
  Scale {
    scaleFactor 2 3 4
  }
  Units {
    units NAUTICAL_MILES
  }
  TransformSeparator {
    Info {
      string "multi
line"
    }
  }
  LOD {
    center 1 0 0
    range [ 5, 10 ]
    Label {
      label "near"
    }
  }
  LevelOfDetail {
    screenArea [ 1000, 100 ]
  }
  Array {
    origin CENTER
    numElements1 3
    numElements2 2
    numElements3 4
    separation1 2 0 0
    separation2 0 2 0
    separation3 0 0 2
  }
  MultipleCopy {
    matrix [
      1 0 0 0 0 1 0 0 0 0 1 0 1 2 3 1,
      2 0 0 0 0 2 0 0 0 0 2 0 0 0 0 1 ]
  }
  Selection {
    renderCaching OFF
    policy SINGLE
  }
  File {
    name "<Undefined file>"
  }
  Annotation {
    pickCulling ON
  }
  PickStyle {
    style BOUNDING_BOX
  }
  SceneKit {
    cameraList NodeKitListPart {
      containerTypeName "Switch"
      childTypeNames [ "CameraKit" ]
      containerNode Switch {
        whichChild 0
        CameraKit {
          transform Transform {
            translation 0 0 3
          }
          camera OrthographicCamera {
          }
        }
      }
    }
    childList NodeKitListPart {
      containerNode Group {
        WrapperKit {
          contents Separator {
          }
        }
        LightKit {
          light PointLight {
          }
          icon NULL
        }
        ShapeKit {
          renderCulling ON
          appearance AppearanceKit {
            material Material {
            }
          }
          localTransform Transform {
          }
          shape Sphere {
          }
        }
        BaseKit {
        }
        SeparatorKit {
          units Units {
          }
        }
      }
    }
  }
}
)";
    ref_ptr<Node> root = readSceneFromString(text, "<string>");
    CHECK(writeSceneToString(*root) == text);
    std::string why;
    CHECK_MESSAGE(graphsEqual(*root, *readSceneFromString(writeSceneToString(*root)), &why), why);
}

TEST_CASE("a kit file written by Coin reads, keeps its parts and writes back the same graph") {
    // Part of the SGI robot (robots/kitMan.iv) as Coin writes it.
    const std::string coin = R"(#Inventor V2.1 ascii

DEF ROBOT ShapeKit {
  renderCaching AUTO
  boundingBoxCaching AUTO
  renderCulling AUTO
  pickCulling AUTO
  childList
  NodeKitListPart {
    containerTypeName "Separator"
    childTypeNames [ "ShapeKit",
        "SeparatorKit" ]
    containerNode
    Separator {

      DEF LEFT_THIGH ShapeKit {
        renderCaching AUTO
        boundingBoxCaching AUTO
        renderCulling AUTO
        pickCulling AUTO
        transform
        Transform {
          translation -3.5 0 1.3
          center 0 0 0

        }
        localTransform
        Transform {
          translation 0 -12 0
          scaleFactor 3.25 12 2.5

        }
        shape
        Cylinder {

        }

      }
    }

  }
  localTransform
  Transform {
    translation 0 4 0
  }
}
)";
    ref_ptr<Node> root = read(coin.substr(coin.find('\n') + 1));
    REQUIRE(root->isA<ShapeKit>());
    CHECK(root->getName() == "ROBOT");
    const Node* thigh = findByName(*root, "LEFT_THIGH");
    REQUIRE(thigh);
    CHECK(thigh->isA<ShapeKit>());
    // The default Cube of the robot's own shape part, and the thigh's Cylinder.
    CHECK(findAll(*root, Cube::classType()).size() == 1);
    ref_ptr<Node> back = readSceneFromString(writeSceneToString(*root));
    std::string why;
    CHECK_MESSAGE(graphsEqual(*root, *back, &why), why);
    // The box: the robot's default 2 x 2 x 2 cube moved up 4, and the thigh's cylinder
    // (radius 1, height 2, scaled by 3.25 x 12 x 2.5) at (-3.5, -12, 1.3).
    const Box3 box = computeBoundingBox(*root);
    CHECK(boxNear(box, {-6.75, -24.0, -1.2}, {1.0, 5.0, 3.8}, 1e-5));
}

TEST_CASE("default kit parts are not written, parts set to NULL are") {
    auto kit = ShapeKit::create();
    CHECK(writeSceneToString(*kit) == "#Inventor V2.1 ascii\n\nShapeKit {\n}\n");
    auto xf = Transform::create();
    xf->translation = glm::vec3(1, 0, 0);
    kit->transform.setValue(xf);
    kit->shape.setValue(nullptr);
    CHECK(writeSceneToString(*kit) == "#Inventor V2.1 ascii\n\nShapeKit {\n"
                                      "  transform Transform {\n    translation 1 0 0\n  }\n"
                                      "  shape NULL\n}\n");
    CHECK(computeBoundingBox(*kit).isEmpty()); // no shape: nothing to bound
}

TEST_CASE("bounding boxes: transforms, copies, all LOD children, units and kits") {
    const auto box = [](const std::string& body) { return computeBoundingBox(*read(body)); };
    CHECK(boxNear(box("Separator { Translation { translation 1 2 3 } Cube { } }"), {0, 1, 2},
                  {2, 3, 4}));
    CHECK(boxNear(box("Separator { Scale { scaleFactor 2 1 1 } RotationXYZ { axis Z angle "
                      "1.5707963267948966 } Cube { width 2 height 4 depth 2 } }"),
                  {-4, -1, -1}, {4, 1, 1}));
    CHECK(boxNear(box("Separator { Units { units CENTIMETERS } Cube { width 100 height 100 depth "
                      "100 } }"),
                  {-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}));
    // TransformSeparator: the translation inside stops at it.
    CHECK(boxNear(box("Separator { TransformSeparator { Translation { translation 5 0 0 } } Cube "
                      "{ } }"),
                  {-1, -1, -1}, {1, 1, 1}));
    // Array: FIRST, 3 x 2 copies; LAST along x.
    CHECK(boxNear(box("Array { numElements1 3 numElements2 2 separation2 0 3 0 Cube { } }"),
                  {-1, -1, -1}, {3, 4, 1}));
    CHECK(boxNear(box("Array { origin LAST numElements1 3 Cube { } }"), {-3, -1, -1}, {1, 1, 1}));
    CHECK(boxNear(box("Array { origin CENTER numElements3 5 separation3 0 0 2 Cube { } }"),
                  {-1, -1, -5}, {1, 1, 5}));
    CHECK(box("Array { numElements1 0 Cube { } }").isEmpty());
    CHECK(boxNear(box("MultipleCopy { matrix [ 1 0 0 0 0 1 0 0 0 0 1 0 5 0 0 1, 1 0 0 0 0 1 0 "
                      "0 0 0 1 0 -5 0 0 1 ] Cube { } }"),
                  {-6, -1, -1}, {6, 1, 1}));
    // LOD and LevelOfDetail: every child, as Inventor's bounding box action.
    CHECK(boxNear(box("LOD { range 1 Cube { } Cube { width 10 } }"), {-5, -1, -1}, {5, 1, 1}));
    CHECK(boxNear(box("LevelOfDetail { screenArea 1 Cube { } Cube { height 10 } }"), {-1, -5, -1},
                  {1, 5, 1}));
    CHECK(boxNear(box("ShapeKit { transform Transform { translation 0 0 5 } }"), {-1, -1, 4},
                  {1, 1, 6}));
    CHECK(boxNear(box("Separator { Annotation { Translation { translation 3 0 0 } Cube { } } "
                      "Selection { Cube { } } Info { } Label { } PickStyle { } }"),
                  {-1, -1, -1}, {4, 1, 1}));
}

TEST_CASE("bounding boxes of the kits without shapes of their own (as Coin's)") {
    const auto box = [](const std::string& body) { return computeBoundingBox(*read(body)); };
    // Values from Coin 4.0's SoGetBoundingBoxAction on the same scenes.
    CHECK(boxNear(box("LightKit { transform Transform { translation 5 0 0 } icon Cube { } }"),
                  {4, -1, -1}, {6, 1, 1}));
    CHECK(boxNear(box("Separator { CameraKit { transform Transform { translation 5 0 0 } } Cube "
                      "{ } }"),
                  {-1, -1, -1}, {1, 1, 1}));
    CHECK(boxNear(box("SceneKit { childList NodeKitListPart { containerNode Group { ShapeKit { "
                      "transform Transform { translation 0 3 0 } } } } }"),
                  {-1, 2, -1}, {1, 4, 1}));
    CHECK(boxNear(box("WrapperKit { localTransform Transform { translation -5 0 0 } contents "
                      "Separator { Sphere { } } }"),
                  {-6, -1, -1}, {-4, 1, 1}));
    CHECK(boxNear(box("BaseKit { callbackList NodeKitListPart { containerNode Group { Cube { } } "
                      "} }"),
                  {-1, -1, -1}, {1, 1, 1}));
    CHECK(box("Separator { LightKit { } CameraKit { } AppearanceKit { } BaseKit { } "
              "NodeKitListPart { } }")
              .isEmpty());
}

TEST_CASE("every new node type goes through bounding box, pick and search actions") {
    for (const char* name : {"Translation",
                             "Rotation",
                             "RotationXYZ",
                             "Scale",
                             "TransformSeparator",
                             "Units",
                             "LOD",
                             "LevelOfDetail",
                             "Array",
                             "MultipleCopy",
                             "Selection",
                             "File",
                             "Annotation",
                             "Info",
                             "Label",
                             "PickStyle",
                             "NodeKitListPart",
                             "BaseKit",
                             "AppearanceKit",
                             "SeparatorKit",
                             "ShapeKit",
                             "WrapperKit",
                             "LightKit",
                             "CameraKit",
                             "SceneKit"}) {
        CAPTURE(name);
        ref_ptr<Node> node = nodeTypes().find(name)->create();
        REQUIRE(node);
        if (auto* children = node->children()) children->push_back(Cube::create());
        auto root = Separator::create();
        root->addChild(node);
        root->addChild(Cube::create());
        // Every one of them leaves the cube after it where it is, and holds a cube itself when
        // it is a group (ShapeKit: its default Cube).
        const Box3 box = computeBoundingBox(*root);
        CHECK(boxNear(box, {-1, -1, -1}, {1, 1, 1}));
        const auto hit = pickRay(*root, {0, 0, 10}, {0, 0, -1});
        REQUIRE(hit);
        CHECK(hit->point.z == doctest::Approx(1.0));
        const std::size_t cubes = findAll(*root, Cube::classType()).size();
        CHECK(cubes == (node->children() || std::string(name) == "ShapeKit" ? 2u : 1u));
        SearchAction search;
        search.setType(&node->type(), false);
        search.apply(*root);
        REQUIRE(search.paths().size() == 1);
        CHECK(search.paths()[0].back() == node.get());
    }
}

TEST_CASE("an Array with too many copies is an error when traversed") {
    ref_ptr<Node> root = read("Array { numElements1 2000 numElements2 2000 Cube { } }");
    const std::string what = errorOf([&] { computeBoundingBox(*root); });
    CHECK(contains(what, "2000 x 2000 x 1 copies"));
    CHECK(contains(what, std::to_string(std::size_t(1) << 20)));
}

TEST_CASE("PickStyle: UNPICKABLE shapes are not hit, BOUNDING_BOX hits the shape's box") {
    // A unit sphere at the origin, a cube behind it.
    const auto scene = [](const char* style) {
        return read(std::string("Separator { Separator { PickStyle { style ") + style +
                    " } Sphere { } }\n"
                    "Translation { translation 0 0 -5 } Cube { width 4 height 4 depth 2 } }");
    };
    const glm::dvec3 down(0, 0, -1);
    auto shape = scene("SHAPE");
    auto hit = pickRay(*shape, {0, 0, 10}, down);
    REQUIRE(hit);
    CHECK(hit->point.z == doctest::Approx(1.0)); // the exact sphere, as Coin picks it
    CHECK(hit->path.back()->isA<Sphere>());
    // Near the box's corner the sphere is missed; its box is not.
    hit = pickRay(*shape, {0.9, 0.9, 10}, down);
    REQUIRE(hit);
    CHECK(hit->path.back()->isA<Cube>());

    auto box = scene("BOUNDING_BOX");
    hit = pickRay(*box, {0.9, 0.9, 10}, down);
    REQUIRE(hit);
    CHECK(hit->path.back()->isA<Sphere>());
    CHECK(hit->point.x == doctest::Approx(0.9));
    CHECK(hit->point.z == doctest::Approx(1.0).epsilon(1e-3));
    CHECK(hit->normal.z == doctest::Approx(1.0));
    CHECK(hit->distance == doctest::Approx(9.0).epsilon(1e-3));
    // From the side: the box face x = +1.
    hit = pickRay(*box, {10, 0.9, 0.9}, {-1, 0, 0});
    REQUIRE(hit);
    CHECK(hit->normal.x == doctest::Approx(1.0));
    CHECK(hit->point.x == doctest::Approx(1.0).epsilon(1e-3));
    // Coin's ON_TOP variant picks as its base style.
    auto onTop = scene("BOUNDING_BOX_ON_TOP");
    hit = pickRay(*onTop, {0.9, 0.9, 10}, down);
    REQUIRE(hit);
    CHECK(hit->path.back()->isA<Sphere>());

    auto unpickable = scene("UNPICKABLE");
    hit = pickRay(*unpickable, {0, 0, 10}, down);
    REQUIRE(hit);
    CHECK(hit->path.back()->isA<Cube>()); // through the sphere to the cube behind
    CHECK(hit->point.z == doctest::Approx(-4.0));
    // The style is state: the Separator around it ends it.
    CHECK(hit->path.size() == 2);
}

TEST_CASE("LOD picks the child for the distance from the ray's origin or the camera") {
    ref_ptr<Node> root = read("Separator { LOD { range 8\n"
                              "  DEF near Cube { width 1 height 1 depth 1 }\n"
                              "  DEF far Cube { width 4 height 4 depth 1 } } }");
    // At x = 1 only the far child (4 wide) is there.
    CHECK(!pickRay(*root, {1, 0, 5}, {0, 0, -1}));
    auto hit = pickRay(*root, {1, 0, 9}, {0, 0, -1});
    REQUIRE(hit);
    CHECK(hit->path.back()->getName() == "far");
    hit = pickRay(*root, {0, 0, 5}, {0, 0, -1});
    REQUIRE(hit);
    CHECK(hit->path.back()->getName() == "near");

    // Through a pixel: the camera's position counts.
    for (const double z : {5.0, 9.0}) {
        auto camera = OrthographicCamera::create();
        camera->position = glm::vec3(0, 0, float(z));
        camera->height = 10.0f;
        camera->farDistance = 20.0f;
        PickAction pick;
        pick.setCamera(camera);
        pick.setPixel(59, 50, 100, 100); // x = 0.95
        pick.apply(*root);
        CHECK(bool(pick.picked()) == (z == 9.0));
    }
}

TEST_CASE("LevelOfDetail picks the child drawn under the pick's camera") {
    ref_ptr<Node> root = read("LevelOfDetail { screenArea 2000\n"
                              "  DEF big Cube { width 2 height 2 depth 2 }\n"
                              "  DEF small Cube { width 0.5 height 0.5 depth 0.5 } }");
    // 100 x 100 pixels, 2 units = 40 pixels at height 5: 1600 < 2000: the small cube; at
    // height 2.5: 6400: the big one.
    for (const float height : {5.0f, 2.5f}) {
        auto camera = OrthographicCamera::create();
        camera->position = glm::vec3(0, 0, 5);
        camera->height = height;
        camera->farDistance = 20.0f;
        PickAction pick;
        pick.setCamera(camera);
        pick.setPixel(50, 50, 100, 100);
        pick.apply(*root);
        REQUIRE(pick.picked());
        CHECK(pick.picked()->path.back()->getName() == (height == 5.0f ? "small" : "big"));
    }
    // A ray given directly has no screen: the first child.
    auto hit = pickRay(*root, {0, 0, 5}, {0, 0, -1});
    REQUIRE(hit);
    CHECK(hit->path.back()->getName() == "big");
}

TEST_CASE("picks reach into kits, copies and includes with their paths") {
    ref_ptr<Node> root = read("Separator {\n"
                              "  DEF kit ShapeKit { transform Transform { translation 3 0 0 }\n"
                              "    shape DEF ball Sphere { } }\n"
                              "  DEF row Array { numElements1 2 separation1 -3 0 0 DEF box Cube "
                              "{ } } }");
    auto hit = pickRay(*root, {3, 0, 10}, {0, 0, -1});
    REQUIRE(hit);
    CHECK(hit->path.back()->getName() == "ball");
    CHECK(std::find(hit->path.begin(), hit->path.end(), findByName(*root, "kit")) !=
          hit->path.end());
    hit = pickRay(*root, {-3, 0, 10}, {0, 0, -1}); // the Array's second copy
    REQUIRE(hit);
    CHECK(hit->path.back()->getName() == "box");
    CHECK(hit->point.x == doctest::Approx(-3.0));
}

TEST_CASE("picks reach into a File's contents, MultipleCopy's copies and Units' scale") {
    const auto dir = freshFolder("pick");
    writeText(dir / "inc.iv", "#Inventor V2.1 ascii\nDEF inside Cube { }\n");
    writeText(dir / "scene.iv",
              "#Inventor V2.1 ascii\nSeparator {\n"
              "  DEF file File { name \"inc.iv\" }\n"
              "  MultipleCopy { matrix [ 1 0 0 0 0 1 0 0 0 0 1 0 0 5 0 1 ] DEF copy Sphere { } }\n"
              "  Translation { translation 0 -5 0 } Units { units CENTIMETERS }\n"
              "  DEF small Cube { width 100 height 100 depth 100 }\n"
              "}\n");
    ref_ptr<Node> root = readScene((dir / "scene.iv").string());
    auto hit = pickRay(*root, {0, 0, 10}, {0, 0, -1});
    REQUIRE(hit);
    CHECK(hit->path.back()->getName() == "inside");
    CHECK(std::find(hit->path.begin(), hit->path.end(), findByName(*root, "file")) !=
          hit->path.end());
    hit = pickRay(*root, {0, 5, 10}, {0, 0, -1});
    REQUIRE(hit);
    CHECK(hit->path.back()->getName() == "copy");
    CHECK(hit->point.z == doctest::Approx(1.0).epsilon(1e-3));
    hit = pickRay(*root, {0.45, -5, 10}, {0, 0, -1});
    REQUIRE(hit);
    CHECK(hit->path.back()->getName() == "small"); // 100 cm wide: x in [-0.5, 0.5]
    CHECK(hit->point.z == doctest::Approx(0.5));
    CHECK(!pickRay(*root, {0.55, -5, 10}, {0, 0, -1}));
    std::filesystem::remove_all(dir);
}

TEST_CASE("searches look into kit parts, list containers, copies, LOD children and includes") {
    const auto dir = freshFolder("search");
    writeText(dir / "inc.iv", "#Inventor V2.1 ascii\nDEF included Cone { }\n");
    writeText(dir / "scene.iv", "#Inventor V2.1 ascii\nSeparator {\n"
                                "  ShapeKit { childList NodeKitListPart { containerNode Group {\n"
                                "    ShapeKit { shape DEF inner Cube { } } } } }\n"
                                "  LOD { range 1 Cube { } DEF second Cube { } }\n"
                                "  Array { numElements1 3 DEF copied Cube { } }\n"
                                "  File { name \"inc.iv\" }\n"
                                "}\n");
    ref_ptr<Node> root = readScene((dir / "scene.iv").string());
    // The kits' own default Cube, the inner kit's Cube, both LOD children, the Array's child.
    CHECK(findAll(*root, Cube::classType()).size() == 5);
    CHECK(findByName(*root, "inner"));
    CHECK(findByName(*root, "second"));
    CHECK(findByName(*root, "included"));
    SearchAction search;
    search.setName("copied");
    search.setInterest(SearchAction::Interest::All);
    search.apply(*root);
    CHECK(search.paths().size() == 3); // once per copy
    std::filesystem::remove_all(dir);
}

TEST_CASE("File reads its file relative to the scene's folder and writes only its name") {
    const auto dir = freshFolder("relative");
    writeText(dir / "sub" / "part.iv",
              "#Inventor V2.1 ascii\nSeparator { File { name \"../leaf.iv\" } Cube { } }\n");
    writeText(dir / "leaf.iv", "#Inventor V2.1 ascii\nDEF leaf Sphere { radius 3 }\n");
    const std::string text = "#Inventor V2.1 ascii\n\nSeparator {\n  File {\n"
                             "    name \"sub/part.iv\"\n  }\n}\n";
    writeText(dir / "scene.iv", text);
    ref_ptr<Node> root = readScene((dir / "scene.iv").string());
    CHECK(findByName(*root, "leaf"));
    CHECK(boxNear(computeBoundingBox(*root), {-3, -3, -3}, {3, 3, 3}));
    CHECK(writeSceneToString(*root) == text);
    // The File node keeps what it read, not as children.
    auto* file = dynamic_cast<File*>(root->children()->at(0).get());
    REQUIRE(file);
    CHECK(file->children() == nullptr);
    REQUIRE(file->contents());
    CHECK(file->contents()->isA<Separator>());

    // A name changed in code is read again when the File is next traversed (as Inventor re-reads
    // on a change), relative to the same folder.
    file->name = "leaf.iv";
    CHECK(computeBoundingBox(*root).max.x == doctest::Approx(3.0));
    CHECK(file->contents()->isA<Sphere>());
    // No name (or Inventor's undefined one): nothing, no error.
    file->name = "";
    CHECK(computeBoundingBox(*root).isEmpty());
    CHECK(!file->readError());
    std::filesystem::remove_all(dir);
}

TEST_CASE("a File that includes itself, directly or through others, is refused in one line") {
    const auto dir = freshFolder("cycle");
    writeText(dir / "self.iv", "#Inventor V2.1 ascii\nSeparator {\n  Cube { }\n"
                               "  File { name \"self.iv\" }\n}\n");
    std::string what = errorOf([&] { readScene((dir / "self.iv").string()); });
    CHECK(what.find((dir / "self.iv").string() + ":4:15: File \"self.iv\": ") == 0);
    CHECK(contains(what, "cannot include itself"));
    CHECK(!contains(what, "\n"));

    // a -> b -> c -> a: refused at c's File, with the chain.
    writeText(dir / "a.iv", "#Inventor V2.1 ascii\nFile { name \"b.iv\" }\n");
    writeText(dir / "b.iv", "#Inventor V2.1 ascii\nGroup { File { name \"sub/c.iv\" } }\n");
    writeText(dir / "sub" / "c.iv", "#Inventor V2.1 ascii\nFile { name \"../a.iv\" }\n");
    what = errorOf([&] { readScene((dir / "a.iv").string()); });
    CHECK(what.find((dir / "sub" / "c.iv").string() + ":2:13: File \"../a.iv\": ") == 0);
    CHECK(contains(what, "cannot include itself"));
    CHECK(contains(what, "a.iv -> "));
    CHECK(!contains(what, "\n"));
    // Read from b, the same cycle is found where it closes (at a's File naming b).
    what = errorOf([&] { readScene((dir / "b.iv").string()); });
    CHECK(what.find((dir / "a.iv").string() + ":2:13: File \"b.iv\": ") == 0);

    // The same file twice side by side, or down two branches, is not a cycle.
    writeText(dir / "leaf.iv", "#Inventor V2.1 ascii\nCube { }\n");
    writeText(dir / "twice.iv", "#Inventor V2.1 ascii\nSeparator { File { name \"leaf.iv\" } "
                                "File { name \"leaf.iv\" } File { name \"mid.iv\" } }\n");
    writeText(dir / "mid.iv", "#Inventor V2.1 ascii\nFile { name \"leaf.iv\" }\n");
    CHECK(findAll(*readScene((dir / "twice.iv").string()), Cube::classType()).size() == 3);
    std::filesystem::remove_all(dir);
}

TEST_CASE("errors inside an included file name that file and the File that included it") {
    const auto dir = freshFolder("bad");
    writeText(dir / "bad.iv", "#Inventor V2.1 ascii\nCube { width wide }\n");
    writeText(dir / "scene.iv",
              "#Inventor V2.1 ascii\nSeparator {\n File { name \"bad.iv\" }\n}\n");
    const std::string what = errorOf([&] { readScene((dir / "scene.iv").string()); });
    CHECK(what.find((dir / "bad.iv").string() + ":2:14: field 'width' of Cube") == 0);
    CHECK(contains(what, "included by the File at " + (dir / "scene.iv").string() + ":3:14"));
    std::filesystem::remove_all(dir);
}

TEST_CASE("a missing file is an error of the actions that need it, naming the scene and line") {
    const auto dir = freshFolder("missing");
    writeText(dir / "scene.iv", "#Inventor V2.1 ascii\nSeparator {\n  Cube { }\n  File {\n"
                                "    name \"gone.iv\"\n  }\n}\n");
    ref_ptr<Node> root = readScene((dir / "scene.iv").string()); // reading works (as Coin)
    const std::string where = (dir / "scene.iv").string() + ":5:10: File \"gone.iv\": cannot read";
    CHECK(errorOf([&] { computeBoundingBox(*root); }).find(where) == 0);
    CHECK(errorOf([&] { pickRay(*root, {0, 0, 5}, {0, 0, -1}); }).find(where) == 0);
    CHECK(contains(errorOf([&] { computeBoundingBox(*root); }), "gone.iv'"));
    // Searches and writing are fine.
    CHECK(findAll(*root, Cube::classType()).size() == 1);
    CHECK(contains(writeSceneToString(*root), "name \"gone.iv\""));
    // A folder is not a file either.
    std::filesystem::create_directories(dir / "folder.iv");
    ref_ptr<Node> folder = read("File { name \"folder.iv\" }", (dir / "x.iv").string());
    CHECK(contains(errorOf([&] { computeBoundingBox(*folder); }), "not a regular file"));
    std::filesystem::remove_all(dir);
}

TEST_CASE("a long chain of includes, and an include at the deepest nesting, read without "
          "recursion") {
    const auto dir = freshFolder("chain");
    const int files = 60;
    for (int i = 0; i < files; ++i) {
        const std::string next = i + 1 < files
                                     ? "File { name \"f" + std::to_string(i + 1) + ".iv\" }"
                                     : std::string("DEF end Cube { }");
        writeText(dir / ("f" + std::to_string(i) + ".iv"),
                  "#Inventor V2.1 ascii\nSeparator { " + next + " }\n");
    }
    ref_ptr<Node> root = readScene((dir / "f0.iv").string());
    CHECK(findByName(*root, "end"));
    // A File 999 levels deep including a file 999 levels deep: the included file is parsed
    // on a stack of its own (under AddressSanitizer two such nestings on one stack overflow).
    const int depth = maxSceneNestingDepth - 1;
    std::string deep, close;
    for (int i = 0; i < depth; ++i) {
        deep += "Group {\n";
        close += "}\n";
    }
    writeText(dir / "deep.iv", "#Inventor V2.1 ascii\n" + deep + "DEF bottom Cube { }\n" + close);
    writeText(dir / "top.iv",
              "#Inventor V2.1 ascii\n" + deep + "File { name \"deep.iv\" }\n" + close);
    root = readScene((dir / "top.iv").string());
    CHECK(findByName(*root, "bottom"));
    std::filesystem::remove_all(dir);
}

TEST_CASE("the nodes of all the files one scene includes count against the node limit") {
    const auto dir = freshFolder("limit");
    // 70,001 nodes a file: 59 of them fit in limits::maxSceneNodes (4,194,304), 60 do not.
    const std::size_t perFile = 70001;
    std::string many = "#Inventor V2.1 ascii\nSeparator {\n";
    for (std::size_t i = 1; i < perFile; ++i)
        many += "Group{}\n";
    writeText(dir / "many.iv", many + "}\n");
    REQUIRE(59 * perFile <= limits::maxSceneNodes);
    REQUIRE(60 * perFile > limits::maxSceneNodes);
    std::string files;
    for (int i = 0; i < 60; ++i)
        files += "File { name \"many.iv\" }\n";
    writeText(dir / "scene.iv", "#Inventor V2.1 ascii\nSeparator {\n" + files + "}\n");
    const std::string what = errorOf([&] { readScene((dir / "scene.iv").string()); });
    CHECK(what.find((dir / "scene.iv").string() + ":62:13: File \"many.iv\": ") == 0);
    CHECK(contains(what, "more than 4194304 nodes"));
    // The count is per read: the same scene file, now with one include, reads.
    writeText(dir / "scene.iv",
              "#Inventor V2.1 ascii\nSeparator {\n" + files.substr(0, 24) + "}\n");
    REQUIRE(files.substr(0, 24) == "File { name \"many.iv\" }\n");
    CHECK_NOTHROW(readScene((dir / "scene.iv").string()));
    std::filesystem::remove_all(dir);
}
