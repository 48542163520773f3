// Inventor 2.1's vertex shapes and appearance nodes, rendered from scene text and checked
// against closed-form expectations: which pixels are covered and in what colour. Every scene
// looks down -Z with an OrthographicCamera 4 units high on a 64x64 image (16 pixels per unit,
// pixel (i, j) centred at world (-2 + (i + 0.5) / 16, 2 - (j + 0.5) / 16)), and most draw
// unlit (LightModel BASE_COLOR) so colours are exact.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include <volsg/context/OSMesaContext.h>
#include <volsg/gl/GlDebug.h>
#include <volsg/image/Image.h>
#include <volsg/io/SceneReader.h>
#include <volsg/render/Renderer.h>

using namespace volsg;

namespace {

constexpr int kSize = 64;
constexpr float k8Bit = 1.0f / 255.0f;

struct Offscreen {
    OSMesaContext context;
    bool errorChecking = enableGlErrorChecking();
    Renderer renderer;

    /// Renders `body` under the standard camera (and an unlit light model unless `lit`).
    Image render(const std::string& body, bool lit = false) {
        const std::string text =
            "#Inventor V2.1 ascii\nSeparator {\n"
            "OrthographicCamera { position 0 0 5 height 4 nearDistance 1 farDistance 10 }\n" +
            std::string(lit ? "" : "LightModel { model BASE_COLOR }\n") + body + "\n}\n";
        const ref_ptr<Node> root = readSceneFromString(text);
        RenderOptions options;
        options.width = options.height = kSize;
        return renderer.render(*root, options);
    }
};

/// The pixel whose centre is nearest world (x, y).
glm::vec3 at(const Image& image, double x, double y) {
    const int i = int(std::floor((x + 2.0) * 16.0)), j = int(std::floor((2.0 - y) * 16.0));
    return glm::vec3(image.at(i, j));
}

bool near(glm::vec3 a, glm::vec3 b, float tolerance = 1.5f * k8Bit) {
    return glm::all(glm::lessThanEqual(glm::abs(a - b), glm::vec3(tolerance)));
}

int coveredPixels(const Image& image) {
    int n = 0;
    for (const glm::vec4& p : image.pixels)
        if (glm::vec3(p) != glm::vec3(0.0f)) ++n;
    return n;
}

const std::string kTwoSquares = R"(
Coordinate3 { point [ -1.5 -0.5 0, -0.5 -0.5 0, -0.5 0.5 0, -1.5 0.5 0,
                      0.5 -0.5 0, 1.5 -0.5 0, 1.5 0.5 0, 0.5 0.5 0 ] }
)";

} // namespace

TEST_CASE("FaceSet with PER_FACE materials colours each face with its own material") {
    Offscreen gl;
    const Image image = gl.render(kTwoSquares + R"(
        Material { diffuseColor [ 1 0 0, 0 0 1 ] }
        MaterialBinding { value PER_FACE }
        FaceSet { numVertices [ 4, 4 ] })");
    CHECK(near(at(image, -1, 0), {1, 0, 0}));
    CHECK(near(at(image, 1, 0), {0, 0, 1}));
    CHECK(near(at(image, 0, 0), {0, 0, 0})); // the gap between them
    // 2 unit squares at 16 pixels per unit: 512 pixels (edges on pixel boundaries).
    CHECK(coveredPixels(image) == 512);
}

TEST_CASE("OVERALL binding uses the first material, BaseColor replaces only the diffuse") {
    Offscreen gl;
    const Image overall = gl.render(kTwoSquares + R"(
        Material { diffuseColor [ 0 1 0, 0 0 1 ] }
        FaceSet { numVertices [ 4, 4 ] })");
    CHECK(near(at(overall, -1, 0), {0, 1, 0}));
    CHECK(near(at(overall, 1, 0), {0, 1, 0}));
    const Image base = gl.render(kTwoSquares + R"(
        Material { diffuseColor 1 0 0 }
        BaseColor { rgb [ 1 1 0, 0 1 1 ] }
        MaterialBinding { value PER_PART }
        FaceSet { numVertices [ 4, 4 ] })");
    CHECK(near(at(base, -1, 0), {1, 1, 0}));
    CHECK(near(at(base, 1, 0), {0, 1, 1}));
}

