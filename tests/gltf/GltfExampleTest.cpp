// The example of a glTF mesh inside a volume: the committed mesh is what its tool writes, and
// the scene shows the mesh veiled by the volume around it.
#include <doctest/doctest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/context/OSMesaContext.h>
#include <volsg/gltf/GltfAsset.h>
#include <volsg/gltf/GltfLoader.h>
#include <volsg/io/SceneReader.h>
#include <volsg/render/Renderer.h>

#include "../../examples/gltf/ExampleMesh.h"

using namespace volsg;

namespace {

std::string examplePath(const std::string& name) {
    return std::string(VOLSG_SOURCE_DIR) + "/examples/" + name;
}

} // namespace

TEST_CASE("the committed example mesh is exactly what MakeExampleMesh writes") {
    std::ifstream in(examplePath("gltf/torus-knot.glb"), std::ios::binary);
    REQUIRE(in);
    const std::vector<std::uint8_t> committed((std::istreambuf_iterator<char>(in)),
                                              std::istreambuf_iterator<char>());
    const std::vector<std::uint8_t> written = example::torusKnotGlb();
    CHECK(committed.size() == written.size());
    CHECK(committed == written);

    // And it loads: one closed tube of 256 x 16 quads.
    const GltfAsset a = loadGltf(examplePath("gltf/torus-knot.glb"));
    REQUIRE(a.meshes.size() == 1);
    CHECK(a.meshes[0].primitives[0].positions.size() == 256u * 16u);
    CHECK(a.meshes[0].primitives[0].triangleCount() == 2u * 256u * 16u);
    // The knot's curve reaches radius 3 * 0.11, plus the tube's 0.045.
    CHECK(a.bounds.max.x == doctest::Approx(0.33 + 0.045).epsilon(0.01));
}

TEST_CASE("the volume-with-mesh example shows the mesh veiled by the volume around it") {
    OSMesaContext context;
    Renderer renderer;
    const ref_ptr<Node> root = readScene(examplePath("volume-with-mesh.iv"));
    RenderOptions options;
    options.width = options.height = 128;
    const Image withVolume = renderer.render(*root, options);
    options.opaqueOnly = true;
    const Image meshOnly = renderer.render(*root, options);
    int mesh = 0, veiled = 0, orange = 0;
    for (std::size_t i = 0; i < meshOnly.pixels.size(); ++i) {
        const glm::vec4 m = meshOnly.pixels[i], v = withVolume.pixels[i];
        if (m.r + m.g + m.b == 0.0f) continue;
        ++mesh;
        orange += m.r > m.g && m.g > m.b; // the knot's base colour is (0.9, 0.45, 0.12)
        veiled += v.b > m.b + 0.02f;      // blue volume in front of it
    }
    MESSAGE(mesh << " mesh pixels, " << veiled << " veiled by the volume");
    CHECK(mesh > 128 * 128 / 10);
    CHECK(orange > mesh * 9 / 10);
    CHECK(veiled > mesh / 2); // the knot lies inside the sphere: the volume veils it
}
