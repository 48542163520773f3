#include <volsg/manipulators/TransformManip.h>

#include <algorithm>
#include <cmath>

#include <volsg/manipulators/DragMath.h>
#include <volsg/nodes/Cone.h>
#include <volsg/nodes/Cylinder.h>
#include <volsg/nodes/Sphere.h>

namespace volsg {

namespace {
const glm::dvec3 axes[3] = {{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};
const glm::vec3 axisColors[3] = {{1.0f, 0.2f, 0.2f}, {0.2f, 1.0f, 0.2f}, {0.3f, 0.4f, 1.0f}};
int axisOfPart(int part) {
    return (part - TransformManip::ShaftX) / 2;
}
} // namespace

void TransformManip::buildHandles(DraggerGeometry& parts) {
    parts.addPart(Sphere::create(), glm::vec3(0.8f, 0.8f, 0.5f), 0.75f);
    for (int a = 0; a < 3; ++a) {
        parts.addPart(Cylinder::create(), axisColors[a]);
        parts.addPart(Cone::create(), axisColors[a]);
    }
}

glm::dvec3 TransformManip::pivot() const {
    return glm::dvec3(translation()) + glm::dvec3(center());
}

void TransformManip::placeHandles() {
    const double size = localHandleSize();
    const glm::dvec3 p = pivot();
    auto& ball = static_cast<Sphere&>(handles().shape(Ball));
    if (ball.radius() != float(size * ballRadius)) ball.radius = float(size * ballRadius);
    handles().place(Ball, p);
    const double shaft = size * arrowLength * 0.8, tip = size * arrowLength * 0.2;
    for (int a = 0; a < 3; ++a) {
        const int shaftId = ShaftX + 2 * a, tipId = TipX + 2 * a;
        auto& cylinder = static_cast<Cylinder&>(handles().shape(shaftId));
        if (cylinder.height() != float(shaft)) {
            cylinder.height = float(shaft);
            cylinder.radius = float(size * 0.01);
        }
        auto& cone = static_cast<Cone&>(handles().shape(tipId));
        if (cone.height() != float(tip)) {
            cone.height = float(tip);
            cone.bottomRadius = float(size * 0.035);
        }
        const glm::dquat turn = rotationBetween({0.0, 1.0, 0.0}, axes[a]); // shapes stand on +y
        handles().place(shaftId, p + axes[a] * (0.5 * shaft), turn);
        handles().place(tipId, p + axes[a] * (shaft + 0.5 * tip), turn);
    }
}

void TransformManip::startDrag(int part, const Ray& localRay) {
    startPivot_ = pivot();
    startTranslation_ = glm::dvec3(translation());
    startRotation_ = rotation().quat();
    if (part == Ball) {
        startGrab_ = trackballPoint(localRay, startPivot_, localHandleSize() * ballRadius);
    } else {
        const auto s = closestLineParameter(localRay, startPivot_, axes[axisOfPart(part)]);
        lineValid_ = s.has_value();
        startLine_ = s.value_or(0.0);
    }
}

void TransformManip::continueDrag(int part, const Ray& localRay) {
    if (part == Ball) {
        const glm::dvec3 grab =
            trackballPoint(localRay, startPivot_, localHandleSize() * ballRadius);
        // The turn happens in the parent's frame, about the pivot: R' = turn * R.
        const glm::dquat turn = rotationBetween(startGrab_ - startPivot_, grab - startPivot_);
        rotation = rotationFromQuat(turn * startRotation_);
        return;
    }
    if (!lineValid_) {
        startDrag(part, localRay);
        return;
    }
    const glm::dvec3 axis = axes[axisOfPart(part)];
    const auto s = closestLineParameter(localRay, startPivot_, axis);
    if (!s) return;
    translation = glm::vec3(startTranslation_ + axis * (*s - startLine_));
}

} // namespace volsg
