// The glTF loader without GL: the real sample files of examples/data/gltf against what their
// JSON defines, small written files for each feature, and every kind of broken file.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include <volsg/core/Error.h>
#include <volsg/gltf/GltfLoader.h>

#include "GltfTestFiles.h"

using namespace volsg;
using namespace volsg::test;

namespace {

std::string sample(const std::string& relative) {
    return std::string(VOLSG_DATA_DIR) + "/gltf/" + relative;
}

/// The union of every primitive's POSITION box, in mesh coordinates (what the README lists).
Box3 meshLocalBounds(const GltfAsset& a) {
    Box3 b;
    for (const GltfMesh& m : a.meshes)
        for (const GltfPrimitive& p : m.primitives)
            b.extendBy(p.bounds);
    return b;
}

bool near(const glm::dvec3& a, const glm::dvec3& b, double tolerance) {
    return glm::all(glm::lessThanEqual(glm::abs(a - b), glm::dvec3(tolerance)));
}

/// The message of the Error that loading `path` throws ("" if it loads).
std::string loadError(const std::string& path) {
    try {
        loadGltf(path);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

/// A one-triangle file whose accessor JSON for POSITION is given raw (to break it).
std::string triangleWithPositionAccessor(const std::string& name, const std::string& accessor) {
    GltfBuilder b;
    const std::vector<glm::vec3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    b.addView(p);
    b.addAccessorJson(accessor);
    return b.writeGltf(name, std::string("\"meshes\":[{\"primitives\":[{\"attributes\":{"
                                         "\"POSITION\":0}}]}],") +
                                 kOneNodeScene);
}

} // namespace

TEST_CASE("every sample model loads with the POSITION bounds its JSON states") {
    struct Expected {
        const char* file;
        glm::dvec3 min, max;
    };
    const Expected samples[] = {
        {"Box/glTF-Embedded/Box.gltf", glm::dvec3(-0.5), glm::dvec3(0.5)},
        {"BoxInterleaved/glTF-Binary/BoxInterleaved.glb", glm::dvec3(-0.5), glm::dvec3(0.5)},
        {"BoxTextured/glTF-Binary/BoxTextured.glb", glm::dvec3(-0.5), glm::dvec3(0.5)},
        {"Duck/glTF-Binary/Duck.glb",
         {-69.29850006103516, 9.929369926452637, -61.32819747924805},
         {96.17990112304688, 163.97000122070312, 53.92519760131836}},
        {"CesiumMilkTruck/glTF-Binary/CesiumMilkTruck.glb",
         {-2.430910110473633, -0.4278, -1.396},
         {2.437999963760376, 2.5843698978424072, 1.3960000276565552}},
        {"AlphaBlendModeTest/trimesh-reexport/AlphaBlendModeTest.glb",
         {-4.300000190734863, -0.4815960228443146, -0.75},
         {4.300000190734863, 2.2995333671569824, 0.550000011920929}},
        {"Cube/Cube.gltf", {-1.0, -1.0, -1.0}, {1.0, 1.0, 1.000001}},
        {"SimpleSparseAccessor/glTF-Embedded/SimpleSparseAccessor.gltf", {0, 0, 0}, {6, 4, 0}},
        {"TriangleWithoutIndices/glTF-Embedded/TriangleWithoutIndices.gltf", {0, 0, 0}, {1, 1, 0}},
        {"SparseMorphTargets/singleBlendshapeCube_sparse.glb", glm::dvec3(-0.004999999888241291),
         glm::dvec3(0.004999999888241291)},
    };
    for (const Expected& e : samples) {
        CAPTURE(e.file);
        const GltfAsset a = loadGltf(sample(e.file));
        const Box3 b = meshLocalBounds(a);
        CHECK(near(b.min, e.min, 1e-6));
        CHECK(near(b.max, e.max, 1e-6));
        CHECK(!a.instances.empty());
    }
}

TEST_CASE("sample node transforms place the meshes as the files say") {
    // Box: the root rotates 90 degrees about x; a centred unit cube stays [-0.5, 0.5]^3.
    const GltfAsset box = loadGltf(sample("Box/glTF-Embedded/Box.gltf"));
    CHECK(near(box.bounds.min, glm::dvec3(-0.5), 1e-6));
    CHECK(near(box.bounds.max, glm::dvec3(0.5), 1e-6));
    REQUIRE(box.instances.size() == 1);
    CHECK(std::abs(box.instances[0].matrix[1][2] + 1.0) < 1e-12); // y goes to -z

    // Duck: scaled by 0.01 at the root (the camera node has no mesh).
    const GltfAsset duck = loadGltf(sample("Duck/glTF-Binary/Duck.glb"));
    const double s = 0.009999999776482582;
    CHECK(near(duck.bounds.min, s * glm::dvec3(-69.2985, 9.92937, -61.3282), 1e-5));
    CHECK(near(duck.bounds.max, s * glm::dvec3(96.1799, 163.97, 53.9252), 1e-5));
    REQUIRE(duck.instances.size() == 1);
    CHECK(duck.meshes[0].primitives[0].positions.size() == 2399);
    CHECK(duck.meshes[0].primitives[0].triangleCount() == 4212);

    // CesiumMilkTruck: the wheel mesh placed twice by node matrices; 3 + 1 + 1 primitives.
    const GltfAsset truck = loadGltf(sample("CesiumMilkTruck/glTF-Binary/CesiumMilkTruck.glb"));
    REQUIRE(truck.instances.size() == 3);
    CHECK(truck.instances[0].mesh == 0);
    CHECK(truck.instances[1].mesh == 1);
    CHECK(truck.instances[2].mesh == 1);
    CHECK(truck.meshes[0].primitives.size() == 3);
    CHECK(std::abs(truck.instances[1].matrix[3].x - 1.43267) < 1e-5); // node 3 before node 1
    CHECK(std::abs(truck.instances[2].matrix[3].x + 1.35233) < 1e-5);
    // The wheels (radius 0.4278 about their axle at y = 0.42772) reach down to y ~ 0.
    CHECK(truck.bounds.min.y > -0.0002);
    CHECK(truck.bounds.min.y < 0.01);
    CHECK(std::abs(truck.bounds.max.y - 2.5843698978424072) < 1e-6);

    // AlphaBlendModeTest: 9 meshes on 8 translated/rotated nodes plus one at the origin.
    const GltfAsset blend =
        loadGltf(sample("AlphaBlendModeTest/trimesh-reexport/AlphaBlendModeTest.glb"));
    CHECK(blend.instances.size() == 9);
    CHECK(blend.images.size() == 9);
    int masks = 0, blends = 0, normalMaps = 0;
    for (const GltfMaterial& m : blend.materials) {
        masks += m.alphaMode == GltfAlphaMode::Mask;
        blends += m.alphaMode == GltfAlphaMode::Blend;
        normalMaps += m.normalTexture.present();
    }
    CHECK(masks >= 1);
    CHECK(blends >= 1);
    CHECK(normalMaps >= 1);
}

TEST_CASE("sparse accessors substitute their values") {
    const GltfAsset a =
        loadGltf(sample("SimpleSparseAccessor/glTF-Embedded/SimpleSparseAccessor.gltf"));
    const GltfPrimitive& p = a.meshes[0].primitives[0];
    REQUIRE(p.positions.size() == 14);
    // Indices 8, 10 and 12 are lifted from y = 0..1 to y = 2..4 in the sample.
    CHECK(p.positions[8].y > 1.0f);
    CHECK(p.positions[10].y > 1.0f);
    CHECK(p.positions[12].y > 1.0f);
    CHECK(p.positions[9].y <= 1.0f);

    // A sparse accessor without a bufferView: zeros except the given elements.
    GltfBuilder b;
    const std::vector<glm::vec3> base{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    b.addAccessor(base, kFloat, "VEC3", 3);
    const std::vector<std::uint8_t> which{1};
    const std::vector<glm::vec3> values{{0, 0, 5}};
    const int iv = b.addView(which), vv = b.addView(values);
    b.addAccessorJson("{\"componentType\":5126,\"count\":3,\"type\":\"VEC3\",\"sparse\":{"
                      "\"count\":1,\"indices\":{\"bufferView\":" +
                      std::to_string(iv) + ",\"componentType\":5121},\"values\":{\"bufferView\":" +
                      std::to_string(vv) + "}}}");
    const std::string path = b.writeGltf(
        "morph.gltf", std::string("\"meshes\":[{\"weights\":[0.5],\"primitives\":[{"
                                  "\"attributes\":{\"POSITION\":0},\"targets\":[{\"POSITION\":1}]"
                                  "}]}],") +
                          kOneNodeScene);
    const GltfAsset m = loadGltf(path);
    // Morph target 0 at the mesh's weight 0.5 moves vertex 1 by (0, 0, 5) * 0.5.
    const auto& q = m.meshes[0].primitives[0].positions;
    CHECK(q[0] == glm::vec3(0, 0, 0));
    CHECK(q[1] == glm::vec3(1, 0, 2.5f));
    CHECK(q[2] == glm::vec3(0, 1, 0));
}

TEST_CASE("every index and component type reads the same triangle") {
    const std::vector<glm::vec3> ref{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    struct Case {
        const char* name;
        int component;
        bool normalized;
        std::vector<std::uint8_t> bytes; // 3 vertices of VEC3, little endian
        double scale;                    // what 1.0 of the reference becomes
    };
    auto pack = [](const std::vector<int>& v, int size) {
        std::vector<std::uint8_t> out;
        for (int x : v)
            for (int i = 0; i < size; ++i)
                out.push_back(std::uint8_t(unsigned(x) >> (8 * i)));
        // VEC3 of 1- and 2-byte components: pad each element to 4 bytes via stride below.
        return out;
    };
    const std::vector<int> ones{0, 0, 0, 1, 0, 0, 0, 1, 0};
    const std::vector<int> bytes127{0, 0, 0, 127, 0, 0, 0, 127, 0};
    const std::vector<int> bytes255{0, 0, 0, 255, 0, 0, 0, 255, 0};
    const std::vector<int> shorts{0, 0, 0, 32767, 0, 0, 0, 32767, 0};
    const std::vector<int> ushorts{0, 0, 0, 65535, 0, 0, 0, 65535, 0};
    const Case cases[] = {
        {"byte", kByte, false, pack(ones, 1), 1.0},
        {"byte normalized", kByte, true, pack(bytes127, 1), 1.0},
        {"ubyte normalized", kUByte, true, pack(bytes255, 1), 1.0},
        {"short normalized", kShort, true, pack(shorts, 2), 1.0},
        {"ushort normalized", kUShort, true, pack(ushorts, 2), 1.0},
        {"ushort", kUShort, false, pack(ones, 2), 1.0},
    };
    const int indexTypes[] = {kUByte, kUShort, kUInt};
    for (const Case& c : cases)
        for (int indexType : indexTypes) {
            CAPTURE(c.name);
            CAPTURE(indexType);
            GltfBuilder b;
            b.addAccessor(c.bytes, c.component, "VEC3", 3, c.normalized);
            std::vector<std::uint8_t> idx;
            const int size = indexType == kUByte ? 1 : indexType == kUShort ? 2 : 4;
            for (int i : {2, 1, 0})
                for (int k = 0; k < size; ++k)
                    idx.push_back(std::uint8_t(k == 0 ? i : 0));
            b.addAccessor(idx, indexType, "SCALAR", 3);
            const GltfAsset a = loadGltf(b.writeGltf(
                "types.gltf", std::string("\"extensionsRequired\":[\"KHR_mesh_quantization\"],"
                                          "\"extensionsUsed\":[\"KHR_mesh_quantization\"],"
                                          "\"meshes\":[{\"primitives\":[{\"attributes\":{"
                                          "\"POSITION\":0},\"indices\":1}]}],") +
                                  kOneNodeScene));
            const GltfPrimitive& p = a.meshes[0].primitives[0];
            REQUIRE(p.positions.size() == 3);
            for (int v = 0; v < 3; ++v)
                CHECK(glm::all(glm::lessThan(
                    glm::abs(p.positions[std::size_t(v)] - ref[std::size_t(v)] * float(c.scale)),
                    glm::vec3(1e-6f))));
            CHECK(p.indices == std::vector<std::uint32_t>{2, 1, 0});
        }
}

TEST_CASE("interleaved views, strips, fans, loops and non-indexed draws unroll as glTF numbers") {
    GltfBuilder b;
    // Interleaved: position then normal, stride 24.
    std::vector<float> interleaved;
    const glm::vec3 p[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    for (const auto& v : p)
        interleaved.insert(interleaved.end(), {v.x, v.y, v.z, 0.0f, 0.0f, 1.0f});
    const int view = b.addView(interleaved.data(), interleaved.size() * 4, 24);
    b.addAccessorJson("{\"bufferView\":" + std::to_string(view) +
                      ",\"componentType\":5126,\"count\":4,\"type\":\"VEC3\"}");
    b.addAccessorJson("{\"bufferView\":" + std::to_string(view) +
                      ",\"byteOffset\":12,\"componentType\":5126,\"count\":4,\"type\":\"VEC3\"}");
    auto prim = [](int mode) {
        return "{\"attributes\":{\"POSITION\":0,\"NORMAL\":1},\"mode\":" + std::to_string(mode) +
               "}";
    };
    const GltfAsset a = loadGltf(b.writeGlb(
        "modes.glb", "\"meshes\":[{\"primitives\":[" + prim(5) + "," + prim(6) + "," + prim(2) +
                         "," + prim(3) + "," + prim(0) + "]}]," + kOneNodeScene));
    const auto& ps = a.meshes[0].primitives;
    REQUIRE(ps.size() == 5);
    CHECK(ps[0].kind == GltfPrimitive::Kind::Triangles); // strip: {0,1,2}, {1,3,2}
    CHECK(ps[0].indices == std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2});
    CHECK(ps[1].indices == std::vector<std::uint32_t>{1, 2, 0, 2, 3, 0}); // fan
    CHECK(ps[2].kind == GltfPrimitive::Kind::Lines);                      // loop
    CHECK(ps[2].indices == std::vector<std::uint32_t>{0, 1, 1, 2, 2, 3, 3, 0});
    CHECK(ps[3].indices == std::vector<std::uint32_t>{0, 1, 1, 2, 2, 3}); // line strip
    CHECK(ps[4].kind == GltfPrimitive::Kind::Points);
    CHECK(ps[0].normals[3] == glm::vec3(0, 0, 1));
    CHECK(ps[0].positions[3] == glm::vec3(1, 1, 0));

    // Four vertices drawn as TRIANGLES do not make whole triangles.
    CHECK(contains(loadError(b.writeGlb("partial.glb", "\"meshes\":[{\"primitives\":[" + prim(4) +
                                                           "]}]," + kOneNodeScene)),
                   "meshes[0].primitives[0]: 4 vertices do not make whole triangles"));
}

TEST_CASE("TRS and matrix nodes compose down the default scene only") {
    GltfBuilder b;
    b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    // Scene 1 (the default) holds node 0: translate (10,0,0), child node 1: rotate 90 deg about
    // z (quaternion), scale 2; node 2 (in scene 0 only) must not appear.
    const double h = std::sqrt(0.5);
    const std::string rest = "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],"
                             "\"nodes\":[{\"translation\":[10,0,0],\"children\":[1]},"
                             "{\"rotation\":[0,0," +
                             GltfBuilder::num(h) + "," + GltfBuilder::num(h) +
                             "],\"scale\":[2,2,2],\"mesh\":0},"
                             "{\"matrix\":[1,0,0,0,0,1,0,0,0,0,1,0,0,0,-7,1],\"mesh\":0}],"
                             "\"scenes\":[{\"nodes\":[2]},{\"nodes\":[0]}],\"scene\":1";
    const GltfAsset a = loadGltf(b.writeGltf("trs.gltf", rest));
    REQUIRE(a.instances.size() == 1);
    CHECK(a.instances[0].node == 1);
    // (1,0,0) -> scaled (2,0,0) -> rotated (0,2,0) -> translated (10,2,0).
    const glm::dvec4 q = a.instances[0].matrix * glm::dvec4(1, 0, 0, 1);
    CHECK(near(glm::dvec3(q), {10, 2, 0}, 1e-6));
    CHECK(near(a.bounds.min, {8, 0, 0}, 1e-6));
    CHECK(near(a.bounds.max, {10, 2, 0}, 1e-6));

    // Without "scene", scene 0; the matrix node translates by -7 in z.
    std::string rest0 = rest;
    rest0.erase(rest0.find(",\"scene\":1"));
    const GltfAsset b0 = loadGltf(b.writeGltf("trs0.gltf", rest0));
    REQUIRE(b0.instances.size() == 1);
    CHECK(b0.instances[0].node == 2);
    CHECK(near(b0.bounds.min, {0, 0, -7}, 1e-12));
}

TEST_CASE("materials, textures and samplers are read with glTF's defaults") {
    const GltfAsset cube = loadGltf(sample("Cube/Cube.gltf"));
    REQUIRE(cube.materials.size() == 1);
    const GltfMaterial& m = cube.materials[0];
    CHECK(m.baseColorTexture.present());
    CHECK(m.metallicRoughnessTexture.present());
    CHECK(m.alphaMode == GltfAlphaMode::Opaque);
    REQUIRE(cube.images.size() == 2);
    CHECK(cube.images[0].width == 512);
    CHECK(cube.images[0].rgba.size() == 512u * 512u * 4u);
    CHECK(!cube.meshes[0].primitives[0].tangents.empty());

    const GltfAsset textured = loadGltf(sample("BoxTextured/glTF-Binary/BoxTextured.glb"));
    REQUIRE(textured.samplers.size() == 1);
    CHECK(textured.samplers[0].magFilter == 9729);
    CHECK(textured.samplers[0].minFilter == 9986); // as the file says
    CHECK(textured.samplers[0].wrapS == 10497);

    // A default material where none is named.
    const GltfAsset tri =
        loadGltf(sample("TriangleWithoutIndices/glTF-Embedded/TriangleWithoutIndices.gltf"));
    const GltfMaterial& d = tri.materialOf(tri.meshes[0].primitives[0]);
    CHECK(d.baseColorFactor == glm::vec4(1.0f));
    CHECK(d.metallicFactor == 1.0f);
    CHECK(d.roughnessFactor == 1.0f);
    CHECK(!d.doubleSided);

    // KHR_materials_unlit, MASK with its cutoff, double-sided, emissive.
    GltfBuilder b;
    b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const GltfAsset u = loadGltf(b.writeGltf(
        "unlit.gltf",
        std::string("\"extensionsUsed\":[\"KHR_materials_unlit\"],\"materials\":[{"
                    "\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.25,0.5,0.75,0.6]},"
                    "\"alphaMode\":\"MASK\",\"alphaCutoff\":0.3,\"doubleSided\":true,"
                    "\"emissiveFactor\":[0.1,0.2,0.3],"
                    "\"extensions\":{\"KHR_materials_unlit\":{}}}],"
                    "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},"
                    "\"material\":0}]}],") +
            kOneNodeScene));
    const GltfMaterial& um = u.materials[0];
    CHECK(um.unlit);
    CHECK(um.alphaMode == GltfAlphaMode::Mask);
    CHECK(um.alphaCutoff == doctest::Approx(0.3));
    CHECK(um.doubleSided);
    CHECK(um.baseColorFactor == glm::vec4(0.25f, 0.5f, 0.75f, 0.6f));
    CHECK(um.emissiveFactor == glm::vec3(0.1f, 0.2f, 0.3f));
}

TEST_CASE("external buffers resolve next to the .gltf and a missing normal stays missing") {
    GltfBuilder b;
    b.addPositions({{0, 0, 0}, {2, 0, 0}, {0, 3, 0}});
    writeBytes(gltfScratch() / "external.bin", b.bin());
    const auto path = gltfScratch() / "external.gltf";
    writeText(path, b.json(std::string("\"meshes\":[{\"primitives\":[{\"attributes\":{"
                                       "\"POSITION\":0}}]}],") +
                               kOneNodeScene,
                           "external.bin"));
    const GltfAsset a = loadGltf(path.string());
    CHECK(a.meshes[0].primitives[0].normals.empty()); // flat normals are made when drawn
    CHECK(near(a.bounds.max, {2, 3, 0}, 0.0));
}

TEST_CASE("broken sample files fail with an error naming the file") {
    for (const char* name : {"integer-out-of-bounds.gltf", "invalid-buffer-index.gltf",
                             "invalid-buffer-view-index.gltf", "invalid-primitive-indices.gltf"}) {
        CAPTURE(name);
        const std::string message = loadError(sample(std::string("BoundsChecking/") + name));
        CHECK(contains(message, name));
    }
}

TEST_CASE("bad files throw errors that name the file and the glTF element") {
    const std::string missing = (gltfScratch() / "nothing-here.glb").string();
    CHECK(contains(loadError(missing), "nothing-here.glb: cannot read glTF file: No such file"));

    // An external buffer that is not there.
    GltfBuilder e;
    e.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const auto lost = gltfScratch() / "lost-buffer.gltf";
    writeText(lost, e.json(std::string("\"meshes\":[{\"primitives\":[{\"attributes\":{"
                                       "\"POSITION\":0}}]}],") +
                               kOneNodeScene,
                           "no-such.bin"));
    CHECK(contains(loadError(lost.string()), "lost-buffer.gltf: tinygltf"));

    // A count far beyond the view (36 bytes).
    const std::string huge = loadError(triangleWithPositionAccessor(
        "huge.gltf", "{\"bufferView\":0,\"componentType\":5126,\"count\":4294967295,"
                     "\"type\":\"VEC3\"}"));
    CHECK(contains(huge, "huge.gltf: accessors[0]: count 4294967295"));
    CHECK(contains(huge, "exceeds bufferViews[0]"));
    // An offset that pushes the last element out.
    CHECK(contains(loadError(triangleWithPositionAccessor(
                       "offset.gltf", "{\"bufferView\":0,\"byteOffset\":4,\"componentType\":5126,"
                                      "\"count\":3,\"type\":\"VEC3\"}")),
                   "accessors[0]: count 3 at byteOffset 4 exceeds"));
    // Unknown component type; a huge count with no view to back it.
    CHECK(contains(loadError(triangleWithPositionAccessor(
                       "ctype.gltf",
                       "{\"bufferView\":0,\"componentType\":5127,\"count\":3,\"type\":\"VEC3\"}")),
                   "ctype.gltf"));
    CHECK(contains(
        loadError(triangleWithPositionAccessor(
            "unbacked.gltf", "{\"componentType\":5126,\"count\":4000000000,\"type\":\"VEC3\"}")),
        "without a bufferView exceeds"));
    // Accessors count against a total of decoded values per file, checked before decoding:
    // 16 Mi MAT4 elements (2^28 values) pass the per-accessor count but not the file's total.
    CHECK(contains(
        loadError(triangleWithPositionAccessor(
            "total.gltf", "{\"componentType\":5126,\"count\":16777216,\"type\":\"MAT4\"}")),
        "accessors decode more than 134217728 values in all"));

    GltfBuilder b;
    b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const std::vector<std::uint16_t> bad{0, 1, 3};
    b.addAccessor(bad, kUShort, "SCALAR", 3);
    const std::string outOfRange = loadError(b.writeGltf(
        "index.gltf", std::string("\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},"
                                  "\"indices\":1}]}],") +
                          kOneNodeScene));
    CHECK(contains(outOfRange, "meshes[0].primitives[0]: index 3"));
    CHECK(contains(outOfRange, "not below the vertex count 3"));

    const std::string extension = loadError(b.writeGltf(
        "ext.gltf",
        std::string("\"extensionsRequired\":[\"KHR_draco_mesh_compression\"],"
                    "\"extensionsUsed\":[\"KHR_draco_mesh_compression\"],"
                    "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],") +
            kOneNodeScene));
    CHECK(contains(extension, "unsupported extension KHR_draco_mesh_compression"));

    const std::string cycle = loadError(b.writeGltf(
        "cycle.gltf", "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],"
                      "\"nodes\":[{\"mesh\":0,\"children\":[1]},{\"children\":[0]}],"
                      "\"scenes\":[{\"nodes\":[0]}]"));
    CHECK(contains(cycle, "nodes[0]: reached twice"));

    CHECK(contains(loadError(b.writeGltf(
                       "material.gltf",
                       std::string("\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},"
                                   "\"material\":4}]}],") +
                           kOneNodeScene)),
                   "meshes[0].primitives[0]: material 4 does not exist"));

    CHECK(contains(
        loadError(b.writeGltf("mesh.gltf",
                              "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],"
                              "\"nodes\":[{\"mesh\":9}],\"scenes\":[{\"nodes\":[0]}]")),
        "nodes[0]: mesh 9 does not exist"));

    // Sparse index beyond the count.
    GltfBuilder s;
    s.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const std::vector<std::uint8_t> where{7};
    const std::vector<glm::vec3> what{{1, 1, 1}};
    const int iv = s.addView(where), vv = s.addView(what);
    s.addAccessorJson("{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\","
                      "\"sparse\":{\"count\":1,\"indices\":{\"bufferView\":" +
                      std::to_string(iv) + ",\"componentType\":5121},\"values\":{\"bufferView\":" +
                      std::to_string(vv) + "}}}");
    CHECK(contains(loadError(s.writeGltf(
                       "sparse.gltf",
                       std::string("\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":1}"
                                   "}]}],") +
                           kOneNodeScene)),
                   "accessors[1].sparse.indices[0]: 7 is not below count 3"));

    // Attribute counts that disagree.
    GltfBuilder c;
    c.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    c.addAccessor(std::vector<glm::vec3>{{0, 0, 1}, {0, 0, 1}}, kFloat, "VEC3", 2);
    CHECK(contains(loadError(c.writeGltf(
                       "counts.gltf",
                       std::string("\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,"
                                   "\"NORMAL\":1}}]}],") +
                           kOneNodeScene)),
                   "attribute NORMAL has 2 elements, POSITION has 3"));
}

TEST_CASE("truncated and corrupted files are refused without reading past their end") {
    const std::string source = sample("Duck/glTF-Binary/Duck.glb");
    std::ifstream in(source, std::ios::binary);
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                          std::istreambuf_iterator<char>());
    REQUIRE(bytes.size() == 120484);
    for (std::size_t keep : {std::size_t(0), std::size_t(3), std::size_t(11), std::size_t(20),
                             std::size_t(500), bytes.size() / 2, bytes.size() - 1}) {
        CAPTURE(keep);
        const auto path = gltfScratch() / "truncated.glb";
        writeBytes(path,
                   std::vector<std::uint8_t>(bytes.begin(), bytes.begin() + std::ptrdiff_t(keep)));
        CHECK(contains(loadError(path.string()), "truncated.glb"));
    }
    // Garbage where JSON should be.
    const auto junk = gltfScratch() / "junk.gltf";
    writeText(junk, "{\"asset\":{\"version\":\"2.0\"},\"accessors\":[{\"count\":");
    CHECK(contains(loadError(junk.string()), "junk.gltf"));
}
