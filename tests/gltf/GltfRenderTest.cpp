// GltfModel in the render passes and the other actions, against analytic expectations: colours
// of unlit and lit quads, a MASK cutoff edge, texels at known pixels, sampler wraps, a normal
// map, BLEND ordering, clipping, a mesh inside a volume against the reference renderer, the
// sample files' silhouettes, picking, bounding boxes, search and write.
#include <doctest/doctest.h>

#include "support/Offscreen.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>

#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/actions/PickAction.h>
#include <volsg/actions/SearchAction.h>
#include <volsg/context/OSMesaContext.h>
#include <volsg/core/Error.h>
#include <volsg/gl/GlDebug.h>
#include <volsg/gltf/GltfAsset.h>
#include <volsg/image/Image.h>
#include <volsg/io/GraphCompare.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/SceneWriter.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/GltfModel.h>
#include <volsg/nodes/Separator.h>
#include <volsg/render/Renderer.h>
#include <volsg/volumescene/ReferenceScene.h>

#include "GltfTestFiles.h"

using namespace volsg;
using namespace volsg::test;

namespace {

constexpr float k8Bit = 1.0f / 255.0f;
constexpr int kSize = 64;
/// With the orthographic camera below, one world unit is this many pixels.
constexpr float kPixelsPerUnit = kSize / 2.5f;

using volsg::test::Offscreen;

std::string sample(const std::string& relative) {
    return std::string(VOLSG_DATA_DIR) + "/gltf/" + relative;
}

/// Keeps an image for a look when VOLSG_TEST_IMAGES names a folder.
void keepImage(const Image& image, const std::string& name) {
    if (const char* folder = std::getenv("VOLSG_TEST_IMAGES"))
        writePng(std::string(folder) + "/gltf-" + name + ".png", image);
}

/// A scene: an orthographic camera on +z looking down -z (2.5 units high), `body` after it.
ref_ptr<Node> scene(const std::string& body) {
    return readSceneFromString("#Inventor V2.1 ascii\nSeparator {\n"
                               "OrthographicCamera { position 0 0 5 height 2.5 "
                               "nearDistance 1 farDistance 10 }\n" +
                               body + "\n}\n");
}

std::string model(const std::string& path) {
    return "GltfModel { fileName \"" + path + "\" }";
}

Image render(Offscreen& o, Node& root, glm::vec3 background = glm::vec3(0.0f), int size = kSize) {
    RenderOptions options;
    options.width = options.height = size;
    options.background = background;
    return o.renderer.render(root, options);
}

/// The pixel whose centre is nearest the world point (x, y) of the z = 0 plane.
glm::vec4 at(const Image& image, float x, float y) {
    const int px = int(std::floor(kSize / 2.0f + x * kPixelsPerUnit));
    const int py = int(std::floor(kSize / 2.0f - y * kPixelsPerUnit));
    return image.at(px, py);
}

bool close(glm::vec3 a, glm::vec3 b, float tolerance) {
    return glm::all(glm::lessThanEqual(glm::abs(a - b), glm::vec3(tolerance)));
}

/// The smallest rectangle of pixels that differ from `background` (min x, min y, max x, max y).
glm::ivec4 coveredRect(const Image& image, glm::vec3 background) {
    glm::ivec4 r(-1);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            if (close(glm::vec3(image.at(x, y)), background, 1e-6f)) continue;
            if (r.x < 0) r = {x, y, x, y};
            r = {std::min(r.x, x), std::min(r.y, y), std::max(r.z, x), std::max(r.w, y)};
        }
    return r;
}

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

/// A quad file with a material (JSON) and extra attributes; returns the path.
std::string quadFile(const std::string& name, const std::string& material,
                     const std::string& extraAttributes = "", GltfBuilder* builder = nullptr,
                     const std::string& extraTopLevel = "") {
    GltfBuilder local;
    GltfBuilder& b = builder ? *builder : local;
    const Quad q;
    const int pos = b.addPositions(q.positions);
    const int nor = b.addAccessor(q.normals, kFloat, "VEC3", 4);
    const int uv = b.addAccessor(q.uvs, kFloat, "VEC2", 4);
    const int idx = b.addAccessor(q.indices, kUShort, "SCALAR", 6);
    std::string rest =
        "\"materials\":[" + material +
        "],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
        ",\"NORMAL\":" + std::to_string(nor) + ",\"TEXCOORD_0\":" + std::to_string(uv) +
        extraAttributes + "},\"indices\":" + std::to_string(idx) + ",\"material\":0}]}]," +
        kOneNodeScene;
    if (!extraTopLevel.empty()) rest += "," + extraTopLevel;
    return b.writeGltf(name, rest);
}

/// An RGB PNG of w x h texels given as 0..255 values, row 0 at the top.
std::string pngFile(const std::string& name, int w, int h, const std::vector<glm::ivec3>& texels) {
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            image.at(x, y) = glm::vec4(glm::vec3(texels[std::size_t(y * w + x)]) / 255.0f, 1.0f);
    const auto path = gltfScratch() / name;
    writePng(path.string(), image);
    return path.string();
}

const char* kUnlit = "\"extensions\":{\"KHR_materials_unlit\":{}}";

} // namespace

