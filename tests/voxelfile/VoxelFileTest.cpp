// The compact voxel-list file (.vsgv): bit-exact round trips of voxels, parameters and the
// rendered image without the volume, visualization edits, refused re-extraction, and the
// reader's refusal of truncated, corrupt, foreign and oversized files.
#include <doctest/doctest.h>

#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/context/OSMesaContext.h>
#include <volsg/core/Error.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/SceneWriter.h>
#include <volsg/nodes/ClipPlane.h>
#include <volsg/nodes/ShearWarpVolume.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/VolumeObject.h>
#include <volsg/render/Renderer.h>
#include <volsg/volume/VolumeGrid.h>
#include <volsg/voxelfile/PositionCoding.h>
#include <volsg/voxelfile/VoxelFile.h>
#include <volsg/voxelfile/VoxelFileScene.h>

#include <unistd.h>
#include <zlib.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <vector>

using namespace volsg;
namespace fs = std::filesystem;

namespace {

template <class T> void collect(Node& node, std::vector<T*>& out) {
    if (node.isA<T>()) out.push_back(static_cast<T*>(&node));
    if (auto* children = node.children())
        for (const auto& child : *children)
            if (child) collect(*child, out);
}

/// The `index`-th node of type T, depth first, or null.
template <class T> T* findNode(Node& root, std::size_t index = 0) {
    std::vector<T*> all;
    collect(root, all);
    return index < all.size() ? all[index] : nullptr;
}

/// A fresh folder under the system temp folder, removed at the end of the test.
struct TempDir {
    fs::path path;
    explicit TempDir(const std::string& name) {
        path = fs::temp_directory_path() /
               ("volsg-voxelfile-" + name + "-" + std::to_string(::getpid()));
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

void writeBytes(const fs::path& path, const std::vector<unsigned char>& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

/// A 32^3 UBYTE volume (a soft ball brighter towards its centre, with a bright off-centre
/// knot) and its labels (1: the knot, 2: the rest of the ball), written as raw files.
void writeVolumeFiles(const fs::path& dir) {
    const int n = 32;
    std::vector<unsigned char> data(std::size_t(n * n * n)), tags(data.size());
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const glm::dvec3 p = (glm::dvec3(i, j, k) + 0.5) / double(n) * 2.0 - 1.0;
                const double ball = std::max(0.0, 1.0 - glm::length(p) / 0.85);
                const double knot =
                    std::max(0.0, 1.0 - glm::length(p - glm::dvec3(0.3, 0.2, -0.1)) / 0.35);
                const double v = std::min(1.0, 0.8 * ball + knot);
                const std::size_t index = std::size_t((k * n + j) * n + i);
                data[index] = (unsigned char)std::lround(255.0 * v);
                tags[index] = knot > 0.3 ? 1 : ball > 0.0 ? 2 : 0;
            }
    writeBytes(dir / "ball.raw", data);
    writeBytes(dir / "ball-tags.raw", tags);
}

/// Every kind of parameter the file must keep: camera, light, transform, clip plane, box
/// clip, transfer functions per tag, render modes, compositing, opacities.
const char* kScene = R"(#Inventor V2.1 ascii
Separator {
  OrthographicCamera { position 0.3 0.4 5 orientation 1 0 0 -0.08 height 2.6 nearDistance 1 farDistance 9 }
  DirectionalLight { direction -0.4 -0.5 -1 }
  Transform { rotation 0 1 0 0.35 translation 0.05 0 0 }
  VolumeData { fileName "ball.raw" tagFileName "ball-tags.raw" dimensions 32 32 32 dataType UBYTE spacing 0.0625 0.0625 0.0625 }
  ClipPlane { plane 0 0 -1 -0.55 }
  DEF PACKED ShearWarpVolume {
    interObjectCompositing DVR
    DEF SHELL_TF TransferFunction {
      dataRange 0 255
      red [ 0 0.9, 1 1 ] green [ 0 0.6, 1 0.9 ] blue [ 0 0.4, 1 0.8 ] alpha [ 0 0.35, 1 0.35 ]
    }
    BoxClip { origin -0.9 -0.9 -0.9 extent 1.8 1.1 1.8 }
    DEF SHELL VolumeObject { source THRESHOLD threshold 60 255 voxels SURFACE renderMode SHADED clippedOpacity 0.25 clippedRenderMode CONTOUR shininess 12 }
    DEF KNOT_TF TransferFunction {
      tag 1 dataRange 0 255
      red [ 0 0.2, 1 1 ] green [ 0 0.1, 1 0.3 ] blue [ 0 0.9, 1 0.2 ] alpha [ 0 0, 0.5 0.05, 1 0.4 ]
    }
    DEF KNOT VolumeObject { source TAG tag 1 voxels VISIBLE renderMode TF compositing DVR opacity 0.8 }
  }
}
)";

RenderOptions options64() {
    RenderOptions o;
    o.width = o.height = 64;
    o.background = glm::vec3(0.05f, 0.05f, 0.1f);
    return o;
}

/// Pixels equal bit for bit; returns how many differ.
std::size_t differingPixels(const Image& a, const Image& b) {
    REQUIRE(a.width == b.width);
    REQUIRE(a.height == b.height);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        differ += std::memcmp(&a.pixels[i], &b.pixels[i], sizeof(glm::vec4)) != 0;
    return differ;
}

std::size_t coloredPixels(const Image& image) {
    std::size_t n = 0;
    for (const glm::vec4& p : image.pixels)
        n += std::abs(p.r - 0.05f) > 0.02f || std::abs(p.b - 0.1f) > 0.02f;
    return n;
}

/// The scene in its own folder with its volume files, and its packed bytes.
struct PackedScene {
    TempDir dir{"scene"};
    ref_ptr<Node> root;
    VoxelFileContent content;
    std::string bytes;
    PackedScene() {
        writeVolumeFiles(dir.path);
        std::ofstream(dir.path / "scene.iv") << kScene;
        root = readScene((dir.path / "scene.iv").string());
        content = packScene(*root);
        bytes = encodeVoxelFile(content);
    }
};

std::span<const std::byte> asBytes(const std::string& s) {
    return {reinterpret_cast<const std::byte*>(s.data()), s.size()};
}

/// readVoxelFile must refuse `bytes` with an Error naming the file.
void checkRefused(const std::string& bytes, const std::string& expect = "") {
    try {
        readVoxelFile(asBytes(bytes), "damaged.vsgv");
        FAIL("accepted a damaged file");
    } catch (const Error& e) {
        const std::string what = e.what();
        CHECK(what.find("damaged.vsgv") != std::string::npos);
        if (!expect.empty()) CHECK_MESSAGE(what.find(expect) != std::string::npos, what);
    }
}

void putLE(std::string& s, std::size_t at, std::uint64_t v, int bytes) {
    for (int b = 0; b < bytes; ++b)
        s[at + std::size_t(b)] = char(std::uint8_t(v >> (8 * b)));
}

std::uint32_t crcOf(const char* p, std::size_t n, std::uint32_t crc = 0) {
    return std::uint32_t(crc32(crc, reinterpret_cast<const Bytef*>(p), uInt(n)));
}

/// Rewrites the file header's CRC after an edit, so only the edited field is wrong.
void fixHeaderCrc(std::string& s) {
    putLE(s, 24, crcOf(s.data(), 24), 4);
}

/// Offsets of the sections (their 24-byte headers) in a well-formed file.
std::vector<std::size_t> sectionOffsets(const std::string& s) {
    std::vector<std::size_t> out;
    std::size_t at = 28;
    while (at < s.size()) {
        out.push_back(at);
        std::uint64_t stored = 0;
        for (int b = 0; b < 8; ++b)
            stored |= std::uint64_t(std::uint8_t(s[at + 4 + std::size_t(b)])) << (8 * b);
        at += 24 + std::size_t(stored);
    }
    return out;
}

/// A file of the scene section and one object section holding `record` (compressed, with
/// correct sizes and CRCs): a record that passes every checksum reaches the record parser.
std::string fileWithRecord(const std::string& sceneText, const std::string& record) {
    auto section = [](const char* tag, const std::string& raw) {
        uLongf size = compressBound(uLong(raw.size()));
        std::string stored(size, '\0');
        compress2(reinterpret_cast<Bytef*>(stored.data()), &size,
                  reinterpret_cast<const Bytef*>(raw.data()), uLong(raw.size()), 6);
        stored.resize(size);
        std::string s(24, '\0');
        std::memcpy(s.data(), tag, 4);
        putLE(s, 4, stored.size(), 8);
        putLE(s, 12, raw.size(), 8);
        putLE(s, 20, crcOf(stored.data(), stored.size(), crcOf(s.data(), 20)), 4);
        return s + stored;
    };
    std::string file = "VSGV\r\n\x1a\n" + std::string(20, '\0');
    putLE(file, 8, 1, 4);
    putLE(file, 12, 2, 4);
    file += section("SCNE", sceneText) + section("VOXL", record);
    putLE(file, 16, file.size(), 8);
    fixHeaderCrc(file);
    return file;
}

/// An object record with the given counts (and nothing after them).
std::string recordHeader(glm::ivec3 dims, std::uint64_t voxels, std::uint64_t positionBytes) {
    std::string r(4 + 4 + 4 + 4 + 5 * 8 + 12 + 32 + 18, '\0');
    std::size_t at = 16 + 5 * 8;
    for (int a = 0; a < 3; ++a, at += 4)
        putLE(r, at, std::uint32_t(dims[a]), 4);
    const double one = 1.0;
    std::uint64_t bits;
    std::memcpy(&bits, &one, 8);
    for (int a = 0; a < 3; ++a, at += 8)
        putLE(r, at, bits, 8);
    at += 8; // maxMagnitude 0
    putLE(r, at, voxels, 8);
    putLE(r, at + 8, positionBytes, 8);
    return r;
}

/// The arrays equal bit for bit, the magnitude at its rendering precision (the 4 bits the
/// packed voxel takes).
void checkSameVoxels(const VoxelObject::Arrays& x, const VoxelObject::Arrays& y) {
    CHECK(y.dimensions == x.dimensions);
    CHECK(y.spacing == x.spacing);
    CHECK(y.maxMagnitude == x.maxMagnitude);
    CHECK(y.i == x.i);
    CHECK(y.j == x.j);
    CHECK(y.k == x.k);
    CHECK(y.value12 == x.value12);
    CHECK(y.gradientCode == x.gradientCode);
    REQUIRE(y.magnitude8.size() == x.magnitude8.size());
    std::size_t magnitudesDiffer = 0;
    for (std::size_t v = 0; v < x.magnitude8.size(); ++v)
        magnitudesDiffer += (x.magnitude8[v] >> 4) != (y.magnitude8[v] >> 4);
    CHECK(magnitudesDiffer == 0u);
}

} // namespace

TEST_CASE("voxels, extraction records and the scene round trip bit for bit") {
    PackedScene packed;
    REQUIRE(packed.content.objects.size() == 2u);
    const VoxelFileContent back = readVoxelFile(asBytes(packed.bytes), "scene.vsgv");
    CHECK(back.sceneText == packed.content.sceneText);
    REQUIRE(back.objects.size() == 2u);
    for (std::size_t o = 0; o < 2; ++o) {
        const PackedObject& a = packed.content.objects[o];
        const PackedObject& b = back.objects[o];
        CHECK(b.volumeIndex == 0u);
        CHECK(b.objectIndex == std::uint32_t(o));
        CHECK(b.extraction.source.kind == a.extraction.source.kind);
        CHECK(b.extraction.source.tag == a.extraction.source.tag);
        CHECK(b.extraction.source.low == a.extraction.source.low);
        CHECK(b.extraction.source.high == a.extraction.source.high);
        CHECK(b.extraction.selection == a.extraction.selection);
        CHECK(b.extraction.gradientThreshold == a.extraction.gradientThreshold);
        CHECK(b.extraction.dataRange == a.extraction.dataRange);
        const VoxelObject::Arrays x = a.voxels->arrays(), y = b.voxels->arrays();
        CHECK(x.i.size() > 100u); // both objects hold real voxels
        checkSameVoxels(x, y);
    }
    CHECK(packed.content.objects[0].extraction.source.kind == ObjectSource::Threshold);
    CHECK(packed.content.objects[0].extraction.source.low == 60.0);
    CHECK(packed.content.objects[1].extraction.source.tag == 1);
    // The stored scene keeps the parameters and drops the volume files.
    const std::string& text = back.sceneText;
    CHECK(text.find("VolumeData") == std::string::npos);
    CHECK(text.find("voxelFile \"#0\"") != std::string::npos);
    for (const char* kept : {"OrthographicCamera", "DirectionalLight", "ClipPlane", "BoxClip",
                             "clippedRenderMode CONTOUR", "shininess 12", "opacity 0.8"})
        CHECK_MESSAGE(text.find(kept) != std::string::npos, kept);
}

TEST_CASE("objects with more than 256 distinct values round trip without the value palette") {
    std::mt19937 random(11);
    VoxelObject::Arrays a;
    a.dimensions = glm::ivec3(300, 3, 2);
    a.spacing = glm::dvec3(0.5, 0.25, 2.0);
    a.maxMagnitude = 3.5;
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 300; ++i)
                if (random() % 4 != 0) {
                    a.i.push_back(std::uint16_t(i));
                    a.j.push_back(std::uint16_t(j));
                    a.k.push_back(std::uint16_t(k));
                    a.value12.push_back(std::uint16_t(random() % 4096));
                    a.gradientCode.push_back(std::uint16_t(random() % 4096));
                    a.magnitude8.push_back(std::uint8_t((random() % 16) << 4));
                }
    const VoxelObject::Arrays expected = a;
    VoxelFileContent content;
    content.sceneText = "#Inventor V2.1 ascii\nSeparator { }\n";
    PackedObject o;
    o.volumeIndex = 3;
    o.extraction.source.kind = ObjectSource::Threshold;
    o.extraction.source.low = 0.25;
    o.extraction.source.high = 1e9;
    o.extraction.selection = VoxelSelection::Gradient;
    o.extraction.gradientThreshold = 0.125;
    o.extraction.dataRange = glm::dvec2(-1000.0, 3000.5);
    o.voxels = VoxelObject::fromArrays(std::move(a));
    content.objects.push_back(o);
    const VoxelFileContent back = readVoxelFile(asBytes(encodeVoxelFile(content)), "random.vsgv");
    REQUIRE(back.objects.size() == 1u);
    const PackedObject& b = back.objects[0];
    CHECK(b.volumeIndex == 3u);
    CHECK(b.extraction.source.high == 1e9);
    CHECK(b.extraction.selection == VoxelSelection::Gradient);
    CHECK(b.extraction.gradientThreshold == 0.125);
    CHECK(b.extraction.dataRange == glm::dvec2(-1000.0, 3000.5));
    const VoxelObject::Arrays y = b.voxels->arrays();
    checkSameVoxels(expected, y);
    CHECK(y.magnitude8 == expected.magnitude8); // its low bits were zero: all of it returns
}

