#pragma once
// A transform's parts in Inventor's order (SbMatrix::setTransform / getTransform):
// M = T * C * R * SO * S * SO^-1 * C^-1, for Transform nodes, DecomposeMatrix and draggers.

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace volsg {

struct TransformParts {
    glm::dvec3 translation{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 scaleFactor{1.0};
    glm::dquat scaleOrientation{1.0, 0.0, 0.0, 0.0};
};

/// The matrix of `parts` about `center`.
glm::dmat4 composeTransform(const TransformParts& parts,
                            const glm::dvec3& center = glm::dvec3(0.0));

/// The parts of an affine matrix about `center`: the linear part split as A = R * P by the
/// polar decomposition (P = SO * S * SO^-1 symmetric, from the eigenvectors of A^T A), a
/// negative determinant carried by the scale.
TransformParts decomposeTransform(const glm::dmat4& matrix,
                                  const glm::dvec3& center = glm::dvec3(0.0));

} // namespace volsg