TEST_CASE("an unlit quad shows its base colour factor over exactly its pixels") {
    Offscreen o;
    const std::string path =
        quadFile("unlit.gltf",
                 std::string("{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.25,0.5,0.75,1]},") +
                     kUnlit + "}");
    const ref_ptr<Node> root = scene(model(path));
    const Image image = render(o, *root);
    keepImage(image, "unlit");
    // Pixel centres inside [-1, 1]^2: 32 -/+ 25.6 covers centres 6.5 .. 57.5.
    CHECK(coveredRect(image, glm::vec3(0.0f)) == glm::ivec4(6, 6, 57, 57));
    CHECK(close(glm::vec3(image.at(32, 32)), {0.25f, 0.5f, 0.75f}, 1e-6f));
    CHECK(close(glm::vec3(image.at(7, 56)), {0.25f, 0.5f, 0.75f}, 1e-6f));
}

TEST_CASE("a MASK cutoff cuts a quad where its vertex alpha crosses the cutoff") {
    Offscreen o;
    GltfBuilder b;
    // COLOR_0 as normalized unsigned bytes: alpha 0 on the left edge, 1 on the right.
    const std::vector<std::uint8_t> colors{255, 255, 255, 0,   255, 255, 255, 255,
                                           255, 255, 255, 255, 255, 255, 255, 0};
    const int color = b.addAccessor(colors, kUByte, "VEC4", 4, true);
    const std::string path =
        quadFile("mask.gltf",
                 std::string("{\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,0.5,0.25,1]},"
                             "\"alphaMode\":\"MASK\",\"alphaCutoff\":0.25,") +
                     kUnlit + "}",
                 ",\"COLOR_0\":" + std::to_string(color), &b);
    const ref_ptr<Node> root = scene(model(path));
    const Image image = render(o, *root, glm::vec3(0.0f, 0.0f, 1.0f));
    keepImage(image, "mask");
    // alpha(x) = (x + 1) / 2 = 0.25 at x = -0.5, pixel 32 - 12.8 = 19.2: centres 18.5 and
    // 19.5 fall either side.
    for (int y = 8; y < 56; ++y) {
        CAPTURE(y);
        CHECK(close(glm::vec3(image.at(18, y)), {0, 0, 1}, 1e-6f));
        CHECK(close(glm::vec3(image.at(19, y)), {1, 0.5f, 0.25f}, 1e-6f)); // opaque: alpha 1
    }
}

TEST_CASE("texels land on the pixels their UVs name, decoded from sRGB") {
    Offscreen o;
    // 4 x 4 texels, all different, NEAREST; the first row is the top of the quad (v = 0).
    std::vector<glm::ivec3> texels;
    for (int i = 0; i < 16; ++i)
        texels.push_back({16 * i, 255 - 16 * i, (i * 67) % 256});
    const std::string png = pngFile("checker.png", 4, 4, texels);
    const std::string material =
        std::string("{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}},") + kUnlit +
        "}";
    const std::string textures = "\"samplers\":[{\"magFilter\":9728,\"minFilter\":9728}],"
                                 "\"textures\":[{\"source\":0,\"sampler\":0}],";

    // External PNG next to a .gltf, and the same PNG inside a .glb's buffer.
    GltfBuilder external;
    const std::string gltf = quadFile("texture.gltf", material, "", &external,
                                      textures + "\"images\":[{\"uri\":\"checker.png\"}]");
    std::ifstream in(png, std::ios::binary);
    const std::vector<std::uint8_t> pngBytes((std::istreambuf_iterator<char>(in)),
                                             std::istreambuf_iterator<char>());
    GltfBuilder embedded;
    const int view = embedded.addView(pngBytes);
    const Quad q;
    const int pos = embedded.addPositions(q.positions);
    const int uv = embedded.addAccessor(q.uvs, kFloat, "VEC2", 4);
    const int idx = embedded.addAccessor(q.indices, kUShort, "SCALAR", 6);
    const std::string glb = embedded.writeGlb(
        "texture.glb", "\"materials\":[" + material + "]," + textures +
                           "\"images\":[{\"bufferView\":" + std::to_string(view) +
                           ",\"mimeType\":\"image/png\"}],\"meshes\":[{\"primitives\":[{"
                           "\"attributes\":{\"POSITION\":" +
                           std::to_string(pos) + ",\"TEXCOORD_0\":" + std::to_string(uv) +
                           "},\"indices\":" + std::to_string(idx) + ",\"material\":0}]}]," +
                           kOneNodeScene);

    for (const std::string& path : {gltf, glb}) {
        CAPTURE(path);
        const ref_ptr<Node> root = scene(model(path));
        const Image image = render(o, *root);
        keepImage(image, std::filesystem::path(path).extension().string().substr(1));
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 4; ++i) {
                CAPTURE(i);
                CAPTURE(j);
                const glm::ivec3 t = texels[std::size_t(j * 4 + i)];
                const glm::vec3 expected(srgbToLinear(t.r / 255.0f), srgbToLinear(t.g / 255.0f),
                                         srgbToLinear(t.b / 255.0f));
                // Texel (i, j) covers x in -1 + 0.5 [i, i+1], y in 1 - 0.5 [j+1, j].
                const glm::vec4 p = at(image, -0.75f + 0.5f * i, 0.75f - 0.5f * j);
                CHECK(close(glm::vec3(p), expected, 2e-3f));
            }
    }
}

