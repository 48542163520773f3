#include <volsg/geometry/Nurbs.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include <volsg/core/Error.h>
#include <volsg/geometry/PolygonTessellator.h>

namespace volsg {

namespace {

/// The knot span holding u (knots[s] <= u < knots[s + 1], non-empty), for a B-spline of
/// `count` control points and `degree`; u outside the domain takes the first or last span.
int findSpan(int count, int degree, double u, std::span<const double> knots) {
    if (u >= knots[std::size_t(count)]) {
        int s = count - 1;
        while (s > degree && knots[std::size_t(s)] >= knots[std::size_t(s) + 1])
            --s;
        return s;
    }
    if (u <= knots[std::size_t(degree)]) {
        int s = degree;
        while (s < count - 1 && knots[std::size_t(s)] >= knots[std::size_t(s) + 1])
            ++s;
        return s;
    }
    int low = degree, high = count;
    int mid = (low + high) / 2;
    while (u < knots[std::size_t(mid)] || u >= knots[std::size_t(mid) + 1]) {
        if (u < knots[std::size_t(mid)])
            high = mid;
        else
            low = mid;
        mid = (low + high) / 2;
    }
    return mid;
}

/// The order non-zero basis functions N[span - degree + r] at u and their first derivatives
/// (Piegl and Tiller, The NURBS Book, A2.3 for one derivative).
struct Basis {
    std::array<double, kMaxNurbsOrder> value{}, derivative{};
};
void basisFunctions(int span, int degree, double u, std::span<const double> knots, Basis& b) {
    std::array<std::array<double, kMaxNurbsOrder>, kMaxNurbsOrder> ndu{};
    std::array<double, kMaxNurbsOrder> left{}, right{};
    ndu[0][0] = 1.0;
    for (int j = 1; j <= degree; ++j) {
        left[std::size_t(j)] = u - knots[std::size_t(span + 1 - j)];
        right[std::size_t(j)] = knots[std::size_t(span + j)] - u;
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            // Lower triangle: knot differences (positive in a non-empty span).
            ndu[std::size_t(j)][std::size_t(r)] =
                right[std::size_t(r + 1)] + left[std::size_t(j - r)];
            const double temp =
                ndu[std::size_t(r)][std::size_t(j - 1)] / ndu[std::size_t(j)][std::size_t(r)];
            ndu[std::size_t(r)][std::size_t(j)] = saved + right[std::size_t(r + 1)] * temp;
            saved = left[std::size_t(j - r)] * temp;
        }
        ndu[std::size_t(j)][std::size_t(j)] = saved;
    }
    const auto p = std::size_t(degree);
    for (std::size_t r = 0; r <= p; ++r) {
        b.value[r] = ndu[r][p];
        if (degree == 0) {
            b.derivative[r] = 0.0;
            continue;
        }
        double d = 0.0;
        if (r >= 1) d += ndu[r - 1][p - 1] / ndu[p][r - 1];
        if (r <= p - 1) d -= ndu[r][p - 1] / ndu[p][r];
        b.derivative[r] = double(degree) * d;
    }
}

std::vector<double> toDouble(std::span<const float> knots) {
    return std::vector<double>(knots.begin(), knots.end());
}

/// Steps s of a surface and c of a curve for a complexity (Coin's sogl_set_nurbs_complexity).
int surfaceSteps(float complexity) {
    const float c = std::clamp(complexity, 0.0f, 1.0f);
    if (c < 0.10f) return 2;
    if (c < 0.25f) return 3;
    if (c < 0.40f) return 4;
    if (c < 0.55f) return 5;
    return int(std::pow(c, 3.32f) * 28.0f) + 2;
}
int curveSteps(float complexity) {
    const float c = std::clamp(complexity, 0.0f, 1.0f);
    return c < 0.5f ? int(18.0f * c) + 1 : int(380.0f * c) - 180;
}

// ---- trimming ------------------------------------------------------------------------------

struct Rect {
    double u0, u1, v0, v1;
};

/// Whether segment a-b meets the closed rectangle (Liang-Barsky).
bool segmentMeetsRect(glm::dvec2 a, glm::dvec2 b, const Rect& r) {
    double t0 = 0.0, t1 = 1.0;
    const glm::dvec2 d = b - a;
    const double p[4] = {-d.x, d.x, -d.y, d.y};
    const double q[4] = {a.x - r.u0, r.u1 - a.x, a.y - r.v0, r.v1 - a.y};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0.0) {
            if (q[i] < 0.0) return false;
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0.0)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
        if (t0 > t1) return false;
    }
    return true;
}

