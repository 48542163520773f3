// Valid but hostile scenes (tests/BAD-INPUT.md, "Extreme values", "Totals", "Instances",
// "Degenerate cameras"): each renders or is refused with one line naming the scene file and
// the node, never a crash, a hang or an unbounded allocation; the GL renderer and the
// reference ray caster agree on which.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include <volsg/actions/SearchAction.h>
#include <volsg/context/OSMesaContext.h>
#include <volsg/core/Error.h>
#include <volsg/engines/AnimatedNodes.h>
#include <volsg/engines/Evaluator.h>
#include <volsg/fields/Fields.h>
#include <volsg/image/Image.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/Volume.h>
#include <volsg/render/Renderer.h>
#include <volsg/volumeio/VolumeReader.h>
#include <volsg/volumescene/ReferenceScene.h>

using namespace volsg;

namespace {

const std::string kHeader = "#Inventor V2.1 ascii\n";
const std::string kSphere =
    "VolumeData { generator SOFT_SPHERE dimensions 16 16 16 }\nTransferFunction { }\n";

/// Separators S1..Sn, each USEing the one before twice: 2^n paths to what S0 holds.
std::string doublingChain(int n) {
    std::string text;
    for (int i = 1; i <= n; ++i)
        text += "DEF S" + std::to_string(i) + " Separator { USE S" + std::to_string(i - 1) +
                " USE S" + std::to_string(i - 1) + " }\n";
    return text;
}

std::string shearWarpScene(const std::string& before, const std::string& fields = "") {
    return kHeader + "Separator {\n" + before + "\n" + kSphere + "ShearWarpVolume { " + fields +
           " VolumeObject { } }\n}\n";
}

std::string volumeScene(const std::string& before, const std::string& fields = "") {
    return kHeader + "Separator {\n" + before + "\n" + kSphere + "Volume { " + fields + " }\n}\n";
}

const std::string kOrtho = "OrthographicCamera { position 0 0 5 height 4 }";

/// What a render of the scene text does: "" when it draws, else the error's message.
struct Outcome {
    std::string gl, reference;
};

Outcome renderBoth(Node& root, bool reference = true);

Outcome renderBoth(const std::string& text, bool reference = true) {
    const ref_ptr<Node> root = readSceneFromString(text, "hostile.iv");
    return renderBoth(*root, reference);
}

Outcome renderBoth(Node& root, bool reference) {
    Outcome out;
    RenderOptions options;
    options.width = options.height = 32;
    Renderer renderer;
    try {
        (void)renderer.render(root, options);
    } catch (const Error& e) {
        out.gl = e.what();
    }
    if (!reference) return out;
    try {
        RayCastOptions rays;
        rays.tolerance = 1e-2;
        (void)renderReference(root, options, nullptr, rays);
    } catch (const Error& e) {
        out.reference = e.what();
    }
    return out;
}

/// Refused by both paths, each naming the scene file and the node at fault.
void checkRefusedByBoth(const Outcome& o, const std::string& node, const std::string& why) {
    CAPTURE(o.gl);
    CAPTURE(o.reference);
    CHECK(o.gl.rfind("hostile.iv:", 0) == 0);
    CHECK(o.gl.find(node) != std::string::npos);
    CHECK(o.gl.find(why) != std::string::npos);
    CHECK(o.reference.rfind("hostile.iv:", 0) == 0);
    CHECK(o.reference.find(why) != std::string::npos);
}

} // namespace

TEST_CASE("degenerate cameras are refused by the GL renderer and the reference alike") {
    OSMesaContext context;
    struct Case {
        const char* camera;
        const char* why;
    };
    for (const Case& c : {
             Case{"OrthographicCamera { position 0 0 5 height 0 }", "height > 0"},
             Case{"PerspectiveCamera { position 0 0 5 nearDistance 0 }", "nearDistance > 0"},
             Case{"PerspectiveCamera { position 0 0 5 heightAngle 0 }", "heightAngle"},
             Case{"PerspectiveCamera { position 0 0 5 nearDistance 10 farDistance 1 }",
                  "beyond nearDistance"},
             Case{"Transform { scaleFactor 0 1 1 } PerspectiveCamera { position 0 0 5 }",
                  "singular"},
         }) {
        CAPTURE(c.camera);
        checkRefusedByBoth(renderBoth(volumeScene(c.camera)), "Camera", c.why);
        checkRefusedByBoth(renderBoth(shearWarpScene(c.camera)), "Camera", c.why);
    }
}