TEST_CASE("sampler wrap modes repeat, clamp and mirror UVs beyond 1") {
    Offscreen o;
    // Two texels, black and white; u runs 0..2 across the quad, so each quarter is one texel.
    const std::string png = pngFile("two.png", 2, 1, {{0, 0, 0}, {255, 255, 255}});
    (void)png;
    struct Case {
        int wrap;
        float quarters[4];
    };
    const Case cases[] = {{10497, {0, 1, 0, 1}}, {33071, {0, 1, 1, 1}}, {33648, {0, 1, 1, 0}}};
    for (const Case& c : cases) {
        CAPTURE(c.wrap);
        GltfBuilder b;
        const std::vector<glm::vec2> uvs{{0, 1}, {2, 1}, {2, 0}, {0, 0}};
        const int uv = b.addAccessor(uvs, kFloat, "VEC2", 4);
        const Quad q;
        const int pos = b.addPositions(q.positions);
        const int idx = b.addAccessor(q.indices, kUShort, "SCALAR", 6);
        const std::string path = b.writeGltf(
            "wrap.gltf",
            std::string("\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{"
                        "\"index\":0}},") +
                kUnlit + "}],\"samplers\":[{\"magFilter\":9728,\"minFilter\":9728,\"wrapS\":" +
                std::to_string(c.wrap) +
                "}],\"textures\":[{\"source\":0,\"sampler\":0}],\"images\":[{\"uri\":\"two.png\"}],"
                "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":" +
                std::to_string(pos) + ",\"TEXCOORD_0\":" + std::to_string(uv) +
                "},\"indices\":" + std::to_string(idx) + ",\"material\":0}]}]," + kOneNodeScene);
        const ref_ptr<Node> root = scene(model(path));
        const Image image = render(o, *root, glm::vec3(0.5f));
        for (int k = 0; k < 4; ++k) {
            CAPTURE(k);
            CHECK(close(glm::vec3(at(image, -0.75f + 0.5f * k, 0.0f)), glm::vec3(c.quarters[k]),
                        1e-6f));
        }
    }
}

TEST_CASE("LINEAR magnification blends neighbouring texels after sRGB decoding") {
    Offscreen o;
    pngFile("pair.png", 2, 1, {{0, 0, 0}, {255, 255, 255}});
    for (const int filter : {9728, 9729}) {
        CAPTURE(filter);
        const std::string path = quadFile(
            "filter.gltf",
            std::string("{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}},") +
                kUnlit + "}",
            "", nullptr,
            "\"samplers\":[{\"magFilter\":" + std::to_string(filter) +
                ",\"minFilter\":9728,\"wrapS\":33071,\"wrapT\":33071}],"
                "\"textures\":[{\"source\":0,\"sampler\":0}],\"images\":[{\"uri\":\"pair.png\"}]");
        const Image image = render(o, *scene(model(path)), glm::vec3(0.5f));
        // u = (x + 1) / 2; texel centres at u = 0.25 and 0.75. The pixel centre nearest
        // x = -0.25 is at u = 0.3848: LINEAR weight (u - 0.25) * 2 of the white texel.
        const float x = (std::floor(kSize / 2.0f - 0.25f * kPixelsPerUnit) + 0.5f - kSize / 2.0f) /
                        kPixelsPerUnit;
        const float u = (x + 1.0f) / 2.0f;
        const float expected = filter == 9729 ? (u - 0.25f) * 2.0f : 0.0f;
        CHECK(std::abs(at(image, -0.25f, 0.0f).r - expected) < 2.0f * k8Bit);
        CHECK(std::abs(at(image, 0.9f, 0.0f).r - 1.0f) < 1e-5f); // clamped beyond the centre
    }
}

