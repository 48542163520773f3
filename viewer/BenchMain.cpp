// volsg-bench: frame times of a scene seen from orbiting views, and the built-in suites.
// A benchmark, not a test: it prints medians and minima and asserts nothing.
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "CommandLine.h"
#include "bench/OrbitCamera.h"
#include "bench/SceneGenerators.h"
#include "bench/Timing.h"
#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/context/Context.h>
#include <volsg/core/Error.h>
#include <volsg/io/SceneReader.h>
#include <volsg/render/Renderer.h>

namespace {

using namespace volsg;

const char* usage =
    "usage: volsg-bench SCENE.iv [--frames N] [--size WxH] [--backend osmesa|egl]\n"
    "       volsg-bench --suite parse|traversal|all [--nodes N] [--side S] [--frames N]\n"
    "                   [--keep DIR]\n";

struct Settings {
    std::string scene, suite, keepDir;
    int frames = 20;
    int nodes = 100000;
    int side = 100;
    RenderOptions options;
    Backend backend = Backend::OSMesa;
};

void printRow(const char* what, const bench::Samples& s, const char* unit = "ms/frame") {
    std::printf("%-44s %6zu runs  median %9.3f  min %9.3f  %s\n", what, s.ms.size(), s.median(),
                s.min(), unit);
}

bench::Samples orbitFrames(Node& root, const Settings& st) {
    auto context = Context::createOffscreen(st.backend);
    Renderer renderer;
    const double aspect = double(st.options.width) / st.options.height;
    const SceneCamera sceneCamera = findOrMakeCamera(root, aspect);
    const Box3 box = computeBoundingBox(root);
    const glm::dvec3 center = box.isEmpty() ? glm::dvec3(0.0) : box.center();
    RenderOptions options = st.options;
    options.camera = bench::orbitCamera(sceneCamera, center, 0.0);
    renderer.render(root, options); // warm-up: shader compiles and uploads are not frames
    bench::Samples samples;
    for (int i = 0; i < st.frames; ++i) {
        options.camera = bench::orbitCamera(sceneCamera, center, 2.0 * std::numbers::pi * i / st.frames);
        samples.ms.push_back(bench::timeMs([&] { renderer.render(root, options); }));
    }
    return samples;
}

void keep(const Settings& st, const std::string& name, const std::string& text) {
    if (st.keepDir.empty()) return;
    std::filesystem::create_directories(st.keepDir);
    std::ofstream(std::filesystem::path(st.keepDir) / name) << text;
    std::printf("wrote %s/%s\n", st.keepDir.c_str(), name.c_str());
}

void parseSuite(const Settings& st) {
    const std::string text = bench::generateParseScene(st.nodes);
    keep(st, "parse.iv", text);
    bench::Samples s;
    for (int i = 0; i < 5; ++i)
        s.ms.push_back(bench::timeMs([&] { readSceneFromString(text, "parse.iv"); }));
    char what[96];
    std::snprintf(what, sizeof what, "parse %d-node file (%.1f MB)", st.nodes, text.size() / 1e6);
    printRow(what, s, "ms/parse");
}

void traversalSuite(const Settings& st) {
    const std::string text = bench::generateGridScene(st.side);
    keep(st, "traversal.iv", text);
    ref_ptr<Node> root = readSceneFromString(text, "traversal.iv");
    bench::Samples bbox;
    for (int i = 0; i < 20; ++i) bbox.ms.push_back(bench::timeMs([&] { computeBoundingBox(*root); }));
    char what[96];
    std::snprintf(what, sizeof what, "bounding box, %dx%d grid (%d shapes)", st.side, st.side,
                  st.side * st.side);
    printRow(what, bbox, "ms/traversal");
    std::snprintf(what, sizeof what, "render %dx%d, %dx%d grid", st.options.width,
                  st.options.height, st.side, st.side);
    printRow(what, orbitFrames(*root, st));
}

int run(int argc, char** argv) {
    cli::Arguments args(argc, argv);
    Settings st;
    while (!args.empty()) {
        const std::string a = args.take();
        if (a == "--frames") st.frames = args.intValue(a, 1, 100000);
        else if (a == "--size") {
            const glm::ivec2 s = cli::parseSize(args.value(a));
            st.options.width = s.x;
            st.options.height = s.y;
        } else if (a == "--backend") st.backend = parseBackend(args.value(a));
        else if (a == "--suite") st.suite = args.value(a);
        else if (a == "--nodes") st.nodes = args.intValue(a, 4, 10000000);
        else if (a == "--side") st.side = args.intValue(a, 1, 1000);
        else if (a == "--keep") st.keepDir = args.value(a);
        else if (a == "-h" || a == "--help") {
            std::fputs(usage, stdout);
            return 0;
        } else if (!a.empty() && a[0] == '-') throw Error("unknown option '" + a + "'");
        else if (st.scene.empty()) st.scene = a;
        else throw Error("more than one scene file given");
    }
    if (st.scene.empty() == st.suite.empty()) {
        std::fputs(usage, stderr);
        return 2;
    }
    if (!st.scene.empty()) {
        ref_ptr<Node> root = readScene(st.scene);
        char what[160];
        std::snprintf(what, sizeof what, "%s %dx%d %s", st.scene.c_str(), st.options.width,
                      st.options.height, st.backend == Backend::EGL ? "egl" : "osmesa");
        printRow(what, orbitFrames(*root, st));
        return 0;
    }
    if (st.suite == "parse" || st.suite == "all") parseSuite(st);
    if (st.suite == "traversal" || st.suite == "all") traversalSuite(st);
    if (st.suite != "parse" && st.suite != "traversal" && st.suite != "all")
        throw Error("unknown suite '" + st.suite + "' (parse, traversal, all)");
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "volsg-bench: %s\n", e.what());
        return 1;
    }
}
