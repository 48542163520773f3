#include <volsg/editors/TransferFunctionEditor.h>

#include <cmath>

#include <volsg/actions/SearchAction.h>
#include <volsg/editors/EditHistory.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/volume/TransferFunction1D.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

namespace {
const int channelBits[4] = {TransferFunctionEditor::Red, TransferFunctionEditor::Green,
                            TransferFunctionEditor::Blue, TransferFunctionEditor::Alpha};
} // namespace

const char* TransferFunctionEditor::channelName(int bit) {
    switch (bit) {
    case Red:
        return "red";
    case Green:
        return "green";
    case Blue:
        return "blue";
    case Alpha:
        return "alpha";
    default:
        return "?";
    }
}

TransferFunctionEditor::TransferFunctionEditor(EditHistory& history)
    : history_(history), curves_(history, 0.0f, 1.0f) {}

void TransferFunctionEditor::setScene(Node* root) {
    const int previousTag = selected() ? selected()->tag() : -1;
    functions_.clear();
    data_ = nullptr;
    histogramValid_ = false;
    minMaxValid_ = false;
    if (windowLevelling_) endWindowLevel();
    selected_ = 0;
    if (root) {
        for (Node* n : findAll(*root, TransferFunction::classType(), true))
            functions_.emplace_back(static_cast<TransferFunction*>(n));
        const std::vector<Node*> data = findAll(*root, VolumeData::classType(), true);
        if (!data.empty()) data_ = ref_ptr<VolumeData>(static_cast<VolumeData*>(data.front()));
    }
    if (!selectTag(previousTag)) rebindCurves();
}

void TransferFunctionEditor::select(std::size_t index) {
    if (index < functions_.size()) selected_ = index;
    histogramValid_ = false;
    rebindCurves();
}

bool TransferFunctionEditor::selectTag(int tag) {
    for (std::size_t i = 0; i < functions_.size(); ++i)
        if (functions_[i]->tag() == tag) {
            select(i);
            return true;
        }
    return false;
}

TransferFunction* TransferFunctionEditor::selected() const {
    return selected_ < functions_.size() ? functions_[selected_].get() : nullptr;
}

void TransferFunctionEditor::setChannels(int mask) {
    channels_ = mask & AllChannels;
    rebindCurves();
}

MFVec2f* TransferFunctionEditor::channelField(int bit) const {
    TransferFunction* tf = selected();
    if (!tf) return nullptr;
    switch (bit) {
    case Red:
        return &tf->red;
    case Green:
        return &tf->green;
    case Blue:
        return &tf->blue;
    case Alpha:
        return &tf->alpha;
    default:
        return nullptr;
    }
}

int TransferFunctionEditor::channelOfField(std::size_t i) const {
    std::size_t k = 0;
    for (int bit : channelBits)
        if (channels_ & bit) {
            if (k == i) return bit;
            ++k;
        }
    return 0;
}

void TransferFunctionEditor::rebindCurves() {
    std::vector<MFVec2f*> fields;
    if (selected())
        for (int bit : channelBits)
            if (channels_ & bit) fields.push_back(channelField(bit));
    curves_.setFields(std::move(fields));
}

void TransferFunctionEditor::applyPreset(const TransferFunctionPreset& preset, PresetApply apply) {
    TransferFunction* tf = selected();
    if (!tf) return;
    const glm::dvec2 range = effectiveDataRange(), minMax = dataMinMax();
    std::vector<Field*> changed;
    std::vector<int> channels;
    for (int i = 0; i < 4; ++i) {
        const bool colour = i < 3;
        if ((colour && apply == PresetApply::Opacity) || (!colour && apply == PresetApply::Colour))
            continue;
        channels.push_back(i);
        changed.push_back(channelField(channelBits[i]));
    }
    history_.begin("preset " + preset.name + " (" + presetApplyName(apply) + ")", changed);
    for (int i : channels) {
        MFVec2f* f = channelField(channelBits[i]);
        const auto points = presetChannelInV(preset, i, range, minMax, hounsfieldZero_);
        if (f->getValues() != points) f->setValues(points);
    }
    history_.commit();
}

void TransferFunctionEditor::beginWindowLevel() {
    TransferFunction* tf = selected();
    if (!tf || windowLevelling_) return;
    windowLevelling_ = true;
    windowLevelStart_ = windowLevel();
    history_.begin("window/level", {&tf->dataRange});
}

void TransferFunctionEditor::dragWindowLevel(glm::dvec2 offset, glm::dvec2 viewPixels) {
    TransferFunction* tf = selected();
    if (!tf || !windowLevelling_) return;
    const glm::dvec2 minMax = dataMinMax();
    double span = minMax.y - minMax.x;
    if (!(span > 0.0)) span = std::abs(windowLevelStart_.width);
    const glm::vec2 range(windowLevelStart_.dragged(offset, viewPixels, span).range());
    if (std::isfinite(range.x) && std::isfinite(range.y) && tf->dataRange() != range)
        tf->dataRange = range;
}

void TransferFunctionEditor::endWindowLevel() {
    if (!windowLevelling_) return;
    windowLevelling_ = false;
    history_.commit();
}

TransferFunctionEditor::Readout TransferFunctionEditor::readout(double v) const {
    Readout out;
    const TransferFunction* tf = selected();
    if (!tf) return out;
    const glm::dvec2 range = effectiveDataRange();
    out.value = range.x + v * (range.y - range.x);
    out.rgba = tf->function().evaluate(v);
    return out;
}

glm::dvec2 TransferFunctionEditor::dataMinMax() {
    const std::uint64_t version = data_ ? data_->version() : 0;
    if (minMaxValid_ && version == minMaxVersion_) return minMax_;
    minMax_ = effectiveDataRange();
    if (data_) {
        try {
            if (const ref_ptr<const VolumeGrid> grid = data_->grid()) {
                const auto [lo, hi] = grid->minMax();
                minMax_ = {lo, hi};
            }
        } catch (const std::exception&) {
            // No data: the function's range stands in.
        }
    }
    minMaxVersion_ = version;
    minMaxValid_ = true;
    return minMax_;
}

glm::dvec2 TransferFunctionEditor::effectiveDataRange() const {
    const TransferFunction* tf = selected();
    if (tf && !tf->dataRange.isDefault()) return glm::dvec2(tf->dataRange());
    if (data_) {
        try {
            if (const ref_ptr<const VolumeGrid> grid = data_->grid()) {
                const auto r = grid->naturalRange();
                return {r.first, r.second};
            }
        } catch (const std::exception&) {
            // A volume that does not load has no range; the default below stands.
        }
    }
    return tf ? glm::dvec2(tf->dataRange()) : glm::dvec2(0.0, 255.0);
}

const Histogram& TransferFunctionEditor::histogram() {
    const glm::dvec2 range = effectiveDataRange();
    const std::uint64_t version = data_ ? data_->version() : 0;
    if (histogramValid_ && range == histogramRange_ && version == histogramDataVersion_)
        return histogram_;
    // A window/level drag changes the range every frame: the histogram (a pass over the data)
    // is redone when the drag ends, not for each step.
    if (histogramValid_ && windowLevelling_ && version == histogramDataVersion_) return histogram_;
    histogram_ = Histogram{};
    histogramRange_ = range;
    histogramDataVersion_ = version;
    histogramValid_ = true;
    if (data_) {
        try {
            if (const ref_ptr<const VolumeGrid> grid = data_->grid())
                histogram_ = Histogram::of(*grid, range);
        } catch (const std::exception&) {
            // No data, no histogram: the editor still edits the curves.
        }
    }
    return histogram_;
}

} // namespace volsg