TEST_CASE("a normal map turns a flat quad's shading as the BRDF says") {
    Offscreen o;
    // Light along -x (towards the light is +x): the flat quad facing +z gets N.L = 0. A normal
    // map tilting N by angle t towards +x (tangent u = +x) gives N.L = sin t.
    const float tilt = 0.6f;
    const glm::ivec3 texel(int(std::lround((std::sin(tilt) * 0.5f + 0.5f) * 255.0f)), 128,
                           int(std::lround((std::cos(tilt) * 0.5f + 0.5f) * 255.0f)));
    const glm::ivec3 away(255 - texel.x, 128, texel.z); // tilted towards -x
    pngFile("normal.png", 1, 1, {texel});
    pngFile("away.png", 1, 1, {away});
    const float base = 0.8f;
    auto expected = [&](glm::ivec3 t) {
        glm::vec3 n = glm::vec3(t) / 255.0f * 2.0f - 1.0f;
        n = glm::normalize(n); // the tangent frame here is the identity
        const float NdotL = n.x, NdotV = n.z;
        const float ambient = 0.2f * base;
        if (NdotL <= 0.0f) return ambient;
        // roughness 1, metallic 0: D = 1/pi, Vis = 0.5 / (N.L + N.V), F at V.H = 1/sqrt 2.
        const float F = 0.04f + 0.96f * std::pow(1.0f - std::sqrt(0.5f), 5.0f);
        return ambient + (1.0f - F) * base * NdotL + F * 0.5f / (NdotL + NdotV) * NdotL;
    };
    const std::string light = "DirectionalLight { direction -1 0 0 }\n";
    const std::string material =
        "{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.8,0.8,0.8,1],\"metallicFactor\":0},"
        "\"normalTexture\":{\"index\":0}}";
    auto textures = [](const char* image) {
        return std::string("\"textures\":[{\"source\":0}],\"images\":[{\"uri\":\"") + image +
               "\"}]";
    };
    const std::string flat = quadFile(
        "flat.gltf",
        "{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.8,0.8,0.8,1],\"metallicFactor\":0}}");
    const std::string mapped =
        quadFile("mapped.gltf", material, "", nullptr, textures("normal.png"));
    const std::string mappedAway =
        quadFile("away.gltf", material, "", nullptr, textures("away.png"));
    // The same with a TANGENT attribute (u along +x, w = 1) instead of derivatives.
    GltfBuilder tb;
    const std::vector<glm::vec4> tangents(4, glm::vec4(1, 0, 0, 1));
    const int tangent = tb.addAccessor(tangents, kFloat, "VEC4", 4);
    const std::string withTangents =
        quadFile("tangents.gltf", material, ",\"TANGENT\":" + std::to_string(tangent), &tb,
                 textures("normal.png"));

    const Image imageFlat = render(o, *scene(light + model(flat)));
    const Image imageMapped = render(o, *scene(light + model(mapped)));
    const Image imageAway = render(o, *scene(light + model(mappedAway)));
    const Image imageTangents = render(o, *scene(light + model(withTangents)));
    keepImage(imageMapped, "normal-map");
    const float lit = expected(texel);
    MESSAGE("flat " << imageFlat.at(32, 32).r << ", mapped " << imageMapped.at(32, 32).r
                    << " (expected " << lit << ")");
    CHECK(lit > 0.2f * base + 0.3f); // the test means something
    for (const glm::ivec2 p : {glm::ivec2(20, 20), glm::ivec2(32, 32), glm::ivec2(50, 40)}) {
        CHECK(std::abs(imageFlat.at(p.x, p.y).r - 0.2f * base) < 1e-5f);
        CHECK(std::abs(imageMapped.at(p.x, p.y).r - lit) < 2e-3f);
        CHECK(std::abs(imageTangents.at(p.x, p.y).r - lit) < 2e-3f);
        CHECK(std::abs(imageAway.at(p.x, p.y).r - expected(away)) < 1e-5f);
    }
}

TEST_CASE("lit materials follow the documented BRDF under the headlight and Inventor lights") {
    Offscreen o;
    // Rough white-ish dielectric facing the viewer: N = L = V = H, F = 0.04, Vis = 1/4 (a = 1).
    const std::string path = quadFile(
        "lit.gltf",
        "{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.5,0.25,1,1],\"metallicFactor\":0}}");
    const glm::vec3 base(0.5f, 0.25f, 1.0f);
    auto facing = [&](float intensity) {
        return 0.2f * base + intensity * (0.96f * base + glm::vec3(0.04f * 0.25f));
    };
    const Image headlight = render(o, *scene(model(path)));
    CHECK(close(glm::vec3(headlight.at(32, 32)), facing(1.0f), 1e-4f));
    const Image directional =
        render(o, *scene("DirectionalLight { direction 0 0 -1 intensity 0.5 }\n" + model(path)));
    CHECK(close(glm::vec3(directional.at(32, 32)), facing(0.5f), 1e-4f));
    // A point light straight in front of the pixel at (0.02, -0.02): no distance falloff.
    const Image point =
        render(o, *scene("PointLight { location 0.0195 -0.0195 3 intensity 0.5 }\n" + model(path)));
    CHECK(close(glm::vec3(point.at(32, 32)), facing(0.5f), 2e-3f));
    // Emissive alone: a black metal reflects nothing head-on (F0 = 0, V.H = 1).
    const std::string glowing =
        quadFile("emissive.gltf", "{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0,0,0,1]},"
                                  "\"emissiveFactor\":[0.2,0.4,0.6]}");
    const Image glow = render(o, *scene(model(glowing)));
    CHECK(close(glm::vec3(glow.at(32, 32)), {0.2f, 0.4f, 0.6f}, 1e-5f));
    // A metal: no diffuse, F = F0 = base colour. Box.gltf: baseColor (0.8, 0, 0), metallic 1.
    const Image box = render(o, *scene(model(sample("Box/glTF-Embedded/Box.gltf"))));
    keepImage(box, "box");
    CHECK(close(glm::vec3(box.at(32, 32)), {0.2f * 0.8f + 0.8f * 0.25f, 0.0f, 0.0f}, 1e-4f));
}

