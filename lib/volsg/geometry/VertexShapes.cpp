#include <volsg/geometry/VertexShapes.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>

namespace volsg {

namespace {

bool validIndex(std::int64_t i, std::size_t count) {
    return i >= 0 && static_cast<std::uint64_t>(i) < count;
}

/// A count field's entries: -1 takes the rest of the points; other negative counts are left
/// out; counts past the points are cut at them.
template <class Visit>
void forEachCounted(std::span<const std::int32_t> counts, std::int32_t startIndex,
                    std::size_t pointCount, Visit&& visit) {
    std::int64_t next = std::max(startIndex, 0);
    for (std::int32_t n : counts) {
        if (next >= std::int64_t(pointCount)) return;
        const std::int64_t count = n == -1 ? std::int64_t(pointCount) - next : n;
        if (count < 0) continue;
        const std::int64_t end = std::min<std::int64_t>(next + count, std::int64_t(pointCount));
        visit(next, end);
        next = end;
    }
}

/// forEachCounted with each run's corners made: a non-indexed shape's vertex k is its point
/// startIndex + k. `visit` gets the run's corners.
template <class Visit>
void forEachCountedRun(std::span<const std::int32_t> counts, std::int32_t startIndex,
                       std::size_t pointCount, Visit&& visit) {
    std::vector<Corner> corners;
    forEachCounted(counts, startIndex, pointCount, [&](std::int64_t begin, std::int64_t end) {
        corners.clear();
        for (std::int64_t i = begin; i < end; ++i) {
            const auto vertex = std::uint32_t(i - std::max(startIndex, 0));
            corners.push_back({std::int32_t(i), vertex, vertex});
        }
        visit(std::span<const Corner>(corners));
    });
}

/// Runs of an index field split at -1 (a trailing run without -1 counts too).
template <class Visit> void forEachRun(std::span<const std::int32_t> index, Visit&& visit) {
    std::size_t begin = 0;
    for (std::size_t k = 0; k <= index.size(); ++k)
        if (k == index.size() || index[k] == -1) {
            if (k > begin) visit(begin, k);
            begin = k + 1;
        }
}

bool allValid(std::span<const std::int32_t> index, std::size_t begin, std::size_t end,
              std::size_t count) {
    for (std::size_t k = begin; k < end; ++k)
        if (!validIndex(index[k], count)) return false;
    return true;
}

void addFace(ShapeTopology& t, std::uint32_t face, std::uint32_t part) {
    const std::uint32_t end = std::uint32_t(t.corners.size());
    const std::uint32_t begin = t.faces.empty() ? 0 : t.faces.back().end;
    t.faces.push_back({begin, end, face, part});
}

/// Strips of `points` (indices into the shape's points, each with its slot and vertex
/// number) as triangles: every other triangle reversed, so all wind like the first.
void addStrip(ShapeTopology& t, std::span<const Corner> strip, std::uint32_t part,
              std::uint32_t& triangle) {
    for (std::size_t i = 0; i + 2 < strip.size(); ++i) {
        const bool even = i % 2 == 0;
        t.corners.push_back(strip[even ? i : i + 1]);
        t.corners.push_back(strip[even ? i + 1 : i]);
        t.corners.push_back(strip[i + 2]);
        addFace(t, triangle++, part);
    }
}

// ---- attribute indices by binding --------------------------------------------------------

bool indexInUse(std::span<const std::int32_t> index) {
    return !index.empty() && !(index.size() == 1 && index[0] == -1);
}

/// Which entry of an attribute array a corner takes under `binding` (may be out of range).
std::int64_t attributeIndex(Binding binding, const ShapeTopology& t, const Face& f, const Corner& c,
                            std::span<const std::int32_t> index) {
    auto indexed = [&](std::uint32_t at) -> std::int64_t {
        if (!t.indexed) return at;
        return at < index.size() ? index[at] : -1;
    };
    switch (binding) {
    case Binding::Overall:
        return 0;
    case Binding::PerPart:
        return f.part;
    case Binding::PerPartIndexed:
        return indexed(f.part);
    case Binding::PerFace:
        return f.face;
    case Binding::PerFaceIndexed:
        return indexed(f.face);
    case Binding::PerVertex:
        return c.vertex;
    case Binding::PerVertexIndexed:
        if (!t.indexed) return c.vertex;
        // The index field not in use: the attribute runs parallel to the points.
        if (!indexInUse(index)) return c.point;
        return c.slot < index.size() ? index[c.slot] : -1;
    }
    return 0;
}

/// Out of range: the last entry (as Coin clamps), so a short list never drops geometry.
template <class T> const T& clampedEntry(std::span<const T> values, std::int64_t i) {
    return values[std::size_t(std::clamp<std::int64_t>(i, 0, std::int64_t(values.size()) - 1))];
}

// ---- normals -----------------------------------------------------------------------------

glm::dvec3 newellNormal(std::span<const glm::vec3> points, const ShapeTopology& t, const Face& f) {
    glm::dvec3 n(0.0);
    for (std::uint32_t k = f.begin; k < f.end; ++k) {
        const glm::dvec3 p(points[std::size_t(t.corners[k].point)]);
        const std::uint32_t next = k + 1 < f.end ? k + 1 : f.begin;
        const glm::dvec3 q(points[std::size_t(t.corners[next].point)]);
        n.x += (p.y - q.y) * (p.z + q.z);
        n.y += (p.z - q.z) * (p.x + q.x);
        n.z += (p.x - q.x) * (p.y + q.y);
    }
    return n;
}

glm::dvec3 normalizedOrZero(const glm::dvec3& v) {
    const double len = glm::length(v);
    return len > 0.0 && std::isfinite(len) ? v / len : glm::dvec3(0.0);
}

struct PositionKey {
    std::uint32_t x, y, z;
    bool operator==(const PositionKey&) const = default;
};
struct PositionHash {
    std::size_t operator()(const PositionKey& k) const noexcept {
        std::uint64_t h = k.x;
        h = h * 0x9e3779b97f4a7c15ULL ^ k.y;
        h = h * 0x9e3779b97f4a7c15ULL ^ k.z;
        return std::size_t(h ^ (h >> 29));
    }
};
PositionKey keyOf(const glm::vec3& p) {
    PositionKey k{};
    // +0 and -0 are the same position.
    const glm::vec3 q = p + glm::vec3(0.0f);
    std::memcpy(&k.x, &q.x, 4);
    std::memcpy(&k.y, &q.y, 4);
    std::memcpy(&k.z, &q.z, 4);
    return k;
}

/// Per-corner normals generated from the faces (SoNormalGenerator): flat per face, smoothed
/// over the faces sharing a corner's position whose normals are within the crease angle.
std::vector<glm::dvec3> generatedNormals(const ShapeTopology& t, const VertexAttributes& a,
                                         std::vector<glm::dvec3>& faceNormals) {
    faceNormals.resize(t.faces.size());
    for (std::size_t f = 0; f < t.faces.size(); ++f) {
        glm::dvec3 n = normalizedOrZero(newellNormal(a.points, t, t.faces[f]));
        faceNormals[f] = a.clockwise ? -n : n;
    }
    std::vector<glm::dvec3> out(t.corners.size());
    for (std::size_t f = 0; f < t.faces.size(); ++f)
        for (std::uint32_t k = t.faces[f].begin; k < t.faces[f].end; ++k)
            out[k] = faceNormals[f];
    if (!(a.creaseAngle > 0.0f) && !t.alwaysSmooth) return out;

    // Faces at each position (a face once per position).
    std::unordered_map<PositionKey, std::vector<std::uint32_t>, PositionHash> facesAt;
    facesAt.reserve(t.corners.size());
    for (std::size_t f = 0; f < t.faces.size(); ++f)
        for (std::uint32_t k = t.faces[f].begin; k < t.faces[f].end; ++k) {
            std::vector<std::uint32_t>& list =
                facesAt[keyOf(a.points[std::size_t(t.corners[k].point)])];
            if (list.empty() || list.back() != f) list.push_back(std::uint32_t(f));
        }
    const double cosCrease =
        t.alwaysSmooth ? -2.0 : std::cos(std::min(double(a.creaseAngle), 3.14159265358979323846));
    for (std::size_t f = 0; f < t.faces.size(); ++f) {
        const glm::dvec3& own = faceNormals[f];
        if (own == glm::dvec3(0.0)) continue;
        for (std::uint32_t k = t.faces[f].begin; k < t.faces[f].end; ++k) {
            glm::dvec3 sum(0.0);
            for (std::uint32_t g : facesAt[keyOf(a.points[std::size_t(t.corners[k].point)])])
                if (glm::dot(own, faceNormals[g]) >= cosCrease - 1e-12) sum += faceNormals[g];
            const glm::dvec3 n = normalizedOrZero(sum);
            out[k] = n == glm::dvec3(0.0) ? own : n;
        }
    }
    return out;
}

/// The given normals for every corner, or nothing when some corner has none (then the shape
/// generates its normals, as Coin does when the normals in scope do not cover it).
bool givenNormals(const ShapeTopology& t, const VertexAttributes& a, std::vector<glm::dvec3>& out) {
    if (a.normals.empty()) return false;
    out.resize(t.corners.size());
    for (const Face& f : t.faces)
        for (std::uint32_t k = f.begin; k < f.end; ++k) {
            const std::int64_t i =
                attributeIndex(a.normalBinding, t, f, t.corners[k], t.normalIndex);
            if (!validIndex(i, a.normals.size())) return false;
            out[k] = normalizedOrZero(glm::dvec3(a.normals[std::size_t(i)]));
        }
    return true;
}

// ---- triangulation -----------------------------------------------------------------------

/// Ear clipping of a simple polygon given by 2D points (its projection on its own plane),
/// counter-clockwise or not; appends triangles of local corner numbers. Falls back to a fan
/// where no ear is found (self-intersecting input).
void earClip(const std::vector<glm::dvec2>& p, std::vector<std::uint32_t>& triangles) {
    const std::size_t n = p.size();
    double area = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2 &a = p[i], &b = p[(i + 1) % n];
        area += a.x * b.y - b.x * a.y;
    }
    const double orientation = area >= 0.0 ? 1.0 : -1.0;
    std::vector<std::uint32_t> ring(n);
    for (std::size_t i = 0; i < n; ++i)
        ring[i] = std::uint32_t(i);
    auto cross = [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
        return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    std::size_t guard = 0;
    while (ring.size() > 3 && guard < n * n) {
        bool clipped = false;
        for (std::size_t i = 0; i < ring.size(); ++i, ++guard) {
            const std::uint32_t ia = ring[(i + ring.size() - 1) % ring.size()], ib = ring[i],
                                ic = ring[(i + 1) % ring.size()];
            if (orientation * cross(p[ia], p[ib], p[ic]) <= 0.0) continue; // reflex or flat
            bool inside = false;
            for (std::uint32_t j : ring) {
                if (j == ia || j == ib || j == ic) continue;
                if (orientation * cross(p[ia], p[ib], p[j]) >= 0.0 &&
                    orientation * cross(p[ib], p[ic], p[j]) >= 0.0 &&
                    orientation * cross(p[ic], p[ia], p[j]) >= 0.0) {
                    inside = true;
                    break;
                }
            }
            if (inside) continue;
            triangles.insert(triangles.end(), {ia, ib, ic});
            ring.erase(ring.begin() + std::ptrdiff_t(i));
            clipped = true;
            break;
        }
        if (!clipped) break;
    }
    for (std::size_t i = 1; i + 1 < ring.size(); ++i) // the rest (a triangle, or a fan)
        triangles.insert(triangles.end(), {ring[0], ring[i], ring[i + 1]});
}

void triangulate(const ShapeTopology& t, const VertexAttributes& a, const Face& f,
                 const glm::dvec3& normal, std::uint32_t first, Mesh& out) {
    const std::uint32_t corners = f.end - f.begin;
    if (a.convexFaces || corners <= 3 || normal == glm::dvec3(0.0)) {
        for (std::uint32_t c = 1; c + 1 < corners; ++c)
            out.indices.insert(out.indices.end(), {first, first + c, first + c + 1});
        return;
    }
    // Project on the plane of the dominant normal component.
    const glm::dvec3 m = glm::abs(normal);
    const int drop = m.x >= m.y && m.x >= m.z ? 0 : m.y >= m.z ? 1 : 2;
    std::vector<glm::dvec2> p;
    p.reserve(corners);
    for (std::uint32_t k = f.begin; k < f.end; ++k) {
        const glm::dvec3 q(a.points[std::size_t(t.corners[k].point)]);
        p.emplace_back(drop == 0   ? glm::dvec2(q.y, q.z)
                       : drop == 1 ? glm::dvec2(q.z, q.x)
                                   : glm::dvec2(q.x, q.y));
    }
    std::vector<std::uint32_t> triangles;
    earClip(p, triangles);
    for (std::uint32_t i : triangles)
        out.indices.push_back(first + i);
}

} // namespace

// ---- topologies --------------------------------------------------------------------------

ShapeTopology makeFaceSetTopology(std::span<const std::int32_t> numVertices,
                                  std::int32_t startIndex, std::size_t pointCount) {
    ShapeTopology t;
    std::uint32_t polygon = 0;
    forEachCounted(numVertices, startIndex, pointCount, [&](std::int64_t begin, std::int64_t end) {
        for (std::int64_t i = begin; i < end; ++i)
            t.corners.push_back({std::int32_t(i), std::uint32_t(i - std::max(startIndex, 0)),
                                 std::uint32_t(i - std::max(startIndex, 0))});
        if (end - begin >= 3)
            addFace(t, polygon, polygon);
        else
            t.corners.resize(t.faces.empty() ? 0 : t.faces.back().end);
        ++polygon;
    });
    return t;
}

ShapeTopology makeIndexedFaceSetTopology(std::span<const std::int32_t> coordIndex,
                                         std::size_t pointCount) {
    ShapeTopology t;
    t.indexed = true;
    std::uint32_t polygon = 0, vertex = 0;
    forEachRun(coordIndex, [&](std::size_t begin, std::size_t end) {
        const bool good = end - begin >= 3 && allValid(coordIndex, begin, end, pointCount);
        for (std::size_t k = begin; k < end; ++k, ++vertex)
            if (good) t.corners.push_back({coordIndex[k], std::uint32_t(k), vertex});
        if (good) addFace(t, polygon, polygon);
        ++polygon;
    });
    return t;
}

ShapeTopology makeTriangleStripSetTopology(std::span<const std::int32_t> numVertices,
                                           std::int32_t startIndex, std::size_t pointCount) {
    ShapeTopology t;
    std::uint32_t strip = 0, triangle = 0;
    forEachCountedRun(numVertices, startIndex, pointCount,
                      [&](std::span<const Corner> run) { addStrip(t, run, strip++, triangle); });
    return t;
}

ShapeTopology makeIndexedTriangleStripSetTopology(std::span<const std::int32_t> coordIndex,
                                                  std::size_t pointCount) {
    ShapeTopology t;
    t.indexed = true;
    std::uint32_t strip = 0, triangle = 0, vertex = 0;
    std::vector<Corner> corners;
    forEachRun(coordIndex, [&](std::size_t begin, std::size_t end) {
        corners.clear();
        const bool good = allValid(coordIndex, begin, end, pointCount);
        for (std::size_t k = begin; k < end; ++k, ++vertex)
            corners.push_back({coordIndex[k], std::uint32_t(k), vertex});
        if (good)
            addStrip(t, corners, strip, triangle);
        else if (end - begin >= 3)
            triangle += std::uint32_t(end - begin - 2); // its triangles still count
        ++strip;
    });
    return t;
}

ShapeTopology makeQuadMeshTopology(std::int32_t verticesPerRow, std::int32_t verticesPerColumn,
                                   std::int32_t startIndex, std::size_t pointCount) {
    ShapeTopology t;
    t.alwaysSmooth = true;
    const std::int64_t start = std::max(startIndex, 0);
    const std::int64_t columns = verticesPerRow, rows = verticesPerColumn;
    if (columns < 2 || rows < 2 || start >= std::int64_t(pointCount)) return t;
    // Only the rows that fit in the points.
    const std::int64_t fitting =
        std::min<std::int64_t>(rows, (std::int64_t(pointCount) - start) / columns);
    auto corner = [&](std::int64_t r, std::int64_t c) {
        const auto vertex = std::uint32_t(r * columns + c);
        return Corner{std::int32_t(start + r * columns + c), vertex, vertex};
    };
    std::uint32_t quad = 0;
    for (std::int64_t r = 0; r + 1 < fitting; ++r)
        for (std::int64_t c = 0; c + 1 < columns; ++c) {
            // As Coin draws a row: a quad strip of this row's and the next row's vertices,
            // (r, c) (r+1, c) (r, c+1) (r+1, c+1) ...; each quad winds (r, c) (r+1, c)
            // (r+1, c+1) (r, c+1), which decides what SOLID culls.
            t.corners.push_back(corner(r, c));
            t.corners.push_back(corner(r + 1, c));
            t.corners.push_back(corner(r + 1, c + 1));
            t.corners.push_back(corner(r, c + 1));
            addFace(t, quad++, std::uint32_t(r));
        }
    return t;
}

namespace {

void addPolylineSegments(ShapeTopology& t, std::span<const Corner> line, std::uint32_t polyline,
                         std::uint32_t& segment) {
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        t.corners.push_back(line[i]);
        t.corners.push_back(line[i + 1]);
        addFace(t, polyline, segment++);
    }
}

} // namespace

