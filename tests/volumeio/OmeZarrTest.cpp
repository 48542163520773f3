// OME-Zarr pyramids: what writeOmeZarrPyramid writes, readOmeZarr reads back voxel for voxel;
// the coarse levels are the means the test computes itself; broken chunks and lying metadata
// are errors naming the file.

#include "ZarrTestSupport.h"

#include <nlohmann/json.hpp>

#include <volsg/volumeio/OmeZarrPyramid.h>
#include <volsg/volumeio/VolumeReader.h>
#include <volsg/volumeio/ZarrCodec.h>

using namespace volsg;
using namespace zarrtest;
using nlohmann::json;

namespace {

const VoxelType allTypes[] = {VoxelType::UByte, VoxelType::UShort, VoxelType::Short,
                              VoxelType::Float};
const char* const allCompressors[] = {"none", "zlib", "gzip", "zstd", "blosc"};

PyramidOptions optionsWith(const char* compressor, int chunk = 16) {
    PyramidOptions options;
    options.chunk = chunk;
    options.codec = ZarrCodec::named(compressor);
    return options;
}

// Level `from` reduced as the writer documents it, computed here voxel by voxel: the mean of
// the (up to) 2x2x2 voxels, an axis of length 1 kept, integers rounded to nearest.
ref_ptr<VolumeGrid> meansOf(const VolumeGrid& from) {
    const glm::ivec3 d = from.dimensions();
    const glm::ivec3 f(d.x > 1 ? 2 : 1, d.y > 1 ? 2 : 1, d.z > 1 ? 2 : 1);
    const glm::ivec3 to = (d + f - 1) / f;
    auto out = VolumeGrid::create(to, from.type());
    for (int z = 0; z < to.z; ++z)
        for (int y = 0; y < to.y; ++y)
            for (int x = 0; x < to.x; ++x) {
                double sum = 0.0;
                int n = 0;
                for (int k = z * f.z; k < std::min(z * f.z + f.z, d.z); ++k)
                    for (int j = y * f.y; j < std::min(y * f.y + f.y, d.y); ++j)
                        for (int i = x * f.x; i < std::min(x * f.x + f.x, d.x); ++i, ++n)
                            sum += from.value(i, j, k);
                out->setValue(x, y, z, sum / n);
            }
    return out;
}

void checkEqual(const VolumeGrid& got, const VolumeGrid& want) {
    std::string first;
    const std::size_t differences = countDifferences(got, want, first);
    INFO(first);
    CHECK(differences == 0);
}

void editJson(const std::string& path, const std::function<void(json&)>& edit) {
    json j = json::parse(readFile(path));
    edit(j);
    writeFile(path, j.dump());
}

} // namespace

TEST_CASE("pyramid level 0 reads back voxel for voxel for every dtype and compressor") {
    for (const glm::ivec3 dims : {glm::ivec3(37, 23, 19), glm::ivec3(70, 65, 3)})
        for (const VoxelType type : allTypes)
            for (const char* compressor : allCompressors) {
                CAPTURE(voxelTypeName(type));
                CAPTURE(compressor);
                CAPTURE(dims.x);
                TempDir dir;
                const auto grid = patternGrid(dims, type, {0.5, 0.75, 2.0});
                const std::string path = dir.file("p.zarr");
                // Chunks of 32: edge chunks on every axis, few files.
                writeOmeZarrPyramid(*grid, path, optionsWith(compressor, 32));
                const auto back = readVolume(path); // a .zarr folder: OME-Zarr, level 0
                checkEqual(*back, *grid);
                CHECK(back->spacing() == glm::dvec3(0.5, 0.75, 2.0));
            }
}

TEST_CASE("coarser levels are the 2x2x2 means of the finer level, with doubled spacing") {
    for (const VoxelType type : allTypes) {
        CAPTURE(voxelTypeName(type));
        TempDir dir;
        const auto grid = patternGrid({37, 23, 19}, type, {1.0, 2.0, 3.0});
        const std::string path = dir.file("m.zarr");
        const auto levels = writeOmeZarrPyramid(*grid, path, optionsWith("zstd", 8));
        REQUIRE(levels.size() == 4); // 37 -> 19 -> 10 -> 5 (<= 8)
        ref_ptr<VolumeGrid> finer = grid;
        for (int level = 1; level < int(levels.size()); ++level) {
            CAPTURE(level);
            const auto coarse = readOmeZarr(path, level);
            checkEqual(*coarse, *meansOf(*finer));
            const double twice = std::ldexp(1.0, level);
            CHECK(coarse->spacing() == glm::dvec3(1.0, 2.0, 3.0) * twice);
            finer = coarse;
        }
    }
}

