#include <volsg/paging/LodSelection.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <set>
#include <tuple>

namespace volsg {

namespace {

/// The box's corners outside one plane of the view frustum, all of them: not seen.
bool outsideFrustum(const glm::dmat4& clipFromLocal, const glm::dvec3& lo, const glm::dvec3& hi) {
    int outside[6] = {0, 0, 0, 0, 0, 0};
    for (int c = 0; c < 8; ++c) {
        const glm::dvec4 p =
            clipFromLocal *
            glm::dvec4((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z, 1.0);
        for (int a = 0; a < 3; ++a) {
            if (p[a] < -p.w) ++outside[2 * a];
            if (p[a] > p.w) ++outside[2 * a + 1];
        }
    }
    return std::any_of(std::begin(outside), std::end(outside), [](int n) { return n == 8; });
}

/// Eye-space distance from the eye (perspective) to the nearest point of the brick's region.
double eyeDistance(const PagedLayout& layout, const BrickKey& key, const LodView& view) {
    glm::dvec3 lo, hi;
    layout.box(key, lo, hi);
    if (view.orthographic) {
        // Depth of the nearest corner: an order only.
        double nearest = std::numeric_limits<double>::infinity();
        for (int c = 0; c < 8; ++c) {
            const glm::dvec4 e =
                view.modelView * glm::dvec4((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y,
                                            (c & 4) ? hi.z : lo.z, 1.0);
            nearest = std::min(nearest, -e.z);
        }
        return nearest;
    }
    const glm::dvec3 eye = glm::dvec3(glm::inverse(view.modelView) * glm::dvec4(0, 0, 0, 1));
    const glm::dvec3 nearest = glm::clamp(eye, lo, hi);
    return glm::length(glm::dvec3(view.modelView * glm::dvec4(nearest, 1.0)));
}

struct Candidate {
    double pixels;
    BrickKey key;
    bool operator<(const Candidate& o) const { return pixels < o.pixels; } // largest on top
};

} // namespace

double projectedVoxelPixels(const PagedLayout& layout, const BrickKey& key, const LodView& view) {
    const glm::dvec3 voxel = layout.spacingOf(key.level);
    double eyeVoxel = 0.0; // the longest voxel edge in eye units
    for (int a = 0; a < 3; ++a)
        eyeVoxel = std::max(eyeVoxel, voxel[a] * glm::length(glm::dvec3(view.modelView[a])));
    const double pixelsPerEyeUnit = 0.5 * view.projection[1][1] * view.viewportHeight;
    if (view.orthographic) return eyeVoxel * pixelsPerEyeUnit;
    const double distance = eyeDistance(layout, key, view);
    if (!(distance > 0.0)) return std::numeric_limits<double>::infinity();
    return eyeVoxel * pixelsPerEyeUnit / distance;
}

LodSelection selectBricks(const PagedLayout& layout, const LodView& view,
                          const LodRequest& request) {
    LodSelection out;
    const glm::dmat4 clipFromLocal = view.projection * view.modelView;
    auto visible = [&](const BrickKey& key) {
        glm::dvec3 lo, hi;
        layout.box(key, lo, hi);
        const bool inRegion = request.regionMin.x > request.regionMax.x ||
                              (glm::all(glm::lessThan(lo, request.regionMax)) &&
                               glm::all(glm::greaterThan(hi, request.regionMin)));
        if (inRegion && !outsideFrustum(clipFromLocal, lo, hi)) return true;
        ++out.culled;
        return false;
    };
    auto bytesOf = [&](const BrickKey& key) { return request.bytes ? request.bytes(key) : 0; };

    std::priority_queue<Candidate> open;
    std::set<BrickKey> cut, refined;
    std::vector<std::pair<std::tuple<int, double>, BrickKey>> wanted;
    auto want = [&](const BrickKey& key) {
        wanted.push_back({{-key.level, eyeDistance(layout, key, view)}, key});
    };
    for (const BrickKey& root : layout.roots()) {
        if (!visible(root)) continue;
        if (!request.available(root)) {
            want(root);
            continue;
        }
        open.push({projectedVoxelPixels(layout, root, view), root});
        cut.insert(root);
        out.bytes += bytesOf(root);
    }
    while (!open.empty()) {
        const Candidate c = open.top();
        open.pop();
        if (c.pixels <= request.pixelBudget || c.key.level == 0) continue; // fine enough
        std::vector<BrickKey> children;
        std::uint64_t childBytes = 0;
        for (const BrickKey& child : layout.children(c.key)) {
            if (!visible(child)) continue;
            children.push_back(child);
            childBytes += bytesOf(child);
        }
        // The budget first: children that could never be drawn are not worth loading.
        const std::uint64_t after = out.bytes + childBytes; // the parent stays, a fallback
        if (request.textureBudget > 0 && after > request.textureBudget) {
            out.budgetLimited = true;
            continue;
        }
        bool missing = false;
        for (const BrickKey& child : children)
            if (!request.available(child)) {
                want(child);
                missing = true;
            }
        if (missing) continue;
        cut.erase(c.key);
        refined.insert(c.key);
        out.bytes = after;
        for (const BrickKey& child : children) {
            cut.insert(child);
            open.push({projectedVoxelPixels(layout, child, view), child});
        }
    }
    out.refined.assign(refined.begin(), refined.end());
    std::sort(wanted.begin(), wanted.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& w : wanted)
        out.wanted.push_back(w.second);

    // Back to front: the roots in their grid's order, each brick not drawn itself replaced by
    // its children in theirs (an octree's cut keeps a visibility order that way).
    const glm::dvec3 viewer =
        view.orthographic
            ? glm::dvec3(glm::inverse(view.modelView) * glm::dvec4(0.0, 0.0, -1.0, 0.0))
            : glm::dvec3(glm::inverse(view.modelView) * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    std::vector<BrickKey> stack = layout.roots();
    layout.backToFront(stack, viewer, view.orthographic);
    std::reverse(stack.begin(), stack.end()); // the back one on top
    while (!stack.empty()) {
        const BrickKey key = stack.back();
        stack.pop_back();
        if (cut.count(key)) {
            out.drawn.push_back(key);
            const double pixels = projectedVoxelPixels(layout, key, view);
            out.worstPixels = std::max(out.worstPixels, pixels);
            if (key.level > 0 && pixels > request.pixelBudget) ++out.coarser;
            continue;
        }
        if (!refined.count(key)) continue; // culled, or wanted and not yet available
        std::vector<BrickKey> children = layout.children(key);
        layout.backToFront(children, viewer, view.orthographic);
        for (auto it = children.rbegin(); it != children.rend(); ++it)
            stack.push_back(*it);
    }
    return out;
}

} // namespace volsg