TEST_CASE("a vsgv opened without its volume renders exactly the original image") {
    OSMesaContext context;
    Renderer renderer;
    PackedScene packed;
    const Image original = renderer.render(*packed.root, options64());
    REQUIRE(coloredPixels(original) > 300u);

    TempDir elsewhere("elsewhere"); // no volume files here
    const fs::path file = elsewhere.path / "ball.vsgv";
    writeVoxelFile(file.string(), packed.content);
    ref_ptr<Node> loaded = readSceneOrVoxelFile(file.string());
    const Image fromFile = renderer.render(*loaded, options64());
    CHECK(differingPixels(original, fromFile) == 0u);

    // The same through a plain scene that names the file (volsg-pack --scene).
    std::ofstream(elsewhere.path / "companion.iv")
        << companionSceneText(packed.content, "ball.vsgv");
    ref_ptr<Node> companion = readSceneOrVoxelFile((elsewhere.path / "companion.iv").string());
    REQUIRE(findNode<ShearWarpVolume>(*companion) != nullptr);
    CHECK(findNode<ShearWarpVolume>(*companion)->voxelFile() == "ball.vsgv#0");
    CHECK(differingPixels(original, renderer.render(*companion, options64())) == 0u);

    // The bounding box (the viewer's view-all) comes from the stored dimensions.
    const Box3 a = computeBoundingBox(*packed.root), b = computeBoundingBox(*loaded);
    CHECK(!a.isEmpty());
    CHECK(glm::all(glm::equal(a.min, b.min)));
    CHECK(glm::all(glm::equal(a.max, b.max)));
}

