#include <volsg/actions/Action.h>
#include <volsg/nodes/MatrixTransform.h>
#include <volsg/nodes/Transform.h>

#include <glm/gtc/matrix_transform.hpp>

namespace volsg {

glm::dmat4 Transform::matrix() const {
    const glm::dmat4 I(1.0);
    const glm::dvec3 c(center());
    const glm::dmat4 so = scaleOrientation().matrix();
    return glm::translate(I, glm::dvec3(translation())) * glm::translate(I, c) *
           rotation().matrix() * so * glm::scale(I, glm::dvec3(scaleFactor())) *
           glm::transpose(so) * glm::translate(I, -c);
}

void Transform::doAction(Action& action) {
    action.state().multModelMatrix(matrix());
}

void MatrixTransform::doAction(Action& action) {
    action.state().multModelMatrix(glm::dmat4(matrix()));
}

} // namespace volsg
