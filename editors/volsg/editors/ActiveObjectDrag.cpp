#include <volsg/editors/ActiveObjectDrag.h>

#include <algorithm>
#include <cmath>

#include <volsg/editors/EditHistory.h>
#include <volsg/editors/ScenePicker.h>
#include <volsg/nodes/Material.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/Volume.h>

namespace volsg {

namespace {
// Piecewise linear with constant ends, on points sorted by x that may lie outside [0, 1].
float interpolate(const std::vector<glm::vec2>& p, float x) {
    if (x <= p.front().x) return p.front().y;
    if (x >= p.back().x) return p.back().y;
    for (std::size_t i = 1; i < p.size(); ++i)
        if (x <= p[i].x) {
            const float w = p[i].x > p[i - 1].x ? (x - p[i - 1].x) / (p[i].x - p[i - 1].x) : 1.0f;
            return p[i - 1].y + w * (p[i].y - p[i - 1].y);
        }
    return p.back().y;
}
} // namespace

ActiveObjectDrag::ActiveObjectDrag(EditHistory& history) : history_(history) {}

std::vector<glm::vec2> ActiveObjectDrag::scaleOpacity(const std::vector<glm::vec2>& alpha,
                                                      double factor) {
    // Scaled, the curve may rise above 1 between points: a point where it crosses 1 keeps the
    // clamped curve exactly min(1, factor * alpha).
    std::vector<glm::vec2> out;
    out.reserve(alpha.size() * 2);
    for (std::size_t i = 0; i < alpha.size(); ++i) {
        const double y = double(alpha[i].y) * factor;
        if (i > 0) {
            const double prev = double(alpha[i - 1].y) * factor;
            if ((prev - 1.0) * (y - 1.0) < 0.0) {
                const double t = (1.0 - prev) / (y - prev);
                out.push_back({float(alpha[i - 1].x + t * (alpha[i].x - alpha[i - 1].x)), 1.0f});
            }
        }
        out.push_back({alpha[i].x, float(std::clamp(y, 0.0, 1.0))});
    }
    return out;
}

std::vector<glm::vec2> ActiveObjectDrag::scaleContrast(const std::vector<glm::vec2>& alpha,
                                                       double factor) {
    if (alpha.size() < 2 || !(factor > 0.0)) return alpha;
    // The span where the curve changes: from the first to the last point next to a change.
    std::size_t first = alpha.size(), last = 0;
    for (std::size_t i = 0; i + 1 < alpha.size(); ++i)
        if (alpha[i].y != alpha[i + 1].y) {
            first = std::min(first, i);
            last = std::max(last, i + 1);
        }
    if (first >= alpha.size()) return alpha; // constant: contrast means nothing
    const double c = 0.5 * (double(alpha[first].x) + double(alpha[last].x));
    std::vector<glm::vec2> moved = alpha;
    for (glm::vec2& p : moved)
        p.x = float(c + (double(p.x) - c) / factor);
    std::vector<glm::vec2> out;
    out.push_back({0.0f, interpolate(moved, 0.0f)});
    for (const glm::vec2& p : moved)
        if (p.x > 1e-4f && p.x < 1.0f - 1e-4f) out.push_back(p);
    out.push_back({1.0f, interpolate(moved, 1.0f)});
    return out;
}

bool ActiveObjectDrag::begin(Node& root, Node& object) {
    end();
    if (object.isA<Volume>()) {
        // The transfer function the volume is drawn with: the nearest one in its scope.
        auto* tf = static_cast<TransferFunction*>(
            nearestInScope(root, object, TransferFunction::classType()));
        if (!tf) return false;
        target_ = ref_ptr<Node>(tf);
        startAlpha_ = tf->alpha.getValues();
        history_.begin("drag opacity and contrast", {&tf->alpha});
        return true;
    }
    auto* material = static_cast<Material*>(nearestInScope(root, object, Material::classType()));
    if (!material) return false;
    target_ = ref_ptr<Node>(material);
    startTransparency_ = material->transparency.empty() ? 0.0f : material->transparency[0];
    history_.begin("drag opacity", {&material->transparency});
    return true;
}

void ActiveObjectDrag::update(const glm::dvec2& delta) {
    if (!target_) return;
    // Up: more opaque; right: steeper. Within 16x either way, so a long drag stays undoable by
    // dragging back (a curve squeezed to a point would lose its shape).
    const double opacity = std::exp2(std::clamp(-delta.y / pixelsPerDoubling, -4.0, 4.0));
    const double contrast = std::exp2(std::clamp(delta.x / pixelsPerDoubling, -4.0, 4.0));
    if (auto* tf = dynamic_cast<TransferFunction*>(target_.get())) {
        const auto points = scaleOpacity(scaleContrast(startAlpha_, contrast), opacity);
        if (tf->alpha.getValues() != points) tf->alpha.setValues(points);
    } else if (auto* m = dynamic_cast<Material*>(target_.get())) {
        const float t =
            float(std::clamp(1.0 - (1.0 - double(startTransparency_)) * opacity, 0.0, 1.0));
        if (m->transparency.empty() || m->transparency[0] != t) m->transparency.set1Value(0, t);
    }
}

void ActiveObjectDrag::end() {
    if (!target_) return;
    target_ = nullptr;
    history_.commit();
}

} // namespace volsg