TEST_CASE("each face takes its own material's transparency under PER_FACE") {
    Offscreen gl;
    const Image image = gl.render(kTwoSquares + R"(
        Material { diffuseColor [ 1 0 0, 0 0 1 ] transparency [ 0.5, 0 ] }
        MaterialBinding { value PER_FACE }
        FaceSet { numVertices [ 4, 4 ] })");
    CHECK(near(at(image, -1, 0), {0.5f, 0, 0})); // half over the black background
    CHECK(near(at(image, 1, 0), {0, 0, 1}));     // opaque, not the first material's alpha
}

TEST_CASE("diffuse colours above 1 are clamped before lighting, as Coin packs them") {
    Offscreen gl;
    // A light 60 degrees off the normal: N.L = 0.5, so 1.7 would light to 0.85, clamped 0.5.
    const Image image = gl.render(kTwoSquares + R"(
        DirectionalLight { direction 0 -0.8660254 -0.5 }
        Material { ambientColor 0 0 0 specularColor 0 0 0 diffuseColor 1.7 0.6 0 }
        FaceSet { numVertices [ 4, 4 ] })",
                                  true);
    CHECK(near(at(image, -1, 0), {0.5f, 0.3f, 0.0f}));
}

TEST_CASE("IndexedFaceSet PER_VERTEX_INDEXED materials interpolate across a face") {
    Offscreen gl;
    const Image image = gl.render(R"(
        Coordinate3 { point [ -1 -1 0, 1 -1 0, 1 1 0, -1 1 0 ] }
        Material { diffuseColor [ 0 0 0, 1 1 1 ] }
        MaterialBinding { value PER_VERTEX_INDEXED }
        IndexedFaceSet { coordIndex [ 0, 1, 2, 3, -1 ] materialIndex [ 0, 1, 1, 0, -1 ] })");
    // Black on the left edge, white on the right: linear in x (within the triangle split).
    for (double x : {-0.75, -0.25, 0.25, 0.75}) {
        const float expected = float((x + 1.0) / 2.0);
        CHECK(std::abs(at(image, x, 0.03).r - expected) < 0.03f);
    }
}

TEST_CASE("VertexProperty as a field supplies points, packed colours and their binding") {
    Offscreen gl;
    const Image image = gl.render(R"(
        IndexedFaceSet {
          vertexProperty VertexProperty {
            vertex [ -1.5 -0.5 0, -0.5 -0.5 0, -0.5 0.5 0, -1.5 0.5 0,
                     0.5 -0.5 0, 1.5 -0.5 0, 1.5 0.5 0, 0.5 0.5 0 ]
            orderedRGBA [ 0xff0000ff, 0x00ff00ff ]
            materialBinding PER_FACE
          }
          coordIndex [ 0, 1, 2, 3, -1, 4, 5, 6, 7, -1 ]
        })");
    CHECK(near(at(image, -1, 0), {1, 0, 0}));
    CHECK(near(at(image, 1, 0), {0, 1, 0}));
}

TEST_CASE("TriangleStripSet and QuadMesh cover what their triangles and quads cover") {
    Offscreen gl;
    // A strip of 4 points making the unit square at the origin's upper right.
    const Image strip = gl.render(R"(
        BaseColor { rgb 1 1 1 }
        Coordinate3 { point [ 0 0 0, 0 1 0, 1 0 0, 1 1 0 ] }
        TriangleStripSet { numVertices 4 })");
    CHECK(coveredPixels(strip) == 256);
    CHECK(near(at(strip, 0.5, 0.5), {1, 1, 1}));
    // A 3 x 3 quad mesh over [-1, 1]^2 with a material per row.
    const Image quads = gl.render(R"(
        Material { diffuseColor [ 1 0 0, 0 1 0 ] }
        MaterialBinding { value PER_PART }
        Coordinate3 { point [ -1 -1 0, 0 -1 0, 1 -1 0, -1 0 0, 0 0 0, 1 0 0, -1 1 0, 0 1 0, 1 1 0 ] }
        QuadMesh { verticesPerRow 3 verticesPerColumn 3 })");
    CHECK(coveredPixels(quads) == 32 * 32);
    CHECK(near(at(quads, 0.5, -0.5), {1, 0, 0}));
    CHECK(near(at(quads, 0.5, 0.5), {0, 1, 0}));
}