ShapeTopology makeLineSetTopology(std::span<const std::int32_t> numVertices,
                                  std::int32_t startIndex, std::size_t pointCount) {
    ShapeTopology t;
    t.primitive = Mesh::Primitive::Lines;
    std::uint32_t polyline = 0, segment = 0;
    forEachCountedRun(numVertices, startIndex, pointCount, [&](std::span<const Corner> run) {
        addPolylineSegments(t, run, polyline++, segment);
    });
    return t;
}

ShapeTopology makeIndexedLineSetTopology(std::span<const std::int32_t> coordIndex,
                                         std::size_t pointCount) {
    ShapeTopology t;
    t.primitive = Mesh::Primitive::Lines;
    t.indexed = true;
    std::uint32_t polyline = 0, segment = 0, vertex = 0;
    std::vector<Corner> corners;
    forEachRun(coordIndex, [&](std::size_t begin, std::size_t end) {
        corners.clear();
        const bool good = allValid(coordIndex, begin, end, pointCount);
        for (std::size_t k = begin; k < end; ++k, ++vertex)
            corners.push_back({coordIndex[k], std::uint32_t(k), vertex});
        if (good)
            addPolylineSegments(t, corners, polyline, segment);
        else if (end - begin >= 2)
            segment += std::uint32_t(end - begin - 1);
        ++polyline;
    });
    return t;
}

