// VolumeData, TransferFunction and BoxClip: read from scene text, generated grids, lazy reload.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <volsg/core/Error.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/BoxClip.h>
#include <volsg/nodes/Group.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/volume/TestVolumes.h>
#include <volsg/volume/TransferFunction1D.h>
#include <volsg/volume/VolumeGrid.h>

#include "../support/TempDir.h"

using namespace volsg;

namespace {

// The first child of the Separator a scene string reads into, as a T.
template <class T> ref_ptr<T> readOne(const std::string& body) {
    ref_ptr<Node> root = readSceneFromString("#Inventor V2.1 ascii\n" + body);
    if (root->isA<T>()) return root.cast<T>();
    REQUIRE(root->children());
    REQUIRE(!root->children()->empty());
    ref_ptr<T> node = (*root->children())[0].template cast<T>();
    REQUIRE(node);
    return node;
}

std::filesystem::path scratchDir() {
    return test::processScratch("volsg-volume-nodes-test");
}

void writeBytes(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// The first child of a scene file's root Separator, as a T.
template <class T> ref_ptr<T> readOneFromFile(const std::filesystem::path& scene) {
    ref_ptr<Node> root = readScene(scene.string());
    REQUIRE(root->children());
    ref_ptr<T> node = (*root->children())[0].template cast<T>();
    REQUIRE(node);
    return node;
}

} // namespace

TEST_CASE("VolumeData reads its enum fields by their file names") {
    auto data = readOne<VolumeData>(
        "VolumeData { dataType SHORT byteOrder BIG_ENDIAN tagDataType USHORT generator THIN_SHELL "
        "dimensions 8 8 8 headerSkip 12 }");
    CHECK(data->dataType() == VolumeData::SHORT);
    CHECK(data->byteOrder() == VolumeData::BIG_ENDIAN_ORDER);
    CHECK(data->tagDataType() == VolumeData::USHORT);
    CHECK(data->generator() == VolumeData::THIN_SHELL);
    CHECK(data->headerSkip() == 12u);
    CHECK(std::string(VolumeData::byteOrderNames.nameOf(VolumeData::LITTLE_ENDIAN_ORDER)) ==
          "LITTLE_ENDIAN");
    CHECK_THROWS_AS(readOne<VolumeData>("VolumeData { tagDataType FLOAT }"), Error);
}

TEST_CASE("a generated Marschner-Lobb VolumeData holds the sampled signal") {
    auto data = readOne<VolumeData>("VolumeData { generator MARSCHNER_LOBB dimensions 17 17 17 }");
    ref_ptr<const VolumeGrid> grid = data->grid();
    REQUIRE(grid);
    CHECK(grid->dimensions() == glm::ivec3(17));
    CHECK(grid->type() == VoxelType::UByte);
    CHECK(grid->spacing().x == doctest::Approx(2.0 / 16.0).epsilon(1e-12));
    CHECK(!data->tagGrid());
    // Voxel (i,j,k) samples the signal at -1 + i/8 (UByte stores round(255 rho)).
    for (const glm::ivec3 v : {glm::ivec3(0, 0, 0), glm::ivec3(8, 8, 8), glm::ivec3(3, 11, 16)}) {
        const double rho = marschnerLobb(-1.0 + v.x / 8.0, -1.0 + v.y / 8.0, -1.0 + v.z / 8.0);
        CHECK(grid->value(v.x, v.y, v.z) == std::nearbyint(255.0 * rho));
    }
}

TEST_CASE("a generator without dimensions makes a 64 cubed volume") {
    auto data = readOne<VolumeData>("VolumeData { generator SOFT_SPHERE }");
    CHECK(data->grid()->dimensions() == glm::ivec3(64));
}

TEST_CASE("the RAMP16 generator spans the whole 16-bit range along x") {
    auto data = readOne<VolumeData>("VolumeData { generator RAMP16 dimensions 6 3 2 }");
    ref_ptr<const VolumeGrid> grid = data->grid();
    CHECK(grid->type() == VoxelType::UShort);
    CHECK(grid->dimensions() == glm::ivec3(6, 3, 2));
    CHECK(grid->value(0, 2, 1) == 0.0);
    CHECK(grid->value(5, 0, 0) == 65535.0);
    CHECK(grid->value(2, 1, 1) == std::nearbyint(65535.0 * 2.0 / 5.0));
}

TEST_CASE("the LABELLED generator gives data and a tag grid of the same size") {
    auto data = readOne<VolumeData>("VolumeData { generator LABELLED dimensions 20 20 20 }");
    REQUIRE(data->tagGrid());
    CHECK(data->tagGrid()->dimensions() == data->grid()->dimensions());
    // Centre voxel is within r < 0.25 n: tag 1. A corner voxel with k < n/4 is outside r < 0.4 n:
    // tag 3.
    CHECK(data->tagGrid()->value(10, 10, 10) == 1.0);
    CHECK(data->tagGrid()->value(0, 0, 0) == 3.0);
    CHECK(data->tagGrid()->value(0, 0, 19) == 0.0);
}

TEST_CASE("a spacing written in the scene replaces a generator's own") {
    auto data = readOne<VolumeData>(
        "VolumeData { generator SOFT_SPHERE dimensions 4 4 4 spacing 0.5 1 2 }");
    CHECK(data->grid()->spacing() == glm::dvec3(0.5, 1.0, 2.0));
}

TEST_CASE("VolumeData loads once and reloads after a field changes") {
    auto data = readOne<VolumeData>("VolumeData { generator SOFT_SPHERE dimensions 8 8 8 }");
    ref_ptr<const VolumeGrid> first = data->grid();
    CHECK(data->grid().get() == first.get()); // cached: the same grid object
    data->dimensions = glm::vec3(10.0f);
    ref_ptr<const VolumeGrid> second = data->grid();
    CHECK(second.get() != first.get());
    CHECK(second->dimensions() == glm::ivec3(10));
}

TEST_CASE("VolumeData reports bad dimensions and missing input as errors") {
    auto notCubic = readOne<VolumeData>("VolumeData { generator MARSCHNER_LOBB dimensions 8 8 9 }");
    CHECK_THROWS_AS(notCubic->grid(), Error);
    auto fractional =
        readOne<VolumeData>("VolumeData { generator SOFT_SPHERE dimensions 8.5 8 8 }");
    CHECK_THROWS_AS(fractional->grid(), Error);
    auto nothing = readOne<VolumeData>("VolumeData { }");
    CHECK_THROWS_AS(nothing->grid(), Error);
    auto missing = readOne<VolumeData>("VolumeData { fileName \"/nonexistent/volume.nrrd\" }");
    try {
        missing->grid();
        FAIL("no error for a missing file");
    } catch (const Error& e) {
        CHECK(std::string(e.what()).find("/nonexistent/volume.nrrd") != std::string::npos);
    }
}

TEST_CASE("TransferFunction builds the function its fields describe") {
    auto node = readOne<TransferFunction>(
        "TransferFunction { tag 2 red [ 0 1, 1 0 ] green 0.5 0.5 blue [ 0 0, 0.5 1 ] "
        "alpha [ 0.25 0, 0.75 0.8 ] }");
    CHECK(node->tag() == 2);
    const TransferFunction1D tf = node->function();
    CHECK(!tf.dataRange()); // unset: the grid's natural range
    CHECK(tf.evaluate(TransferFunction1D::Red, 0.25) == doctest::Approx(0.75).epsilon(1e-12));
    CHECK(tf.evaluate(TransferFunction1D::Green, 0.9) == doctest::Approx(0.5).epsilon(1e-12));
    CHECK(tf.evaluate(TransferFunction1D::Blue, 0.9) == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(tf.evaluate(TransferFunction1D::Alpha, 0.5) == doctest::Approx(0.4).epsilon(1e-7));
    CHECK(tf.evaluate(TransferFunction1D::Alpha, 0.1) == 0.0);
}

TEST_CASE("TransferFunction sets dataRange only when the scene gives it") {
    auto node = readOne<TransferFunction>("TransferFunction { dataRange 100 300 }");
    const TransferFunction1D tf = node->function();
    REQUIRE(tf.dataRange());
    CHECK(tf.dataRange()->x == 100.0);
    CHECK(tf.dataRange()->y == 300.0);
    // The default identity channels.
    CHECK(tf.evaluate(TransferFunction1D::Alpha, 0.3) == doctest::Approx(0.3).epsilon(1e-7));
}

TEST_CASE("TransferFunction with an empty channel is an error naming the channel") {
    auto node = readOne<TransferFunction>("TransferFunction { alpha [ ] }");
    try {
        node->function();
        FAIL("no error for an empty channel");
    } catch (const Error& e) {
        CHECK(std::string(e.what()).find("alpha") != std::string::npos);
    }
}

TEST_CASE("BoxClip reads its fields") {
    auto clip = readOne<BoxClip>(
        "BoxClip { origin 0 0 0 extent 2 3 4 insideOpacity 0.5 outsideColorWeight 1 }");
    CHECK(clip->origin() == glm::vec3(0.0f));
    CHECK(clip->extent() == glm::vec3(2.0f, 3.0f, 4.0f));
    CHECK(clip->insideOpacity() == 0.5f);
    CHECK(clip->outsideOpacity() == 0.0f);
    CHECK(clip->outsideColorWeight() == 1.0f);
}

TEST_CASE("a raw VolumeData file resolves against the scene folder and takes the raw fields") {
    const auto dir = scratchDir() / "raw";
    std::filesystem::create_directories(dir);
    // 4 junk header bytes, then a 2x1x2 big-endian USHORT volume; labels: 2x1x2 UBYTE.
    writeBytes(dir / "data.raw", {9, 9, 9, 9, 0x01, 0x02, 0x00, 0x05, 0xff, 0xff, 0x10, 0x00});
    writeBytes(dir / "tags.raw", {0, 1, 2, 3});
    std::ofstream(dir / "scene.iv")
        << "#Inventor V2.1 ascii\nSeparator { VolumeData { fileName \"data.raw\" "
           "dimensions 2 1 2 dataType USHORT byteOrder BIG_ENDIAN headerSkip 4 "
           "spacing 0.5 1 2 tagFileName \"tags.raw\" } }\n";
    auto data = readOneFromFile<VolumeData>(dir / "scene.iv");
    ref_ptr<const VolumeGrid> grid = data->grid();
    CHECK(grid->type() == VoxelType::UShort);
    CHECK(grid->dimensions() == glm::ivec3(2, 1, 2));
    CHECK(grid->spacing() == glm::dvec3(0.5, 1.0, 2.0));
    CHECK(grid->value(0, 0, 0) == 0x0102);
    CHECK(grid->value(1, 0, 0) == 5);
    CHECK(grid->value(0, 0, 1) == 65535);
    CHECK(grid->value(1, 0, 1) == 0x1000);
    REQUIRE(data->tagGrid());
    CHECK(data->tagGrid()->type() == VoxelType::UByte);
    CHECK(data->tagGrid()->value(1, 0, 1) == 3);
}

TEST_CASE("a raw VolumeData file without dimensions is an error") {
    const auto dir = scratchDir() / "rawnodims";
    std::filesystem::create_directories(dir);
    writeBytes(dir / "data.raw", {1, 2, 3, 4});
    std::ofstream(dir / "scene.iv")
        << "#Inventor V2.1 ascii\nSeparator { VolumeData { fileName \"data.raw\" } }\n";
    auto data = readOneFromFile<VolumeData>(dir / "scene.iv");
    CHECK_THROWS_AS(data->grid(), Error);
}

TEST_CASE("a NRRD VolumeData keeps the header's spacing unless the scene sets one") {
    const auto dir = scratchDir() / "nrrd";
    std::filesystem::create_directories(dir);
    {
        std::ofstream out(dir / "small.nrrd", std::ios::binary);
        out << "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2 1\nspacings: 2 3 4\n"
               "encoding: raw\n\n";
        out.write("\x0a\x14\x1e\x28", 4);
    }
    std::ofstream(dir / "header.iv")
        << "#Inventor V2.1 ascii\nSeparator { VolumeData { fileName \"small.nrrd\" } }\n";
    std::ofstream(dir / "override.iv") << "#Inventor V2.1 ascii\nSeparator { VolumeData { "
                                          "fileName \"small.nrrd\" spacing 1 1 0.25 } }\n";
    auto fromHeader = readOneFromFile<VolumeData>(dir / "header.iv");
    CHECK(fromHeader->grid()->spacing() == glm::dvec3(2.0, 3.0, 4.0));
    CHECK(fromHeader->grid()->value(1, 1, 0) == 40);
    auto overridden = readOneFromFile<VolumeData>(dir / "override.iv");
    CHECK(overridden->grid()->spacing() == glm::dvec3(1.0, 1.0, 0.25));
}