TEST_CASE("PointSet draws one pixel per point, sized by DrawStyle pointSize") {
    Offscreen gl;
    const std::string points = R"(
        BaseColor { rgb 1 1 1 }
        Coordinate3 { point [ -1.0 -1.0 0, 0.5 0.5 0, 1.0 -0.75 0 ] })";
    CHECK(coveredPixels(gl.render(points + "PointSet { }")) == 3);
    CHECK(coveredPixels(gl.render(points + "PointSet { startIndex 1 }")) == 2);
    CHECK(coveredPixels(gl.render(points + "DrawStyle { pointSize 3 } PointSet { }")) == 27);
}

TEST_CASE("LineSet PER_PART colours each segment, lineWidth widens the lines") {
    Offscreen gl;
    const Image image = gl.render(R"(
        Material { diffuseColor [ 1 0 0, 0 0 1 ] }
        MaterialBinding { value PER_PART }
        Coordinate3 { point [ -1.5 0.01 0, 0.01 0.01 0, 1.5 0.01 0 ] }
        LineSet { numVertices 3 })");
    CHECK(near(at(image, -1, 0.01), {1, 0, 0}));
    CHECK(near(at(image, 1, 0.01), {0, 0, 1}));
    const int thin = coveredPixels(image);
    CHECK(thin >= 46);
    CHECK(thin <= 49); // 3 units at 16 pixels per unit, one pixel wide
    const int wide = coveredPixels(gl.render(R"(
        BaseColor { rgb 1 1 1 } DrawStyle { lineWidth 3 }
        Coordinate3 { point [ -1.5 0.01 0, 1.5 0.01 0 ] } LineSet { })"));
    CHECK(wide >= 3 * 46);
    CHECK(wide <= 3 * 50);
}

TEST_CASE("DrawStyle LINES outlines polygons, POINTS draws their corners, INVISIBLE nothing") {
    Offscreen gl;
    const std::string square = R"(
        BaseColor { rgb 1 1 1 }
        Coordinate3 { point [ -1 -1 0, 1 -1 0, 1 1 0, -1 1 0 ] })";
    const Image filled = gl.render(square + "FaceSet { }");
    CHECK(coveredPixels(filled) == 32 * 32);
    const Image lines = gl.render(square + "DrawStyle { style LINES } FaceSet { }");
    CHECK(near(at(lines, 0, 0), {0, 0, 0})); // hollow
    CHECK(coveredPixels(lines) > 100);       // four 32-pixel sides (and the fan's diagonal)
    CHECK(coveredPixels(lines) < 200);
    CHECK(coveredPixels(gl.render(square + "DrawStyle { style POINTS } FaceSet { }")) <= 4);
    CHECK(coveredPixels(gl.render(square + "DrawStyle { style INVISIBLE } FaceSet { }")) == 0);
}

TEST_CASE("ShapeHints SOLID with a known ordering culls back faces, unknown draws both") {
    Offscreen gl;
    // Clockwise seen from the camera (+Z): a back face under COUNTERCLOCKWISE.
    const std::string backFacing = R"(
        BaseColor { rgb 1 1 1 }
        Coordinate3 { point [ -1 -1 0, -1 1 0, 1 1 0, 1 -1 0 ] })";
    CHECK(coveredPixels(gl.render(backFacing + "FaceSet { }")) == 32 * 32);
    CHECK(coveredPixels(gl.render(
              backFacing +
              "ShapeHints { vertexOrdering COUNTERCLOCKWISE shapeType SOLID } FaceSet { }")) == 0);
    CHECK(coveredPixels(gl.render(
              backFacing +
              "ShapeHints { vertexOrdering CLOCKWISE shapeType SOLID } FaceSet { }")) == 32 * 32);
}

