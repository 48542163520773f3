// volsg-pyramid against python-zarr (Debian's python3-zarr): what the tool writes, zarr reads
// with the same values, and what zarr writes (blosc, zstd, zlib, gzip; both key separators),
// volsg reads with the same values. The python halves are skipped, with a message, where
// /usr/bin/python3 cannot import zarr.

#include "ZarrTestSupport.h"

#include <cstdlib>
#include <cstring>

#include <volsg/io/SceneReader.h>
#include <volsg/io/SceneWriter.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/volumeio/OmeZarrPyramid.h>
#include <volsg/volumeio/VolumeReader.h>
#include <volsg/volumescene/SceneForFile.h>

using namespace volsg;
using namespace zarrtest;

namespace {

const std::string tool = std::string(VOLSG_BINARY_DIR) + "/viewer/volsg-pyramid";

bool pythonHasZarr() {
    static const bool found =
        std::system("/usr/bin/python3 -c 'import zarr, numcodecs' > /dev/null 2>&1") == 0;
    return found;
}

int runPython(const TempDir& dir, const std::string& script) {
    writeFile(dir.file("check.py"), script);
    return std::system(
        ("/usr/bin/python3 " + dir.file("check.py") + " > " + dir.file("py.log") + " 2>&1")
            .c_str());
}

// The grid's voxels equal the little-endian bytes in `path`.
void checkBytes(const VolumeGrid& grid, const std::string& path) {
    const std::string want = readFile(path);
    const std::span<const std::byte> got = grid.bytes();
    REQUIRE(got.size() == want.size());
    CHECK(std::memcmp(got.data(), want.data(), want.size()) == 0);
}

} // namespace

