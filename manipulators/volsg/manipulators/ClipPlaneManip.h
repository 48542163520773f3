#pragma once
// ClipPlaneManip: a ClipPlane with handles (the seed's clip-plane manipulator). Drag the
// translucent square to move the plane along its normal; drag the knob at the end of the
// normal arrow to turn the normal about the square's centre.

#include <volsg/manipulators/Manipulator.h>
#include <volsg/math/Ray.h>
#include <volsg/nodes/ClipPlane.h>

namespace volsg {

class ClipPlaneManip : public Inherit<ClipPlane, ClipPlaneManip>, public Manipulator {
public:
    static constexpr const char* typeName = "ClipPlaneManip";
    enum Part { Square, Arm, Knob };

    Node& node() override { return *this; }

    /// Where the handles sit: the point of the plane nearest the anchor, local coordinates.
    glm::dvec3 handleCenter() const;

protected:
    ~ClipPlaneManip() override = default;
    void buildHandles(DraggerGeometry& handles) override;
    void placeHandles() override;
    void startDrag(int part, const Ray& localRay) override;
    void continueDrag(int part, const Ray& localRay) override;

private:
    // Drag start: the handle centre, unit normal, distance, and where the mouse ray was.
    glm::dvec3 startCenter_{0.0}, startNormal_{0.0, 0.0, 1.0}, startGrab_{0.0};
    double startDistance_ = 0.0, startLine_ = 0.0;
    bool lineValid_ = false;
};

} // namespace volsg