TEST_CASE("Coordinate4 points are divided by w") {
    Offscreen gl;
    const Image image = gl.render(R"(
        BaseColor { rgb 1 1 1 }
        Coordinate4 { point [ 0 0 0 2, 2 0 0 2, 2 2 0 2, 0 2 0 2 ] }
        FaceSet { })");
    CHECK(coveredPixels(image) == 256); // the unit square [0, 1]^2
    CHECK(near(at(image, 0.5, 0.5), {1, 1, 1}));
    CHECK(near(at(image, 1.5, 0.5), {0, 0, 0}));
}

TEST_CASE("Texture2 with an inline image maps its texels by the texture coordinates") {
    Offscreen gl;
    // A 2 x 2 image, rows bottom up: red, green / blue, white. The square [-1, 1]^2 takes it
    // whole by Coin's default coordinates over its box: on a square the tie puts s along y and
    // t along x (SoTextureCoordinateBundle; toys/top.iv in inventor-data shows it).
    const std::string textured = R"(
        BaseColor { rgb 1 1 1 }
        Texture2 { image 2 2 3 0xff0000 0x00ff00 0x0000ff 0xffffff  wrapS CLAMP wrapT CLAMP }
        Coordinate3 { point [ -1 -1 0, 1 -1 0, 1 1 0, -1 1 0 ] }
        FaceSet { })";
    const Image image = gl.render(textured);
    // Texel centres are a quarter of the square from each edge; the pixel centres nearest to
    // them are 1/64 of the square off, so bilinear filtering blends in 2/64 of each neighbour (up
    // to 0.06 per channel).
    CHECK(near(at(image, -0.5, -0.5), {1, 0, 0}, 0.07f));
    CHECK(near(at(image, 0.5, -0.5), {0, 0, 1}, 0.07f));
    CHECK(near(at(image, -0.5, 0.5), {0, 1, 0}, 0.07f));
    CHECK(near(at(image, 0.5, 0.5), {1, 1, 1}, 0.07f));
    // MODULATE by a grey base colour halves every texel.
    const Image grey = gl.render(R"(
        BaseColor { rgb 0.5 0.5 0.5 }
        Texture2 { image 1 1 3 0xffff00 }
        Coordinate3 { point [ -1 -1 0, 1 -1 0, 1 1 0, -1 1 0 ] }
        FaceSet { })");
    CHECK(near(at(grey, 0, 0), {0.5f, 0.5f, 0.0f}, 0.01f));
    // Texture2Transform translation 0.5 in s moves the red texel to the right half.
    const Image moved = gl.render(R"(
        BaseColor { rgb 1 1 1 }
        Texture2 { image 2 1 3 0xff0000 0x0000ff  wrapS REPEAT }
        Texture2Transform { translation 0.5 0 }
        TextureCoordinate2 { point [ 0 0, 1 0, 1 1, 0 1 ] }
        Coordinate3 { point [ -1 -1 0, 1 -1 0, 1 1 0, -1 1 0 ] }
        FaceSet { })");
    // s' = s + 0.5: the left quarter (s ~ 0.25) samples s' = 0.75, the blue texel.
    CHECK(near(at(moved, -0.5, 0), {0, 0, 1}, 0.07f));
    CHECK(near(at(moved, 0.5, 0), {1, 0, 0}, 0.07f));
}

