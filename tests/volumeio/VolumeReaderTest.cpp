// Volume file readers: every file is written by the test into a temporary folder, byte by byte,
// and every voxel read back is compared exactly with the value that was written.

#include "support/TempDir.h"
#include <doctest/doctest.h>

#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <unistd.h>
#include <zlib.h>

#include <volsg/core/Error.h>
#include <volsg/volumeio/VolumeReader.h>

using namespace volsg;
namespace fs = std::filesystem;

namespace {

/// This file's temporary folders.
class TempDir : public volsg::test::TempDir {
public:
    TempDir() : volsg::test::TempDir("volsg-readers") {}
};

void writeFile(const std::string& path, const std::string& bytes) {
    fs::create_directories(fs::path(path).parent_path());
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    REQUIRE(out.good());
}

const glm::ivec3 dims{5, 4, 3};
const std::size_t voxelCount = 5 * 4 * 3;

// Values that use every byte of the type, so a byte-order mistake cannot go unnoticed.
double patternValue(VoxelType type, std::size_t index) {
    switch (type) {
    case VoxelType::UByte:
        return double((index * 37 + 11) % 256);
    case VoxelType::UShort:
        return double((index * 4099 + 513) % 65536);
    case VoxelType::Short:
        return double(int((index * 4099 + 513) % 65536) - 32768);
    case VoxelType::Float:
        return double(float(index) * 0.75f - 20.125f);
    }
    return 0.0;
}

// The pattern as a file stores it.
std::string encodePattern(VoxelType type, bool bigEndian, std::size_t count = voxelCount) {
    std::string out;
    for (std::size_t i = 0; i < count; ++i) {
        const double v = patternValue(type, i);
        std::uint32_t bits = 0;
        std::size_t size = 1;
        switch (type) {
        case VoxelType::UByte:
            bits = std::uint32_t(v);
            break;
        case VoxelType::UShort:
            bits = std::uint32_t(v), size = 2;
            break;
        case VoxelType::Short:
            bits = std::uint16_t(std::int16_t(v)), size = 2;
            break;
        case VoxelType::Float:
            bits = std::bit_cast<std::uint32_t>(float(v)), size = 4;
            break;
        }
        for (std::size_t b = 0; b < size; ++b) {
            const std::size_t shift = 8 * (bigEndian ? size - 1 - b : b);
            out.push_back(char((bits >> shift) & 0xff));
        }
    }
    return out;
}

void checkPattern(const ref_ptr<VolumeGrid>& grid, VoxelType type, glm::ivec3 expectDims = dims) {
    REQUIRE(grid);
    REQUIRE(grid->type() == type);
    REQUIRE(grid->dimensions() == expectDims);
    std::size_t mismatches = 0, first = 0;
    for (std::size_t i = 0; i < grid->voxelCount(); ++i)
        if (grid->value(i) != patternValue(type, i) && mismatches++ == 0) first = i;
    INFO("first mismatch at voxel " << first << ": " << grid->value(first) << " instead of "
                                    << patternValue(type, first));
    CHECK(mismatches == 0);
}

std::string deflateWith(const std::string& data, int windowBits) {
    z_stream zs{};
    REQUIRE(deflateInit2(&zs, Z_BEST_COMPRESSION, Z_DEFLATED, windowBits, 8, Z_DEFAULT_STRATEGY) ==
            Z_OK);
    std::string out(deflateBound(&zs, uLong(data.size())) + 64, '\0');
    zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
    zs.avail_in = uInt(data.size());
    zs.next_out = reinterpret_cast<Bytef*>(out.data());
    zs.avail_out = uInt(out.size());
    const int rc = deflate(&zs, Z_FINISH);
    out.resize(zs.total_out);
    deflateEnd(&zs);
    REQUIRE(rc == Z_STREAM_END);
    return out;
}
std::string gzipBytes(const std::string& data) {
    return deflateWith(data, 15 + 16);
}
std::string zlibBytes(const std::string& data) {
    return deflateWith(data, 15);
}

// What a reader threw: its one-line message and the header line (0 when none was given).
struct Caught {
    std::string what = "no error was thrown";
    int line = -1;
};
Caught errorOf(const std::function<void()>& read) {
    Caught c;
    try {
        read();
    } catch (const Error& e) {
        c.what = e.what();
        c.line = e.line();
    } catch (const std::exception& e) {
        c.what = std::string("not a volsg::Error: ") + e.what();
    }
    return c;
}
bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}
#define CHECK_HAS(text, part)                                                                      \
    CHECK_MESSAGE(has(text, part), "'" << (text) << "' lacks '" << (part) << "'")

std::string joinLines(const std::vector<std::string>& lines) {
    std::string s;
    for (const auto& l : lines)
        s += l + "\n";
    return s;
}

RawVolumeLayout layoutOf(VoxelType type, bool bigEndian, std::uint64_t skip = 0) {
    return RawVolumeLayout{.dimensions = dims,
                           .type = type,
                           .bigEndian = bigEndian,
                           .headerSkip = skip,
                           .spacing = glm::dvec3(1.0)};
}

