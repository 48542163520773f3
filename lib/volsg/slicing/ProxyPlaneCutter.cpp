#include <volsg/slicing/ProxyPlaneCutter.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace volsg {

PlaneLayout PlaneLayout::over(const glm::dvec2& range, double wantedSpacing) {
    PlaneLayout layout;
    layout.nearDepth = range.x;
    const double extent = std::max(range.y - range.x, 0.0);
    const double n = std::ceil(extent / std::max(wantedSpacing, 1e-12));
    layout.count = int(std::clamp(n, 1.0, 1.0e6));
    layout.spacing = extent > 0.0 ? extent / layout.count : std::max(wantedSpacing, 1e-12);
    return layout;
}

namespace {

// Depth of a box-local point: -(modelView * p).z, an affine function a.p + b.
struct DepthFunction {
    glm::dvec3 a;
    double b;
    explicit DepthFunction(const glm::dmat4& mv)
        : a(-mv[0][2], -mv[1][2], -mv[2][2]), b(-mv[3][2]) {}
    double operator()(const glm::dvec3& p) const { return glm::dot(a, p) + b; }
};

std::array<glm::dvec3, 8> corners(const glm::dvec3& lo, const glm::dvec3& hi) {
    std::array<glm::dvec3, 8> c;
    for (int i = 0; i < 8; ++i)
        c[i] = {(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
    return c;
}

// The 12 edges of a box as pairs of corner indices (corners differ in exactly one bit).
constexpr std::array<std::array<int, 2>, 12> kEdges{{{0, 1},
                                                     {2, 3},
                                                     {4, 5},
                                                     {6, 7},
                                                     {0, 2},
                                                     {1, 3},
                                                     {4, 6},
                                                     {5, 7},
                                                     {0, 4},
                                                     {1, 5},
                                                     {2, 6},
                                                     {3, 7}}};

/// A number that grows with the angle of (x, y) around the origin like atan2 does (in
/// [-2, 2)), without its cost: the polygon's vertices only need to be put in order.
double pseudoAngle(double x, double y) {
    const double a = std::abs(x) + std::abs(y);
    if (a == 0.0) return 0.0;
    const double p = y / a; // in [-1, 1], monotonic in the angle on each half plane
    return x >= 0.0 ? p : (y >= 0.0 ? 2.0 - p : -2.0 - p);
}

/// Insertion sort: a slice polygon has 3 to 6 vertices.
void sortSmall(std::pair<double, int>* items, int count) {
    for (int i = 1; i < count; ++i)
        for (int j = i; j > 0 && items[j] < items[j - 1]; --j)
            std::swap(items[j], items[j - 1]);
}

} // namespace

glm::dvec2 ProxyPlaneCutter::depthRange(const glm::dvec3& lo, const glm::dvec3& hi,
                                        const glm::dmat4& modelView) {
    const DepthFunction depth(modelView);
    glm::dvec2 range(std::numeric_limits<double>::infinity(),
                     -std::numeric_limits<double>::infinity());
    for (const auto& c : corners(lo, hi)) {
        const double d = depth(c);
        range.x = std::min(range.x, d);
        range.y = std::max(range.y, d);
    }
    return range;
}

ProxySlices ProxyPlaneCutter::cut(const glm::dvec3& lo, const glm::dvec3& hi,
                                  const glm::dmat4& modelView, const PlaneLayout& layout,
                                  double minDepth) {
    ProxySlices out;
    cutInto(lo, hi, modelView, layout, minDepth, out);
    return out;
}

void ProxyPlaneCutter::cutInto(const glm::dvec3& lo, const glm::dvec3& hi,
                               const glm::dmat4& modelView, const PlaneLayout& layout,
                               double minDepth, ProxySlices& out) {
    out.vertices.clear();
    out.firsts.clear();
    out.spacing = layout.spacing;
    const DepthFunction depth(modelView);
    const auto c = corners(lo, hi);
    std::array<double, 8> cd;
    for (int i = 0; i < 8; ++i)
        cd[i] = depth(c[i]);
    const auto [dMin, dMax] = std::minmax_element(cd.begin(), cd.end());

    // An in-plane basis for ordering polygon vertices by angle.
    const glm::dvec3 n = glm::normalize(depth.a);
    const glm::dvec3 helper = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(n, helper));
    const glm::dvec3 v = glm::cross(n, u);

    const int first = int(std::floor((*dMin - layout.nearDepth) / layout.spacing - 0.5));
    const int last = int(std::ceil((*dMax - layout.nearDepth) / layout.spacing - 0.5));
    std::array<glm::dvec3, 12> points;
    std::array<std::pair<double, int>, 12> order;
    for (int k = std::min(last, layout.count - 1); k >= std::max(first, 0); --k) {
        const double d = layout.depth(k);
        if (d <= *dMin || d >= *dMax || d < minDepth) continue;
        int count = 0;
        glm::dvec3 centroid(0.0);
        for (const auto& e : kEdges) {
            const double d0 = cd[e[0]], d1 = cd[e[1]];
            if ((d0 < d) == (d1 < d)) continue; // the plane does not cross this edge
            const double t = (d - d0) / (d1 - d0);
            points[count] = glm::mix(c[e[0]], c[e[1]], t);
            centroid += points[count++];
        }
        if (count < 3) continue;
        centroid /= count;
        for (int i = 0; i < count; ++i) {
            const glm::dvec3 r = points[i] - centroid;
            order[i] = {pseudoAngle(glm::dot(r, u), glm::dot(r, v)), i};
        }
        sortSmall(order.data(), count);
        out.firsts.push_back(std::uint32_t(out.vertices.size()));
        for (int i = 1; i + 1 < count; ++i) {
            out.vertices.emplace_back(points[order[0].second]);
            out.vertices.emplace_back(points[order[i].second]);
            out.vertices.emplace_back(points[order[i + 1].second]);
        }
    }
}

void ProxyPlaneCutter::appendPlanePolygon(const glm::dvec3& lo, const glm::dvec3& hi,
                                          const glm::dvec3& normal, double distance,
                                          std::vector<glm::vec3>& out) {
    if (!(glm::length(normal) > 0.0)) return;
    const auto c = corners(lo, hi);
    std::array<double, 8> f;
    for (int i = 0; i < 8; ++i)
        f[i] = glm::dot(normal, c[i]) - distance;
    std::array<glm::dvec3, 12> points;
    int count = 0;
    glm::dvec3 centroid(0.0);
    for (const auto& e : kEdges) {
        const double f0 = f[e[0]], f1 = f[e[1]];
        if ((f0 < 0.0) == (f1 < 0.0)) continue;
        points[count] = glm::mix(c[e[0]], c[e[1]], f0 / (f0 - f1));
        centroid += points[count++];
    }
    if (count < 3) return;
    centroid /= count;
    const glm::dvec3 n = glm::normalize(normal);
    const glm::dvec3 helper = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(n, helper));
    const glm::dvec3 v = glm::cross(n, u);
    std::array<std::pair<double, int>, 12> order;
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 r = points[i] - centroid;
        order[i] = {pseudoAngle(glm::dot(r, u), glm::dot(r, v)), i};
    }
    sortSmall(order.data(), count);
    for (int i = 1; i + 1 < count; ++i) {
        out.emplace_back(points[order[0].second]);
        out.emplace_back(points[order[i].second]);
        out.emplace_back(points[order[i + 1].second]);
    }
}

} // namespace volsg
