#include "OrbitCamera.h"

#include <glm/gtc/quaternion.hpp>

#include <volsg/nodes/Camera.h>

namespace volsg::bench {

ref_ptr<Camera> orbitCamera(const SceneCamera& sc, const glm::dvec3& center, double angle) {
    ref_ptr<Camera> copy = sc.camera->type().create().cast<Camera>();
    for (std::size_t i = 0; i < sc.camera->fieldCount(); ++i)
        copy->fieldAt(i)->copyFrom(*sc.camera->fieldAt(i));

    const glm::dvec3 worldPosition(sc.model * glm::dvec4(glm::dvec3(sc.camera->position()), 1.0));
    const glm::dquat modelRotation = glm::quat_cast(glm::dmat3(sc.model));
    const glm::dquat worldOrientation = modelRotation * sc.camera->orientation().quat();
    const glm::dquat spin = glm::angleAxis(angle, glm::dvec3(0.0, 1.0, 0.0));

    // q and -q are the same rotation; take w >= 0. GLM 0.9.9.8's glm::angle returns
    // 2 asin(|xyz|) for w < -cos(1/2), not 2 pi minus it: views past about 300 degrees of the
    // orbit then looked away from the scene and drew nothing (the benchmark's 0.8 ms minima).
    glm::dquat q = glm::normalize(spin * worldOrientation);
    if (q.w < 0.0) q = -q;
    copy->position = glm::vec3(center + spin * (worldPosition - center));
    copy->orientation = Rotation{glm::vec3(glm::axis(q)), float(glm::angle(q))};
    return copy;
}

} // namespace volsg::bench