void checkRawRoundTrip(VoxelType type) {
    TempDir dir;
    for (const bool big : {false, true}) {
        INFO(voxelTypeName(type) << (big ? " big" : " little") << " endian");
        const std::string path = dir.file(big ? "big.raw" : "little.raw");
        writeFile(path, std::string(7, 'H') + encodePattern(type, big)); // odd header on purpose
        RawVolumeLayout layout = layoutOf(type, big, 7);
        layout.spacing = {0.5, 0.25, 3.0};
        const auto grid = readRawVolume(path, layout);
        checkPattern(grid, type);
        CHECK(grid->spacing() == glm::dvec3(0.5, 0.25, 3.0));
    }
}

} // namespace

TEST_CASE("raw UBYTE volume is read exactly after a header skip") {
    checkRawRoundTrip(VoxelType::UByte);
}

TEST_CASE("raw USHORT volume is read exactly in little and big endian") {
    checkRawRoundTrip(VoxelType::UShort);
}

TEST_CASE("raw SHORT volume keeps negative values in both byte orders") {
    checkRawRoundTrip(VoxelType::Short);
}

TEST_CASE("raw FLOAT volume is read bit-exactly in both byte orders") {
    checkRawRoundTrip(VoxelType::Float);
}

TEST_CASE("gzip raw volume decompresses transparently with the header skip in decompressed bytes") {
    TempDir dir;
    const std::string path = dir.file("vol.raw.gz");
    writeFile(path, gzipBytes("0123456789" + encodePattern(VoxelType::UShort, true)));
    checkPattern(readRawVolume(path, layoutOf(VoxelType::UShort, true, 10)), VoxelType::UShort);
    // A plain ".gz" name goes through readVolume's raw branch to the same reader.
    const std::string plain = dir.file("vol.gz");
    writeFile(plain, gzipBytes(encodePattern(VoxelType::Float, false)));
    const RawVolumeLayout layout = layoutOf(VoxelType::Float, false);
    checkPattern(readVolume(plain, &layout), VoxelType::Float);
}

TEST_CASE("concatenated gzip members read as one volume") {
    TempDir dir;
    const std::string data = encodePattern(VoxelType::Short, false);
    const std::string path = dir.file("members.raw.gz");
    writeFile(path, gzipBytes(data.substr(0, 50)) + gzipBytes(data.substr(50)));
    checkPattern(readRawVolume(path, layoutOf(VoxelType::Short, false)), VoxelType::Short);
}

TEST_CASE("label volumes read through the same functions are label grids") {
    TempDir dir;
    const std::string path = dir.file("tags.raw");
    writeFile(path, encodePattern(VoxelType::UShort, false));
    const auto tags = readRawVolume(path, layoutOf(VoxelType::UShort, false));
    checkPattern(tags, VoxelType::UShort);
    CHECK(tags->isLabelType());
}

TEST_CASE("raw volume without a layout asks for dimensions and dataType") {
    TempDir dir;
    const std::string path = dir.file("anything.dat");
    writeFile(path, encodePattern(VoxelType::UByte, false));
    const Caught e = errorOf([&] { readVolume(path); });
    CHECK_HAS(e.what, "anything.dat");
    CHECK_HAS(e.what, "raw volume needs dimensions and dataType");
}

TEST_CASE("missing volume files are errors naming the file") {
    TempDir dir;
    const RawVolumeLayout layout = layoutOf(VoxelType::UByte, false);
    for (const std::string name : {"absent.raw", "absent.nrrd", "absent.nhdr", "absent.mhd"}) {
        const Caught e = errorOf([&] { readVolume(dir.file(name), &layout); });
        CHECK_HAS(e.what, name);
        CHECK_HAS(e.what, "cannot open volume file");
    }
    const Caught folder = errorOf([&] { readRawVolume(dir.file(""), layout); });
    CHECK_HAS(folder.what, "not a regular file");
}

TEST_CASE("raw file whose size disagrees with the dimensions names both sizes") {
    TempDir dir;
    const std::string path = dir.file("short.raw");
    writeFile(path, std::string(1048000, '\x7f'));
    RawVolumeLayout layout = layoutOf(VoxelType::UByte, false);
    layout.dimensions = {128, 128, 64};
    const Caught e = errorOf([&] { readRawVolume(path, layout); });
    CHECK_HAS(e.what, "short.raw");
    CHECK_HAS(e.what, "expected 1048576 bytes of data, file has 1048000");

    const std::string longer = dir.file("long.raw");
    writeFile(longer, std::string(16, 'H') + encodePattern(VoxelType::UByte, false) + "x");
    const Caught extra =
        errorOf([&] { readRawVolume(longer, layoutOf(VoxelType::UByte, false, 16)); });
    CHECK_HAS(extra.what, "expected 60 bytes of data, file has 61 after offset 16");

    const Caught skipPastEnd =
        errorOf([&] { readRawVolume(longer, layoutOf(VoxelType::UByte, false, 1000)); });
    CHECK_HAS(skipPastEnd.what, "past the end of the file");
}

