#pragma once
// volsg-bench --suite coin: the same files drawn by Coin3D and by volsg, alternating frame by
// frame in one process, with the median frame times and their ratio (viewer/bench/CoinScene.h
// for Coin's frame; built only where CMake finds Coin).

#include <string>
#include <vector>

#include <volsg/render/Renderer.h>

namespace volsg::bench {

struct CoinSuiteSettings {
    int width = 512, height = 512;
    int frames = 20; ///< timed frames per renderer and case
    /// grid, grid-edit, grid100k, grid100k-edit, cone, models (default: all of them).
    std::vector<std::string> cases;
    /// The inventor-data models of the "models" case (files, or folders searched for *.iv).
    std::vector<std::string> models;
    std::string keepDir;   ///< the scene files and both renderers' last frames go there
    RenderDebug debug;     ///< volsg's switches (--float-target, ...)
    bool readBack = false; ///< volsg's frame reads the image back (Renderer::render)
};

/// Prints the table; returns the number of cases that ran.
int runCoinSuite(const CoinSuiteSettings& settings);

} // namespace volsg::bench
