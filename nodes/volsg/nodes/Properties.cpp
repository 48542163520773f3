// Property nodes that only put themselves in scope; renderers read them from the State.
#include <volsg/actions/Action.h>
#include <volsg/nodes/ClipPlane.h>
#include <volsg/nodes/Coordinate3.h>
#include <volsg/nodes/Light.h>
#include <volsg/nodes/Material.h>
#include <volsg/nodes/Normal.h>

namespace volsg {

void Material::doAction(Action& action) {
    action.state().add(*this);
}
void Coordinate3::doAction(Action& action) {
    action.state().add(*this);
}
void Normal::doAction(Action& action) {
    action.state().add(*this);
}
void Light::doAction(Action& action) {
    if (on()) action.state().add(*this);
}
void ClipPlane::doAction(Action& action) {
    if (on()) action.state().add(*this);
}

glm::dvec4 ClipPlane::worldPlane(const Plane& local, const glm::dmat4& model) {
    // A plane as a covector transforms by the inverse transpose: (n, -d) * M^-1.
    const glm::dvec4 p(glm::dvec3(local.normal), -double(local.distance));
    const glm::dvec4 w = glm::transpose(glm::inverse(model)) * p;
    return {w.x, w.y, w.z, -w.w};
}

} // namespace volsg