TEST_CASE("gzip raw data that decompresses to the wrong size is an error") {
    TempDir dir;
    const std::string path = dir.file("small.raw.gz");
    writeFile(path, gzipBytes(encodePattern(VoxelType::UShort, false, voxelCount - 1)));
    const Caught shortData =
        errorOf([&] { readRawVolume(path, layoutOf(VoxelType::UShort, false)); });
    CHECK_HAS(shortData.what, "small.raw.gz");
    CHECK_HAS(shortData.what, "decompressed gzip data has 118 bytes, expected 120");

    const std::string big = dir.file("big.raw.gz");
    writeFile(big, gzipBytes(encodePattern(VoxelType::UShort, false, voxelCount + 1)));
    const Caught longData =
        errorOf([&] { readRawVolume(big, layoutOf(VoxelType::UShort, false)); });
    CHECK_HAS(longData.what, "big.raw.gz");
    CHECK_HAS(longData.what, "larger than the expected 120 bytes");
}

TEST_CASE("truncated gzip stream is an error") {
    TempDir dir;
    const std::string full = gzipBytes(encodePattern(VoxelType::Float, false));
    for (const std::size_t keep :
         {std::size_t(2), std::size_t(12), full.size() / 2, full.size() - 4}) {
        INFO("kept " << keep << " of " << full.size() << " bytes");
        const std::string path = dir.file("cut.raw.gz");
        writeFile(path, full.substr(0, keep));
        const Caught e = errorOf([&] { readRawVolume(path, layoutOf(VoxelType::Float, false)); });
        CHECK_HAS(e.what, "cut.raw.gz");
        CHECK_HAS(e.what, "truncated gzip stream");
    }
}

TEST_CASE("corrupt gzip data is an error") {
    TempDir dir;
    std::string bytes = gzipBytes(encodePattern(VoxelType::Float, false));
    for (std::size_t i = 10; i < bytes.size() - 8; ++i)
        bytes[i] = char(0xff);
    const std::string path = dir.file("corrupt.raw.gz");
    writeFile(path, bytes);
    const Caught e = errorOf([&] { readRawVolume(path, layoutOf(VoxelType::Float, false)); });
    CHECK_HAS(e.what, "corrupt.raw.gz");
    CHECK_HAS(e.what, "corrupt gzip stream");
}

TEST_CASE("gzip bomb stops at the expected size and errors") {
    // 64 members of 16 MiB of zeros: about 1 GiB once inflated, from a file of some 1 MiB.
    TempDir dir;
    const std::string member = gzipBytes(std::string(std::size_t(16) << 20, '\0'));
    std::string bomb;
    for (int i = 0; i < 64; ++i)
        bomb += member;
    CHECK(bomb.size() < (std::size_t(2) << 20));
    const std::string path = dir.file("bomb.raw.gz");
    writeFile(path, bomb);
    const Caught e = errorOf([&] { readRawVolume(path, layoutOf(VoxelType::UByte, false)); });
    CHECK_HAS(e.what, "bomb.raw.gz");
    CHECK_HAS(e.what, "larger than the expected 60 bytes");
}

TEST_CASE("dimensions beyond the byte limit are refused before allocating") {
    TempDir dir;
    const std::string path = dir.file("tiny.raw");
    writeFile(path, "abc");
    RawVolumeLayout layout = layoutOf(VoxelType::Float, false);
    layout.dimensions = {2147483647, 2147483647, 2147483647};
    const Caught overflow = errorOf([&] { readRawVolume(path, layout); });
    CHECK_HAS(overflow.what, "tiny.raw");
    CHECK_HAS(overflow.what, "exceed the limit of 65536 voxels per axis"); // core/Limits.h

    layout.dimensions = {65536, 65536, 65536}; // every axis allowed, the product is not
    const Caught product = errorOf([&] { readRawVolume(path, layout); });
    CHECK_HAS(product.what, "exceeds the allocation limit");

    layout.dimensions = {20, 20, 20}; // 32000 bytes against a limit of 1000
    const Caught limit = errorOf([&] { readRawVolume(path, layout, 1000); });
    CHECK_HAS(limit.what, "exceeds the allocation limit of 1000 bytes");

    layout.dimensions = {4, 0, 4};
    const Caught zero = errorOf([&] { readRawVolume(path, layout); });
    CHECK_HAS(zero.what, "tiny.raw");
    CHECK_HAS(zero.what, "dimensions must be >= 1");
}

