#pragma once
// The viewer's view settings by name, for the command line, the script and the panels:
// the window layout (the 3D view alone, or with the three section views) and the navigation
// mode (Inventor's examiner, fly and walk viewers) and the antialiasing of the 3D view.
// Stereo modes: StereoRenderer.h.

#include <string>

namespace volsg {

enum class ViewLayout {
    Single, ///< the 3D view fills the window
    Four    ///< 2x2: 3D top left, axial top right, coronal bottom left, sagittal bottom right
};

enum class NavigationMode { Examiner, Fly, Walk };

/// "single" / "four"; throws Error for anything else.
ViewLayout parseViewLayout(const std::string& text);
const char* viewLayoutName(ViewLayout layout);
/// "examiner" / "fly" / "walk"; throws Error for anything else.
NavigationMode parseNavigationMode(const std::string& text);
const char* navigationModeName(NavigationMode mode);

/// Antialiasing of the 3D view: off, 4x multisampling of the opaque pass
/// (RenderOptions::samples; volumes composite against its resolved depth) or 2x2 supersampling
/// of the whole view (four times the pixels, volumes included).
enum class Antialias { Off, Multisample, Supersample };
/// "off" / "msaa" / "2x2"; throws Error for anything else.
Antialias parseAntialias(const std::string& text);
const char* antialiasName(Antialias mode);

} // namespace volsg
