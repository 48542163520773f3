#pragma once
// TransformManip: a Transform with handles, usable in place of any Transform. Drag the
// translucent ball to rotate about the transform's centre (a virtual trackball); drag one of
// the three axis arrows to translate along that axis of the parent's coordinates.

#include <volsg/manipulators/Manipulator.h>
#include <volsg/nodes/Transform.h>

namespace volsg {

class TransformManip : public Inherit<Transform, TransformManip>, public Manipulator {
public:
    static constexpr const char* typeName = "TransformManip";
    /// Parts: the ball, then the shaft and the tip of the x, y and z arrows.
    enum Part { Ball, ShaftX, TipX, ShaftY, TipY, ShaftZ, TipZ };
    static constexpr double ballRadius = 0.25; ///< of the handle size
    static constexpr double arrowLength = 0.5; ///< of the handle size, tip included

    Node& node() override { return *this; }

    /// The point the handles turn about, in the parent's coordinates: translation + center.
    glm::dvec3 pivot() const;

protected:
    ~TransformManip() override = default;
    void buildHandles(DraggerGeometry& handles) override;
    void placeHandles() override;
    void startDrag(int part, const Ray& localRay) override;
    void continueDrag(int part, const Ray& localRay) override;

private:
    glm::dvec3 startPivot_{0.0}, startTranslation_{0.0}, startGrab_{0.0};
    glm::dquat startRotation_{1.0, 0.0, 0.0, 0.0};
    double startLine_ = 0.0;
    bool lineValid_ = false;
};

} // namespace volsg
