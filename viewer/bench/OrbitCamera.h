#pragma once
// Cameras on a circle around the scene's centre, for benchmark frames that rotate the view.

#include <volsg/math/Box3.h>
#include <volsg/render/Renderer.h>

namespace volsg::bench {

/// A copy of the scene's camera moved in world space by a rotation of `angle` radians about
/// the vertical axis through `center`; its model matrix is folded in (use it with identity).
ref_ptr<Camera> orbitCamera(const SceneCamera& sceneCamera, const glm::dvec3& center, double angle);

} // namespace volsg::bench