TEST_CASE("volsg-pyramid writes a pyramid that volsg and python-zarr read with the same values") {
    TempDir dir;
    const auto grid = patternGrid({37, 23, 19}, VoxelType::UShort);
    const std::span<const std::byte> bytes = std::as_const(*grid).bytes();
    writeFile(dir.file("in.raw"),
              std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
    for (const std::string compressor : {"zstd", "blosc"}) {
        const std::string out = dir.file(compressor + ".zarr");
        const std::string command = tool + " " + dir.file("in.raw") +
                                    " --dims 37 23 19 --type ushort --spacing 0.5 0.5 1 -o " + out +
                                    " --chunk 16 --compressor " + compressor + " > " +
                                    dir.file("tool.log") + " 2>&1";
        REQUIRE_MESSAGE(std::system(command.c_str()) == 0, readFile(dir.file("tool.log")));
        CHECK_HAS(readFile(dir.file("tool.log")), "/1: 19x12x10 USHORT");
        std::string first;
        CHECK(countDifferences(*readVolume(out), *grid, first) == 0);
    }
    if (!pythonHasZarr()) {
        MESSAGE("skipped the python-zarr half: /usr/bin/python3 cannot import zarr");
        return;
    }
    // Each level as zarr reads it, in little-endian C order.
    const int rc = runPython(dir, "import zarr\n"
                                  "for name in ['zstd', 'blosc']:\n"
                                  "    g = zarr.open_group('" +
                                      dir.file("") +
                                      "' + name + '.zarr', mode='r')\n"
                                      "    for d in g.attrs['multiscales'][0]['datasets']:\n"
                                      "        a = g[d['path']][...]\n"
                                      "        a.astype(a.dtype.newbyteorder('<')).tofile('" +
                                      dir.file("") + "' + name + d['path'] + '.bin')\n");
    REQUIRE_MESSAGE(rc == 0, readFile(dir.file("py.log")));
    for (const std::string compressor : {"zstd", "blosc"})
        for (int level = 0; level < 3; ++level) {
            CAPTURE(compressor);
            CAPTURE(level);
            checkBytes(*readOmeZarr(dir.file(compressor + ".zarr"), level),
                       dir.file(compressor + std::to_string(level) + ".bin"));
        }
}

TEST_CASE("volsg reads the OME-Zarr images python-zarr writes") {
    if (!pythonHasZarr()) {
        MESSAGE("skipped: /usr/bin/python3 cannot import zarr");
        return;
    }
    TempDir dir;
    const int rc = runPython(
        dir, "import numpy as np, zarr\n"
             "from numcodecs import Blosc, Zstd, Zlib, GZip\n"
             "v = (np.arange(19 * 23 * 37).reshape(19, 23, 37) * 7919) % 65536\n"
             "cases = [('a', v.astype('>u2'), Blosc(cname='zstd', clevel=3, "
             "shuffle=Blosc.SHUFFLE), '/'),\n"
             "         ('b', (v * 0.25 - 100).astype('<f4'), Zstd(level=1), '.'),\n"
             "         ('c', (v % 256).astype('|u1'), Blosc(cname='lz4', "
             "shuffle=Blosc.BITSHUFFLE), '/'),\n"
             "         ('d', (v - 32768).astype('<i2'), GZip(level=6), '.'),\n"
             "         ('e', v.astype('<u2'), Zlib(level=1), '/'),\n"
             "         ('f', (v - 32768).astype('>i2'), Blosc(cname='zlib', "
             "shuffle=Blosc.NOSHUFFLE), '.')]\n"
             "for name, data, codec, sep in cases:\n"
             "    g = zarr.open_group('" +
                 dir.file("") +
                 "' + name + '.zarr', mode='w')\n"
                 "    g.create_dataset('0', data=data, chunks=(16, 16, 16), compressor=codec,\n"
                 "                     dimension_separator=sep)\n"
                 "    g.attrs['multiscales'] = [{'version': '0.4', 'axes': [\n"
                 "        {'name': 'z', 'type': 'space'}, {'name': 'y', 'type': 'space'},\n"
                 "        {'name': 'x', 'type': 'space'}], 'datasets': [{'path': '0',\n"
                 "        'coordinateTransformations': [{'type': 'scale', 'scale': [2.0, 1.0, "
                 "0.5]}]}]}]\n"
                 "    data.astype(data.dtype.newbyteorder('<')).tofile('" +
                 dir.file("") + "' + name + '.bin')\n");
    REQUIRE_MESSAGE(rc == 0, readFile(dir.file("py.log")));
    const std::pair<const char*, VoxelType> cases[] = {
        {"a", VoxelType::UShort}, {"b", VoxelType::Float},  {"c", VoxelType::UByte},
        {"d", VoxelType::Short},  {"e", VoxelType::UShort}, {"f", VoxelType::Short}};
    for (const auto& entry : cases) {
        // Not a structured binding: clang 14 cannot capture one in CAPTURE's lambda.
        const char* const name = entry.first;
        const VoxelType type = entry.second;
        CAPTURE(name);
        const auto grid = readVolume(dir.file(std::string(name) + ".zarr"));
        CHECK(grid->type() == type);
        CHECK(grid->dimensions() == glm::ivec3(37, 23, 19));
        CHECK(grid->spacing() == glm::dvec3(0.5, 1.0, 2.0));
        checkBytes(*grid, dir.file(std::string(name) + ".bin"));
    }
}

TEST_CASE("VolumeData opens an OME-Zarr image by fileName, a level by its folder") {
    TempDir dir;
    const auto grid = patternGrid({37, 23, 19}, VoxelType::Short, {0.5, 0.5, 1.0});
    PyramidOptions options;
    options.chunk = 16;
    writeOmeZarrPyramid(*grid, dir.file("head.zarr"), options);
    const auto open = [&](const std::string& name) {
        writeFile(dir.file("scene.iv"),
                  "#Inventor V2.1 ascii\nVolumeData { fileName \"" + name + "\" }\n");
        const ref_ptr<Node> root = readScene(dir.file("scene.iv"));
        return static_cast<VolumeData&>(*root).grid();
    };
    std::string first;
    CHECK(countDifferences(*open("head.zarr"), *grid, first) == 0);
    const auto level1 = open("head.zarr/1");
    CHECK(level1->dimensions() == glm::ivec3(19, 12, 10));
    CHECK(level1->spacing() == glm::dvec3(1.0, 1.0, 2.0));
    const std::string absent = errorOf([&] { open("absent.zarr"); });
    CHECK_HAS(absent, "absent.zarr");
    CHECK_HAS(absent, "no such folder");
}

TEST_CASE("the scene built for a .zarr folder names it, also when given as 'head.zarr/'") {
    TempDir dir;
    writeOmeZarrPyramid(*patternGrid({5, 4, 3}, VoxelType::UByte), dir.file("head.zarr"));
    for (const std::string& given : {dir.file("head.zarr"), dir.file("head.zarr/")}) {
        CAPTURE(given);
        CHECK(fileKindOf(given) == FileKind::Volume);
        CHECK_HAS(writeSceneToString(*sceneForVolumeFile(given)), "fileName \"head.zarr\"");
    }
}

TEST_CASE("volsg-pyramid says what is wrong in one line") {
    TempDir dir;
    const std::string command = tool + " " + dir.file("absent.nrrd") + " -o " + dir.file("o.zarr") +
                                " > " + dir.file("tool.log") + " 2>&1";
    CHECK(std::system(command.c_str()) != 0);
    const std::string log = readFile(dir.file("tool.log"));
    CHECK_HAS(log, "volsg-pyramid: ");
    CHECK_HAS(log, "absent.nrrd");
    const std::string bad =
        tool + " x.nrrd -o y.zarr --compressor lzma > " + dir.file("tool.log") + " 2>&1";
    CHECK(std::system(bad.c_str()) != 0);
    CHECK_HAS(readFile(dir.file("tool.log")), "unknown compressor 'lzma'");
}
