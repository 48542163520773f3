// The transfer-function editor's CT and MR presets (in data units, mapped through the
// function's data range), the colour / opacity / both choice, window/level maths and drags,
// the channel selected at the start, the value axis's ticks and the hover readout.
#include <doctest/doctest.h>

#include <volsg/core/Error.h>
#include <volsg/editors/EditHistory.h>
#include <volsg/editors/TransferFunctionEditor.h>
#include <volsg/editors/ValueAxis.h>
#include <volsg/editors/WindowLevel.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/volume/TransferFunction1D.h>

#include <cmath>
#include <limits>

using namespace volsg;

namespace {

// A float volume whose values run -1000 .. 1000 (RAMP16 scaled is not needed: dataRange set).
const char* ctScene = "#Inventor V2.1 ascii\n"
                      "Separator {\n"
                      "  VolumeData { generator RAMP16 dimensions 16 4 4 }\n"
                      "  DEF tf TransferFunction { dataRange -1024 3071\n"
                      "    red [ 0 0.1, 1 0.2 ] alpha [ 0 0.3, 1 0.4 ] }\n"
                      "  Volume { }\n"
                      "}\n";

const TransferFunctionPreset& presetNamed(const std::string& name) {
    for (const TransferFunctionPreset& p : transferFunctionPresets())
        if (p.name == name) return p;
    throw Error("no preset " + name);
}

std::vector<PiecewiseLinear::Point> asPoints(const std::vector<glm::vec2>& points) {
    std::vector<PiecewiseLinear::Point> out;
    for (const glm::vec2& p : points)
        out.push_back({double(p.x), double(p.y)});
    return out;
}

/// The preset's own curve at data value `x` (in its units), piecewise linear.
double presetAt(const TransferFunctionPreset& preset, int channel, double x) {
    const auto& p = preset.channels[std::size_t(channel)];
    if (x <= p.front().x) return p.front().y;
    for (std::size_t i = 1; i < p.size(); ++i)
        if (x <= p[i].x)
            return p[i - 1].y + (x - p[i - 1].x) / (p[i].x - p[i - 1].x) * (p[i].y - p[i - 1].y);
    return p.back().y;
}

} // namespace

TEST_CASE("the editor starts with the opacity channel alone selected") {
    EditHistory history;
    TransferFunctionEditor editor(history);
    ref_ptr<Node> root = readSceneFromString(ctScene);
    editor.setScene(root.get());
    CHECK(editor.channels() == TransferFunctionEditor::Alpha);
    REQUIRE(editor.curves().fields().size() == 1);
    CHECK(editor.curves().fields()[0] == &editor.selected()->alpha);
    // A click on the canvas shapes the opacity alone.
    editor.curves().addPoint({0.5f, 0.9f});
    CHECK(editor.selected()->alpha.size() == 3);
    CHECK(editor.selected()->red.size() == 2);
}

TEST_CASE("CT and MR presets exist for bone, soft tissue, lung, angiography and T1 brain") {
    for (const char* name : {"CT bone", "CT soft tissue", "CT lung", "CT angiography (MIP)"}) {
        CAPTURE(name);
        CHECK(presetNamed(name).units == TransferFunctionPreset::Units::Hounsfield);
        CHECK(presetNamed(name).modality == "CT");
    }
    CHECK(presetNamed("MR T1 brain").units == TransferFunctionPreset::Units::DataFraction);
    // Bone is opaque where soft tissue (40 HU) is transparent; lung shows -700 HU and hides
    // soft tissue.
    CHECK(presetAt(presetNamed("CT bone"), 3, 40.0) < 0.01);
    CHECK(presetAt(presetNamed("CT bone"), 3, 1000.0) > 0.7);
    CHECK(presetAt(presetNamed("CT lung"), 3, -700.0) > 0.05);
    CHECK(presetAt(presetNamed("CT lung"), 3, 40.0) < 0.03);
    CHECK(presetAt(presetNamed("CT lung"), 3, -1000.0) == 0.0);
}

TEST_CASE("a CT preset lands on the same Hounsfield values whatever the data range") {
    const TransferFunctionPreset& bone = presetNamed("CT bone");
    for (const glm::dvec2 range : {glm::dvec2(-1024, 3071), glm::dvec2(-200, 1200),
                                   glm::dvec2(0, 4095), glm::dvec2(3071, -1024)}) {
        CAPTURE(range.x);
        CAPTURE(range.y);
        for (int channel = 0; channel < 4; ++channel) {
            const auto points = presetChannelInV(bone, channel, range, {0, 1});
            REQUIRE(points.size() >= 2);
            CHECK(points.front().x == 0.0f);
            CHECK(points.back().x == 1.0f);
            TransferFunction1D f;
            f.setChannel(TransferFunction1D::Red, asPoints(points));
            // Every 50 HU inside the range: the function in v is the preset in HU.
            for (double hu = std::min(range.x, range.y); hu <= std::max(range.x, range.y);
                 hu += 50.0) {
                const double v = (hu - range.x) / (range.y - range.x);
                CAPTURE(hu);
                CHECK(f.evaluate(TransferFunction1D::Red, v) ==
                      doctest::Approx(presetAt(bone, channel, hu)).epsilon(1e-4));
            }
        }
    }
}

