#include "ViewModes.h"

#include <volsg/core/Error.h>

namespace volsg {

ViewLayout parseViewLayout(const std::string& text) {
    if (text == "single") return ViewLayout::Single;
    if (text == "four") return ViewLayout::Four;
    throw Error("unknown layout '" + text + "' (single, four)");
}

const char* viewLayoutName(ViewLayout layout) {
    return layout == ViewLayout::Four ? "four" : "single";
}

NavigationMode parseNavigationMode(const std::string& text) {
    if (text == "examiner") return NavigationMode::Examiner;
    if (text == "fly") return NavigationMode::Fly;
    if (text == "walk") return NavigationMode::Walk;
    throw Error("unknown navigation mode '" + text + "' (examiner, fly, walk)");
}

const char* navigationModeName(NavigationMode mode) {
    switch (mode) {
    case NavigationMode::Fly:
        return "fly";
    case NavigationMode::Walk:
        return "walk";
    case NavigationMode::Examiner:
        break;
    }
    return "examiner";
}

Antialias parseAntialias(const std::string& text) {
    if (text == "off") return Antialias::Off;
    if (text == "msaa") return Antialias::Multisample;
    if (text == "2x2") return Antialias::Supersample;
    throw Error("unknown antialiasing '" + text + "' (off, msaa, 2x2)");
}

const char* antialiasName(Antialias mode) {
    return mode == Antialias::Multisample ? "msaa" : mode == Antialias::Supersample ? "2x2" : "off";
}

} // namespace volsg