/// Where segment a-b crosses the line u = L (axis 0) or v = L (axis 1), computed from the
/// endpoints in a fixed order so both cells beside the line get the same bits.
glm::dvec2 crossing(glm::dvec2 a, glm::dvec2 b, int axis, double line) {
    if (b.x < a.x || (b.x == a.x && b.y < a.y)) std::swap(a, b);
    const int other = 1 - axis;
    const double t = (line - a[axis]) / (b[axis] - a[axis]);
    glm::dvec2 p;
    p[axis] = line;
    p[other] = a[other] + t * (b[other] - a[other]);
    return p;
}

bool onLine(glm::dvec2 p, const Rect& r, int line) {
    switch (line) {
    case 0:
        return p.x == r.u0;
    case 1:
        return p.x == r.u1;
    case 2:
        return p.y == r.v0;
    default:
        return p.y == r.v1;
    }
}

/// prev -> p -> next all lie on one side line of the rectangle: p adds nothing to the region.
bool removable(glm::dvec2 prev, glm::dvec2 p, glm::dvec2 next, const Rect& r) {
    for (int line = 0; line < 4; ++line)
        if (onLine(prev, r, line) && onLine(p, r, line) && onLine(next, r, line)) return true;
    return false;
}

/// The loop clamped into the rectangle, with its crossings of the rectangle's four lines
/// inserted first: inside the rectangle it winds around every point as the loop does (each
/// piece between crossings lies in one of the nine regions around the rectangle, where the
/// clamp is affine; points outside move to the nearest boundary point, never through the
/// inside). Runs along one side line are dropped.
std::vector<glm::dvec2> clampLoop(const std::vector<glm::dvec2>& loop, const Rect& r) {
    std::vector<glm::dvec2> points;
    points.reserve(loop.size() + 8);
    const double lines[4] = {r.u0, r.u1, r.v0, r.v1};
    const std::size_t n = loop.size();
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2 a = loop[i], b = loop[(i + 1) % n];
        points.push_back(a);
        std::array<std::pair<double, glm::dvec2>, 4> hits;
        int count = 0;
        for (int line = 0; line < 4; ++line) {
            const int axis = line / 2;
            const double da = a[axis] - lines[line], db = b[axis] - lines[line];
            if (!((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0))) continue;
            const glm::dvec2 p = crossing(a, b, axis, lines[line]);
            hits[std::size_t(count++)] = {da / (da - db), p};
        }
        for (int k = 1; k < count; ++k) // at most four: an insertion sort
            for (int m = k; m > 0 && hits[std::size_t(m)].first < hits[std::size_t(m - 1)].first;
                 --m)
                std::swap(hits[std::size_t(m)], hits[std::size_t(m - 1)]);
        for (int k = 0; k < count; ++k)
            points.push_back(hits[std::size_t(k)].second);
    }
    std::vector<glm::dvec2> out;
    out.reserve(points.size());
    for (glm::dvec2 p : points) {
        p = {std::clamp(p.x, r.u0, r.u1), std::clamp(p.y, r.v0, r.v1)};
        if (!out.empty() && out.back() == p) continue;
        while (out.size() >= 2 && removable(out[out.size() - 2], out.back(), p, r))
            out.pop_back();
        if (!out.empty() && out.back() == p) continue;
        out.push_back(p);
    }
    for (bool changed = true; changed && out.size() >= 3;) {
        changed = false;
        if (out.back() == out.front()) {
            out.pop_back();
            changed = true;
        } else if (removable(out[out.size() - 2], out.back(), out.front(), r)) {
            out.pop_back();
            changed = true;
        } else if (removable(out.back(), out[0], out[1], r)) {
            out.erase(out.begin());
            changed = true;
        }
    }
    if (out.size() < 3) out.clear();
    return out;
}

struct PointKey {
    std::uint64_t u, v;
    bool operator==(const PointKey&) const = default;
};
struct PointKeyHash {
    std::size_t operator()(const PointKey& k) const noexcept {
        return std::size_t(k.u * 0x9e3779b97f4a7c15ULL ^
                           (k.v + 0x7f4a7c159e3779b9ULL + (k.u << 6)));
    }
};
PointKey keyOf(glm::dvec2 p) {
    PointKey k{};
    std::memcpy(&k.u, &p.x, sizeof(double));
    std::memcpy(&k.v, &p.y, sizeof(double));
    return k;
}

