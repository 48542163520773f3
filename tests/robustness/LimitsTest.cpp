// The declared limits of core/Limits.h: past each one a reader or generator refuses with an
// Error naming the limit (and the file and place), before allocating anything.
#include <doctest/doctest.h>

#include <climits>
#include <fstream>
#include <string>
#include <vector>

#include <volsg/io/Tokenizer.h>
#include <volsg/volume/VolumeGrid.h>

#include "robustness/RobustnessSupport.h"

using namespace volsg;
using namespace volsg::test;
namespace fs = std::filesystem;

TEST_CASE("volume dimensions past the per-axis limit are refused before allocating") {
    for (const glm::ivec3 d : {glm::ivec3(100000, 100000, 100000), glm::ivec3(1, 1, INT_MAX),
                               glm::ivec3(limits::maxVolumeDimension + 1, 1, 1)}) {
        CAPTURE(d.x);
        CAPTURE(d.z);
        CHECK_THROWS_WITH_AS(VolumeGrid::create(d, VoxelType::Float),
                             doctest::Contains("exceed the limit of 65536 voxels per axis"), Error);
    }
    // The largest allowed axis alone is fine.
    CHECK(VolumeGrid::create({limits::maxVolumeDimension, 1, 1}, VoxelType::UByte)->voxelCount() ==
          std::size_t(limits::maxVolumeDimension));
}

TEST_CASE("a volume larger than the machine's memory is refused whatever limit is passed") {
    const std::uint64_t memory = limits::physicalMemoryBytes();
    REQUIRE(memory > 0);
    const int n = limits::maxVolumeDimension; // 65536^3 floats: 1 PiB
    CHECK_THROWS_WITH_AS(
        VolumeGrid::create({n, n, n}, VoxelType::Float, glm::dvec3(1.0), std::uint64_t(-1)),
        doctest::Contains("more than this machine's memory"), Error);
    CHECK_THROWS_WITH_AS(VolumeGrid::create({n, n, n}, VoxelType::Float),
                         doctest::Contains("exceeds the allocation limit"), Error);
}

TEST_CASE("raw volume layouts with absurd dimensions are refused naming the file") {
    const fs::path dir = robustnessScratch("rawlimits");
    const fs::path file = dir / "tiny.raw";
    std::ofstream(file) << "abcd";
    RawVolumeLayout layout;
    layout.dimensions = {100000, 100000, 100000};
    CHECK_THROWS_WITH_AS(readRawVolume(file.string(), layout), doctest::Contains("tiny.raw"),
                         Error);
    layout.dimensions = {65536, 65536, 65536};
    layout.type = VoxelType::Float;
    CHECK_THROWS_WITH_AS(readRawVolume(file.string(), layout),
                         doctest::Contains("exceeds the allocation limit"), Error);
}

TEST_CASE("scene limits are the ones Limits.h declares") {
    CHECK(maxSceneNestingDepth == limits::maxSceneNestingDepth);
    CHECK(maxSceneFileSize == limits::maxSceneFileSize);
    CHECK(Tokenizer::maxWordLength == limits::maxWordLength);
    CHECK(VolumeGrid::defaultByteLimit == limits::maxVolumeBytes);
}

TEST_CASE("an unknown node declaring too many fields is refused at the field past the limit") {
    std::string text = "#Inventor V2.1 ascii\nFoo { fields [ ";
    for (std::size_t i = 0; i <= limits::maxDeclaredFields; ++i)
        text += "SFFloat f" + std::to_string(i) + ", ";
    text += "] }\n";
    try {
        readSceneFromString(text, "many.iv");
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(e.file() == "many.iv");
        CHECK(e.line() == 2);
        CHECK(std::string(e.what()).find("declares more than 1024 fields") != std::string::npos);
    }
}

TEST_CASE("a glTF image header larger than the image limit is refused before decoding") {
    const fs::path dir = robustnessScratch("gltfimage");
    // A PNG signature and IHDR declaring 70000 x 10 pixels: over the 65536 side limit.
    const unsigned char png[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0,    0, 0,
                                 13,   'I', 'H', 'D', 'R',  0,    1,    0x11, 0x70, 0, 0,
                                 0,    10,  8,   6,   0,    0,    0,    0,    0,    0, 0};
    std::ofstream(dir / "big.png", std::ios::binary)
        .write(reinterpret_cast<const char*>(png), sizeof png);
    std::ofstream(dir / "model.gltf")
        << R"({"asset":{"version":"2.0"},"images":[{"uri":"big.png"}]})";
    const std::string message = loadError(dir / "model.gltf");
    CHECK(message.find("model.gltf") != std::string::npos);
    CHECK(message.find("70000x10 pixels exceeds the image limit") != std::string::npos);
}

TEST_CASE("glTF URIs cannot read files outside the model's folder") {
    const fs::path dir = robustnessScratch("gltfuri");
    fs::create_directories(dir / "models");
    std::ofstream(dir / "secret.bin") << "0123456789abcdef";
    fs::create_symlink(dir / "secret.bin", dir / "models" / "link.bin");
    for (const std::string& uri : std::vector<std::string>{
             "../secret.bin", (dir / "secret.bin").string(), "link.bin", "sub/../../secret.bin"}) {
        CAPTURE(uri);
        std::ofstream(dir / "models" / "m.gltf")
            << R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":16,"uri":")" << uri
            << R"("}]})";
        const std::string message = loadError(dir / "models" / "m.gltf");
        CHECK(!message.empty());
        CHECK(message.find("m.gltf") != std::string::npos);
    }
    // A buffer beside the model is read.
    std::ofstream(dir / "models" / "ok.bin") << "0123456789abcdef";
    std::ofstream(dir / "models" / "m.gltf")
        << R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":16,"uri":"ok.bin"}]})";
    CHECK(loadError(dir / "models" / "m.gltf").empty());
}