TEST_CASE("extreme but valid views render without crashing, on both paths") {
    OSMesaContext context;
    for (const char* before : {
             "OrthographicCamera { position 0 0 5 height 1e17 }",
             "OrthographicCamera { position 0 0 5 height 1e-12 }",
             "OrthographicCamera { position 0 0 5 height 4 } Transform { translation 1e16 0 0 }",
             "OrthographicCamera { position 0 0 5 height 4 } Transform { scaleFactor 1e-15 1e-15 "
             "1e-15 }",
             "OrthographicCamera { position 1e30 0 5 height 4 }",
         }) {
        CAPTURE(before);
        const Outcome sw = renderBoth(shearWarpScene(before), false);
        CHECK(sw.gl.empty());
        const Outcome v = renderBoth(volumeScene(before), false);
        CHECK(v.gl.empty());
    }
}

TEST_CASE("a flattening transform above a volume is refused by every volume path") {
    OSMesaContext context;
    const std::string flat = kOrtho + " Transform { scaleFactor 1 1 0 }";
    checkRefusedByBoth(renderBoth(volumeScene(flat)), "Volume", "singular");
    checkRefusedByBoth(renderBoth(shearWarpScene(flat)), "ShearWarpVolume", "singular");
}

TEST_CASE("thread counts are clamped to the cores, not obeyed") {
    OSMesaContext context;
    CHECK(renderBoth(shearWarpScene(kOrtho, "threads 2147483647"), false).gl.empty());
}

TEST_CASE("USE chains that multiply instances stop at the traversal's instance total") {
    OSMesaContext context;
    // 41 Separators, each USEing the one before twice: 2^40 paths to the cube.
    std::string text = kHeader + "Separator {\nDEF S0 Separator { Cube { } }\n";
    text += doublingChain(40);
    text += "}\n";
    const Outcome o = renderBoth(text, false);
    CAPTURE(o.gl);
    CHECK(o.gl.rfind("hostile.iv:", 0) == 0);
    CHECK(o.gl.find("node instances") != std::string::npos);
}

TEST_CASE("100,000 USEs of one volume stop at the frame's volume total") {
    OSMesaContext context;
    std::string text = kHeader + "Separator {\n" + kSphere + "DEF V Volume { }\n";
    for (int i = 0; i < 100000; ++i)
        text += "USE V\n";
    text += "}\n";
    const Outcome o = renderBoth(text, false);
    CAPTURE(o.gl);
    CHECK(o.gl.rfind("hostile.iv:", 0) == 0);
    CHECK(o.gl.find("volume instances") != std::string::npos);
}

TEST_CASE("quality fields are bounded as a product, and a tiny texture budget gets at most 16 "
          "bricks an axis") {
    OSMesaContext context;
    CHECK(
        renderBoth(volumeScene(kOrtho, "numPlanes 100000 samplesPerPlane 256"), false).gl.empty());
    CHECK(renderBoth(volumeScene(kOrtho, "textureBudget 1"), false).gl.empty());
}

TEST_CASE("volume spacings beyond single precision are refused when the data loads") {
    OSMesaContext context;
    for (const char* spacing : {"1e18 1e18 1e18", "1e-15 1 1"}) {
        CAPTURE(spacing);
        const std::string text = kHeader + "Separator { " + kOrtho +
                                 " VolumeData { generator SOFT_SPHERE " +
                                 "dimensions 8 8 8 spacing " + spacing + " } Volume { } }\n";
        checkRefusedByBoth(renderBoth(text), "VolumeData", "volume spacing must be in");
    }
}

TEST_CASE("messages are bounded in length") {
    const Error e(std::string(3 << 20, 'x'), "file.iv", 1, 1);
    CHECK(std::string(e.what()).size() <= Error::kMaxMessageLength);
    CHECK(std::string(e.what()).rfind("file.iv:1:1: xxx", 0) == 0);
}

TEST_CASE("FLOAT values whose span overflows single precision are refused, not drawn blank") {
    OSMesaContext context;
    const auto path = std::filesystem::temp_directory_path() / "volsg-hostile-float-span.raw";
    {
        const float values[8] = {-3e38f, 3e38f, 0, 0, 0, 0, 0, 0}; // finite, span 6e38
        std::ofstream out(path, std::ios::binary);
        out.write(reinterpret_cast<const char*>(values), sizeof values);
    }
    const std::string text =
        kHeader + "Separator { " + kOrtho + " VolumeData { fileName \"" + path.string() +
        "\" dimensions 2 2 2 dataType FLOAT } TransferFunction { } Volume { } }\n";
    checkRefusedByBoth(renderBoth(text), "VolumeData", "wider than single precision");
    std::filesystem::remove(path);
}

TEST_CASE("generator errors speak of the volume, not of internal functions") {
    OSMesaContext context;
    const std::string text = kHeader + "Separator { " + kOrtho +
                             " VolumeData { generator MARSCHNER_LOBB dimensions 1 1 1 }"
                             " TransferFunction { } Volume { } }\n";
    const Outcome o = renderBoth(text);
    checkRefusedByBoth(o, "VolumeData", "the Marschner-Lobb volume needs at least 2 voxels");
    CHECK(o.gl.find("make") == std::string::npos);
}