TEST_CASE("label pyramids keep the most frequent label, ties to the smallest") {
    TempDir dir;
    auto labels = VolumeGrid::create({4, 2, 2}, VoxelType::UByte);
    // Block x 0..1: seven 5s and one 9; block x 2..3: four 3s and four 8s (a tie).
    const int values[16] = {5, 5, 3, 8, 5, 9, 8, 3, 5, 5, 3, 8, 5, 5, 8, 3};
    for (int i = 0; i < 16; ++i)
        labels->setValue(std::size_t(i), values[i]);
    PyramidOptions options = optionsWith("zstd", 2);
    options.labels = true;
    writeOmeZarrPyramid(*labels, dir.file("l.zarr"), options);
    const auto coarse = readOmeZarr(dir.file("l.zarr"), 1);
    REQUIRE(coarse->dimensions() == glm::ivec3(2, 1, 1));
    CHECK(coarse->value(0, 0, 0) == 5.0);
    CHECK(coarse->value(1, 0, 0) == 3.0);
}

TEST_CASE("levels halve each axis longer than 1 until the longest fits a chunk") {
    const auto levels = pyramidLevelDimensions({70, 65, 3}, 16);
    REQUIRE(levels.size() == 4);
    CHECK(levels[1] == glm::ivec3(35, 33, 2));
    CHECK(levels[2] == glm::ivec3(18, 17, 1));
    CHECK(levels[3] == glm::ivec3(9, 9, 1));
    CHECK(pyramidLevelDimensions({37, 23, 19}, 64).size() == 1);
}

TEST_CASE("the metadata is OME-NGFF 0.4 multiscales over Zarr v2 arrays") {
    TempDir dir;
    const auto grid = patternGrid({37, 23, 19}, VoxelType::UShort, {0.5, 0.5, 1.0});
    PyramidOptions options = optionsWith("blosc");
    options.unit = "millimeter";
    writeOmeZarrPyramid(*grid, dir.file("n.zarr"), options);
    CHECK(json::parse(readFile(dir.file("n.zarr/.zgroup")))["zarr_format"] == 2);
    const json image = json::parse(readFile(dir.file("n.zarr/.zattrs")))["multiscales"][0];
    CHECK(image["version"] == "0.4");
    CHECK(image["axes"][0] == json({{"name", "z"}, {"type", "space"}, {"unit", "millimeter"}}));
    CHECK(image["axes"][2]["name"] == "x");
    REQUIRE(image["datasets"].size() == 3); // 37 -> 19 -> 10 (<= 16)
    const json level1 = image["datasets"][1];
    CHECK(level1["path"] == "1");
    CHECK(level1["coordinateTransformations"][0]["scale"] == json({2.0, 1.0, 1.0}));
    // Coarse voxel 0 is centred between fine voxels 0 and 1.
    CHECK(level1["coordinateTransformations"][1]["translation"] == json({0.5, 0.25, 0.25}));
    const json array = json::parse(readFile(dir.file("n.zarr/1/.zarray")));
    CHECK(array["shape"] == json({10, 12, 19}));
    CHECK(array["chunks"] == json({10, 12, 16}));
    CHECK(array["dtype"] == "<u2");
    CHECK(array["compressor"]["id"] == "blosc");
    CHECK(array["order"] == "C");
    CHECK(array["dimension_separator"] == "/");
}

TEST_CASE("a missing chunk file reads as the array's fill_value") {
    TempDir dir;
    const auto grid = patternGrid({37, 23, 19}, VoxelType::Short);
    const std::string path = dir.file("f.zarr");
    writeOmeZarrPyramid(*grid, path, optionsWith("zstd"));
    editJson(path + "/0/.zarray", [](json& j) { j["fill_value"] = -7; });
    fs::remove(path + "/0/1/0/2"); // z 16..18, y 0..15, x 32..36
    const auto back = readOmeZarr(path);
    std::size_t wrong = 0;
    for (int z = 0; z < 19; ++z)
        for (int y = 0; y < 23; ++y)
            for (int x = 0; x < 37; ++x) {
                const bool missing = z >= 16 && y < 16 && x >= 32;
                wrong += back->value(x, y, z) != (missing ? -7.0 : grid->value(x, y, z));
            }
    CHECK(wrong == 0);
}

