// The transfer-function and plane-opacity editor models working on real scene nodes.
#include <doctest/doctest.h>

#include <volsg/editors/EditHistory.h>
#include <volsg/editors/PlaneOpacityEditor.h>
#include <volsg/editors/TransferFunctionEditor.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/Volume.h>
#include <volsg/volume/TransferFunction1D.h>
#include <volsg/volume/VolumeGrid.h>

#include <algorithm>
#include <cmath>

using namespace volsg;

namespace {
const char* labelledScene = "#Inventor V2.1 ascii\n"
                            "Separator {\n"
                            "  VolumeData { generator RAMP16 dimensions 16 4 4 }\n"
                            "  TransferFunction { }\n"
                            "  TransferFunction { tag 2 alpha [ 0 0.5, 1 0.5 ] }\n"
                            "  Volume { }\n"
                            "}\n";
} // namespace

TEST_CASE("the editor finds one function per tag and selects by tag") {
    EditHistory history;
    TransferFunctionEditor editor(history);
    ref_ptr<Node> root = readSceneFromString(labelledScene);
    editor.setScene(root.get());
    REQUIRE(editor.functions().size() == 2);
    CHECK(editor.selected()->tag() == -1);
    REQUIRE(editor.selectTag(2));
    CHECK(editor.selected()->tag() == 2);
    CHECK_FALSE(editor.selectTag(7));
    CHECK(editor.selected()->tag() == 2);
    // Reloading the scene keeps the tag selected.
    editor.setScene(root.get());
    CHECK(editor.selected()->tag() == 2);
}

TEST_CASE("a point added with colour channels selected changes only those channels") {
    EditHistory history;
    TransferFunctionEditor editor(history);
    ref_ptr<Node> root = readSceneFromString(labelledScene);
    editor.setScene(root.get());
    editor.setChannels(TransferFunctionEditor::Red | TransferFunctionEditor::Blue);
    REQUIRE(editor.curves().fields().size() == 2);
    CHECK(editor.channelOfField(1) == TransferFunctionEditor::Blue);
    editor.curves().addPoint({0.5f, 0.2f});
    TransferFunction& tf = *editor.selected();
    CHECK(tf.red.size() == 3);
    CHECK(tf.blue.size() == 3);
    CHECK(tf.green.isDefault());
    CHECK(tf.alpha.isDefault());
    CHECK(tf.function().evaluate(TransferFunction1D::Red, 0.5) ==
          doctest::Approx(0.2).epsilon(1e-6));
    REQUIRE(history.undo()); // one step for both channels
    CHECK(tf.red.size() == 2);
    CHECK(tf.blue.size() == 2);
}

TEST_CASE("dragging a point is one undo step and ends where the mouse let go") {
    EditHistory history;
    TransferFunctionEditor editor(history);
    ref_ptr<Node> root = readSceneFromString(labelledScene);
    editor.setScene(root.get());
    editor.setChannels(TransferFunctionEditor::Alpha);
    CurveEditor& curves = editor.curves();
    curves.beginDrag(0, 1); // the (1, 1) end point
    curves.dragTo({0.9f, 0.6f});
    CHECK(editor.selected()->alpha[1] == glm::vec2(0.9f, 0.6f)); // visible during the drag
    curves.dragTo({0.8f, 0.4f});
    curves.endDrag();
    CHECK(editor.selected()->alpha[1] == glm::vec2(0.8f, 0.4f));
    CHECK(history.size() == 1);
    REQUIRE(history.undo());
    CHECK(editor.selected()->alpha[1] == glm::vec2(1.0f, 1.0f));
    REQUIRE(history.redo());
    CHECK(editor.selected()->alpha[1] == glm::vec2(0.8f, 0.4f));
}

