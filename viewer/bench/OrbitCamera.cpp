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

    const glm::dquat q = glm::normalize(spin * worldOrientation);
    copy->position = glm::vec3(center + spin * (worldPosition - center));
    copy->orientation = Rotation{glm::vec3(glm::axis(q)), float(glm::angle(q))};
    return copy;
}

} // namespace volsg::bench