TEST_CASE("a hand-written 5D big-endian array with '.' keys reads as its t=0, c=0 volume") {
    TempDir dir;
    const std::string root = dir.file("h");
    // shape t=2, c=1, z=3, y=4, x=5; chunks 1,1,2,4,3: chunk (0,0,kz,ky,kx) holds the volume.
    const glm::ivec3 dims(5, 4, 3), chunk(3, 4, 2);
    writeFile(root + "/.zattrs",
              json({{"multiscales",
                     {{{"version", "0.4"},
                       {"axes",
                        {{{"name", "t"}, {"type", "time"}},
                         {{"name", "c"}, {"type", "channel"}},
                         {{"name", "z"}, {"type", "space"}},
                         {{"name", "y"}, {"type", "space"}},
                         {{"name", "x"}, {"type", "space"}}}},
                       {"datasets",
                        {{{"path", "s0"},
                          {"coordinateTransformations",
                           {{{"type", "scale"}, {"scale", {1.0, 1.0, 4.0, 2.0, 0.5}}}}}}}}}}}})
                  .dump());
    writeFile(root + "/s0/.zarray", json({{"zarr_format", 2},
                                          {"shape", {2, 1, 3, 4, 5}},
                                          {"chunks", {1, 1, 2, 4, 3}},
                                          {"dtype", ">i2"},
                                          {"compressor", {{"id", "zlib"}, {"level", 1}}},
                                          {"fill_value", 0},
                                          {"order", "C"},
                                          {"filters", nullptr}})
                                        .dump());
    const auto grid = patternGrid(dims, VoxelType::Short);
    for (int t = 0; t < 2; ++t)
        for (int kz = 0; kz < 2; ++kz)
            for (int kx = 0; kx < 2; ++kx) {
                std::string bytes;
                for (int z = 0; z < chunk.z; ++z)
                    for (int y = 0; y < chunk.y; ++y)
                        for (int x = 0; x < chunk.x; ++x) {
                            const int gx = kx * chunk.x + x, gz = kz * chunk.z + z;
                            // t = 1 holds other values: reading it would show.
                            const int v =
                                gx < dims.x && gz < dims.z ? int(grid->value(gx, y, gz)) + t : 0;
                            bytes.push_back(char((v >> 8) & 0xff));
                            bytes.push_back(char(v & 0xff));
                        }
                const auto stored =
                    encodeZarrChunk(ZarrCodec::named("zlib"), std::as_bytes(std::span(bytes)), 2);
                writeFile(root + "/s0/" + std::to_string(t) + ".0." + std::to_string(kz) + ".0." +
                              std::to_string(kx),
                          std::string(reinterpret_cast<const char*>(stored.data()), stored.size()));
            }
    CHECK(isZarrFolder(root));
    const auto back = readVolume(root);
    checkEqual(*back, *grid);
    CHECK(back->spacing() == glm::dvec3(0.5, 2.0, 4.0));
}

TEST_CASE("one level's array folder opens with the spacing its image gives it") {
    TempDir dir;
    const auto grid = patternGrid({37, 23, 19}, VoxelType::UByte, {1.0, 1.0, 2.0});
    writeOmeZarrPyramid(*grid, dir.file("a.zarr"), optionsWith("zlib"));
    const auto level1 = readVolume(dir.file("a.zarr/1"));
    checkEqual(*level1, *readOmeZarr(dir.file("a.zarr"), 1));
    CHECK(level1->spacing() == glm::dvec3(2.0, 2.0, 4.0));
    const std::string beyond = errorOf([&] { readOmeZarr(dir.file("a.zarr"), 3); });
    CHECK_HAS(beyond, "level 3 asked for, the pyramid has levels 0..2");
    CHECK_HAS(beyond, ".zattrs");
}

TEST_CASE("broken chunks are errors naming the chunk file") {
    TempDir dir;
    const auto grid = patternGrid({37, 23, 19}, VoxelType::UShort);
    for (const char* compressor : {"none", "zlib", "gzip", "zstd", "blosc"}) {
        CAPTURE(compressor);
        const std::string path = dir.file(std::string(compressor) + ".zarr");
        writeOmeZarrPyramid(*grid, path, optionsWith(compressor));
        const std::string chunk = path + "/0/0/1/1";
        const std::string good = readFile(chunk);

        writeFile(chunk, good.substr(0, good.size() / 2));
        std::string message = errorOf([&] { readOmeZarr(path); });
        CHECK_HAS(message, chunk);
        if (std::string(compressor) != "none") CHECK_HAS(message, "truncated");

        // A valid stream of the wrong size: half a chunk.
        const std::vector<std::byte> half(16 * 16 * 16, std::byte{1});
        const auto stored = encodeZarrChunk(ZarrCodec::named(compressor), half, 2);
        writeFile(chunk, std::string(reinterpret_cast<const char*>(stored.data()), stored.size()));
        message = errorOf([&] { readOmeZarr(path); });
        CHECK_HAS(message, chunk);
        CHECK_HAS(message, "expected 8192");

        if (std::string(compressor) != "none") {
            writeFile(chunk, std::string(200, 'x'));
            message = errorOf([&] { readOmeZarr(path); });
            CHECK_HAS(message, chunk);
        }
        writeFile(chunk, good);
        CHECK(readOmeZarr(path)->value(20, 0, 0) == grid->value(20, 0, 0));
    }
}

