// NURBS curves and surfaces: control points, knots and trim loops gathered from the fields
// and the state, tessellated by lib/volsg/geometry/Nurbs.
#include <volsg/nodes/NurbsCurve.h>
#include <volsg/nodes/NurbsSurface.h>

#include <cmath>
#include <optional>
#include <string>

#include <volsg/core/Error.h>
#include <volsg/geometry/MeshKey.h>
#include <volsg/geometry/Nurbs.h>
#include <volsg/nodes/Coordinate3.h>
#include <volsg/nodes/Coordinate4.h>
#include <volsg/nodes/NodeNames.h>
#include <volsg/nodes/Profile.h>
#include <volsg/nodes/ShapeState.h>
#include <volsg/nodes/TextureCoordinate2.h>
#include <volsg/nodes/TextureCoordinatePlane.h>
#include <volsg/nodes/VertexProperty.h>
#include <volsg/state/State.h>

namespace volsg {

namespace {

/// Most samples (parameter grid points) one surface or curve is tessellated into.
constexpr std::size_t kMaxNurbsSamples = std::size_t(1) << 21;

[[noreturn]] void fail(const Node& node, const std::string& message) {
    throw Error(describeNode(node) + ": " + message);
}

/// The homogeneous control points in scope: Coordinate3 and VertexProperty points with weight
/// 1, Coordinate4 as it is.
std::vector<glm::dvec4> controlPoints(const Node& node, const ShapeState& scope) {
    std::vector<glm::dvec4> out;
    const Node* c = scope.coordinates;
    if (!c) return out;
    if (c->isA<Coordinate4>()) {
        const auto& p = static_cast<const Coordinate4*>(c)->point.getValues();
        out.assign(p.begin(), p.end());
    } else {
        const std::vector<glm::vec3>* p = nullptr;
        if (c->isA<Coordinate3>())
            p = &static_cast<const Coordinate3*>(c)->point.getValues();
        else if (c->isA<VertexProperty>())
            p = &static_cast<const VertexProperty*>(c)->vertex.getValues();
        if (p) {
            out.reserve(p->size());
            for (const glm::vec3& v : *p)
                out.emplace_back(glm::dvec3(v), 1.0);
        }
    }
    for (std::size_t i = 0; i < out.size(); ++i)
        for (int k = 0; k < 4; ++k)
            if (!std::isfinite(out[i][k]))
                fail(node, "control point " + std::to_string(i) + " is not a finite number");
    return out;
}

/// `count` points of `all`, in order or through `indices` (when given); nothing when there
/// are too few or an index is out of range.
std::optional<std::vector<glm::dvec4>> select(const std::vector<glm::dvec4>& all,
                                              std::int64_t count,
                                              const std::vector<std::int32_t>* indices) {
    if (count <= 0) return std::nullopt;
    const std::size_t n = std::size_t(count);
    if (!indices) {
        if (all.size() < n) return std::nullopt;
        return std::vector<glm::dvec4>(all.begin(), all.begin() + std::ptrdiff_t(n));
    }
    if (indices->size() < n) return std::nullopt;
    std::vector<glm::dvec4> out;
    out.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        const std::int32_t k = (*indices)[i];
        if (k < 0 || std::size_t(k) >= all.size()) return std::nullopt;
        out.push_back(all[std::size_t(k)]);
    }
    return out;
}

/// Non-finite knots are an error; other knot problems leave the shape undrawn.
bool knotsUsable(const Node& node, const char* field, std::int64_t count,
                 const std::vector<float>& knots) {
    for (std::size_t i = 0; i < knots.size(); ++i)
        if (!std::isfinite(knots[i]))
            fail(node,
                 std::string(field) + " value " + std::to_string(i) + " is not a finite number");
    return nurbsKnotProblem(count, knots).empty();
}

void buildCurve(const Node& node, const State& state, std::int32_t count,
                const std::vector<float>& knots, const std::vector<std::int32_t>* indices,
                Mesh& out) {
    out = Mesh{};
    out.primitive = Mesh::Primitive::Lines;
    const ShapeState scope = gatherShapeState(state, nullptr);
    const std::vector<glm::dvec4> all = controlPoints(node, scope);
    if (!knotsUsable(node, "knotVector", count, knots)) return;
    const auto points = select(all, count, indices);
    if (!points) return;
    NurbsCurveData curve;
    curve.order = int(knots.size()) - count;
    curve.knots = knots;
    curve.points = *points;
    const bool closed = points->front() == points->back();
    const double rate = nurbsCurveRate(count, closed, double(knots.back()) - double(knots.front()),
                                       scope.complexityValue());
    try {
        buildNurbsCurveMesh(curve, rate, kMaxNurbsSamples, out);
    } catch (const Error& e) {
        fail(node, e.message());
    }
}

struct SurfaceFields {
    std::int32_t numU = 0, numV = 0, numS = 0, numT = 0;
    const std::vector<float>*knotsU = nullptr, *knotsV = nullptr, *knotsS = nullptr,
          *knotsT = nullptr;
    const std::vector<std::int32_t>* coordIndex = nullptr;   ///< null: points in order
    const std::vector<std::int32_t>* textureIndex = nullptr; ///< null: in order
};

void buildSurface(const Node& node, const State& state, const SurfaceFields& f, Mesh& out) {
    out = Mesh{};
    const ShapeState scope = gatherShapeState(state, nullptr);
    const std::vector<glm::dvec4> all = controlPoints(node, scope);
    if (!knotsUsable(node, "uKnotVector", f.numU, *f.knotsU) ||
        !knotsUsable(node, "vKnotVector", f.numV, *f.knotsV))
        return;
    const auto points = select(all, std::int64_t(f.numU) * std::int64_t(f.numV), f.coordIndex);
    if (!points) return;

    NurbsSurfaceData surface;
    surface.countU = f.numU;
    surface.countV = f.numV;
    surface.orderU = int(f.knotsU->size()) - f.numU;
    surface.orderV = int(f.knotsV->size()) - f.numV;
    surface.knotsU = *f.knotsU;
    surface.knotsV = *f.knotsV;
    surface.points = *points;

    // Coin's sampling: closed when the first and last control points agree (in u along the
    // first row, in v for the whole first and last rows).
    const auto& p = *points;
    const std::size_t nu = std::size_t(f.numU), nv = std::size_t(f.numV);
    const bool closedU = p.front() == p[nu - 1];
    bool closedV = true;
    for (std::size_t i = 0; i < nu && closedV; ++i)
        closedV = p[i] == p[(nv - 1) * nu + i];
    const float complexity = scope.complexityValue();
    NurbsSurfaceMeshOptions options;
    options.maxSamples = kMaxNurbsSamples;
    options.rateU =
        nurbsSurfaceRate(f.numU, int(f.knotsU->size()), closedU,
                         double(f.knotsU->back()) - double(f.knotsU->front()), complexity);
    options.rateV =
        nurbsSurfaceRate(f.numV, int(f.knotsV->size()), closedV,
                         double(f.knotsV->back()) - double(f.knotsV->front()), complexity);

    // The profiles in scope trim the surface: GLU keeps what the loops wind around.
    TrimLoops trims;
    const ProfilesInScope profiles = gatherProfiles(state);
    if (!profiles.profiles.empty()) {
        try {
            trims = trimLoops(profiles, complexity);
        } catch (const Error& e) {
            fail(node, e.message());
        }
        if (!trims.ok || trims.loops.empty()) return;
        options.trimLoops = trims.loops;
    }

    // Texture coordinates, only when a texture is in scope.
    NurbsSurfaceData texture;
    std::vector<glm::dvec4> texturePoints;
    const TextureCoordinatePlane* plane = nullptr;
    if (scope.textured()) {
        options.texCoords = NurbsSurfaceMeshOptions::TexCoords::Default;
        if (scope.textureCoords && scope.textureCoords->isA<TextureCoordinatePlane>()) {
            plane = static_cast<const TextureCoordinatePlane*>(scope.textureCoords);
            options.texCoords = NurbsSurfaceMeshOptions::TexCoords::None;
        } else if (scope.textureCoords && scope.textureCoords->isA<TextureCoordinate2>() &&
                   f.numS > 0 && f.numT > 0 &&
                   knotsUsable(node, "sKnotVector", f.numS, *f.knotsS) &&
                   knotsUsable(node, "tKnotVector", f.numT, *f.knotsT)) {
            const auto& tc =
                static_cast<const TextureCoordinate2*>(scope.textureCoords)->point.getValues();
            std::vector<glm::dvec4> allTc;
            allTc.reserve(tc.size());
            for (const glm::vec2& t : tc)
                allTc.emplace_back(t.x, t.y, 0.0, 1.0);
            if (auto chosen =
                    select(allTc, std::int64_t(f.numS) * std::int64_t(f.numT), f.textureIndex)) {
                texturePoints = std::move(*chosen);
                texture.countU = f.numS;
                texture.countV = f.numT;
                texture.orderU = int(f.knotsS->size()) - f.numS;
                texture.orderV = int(f.knotsT->size()) - f.numT;
                texture.knotsU = *f.knotsS;
                texture.knotsV = *f.knotsT;
                texture.points = texturePoints;
                options.texCoords = NurbsSurfaceMeshOptions::TexCoords::Surface;
                options.texture = &texture;
            }
        }
    }

    try {
        buildNurbsSurfaceMesh(surface, options, out);
    } catch (const Error& e) {
        fail(node, e.message());
    }
    if (plane && !out.positions.empty()) {
        out.texCoords.resize(out.positions.size());
        for (std::size_t k = 0; k < out.positions.size(); ++k)
            out.texCoords[k] = {glm::dot(plane->directionS(), out.positions[k]),
                                glm::dot(plane->directionT(), out.positions[k])};
    }
}

/// textureCoordIndex [-1] (or empty) means the texture points in order.
const std::vector<std::int32_t>* indicesInUse(const std::vector<std::int32_t>& indices) {
    if (indices.empty() || (indices.size() == 1 && indices[0] < 0)) return nullptr;
    return &indices;
}

} // namespace

