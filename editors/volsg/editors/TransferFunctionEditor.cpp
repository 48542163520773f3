#include <volsg/editors/TransferFunctionEditor.h>

#include <volsg/actions/SearchAction.h>
#include <volsg/editors/EditHistory.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/VolumeData.h>

namespace volsg {

namespace {
const int channelBits[4] = {TransferFunctionEditor::Red, TransferFunctionEditor::Green,
                            TransferFunctionEditor::Blue, TransferFunctionEditor::Alpha};
} // namespace

const char* TransferFunctionEditor::presetName(Preset preset) {
    switch (preset) {
    case GreyRamp:
        return "grey ramp";
    case HotMetal:
        return "hot metal";
    case CoolWarm:
        return "cool to warm";
    case AlphaTent:
        return "alpha tent";
    case AlphaStep:
        return "alpha step";
    default:
        return "?";
    }
}

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

std::vector<glm::vec2> TransferFunctionEditor::presetChannel(Preset preset, int bit) {
    using P = std::vector<glm::vec2>;
    switch (preset) {
    case GreyRamp:
        return P{{0, 0}, {1, 1}};
    case HotMetal:
        if (bit == Red) return P{{0, 0}, {0.4f, 1}, {1, 1}};
        if (bit == Green) return P{{0, 0}, {0.3f, 0}, {0.8f, 1}, {1, 1}};
        if (bit == Blue) return P{{0, 0}, {0.6f, 0}, {1, 1}};
        return P{{0, 0}, {1, 1}};
    case CoolWarm:
        if (bit == Red) return P{{0, 0.23f}, {0.5f, 0.87f}, {1, 0.71f}};
        if (bit == Green) return P{{0, 0.3f}, {0.5f, 0.86f}, {1, 0.02f}};
        if (bit == Blue) return P{{0, 0.75f}, {0.5f, 0.86f}, {1, 0.15f}};
        return P{{0, 0}, {1, 1}};
    case AlphaTent:
        if (bit == Alpha) return P{{0, 0}, {0.3f, 0}, {0.5f, 0.8f}, {0.7f, 0}, {1, 0}};
        return P{{0, 0}, {1, 1}};
    case AlphaStep:
        if (bit == Alpha) return P{{0, 0}, {0.49f, 0}, {0.51f, 1}, {1, 1}};
        return P{{0, 0}, {1, 1}};
    default:
        return P{{0, 0}, {1, 1}};
    }
}

TransferFunctionEditor::TransferFunctionEditor(EditHistory& history)
    : history_(history), curves_(history, 0.0f, 1.0f) {}

void TransferFunctionEditor::setScene(Node* root) {
    const int previousTag = selected() ? selected()->tag() : -1;
    functions_.clear();
    data_ = nullptr;
    histogramValid_ = false;
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

void TransferFunctionEditor::applyPreset(Preset preset) {
    TransferFunction* tf = selected();
    if (!tf) return;
    history_.begin(std::string("preset ") + presetName(preset),
                   {&tf->red, &tf->green, &tf->blue, &tf->alpha});
    for (int bit : channelBits) {
        MFVec2f* f = channelField(bit);
        const auto points = presetChannel(preset, bit);
        if (f->getValues() != points) f->setValues(points);
    }
    history_.commit();
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
