// GLU's polygon tessellator (libtess) through its data callbacks. Only GLU's header is
// included here (it brings GL/gl.h for the types): nothing in this file calls GL.
#include <volsg/geometry/PolygonTessellator.h>

#include <GL/glu.h>

#include <array>
#include <cmath>
#include <deque>
#include <memory>
#include <string>

#include <volsg/core/Error.h>

namespace volsg {

namespace {

struct TessData {
    Triangulation* out = nullptr;
    std::deque<std::uint32_t> ids; ///< stable addresses: the tessellator keeps pointers to them
    std::vector<std::uint32_t> current;
    bool failed = false;
};

void GLAPIENTRY onBegin(GLenum, void*) {}

void GLAPIENTRY onVertex(void* vertex, void* data) {
    static_cast<TessData*>(data)->current.push_back(*static_cast<std::uint32_t*>(vertex));
}

void GLAPIENTRY onEnd(void* data) {
    auto& d = *static_cast<TessData*>(data);
    // With an edge-flag callback set, the tessellator emits GL_TRIANGLES only.
    const std::size_t n = d.current.size() - d.current.size() % 3;
    for (std::size_t i = 0; i < n; i += 3) {
        const std::uint32_t a = d.current[i], b = d.current[i + 1], c = d.current[i + 2];
        const glm::dvec2 pa = d.out->points[a], pb = d.out->points[b], pc = d.out->points[c];
        const double area = (pb.x - pa.x) * (pc.y - pa.y) - (pc.x - pa.x) * (pb.y - pa.y);
        if (area > 0.0)
            d.out->triangles.insert(d.out->triangles.end(), {a, b, c});
        else if (area < 0.0)
            d.out->triangles.insert(d.out->triangles.end(), {a, c, b});
    }
    d.current.clear();
}

void GLAPIENTRY onEdgeFlag(GLboolean, void*) {}

void GLAPIENTRY onCombine(GLdouble coords[3], void* [4], GLfloat[4], void** outData, void* data) {
    auto& d = *static_cast<TessData*>(data);
    const auto id = static_cast<std::uint32_t>(d.out->points.size());
    d.out->points.emplace_back(coords[0], coords[1]);
    d.ids.push_back(id);
    *outData = &d.ids.back();
}

void GLAPIENTRY onError(GLenum, void* data) {
    static_cast<TessData*>(data)->failed = true;
}

GLdouble ruleOf(WindingRule rule) {
    switch (rule) {
    case WindingRule::Odd:
        return GLU_TESS_WINDING_ODD;
    case WindingRule::NonZero:
        return GLU_TESS_WINDING_NONZERO;
    case WindingRule::Positive:
        return GLU_TESS_WINDING_POSITIVE;
    case WindingRule::Negative:
        return GLU_TESS_WINDING_NEGATIVE;
    case WindingRule::AbsGeqTwo:
        return GLU_TESS_WINDING_ABS_GEQ_TWO;
    }
    return GLU_TESS_WINDING_ODD;
}

struct TessDeleter {
    void operator()(GLUtesselator* t) const { gluDeleteTess(t); }
};

} // namespace

double twiceSignedArea(std::span<const glm::dvec2> polygon) {
    double sum = 0.0;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2 a = polygon[i], b = polygon[(i + 1) % n];
        sum += a.x * b.y - b.x * a.y;
    }
    return sum;
}

bool triangulatePolygons(std::span<const std::vector<glm::dvec2>> contours, WindingRule rule,
                         Triangulation& out, std::size_t maxPoints) {
    out.points.clear();
    out.triangles.clear();
    std::size_t total = 0;
    for (const auto& c : contours)
        total += c.size();
    if (total > maxPoints)
        throw Error("polygon of " + std::to_string(total) + " points exceeds the limit of " +
                    std::to_string(maxPoints) + " points");
    for (const auto& c : contours)
        for (const glm::dvec2& p : c)
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || std::abs(p.x) > 1e100 ||
                std::abs(p.y) > 1e100)
                return false;
    if (total < 3) return true;

    std::unique_ptr<GLUtesselator, TessDeleter> tess(gluNewTess());
    if (!tess) throw Error("GLU could not make a polygon tessellator");
    using Callback = _GLUfuncptr;
    gluTessCallback(tess.get(), GLU_TESS_BEGIN_DATA, reinterpret_cast<Callback>(&onBegin));
    gluTessCallback(tess.get(), GLU_TESS_VERTEX_DATA, reinterpret_cast<Callback>(&onVertex));
    gluTessCallback(tess.get(), GLU_TESS_END_DATA, reinterpret_cast<Callback>(&onEnd));
    gluTessCallback(tess.get(), GLU_TESS_EDGE_FLAG_DATA, reinterpret_cast<Callback>(&onEdgeFlag));
    gluTessCallback(tess.get(), GLU_TESS_COMBINE_DATA, reinterpret_cast<Callback>(&onCombine));
    gluTessCallback(tess.get(), GLU_TESS_ERROR_DATA, reinterpret_cast<Callback>(&onError));
    gluTessProperty(tess.get(), GLU_TESS_WINDING_RULE, ruleOf(rule));
    gluTessNormal(tess.get(), 0.0, 0.0, 1.0);

    TessData data;
    data.out = &out;
    out.points.reserve(total + total / 4);
    std::vector<std::array<GLdouble, 3>> coords(total);
    std::size_t k = 0;
    gluTessBeginPolygon(tess.get(), &data);
    for (const auto& contour : contours) {
        if (contour.empty()) continue;
        gluTessBeginContour(tess.get());
        for (const glm::dvec2& p : contour) {
            coords[k] = {p.x, p.y, 0.0};
            out.points.push_back(p);
            data.ids.push_back(static_cast<std::uint32_t>(k));
            gluTessVertex(tess.get(), coords[k].data(), &data.ids.back());
            ++k;
        }
        gluTessEndContour(tess.get());
    }
    gluTessEndPolygon(tess.get());
    if (data.failed) {
        out.points.clear();
        out.triangles.clear();
        return false;
    }
    return true;
}

} // namespace volsg
