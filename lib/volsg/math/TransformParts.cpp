#include <volsg/math/TransformParts.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace volsg {

glm::dmat4 composeTransform(const TransformParts& p, const glm::dvec3& c) {
    const glm::dmat4 I(1.0);
    const glm::dmat4 so = glm::mat4_cast(p.scaleOrientation);
    return glm::translate(I, p.translation) * glm::translate(I, c) * glm::mat4_cast(p.rotation) *
           so * glm::scale(I, p.scaleFactor) * glm::transpose(so) * glm::translate(I, -c);
}

TransformParts decomposeTransform(const glm::dmat4& M, const glm::dvec3& c) {
    TransformParts out;
    const glm::dmat3 A(M);
    // M's translation is t + c - A c.
    out.translation = glm::dvec3(M[3]) + (A * c - c);
    glm::dmat3 S = glm::transpose(A) * A;
    // Jacobi eigen decomposition of the symmetric S.
    glm::dmat3 V(1.0);
    for (int sweep = 0; sweep < 50; ++sweep) {
        double off = 0.0;
        for (int p = 0; p < 3; ++p)
            for (int q = p + 1; q < 3; ++q)
                off += S[q][p] * S[q][p];
        if (off < 1e-24) break;
        for (int p = 0; p < 3; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (std::abs(S[q][p]) < 1e-300) continue;
                const double theta = (S[q][q] - S[p][p]) / (2.0 * S[q][p]);
                const double tt =
                    (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const double cs = 1.0 / std::sqrt(tt * tt + 1.0), sn = tt * cs;
                glm::dmat3 J(1.0);
                J[p][p] = cs;
                J[q][q] = cs;
                J[q][p] = sn;  // row p, column q
                J[p][q] = -sn; // row q, column p
                S = glm::transpose(J) * S * J;
                V = V * J;
            }
    }
    if (glm::determinant(V) < 0.0) V[2] = -V[2];
    glm::dvec3 scale(std::sqrt(std::max(0.0, S[0][0])), std::sqrt(std::max(0.0, S[1][1])),
                     std::sqrt(std::max(0.0, S[2][2])));
    if (glm::determinant(A) < 0.0) scale = -scale;
    // P = V diag(scale) V^T, R = A P^-1.
    glm::dmat3 Pinv(0.0);
    for (int k = 0; k < 3; ++k)
        Pinv += (scale[k] != 0.0 ? 1.0 / scale[k] : 0.0) *
                glm::outerProduct(glm::dvec3(V[k]), glm::dvec3(V[k]));
    out.scaleFactor = scale;
    out.rotation = glm::quat_cast(A * Pinv);
    out.scaleOrientation = glm::quat_cast(V);
    return out;
}

} // namespace volsg