TEST_CASE("a freehand stroke in the editor turns into a few control points") {
    EditHistory history;
    TransferFunctionEditor editor(history);
    ref_ptr<Node> root = readSceneFromString(labelledScene);
    editor.setScene(root.get());
    editor.setChannels(TransferFunctionEditor::Alpha);
    CurveEditor& curves = editor.curves();
    curves.beginStroke();
    // A tent drawn with 101 mouse samples.
    for (int i = 0; i <= 100; ++i) {
        const float x = float(i) / 100.0f;
        curves.addStrokePoint({x, x < 0.5f ? 2.0f * x : 2.0f - 2.0f * x});
    }
    curves.endStroke(0.01f);
    const auto& alpha = editor.selected()->alpha.getValues();
    CHECK(alpha.size() == 3);
    CHECK(editor.selected()->function().evaluate(TransferFunction1D::Alpha, 0.25) ==
          doctest::Approx(0.5).epsilon(1e-5));
    CHECK(history.size() == 1);
}

TEST_CASE("a generic preset applied to both sets all four channels in one step") {
    EditHistory history;
    TransferFunctionEditor editor(history);
    ref_ptr<Node> root = readSceneFromString(labelledScene);
    editor.setScene(root.get());
    const TransferFunctionPreset& hot = transferFunctionPresets()[1];
    REQUIRE(hot.name == "hot metal");
    editor.applyPreset(hot, PresetApply::Both);
    TransferFunction& tf = *editor.selected();
    CHECK(tf.red.getValues() == hot.channels[0]);
    CHECK(tf.function().evaluate(TransferFunction1D::Red, 0.2) ==
          doctest::Approx(0.5).epsilon(1e-6)); // 0 -> 1 over [0, 0.4]
    CHECK(history.size() == 1);
    history.undo();
    CHECK(tf.red.isDefault());
}

TEST_CASE("the histogram counts the ramp volume evenly over the data range") {
    EditHistory history;
    TransferFunctionEditor editor(history);
    ref_ptr<Node> root = readSceneFromString(labelledScene);
    editor.setScene(root.get());
    // RAMP16: USHORT, 0..65535 along x, 16 columns of 16 voxels each; default range 0..65535.
    CHECK(editor.effectiveDataRange() == glm::dvec2(0.0, 65535.0));
    const Histogram& h = editor.histogram();
    CHECK(h.samples == 16 * 4 * 4);
    std::uint64_t total = 0, nonEmpty = 0;
    for (auto c : h.counts) {
        total += c;
        if (c) {
            ++nonEmpty;
            CHECK(c == 16); // one x column: 4 * 4 voxels
        }
    }
    CHECK(total == 256);
    CHECK(nonEmpty == 16);
    const auto heights = h.heights(true);
    CHECK(*std::max_element(heights.begin(), heights.end()) == doctest::Approx(1.0f));
}

TEST_CASE("histogram heights on a log scale lift small counts") {
    Histogram h;
    h.counts = {0, 1, 9, 99};
    const auto linear = h.heights(false), logarithmic = h.heights(true);
    CHECK(linear[1] == doctest::Approx(1.0 / 99.0).epsilon(1e-6));
    CHECK(logarithmic[1] == doctest::Approx(std::log(2.0) / std::log(100.0)).epsilon(1e-6));
    CHECK(logarithmic[2] == doctest::Approx(0.5).epsilon(1e-6)); // log 10 / log 100
    CHECK(linear[0] == 0.0f);
}

TEST_CASE("the plane-opacity editor edits Volume.planeOpacity up to twice the extinction") {
    EditHistory history;
    PlaneOpacityEditor editor(history);
    auto volume = Volume::create();
    editor.setVolume(volume.get());
    editor.curves().addPoint({0.5f, 3.0f}); // clamped to the editor's maximum
    REQUIRE(volume->planeOpacity.size() == 3);
    CHECK(volume->planeOpacity[1] == glm::vec2(0.5f, PlaneOpacityEditor::maximumMultiplier));
    editor.curves().drawLine({0.0f, 0.0f}, {1.0f, 0.0f});
    CHECK(volume->planeOpacity.getValues() == std::vector<glm::vec2>{{0, 0}, {1, 0}});
    editor.reset();
    CHECK(volume->planeOpacity.getValues() == std::vector<glm::vec2>{{0, 1}, {1, 1}});
    CHECK(history.size() == 3);
}
