// volsg-view: shows a scene in a window with examiner navigation, manipulators and the editor
// panels; `--script FILE` plays recorded input (see view/ViewerScript.h).
#include <cstdlib>
#include <filesystem>
#include <string>

#include "CommandLine.h"
#include "view/Viewer.h"
#include <volsg/core/Error.h>

namespace {

const char* usage =
    "usage: volsg-view FILE [--script FILE] [--size WxH] [--background R,G,B]\n"
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
    "  files: ctrl+o the open dialog (File menu: open, open recent, save), or drop a file on\n"
    "         the window; the last 10 opened are in $XDG_CONFIG_HOME/volsg/recent\n"
    "  The scene reloads when its file changes.\n"
    "  FILE: a scene file, a .vsgv, a volume (.nrrd .nhdr .mhd .mha .nii .nii.gz, a DICOM\n"
    "  folder or file, raw with the options below) or a glTF model (.gltf .glb): a data file\n"
    "  opens in the scene built for it, which ctrl+s saves as an .iv beside it.\n"
    "%s";

int run(volsg::cli::Arguments& args) {
    volsg::ViewerOptions options;
    volsg::cli::Options table;
    table.text("--script", options.scriptPath)
        .size("--size", options.width, options.height)
        .color("--background", options.background)
        .add("--antialias", // optionally followed by the mode: msaa (default), 2x2
             [&](volsg::cli::Arguments& words, const std::string&) {
                 // The next word is the mode unless it is an option or an existing file (the
                 // scene), so a mistyped mode is named as such rather than taken for a second
                 // scene.
                 const bool modeFollows = !words.empty() && !words.peek().empty() &&
                                          words.peek()[0] != '-' &&
                                          !std::filesystem::exists(words.peek());
                 options.antialias = modeFollows ? volsg::parseAntialias(words.take())
                                                 : volsg::Antialias::Multisample;
             })
        .value("--seek-time",
               [&](const std::string& text) {
                   char* end = nullptr;
                   options.seekTime = std::strtod(text.c_str(), &end);
                   if (text.empty() || *end != '\0' || !(options.seekTime >= 0.0) ||
                       !(options.seekTime <= 10.0))
                       throw volsg::Error("option --seek-time expects seconds in [0, 10], not '" +
                                          text + "'");
               })
        .flag("--no-panels", options.panels, false)
        .value("--layout",
               [&](const std::string& v) { options.layout = volsg::parseViewLayout(v); })
        .value("--navigation",
               [&](const std::string& v) { options.navigation = volsg::parseNavigationMode(v); })
        .value("--stereo",
               [&](const std::string& v) { options.stereo.mode = volsg::parseStereoMode(v); })
        .fraction("--eye-separation", options.stereo.separationFraction)
        .rawVolume(options.open);
    const std::string help = volsg::cli::withRawUsage(usage);
    if (!table.read(args, help.c_str(), volsg::cli::sceneOperand(options.scenePath))) return 0;
    if (options.scenePath.empty()) return volsg::cli::usageError(help.c_str());
    volsg::cli::checkRawLayout(options.open);
    volsg::Viewer viewer(options);
    return viewer.run();
}

} // namespace

int main(int argc, char** argv) {
    return volsg::cli::runTool("volsg-view", argc, argv, run);
}
