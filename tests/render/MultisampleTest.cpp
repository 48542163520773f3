// Multisample antialiasing of the opaque pass (RenderOptions::samples): edges get coverage
// between 0 and 1, interiors stay as they were, and volumes composite against the resolved
// depth exactly as without it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <volsg/context/OSMesaContext.h>
#include <volsg/image/Image.h>
#include <volsg/io/SceneReader.h>
#include <volsg/render/Renderer.h>

using namespace volsg;

namespace {

constexpr int kSize = 64;

// An emissive white cube turned about the view axis under an orthographic camera, unlit
// otherwise: each pixel is the fraction of it the cube covers (0 or 1 without antialiasing).
const char* tiltedCube = "#Inventor V2.1 ascii\n"
                         "Separator {\n"
                         "  OrthographicCamera { position 0 0 5 height 4 nearDistance 1 "
                         "farDistance 9 }\n"
                         "  Material { diffuseColor 0 0 0 ambientColor 0 0 0 "
                         "specularColor 0 0 0 emissiveColor 1 1 1 }\n"
                         "  Transform { rotation 0 0 1 0.35 }\n"
                         "  Cube { }\n"
                         "}\n";

// A soft-sphere volume with a turned opaque cube inside it: the cube's front face (z = 0.5,
// facing the camera, so one depth over the face) hides the volume behind it, the volume in
// front of it is composited over it.
const char* cubeInVolume = "#Inventor V2.1 ascii\n"
                           "Separator {\n"
                           "  OrthographicCamera { position 0 0 5 height 2.4 nearDistance 1 "
                           "farDistance 9 }\n"
                           "  VolumeData { generator SOFT_SPHERE dimensions 32 32 32 "
                           "spacing 0.0625 0.0625 0.0625 }\n"
                           "  TransferFunction { alpha [ 0 0, 1 0.6 ] }\n"
                           "  Volume { numPlanes 64 }\n"
                           "  Separator {\n"
                           "    Material { diffuseColor 0 0 0 ambientColor 0 0 0 "
                           "specularColor 0 0 0 emissiveColor 1 0.5 0 }\n"
                           "    Transform { translation 0.3 0 0 rotation 0 0 1 0.35 }\n"
                           "    Cube { width 1 height 1 depth 1 }\n"
                           "  }\n"
                           "}\n";

Image renderScene(Renderer& renderer, Node& root, int samples, bool opaqueOnly = false) {
    RenderOptions o;
    o.width = o.height = kSize;
    o.samples = samples;
    o.opaqueOnly = opaqueOnly;
    return renderer.render(root, o);
}

/// Whether the 3x3 neighbourhood of (x, y) in `coverage` is all one value (no edge near it).
bool awayFromEdges(const Image& coverage, int x, int y) {
    const glm::vec4 c = coverage.at(x, y);
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int u = std::clamp(x + dx, 0, kSize - 1), v = std::clamp(y + dy, 0, kSize - 1);
            if (coverage.at(u, v) != c) return false;
        }
    return true;
}

float maxChannelDifference(const glm::vec4& a, const glm::vec4& b) {
    const glm::vec4 d = glm::abs(a - b);
    return std::max({d.r, d.g, d.b});
}

} // namespace

TEST_CASE("multisampling gives a tilted cube's edge pixels coverage in quarter steps") {
    OSMesaContext context;
    context.makeCurrent();
    Renderer renderer;
    ref_ptr<Node> root = readSceneFromString(tiltedCube);
    const Image off = renderScene(renderer, *root, 0);
    const Image on = renderScene(renderer, *root, 4);
    int offIntermediate = 0, onIntermediate = 0, onQuarterSteps = 0, interior = 0;
    float worstInterior = 0.0f;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const float a = off.at(x, y).r, b = on.at(x, y).r;
            if (a > 1e-6f && a < 1.0f - 1e-6f) ++offIntermediate;
            if (b > 0.05f && b < 0.95f) {
                ++onIntermediate;
                const float quarters = b * 4.0f;
                if (std::abs(quarters - std::round(quarters)) < 1e-4f) ++onQuarterSteps;
            }
            if (awayFromEdges(off, x, y)) {
                ++interior;
                worstInterior =
                    std::max(worstInterior, maxChannelDifference(off.at(x, y), on.at(x, y)));
            }
        }
    CHECK(offIntermediate == 0); // without MSAA a pixel is covered or not
    // The cube's outline is about 4 x 2 x 16 = 128 pixels long; most edge pixels are partial.
    CHECK(onIntermediate > 60);
    CHECK(onQuarterSteps == onIntermediate); // 4 samples: 1/4, 1/2, 3/4
    CHECK(interior > kSize * kSize / 2);
    CHECK(worstInterior <= 1.0f / 255.0f);
}

TEST_CASE("a volume composites against the multisampled pass's resolved depth") {
    OSMesaContext context;
    context.makeCurrent();
    // Two renderers, so that the multisampled frames' target never holds a single-sampled
    // frame's depth: what the volumes see there is the resolved depth or nothing.
    Renderer renderer, multisampled;
    ref_ptr<Node> root = readSceneFromString(cubeInVolume);
    const Image on = renderScene(multisampled, *root, 4);
    const Image onOpaque = renderScene(multisampled, *root, 4, true);
    const Image coverage = renderScene(renderer, *root, 0, true); // the cube alone
    const Image off = renderScene(renderer, *root, 0);
    int compared = 0, cubePixels = 0, volumeOverCube = 0;
    float worst = 0.0f;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            if (!awayFromEdges(coverage, x, y)) continue;
            ++compared;
            worst = std::max(worst, maxChannelDifference(off.at(x, y), on.at(x, y)));
            if (coverage.at(x, y).r > 0.5f) {
                ++cubePixels;
                // The volume in front of the face adds its light: not the cube alone (but
                // for the corners, which reach the sphere's thin rim).
                if (maxChannelDifference(on.at(x, y), onOpaque.at(x, y)) > 0.02f) ++volumeOverCube;
            }
        }
    CHECK(compared > kSize * kSize / 2);
    CHECK(cubePixels > 100);
    CHECK(volumeOverCube > cubePixels / 2);
    // Away from the cube's edges, exactly the image without multisampling (1/255): the volume
    // behind the cube stays hidden, the volume in front of it is composited over it.
    CHECK(worst <= 1.0f / 255.0f);
}