TEST_CASE("data too short for huge dimensions is refused before allocating") {
    TempDir dir;
    RawVolumeLayout layout = layoutOf(VoxelType::UByte, false);
    layout.dimensions = {1000, 1000, 1000};
    const std::string plain = dir.file("tiny.raw");
    writeFile(plain, encodePattern(VoxelType::UByte, false));
    const Caught p = errorOf([&] { readRawVolume(plain, layout); });
    CHECK_HAS(p.what, "tiny.raw");
    CHECK_HAS(p.what, "expected 1000000000 bytes of data, file has 60");

    // Deflate expands at most 1032:1, so 1 GB cannot come out of a few dozen bytes.
    const std::string packed = dir.file("tiny.raw.gz");
    writeFile(packed, gzipBytes(encodePattern(VoxelType::UByte, false)));
    const Caught g = errorOf([&] { readRawVolume(packed, layout); });
    CHECK_HAS(g.what, "tiny.raw.gz");
    CHECK_HAS(g.what, "truncated gzip stream");
    CHECK_HAS(g.what, "cannot hold the expected 1000000000 decompressed bytes");
}

TEST_CASE("absurd raw spacing is an error naming the file") {
    TempDir dir;
    const std::string path = dir.file("spaced.raw");
    writeFile(path, encodePattern(VoxelType::UByte, false));
    for (const double bad : {0.0, -1.0, std::nan("")}) {
        RawVolumeLayout layout = layoutOf(VoxelType::UByte, false);
        layout.spacing = {1.0, bad, 1.0};
        const Caught e = errorOf([&] { readRawVolume(path, layout); });
        CHECK_HAS(e.what, "spaced.raw");
        CHECK_HAS(e.what, "spacing must be finite and > 0");
    }
}

// ---------------------------------------------------------------- NRRD

TEST_CASE("NRRD attached raw volume with spacings") {
    TempDir dir;
    const std::string path = dir.file("attached.nrrd");
    writeFile(path,
              joinLines({"NRRD0004", "# Complete NRRD file format specification at:",
                         "type: unsigned short", "dimension: 3", "sizes: 5 4 3",
                         "spacings: 0.5 0.75 2", "kinds: domain domain domain", "endian: big",
                         "encoding: raw", "space origin: (1,2,3)", "key:=value: ignored", ""}) +
                  encodePattern(VoxelType::UShort, true));
    const auto grid = readVolume(path);
    checkPattern(grid, VoxelType::UShort);
    CHECK(grid->spacing() == glm::dvec3(0.5, 0.75, 2.0));
}

TEST_CASE("NRRD attached gzip volume") {
    TempDir dir;
    for (const std::string encoding : {"gzip", "gz"}) {
        INFO("encoding: " << encoding);
        const std::string path = dir.file("attached-" + encoding + ".nrrd");
        writeFile(path, joinLines({"NRRD0005", "type: float", "dimension: 3", "sizes: 5 4 3",
                                   "endian: little", "encoding: " + encoding, ""}) +
                            gzipBytes(encodePattern(VoxelType::Float, false)));
        const auto grid = readNrrd(path);
        checkPattern(grid, VoxelType::Float);
        CHECK(grid->spacing() == glm::dvec3(1.0));
    }
}

TEST_CASE("NRRD detached header reads its data file relative to its folder") {
    TempDir dir;
    // Two text lines and five bytes before the voxels: line skip, then byte skip.
    writeFile(dir.file("data/vol.raw"),
              "first line\nsecond line\nSKIPx" + encodePattern(VoxelType::Short, false));
    const std::string header = dir.file("vol.nhdr");
    writeFile(header, joinLines({"NRRD0004", "type: int16", "dimension: 3", "sizes: 5 4 3",
                                 "spacings: 1.5 1.5 4", "endian: little", "encoding: raw",
                                 "line skip: 2", "byte skip: 5", "data file: data/vol.raw"}));
    const auto grid = readVolume(header);
    checkPattern(grid, VoxelType::Short);
    CHECK(grid->spacing() == glm::dvec3(1.5, 1.5, 4.0));

    // The old spelling "datafile", and gzip data whose byte skip counts decompressed bytes.
    writeFile(dir.file("vol 2.raw.gz"),
              gzipBytes("12345678" + encodePattern(VoxelType::UShort, false)));
    const std::string header2 = dir.file("vol2.nhdr");
    writeFile(header2, joinLines({"NRRD0001", "type: ushort", "dimension: 3", "sizes: 5 4 3",
                                  "endian: little", "encoding: gzip", "byteskip: 8",
                                  "datafile: vol 2.raw.gz"}));
    checkPattern(readNrrd(header2), VoxelType::UShort);
}

TEST_CASE("NRRD detached header with a missing data file names the data file") {
    TempDir dir;
    const std::string header = dir.file("lost.nhdr");
    writeFile(header, joinLines({"NRRD0004", "type: uchar", "dimension: 3", "sizes: 5 4 3",
                                 "encoding: raw", "data file: nowhere.raw"}));
    const Caught e = errorOf([&] { readNrrd(header); });
    CHECK_HAS(e.what, "nowhere.raw");
    CHECK_HAS(e.what, "cannot open volume file");
}