ShapeTopology makePointSetTopology(std::int32_t numPoints, std::int32_t startIndex,
                                   std::size_t pointCount) {
    ShapeTopology t;
    t.primitive = Mesh::Primitive::Points;
    const std::int64_t start = std::max(startIndex, 0);
    const std::int64_t end = numPoints < 0 ? std::int64_t(pointCount)
                                           : std::min<std::int64_t>(start + std::int64_t(numPoints),
                                                                    std::int64_t(pointCount));
    for (std::int64_t i = start; i < end; ++i) {
        const auto number = std::uint32_t(i - start);
        t.corners.push_back({std::int32_t(i), number, number});
        addFace(t, number, number);
    }
    return t;
}

// ---- the mesh ----------------------------------------------------------------------------

glm::vec2 defaultTextureCoord(const glm::vec3& point, const glm::vec3& boxMin,
                              const glm::vec3& boxSize) {
    // Coin's mapping (SoTextureCoordinateBundle): s and t along the two axes other than the
    // smallest (the first smallest on ties), the larger first; on a tie between them the
    // higher axis first (Coin keeps Open Inventor's order: a cube's s runs along z). Each is
    // divided by its own side, so both run 0..1 across the box.
    int smallest = 0;
    if (boxSize[1] < boxSize[smallest]) smallest = 1;
    if (boxSize[2] < boxSize[smallest]) smallest = 2;
    int s = (smallest + 1) % 3, t = (smallest + 2) % 3;
    if (boxSize[s] == boxSize[t] ? s < t : boxSize[s] < boxSize[t]) std::swap(s, t);
    const auto along = [&](int axis) {
        const float side = boxSize[axis] > 0.0f ? boxSize[axis] : 1.0f;
        return (point[axis] - boxMin[axis]) / side;
    };
    return {along(s), along(t)};
}

