#include <volsg/geometry/IndexedMeshes.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace volsg {

namespace {

/// One polygon or polyline: coordIndex[begin, end), without its -1.
struct IndexRun {
    std::size_t begin, end;
    std::size_t size() const { return end - begin; }
};

/// Splits at -1; a trailing run without -1 counts. Empty runs (consecutive -1) are dropped.
template <class Visit> void forEachRun(std::span<const std::int32_t> index, Visit&& visit) {
    std::size_t begin = 0;
    for (std::size_t k = 0; k <= index.size(); ++k) {
        if (k == index.size() || index[k] == -1) {
            if (k > begin) visit(IndexRun{begin, k});
            begin = k + 1;
        }
    }
}

bool validIndex(std::int32_t i, std::size_t count) {
    return i >= 0 && static_cast<std::size_t>(i) < count;
}

bool allValid(std::span<const std::int32_t> index, const IndexRun& run, std::size_t count) {
    for (std::size_t k = run.begin; k < run.end; ++k)
        if (!validIndex(index[k], count)) return false;
    return true;
}

/// Newell's method: the polygon's area-weighted normal, exact for planar polygons and a
/// sensible average for slightly non-planar ones.
glm::dvec3 newellNormal(std::span<const glm::vec3> points, std::span<const std::int32_t> index,
                        const IndexRun& run) {
    glm::dvec3 n(0.0);
    for (std::size_t k = run.begin; k < run.end; ++k) {
        const glm::dvec3 p(points[static_cast<std::size_t>(index[k])]);
        const std::size_t next = k + 1 < run.end ? k + 1 : run.begin;
        const glm::dvec3 q(points[static_cast<std::size_t>(index[next])]);
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

enum class NormalSource { Indexed, ByCoordIndex, Flat };

NormalSource chooseNormalSource(std::size_t pointCount, std::span<const std::int32_t> coordIndex,
                                std::span<const glm::vec3> normals,
                                std::span<const std::int32_t> normalIndex) {
    if (normals.empty()) return NormalSource::Flat;
    const bool normalIndexInUse =
        !normalIndex.empty() && !(normalIndex.size() == 1 && normalIndex[0] == -1);
    if (normalIndexInUse) return NormalSource::Indexed;
    std::int32_t maxUsed = -1;
    for (std::int32_t i : coordIndex)
        if (validIndex(i, pointCount)) maxUsed = std::max(maxUsed, i);
    if (maxUsed >= 0 && static_cast<std::size_t>(maxUsed) < normals.size())
        return NormalSource::ByCoordIndex;
    return NormalSource::Flat;
}

} // namespace

void buildFaceSetMesh(std::span<const glm::vec3> points, std::span<const std::int32_t> coordIndex,
                      std::span<const glm::vec3> normals, std::span<const std::int32_t> normalIndex,
                      Mesh& out) {
    out = Mesh{};
    out.primitive = Mesh::Primitive::Triangles;
    const NormalSource source = chooseNormalSource(points.size(), coordIndex, normals, normalIndex);

    forEachRun(coordIndex, [&](const IndexRun& run) {
        if (run.size() < 3 || !allValid(coordIndex, run, points.size())) return;
        if (source == NormalSource::Indexed) {
            // normalIndex runs parallel to coordIndex: it must cover this polygon.
            if (run.end > normalIndex.size()) return;
            if (!allValid(normalIndex, run, normals.size())) return;
        }
        const glm::dvec3 faceNormal = normalizedOrZero(newellNormal(points, coordIndex, run));
        if (source == NormalSource::Flat && faceNormal == glm::dvec3(0.0)) return;

        const std::uint32_t first = static_cast<std::uint32_t>(out.positions.size());
        for (std::size_t k = run.begin; k < run.end; ++k) {
            glm::dvec3 n = faceNormal;
            if (source != NormalSource::Flat) {
                const std::int32_t ni =
                    source == NormalSource::Indexed ? normalIndex[k] : coordIndex[k];
                const glm::dvec3 given =
                    normalizedOrZero(glm::dvec3(normals[static_cast<std::size_t>(ni)]));
                if (given != glm::dvec3(0.0)) n = given;
            }
            out.positions.push_back(points[static_cast<std::size_t>(coordIndex[k])]);
            out.normals.emplace_back(n);
        }
        const std::uint32_t corners = static_cast<std::uint32_t>(run.size());
        for (std::uint32_t c = 1; c + 1 < corners; ++c)
            out.indices.insert(out.indices.end(), {first, first + c, first + c + 1});
    });
}

void buildLineSetMesh(std::span<const glm::vec3> points, std::span<const std::int32_t> coordIndex,
                      Mesh& out) {
    out = Mesh{};
    out.primitive = Mesh::Primitive::Lines;
    forEachRun(coordIndex, [&](const IndexRun& run) {
        if (run.size() < 2 || !allValid(coordIndex, run, points.size())) return;
        const std::uint32_t first = static_cast<std::uint32_t>(out.positions.size());
        for (std::size_t k = run.begin; k < run.end; ++k)
            out.positions.push_back(points[static_cast<std::size_t>(coordIndex[k])]);
        for (std::uint32_t s = 0; s + 1 < static_cast<std::uint32_t>(run.size()); ++s)
            out.indices.insert(out.indices.end(), {first + s, first + s + 1});
    });
}

} // namespace volsg