TEST_CASE("NRRD space directions give the spacing as vector lengths") {
    TempDir dir;
    const std::string path = dir.file("oblique.nrrd");
    // Lengths 5, 2 and 3; the first and last are not axis-aligned.
    writeFile(path, joinLines({"NRRD0004", "type: uchar", "dimension: 3", "space: 3D-right-handed",
                               "sizes: 5 4 3", "space directions: (3,4,0) (0, 0, 2) (1,2,-2)",
                               "encoding: raw", ""}) +
                        encodePattern(VoxelType::UByte, false));
    const auto grid = readNrrd(path);
    checkPattern(grid, VoxelType::UByte);
    CHECK(grid->spacing().x == doctest::Approx(5.0).epsilon(1e-12));
    CHECK(grid->spacing().y == doctest::Approx(2.0).epsilon(1e-12));
    CHECK(grid->spacing().z == doctest::Approx(3.0).epsilon(1e-12));
}

TEST_CASE("NRRD byte skip -1 takes the raw data from the end of the file") {
    TempDir dir;
    writeFile(dir.file("tail.raw"),
              "some preamble of any length" + encodePattern(VoxelType::Float, true));
    const std::string header = dir.file("tail.nhdr");
    writeFile(header,
              joinLines({"NRRD0004", "type: float", "dimension: 3", "sizes: 5 4 3", "endian: big",
                         "encoding: raw", "byte skip: -1", "data file: tail.raw"}));
    checkPattern(readNrrd(header), VoxelType::Float);
}

TEST_CASE("NRRD accepts every spelling of the supported types") {
    TempDir dir;
    const std::vector<std::pair<std::string, VoxelType>> spellings = {
        {"uchar", VoxelType::UByte},
        {"unsigned char", VoxelType::UByte},
        {"uint8", VoxelType::UByte},
        {"uint8_t", VoxelType::UByte},
        {"ushort", VoxelType::UShort},
        {"unsigned short", VoxelType::UShort},
        {"unsigned short int", VoxelType::UShort},
        {"uint16", VoxelType::UShort},
        {"uint16_t", VoxelType::UShort},
        {"short", VoxelType::Short},
        {"short int", VoxelType::Short},
        {"signed short", VoxelType::Short},
        {"signed short int", VoxelType::Short},
        {"int16", VoxelType::Short},
        {"int16_t", VoxelType::Short},
        {"float", VoxelType::Float}};
    for (const auto& spelling : spellings) { // not a structured binding: INFO captures it
        const std::string& name = spelling.first;
        const VoxelType type = spelling.second;
        INFO("type: " << name);
        const std::string path = dir.file("typed.nrrd");
        writeFile(path, joinLines({"NRRD0004", "type: " + name, "dimension: 3", "sizes: 5 4 3",
                                   "endian: big", "encoding: raw", ""}) +
                            encodePattern(type, true));
        checkPattern(readNrrd(path), type);
    }
}