TEST_CASE("lying or unsupported metadata is an error naming the metadata file") {
    TempDir dir;
    const auto grid = patternGrid({37, 23, 19}, VoxelType::UShort);
    const std::string path = dir.file("e.zarr");
    writeOmeZarrPyramid(*grid, path, optionsWith("zstd"));
    const std::string zarray = path + "/0/.zarray", zattrs = path + "/.zattrs";
    const std::string goodArray = readFile(zarray), goodAttrs = readFile(zattrs);
    const auto withArray = [&](const std::function<void(json&)>& edit) {
        writeFile(zarray, goodArray);
        editJson(zarray, edit);
        return errorOf([&] { readOmeZarr(path); });
    };

    std::string m = withArray([](json& j) { j["shape"] = {16, 23, 37}; });
    CHECK_HAS(m, zarray);
    CHECK_HAS(m, "lies outside shape");
    // A dtype of another size: the chunks do not decompress to its chunk size.
    m = withArray([](json& j) { j["dtype"] = "|u1"; });
    CHECK_HAS(m, path + "/0/0/0/0");
    CHECK_HAS(m, "expected 4096");
    m = withArray([](json& j) { j["dtype"] = "<f8"; });
    CHECK_HAS(m, zarray);
    CHECK_HAS(m, "unsupported dtype");
    m = withArray([](json& j) { j["compressor"] = {{"id", "lzma"}}; });
    CHECK_HAS(m, zarray);
    CHECK_HAS(m, "unknown compressor \"lzma\"");
    m = withArray([](json& j) { j["chunks"] = {65536, 65536, 65536}; });
    CHECK_HAS(m, zarray);
    CHECK_HAS(m, "larger than the limit");
    m = withArray([](json& j) { j["shape"] = {0, 23, 37}; });
    CHECK_HAS(m, "whole numbers in 1..");
    m = withArray([](json& j) { j["fill_value"] = 70000; });
    CHECK_HAS(m, "does not fit the dtype");
    m = withArray([](json& j) { j["order"] = "F"; });
    CHECK_HAS(m, "is not \"C\"");
    writeFile(zarray, goodArray);

    writeFile(zattrs, goodAttrs.substr(0, goodAttrs.size() / 2));
    m = errorOf([&] { readOmeZarr(path); });
    CHECK_HAS(m, zattrs);
    CHECK_HAS(m, "malformed JSON");
    writeFile(zarray, goodArray.substr(0, 20));
    writeFile(zattrs, goodAttrs);
    m = errorOf([&] { readOmeZarr(path); });
    CHECK_HAS(m, zarray);
    CHECK_HAS(m, "malformed JSON");
    writeFile(zarray, goodArray);
    editJson(zattrs, [](json& j) {
        j["multiscales"][0]["datasets"][0]["coordinateTransformations"][0]["scale"] = {0, 1, 1};
    });
    m = errorOf([&] { readOmeZarr(path); });
    CHECK_HAS(m, zattrs);
    CHECK_HAS(m, "finite and > 0");
    editJson(zattrs, [](json& j) {
        j["multiscales"][0]["datasets"][0]["coordinateTransformations"][0]["scale"] = {1, 1};
    });
    CHECK_HAS(errorOf([&] { readOmeZarr(path); }), "one entry per axis");
    // Found by fuzz-omezarr: a number beyond double's range is nlohmann's out_of_range, not a
    // parse error.
    writeFile(zattrs, "{\"multiscales\": [{\"version\": 6e358}]}");
    m = errorOf([&] { readOmeZarr(path); });
    CHECK_HAS(m, zattrs);
    CHECK_HAS(m, "number overflow");
    writeFile(zattrs, goodAttrs);
    writeFile(zarray, "{\"zarr_format\": 2, \"shape\": [1e400, 1, 1]}");
    m = errorOf([&] { readOmeZarr(path); });
    CHECK_HAS(m, zarray);
    CHECK_HAS(m, "number overflow");
    writeFile(zarray, goodArray);
    writeFile(zattrs, std::string(200000, '[') + std::string(200000, ']'));
    m = errorOf([&] { readOmeZarr(path); });
    CHECK_HAS(m, zattrs);
    CHECK_HAS(m, "nested deeper than 32");
    writeFile(zattrs, goodAttrs);
    editJson(zattrs, [](json& j) { j["multiscales"][0]["datasets"][0]["path"] = "../../etc"; });
    CHECK_HAS(errorOf([&] { readOmeZarr(path); }), zattrs);
}