TEST_CASE("CT stored unsigned: the presets move by the data value of 0 HU") {
    const TransferFunctionPreset& bone = presetNamed("CT bone");
    // Data 0 .. 4095 holding HU + 1024: 300 HU is the value 1324, v = 1324 / 4095.
    const auto alpha = presetChannelInV(bone, 3, {0, 4095}, {0, 4095}, 1024.0);
    TransferFunction1D f;
    f.setChannel(TransferFunction1D::Alpha, asPoints(alpha));
    CHECK(f.evaluate(TransferFunction1D::Alpha, 1324.0 / 4095.0) ==
          doctest::Approx(presetAt(bone, 3, 300.0)).epsilon(1e-5));
    CHECK(f.evaluate(TransferFunction1D::Alpha, 1064.0 / 4095.0) < 0.01); // 40 HU: soft tissue
    // A non-finite zero is taken as 0.
    CHECK(presetDataValue(bone, 300.0f, {0, 1}, {0, 1}, std::nan("")) == 300.0);
}

TEST_CASE("an MR preset is placed by fractions of the data's actual range") {
    const TransferFunctionPreset& t1 = presetNamed("MR T1 brain");
    // Data 100 .. 1100, function range 0 .. 2000: fraction 0.45 is value 550, v = 0.275.
    const auto alpha = presetChannelInV(t1, 3, {0, 2000}, {100, 1100});
    TransferFunction1D f;
    f.setChannel(TransferFunction1D::Alpha, asPoints(alpha));
    CHECK(f.evaluate(TransferFunction1D::Alpha, 0.275) ==
          doctest::Approx(presetAt(t1, 3, 0.45)).epsilon(1e-5));
    CHECK(f.evaluate(TransferFunction1D::Alpha, 0.0) == 0.0);
}

TEST_CASE("a preset changes colour, opacity or both as asked, each one undo step") {
    EditHistory history;
    TransferFunctionEditor editor(history);
    ref_ptr<Node> root = readSceneFromString(ctScene);
    editor.setScene(root.get());
    TransferFunction& tf = *editor.selected();
    const std::vector<glm::vec2> red0 = tf.red.getValues(), alpha0 = tf.alpha.getValues();
    const TransferFunctionPreset& bone = presetNamed("CT bone");
    const glm::dvec2 range(-1024, 3071);

    editor.applyPreset(bone, PresetApply::Opacity);
    CHECK(tf.alpha.getValues() == presetChannelInV(bone, 3, range, {0, 1}));
    CHECK(tf.red.getValues() == red0); // colour untouched
    CHECK(tf.green.isDefault());
    REQUIRE(history.undo());
    CHECK(tf.alpha.getValues() == alpha0);

    editor.applyPreset(bone, PresetApply::Colour);
    CHECK(tf.red.getValues() == presetChannelInV(bone, 0, range, {0, 1}));
    CHECK(tf.blue.getValues() == presetChannelInV(bone, 2, range, {0, 1}));
    CHECK(tf.alpha.getValues() == alpha0); // opacity untouched
    REQUIRE(history.undo());
    CHECK(tf.red.getValues() == red0);

    editor.applyPreset(bone, PresetApply::Both);
    CHECK(tf.red.getValues() == presetChannelInV(bone, 0, range, {0, 1}));
    CHECK(tf.alpha.getValues() == presetChannelInV(bone, 3, range, {0, 1}));
    CHECK(history.size() == 1);
}

TEST_CASE("window/level maths: width from horizontal drags, level from vertical ones") {
    const WindowLevel wl = WindowLevel::ofRange({-160, 240});
    CHECK(wl.level == 40.0);
    CHECK(wl.width == 400.0);
    CHECK(wl.range() == glm::dvec2(-160, 240));
    // Data spanning 2000 in a 500 x 400 view: 50 px right widens by 200, 40 px up raises the
    // level by 200.
    const WindowLevel d = wl.dragged({50, -40}, {500, 400}, 2000);
    CHECK(d.width == doctest::Approx(600.0));
    CHECK(d.level == doctest::Approx(240.0));
    CHECK(d.range().x == doctest::Approx(-60.0));
    CHECK(d.range().y == doctest::Approx(540.0));
    // Narrowing stops at a thousandth of the data's span; an inverted range stays inverted.
    CHECK(wl.dragged({-5000, 0}, {500, 400}, 2000).width == doctest::Approx(2.0));
    const WindowLevel inverted = WindowLevel::ofRange({240, -160});
    CHECK(inverted.dragged({50, 0}, {500, 400}, 2000).width == doctest::Approx(-600.0));
    // NaN, infinity and an empty view change nothing.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    CHECK(wl.dragged({nan, 0}, {500, 400}, 2000).width == 400.0);
    CHECK(wl.dragged({0, inf}, {500, 400}, 2000).level == 40.0);
    CHECK(wl.dragged({10, 10}, {0, 400}, 2000).width == 400.0);
    CHECK(wl.dragged({10, 10}, {500, 400}, nan).width == 400.0);
}