TEST_CASE("NRRD header errors give the line and the problem") {
    struct Case {
        std::vector<std::string> lines; // the header; a blank line and 60 data bytes follow
        std::string expected;
        int line; // 0: the error concerns the header as a whole
    };
    const std::vector<Case> cases = {
        {{"NRRX0004", "type: uchar"}, "not a NRRD file", 1},
        {{"NRRD0004", "type: uchar", "dimension: 4", "sizes: 1 5 4 3"}, "only 3-dimensional", 3},
        {{"NRRD0004", "type: double"}, "unknown or unsupported type 'double'", 2},
        {{"NRRD0004", "type: uchar", "encoding: ascii"}, "unsupported encoding 'ascii'", 3},
        {{"NRRD0004", "type: uchar", "encoding: bzip2"}, "unsupported encoding 'bzip2'", 3},
        {{"NRRD0004", "endian: middle"}, "unknown endian 'middle'", 2},
        {{"NRRD0004", "dimension: 3", "sizes: 5 4 x3"}, "malformed size", 3},
        {{"NRRD0004", "dimension: 3", "sizes: 5 4"}, "expected 3 sizes, got 2", 3},
        {{"NRRD0004", "dimension: 3", "sizes: 0 4 3"}, "size 0 is out of range", 3},
        {{"NRRD0004", "dimension: 3", "sizes: 1099511627776 4 3"},
         "size 1099511627776 is out of range",
         3},
        {{"NRRD0004", "dimension: 3", "sizes: 99999999999999999999999 4 3"}, "out of range", 3},
        {{"NRRD0004", "dimension: 3", "sizes: -5 4 3"}, "size -5 is out of range", 3},
        {{"NRRD0004", "spacings: -1 1 1"}, "spacing must be finite and > 0", 2},
        {{"NRRD0004", "spacings: 1 0 1"}, "spacing must be finite and > 0", 2},
        {{"NRRD0004", "spacings: 1 1 nan"}, "spacing must be finite and > 0", 2},
        {{"NRRD0004", "spacings: 1 1 1e999"}, "malformed spacing", 2},
        {{"NRRD0004", "spacings: 1 1 abc"}, "malformed spacing", 2},
        {{"NRRD0004", "space directions: (0,0,0) (0,1,0) (0,0,1)"}, "has zero length", 2},
        {{"NRRD0004", "space directions: none (0,1,0) (0,0,1)"}, "is 'none'", 2},
        {{"NRRD0004", "space directions: (1,0,0) (0,1,0)"}, "expected 3 space directions", 2},
        {{"NRRD0004", "space directions: (1,0,0) (0,1) (0,0,1)"}, "different numbers", 2},
        {{"NRRD0004", "space directions: (1,0,0 (0,1,0) (0,0,1)"}, "malformed space direction", 2},
        {{"NRRD0004", "byte skip: -2"}, "byte skip must be >= -1", 2},
        {{"NRRD0004", "line skip: -1"}, "line skip must be >= 0", 2},
        {{"NRRD0004", "type: uchar", "type: uchar"}, "duplicate field 'type'", 3},
        {{"NRRD0004", "type uchar"}, "malformed header line", 2},
        {{"NRRD0004", "data file: LIST"}, "several files", 2},
        {{"NRRD0004", "data file: slice%03d.raw 1 10 1"}, "several files", 2},
        {{"NRRD0004", "type: uchar", "dimension: 3", "encoding: raw"}, "no 'sizes' field", 0},
        {{"NRRD0004", "dimension: 3", "sizes: 5 4 3", "encoding: raw"}, "no 'type' field", 0},
        {{"NRRD0004", "type: uchar", "sizes: 5 4 3", "encoding: raw"}, "no 'dimension' field", 0},
        {{"NRRD0004", "type: uchar", "dimension: 3", "sizes: 5 4 3"}, "no 'encoding' field", 0},
        {{"NRRD0004", "type: short", "dimension: 3", "sizes: 5 4 3", "encoding: raw"},
         "no 'endian' field",
         0},
        {{"NRRD0004", "type: float", "dimension: 3", "sizes: 2000 2000 2000", "endian: little",
          "encoding: raw"},
         "exceeds the allocation limit",
         4},
        {{"NRRD0004", "type: uchar", "dimension: 3", "sizes: 5 4 3", "encoding: gzip",
          "byte skip: -1"},
         "byte skip -1 is only allowed with raw encoding",
         0},
    };
    TempDir dir;
    for (const Case& c : cases) {
        INFO("header: " << joinLines(c.lines));
        const std::string path = dir.file("broken.nrrd");
        writeFile(path, joinLines(c.lines) + "\n" + encodePattern(VoxelType::UByte, false));
        const Caught e = errorOf([&] { readNrrd(path); });
        CHECK_HAS(e.what, "broken.nrrd");
        CHECK_HAS(e.what, c.expected);
        CHECK(e.line == c.line);
    }
}

TEST_CASE("NRRD attached data whose size disagrees with the sizes is an error") {
    TempDir dir;
    const std::string path = dir.file("mismatch.nrrd");
    writeFile(path, joinLines({"NRRD0004", "type: ushort", "dimension: 3", "sizes: 5 4 3",
                               "endian: little", "encoding: raw", ""}) +
                        encodePattern(VoxelType::UShort, false, voxelCount - 1));
    const Caught e = errorOf([&] { readNrrd(path); });
    CHECK_HAS(e.what, "mismatch.nrrd");
    CHECK_HAS(e.what, "expected 120 bytes of data, file has 118");

    const std::string gz = dir.file("mismatch-gz.nrrd");
    writeFile(gz, joinLines({"NRRD0004", "type: ushort", "dimension: 3", "sizes: 5 4 3",
                             "endian: little", "encoding: gzip", ""}) +
                      gzipBytes(encodePattern(VoxelType::UShort, false, voxelCount - 2)));
    const Caught g = errorOf([&] { readNrrd(gz); });
    CHECK_HAS(g.what, "mismatch-gz.nrrd");
    CHECK_HAS(g.what, "decompressed gzip data has 116 bytes, expected 120");

    const std::string open = dir.file("noblank.nrrd");
    writeFile(open, joinLines({"NRRD0004", "type: uchar", "dimension: 3", "sizes: 5 4 3",
                               "encoding: raw"}));
    const Caught n = errorOf([&] { readNrrd(open); });
    CHECK_HAS(n.what, "no 'data file' field and no blank line");
}

TEST_CASE("NRRD header lines and header length are bounded") {
    TempDir dir;
    const std::string longLine = dir.file("longline.nrrd");
    writeFile(longLine, "NRRD0004\n# " + std::string(70000, 'x') + "\n\n");
    const Caught l = errorOf([&] { readNrrd(longLine); });
    CHECK_HAS(l.what, "longline.nrrd");
    CHECK_HAS(l.what, "header line longer than 65536 bytes");
    CHECK(l.line == 2);

    std::string manyLines = "NRRD0004\n";
    while (manyLines.size() < (std::size_t(3) << 19))
        manyLines += "# comment line\n";
    const std::string longHeader = dir.file("longheader.nrrd");
    writeFile(longHeader, manyLines);
    const Caught h = errorOf([&] { readNrrd(longHeader); });
    CHECK_HAS(h.what, "header longer than 1048576 bytes");

    const std::string binary = dir.file("binary.nrrd");
    writeFile(binary, std::string("NRRD0004\ntype: uchar\ndim\0ension: 3\n", 35));
    const Caught b = errorOf([&] { readNrrd(binary); });
    CHECK_HAS(b.what, "binary data in the header");
    CHECK(b.line == 3);
}

