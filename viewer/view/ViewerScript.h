#pragma once
// The input script of `volsg-view --script FILE`: mouse drags, key presses, waits, selections,
// screenshots and saves, played one step per frame, as a user would (each press, move and
// release is its own frame, so the UI sees them as separate events).
//
//   # comment
//   wait N                          N frames
//   wait seek                       until the seek animation is over (at once when none runs)
//   move X Y                        the mouse to a point
//   press BUTTON [X Y] [MODS]       BUTTON: left middle right; MODS: shift ctrl alt
//   release BUTTON [X Y] [MODS]
//   click BUTTON X Y [MODS]         move, press, release
//   drag BUTTON X0 Y0 X1 Y1 [N] [MODS]  move, press, N moves (default 8), release
//   scroll DY [X Y]
//   key NAME [MODS]                 a-z 0-9 escape enter space tab delete f1-f12
//   select NAME                     the node DEF'd NAME, as a click in the scene tree
//   panel NAME                      show the named panel (tf, planeOpacity, material, fields,
//                                   region)
//   layout single|four              the 3D view alone, or with the three section views
//   navigation examiner|fly|walk    the navigation mode of the 3D view
//   stereo off|anaglyph|side-by-side [FRACTION]   stereo, with the eye separation as a
//                                   fraction of the camera's focalDistance
//   view anterior|posterior|left|right|superior|inferior   the 3D view from that side
//   sections radiological|neurological   the section views' convention (neurological: flipped)
//   axes SX SY SZ                   how the volume's axes run in patient coordinates: + or -
//                                   each (- reversed; PatientOrientation.h)
//   preset colour|opacity|both NAME the named transfer-function preset (NAME may have spaces)
//   hounsfield VALUE                the data value of 0 HU for CT presets (1024: unsigned CT)
//   cursor I J K                    the 3D cursor on voxel (I, J, K) of the first volume
//   region K                        the readout's histogram region: K^3 voxels
//   screenshot FILE [scene]         the window with its panels; `scene`: the scene alone
//                                   (an animated scene's time is reported with it)
//   save FILE                       the edited scene (docs/SCENE-FORMAT.md)
//   step N                          show step N of the first VolumeSeries (pauses)
//   play | pause                    play the series on / pause it
//   open FILE                       open a file as the File menu does (a scene with unsaved
//                                   edits asks first; raw voxels: the dialog asks their layout)
//   drop FILE...                    files dropped on the window (the first one opens)
//   recent N                        File > Open recent, entry N (1 the newest)
//   type TEXT                       characters typed into the focused text field (the rest of
//                                   the line, spaces kept as one)
//   dialog raw X Y Z TYPE [SX SY SZ]   the open dialog's raw-voxels form (TYPE: uchar ushort
//                                   short float)
//   confirm save|discard|cancel     answers "unsaved edits" before another file opens
//   quit
//
// A point X Y is window pixels (origin top-left), or one word naming a place that is resolved
// when the step runs: `tf:U,V` / `planeOpacity:U,V` (U, V in [0, 1] across a panel's curve
// canvas, V up; `errorTarget:U,V` across the Scene panel's error-target slider),
// `world:X,Y,Z` (where a world point shows in the 3D view) or `view:NAME:U,V` (U, V in
// [0, 1] across a view of the four-view layout, V up; NAME: 3d axial coronal sagittal), or
// `dialog:NAME`, the middle of a row or control of the open dialog as last drawn: a listed file or
// folder by its name, or up, path, showall, raw, dims, open, cancel. Keys
// (`key`) and typed text also reach the dialog's fields; in a scripted session the UI's clock
// steps 1/30 s a frame, so two clicks on one row within 9 frames are a double-click.

#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace volsg {

/// A point as the script gives it: pixels, or a named place resolved at run time.
struct ScriptPoint {
    enum class Kind { Pixels, Canvas, World, View, Dialog };
    Kind kind = Kind::Pixels;
    std::string canvas;    ///< for Canvas and View: its name
    glm::dvec3 value{0.0}; ///< pixels (x, y), canvas (u, v) or a world point
};

struct ScriptStep {
    enum class Kind {
        Wait,
        Move,
        Press,
        Release,
        Scroll,
        Key,
        Select,
        Panel,
        Layout,
        Navigation,
        Stereo,
        Cursor,
        Region,
        View,
        Sections,
        Axes,
        Preset,
        Hounsfield,
        Screenshot,
        Save,
        SeriesStep,
        SeriesPlay,
        SeriesPause,
        Open,
        Drop,
        Recent,
        Type,
        DialogRaw,
        Confirm,
        Quit
    };
    Kind kind = Kind::Wait;
    int frames = 0; ///< Wait
    int button = 0; ///< Press, Release: 0 left, 1 right, 2 middle (GLFW's numbers)
    bool hasPoint = false;
    ScriptPoint point;
    double scroll = 0.0;
    std::string text;                 ///< key name, node name, panel name or file
    bool sceneOnly = false;           ///< Screenshot
    int mods = 0;                     ///< GLFW modifier bits
    int line = 0;                     ///< in the script file, for messages
    double separation = 0;            ///< Stereo: the eye separation fraction (0: unchanged)
    glm::ivec3 voxel{0};              ///< Cursor; Region: voxel.x = K; DialogRaw: the dimensions
    glm::dvec3 spacing{1.0};          ///< DialogRaw
    std::vector<std::string> files{}; ///< Drop
};

/// Reads a script (drag and click are expanded into their steps). Throws Error with the file,
/// line and column of anything it does not understand.
std::vector<ScriptStep> parseViewerScript(const std::string& text, const std::string& fileName);

/// A key name of the script as a GLFW key code; -1 for an unknown name.
int keyCodeOf(const std::string& name);

} // namespace volsg
