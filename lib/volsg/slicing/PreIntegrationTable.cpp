#include <volsg/slicing/PreIntegrationTable.h>

#include <algorithm>
#include <cmath>

namespace volsg {

namespace {
/// docs/SCENE-FORMAT.md section 4: A is clamped so that tau stays finite.
constexpr double kMaxOpacity = 1.0 - 1e-6;
} // namespace

glm::dvec4 PreIntegrationTable::pointAt(double v) const {
    const glm::dvec4 rgba = function_.evaluate(v);
    const double tau = rgba.a > 0.0 ? -std::log1p(-std::min(rgba.a, kMaxOpacity)) : 0.0;
    return {rgba.r, rgba.g, rgba.b, tau};
}

void PreIntegrationTable::build(const TransferFunction1D& function) {
    function_ = function;
    cumulative_.assign(std::size_t(kIntegrationSteps) + 1, glm::dvec4(0.0));
    const double h = 1.0 / kIntegrationSteps;
    glm::dvec4 previous = pointAt(0.0);
    glm::dvec4 sum(0.0);
    for (int i = 1; i <= kIntegrationSteps; ++i) {
        const glm::dvec4 p = pointAt(i * h);
        // Trapezoids of (tau C, tau): the product of two linear pieces, integrated by its ends.
        const glm::dvec4 a(glm::dvec3(previous) * previous.a, previous.a);
        const glm::dvec4 b(glm::dvec3(p) * p.a, p.a);
        sum += 0.5 * h * (a + b);
        cumulative_[std::size_t(i)] = sum;
        previous = p;
    }

    texels_.assign(std::size_t(kSize) * kSize * 4, 0.0f);
    for (int back = 0; back < kSize; ++back)
        for (int front = 0; front < kSize; ++front) {
            const glm::dvec4 s = segment(double(front) / (kSize - 1), double(back) / (kSize - 1));
            float* out = texels_.data() + (std::size_t(back) * kSize + std::size_t(front)) * 4;
            for (int c = 0; c < 4; ++c)
                out[c] = float(s[c]);
        }
}

glm::dvec4 PreIntegrationTable::cumulativeAt(double v) const {
    const double x = std::clamp(v, 0.0, 1.0) * kIntegrationSteps;
    const int i = std::min(int(x), kIntegrationSteps - 1);
    const double f = x - i;
    return cumulative_[std::size_t(i)] * (1.0 - f) + cumulative_[std::size_t(i) + 1] * f;
}

glm::dvec4 PreIntegrationTable::absorbingSegment(double vFront, double vBack) const {
    vFront = std::clamp(vFront, 0.0, 1.0);
    vBack = std::clamp(vBack, 0.0, 1.0);
    const double width = vBack - vFront;
    if (std::abs(width) < 1e-9) {
        // segment()'s point case: the colour and tau at vFront, where its opacity is positive.
        if (!(function_.evaluate(TransferFunction1D::Alpha, vFront) > 0.0)) return glm::dvec4(0.0);
        const glm::dvec4 p = pointAt(vFront);
        if (!(p.a > 1e-12)) return glm::dvec4(0.0);
        return {glm::dvec3(p) * p.a / p.a, p.a}; // rounded as segment() rounds it
    }
    const glm::dvec4 mean = (cumulativeAt(vBack) - cumulativeAt(vFront)) / width;
    if (mean.a > 1e-12) return {glm::dvec3(mean) / mean.a, mean.a};
    return glm::dvec4(0.0);
}

glm::dvec4 PreIntegrationTable::segment(double vFront, double vBack) const {
    vFront = std::clamp(vFront, 0.0, 1.0);
    vBack = std::clamp(vBack, 0.0, 1.0);
    const double width = vBack - vFront;
    glm::dvec4 mean;
    if (std::abs(width) < 1e-9) {
        const glm::dvec4 p = pointAt(vFront);
        mean = glm::dvec4(glm::dvec3(p) * p.a, p.a);
    } else {
        mean = (cumulativeAt(vBack) - cumulativeAt(vFront)) / width;
    }
    if (mean.a > 1e-12) return {glm::dvec3(mean) / mean.a, mean.a};
    // No extinction: the colour does not matter; the plain mean keeps the table smooth.
    const glm::dvec4 p = pointAt(0.5 * (vFront + vBack));
    return {p.r, p.g, p.b, 0.0};
}

} // namespace volsg