// ---------------------------------------------------------------- MetaImage

TEST_CASE("MetaImage mhd reads its separate raw file") {
    TempDir dir;
    writeFile(dir.file("raw/ct.raw"), encodePattern(VoxelType::Short, true));
    const std::string header = dir.file("ct.mhd");
    writeFile(header, joinLines({"ObjectType = Image", "NDims = 3", "BinaryData = True",
                                 "BinaryDataByteOrderMSB = True", "CompressedData = False",
                                 "TransformMatrix = 1 0 0 0 1 0 0 0 1", "Offset = -10 -20 5",
                                 "ElementSpacing = 0.5 0.5 1.25", "DimSize = 5 4 3",
                                 "ElementType = MET_SHORT", "ElementDataFile = raw/ct.raw"}));
    const auto grid = readVolume(header);
    checkPattern(grid, VoxelType::Short);
    CHECK(grid->spacing() == glm::dvec3(0.5, 0.5, 1.25));
}

TEST_CASE("MetaImage mha reads LOCAL data after the header") {
    TempDir dir;
    const std::string path = dir.file("local.mha");
    // ElementSize stands in for the spacing when ElementSpacing is absent; CRLF line ends.
    writeFile(path, std::string("NDims = 3\r\nDimSize = 5 4 3\r\nElementSize = 2 3 4\r\n"
                                "ElementByteOrderMSB = False\r\nElementType = MET_USHORT\r\n"
                                "ElementDataFile = LOCAL\r\n") +
                        encodePattern(VoxelType::UShort, false));
    const auto grid = readVolume(path);
    checkPattern(grid, VoxelType::UShort);
    CHECK(grid->spacing() == glm::dvec3(2.0, 3.0, 4.0));
}

TEST_CASE("MetaImage compressed data is a zlib stream") {
    TempDir dir;
    const std::string packed = zlibBytes(encodePattern(VoxelType::Float, true));
    for (const bool withSize : {true, false}) {
        INFO("CompressedDataSize given: " << withSize);
        std::vector<std::string> lines = {"ObjectType = Image",
                                          "NDims = 3",
                                          "DimSize = 5 4 3",
                                          "ElementType = MET_FLOAT",
                                          "BinaryDataByteOrderMSB = True",
                                          "CompressedData = True"};
        if (withSize) lines.push_back("CompressedDataSize = " + std::to_string(packed.size()));
        lines.push_back("ElementDataFile = LOCAL");
        const std::string path = dir.file("packed.mha");
        writeFile(path, joinLines(lines) + packed);
        checkPattern(readMetaImage(path), VoxelType::Float);
    }
    // A detached compressed file, found from the end with HeaderSize = -1.
    writeFile(dir.file("packed.zraw"), "junk before" + packed);
    const std::string header = dir.file("packed.mhd");
    writeFile(header, joinLines({"NDims = 3", "DimSize = 5 4 3", "ElementType = MET_FLOAT",
                                 "ElementByteOrderMSB = True", "CompressedData = True",
                                 "CompressedDataSize = " + std::to_string(packed.size()),
                                 "HeaderSize = -1", "ElementDataFile = packed.zraw"}));
    checkPattern(readMetaImage(header), VoxelType::Float);
}

TEST_CASE("MetaImage HeaderSize skips bytes and -1 takes the data from the end") {
    TempDir dir;
    writeFile(dir.file("skip.raw"), "0123456789ABCDEF" + encodePattern(VoxelType::UByte, false));
    const std::string skip = dir.file("skip.mhd");
    writeFile(skip, joinLines({"NDims = 3", "DimSize = 5 4 3", "ElementType = MET_UCHAR",
                               "HeaderSize = 16", "ElementDataFile = skip.raw"}));
    checkPattern(readMetaImage(skip), VoxelType::UByte);

    const std::string end = dir.file("end.mhd");
    writeFile(end, joinLines({"NDims = 3", "DimSize = 5 4 3", "ElementType = MET_UCHAR",
                              "HeaderSize = -1", "ElementDataFile = skip.raw"}));
    checkPattern(readMetaImage(end), VoxelType::UByte);
}