/// The (u, v) samples of the mesh and its triangles over them, before evaluation.
struct DomainMesh {
    std::vector<glm::dvec2> uv;
    std::vector<std::uint32_t> triangles;
};

void gridTriangles(const std::vector<double>& us, const std::vector<double>& vs, DomainMesh& m) {
    const std::size_t nu = us.size(), nv = vs.size();
    m.uv.resize(nu * nv);
    for (std::size_t j = 0; j < nv; ++j)
        for (std::size_t i = 0; i < nu; ++i)
            m.uv[j * nu + i] = {us[i], vs[j]};
    m.triangles.reserve((nu - 1) * (nv - 1) * 6);
    for (std::size_t j = 0; j + 1 < nv; ++j)
        for (std::size_t i = 0; i + 1 < nu; ++i) {
            const auto a = std::uint32_t(j * nu + i), b = a + 1, c = std::uint32_t(a + nu),
                       d = c + 1;
            m.triangles.insert(m.triangles.end(), {a, b, d, a, d, c});
        }
}

/// The domain cells kept by the trim loops (GLU's rule: positive winding), triangulated: whole
/// cells no loop touches as two triangles, the others cut by the loops clamped into them.
void trimmedTriangles(const std::vector<double>& us, const std::vector<double>& vs,
                      std::span<const std::vector<glm::dvec2>> loops, DomainMesh& m) {
    const std::size_t cu = us.size() - 1, cv = vs.size() - 1, cells = cu * cv;
    struct Segment {
        glm::dvec2 a, b;
    };
    std::vector<Segment> segments;
    std::vector<Rect> loopBoxes;
    for (const auto& loop : loops) {
        Rect box{INFINITY, -INFINITY, INFINITY, -INFINITY};
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const glm::dvec2 a = loop[i], b = loop[(i + 1) % loop.size()];
            segments.push_back({a, b});
            box = {std::min(box.u0, a.x), std::max(box.u1, a.x), std::min(box.v0, a.y),
                   std::max(box.v1, a.y)};
        }
        loopBoxes.push_back(box);
    }
    constexpr std::size_t kMaxWork = std::size_t(1) << 27;
    if (segments.size() * cv > kMaxWork)
        throw Error("trimming " + std::to_string(segments.size()) + " trim segments over " +
                    std::to_string(cv) + " rows of samples exceeds the work limit");

    // Cells a loop edge touches.
    std::vector<std::uint8_t> touched(cells, 0);
    std::size_t work = 0;
    auto firstCell = [](const std::vector<double>& grid, double lo) {
        const auto it = std::lower_bound(grid.begin(), grid.end(), lo);
        return std::max<std::ptrdiff_t>(0, (it - grid.begin()) - 1);
    };
    auto lastCell = [](const std::vector<double>& grid, double hi) {
        const auto it = std::upper_bound(grid.begin(), grid.end(), hi);
        return std::min<std::ptrdiff_t>(std::ptrdiff_t(grid.size()) - 2, (it - grid.begin()) - 1);
    };
    for (const Segment& s : segments) {
        const double ulo = std::min(s.a.x, s.b.x), uhi = std::max(s.a.x, s.b.x);
        const double vlo = std::min(s.a.y, s.b.y), vhi = std::max(s.a.y, s.b.y);
        if (uhi < us.front() || ulo > us.back() || vhi < vs.front() || vlo > vs.back()) continue;
        const std::ptrdiff_t i0 = firstCell(us, ulo), i1 = lastCell(us, uhi);
        const std::ptrdiff_t j0 = firstCell(vs, vlo), j1 = lastCell(vs, vhi);
        if (i1 < i0 || j1 < j0) continue;
        work += std::size_t(i1 - i0 + 1) * std::size_t(j1 - j0 + 1);
        if (work > kMaxWork) throw Error("trimming exceeds the work limit (long trim edges)");
        for (std::ptrdiff_t j = j0; j <= j1; ++j)
            for (std::ptrdiff_t i = i0; i <= i1; ++i) {
                const Rect r{us[std::size_t(i)], us[std::size_t(i) + 1], vs[std::size_t(j)],
                             vs[std::size_t(j) + 1]};
                if (segmentMeetsRect(s.a, s.b, r))
                    touched[std::size_t(j) * cu + std::size_t(i)] = 1;
            }
    }

    const std::size_t nu = us.size();
    std::vector<std::int64_t> gridIndex(us.size() * vs.size(), -1);
    auto gridVertex = [&](std::size_t i, std::size_t j) {
        std::int64_t& index = gridIndex[j * nu + i];
        if (index < 0) {
            index = std::int64_t(m.uv.size());
            m.uv.emplace_back(us[i], vs[j]);
        }
        return std::uint32_t(index);
    };
    std::unordered_map<PointKey, std::uint32_t, PointKeyHash> cutVertices;

    std::vector<std::pair<double, int>> crossings;
    std::vector<std::vector<glm::dvec2>> contours;
    Triangulation t;
    for (std::size_t j = 0; j < cv; ++j) {
        // Winding numbers at the cell centres of this row: crossings of the centre line to the
        // right of each centre, upwards +1, downwards -1.
        const double vc = 0.5 * (vs[j] + vs[j + 1]);
        crossings.clear();
        for (const Segment& s : segments) {
            const bool up = s.a.y <= vc && s.b.y > vc, down = s.b.y <= vc && s.a.y > vc;
            if (!up && !down) continue;
            const double u = s.a.x + (vc - s.a.y) / (s.b.y - s.a.y) * (s.b.x - s.a.x);
            crossings.emplace_back(u, up ? 1 : -1);
        }
        std::sort(crossings.begin(), crossings.end());
        int winding = 0;
        for (const auto& c : crossings)
            winding += c.second;
        std::size_t next = 0; // crossings left of the centre are subtracted as we pass them
        for (std::size_t i = 0; i < cu; ++i) {
            const double uc = 0.5 * (us[i] + us[i + 1]);
            while (next < crossings.size() && crossings[next].first <= uc)
                winding -= crossings[next++].second;
            const Rect r{us[i], us[i + 1], vs[j], vs[j + 1]};
            if (!touched[j * cu + i]) {
                if (winding <= 0) continue;
                const std::uint32_t a = gridVertex(i, j), b = gridVertex(i + 1, j),
                                    c = gridVertex(i, j + 1), d = gridVertex(i + 1, j + 1);
                m.triangles.insert(m.triangles.end(), {a, b, d, a, d, c});
                continue;
            }
            contours.clear();
            for (std::size_t l = 0; l < loops.size(); ++l) {
                const Rect& box = loopBoxes[l];
                if (box.u1 < r.u0 || box.u0 > r.u1 || box.v1 < r.v0 || box.v0 > r.v1) continue;
                auto clamped = clampLoop(loops[l], r);
                if (!clamped.empty()) contours.push_back(std::move(clamped));
            }
            if (contours.empty()) continue;
            if (!triangulatePolygons(contours, WindingRule::Positive, t)) continue;
            std::vector<std::uint32_t> ids(t.points.size());
            for (std::size_t k = 0; k < t.points.size(); ++k) {
                const glm::dvec2 p = t.points[k];
                const bool atU0 = p.x == r.u0, atU1 = p.x == r.u1;
                const bool atV0 = p.y == r.v0, atV1 = p.y == r.v1;
                if ((atU0 || atU1) && (atV0 || atV1)) {
                    ids[k] = gridVertex(atU0 ? i : i + 1, atV0 ? j : j + 1);
                    continue;
                }
                const auto [it, added] =
                    cutVertices.try_emplace(keyOf(p), std::uint32_t(m.uv.size()));
                if (added) m.uv.push_back(p);
                ids[k] = it->second;
            }
            for (const std::uint32_t k : t.triangles)
                m.triangles.push_back(ids[k]);
        }
    }
}

