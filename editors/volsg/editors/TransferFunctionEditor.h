#pragma once
// The model of the transfer-function editor: which TransferFunction (per tag, for labelled
// volumes) and which RGBA channels are edited, control-point edits, freehand strokes, linear
// segments and presets through CurveEditor, and the data histogram drawn underneath.

#include <string>
#include <vector>

#include <volsg/core/Node.h>
#include <volsg/editors/CurveEditor.h>
#include <volsg/editors/Histogram.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/VolumeData.h> // held by ref_ptr

namespace volsg {

class EditHistory;

class TransferFunctionEditor {
public:
    enum Channel { Red = 1, Green = 2, Blue = 4, Alpha = 8, AllChannels = 15 };
    enum Preset { GreyRamp, HotMetal, CoolWarm, AlphaTent, AlphaStep, presetCount };
    static const char* presetName(Preset preset);
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

    /// Which channels the edits apply to (bits of Channel).
    void setChannels(int mask);
    int channels() const { return channels_; }
    /// The curve editor for the selected channels: its fields are those channels, in R, G, B,
    /// A order.
    CurveEditor& curves() { return curves_; }
    /// The channel bit of curves().fields()[i].
    int channelOfField(std::size_t i) const;
    /// A channel's field of the selected function (null without one).
    MFVec2f* channelField(int channelBit) const;

    /// Sets all four channels of the selected function to a preset (one undo step).
    void applyPreset(Preset preset);
    static std::vector<glm::vec2> presetChannel(Preset preset, int channelBit);

    /// The histogram of the scene's volume under the selected function's data range
    /// (recomputed when that range or the data changes).
    const Histogram& histogram();
    /// The data range the selected function maps to [0, 1]: dataRange when it is set, else
    /// the data type's range (docs/SCENE-FORMAT.md 3).
    glm::dvec2 effectiveDataRange() const;

private:
    void rebindCurves();
    EditHistory& history_;
    CurveEditor curves_;
    std::vector<ref_ptr<TransferFunction>> functions_;
    ref_ptr<VolumeData> data_;
    std::size_t selected_ = 0;
    int channels_ = AllChannels;
    Histogram histogram_;
    glm::dvec2 histogramRange_{0.0};
    std::uint64_t histogramDataVersion_ = 0;
    bool histogramValid_ = false;
};

} // namespace volsg
