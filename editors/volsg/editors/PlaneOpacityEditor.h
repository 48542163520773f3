#pragma once
// The model of the plane-opacity editor: Volume.planeOpacity, the extinction multiplier m(t)
// over view depth (t = 0 nearest, 1 farthest point of the volume box), as a control curve.

#include <volsg/core/Node.h>
#include <volsg/editors/CurveEditor.h>

namespace volsg {

class Volume;

class PlaneOpacityEditor {
public:
    /// Largest multiplier the editor offers (the field itself takes any m >= 0).
    static constexpr float maximumMultiplier = 2.0f;

    explicit PlaneOpacityEditor(EditHistory& history);
    void setVolume(Volume* volume);
    Volume* volume() const { return volume_.get(); }
    CurveEditor& curves() { return curves_; }
    /// Back to the default: m = 1 at every depth.
    void reset();

private:
    CurveEditor curves_;
    ref_ptr<Volume> volume_;
};

} // namespace volsg