TEST_CASE("TextureCoordinatePlane maps s and t from the local coordinates") {
    Offscreen gl;
    const Image image = gl.render(R"(
        BaseColor { rgb 1 1 1 }
        Texture2 { image 2 1 3 0xff0000 0x0000ff  wrapS CLAMP }
        TextureCoordinatePlane { directionS 0.5 0 0 directionT 0 0.5 0 }
        Coordinate3 { point [ 0 0 0, 2 0 0, 2 1 0, 0 1 0 ] }
        FaceSet { })");
    CHECK(near(at(image, 0.5, 0.5), {1, 0, 0}, 0.07f)); // s = 0.25
    CHECK(near(at(image, 1.5, 0.5), {0, 0, 1}, 0.07f)); // s = 0.75
}

TEST_CASE("a SpotLight lights inside its cone only") {
    Offscreen gl;
    // A white plane at z = 0 facing +Z; a spot at (0, 0, 2) pointing down -Z with a 30 degree
    // half angle lights the disk of radius 2 tan(30) = 1.155 around the origin.
    const Image image = gl.render(R"(
        SpotLight { location 0 0 2 direction 0 0 -1 cutOffAngle 0.5235988 }
        Material { diffuseColor 1 1 1 ambientColor 0 0 0 }
        Coordinate3 { point [ -2 -2 0, 2 -2 0, 2 2 0, -2 2 0 ] }
        FaceSet { })",
                                  true);
    CHECK(at(image, 0, 0).r > 0.95f);   // straight below: N.L = 1
    CHECK(at(image, 1.0, 0).r > 0.5f);  // inside the cone
    CHECK(at(image, 1.4, 0).r < k8Bit); // outside
    CHECK(at(image, 0, -1.4).r < k8Bit);
}

TEST_CASE("Environment HAZE fog fades to the fog colour linearly with distance") {
    Offscreen gl;
    // The camera is 5 units from z = 0; with fogVisibility 10 half the colour remains.
    const Image image = gl.render(R"(
        Environment { fogType HAZE fogColor 0 0 1 fogVisibility 10 }
        BaseColor { rgb 1 0 0 }
        Coordinate3 { point [ -1 -1 0, 1 -1 0, 1 1 0, -1 1 0 ] }
        FaceSet { })");
    CHECK(near(at(image, 0, 0), {0.5f, 0.0f, 0.5f}, 0.01f));
}

TEST_CASE("Environment ambient light scales the materials' ambient colour") {
    Offscreen gl;
    // No light on: the headlight is added; a plane facing away from it... is lit two-sided, so
    // use an emissive-free material with zero diffuse: only the ambient term remains.
    const Image image = gl.render(R"(
        Environment { ambientIntensity 0.5 ambientColor 1 0.5 0 }
        Material { ambientColor 1 1 1 diffuseColor 0 0 0 }
        Coordinate3 { point [ -1 -1 0, 1 -1 0, 1 1 0, -1 1 0 ] }
        FaceSet { })",
                                  true);
    CHECK(near(at(image, 0, 0), {0.5f, 0.25f, 0.0f}, 0.01f));
}

TEST_CASE("Complexity sets the tessellation of round primitives") {
    Offscreen gl;
    // Seen from the side, Coin's sphere of radius 1.5 covers about the disk at complexity 1
    // (30 x 29: within 1%) and at the default 0.5 (15 x 14: within 2.5%); at complexity 0 it
    // is an octahedron (4 slices, poles and one ring) whose outline is a square of corners on
    // the axes: area 2 r^2.
    const std::string sphere = "BaseColor { rgb 1 1 1 } Sphere { radius 1.5 }";
    const int finest = coveredPixels(gl.render("Complexity { value 1 } " + sphere));
    const int standard = coveredPixels(gl.render(sphere));
    const int coarse = coveredPixels(gl.render("Complexity { value 0 } " + sphere));
    const double disk = std::acos(-1.0) * 1.5 * 1.5 * 256.0;
    CHECK(std::abs(finest - disk) / disk < 0.01);
    CHECK(std::abs(standard - disk) / disk < 0.025);
    const double square = 2.0 * 1.5 * 1.5 * 256.0;
    CHECK(std::abs(coarse - square) / square < 0.02);
}