TEST_CASE("a window/level drag rescales the function's data range as one undo step") {
    EditHistory history;
    TransferFunctionEditor editor(history);
    ref_ptr<Node> root = readSceneFromString(ctScene);
    editor.setScene(root.get());
    TransferFunction& tf = *editor.selected();
    // RAMP16's data runs 0 .. 65535 (a ramp along x over the 16-bit range).
    const glm::dvec2 minMax = editor.dataMinMax();
    CHECK(minMax.x == 0.0);
    CHECK(minMax.y > 60000.0);
    const double span = minMax.y - minMax.x;
    editor.beginWindowLevel();
    editor.dragWindowLevel({10, 0}, {100, 100});
    editor.dragWindowLevel({20, -10}, {100, 100});
    editor.endWindowLevel();
    // From the start, not step by step: width 4095 + 0.2 span, level 1023.5 + 0.1 span.
    const double width = 4095.0 + 0.2 * span, level = 1023.5 + 0.1 * span;
    CHECK(tf.dataRange()[0] == doctest::Approx(level - 0.5 * width).epsilon(1e-6));
    CHECK(tf.dataRange()[1] == doctest::Approx(level + 0.5 * width).epsilon(1e-6));
    CHECK(history.size() == 1);
    REQUIRE(history.undo());
    CHECK(tf.dataRange() == glm::vec2(-1024, 3071));
}

TEST_CASE("the histogram follows the range, once a window/level drag ends") {
    EditHistory history;
    TransferFunctionEditor editor(history);
    ref_ptr<Node> root = readSceneFromString(ctScene);
    editor.setScene(root.get());
    // RAMP16 (0 .. 65535 along x) over [-1024, 3071]: all but the x = 0 column clamp into the
    // top bin.
    const std::uint64_t top = editor.histogram().counts.back();
    editor.beginWindowLevel();
    editor.dragWindowLevel({100, 0}, {100, 100});   // the range now spans the whole data
    CHECK(editor.histogram().counts.back() == top); // not redone during the drag
    editor.endWindowLevel();
    CHECK(editor.histogram().counts.back() < top); // redone after it
}

TEST_CASE("the readout gives the data value, colour and opacity at v") {
    EditHistory history;
    TransferFunctionEditor editor(history);
    ref_ptr<Node> root = readSceneFromString(ctScene);
    editor.setScene(root.get());
    const auto r = editor.readout(0.5);
    CHECK(r.value == doctest::Approx(1023.5));
    CHECK(r.rgba.r == doctest::Approx(0.15));
    CHECK(r.rgba.a == doctest::Approx(0.35));
    CHECK(r.rgba.g == doctest::Approx(0.5)); // the default ramp
}

TEST_CASE("axis ticks are round data values inside the range") {
    CHECK(niceStep(0.7) == 1.0);
    CHECK(niceStep(1.3) == 2.0);
    CHECK(niceStep(3.0) == 5.0);
    CHECK(niceStep(700.0) == 1000.0);
    CHECK(niceStep(-1.0) == 0.0);
    CHECK(niceFloor(7.3) == 5.0);
    CHECK(niceFloor(0.19) == doctest::Approx(0.1));
    CHECK(niceFloor(std::numeric_limits<double>::quiet_NaN()) == 0.0);
    CHECK(niceTicks(-1024, 3071, 6) == std::vector<double>{-1000, 0, 1000, 2000, 3000});
    CHECK(niceTicks(0, 255, 6) == std::vector<double>{0, 50, 100, 150, 200, 250});
    CHECK(niceTicks(3071, -1024, 6).size() == 5); // inverted ranges too
    for (int maxTicks = 2; maxTicks < 12; ++maxTicks) {
        const auto t = niceTicks(0.013, 0.087, maxTicks);
        CAPTURE(maxTicks);
        CHECK(t.size() >= 2);
        CHECK(int(t.size()) <= maxTicks);
        for (double x : t) {
            CHECK(x >= 0.013 - 1e-12);
            CHECK(x <= 0.087 + 1e-12);
        }
    }
    CHECK(niceTicks(1, 1, 5).empty());
    CHECK(niceTicks(0, std::numeric_limits<double>::infinity(), 5).empty());
}