void NurbsCurve::buildMesh(const State& state, Mesh& out) const {
    buildCurve(*this, state, numControlPoints(), knotVector.getValues(), nullptr, out);
}

void IndexedNurbsCurve::buildMesh(const State& state, Mesh& out) const {
    buildCurve(*this, state, numControlPoints(), knotVector.getValues(), &coordIndex.getValues(),
               out);
}

std::uint64_t NurbsSurface::meshKey(const State& state) const {
    return combineMeshKey(Shape::meshKey(state), gatherProfiles(state).key());
}

void NurbsSurface::buildMesh(const State& state, Mesh& out) const {
    SurfaceFields f;
    f.numU = numUControlPoints();
    f.numV = numVControlPoints();
    f.numS = numSControlPoints();
    f.numT = numTControlPoints();
    f.knotsU = &uKnotVector.getValues();
    f.knotsV = &vKnotVector.getValues();
    f.knotsS = &sKnotVector.getValues();
    f.knotsT = &tKnotVector.getValues();
    buildSurface(*this, state, f, out);
}

std::uint64_t IndexedNurbsSurface::meshKey(const State& state) const {
    return combineMeshKey(Shape::meshKey(state), gatherProfiles(state).key());
}

void IndexedNurbsSurface::buildMesh(const State& state, Mesh& out) const {
    SurfaceFields f;
    f.numU = numUControlPoints();
    f.numV = numVControlPoints();
    f.numS = numSControlPoints();
    f.numT = numTControlPoints();
    f.knotsU = &uKnotVector.getValues();
    f.knotsV = &vKnotVector.getValues();
    f.knotsS = &sKnotVector.getValues();
    f.knotsT = &tKnotVector.getValues();
    f.coordIndex = &coordIndex.getValues();
    f.textureIndex = indicesInUse(textureCoordIndex.getValues());
    buildSurface(*this, state, f, out);
}

} // namespace volsg