TEST_CASE("the pyramid writer refuses to write over an existing folder") {
    TempDir dir;
    const auto grid = patternGrid({5, 4, 3}, VoxelType::UByte);
    writeOmeZarrPyramid(*grid, dir.file("x.zarr"));
    const std::string m = errorOf([&] { writeOmeZarrPyramid(*grid, dir.file("x.zarr")); });
    CHECK_HAS(m, "x.zarr");
    CHECK_HAS(m, "already exists");
}

TEST_CASE("older NGFF metadata: axes as names and no transformations give spacing 1") {
    TempDir dir;
    const auto grid = patternGrid({37, 23, 19}, VoxelType::UByte, {2.0, 2.0, 2.0});
    const std::string path = dir.file("old.zarr");
    writeOmeZarrPyramid(*grid, path, optionsWith("zlib"));
    editJson(path + "/.zattrs", [](json& j) {
        j["multiscales"][0]["version"] = "0.3";
        j["multiscales"][0]["axes"] = {"z", "y", "x"};
        for (json& d : j["multiscales"][0]["datasets"])
            d.erase("coordinateTransformations");
    });
    const auto back = readOmeZarr(path);
    checkEqual(*back, *grid);
    CHECK(back->spacing() == glm::dvec3(1.0));
}

TEST_CASE("a chunk that is a symbolic link out of its array's folder is an error") {
    TempDir dir;
    const auto grid = patternGrid({37, 23, 19}, VoxelType::UByte);
    const std::string path = dir.file("s.zarr");
    writeOmeZarrPyramid(*grid, path, optionsWith("none"));
    writeFile(dir.file("outside"), std::string(16 * 16 * 16, 'x'));
    fs::remove(path + "/0/0/0/0");
    fs::create_symlink(dir.file("outside"), path + "/0/0/0/0");
    const std::string m = errorOf([&] { readOmeZarr(path); });
    CHECK_HAS(m, path + "/0/.zarray");
    CHECK_HAS(m, "0/0/0");
}

TEST_CASE("a pyramid keeps the patient placement of its source, each level's at its voxel 0") {
    TempDir dir;
    auto grid = patternGrid({37, 23, 19}, VoxelType::Short, {0.5, 0.75, 2.0});
    VolumeGeometry placed;
    placed.known = true;
    placed.directions = glm::dmat3(-1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, -1.0, 0.0); // columns
    placed.origin = {10.0, -20.0, 30.5};
    grid->setGeometry(placed);
    const std::string path = dir.file("g.zarr");
    writeOmeZarrPyramid(*grid, path, optionsWith("zstd"));
    const VolumeGeometry level0 = readOmeZarr(path)->geometry();
    CHECK(level0.known);
    CHECK(level0.directions == placed.directions);
    CHECK(level0.origin == placed.origin);
    // Level 1's voxel 0 is centred between level 0's voxels 0 and 1 on every axis.
    const VolumeGeometry level1 = readOmeZarr(path, 1)->geometry();
    const glm::dvec3 shift = placed.directions * glm::dvec3(0.25, 0.375, 1.0);
    CHECK(glm::length(level1.origin - (placed.origin + shift)) < 1e-12);
    // Without the source's placement none is made up.
    writeOmeZarrPyramid(*patternGrid({5, 4, 3}, VoxelType::UByte), dir.file("n.zarr"));
    CHECK_FALSE(readOmeZarr(dir.file("n.zarr"))->geometry().known);

    editJson(path + "/.zattrs", [](json& j) {
        j["multiscales"][0]["metadata"]["volsg"]["lpsOrigin"] = {1, 2};
    });
    const std::string m = errorOf([&] { readOmeZarr(path); });
    CHECK_HAS(m, path + "/.zattrs");
    CHECK_HAS(m, "lpsOrigin");
}