TEST_CASE("a data file names files only inside its own folder, as glTF files do") {
    namespace fs = std::filesystem;
    const fs::path root = fs::temp_directory_path() / "volsg-hostile-contained";
    fs::remove_all(root);
    fs::create_directories(root / "inner");
    {
        std::ofstream raw(root / "outside.raw", std::ios::binary);
        raw << std::string(8, '\x10');
        std::ofstream inside(root / "inner" / "inside.raw", std::ios::binary);
        inside << std::string(8, '\x10');
    }
    const auto header = [&](const std::string& dataFile) {
        std::ofstream out(root / "inner" / "h.nhdr");
        out << "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2 2\nencoding: raw\n"
               "data file: "
            << dataFile << "\n";
        return (root / "inner" / "h.nhdr").string();
    };
    CHECK(readNrrd(header("inside.raw"))->dimensions() == glm::ivec3(2));
    for (const std::string& escape :
         {std::string("../outside.raw"), (root / "outside.raw").string()}) {
        CAPTURE(escape);
        std::string message;
        try {
            (void)readNrrd(header(escape));
        } catch (const Error& e) {
            message = e.what();
        }
        CHECK(message.find("h.nhdr") != std::string::npos);
        CHECK(message.find("only inside its own folder") != std::string::npos);
    }
    fs::create_symlink(root / "outside.raw", root / "inner" / "link.raw");
    std::string message;
    try {
        (void)readNrrd(header("link.raw"));
    } catch (const Error& e) {
        message = e.what();
    }
    CHECK(message.find("symbolic link") != std::string::npos);
    fs::remove_all(root);
}

// Found by fuzz-scenegraph: fields set to NaN or infinity through the API (the reader refuses
// them in text) reached the engines. Each is refused where the node acts, naming it.
TEST_CASE("non-finite BoxClip values set in code are refused by every volume path") {
    OSMesaContext context;
    for (const char* field : {"outsideColor", "insideColor", "insideOpacity", "outsideOpacity",
                              "insideColorWeight", "outsideColorWeight", "origin", "extent"}) {
        CAPTURE(field);
        const std::string text = volumeScene(kOrtho + " DEF B BoxClip { }");
        const ref_ptr<Node> root = readSceneFromString(text, "hostile.iv");
        Node* box = nullptr;
        for (const ref_ptr<Node>& child : *root->children())
            if (child->getName() == "B") box = child.get();
        REQUIRE(box);
        Field* f = box->field(field);
        REQUIRE(f);
        if (auto* s = dynamic_cast<SFFloat*>(f)) s->setValue(std::nanf(""));
        if (auto* c = dynamic_cast<SFColor*>(f)) c->setValue(glm::vec3(std::nanf(""), 0, 0));
        if (auto* v = dynamic_cast<SFVec3f*>(f))
            v->setValue(glm::vec3(0, std::numeric_limits<float>::infinity(), 0));
        checkRefusedByBoth(renderBoth(*root), "BoxClip", "not a finite number");
    }
}

// Found by fuzz-scenegraph: without a camera, a scene whose bounding box is too large for the
// camera made to view it all was refused as "OrthographicCamera: ..." with no file or node.
TEST_CASE("a scene too large for the camera made to view it all is refused naming its file") {
    OSMesaContext context;
    for (const char* volume : {"Volume { }", "ShearWarpVolume { VolumeObject { } }"}) {
        CAPTURE(volume);
        const std::string text = kHeader +
                                 "Separator {\nCoordinate3 { point [ -3e38 -3e38 0, 3e38 3e38 0 ] "
                                 "}\nPointSet { }\n" +
                                 kSphere + volume + "\n}\n";
        checkRefusedByBoth(renderBoth(text), "Separator", "the scene has no camera");
    }
}

// Found by fuzz-scenegraph: an AsciiText of long strings (a mesh of millions of vertices) as
// a dragger's part under a USE chain of 256 instances drew for minutes (each instance is
// drawn again). Shapes are bounded as a frame total of vertex indices.
TEST_CASE("shapes are bounded as a frame total of drawn vertices") {
    OSMesaContext context;
    // 3D text of 4000 characters (about 240,000 indices) under 2^11 instances.
    const std::string shape = "AsciiText { string \"" + std::string(4000, 'W') + "\" }";
    std::string text =
        kHeader + "Separator {\n" + kOrtho + "\nDEF S0 Separator { " + shape + " }\n";
    text += doublingChain(11);
    text += "}\n";
    const Outcome o = renderBoth(text, false);
    CAPTURE(o.gl);
    CHECK(o.gl.rfind("hostile.iv:", 0) == 0);
    CHECK(o.gl.find("Separator") != std::string::npos); // the one replaying its cache
    CHECK(o.gl.find("shape vertices in one frame") != std::string::npos);
    // 2^6 instances of the same text draw.
    std::string small =
        kHeader + "Separator {\n" + kOrtho + "\nDEF S0 Separator { " + shape + " }\n";
    small += doublingChain(6);
    small += "}\n";
    const Outcome drawn = renderBoth(small, false);
    CHECK(drawn.gl.empty());
}