glm::dvec2 mapToDomain(double u, double v, const NurbsSurfaceData& from,
                       const NurbsSurfaceData& to) {
    auto map = [](double x, std::span<const float> a, int orderA, int countA,
                  std::span<const float> b, int orderB, int countB) {
        const double a0 = a[std::size_t(orderA - 1)], a1 = a[std::size_t(countA)];
        const double b0 = b[std::size_t(orderB - 1)], b1 = b[std::size_t(countB)];
        return a1 > a0 ? b0 + (x - a0) / (a1 - a0) * (b1 - b0) : b0;
    };
    return {map(u, from.knotsU, from.orderU, from.countU, to.knotsU, to.orderU, to.countU),
            map(v, from.knotsV, from.orderV, from.countV, to.knotsV, to.orderV, to.countV)};
}

} // namespace

std::string nurbsKnotProblem(std::int64_t numControlPoints, std::span<const float> knots) {
    if (numControlPoints < 2)
        return std::to_string(numControlPoints) + " control points (at least 2 are needed)";
    const std::int64_t order = std::int64_t(knots.size()) - numControlPoints;
    if (order < 2 || order > kMaxNurbsOrder)
        return std::to_string(knots.size()) + " knots for " + std::to_string(numControlPoints) +
               " control points give order " + std::to_string(order) + " (2 to " +
               std::to_string(kMaxNurbsOrder) + " drawn)";
    for (std::size_t i = 0; i < knots.size(); ++i) {
        if (!std::isfinite(knots[i])) return "knot " + std::to_string(i) + " is not finite";
        if (i > 0 && knots[i] < knots[i - 1]) return "knot " + std::to_string(i) + " decreases";
    }
    if (!(knots[std::size_t(order - 1)] < knots[std::size_t(numControlPoints)]))
        return "the knots leave an empty domain";
    return {};
}

