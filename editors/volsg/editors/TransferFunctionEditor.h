#pragma once
// The model of the transfer-function editor: which TransferFunction (per tag, for labelled
// volumes) and which RGBA channels are edited, control-point edits, freehand strokes, linear
// segments and presets through CurveEditor, window/level of its data range, the readout of a
// value, and the data histogram drawn underneath.

#include <string>
#include <vector>

#include <volsg/core/Node.h>
#include <volsg/editors/CurveEditor.h>
#include <volsg/editors/Histogram.h>
#include <volsg/editors/TransferFunctionPresets.h>
#include <volsg/editors/WindowLevel.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/VolumeData.h> // held by ref_ptr

namespace volsg {

class EditHistory;

class TransferFunctionEditor {
public:
    enum Channel { Red = 1, Green = 2, Blue = 4, Alpha = 8, AllChannels = 15 };
    static const char* channelName(int channelBit);

    explicit TransferFunctionEditor(EditHistory& history);

    /// Finds the TransferFunction nodes under `root` (one per tag) and the first VolumeData, for
    /// the histogram. Selects the first function; keeps the previous selection's tag if it
    /// still exists.
    void setScene(Node* root);
    const std::vector<ref_ptr<TransferFunction>>& functions() const { return functions_; }
    /// Selects by index in functions(); also by tag (false if no function has it).
    void select(std::size_t index);
    bool selectTag(int tag);
    TransferFunction* selected() const;

    /// Which channels the edits apply to (bits of Channel); alpha alone at the start, so that a
    /// first click shapes the opacity and leaves the colours alone.
    void setChannels(int mask);
    int channels() const { return channels_; }
    /// The curve editor for the selected channels: its fields are those channels, in R, G, B,
    /// A order.
    CurveEditor& curves() { return curves_; }
    /// The channel bit of curves().fields()[i].
    int channelOfField(std::size_t i) const;
    /// A channel's field of the selected function (null without one).
    MFVec2f* channelField(int channelBit) const;

    /// Sets the selected function's colour channels, its opacity, or both to a preset (one
    /// undo step), mapped into v through its effective data range (TransferFunctionPresets.h).
    void applyPreset(const TransferFunctionPreset& preset, PresetApply apply);
    /// The data value of 0 HU for CT presets (0: data in HU; 1024: CT stored unsigned).
    void setHounsfieldZero(double value) { hounsfieldZero_ = value; }
    double hounsfieldZero() const { return hounsfieldZero_; }

    /// Window/level of the selected function's data range: a drag from begin to end is one
    /// undo step; each dragTo sets dataRange from the range at the start and the drag's whole
    /// offset (WindowLevel::dragged with the data's actual span).
    void beginWindowLevel();
    void dragWindowLevel(glm::dvec2 offsetPixels, glm::dvec2 viewPixels);
    void endWindowLevel();
    bool isWindowLevelling() const { return windowLevelling_; }
    WindowLevel windowLevel() const { return WindowLevel::ofRange(effectiveDataRange()); }

    /// What the editor's readout shows for v: the data value there and the function's colour
    /// and opacity (alpha in .a). Throws Error for a function with an empty channel.
    struct Readout {
        double value = 0.0;
        glm::dvec4 rgba{0.0};
    };
    Readout readout(double v) const;

    /// The histogram of the scene's volume under the selected function's data range
    /// (recomputed when that range or the data changes; during a window/level drag, once it
    /// ends).
    const Histogram& histogram();
    /// The data range the selected function maps to [0, 1]: dataRange when it is set, else
    /// the data type's range (docs/SCENE-FORMAT.md 3).
    glm::dvec2 effectiveDataRange() const;
    /// The data's actual [min, max] (cached per data version); the effective range without
    /// data.
    glm::dvec2 dataMinMax();

private:
    void rebindCurves();
    EditHistory& history_;
    CurveEditor curves_;
    std::vector<ref_ptr<TransferFunction>> functions_;
    ref_ptr<VolumeData> data_;
    std::size_t selected_ = 0;
    int channels_ = Alpha;
    bool windowLevelling_ = false;
    double hounsfieldZero_ = 0.0;
    WindowLevel windowLevelStart_;
    glm::dvec2 minMax_{0.0};
    std::uint64_t minMaxVersion_ = 0;
    bool minMaxValid_ = false;
    Histogram histogram_;
    glm::dvec2 histogramRange_{0.0};
    std::uint64_t histogramDataVersion_ = 0;
    bool histogramValid_ = false;
};

} // namespace volsg
