#pragma once
// The compact voxel-list format as a volsg-bench suite (`--suite compact`): sizes and times
// of .vsgv files for the RTVR scenes (viewer/bench/scenes/rtvr-*.iv).

#include <string>

namespace volsg::bench {

struct CompactSuiteSettings {
    int repeats = 7;      ///< writes and loads timed per scene (medians reported)
    std::string sceneDir; ///< empty: VOLSG_RTVR_SCENE_DIR (compiled in or from the environment)
    std::string keepDir;  ///< when set, the .vsgv files are left there
};

/// Per scene (chest CT surfaces 380k, attractor and basin 1M): extraction time, voxels,
/// .vsgv bytes and bytes per voxel, the share of positions and attributes (each zlib'd on
/// its own), the in-memory size of the extracted arrays, and median write (encode + atomic
/// write) and load (read + decode + rebuild) times. Returns 0, or 1 when no scene was found.
int runCompactSuite(const CompactSuiteSettings& settings);

} // namespace volsg::bench
