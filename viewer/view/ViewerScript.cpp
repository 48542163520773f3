#include "ViewerScript.h"

#include "PatientOrientation.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <volsg/core/Error.h>
#include <volsg/render/StereoRenderer.h>

#include "ViewModes.h"

namespace volsg {

namespace {

struct LineReader {
    std::vector<std::string> words;
    std::size_t next = 0;
    const std::string& file;
    int line;

    [[noreturn]] void fail(const std::string& message) const {
        throw Error(message, file, line, 1);
    }
    bool more() const { return next < words.size(); }
    std::string word(const char* what) {
        if (!more()) fail(std::string("expected ") + what);
        return words[next++];
    }
    double number(const char* what) {
        const std::string w = word(what);
        char* end = nullptr;
        const double v = std::strtod(w.c_str(), &end);
        if (w.empty() || *end != '\0') fail(std::string("expected ") + what + ", got '" + w + "'");
        return v;
    }
    int count(const char* what) {
        const double v = number(what);
        if (v < 0 || v > 1e6 || v != double(int(v))) fail(std::string(what) + " must be a count");
        return int(v);
    }
    bool nextIsNumber() const {
        if (!more()) return false;
        char* end = nullptr;
        std::strtod(words[next].c_str(), &end);
        return !words[next].empty() && *end == '\0';
    }
    bool nextIsPoint() const {
        if (!more()) return false;
        if (nextIsNumber()) return true;
        const std::string& w = words[next];
        return w.find(':') != std::string::npos;
    }
    std::vector<double> triple(const std::string& text, std::size_t n) {
        std::vector<double> out;
        std::stringstream in(text);
        std::string part;
        while (std::getline(in, part, ',')) {
            char* end = nullptr;
            const double v = std::strtod(part.c_str(), &end);
            if (part.empty() || *end != '\0') fail("bad number '" + part + "' in '" + text + "'");
            out.push_back(v);
        }
        if (out.size() != n) fail("'" + text + "' needs " + std::to_string(n) + " numbers");
        return out;
    }
    ScriptPoint point() {
        ScriptPoint p;
        if (nextIsNumber()) {
            p.value.x = number("x");
            p.value.y = number("y");
            return p;
        }
        const std::string w = word("a point");
        const auto colon = w.find(':');
        if (colon == std::string::npos) fail("expected a point, got '" + w + "'");
        const std::string place = w.substr(0, colon), rest = w.substr(colon + 1);
        if (place == "world") {
            const auto v = triple(rest, 3);
            p.kind = ScriptPoint::Kind::World;
            p.value = {v[0], v[1], v[2]};
        } else if (place == "tf" || place == "planeOpacity" || place == "errorTarget") {
            const auto v = triple(rest, 2);
            p.kind = ScriptPoint::Kind::Canvas;
            p.canvas = place;
            p.value = {v[0], v[1], 0.0};
        } else if (place == "view") {
            const auto colon2 = rest.find(':');
            if (colon2 == std::string::npos) fail("expected view:NAME:U,V, got '" + w + "'");
            const auto v = triple(rest.substr(colon2 + 1), 2);
            p.kind = ScriptPoint::Kind::View;
            p.canvas = rest.substr(0, colon2);
            if (p.canvas != "3d" && p.canvas != "axial" && p.canvas != "coronal" &&
                p.canvas != "sagittal")
                fail("unknown view '" + p.canvas + "' (3d, axial, coronal, sagittal)");
            p.value = {v[0], v[1], 0.0};
        } else if (place == "dialog") {
            p.kind = ScriptPoint::Kind::Dialog;
            p.canvas = rest;
            if (rest.empty()) fail("expected dialog:NAME, got '" + w + "'");
        } else {
            fail("unknown place '" + place +
                 "' (world, tf, planeOpacity, errorTarget, view, dialog)");
        }
        return p;
    }
    int button() {
        const std::string w = word("a button");
        if (w == "left") return GLFW_MOUSE_BUTTON_LEFT;
        if (w == "right") return GLFW_MOUSE_BUTTON_RIGHT;
        if (w == "middle") return GLFW_MOUSE_BUTTON_MIDDLE;
        fail("unknown button '" + w + "' (left, middle, right)");
    }
    int mods() {
        int m = 0;
        while (more()) {
            const std::string w = word("a modifier");
            if (w == "shift")
                m |= GLFW_MOD_SHIFT;
            else if (w == "ctrl")
                m |= GLFW_MOD_CONTROL;
            else if (w == "alt")
                m |= GLFW_MOD_ALT;
            else
                fail("unexpected '" + w + "' (modifiers: shift ctrl alt)");
        }
        return m;
    }
    void end() {
        if (more()) fail("unexpected '" + words[next] + "'");
    }
};

} // namespace

int keyCodeOf(const std::string& name) {
    if (name.size() == 1 && name[0] >= 'a' && name[0] <= 'z') return GLFW_KEY_A + (name[0] - 'a');
    if (name.size() == 1 && name[0] >= '0' && name[0] <= '9') return GLFW_KEY_0 + (name[0] - '0');
    if (name == "escape") return GLFW_KEY_ESCAPE;
    if (name == "enter") return GLFW_KEY_ENTER;
    if (name == "space") return GLFW_KEY_SPACE;
    if (name == "tab") return GLFW_KEY_TAB;
    if (name == "delete") return GLFW_KEY_DELETE;
    if (name.size() >= 2 && name[0] == 'f') {
        int n = 0;
        auto [end, ec] = std::from_chars(name.data() + 1, name.data() + name.size(), n);
        if (ec == std::errc() && end == name.data() + name.size() && n >= 1 && n <= 12)
            return GLFW_KEY_F1 + n - 1;
    }
    return -1;
}

std::vector<ScriptStep> parseViewerScript(const std::string& text, const std::string& fileName) {
    std::vector<ScriptStep> steps;
    std::stringstream in(text);
    std::string lineText;
    int lineNumber = 0;
    while (std::getline(in, lineText)) {
        ++lineNumber;
        if (const auto hash = lineText.find('#'); hash != std::string::npos) lineText.resize(hash);
        LineReader r{{}, 0, fileName, lineNumber};
        std::stringstream words(lineText);
        for (std::string w; words >> w;)
            r.words.push_back(w);
        if (r.words.empty()) continue;
        const std::string command = r.word("a command");
        ScriptStep s;
        s.line = lineNumber;
        using K = ScriptStep::Kind;
        if (command == "wait") {
            s.kind = K::Wait;
            if (r.more() && !r.nextIsNumber())
                s.text = r.word("seek"); // until the seek animation is over
            else
                s.frames = r.count("a frame count");
            if (!s.text.empty() && s.text != "seek")
                r.fail("expected a frame count or 'seek', got '" + s.text + "'");
            r.end();
            steps.push_back(s);
        } else if (command == "move") {
            s.kind = K::Move;
            s.hasPoint = true;
            s.point = r.point();
            r.end();
            steps.push_back(s);
        } else if (command == "press" || command == "release") {
            s.kind = command == "press" ? K::Press : K::Release;
            s.button = r.button();
            if (r.nextIsPoint()) {
                s.hasPoint = true;
                s.point = r.point();
            }
            s.mods = r.mods();
            steps.push_back(s);
        } else if (command == "click") {
            const int button = r.button();
            const ScriptPoint p = r.point();
            const int mods = r.mods();
            steps.push_back({K::Move, 0, 0, true, p, 0.0, "", false, mods, lineNumber});
            steps.push_back({K::Press, 0, button, false, p, 0.0, "", false, mods, lineNumber});
            steps.push_back({K::Release, 0, button, false, p, 0.0, "", false, mods, lineNumber});
        } else if (command == "drag") {
            const int button = r.button();
            const ScriptPoint from = r.point(), to = r.point();
            int moves = 8;
            if (r.nextIsNumber()) moves = std::max(1, r.count("a step count"));
            const int mods = r.mods();
            if (from.kind != to.kind || from.canvas != to.canvas)
                r.fail("a drag's two points must be of the same kind");
            steps.push_back({K::Move, 0, 0, true, from, 0.0, "", false, mods, lineNumber});
            steps.push_back({K::Press, 0, button, false, from, 0.0, "", false, mods, lineNumber});
            for (int i = 1; i <= moves; ++i) {
                ScriptPoint p = from;
                p.value = from.value + (to.value - from.value) * (double(i) / double(moves));
                steps.push_back({K::Move, 0, 0, true, p, 0.0, "", false, mods, lineNumber});
            }
            steps.push_back({K::Release, 0, button, false, to, 0.0, "", false, mods, lineNumber});
        } else if (command == "scroll") {
            s.kind = K::Scroll;
            s.scroll = r.number("a scroll amount");
            if (r.nextIsPoint()) {
                s.hasPoint = true;
                s.point = r.point();
            }
            r.end();
            steps.push_back(s);
        } else if (command == "key") {
            s.kind = K::Key;
            s.text = r.word("a key name");
            if (keyCodeOf(s.text) < 0) r.fail("unknown key '" + s.text + "'");
            s.mods = r.mods();
            steps.push_back(s);
        } else if (command == "select" || command == "panel") {
            s.kind = command == "select" ? K::Select : K::Panel;
            s.text = r.word("a name");
            r.end();
            steps.push_back(s);
        } else if (command == "layout" || command == "navigation" || command == "stereo") {
            s.kind = command == "layout"       ? K::Layout
                     : command == "navigation" ? K::Navigation
                                               : K::Stereo;
            s.text = r.word("a mode");
            try {
                if (s.kind == K::Layout) parseViewLayout(s.text);
                if (s.kind == K::Navigation) parseNavigationMode(s.text);
                if (s.kind == K::Stereo) parseStereoMode(s.text);
            } catch (const Error& e) {
                r.fail(e.what());
            }
            if (s.kind == K::Stereo && r.more()) {
                s.separation = r.number("an eye separation");
                if (!(s.separation > 0.0 && s.separation <= 1.0))
                    r.fail("the eye separation is a fraction of the focal distance in (0, 1]");
            }
            r.end();
            steps.push_back(s);
        } else if (command == "view") {
            s.kind = K::View;
            s.text = r.word("a view name");
            if (!parseAnatomicalView(s.text))
                r.fail("unknown view '" + s.text +
                       "' (anterior, posterior, left, right, superior, inferior)");
            r.end();
            steps.push_back(s);
        } else if (command == "sections") {
            s.kind = K::Sections;
            s.text = r.word("radiological or neurological");
            if (s.text != "radiological" && s.text != "neurological")
                r.fail("sections are 'radiological' or 'neurological'");
            r.end();
            steps.push_back(s);
        } else if (command == "axes") {
            s.kind = K::Axes;
            for (int a = 0; a < 3; ++a) {
                const std::string sign = r.word("+ or -");
                if (sign != "+" && sign != "-") r.fail("each axis is + or -");
                s.voxel[a] = sign == "+" ? 1 : -1;
            }
            r.end();
            steps.push_back(s);
        } else if (command == "preset") {
            s.kind = K::Preset;
            const std::string apply = r.word("colour, opacity or both");
            if (apply == "colour")
                s.frames = 0;
            else if (apply == "opacity")
                s.frames = 1;
            else if (apply == "both")
                s.frames = 2;
            else
                r.fail("a preset sets 'colour', 'opacity' or 'both'");
            s.text = r.word("a preset name");
            while (r.more())
                s.text += " " + r.word("a preset name");
            steps.push_back(s);
        } else if (command == "hounsfield") {
            s.kind = K::Hounsfield;
            s.scroll = r.number("the data value of 0 HU");
            if (!std::isfinite(s.scroll)) r.fail("the data value of 0 HU must be finite");
            r.end();
            steps.push_back(s);
        } else if (command == "cursor") {
            s.kind = K::Cursor;
            s.voxel = {r.count("I"), r.count("J"), r.count("K")};
            r.end();
            steps.push_back(s);
        } else if (command == "region") {
            s.kind = K::Region;
            s.voxel.x = r.count("a region size");
            if (s.voxel.x < 1) r.fail("the region size must be at least 1");
            r.end();
            steps.push_back(s);
        } else if (command == "screenshot") {
            s.kind = K::Screenshot;
            s.text = r.word("a PNG file name");
            if (r.more()) {
                if (r.word("scene") != "scene") r.fail("screenshot takes a file and 'scene'");
                s.sceneOnly = true;
            }
            r.end();
            steps.push_back(s);
        } else if (command == "save") {
            s.kind = K::Save;
            s.text = r.word("a scene file name");
            r.end();
            steps.push_back(s);
        } else if (command == "step") {
            s.kind = K::SeriesStep;
            s.frames = r.count("a step number");
            r.end();
            steps.push_back(s);
        } else if (command == "play" || command == "pause") {
            s.kind = command == "play" ? K::SeriesPlay : K::SeriesPause;
            r.end();
            steps.push_back(s);
        } else if (command == "open") {
            s.kind = K::Open;
            s.text = r.word("a file");
            r.end();
            steps.push_back(s);
        } else if (command == "drop") {
            s.kind = K::Drop;
            s.files.push_back(r.word("a file"));
            while (r.more())
                s.files.push_back(r.word("a file"));
            steps.push_back(s);
        } else if (command == "recent") {
            s.kind = K::Recent;
            s.frames = r.count("a recent-file number");
            if (s.frames < 1) r.fail("recent files are numbered from 1");
            r.end();
            steps.push_back(s);
        } else if (command == "type") {
            s.kind = K::Type;
            s.text = r.word("text");
            while (r.more())
                s.text += " " + r.word("text");
            steps.push_back(s);
        } else if (command == "dialog") {
            if (r.word("raw") != "raw") r.fail("dialog takes 'raw X Y Z TYPE [SX SY SZ]'");
            s.kind = K::DialogRaw;
            s.voxel = {r.count("X"), r.count("Y"), r.count("Z")};
            s.text = r.word("a voxel type");
            if (s.text != "uchar" && s.text != "ushort" && s.text != "short" && s.text != "float")
                r.fail("voxel types are uchar, ushort, short, float");
            if (r.more())
                for (int a = 0; a < 3; ++a) {
                    s.spacing[a] = r.number("a spacing");
                    if (!(s.spacing[a] > 0.0) || !std::isfinite(s.spacing[a]))
                        r.fail("a spacing must be > 0");
                }
            r.end();
            steps.push_back(s);
        } else if (command == "confirm") {
            s.kind = K::Confirm;
            s.text = r.word("save, discard or cancel");
            if (s.text != "save" && s.text != "discard" && s.text != "cancel")
                r.fail("confirm takes save, discard or cancel");
            r.end();
            steps.push_back(s);
        } else if (command == "quit") {
            s.kind = K::Quit;
            r.end();
            steps.push_back(s);
        } else {
            r.fail("unknown command '" + command + "'");
        }
    }
    return steps;
}

} // namespace volsg
