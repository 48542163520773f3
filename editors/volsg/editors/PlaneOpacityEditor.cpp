#include <volsg/editors/PlaneOpacityEditor.h>

#include <volsg/nodes/Volume.h>

namespace volsg {

PlaneOpacityEditor::PlaneOpacityEditor(EditHistory& history)
    : curves_(history, 0.0f, maximumMultiplier) {}

void PlaneOpacityEditor::setVolume(Volume* volume) {
    volume_ = ref_ptr<Volume>(volume);
    curves_.setFields(volume ? std::vector<MFVec2f*>{&volume->planeOpacity}
                             : std::vector<MFVec2f*>{});
}

void PlaneOpacityEditor::reset() {
    curves_.setPoints({{0.0f, 1.0f}, {1.0f, 1.0f}}, "reset plane opacity");
}

} // namespace volsg