namespace {

/// Evaluates many points of one curve with its knots converted once.
class CurveEvaluator {
public:
    explicit CurveEvaluator(const NurbsCurveData& c) : c_(c), knots_(toDouble(c.knots)) {}

    glm::dvec4 operator()(double u) const {
        const int count = int(c_.points.size()), degree = c_.order - 1;
        u = std::clamp(u, knots_[std::size_t(degree)], knots_[std::size_t(count)]);
        const int span = findSpan(count, degree, u, knots_);
        Basis b;
        basisFunctions(span, degree, u, knots_, b);
        glm::dvec4 sum(0.0);
        for (int r = 0; r <= degree; ++r)
            sum += b.value[std::size_t(r)] * c_.points[std::size_t(span - degree + r)];
        return sum;
    }

private:
    const NurbsCurveData& c_;
    std::vector<double> knots_;
};

} // namespace

glm::dvec4 evaluateNurbsCurve(const NurbsCurveData& curve, double u) {
    return CurveEvaluator(curve)(u);
}

namespace {

/// Evaluates many points of one surface with its knots converted once.
class SurfaceEvaluator {
public:
    explicit SurfaceEvaluator(const NurbsSurfaceData& s)
        : s_(s), ku_(toDouble(s.knotsU)), kv_(toDouble(s.knotsV)) {}

    NurbsSurfacePoint operator()(double u, double v) const {
        const int pu = s_.orderU - 1, pv = s_.orderV - 1;
        u = std::clamp(u, ku_[std::size_t(pu)], ku_[std::size_t(s_.countU)]);
        v = std::clamp(v, kv_[std::size_t(pv)], kv_[std::size_t(s_.countV)]);
        const int su = findSpan(s_.countU, pu, u, ku_), sv = findSpan(s_.countV, pv, v, kv_);
        Basis bu, bv;
        basisFunctions(su, pu, u, ku_, bu);
        basisFunctions(sv, pv, v, kv_, bv);
        glm::dvec4 S(0.0), Su(0.0), Sv(0.0);
        for (int l = 0; l <= pv; ++l) {
            glm::dvec4 row(0.0), rowDu(0.0);
            const std::size_t base = std::size_t(sv - pv + l) * std::size_t(s_.countU);
            for (int k = 0; k <= pu; ++k) {
                const glm::dvec4& P = s_.points[base + std::size_t(su - pu + k)];
                row += bu.value[std::size_t(k)] * P;
                rowDu += bu.derivative[std::size_t(k)] * P;
            }
            S += bv.value[std::size_t(l)] * row;
            Su += bv.value[std::size_t(l)] * rowDu;
            Sv += bv.derivative[std::size_t(l)] * row;
        }
        NurbsSurfacePoint out;
        out.w = S.w;
        if (!(S.w > 0.0)) return out;
        const glm::dvec3 p = glm::dvec3(S) / S.w;
        const glm::dvec3 du = (glm::dvec3(Su) - Su.w * p) / S.w;
        const glm::dvec3 dv = (glm::dvec3(Sv) - Sv.w * p) / S.w;
        out.position = p;
        const glm::dvec3 n = glm::cross(du, dv);
        const double len = glm::length(n);
        // A normal shorter than this against its tangents is a degenerate point (a pole).
        if (len > 1e-12 * glm::length(du) * glm::length(dv) && len > 0.0 && std::isfinite(len))
            out.normal = n / len;
        return out;
    }

private:
    const NurbsSurfaceData& s_;
    std::vector<double> ku_, kv_;
};

} // namespace