TEST_CASE("MetaImage header errors give the line and the problem") {
    struct Case {
        std::vector<std::string> lines; // the header; 60 bytes follow after ElementDataFile
        std::string expected;
        int line;
    };
    const std::string tail = "ElementDataFile = LOCAL";
    const std::vector<Case> cases = {
        {{"NDims = 2", tail}, "only 3-dimensional volumes are supported, header says NDims 2", 1},
        {{"NDims = 3", "ElementType = MET_DOUBLE", tail},
         "unsupported ElementType 'MET_DOUBLE'",
         2},
        {{"ObjectType = Mesh", tail}, "unsupported ObjectType", 1},
        {{"DimSize = 5 4", tail}, "expected 3 values in DimSize", 1},
        {{"DimSize = 5 -4 3", tail}, "DimSize -4 is out of range", 1},
        {{"DimSize = 5 4 3.5", tail}, "malformed DimSize", 1},
        {{"ElementSpacing = 1 0 1", tail}, "ElementSpacing must be finite and > 0", 1},
        {{"ElementSpacing = 1 NaN 1", tail}, "ElementSpacing must be finite and > 0", 1},
        {{"ElementSize = -1 1 1", tail}, "ElementSize must be finite and > 0", 1},
        {{"BinaryDataByteOrderMSB = Maybe", tail}, "malformed BinaryDataByteOrderMSB", 1},
        {{"BinaryData = False", tail}, "ASCII MetaImage data", 1},
        {{"ElementNumberOfChannels = 3", tail}, "single-channel", 1},
        {{"HeaderSize = -7", tail}, "HeaderSize must be >= -1", 1},
        {{"NDims = 3", "DimSize 5 4 3", tail}, "malformed header line", 2},
        {{"NDims = 3", "NDims = 3", tail}, "duplicate key 'ndims'", 2},
        {{"NDims = 3", "ElementDataFile = LIST"}, "several files", 2},
        {{"NDims = 3", "ElementDataFile = slice%03d.raw 1 3 1"}, "several files", 2},
        {{"NDims = 3", "ElementType = MET_UCHAR", tail}, "no DimSize", 0},
        {{"NDims = 3", "DimSize = 5 4 3", tail}, "no ElementType", 0},
        {{"NDims = 3", "DimSize = 5 4 3", "ElementType = MET_UCHAR", "CompressedData = True",
          "HeaderSize = -1", tail},
         "needs CompressedDataSize",
         0},
        {{"NDims = 3", "DimSize = 50000 50000 50000", "ElementType = MET_UCHAR", tail},
         "exceeds the allocation limit",
         2},
    };
    TempDir dir;
    for (const Case& c : cases) {
        INFO("header: " << joinLines(c.lines));
        const std::string path = dir.file("broken.mha");
        writeFile(path, joinLines(c.lines) + encodePattern(VoxelType::UByte, false));
        const Caught e = errorOf([&] { readMetaImage(path); });
        CHECK_HAS(e.what, "broken.mha");
        CHECK_HAS(e.what, c.expected);
        CHECK(e.line == c.line);
    }
}

TEST_CASE("MetaImage header without ElementDataFile is an error") {
    TempDir dir;
    const std::string path = dir.file("nodata.mhd");
    writeFile(path, joinLines({"NDims = 3", "DimSize = 5 4 3", "ElementType = MET_UCHAR"}));
    const Caught e = errorOf([&] { readMetaImage(path); });
    CHECK_HAS(e.what, "nodata.mhd");
    CHECK_HAS(e.what, "no ElementDataFile");
    CHECK(e.line == 3);
}

TEST_CASE("MetaImage data whose size disagrees with DimSize is an error") {
    TempDir dir;
    writeFile(dir.file("short.raw"), encodePattern(VoxelType::UShort, false, voxelCount - 1));
    const std::string header = dir.file("short.mhd");
    writeFile(header, joinLines({"NDims = 3", "DimSize = 5 4 3", "ElementType = MET_USHORT",
                                 "ElementDataFile = short.raw"}));
    const Caught e = errorOf([&] { readMetaImage(header); });
    CHECK_HAS(e.what, "short.raw");
    CHECK_HAS(e.what, "expected 120 bytes of data, file has 118");

    const std::string packed = dir.file("packed.mha");
    writeFile(packed, joinLines({"NDims = 3", "DimSize = 5 4 3", "ElementType = MET_USHORT",
                                 "CompressedData = True", "ElementDataFile = LOCAL"}) +
                          zlibBytes(encodePattern(VoxelType::UShort, false, voxelCount + 3)));
    const Caught z = errorOf([&] { readMetaImage(packed); });
    CHECK_HAS(z.what, "packed.mha");
    CHECK_HAS(z.what, "decompressed zlib data is larger than the expected 120 bytes");

    const std::string oversized = dir.file("oversized.mha");
    writeFile(oversized, joinLines({"NDims = 3", "DimSize = 5 4 3", "ElementType = MET_UCHAR",
                                    "CompressedData = True", "CompressedDataSize = 100000",
                                    "ElementDataFile = LOCAL"}) +
                             zlibBytes(encodePattern(VoxelType::UByte, false)));
    const Caught o = errorOf([&] { readMetaImage(oversized); });
    CHECK_HAS(o.what, "compressed data size 100000 exceeds");
}