// Found by fuzz-scenegraph: a Text2 of 100,000 characters under a USE chain of 4096 instances
// laid out 400 million characters in one frame (each instance is laid out again).
TEST_CASE("screen text is bounded as a frame total of characters") {
    OSMesaContext context;
    std::string text = kHeader + "Separator {\n" + kOrtho +
                       "\nDEF S0 Separator { Text2 { string \"" + std::string(100000, 'W') +
                       "\" } }\n";
    text += doublingChain(12);
    text += "}\n";
    const Outcome o = renderBoth(text, false);
    CAPTURE(o.gl);
    CHECK(o.gl.rfind("hostile.iv:", 0) == 0);
    CHECK(o.gl.find("Text2") != std::string::npos);
    CHECK(o.gl.find("screen-text characters in one frame") != std::string::npos);
    // One such text alone is drawn.
    const std::string once = kHeader + "Separator {\n" + kOrtho + "\nText2 { string \"" +
                             std::string(100000, 'W') + "\" }\n}\n";
    CHECK(renderBoth(once, false).gl.empty());
}

// Found by fuzz-scenegraph: an Array with no copies along one axis and 2^31-1 along another
// ran 2^31 empty loops in every traversal (80 s a frame under ASan); an empty Array of 65536
// copies inside another ran 2^32 (the instance total counts nodes, and it reached none).
TEST_CASE("an Array with a zero count or no children draws nothing at once") {
    OSMesaContext context;
    for (const char* counts : {"numElements1 0 numElements3 2147483647",
                               "numElements1 -479303389 numElements2 2147483647",
                               "numElements2 2147483647 numElements3 0",
                               "numElements2 65536 Array { numElements1 65536 }"}) {
        CAPTURE(counts);
        const std::string text = kHeader + "Separator {\n" + kOrtho + "\nArray { " + counts +
                                 " Cube { } }\n" + kSphere + "Volume { }\n}\n";
        const Outcome o = renderBoth(text, false);
        CHECK(o.gl.empty());
    }
}

// Found by fuzz-scenegraph (UBSan): a Blinker whose speed code set to infinity turned a NaN
// phase into an int.
TEST_CASE("a Blinker of infinite speed shows a child that exists") {
    const ref_ptr<Node> root = readSceneFromString(
        kHeader + "Separator { DEF B Blinker { Cube { } Sphere { } Cone { } } }\n", "hostile.iv");
    auto* blinker = dynamic_cast<Blinker*>(root->children()->front().get());
    REQUIRE(blinker);
    blinker->speed = std::numeric_limits<float>::infinity();
    for (double t : {0.0, 0.5, 1.0}) {
        evaluateConnections(*root, t);
        CHECK(blinker->whichChild() >= 0);
        CHECK(blinker->whichChild() < 3);
    }
}

// Found by fuzz-scenegraph's runs: a node whose message names itself was named twice
// ("Array 'N4': Array 'N4' has ...").
TEST_CASE("a render-time message names its node once") {
    OSMesaContext context;
    const Outcome o = renderBoth(kHeader + "Separator {\n" + kOrtho +
                                     "\nDEF N4 Array { numElements1 100000 numElements2 100000 "
                                     "Cube { } }\n}\n",
                                 false);
    CAPTURE(o.gl);
    CHECK(o.gl.rfind("hostile.iv:4:8: Array 'N4' has 100000 x 100000 x 1 copies", 0) == 0);
    CHECK(o.gl.find("N4", o.gl.find("N4") + 2) == std::string::npos);
}

// Found by fuzz-scenegraph (slices path): samplesPerPlane -1960023714 was clamped for drawing
// but not for the error model's choice, which then ran for minutes.
TEST_CASE("a negative samplesPerPlane is clamped for the quality choice as for drawing") {
    OSMesaContext context;
    const ref_ptr<Node> root =
        readSceneFromString(kHeader + "Separator {\n" + kOrtho + "\n" + kSphere +
                                "DEF V Volume { samplesPerPlane -1960023714 }\n}\n",
                            "hostile.iv");
    const Outcome o = renderBoth(*root, false);
    CHECK(o.gl.empty());
    const auto* volume = dynamic_cast<const Volume*>(findByName(*root, "V"));
    REQUIRE(volume);
    CHECK(volume->slicingStats().samplesPerPlane == 1);
}