NurbsSurfacePoint evaluateNurbsSurface(const NurbsSurfaceData& surface, double u, double v) {
    return SurfaceEvaluator(surface)(u, v);
}

double nurbsSurfaceRate(int count, int numKnots, bool closed, double knotRange, float complexity) {
    const int s = surfaceSteps(complexity);
    const bool linear = count == 2 && numKnots == 4;
    const int steps = linear ? 1 : closed ? s * 4 : (count < 4 ? 1 : count - 3) * s + 1;
    // Coin truncates steps / range to an integer rate; GLU takes a rate below 1 as one step per
    // knot span.
    return knotRange > 0.0 ? std::floor(steps / knotRange) : 0.0;
}

double nurbsCurveRate(int count, bool closed, double knotRange, float complexity) {
    const int steps = closed ? surfaceSteps(complexity) * 4 - 1
                             : (count < 4 ? 1 : count - 3) * curveSteps(complexity);
    return knotRange > 0.0 ? std::floor(std::max(1, steps) / knotRange) : 0.0;
}

std::vector<double> nurbsSampleParameters(std::span<const float> knots, int order, double rate,
                                          std::size_t limit) {
    const int count = int(knots.size()) - order;
    const double lo = knots[std::size_t(order - 1)];
    if (!(rate > 0.0) || !std::isfinite(rate)) rate = 0.0; // one step per span
    // Count first, so an absurd rate is refused before anything is allocated.
    std::size_t total = 1;
    for (int k = order - 1; k < count; ++k) {
        const double a = knots[std::size_t(k)], b = knots[std::size_t(k) + 1];
        if (!(b > a)) continue;
        const double steps = std::max(1.0, std::ceil(rate * (b - a) - 1e-9));
        if (steps > double(limit)) throw Error("more than " + std::to_string(limit) + " samples");
        total += std::size_t(steps);
        if (total > limit) throw Error("more than " + std::to_string(limit) + " samples");
    }
    std::vector<double> out;
    out.reserve(total);
    out.push_back(lo);
    for (int k = order - 1; k < count; ++k) {
        const double a = knots[std::size_t(k)], b = knots[std::size_t(k) + 1];
        if (!(b > a)) continue;
        const auto steps = std::size_t(std::max(1.0, std::ceil(rate * (b - a) - 1e-9)));
        for (std::size_t i = 1; i < steps; ++i)
            out.push_back(a + (b - a) * double(i) / double(steps));
        out.push_back(b);
    }
    return out;
}