TEST_CASE("transfer functions modes opacities and clipping edit the stored voxels") {
    OSMesaContext context;
    Renderer renderer;
    PackedScene packed;
    TempDir elsewhere("edits");
    const fs::path file = elsewhere.path / "ball.vsgv";
    writeVoxelFile(file.string(), packed.content);
    ref_ptr<Node> loaded = readSceneOrVoxelFile(file.string());
    const Image before = renderer.render(*loaded, options64());

    // The same edits on both graphs: the images stay equal and differ from the first one.
    for (Node* root : {packed.root.get(), loaded.get()}) {
        Node* shell = findNode<VolumeObject>(*root, 0);
        Node* knot = findNode<VolumeObject>(*root, 1);
        REQUIRE(shell);
        REQUIRE(knot);
        auto& s = static_cast<VolumeObject&>(*shell);
        auto& k = static_cast<VolumeObject&>(*knot);
        s.renderMode.setValue(VolumeObject::COLORED_CONTOUR);
        s.opacity.setValue(0.6f);
        k.compositing.setValue(VolumeObject::MIP);
        auto* tf = findNode<TransferFunction>(*root, 0);
        REQUIRE(tf);
        tf->red.setValues({glm::vec2(0.0f, 0.1f), glm::vec2(1.0f, 0.4f)});
        auto* clip = findNode<ClipPlane>(*root);
        REQUIRE(clip);
        clip->plane.setValue(Plane{glm::vec3(1.0f, 0.0f, 0.0f), -0.2f});
    }
    const Image editedOriginal = renderer.render(*packed.root, options64());
    const Image editedLoaded = renderer.render(*loaded, options64());
    CHECK(differingPixels(editedOriginal, editedLoaded) == 0u);
    CHECK(differingPixels(before, editedLoaded) > 200u);
}