TEST_CASE("BLEND primitives draw back to front after the opaque ones") {
    Offscreen o;
    GltfBuilder b;
    const Quad q;
    const int pos = b.addPositions(q.positions);
    const int idx = b.addAccessor(q.indices, kUShort, "SCALAR", 6);
    // Red (near, z = 0.5) listed first, blue (z = 0) second, opaque green (z = -0.5) last.
    const std::string path = b.writeGltf(
        "blend.gltf",
        "\"materials\":["
        "{\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,0,0,0.5]},\"alphaMode\":\"BLEND\"," +
            std::string(kUnlit) +
            "},"
            "{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0,0,1,0.5]},\"alphaMode\":\"BLEND\"," +
            kUnlit + "},{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0,1,0,1]}," + kUnlit +
            "}],\"meshes\":[" + "{\"primitives\":[{\"attributes\":{\"POSITION\":" +
            std::to_string(pos) + "},\"indices\":" + std::to_string(idx) + ",\"material\":0}]}," +
            "{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
            "},\"indices\":" + std::to_string(idx) + ",\"material\":1}]}," +
            "{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
            "},\"indices\":" + std::to_string(idx) + ",\"material\":2}]}]," +
            "\"nodes\":[{\"mesh\":0,\"translation\":[0,0,0.5]},{\"mesh\":1},"
            "{\"mesh\":2,\"translation\":[0,0,-0.5]}],\"scenes\":[{\"nodes\":[0,1,2]}]");
    const Image image = render(o, *scene(model(path)));
    keepImage(image, "blend");
    // Blue over green, then red over that: (0.5, 0.25, 0.25); the other order gives
    // (0.25, 0.25, 0.5).
    CHECK(close(glm::vec3(image.at(32, 32)), {0.5f, 0.25f, 0.25f}, 1e-5f));

    // An Inventor Material's transparency makes the opaque green blend too (over blue bg).
    const Image faded =
        render(o, *scene("Material { transparency 0.75 }\n" + model(path)), glm::vec3(0, 0, 1));
    // Green at 0.25 over (0,0,1): (0, 0.25, 0.75), then blue 0.5 * 0.25 over it ...
    const glm::vec3 g = 0.25f * glm::vec3(0, 1, 0) + 0.75f * glm::vec3(0, 0, 1);
    const glm::vec3 bl = 0.125f * glm::vec3(0, 0, 1) + 0.875f * g;
    const glm::vec3 r = 0.125f * glm::vec3(1, 0, 0) + 0.875f * bl;
    CHECK(close(glm::vec3(faded.at(32, 32)), r, 1e-5f));
}

TEST_CASE("ClipPlane and BoxClip in scope clip the model") {
    Offscreen o;
    const std::string path = quadFile(
        "clip.gltf",
        std::string("{\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,1,1,1]},") + kUnlit + "}");
    const Image plane = render(o, *scene("ClipPlane { plane 1 0 0 0.2 }\n" + model(path)));
    // Keeps x >= 0.2: pixel centres at 32 + 5.12 = 37.12 and beyond.
    CHECK(coveredRect(plane, glm::vec3(0.0f)) == glm::ivec4(37, 6, 57, 57));
    const Image box = render(o, *scene("BoxClip { origin -0.5 -0.5 -1 extent 1 1 2 "
                                       "insideOpacity 0 outsideOpacity 1 }\n" +
                                       model(path)));
    keepImage(box, "boxclip");
    CHECK(close(glm::vec3(at(box, 0.0f, 0.0f)), glm::vec3(0.0f), 1e-6f));  // removed
    CHECK(close(glm::vec3(at(box, 0.75f, 0.0f)), glm::vec3(1.0f), 1e-6f)); // kept
    CHECK(close(glm::vec3(at(box, -0.3f, 0.3f)), glm::vec3(0.0f), 1e-6f)); // removed
}

TEST_CASE("single-sided primitives cull their back faces and double-sided ones do not") {
    Offscreen o;
    for (const bool doubleSided : {false, true}) {
        CAPTURE(doubleSided);
        const std::string path = quadFile(
            "sided.gltf", std::string("{\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,1,0,1]},"
                                      "\"doubleSided\":") +
                              (doubleSided ? "true," : "false,") + kUnlit + "}");
        // Turned around: its front faces -z, away from the camera.
        const Image image =
            render(o, *scene("Transform { rotation 0 1 0 3.14159265 }\n" + model(path)));
        CHECK(close(glm::vec3(image.at(32, 32)), doubleSided ? glm::vec3(1, 1, 0) : glm::vec3(0.0f),
                    1e-6f));
        // Mirrored in x, its triangles wind clockwise on screen, yet it still faces the
        // camera (a negative determinant flips glTF's front face): drawn either way.
        const Image mirrored =
            render(o, *scene("Transform { scaleFactor -1 1 1 }\n" + model(path)));
        CHECK(close(glm::vec3(mirrored.at(32, 32)), glm::vec3(1, 1, 0), 1e-6f));
    }
}