void buildVertexShapeMesh(const ShapeTopology& t, const VertexAttributes& a, Mesh& out) {
    out = Mesh{};
    out.primitive = t.primitive;
    const bool triangles = t.primitive == Mesh::Primitive::Triangles;

    std::vector<glm::dvec3> faceNormals, cornerNormals;
    if (triangles) {
        if (!givenNormals(t, a, cornerNormals)) {
            cornerNormals = generatedNormals(t, a, faceNormals);
        } else {
            faceNormals.resize(t.faces.size());
            for (std::size_t f = 0; f < t.faces.size(); ++f)
                faceNormals[f] = normalizedOrZero(newellNormal(a.points, t, t.faces[f]));
        }
    }
    const bool perCornerColors =
        !a.colors.empty() && a.materialBinding != Binding::Overall && a.colors.size() >= 1;
    const bool hasTexCoords =
        !a.textureCoords.empty() || a.defaultTextureCoords || a.planeTextureCoords;

    glm::vec3 boxMin(0.0f), boxSize(0.0f);
    if (a.textureCoords.empty() && !a.planeTextureCoords && a.defaultTextureCoords &&
        !t.corners.empty()) {
        glm::vec3 lo(a.points[std::size_t(t.corners[0].point)]), hi = lo;
        for (const Corner& c : t.corners) {
            lo = glm::min(lo, a.points[std::size_t(c.point)]);
            hi = glm::max(hi, a.points[std::size_t(c.point)]);
        }
        boxMin = lo;
        boxSize = hi - lo;
    }

    out.positions.reserve(t.corners.size());
    for (std::size_t fi = 0; fi < t.faces.size(); ++fi) {
        const Face& f = t.faces[fi];
        // Faces of zero area cover nothing: left out where normals are generated from them.
        if (triangles && faceNormals[fi] == glm::dvec3(0.0) && a.normals.empty()) continue;
        const std::uint32_t first = std::uint32_t(out.positions.size());
        for (std::uint32_t k = f.begin; k < f.end; ++k) {
            const Corner& c = t.corners[k];
            out.positions.push_back(a.points[std::size_t(c.point)]);
            if (triangles) {
                glm::dvec3 n = cornerNormals[k];
                if (n == glm::dvec3(0.0)) n = faceNormals[fi]; // a zero given normal
                out.normals.emplace_back(n);
            }
            if (perCornerColors)
                out.colors.push_back(clampedEntry(
                    a.colors, attributeIndex(a.materialBinding, t, f, c, t.materialIndex)));
            if (hasTexCoords) {
                const glm::vec3& p = a.points[std::size_t(c.point)];
                if (a.planeTextureCoords) {
                    out.texCoords.emplace_back(glm::dot(a.planeS, p), glm::dot(a.planeT, p));
                } else if (!a.textureCoords.empty()) {
                    const Binding binding = a.textureCoordBinding == Binding::PerVertex
                                                ? Binding::PerVertex
                                                : Binding::PerVertexIndexed;
                    out.texCoords.push_back(clampedEntry(
                        a.textureCoords, attributeIndex(binding, t, f, c, t.textureCoordIndex)));
                } else {
                    out.texCoords.push_back(defaultTextureCoord(p, boxMin, boxSize));
                }
            }
        }
        const std::uint32_t corners = f.end - f.begin;
        switch (t.primitive) {
        case Mesh::Primitive::Triangles:
            triangulate(t, a, f, faceNormals[fi], first, out);
            // The polygon's own edges, as Coin draws a face in line mode.
            for (std::uint32_t c = 0; c < corners; ++c)
                out.outline.insert(out.outline.end(), {first + c, first + (c + 1) % corners});
            break;
        case Mesh::Primitive::Lines:
            for (std::uint32_t c = 0; c + 1 < corners; ++c)
                out.indices.insert(out.indices.end(), {first + c, first + c + 1});
            break;
        case Mesh::Primitive::Points:
            for (std::uint32_t c = 0; c < corners; ++c)
                out.indices.push_back(first + c);
            break;
        }
    }
}

} // namespace volsg
