#include "CompactSuite.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include <unistd.h>
#include <zlib.h>

#include "Timing.h"
#include <volsg/core/Error.h>
#include <volsg/io/SceneReader.h>
#include <volsg/voxelfile/PositionCoding.h>
#include <volsg/voxelfile/VoxelFile.h>
#include <volsg/voxelfile/VoxelFileScene.h>

#ifndef VOLSG_RTVR_SCENE_DIR
#define VOLSG_RTVR_SCENE_DIR ""
#endif

namespace volsg::bench {

namespace {

std::size_t deflatedSize(const std::string& raw) {
    uLongf size = compressBound(uLong(raw.size()));
    std::string out(size, '\0');
    compress2(reinterpret_cast<Bytef*>(out.data()), &size,
              reinterpret_cast<const Bytef*>(raw.data()), uLong(raw.size()), Z_BEST_COMPRESSION);
    return size;
}

/// Bytes of the positions of every object, coded as in the file and compressed on their own
/// (the file compresses them together with the attributes, per object).
std::size_t positionBytes(const VoxelFileContent& content) {
    std::size_t bytes = 0;
    for (const PackedObject& o : content.objects) {
        const VoxelObject::Arrays a = o.voxels->arrays();
        bytes += deflatedSize(encodePositions(a.dimensions, a.i, a.j, a.k));
    }
    return bytes;
}

} // namespace

int runCompactSuite(const CompactSuiteSettings& st) {
    std::string dir = st.sceneDir;
    if (dir.empty()) {
        const char* env = std::getenv("VOLSG_RTVR_SCENE_DIR");
        dir = env && *env ? env : VOLSG_RTVR_SCENE_DIR;
    }
    namespace fs = std::filesystem;
    const fs::path out = st.keepDir.empty() ? fs::temp_directory_path() /
                                                  ("volsg-compact-" + std::to_string(::getpid()))
                                            : fs::path(st.keepDir);
    fs::create_directories(out);
    std::printf("# volsg-bench compact suite: .vsgv files of the RTVR scenes, %d timed writes "
                "and loads each (medians)\n",
                st.repeats);
    std::printf("%-24s %8s %10s %10s %8s %10s %10s %10s %9s %9s %9s\n", "scene", "objects",
                "voxels", "file_B", "B/voxel", "pos_B", "rest_B", "memory_B", "extr_ms", "write_ms",
                "load_ms");
    int measured = 0;
    for (const char* name :
         {"rtvr-chest-380k.iv", "rtvr-chest-640k.iv", "rtvr-attractor-basin.iv"}) {
        const fs::path scene = fs::path(dir) / name;
        try {
            ref_ptr<Node> root = readScene(scene.string());
            VoxelFileContent content;
            const double extractMs = timeMs([&] { content = packScene(*root); });
            std::size_t voxels = 0;
            for (const PackedObject& o : content.objects)
                voxels += o.voxels->voxelCount();
            const fs::path file = out / (scene.stem().string() + ".vsgv");
            Samples writes, loads;
            for (int r = 0; r < st.repeats; ++r) {
                writes.ms.push_back(timeMs([&] { writeVoxelFile(file.string(), content); }));
                loads.ms.push_back(timeMs([&] { (void)readVoxelFileFromPath(file.string()); }));
            }
            const std::size_t positions = positionBytes(content);
            const std::size_t sceneBytes = deflatedSize(content.sceneText);
            const auto bytes = std::size_t(fs::file_size(file));
            const std::size_t attributes =
                bytes > positions + sceneBytes ? bytes - positions - sceneBytes : 0;
            std::printf("%-24s %8zu %10zu %10zu %8.3f %10zu %10zu %10zu %9.0f %9.1f %9.1f\n",
                        scene.stem().c_str(), content.objects.size(), voxels, bytes,
                        voxels ? double(bytes) / double(voxels) : 0.0, positions, attributes,
                        voxels * 11, extractMs, writes.median(), loads.median());
            std::fflush(stdout);
            ++measured;
        } catch (const Error& e) {
            std::printf("%-24s skipped: %s\n", scene.stem().c_str(), e.what());
        }
    }
    if (st.keepDir.empty()) fs::remove_all(out);
    return measured > 0 ? 0 : 1;
}

} // namespace volsg::bench