namespace {

/// A glTF file holding a lit gold cube 0.5 wide at the origin, tilted (the pose of the Inventor
/// cube the mixing tests use as their control: rotation 0.5547 0.83205 0 0.7378).
std::string writeTiltedCube(const std::string& name) {
    GltfBuilder b;
    const std::vector<glm::vec3> corners{{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                         {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    const std::vector<std::uint16_t> faces{0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                           2, 3, 7, 2, 7, 6, 1, 2, 6, 1, 6, 5, 0, 4, 7, 0, 7, 3};
    const int pos = b.addPositions(corners);
    const int idx = b.addAccessor(faces, kUShort, "SCALAR", faces.size());
    const std::string path = b.writeGltf(
        name, "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.9,0.7,0.2,1],"
              "\"metallicFactor\":0,\"roughnessFactor\":0.6}}],"
              "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":" +
                  std::to_string(pos) + "},\"indices\":" + std::to_string(idx) +
                  ",\"material\":0}]}],\"nodes\":[{\"mesh\":0,\"scale\":[0.25,0.25,0.25],"
                  "\"rotation\":[0.2,0.3,0,0.932738]}],\"scenes\":[{\"nodes\":[0]}]");
    return path;
}

} // namespace

TEST_CASE("an opaque mesh inside a Volume matches renderReference per pixel") {
    Offscreen o;
    // A lit cube from a glTF file inside a soft sphere; perspective, so depth matters per pixel.
    const std::string path = writeTiltedCube("inside.gltf");
    // The same scene with an Inventor Cube of the same size and pose in place of the model is
    // the control: the slicer's own error against the reference, which the glTF mesh must not
    // make worse.
    auto sceneWith = [](const std::string& mesh) {
        return readSceneFromString(
            "#Inventor V2.1 ascii\nSeparator {\n"
            "  PerspectiveCamera { position 0 0.6 2.2 orientation 1 0 0 -0.266 heightAngle 0.6 "
            "nearDistance 0.5 farDistance 5 }\n"
            "  DirectionalLight { direction -0.3 -0.5 -1 }\n  " +
            mesh +
            "\n  VolumeData { generator SOFT_SPHERE dimensions 24 24 24 spacing 0.05 0.05 0.05 }\n"
            "  TransferFunction { red [ 0 0.2, 1 1 ] green [ 0 0.5, 1 0.4 ] blue [ 0 1, 1 0.3 ] "
            "alpha [ 0 0, 1 0.4 ] }\n"
            "  Volume { }\n}\n");
    };
    RenderOptions options;
    options.width = options.height = 48;
    options.background = glm::vec3(0.05f, 0.05f, 0.1f);
    RayCastOptions rays;
    rays.tolerance = 2e-4;
    struct Errors {
        double rmse = 0.0, max = 0.0;
    };
    auto compare = [&](Node& root, const std::string& name) {
        const Image gl = o.renderer.render(root, options);
        const Image ref = renderReference(root, options, nullptr, rays);
        keepImage(gl, name + "-gl");
        keepImage(ref, name + "-ref");
        Errors e;
        for (int y = 0; y < gl.height; ++y)
            for (int x = 0; x < gl.width; ++x) {
                const glm::vec3 d = glm::abs(glm::vec3(gl.at(x, y)) - glm::vec3(ref.at(x, y)));
                e.rmse += double(glm::dot(d, d)) / 3.0;
                e.max = std::max(e.max, double(std::max({d.r, d.g, d.b})));
            }
        e.rmse = std::sqrt(e.rmse / double(gl.width * gl.height));
        return e;
    };
    const ref_ptr<Node> root = sceneWith(model(path));
    const ref_ptr<Node> control =
        sceneWith("Separator { Material { diffuseColor 0.9 0.7 0.2 } Transform { rotation 0.5547 "
                  "0.83205 0 0.7378 scaleFactor 0.25 0.25 0.25 } "
                  "Cube { } }");
    const Errors gltf = compare(*root, "inside-volume");
    const Errors cube = compare(*control, "inside-volume-cube");
    MESSAGE("glTF: rmse " << gltf.rmse * 255 << "/255, max " << gltf.max * 255
                          << "/255; Inventor cube: rmse " << cube.rmse * 255 << "/255, max "
                          << cube.max * 255 << "/255");
    CHECK(gltf.rmse < 0.3 * k8Bit);
    CHECK(gltf.max < 2.0 * k8Bit);
    CHECK(gltf.rmse < cube.rmse * 1.5 + 0.02 * k8Bit);

    // The mesh's pixels are dimmed by the volume in front of them (not drawn over it).
    const Image gl = o.renderer.render(*root, options);
    options.opaqueOnly = true;
    const Image meshOnly = o.renderer.render(*root, options);
    int meshPixels = 0, dimmed = 0;
    for (int y = 0; y < gl.height; ++y)
        for (int x = 0; x < gl.width; ++x) {
            const glm::vec3 mesh(meshOnly.at(x, y));
            if (close(mesh, options.background, 1e-6f)) continue;
            ++meshPixels;
            if (!close(glm::vec3(gl.at(x, y)), mesh, 4.0f * k8Bit)) ++dimmed;
        }
    CHECK(meshPixels > 200);
    CHECK(dimmed > meshPixels / 2);
}

TEST_CASE("an opaque mesh inside a ShearWarpVolume matches renderReference per pixel") {
    Offscreen o;
    // A glTF cube 0.5 wide at the centre of a homogeneous 32^3 box [-1, 1]^3 (A = 0.1 per L0 =
    // 1/16), seen along an oblique orthographic view (shear-warp renders parallel views only).
    const std::string path = writeTiltedCube("inside-shearwarp.gltf");
    auto sceneWith = [](const std::string& mesh) {
        return readSceneFromString(
            "#Inventor V2.1 ascii\nSeparator {\n"
            "  OrthographicCamera { position 0 1.2 4.8 orientation 1 0 0 -0.245 height 3 "
            "nearDistance 1 farDistance 9 }\n"
            "  DirectionalLight { direction -0.3 -0.5 -1 }\n  " +
            mesh +
            "\n  VolumeData { generator SOFT_SPHERE dimensions 32 32 32 spacing 0.0625 0.0625 "
            "0.0625 }\n"
            "  ShearWarpVolume { TransferFunction { red [ 0 0.2 ] green [ 0 0.4 ] blue [ 0 1 ] "
            "alpha [ 0 0.1 ] } VolumeObject { } }\n}\n");
    };
    RenderOptions options;
    options.width = options.height = 64;
    options.background = glm::vec3(0.05f, 0.05f, 0.1f);
    RayCastOptions rays;
    rays.tolerance = 1e-3;
    auto rmseAgainstReference = [&](Node& root, const std::string& name) {
        const Image gl = o.renderer.render(root, options);
        const Image ref = renderReference(root, options, nullptr, rays);
        keepImage(gl, name + "-gl");
        keepImage(ref, name + "-ref");
        double sum = 0.0;
        for (std::size_t i = 0; i < gl.pixels.size(); ++i) {
            const glm::dvec3 d = glm::dvec3(gl.pixels[i]) - glm::dvec3(ref.pixels[i]);
            sum += glm::dot(d, d) / 3.0;
        }
        return std::sqrt(sum / double(gl.pixels.size()));
    };
    const ref_ptr<Node> root = sceneWith(model(path));
    // The control: an Inventor Cube of the same size and pose. The shear-warp path's own error
    // against the reference (silhouettes, one sample per slice) is what the mesh must not
    // make worse.
    const ref_ptr<Node> control =
        sceneWith("Separator { Material { diffuseColor 0.9 0.7 0.2 } Transform { rotation 0.5547 "
                  "0.83205 0 0.7378 scaleFactor 0.25 0.25 0.25 } Cube { } }");
    const double gltf = rmseAgainstReference(*root, "inside-shearwarp");
    const double cube = rmseAgainstReference(*control, "inside-shearwarp-cube");
    MESSAGE("glTF in ShearWarpVolume: rmse " << gltf * 255 << "/255; Inventor cube: rmse "
                                             << cube * 255 << "/255");
    CHECK(gltf < 4.0 * k8Bit);
    CHECK(gltf < cube * 1.5 + 0.05 * k8Bit);

    // The mesh's pixels are dimmed by the volume in front of them (not drawn over it).
    const Image gl = o.renderer.render(*root, options);
    options.opaqueOnly = true;
    const Image meshOnly = o.renderer.render(*root, options);
    int meshPixels = 0, dimmed = 0;
    for (int y = 0; y < gl.height; ++y)
        for (int x = 0; x < gl.width; ++x) {
            const glm::vec3 mesh(meshOnly.at(x, y));
            if (close(mesh, options.background, 1e-6f)) continue;
            ++meshPixels;
            if (!close(glm::vec3(gl.at(x, y)), mesh, 4.0f * k8Bit)) ++dimmed;
        }
    CHECK(meshPixels > 100);
    CHECK(dimmed > meshPixels * 9 / 10);
}

TEST_CASE("sample models cover the pixels their bounding boxes project to") {
    Offscreen o;
    for (const char* file :
         {"Box/glTF-Embedded/Box.gltf", "BoxInterleaved/glTF-Binary/BoxInterleaved.glb",
          "BoxTextured/glTF-Binary/BoxTextured.glb", "Duck/glTF-Binary/Duck.glb",
          "CesiumMilkTruck/glTF-Binary/CesiumMilkTruck.glb",
          "AlphaBlendModeTest/trimesh-reexport/AlphaBlendModeTest.glb", "Cube/Cube.gltf",
          "SimpleSparseAccessor/glTF-Embedded/SimpleSparseAccessor.gltf",
          "TriangleWithoutIndices/glTF-Embedded/TriangleWithoutIndices.gltf",
          "SparseMorphTargets/singleBlendshapeCube_sparse.glb"}) {
        CAPTURE(file);
        auto node = GltfModel::create();
        node->fileName = sample(file);
        const Box3 box = computeBoundingBox(*node);
        REQUIRE(!box.isEmpty());
        // An orthographic camera along -z framing the box with a margin; double-sided
        // rendering would differ, so use the files as they are (single-sided ones cull).
        const double height = std::max(box.size().x, box.size().y) * 1.25;
        auto camera = OrthographicCamera::create();
        camera->position = glm::vec3(box.center() + glm::dvec3(0, 0, box.size().z + 1.0));
        camera->height = float(height);
        camera->nearDistance = 0.5f;
        camera->farDistance = float(2.0 * box.size().z + 2.0);
        auto root = Separator::create();
        root->children()->push_back(camera);
        root->children()->push_back(node);
        const int size = 96;
        const Image image = render(o, *root, glm::vec3(1.0f, 0.0f, 1.0f), size);
        keepImage(image, std::filesystem::path(file).stem().string());
        const glm::ivec4 r = coveredRect(image, glm::vec3(1.0f, 0.0f, 1.0f));
        // Pixel centres inside the projected box: covered from ceil(edge - 0.5).
        const double ppu = size / height;
        auto px = [&](double x) { return size / 2.0 + (x - box.center().x) * ppu; };
        auto py = [&](double y) { return size / 2.0 - (y - box.center().y) * ppu; };
        CHECK(std::abs(r.x - std::ceil(px(box.min.x) - 0.5)) <= 1.0);
        CHECK(std::abs(r.z - std::floor(px(box.max.x) - 0.5)) <= 1.0);
        CHECK(std::abs(r.y - std::ceil(py(box.max.y) - 0.5)) <= 1.0);
        CHECK(std::abs(r.w - std::floor(py(box.min.y) - 0.5)) <= 1.0);
    }
}

TEST_CASE("pick names the glTF node, mesh, primitive and triangle it hits") {
    GltfBuilder b;
    const Quad q(0.5f);
    const int pos = b.addPositions(q.positions);
    const int idx = b.addAccessor(q.indices, kUShort, "SCALAR", 6);
    const std::string prim = "{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
                             "},\"indices\":" + std::to_string(idx) + "}";
    // Mesh 1 has two primitives (the second one nearer by 0.1); node 1 places it at x = +1.
    const std::string path =
        b.writeGltf("pick.gltf", "\"meshes\":[{\"primitives\":[" + prim + "]},{\"primitives\":[" +
                                     prim + "," + prim +
                                     "]}],\"nodes\":[{\"mesh\":0,\"translation\":[-1,0,0]},"
                                     "{\"children\":[2],\"translation\":[1,0,0]},{\"mesh\":1}],"
                                     "\"scenes\":[{\"nodes\":[0,1]}]");
    auto node = GltfModel::create();
    node->fileName = path;
    auto root = Separator::create();
    root->children()->push_back(node);

    PickAction pick;
    // Down -z through (1.2, -0.3): node 2's mesh 1, primitive 0 (the same quad twice: the first
    // hit stays on ties), the lower-right triangle 0 (x > y in the quad's coordinates).
    pick.setRay(Ray{{1.2, -0.3, 5.0}, {0.0, 0.0, -1.0}});
    pick.apply(*root);
    REQUIRE(pick.picked());
    const PickedPoint& p = *pick.picked();
    CHECK(std::abs(p.point.x - 1.2) < 1e-9);
    CHECK(std::abs(p.point.z) < 1e-9);
    CHECK(std::abs(p.distance - 5.0) < 1e-9);
    CHECK(std::abs(p.normal.z - 1.0) < 1e-9);
    REQUIRE(!p.path.empty());
    CHECK(p.path.back() == node.get());
    const auto detail = node->pickDetail(p.primitiveIndex);
    REQUIRE(detail);
    CHECK(detail->node == 2);
    CHECK(detail->mesh == 1);
    CHECK(detail->primitive == 0);
    CHECK(detail->triangle == 0);

    // Through (-1.2, 0.3) on the left: node 0, mesh 0, upper-left triangle 1.
    pick.setRay(Ray{{-1.2, 0.3, 5.0}, {0.0, 0.0, -1.0}});
    pick.apply(*root);
    REQUIRE(pick.picked());
    const auto left = node->pickDetail(pick.picked()->primitiveIndex);
    REQUIRE(left);
    CHECK(left->node == 0);
    CHECK(left->mesh == 0);
    CHECK(left->triangle == 1);

    // Between the two: nothing.
    pick.setRay(Ray{{0.0, 0.0, 5.0}, {0.0, 0.0, -1.0}});
    pick.apply(*root);
    CHECK(!pick.picked());
}

TEST_CASE("bounding box, search and write treat GltfModel as a node of the scene") {
    const std::string box = sample("Box/glTF-Embedded/Box.gltf");
    const ref_ptr<Node> root = readSceneFromString(
        "#Inventor V2.1 ascii\nSeparator {\n  Transform { translation 1 0 0 scaleFactor 2 2 2 }\n"
        "  DEF part GltfModel { fileName \"" +
        box + "\" }\n}\n");
    const Box3 bounds = computeBoundingBox(*root);
    CHECK(std::abs(bounds.min.x - 0.0) < 1e-9);
    CHECK(std::abs(bounds.max.x - 2.0) < 1e-9);
    CHECK(std::abs(bounds.min.y + 1.0) < 1e-9);
    CHECK(std::abs(bounds.max.z - 1.0) < 1e-9);

    const std::vector<Node*> found = findAll(*root, GltfModel::classType());
    REQUIRE(found.size() == 1);
    CHECK(findByName(*root, "part") == found[0]);

    // Written self-described with its file name only, and read back equal.
    const std::string text = writeSceneToString(*root);
    CHECK(text.find("GltfModel {") != std::string::npos);
    CHECK(text.find("fields [ SFString fileName ]") != std::string::npos);
    CHECK(text.size() < 1000); // the node, not the mesh data
    const ref_ptr<Node> again = readSceneFromString(text);
    std::string why;
    CHECK_MESSAGE(graphsEqual(*root, *again, &why), why);
}

TEST_CASE("a relative fileName resolves against the scene file's folder") {
    const auto folder = gltfScratch() / "scene-folder";
    std::filesystem::create_directories(folder / "parts");
    std::filesystem::copy_file(sample("Box/glTF-Embedded/Box.gltf"), folder / "parts" / "box.gltf",
                               std::filesystem::copy_options::overwrite_existing);
    writeText(folder / "scene.iv",
              "#Inventor V2.1 ascii\nSeparator { GltfModel { fileName \"parts/box.gltf\" } }\n");
    const ref_ptr<Node> root = readScene((folder / "scene.iv").string());
    const Box3 bounds = computeBoundingBox(*root);
    CHECK(std::abs(bounds.max.x - 0.5) < 1e-9);

    // A missing file is an Error naming it, from any action.
    const ref_ptr<Node> broken = readSceneFromString(
        "#Inventor V2.1 ascii\nSeparator { GltfModel { fileName \"no/such/part.glb\" } }\n");
    CHECK_THROWS_WITH_AS(computeBoundingBox(*broken), doctest::Contains("part.glb"), Error);
}