TEST_CASE("a new extraction without the volume is refused naming the field") {
    OSMesaContext context;
    Renderer renderer;
    PackedScene packed;
    TempDir elsewhere("extract");
    const fs::path file = elsewhere.path / "ball.vsgv";
    writeVoxelFile(file.string(), packed.content);

    auto refusal = [&](const std::function<void(Node&)>& edit) {
        ref_ptr<Node> loaded = readSceneOrVoxelFile(file.string());
        edit(*loaded);
        try {
            renderer.render(*loaded, options64());
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("(rendered)");
    };
    auto shell = [](Node& root) { return findNode<VolumeObject>(root, 0); };
    auto knot = [](Node& root) { return findNode<VolumeObject>(root, 1); };
    std::string what = refusal([&](Node& r) { shell(r)->threshold.setValue({80.0f, 255.0f}); });
    CHECK(what.find("'threshold'") != std::string::npos);
    CHECK(what.find("original volume") != std::string::npos);
    CHECK(what.find("ball.vsgv") != std::string::npos);
    what = refusal([&](Node& r) { shell(r)->voxels.setValue(VolumeObject::GRADIENT); });
    CHECK(what.find("'voxels'") != std::string::npos);
    what = refusal([&](Node& r) { knot(r)->tag.setValue(2); });
    CHECK(what.find("'tag'") != std::string::npos);
    what = refusal([&](Node& r) { knot(r)->source.setValue(VolumeObject::WHOLE); });
    CHECK(what.find("'source'") != std::string::npos);
    what = refusal([&](Node& r) {
        findNode<TransferFunction>(r, 1)->dataRange.setValue({0.0f, 200.0f});
    });
    CHECK(what.find("dataRange") != std::string::npos);
    what = refusal([&](Node& r) {
        static_cast<Group*>(findNode<ShearWarpVolume>(r))
            ->addChild(ref_ptr<Node>(new VolumeObject));
    });
    CHECK(what.find("more VolumeObjects than the 2 stored") != std::string::npos);
    // Fields that only select among stored voxels' looks do not need the volume.
    CHECK(refusal([&](Node& r) { knot(r)->clippedOpacity.setValue(0.5f); }) == "(rendered)");
}

TEST_CASE("truncated files are refused at every length") {
    PackedScene packed;
    const std::string& bytes = packed.bytes;
    REQUIRE(bytes.size() > 1000u);
    const std::size_t step = std::max<std::size_t>(1, bytes.size() / 3000);
    for (std::size_t length = 0; length < bytes.size(); length += step)
        checkRefused(bytes.substr(0, length));
    checkRefused(bytes.substr(0, 20), "truncated");
    checkRefused(bytes.substr(0, bytes.size() - 1), "truncated");
    checkRefused(bytes + "x", "trailing");
}

TEST_CASE("a flipped byte anywhere in any section is refused") {
    PackedScene packed;
    const std::string& bytes = packed.bytes;
    const std::vector<std::size_t> sections = sectionOffsets(bytes);
    REQUIRE(sections.size() == 3u); // the scene and two objects
    const std::size_t step = std::max<std::size_t>(1, bytes.size() / 4000);
    for (std::size_t at = 0; at < bytes.size(); at += step) {
        std::string damaged = bytes;
        damaged[at] = char(damaged[at] ^ 0x5A);
        checkRefused(damaged);
    }
    for (std::size_t s = 0; s < sections.size(); ++s) {
        std::string damaged = bytes;
        const std::size_t at = (s + 1 < sections.size() ? sections[s + 1] : bytes.size()) - 7;
        damaged[at] = char(damaged[at] ^ 1);
        checkRefused(damaged, "section " + std::to_string(s));
        checkRefused(damaged, "checksum mismatch");
    }
}

TEST_CASE("wrong magic and wrong version are refused") {
    PackedScene packed;
    std::string damaged = packed.bytes;
    damaged[0] = 'W';
    checkRefused(damaged, "wrong magic");
    checkRefused("#Inventor V2.1 ascii\nSeparator {}\n", "wrong magic");
    damaged = packed.bytes;
    putLE(damaged, 8, 2, 4);
    fixHeaderCrc(damaged);
    checkRefused(damaged, "format version 2");
}

TEST_CASE("absurd declared sizes are refused before allocation") {
    PackedScene packed;
    const std::vector<std::size_t> sections = sectionOffsets(packed.bytes);
    std::string damaged = packed.bytes;
    putLE(damaged, 16, std::uint64_t(1) << 60, 8); // file size
    fixHeaderCrc(damaged);
    checkRefused(damaged, "truncated");
    damaged = packed.bytes;
    putLE(damaged, 12, 0xFFFFFFFFu, 4); // section count
    fixHeaderCrc(damaged);
    checkRefused(damaged, "section count");
    for (std::size_t at : sections) { // stored and raw sizes of each section
        damaged = packed.bytes;
        putLE(damaged, at + 4, std::uint64_t(1) << 62, 8);
        checkRefused(damaged, "truncated");
        damaged = packed.bytes;
        putLE(damaged, at + 12, std::uint64_t(1) << 40, 8);
        checkRefused(damaged, "limit");
    }
    // Records that pass every checksum but declare absurd counts.
    const std::string scene = packed.content.sceneText;
    checkRefused(fileWithRecord(scene, recordHeader({32, 32, 32}, std::uint64_t(1) << 60, 0)),
                 "cells");
    checkRefused(fileWithRecord(scene, recordHeader({32, 32, 32}, 1000, std::uint64_t(1) << 61)),
                 "declared sizes");
    checkRefused(fileWithRecord(scene, recordHeader({65535, 65535, 65535}, 10, 0)),
                 "declared sizes");
    checkRefused(fileWithRecord(scene, recordHeader({70000, 4, 4}, 0, 0)), "dimension 70000");
    checkRefused(fileWithRecord(scene, recordHeader({4, 4, 4}, 0, 0).substr(0, 30)), "ends inside");
    // A well-sized record whose position code has more scanlines than bytes.
    std::string record = recordHeader({8, 65535, 65535}, 0, 0);
    checkRefused(fileWithRecord(scene, record), "scanlines");
}

TEST_CASE("position run coding round trips and refuses runs past a scanline") {
    const glm::ivec3 n(40, 7, 5);
    std::mt19937 random(7);
    std::vector<std::uint16_t> i, j, k;
    for (int z = 0; z < n.z; ++z)
        for (int y = 0; y < n.y; ++y)
            for (int x = 0; x < n.x; ++x)
                // runs of 5 with random holes, and one run to the scanline's end
                if ((((x / 5) + y + z) % 2 == 0 && random() % 16 != 0) || (y == 3 && x > 30)) {
                    i.push_back(std::uint16_t(x));
                    j.push_back(std::uint16_t(y));
                    k.push_back(std::uint16_t(z));
                }
    const std::string code = encodePositions(n, i, j, k);
    CHECK(code.size() * 10 < i.size() * 6); // runs take well under a byte per voxel here
    std::vector<std::uint16_t> i2, j2, k2;
    decodePositions(reinterpret_cast<const std::uint8_t*>(code.data()), code.size(), n, i.size(),
                    i2, j2, k2, "test");
    CHECK(i2 == i);
    CHECK(j2 == j);
    CHECK(k2 == k);
    // A scanline narrower than the runs, a wrong count, and unsorted input are errors.
    CHECK_THROWS_AS(decodePositions(reinterpret_cast<const std::uint8_t*>(code.data()), code.size(),
                                    glm::ivec3(20, 7, 5), i.size(), i2, j2, k2, "t"),
                    Error);
    CHECK_THROWS_AS(decodePositions(reinterpret_cast<const std::uint8_t*>(code.data()), code.size(),
                                    n, i.size() + 1, i2, j2, k2, "t"),
                    Error);
    std::swap(i[0], i[1]);
    CHECK_THROWS_AS(encodePositions(n, i, j, k), Error);
}

TEST_CASE("writing replaces the file whole and a failed write leaves no file") {
    PackedScene packed;
    TempDir dir("write");
    const fs::path file = dir.path / "out.vsgv";
    writeVoxelFile(file.string(), packed.content);
    writeVoxelFile(file.string(), packed.content); // replaces
    CHECK(fs::file_size(file) == packed.bytes.size());
    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path))
        ++entries;
    CHECK(entries == 1u); // no temporary left behind
    CHECK_THROWS_AS(writeVoxelFile((dir.path / "missing" / "out.vsgv").string(), packed.content),
                    Error);
    CHECK_THROWS_WITH_AS(readVoxelFileFromPath((dir.path / "none.vsgv").string()),
                         doctest::Contains("none.vsgv"), Error);
}
