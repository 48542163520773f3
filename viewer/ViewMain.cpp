// volsg-view: shows a scene in a window with examiner navigation, manipulators and the editor
// panels; `--script FILE` plays recorded input (see view/ViewerScript.h).
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>

#include "CommandLine.h"
#include "view/Viewer.h"
#include <volsg/core/Error.h>

namespace {

const char* usage =
    "usage: volsg-view SCENE [--script FILE] [--size WxH] [--background R,G,B]\n"
    "                  [--antialias [msaa|2x2|off]]\n"
    "                  [--no-panels] [--layout single|four] [--navigation examiner|fly|walk]\n"
    "                  [--stereo off|anaglyph|side-by-side] [--eye-separation F]\n"
    "                  [--seek-time SECONDS]\n"
    "  mouse: left drag rotate, middle or shift+left pan, right or alt+left dolly, wheel dolly,\n"
    "         ctrl+wheel zoom (view angle),\n"
    "         click select, ctrl+left drag on an object: opacity (up/down) and contrast\n"
    "         (left/right), drag a manipulator's handles to move them\n"
    "  keys:  v view all, h home, o perspective/orthographic, a antialiasing (off, msaa,\n"
    "         2x2), s seek (then click: the camera flies half way there in --seek-time,\n"
    "         default 0.5 s),\n"
    "         m manipulator on the selected ClipPlane/BoxClip/Transform, ctrl+s save,\n"
    "         p screenshot, z/x zoom in/out, ctrl+z undo, ctrl+y redo, F1 panels, escape\n"
    "         deselect, q quit, l single/four views, e f w examiner/fly/walk, t stereo\n"
    "         (off, anaglyph, side-by-side)\n"
    "  fly:   the mouse steers, left click faster, middle/right click slower\n"
    "  walk:  hold left: up/down walks, left/right turns; middle drag looks up/down\n"
    "  four views: click a section view to move the cursor (and the planes) there, wheel\n"
    "         steps its plane\n"
    "  The scene reloads when its file changes.\n";

int run(int argc, char** argv) {
    volsg::cli::Arguments args(argc, argv);
    volsg::ViewerOptions options;
    while (!args.empty()) {
        const std::string a = args.take();
        if (a == "--script")
            options.scriptPath = args.value(a);
        else if (a == "--size") {
            const glm::ivec2 s = volsg::cli::parseSize(args.value(a));
            options.width = s.x;
            options.height = s.y;
        } else if (a == "--background")
            options.background = volsg::cli::parseColor(args.value(a));
        else if (a == "--antialias") { // optionally followed by the mode: msaa (default), 2x2
            // The next word is the mode unless it is an option or an existing file (the scene),
            // so a mistyped mode is named as such rather than taken for a second scene.
            const bool modeFollows = !args.empty() && !args.peek().empty() &&
                                     args.peek()[0] != '-' && !std::filesystem::exists(args.peek());
            options.antialias =
                modeFollows ? volsg::parseAntialias(args.take()) : volsg::Antialias::Multisample;
        } else if (a == "--seek-time") {
            const std::string text = args.value(a);
            char* end = nullptr;
            options.seekTime = std::strtod(text.c_str(), &end);
            if (text.empty() || *end != '\0' || !(options.seekTime >= 0.0) ||
                !(options.seekTime <= 10.0))
                throw volsg::Error("option --seek-time expects seconds in [0, 10], not '" + text +
                                   "'");
        } else if (a == "--no-panels")
            options.panels = false;
        else if (a == "--layout")
            options.layout = volsg::parseViewLayout(args.value(a));
        else if (a == "--navigation")
            options.navigation = volsg::parseNavigationMode(args.value(a));
        else if (a == "--stereo")
            options.stereo.mode = volsg::parseStereoMode(args.value(a));
        else if (a == "--eye-separation")
            options.stereo.separationFraction = volsg::cli::parseFraction(args.value(a), a);
        else if (a == "-h" || a == "--help") {
            std::fputs(usage, stdout);
            return 0;
        } else if (!a.empty() && a[0] == '-')
            throw volsg::Error("unknown option '" + a + "'");
        else if (options.scenePath.empty())
            options.scenePath = a;
        else
            throw volsg::Error("more than one scene file given ('" + options.scenePath + "', '" +
                               a + "')");
    }
    if (options.scenePath.empty()) {
        std::fputs(usage, stderr);
        return 2;
    }
    volsg::Viewer viewer(options);
    return viewer.run();
}

} // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "volsg-view: %s\n", e.what());
        return 1;
    }
}