void buildNurbsSurfaceMesh(const NurbsSurfaceData& surface, const NurbsSurfaceMeshOptions& options,
                           Mesh& out) {
    out = Mesh{};
    const std::vector<double> us =
        nurbsSampleParameters(surface.knotsU, surface.orderU, options.rateU, options.maxSamples);
    const std::vector<double> vs =
        nurbsSampleParameters(surface.knotsV, surface.orderV, options.rateV, options.maxSamples);
    if (us.size() < 2 || vs.size() < 2) return;
    if (us.size() * vs.size() > options.maxSamples)
        throw Error("a tessellation of " + std::to_string(us.size()) + " x " +
                    std::to_string(vs.size()) + " samples exceeds the limit of " +
                    std::to_string(options.maxSamples));

    DomainMesh domain;
    if (options.trimLoops.empty())
        gridTriangles(us, vs, domain);
    else
        trimmedTriangles(us, vs, options.trimLoops, domain);
    if (domain.triangles.empty()) return;

    const SurfaceEvaluator evaluate(surface);
    const std::size_t n = domain.uv.size();
    out.positions.resize(n);
    out.normals.resize(n);
    std::vector<std::uint8_t> degenerate(n, 0);
    for (std::size_t k = 0; k < n; ++k) {
        const NurbsSurfacePoint p = evaluate(domain.uv[k].x, domain.uv[k].y);
        if (!(p.w > 0.0) || !std::isfinite(p.position.x) || !std::isfinite(p.position.y) ||
            !std::isfinite(p.position.z)) {
            out = Mesh{}; // a weight that is not positive: no finite surface to draw
            return;
        }
        out.positions[k] = glm::vec3(p.position);
        out.normals[k] = glm::vec3(p.normal);
        degenerate[k] = p.normal == glm::dvec3(0.0);
    }
    out.indices = std::move(domain.triangles);

    // Degenerate points (poles) take the normals of the triangles around them.
    std::vector<glm::dvec3> sums;
    for (std::size_t t = 0; t + 2 < out.indices.size(); t += 3) {
        const std::uint32_t a = out.indices[t], b = out.indices[t + 1], c = out.indices[t + 2];
        if (!degenerate[a] && !degenerate[b] && !degenerate[c]) continue;
        if (sums.empty()) sums.assign(n, glm::dvec3(0.0));
        const glm::dvec3 pa(out.positions[a]), pb(out.positions[b]), pc(out.positions[c]);
        const glm::dvec3 face = glm::cross(pb - pa, pc - pa);
        for (const std::uint32_t v : {a, b, c})
            if (degenerate[v]) sums[v] += face;
    }
    for (std::size_t k = 0; k < sums.size(); ++k)
        if (degenerate[k] && glm::length(sums[k]) > 0.0)
            out.normals[k] = glm::vec3(glm::normalize(sums[k]));

    if (options.texCoords == NurbsSurfaceMeshOptions::TexCoords::Default) {
        const double u0 = *std::min_element(surface.knotsU.begin(), surface.knotsU.end());
        const double u1 = *std::max_element(surface.knotsU.begin(), surface.knotsU.end());
        const double v0 = *std::min_element(surface.knotsV.begin(), surface.knotsV.end());
        const double v1 = *std::max_element(surface.knotsV.begin(), surface.knotsV.end());
        out.texCoords.resize(n);
        for (std::size_t k = 0; k < n; ++k)
            out.texCoords[k] =
                glm::vec2((domain.uv[k].x - u0) / (u1 - u0), (domain.uv[k].y - v0) / (v1 - v0));
    } else if (options.texCoords == NurbsSurfaceMeshOptions::TexCoords::Surface &&
               options.texture) {
        const SurfaceEvaluator texture(*options.texture);
        out.texCoords.resize(n);
        for (std::size_t k = 0; k < n; ++k) {
            const glm::dvec2 st =
                mapToDomain(domain.uv[k].x, domain.uv[k].y, surface, *options.texture);
            const NurbsSurfacePoint p = texture(st.x, st.y);
            out.texCoords[k] = glm::vec2(p.position);
        }
    }
}

void buildNurbsCurveMesh(const NurbsCurveData& curve, double rate, std::size_t maxSamples,
                         Mesh& out) {
    out = Mesh{};
    out.primitive = Mesh::Primitive::Lines;
    const std::vector<double> us =
        nurbsSampleParameters(curve.knots, curve.order, rate, maxSamples);
    out.positions.reserve(us.size());
    const CurveEvaluator evaluate(curve);
    for (const double u : us) {
        const glm::dvec4 h = evaluate(u);
        const glm::dvec3 p = glm::dvec3(h) / h.w;
        if (!(h.w > 0.0) || !std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            out = Mesh{};
            out.primitive = Mesh::Primitive::Lines;
            return;
        }
        out.positions.emplace_back(p);
    }
    for (std::uint32_t i = 0; i + 1 < out.positions.size(); ++i)
        out.indices.insert(out.indices.end(), {i, i + 1});
}

std::vector<glm::dvec2> sampleNurbsCurve2D(const NurbsCurveData& curve, double rate,
                                           std::size_t maxSamples) {
    const std::vector<double> us =
        nurbsSampleParameters(curve.knots, curve.order, rate, maxSamples);
    std::vector<glm::dvec2> out;
    out.reserve(us.size());
    const CurveEvaluator evaluate(curve);
    for (const double u : us) {
        const glm::dvec4 h = evaluate(u);
        if (!(h.w > 0.0)) return {};
        out.emplace_back(h.x / h.w, h.y / h.w);
    }
    return out;
}

} // namespace volsg
