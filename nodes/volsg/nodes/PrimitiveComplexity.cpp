#include <volsg/nodes/Complexity.h>
#include <volsg/nodes/PrimitiveComplexity.h>
#include <volsg/state/State.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace volsg {

namespace {

/// Coin's SoShape::getScreenSize: the projected box's larger side in pixels, the box measured
/// in normalized device coordinates and capped at 10 viewports (a box through the near plane
/// projects far too large).
float screenSize(const StateView& view, const glm::dmat4& model, const Box3& box) {
    if (box.isEmpty()) return 0.5f * float(std::max(view.width, view.height));
    const glm::dmat4 toClip = view.projection * view.view * model;
    glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (int i = 0; i < 8; ++i) {
        const glm::dvec4 c =
            toClip * glm::dvec4((i & 1) ? box.min.x : box.max.x, (i & 2) ? box.min.y : box.max.y,
                                (i & 4) ? box.min.z : box.max.z, 1.0);
        const glm::dvec2 ndc = glm::dvec2(c) / c.w;
        lo = glm::min(lo, ndc);
        hi = glm::max(hi, ndc);
    }
    const auto side = [](double extent, int pixels) {
        const double n = std::isnan(extent) ? 10.0 : std::min(extent, 10.0);
        return std::floor(std::min(32767.0, 0.5 * pixels * n));
    };
    return float(std::max(side(hi.x - lo.x, view.width), side(hi.y - lo.y, view.height)));
}

} // namespace

float primitiveComplexity(const State& state, const Box3& objectBox) {
    const Complexity* c = state.nearestNode<Complexity>();
    if (!c) return 0.5f;
    const float value = std::isfinite(c->value()) ? c->value() : 0.5f;
    switch (c->type()) {
    case Complexity::BOUNDING_BOX:
        return 0.5f;
    case Complexity::SCREEN_SPACE: {
        const StateView* view = state.view();
        if (!view || !view->projected) return value;
        return std::sqrt(screenSize(*view, state.modelMatrix(), objectBox)) * 0.4f * value;
    }
    default:
        return value;
    }
}

bool tessellationFollowsView(const State& state) {
    const Complexity* c = state.nearestNode<Complexity>();
    return c && c->type() == Complexity::SCREEN_SPACE;
}

} // namespace volsg
