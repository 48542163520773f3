#include <volsg/geometry/PrimitiveMeshes.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

namespace volsg {

namespace {

std::uint32_t addVertex(Mesh& m, const glm::dvec3& p, const glm::dvec3& n, const glm::dvec2& st) {
    m.positions.emplace_back(p);
    m.normals.emplace_back(n);
    m.texCoords.emplace_back(st);
    return static_cast<std::uint32_t>(m.positions.size() - 1);
}

void startPart(Mesh& m, PartStarts* parts) {
    if (parts) parts->push_back(std::uint32_t(m.positions.size()));
}

void addTriangle(Mesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    m.indices.insert(m.indices.end(), {a, b, c});
}

/// Two triangles, and the quad's four edges as its outline (Coin draws cubes and cylinder
/// sides as GL quads: no diagonal in line mode).
void addQuad(Mesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    addTriangle(m, a, b, c);
    addTriangle(m, a, c, d);
    m.outline.insert(m.outline.end(), {a, b, b, c, c, d, d, a});
}

/// The edges of the triangles from index `first` on, as outline (Coin's triangle fans).
void outlineTriangles(Mesh& m, std::size_t first) {
    for (std::size_t i = first; i + 2 < m.indices.size(); i += 3) {
        const std::uint32_t a = m.indices[i], b = m.indices[i + 1], c = m.indices[i + 2];
        m.outline.insert(m.outline.end(), {a, b, b, c, c, a});
    }
}

/// Unit directions around +Y: index j at angle 2*pi*j/slices from the back (-Z), turning
/// counter-clockwise seen from +Y (towards -X), as Inventor's texture s runs. The last entry
/// repeats the first exactly, so rings close without a crack (with s = 1 there).
std::vector<glm::dvec3> ringDirections(int slices) {
    std::vector<glm::dvec3> dirs(static_cast<std::size_t>(slices) + 1);
    for (int j = 0; j < slices; ++j) {
        const double phi = 2.0 * std::numbers::pi * j / slices;
        dirs[static_cast<std::size_t>(j)] = {-std::sin(phi), 0.0, -std::cos(phi)};
    }
    dirs.back() = dirs.front();
    return dirs;
}

double ringS(std::size_t j, std::size_t count) {
    return double(j) / double(count - 1);
}

/// A flat disk of the ring at height y, facing +Y when `up`, else -Y; its texture is the disk
/// cut from the image as seen from outside (+X to the right, the front down for the top).
void addDisk(Mesh& m, const std::vector<glm::dvec3>& dirs, double radius, double y, bool up) {
    const glm::dvec3 normal(0.0, up ? 1.0 : -1.0, 0.0);
    auto st = [up](const glm::dvec3& d) {
        return glm::dvec2(0.5 + 0.5 * d.x, up ? 0.5 - 0.5 * d.z : 0.5 + 0.5 * d.z);
    };
    const std::uint32_t centre = addVertex(m, {0.0, y, 0.0}, normal, {0.5, 0.5});
    const std::uint32_t first = static_cast<std::uint32_t>(m.positions.size());
    for (const auto& d : dirs)
        addVertex(m, radius * d + glm::dvec3(0.0, y, 0.0), normal, st(d));
    const std::uint32_t slices = static_cast<std::uint32_t>(dirs.size() - 1);
    for (std::uint32_t j = 0; j < slices; ++j) {
        // Ring order turns counter-clockwise seen from +Y.
        if (up)
            addTriangle(m, centre, first + j, first + j + 1);
        else
            addTriangle(m, centre, first + j + 1, first + j);
    }
}

void clear(Mesh& m) {
    m = Mesh{};
    m.primitive = Mesh::Primitive::Triangles;
}

} // namespace

void buildBoxMesh(const glm::vec3& size, Mesh& out, PartStarts* faces) {
    clear(out);
    const glm::dvec3 half = glm::abs(glm::dvec3(size)) * 0.5;
    // Each face: outward normal n and in-plane axes u (texture s), v (texture t) with
    // u x v = n, so the corners -u-v, +u-v, +u+v, -u+v run counter-clockwise seen from outside.
    struct Face {
        glm::dvec3 n, u, v;
    };
    static constexpr double o = 0.0, l = 1.0;
    const Face order[6] = {
        {{o, o, l}, {l, o, o}, {o, l, o}},   // front
        {{o, o, -l}, {-l, o, o}, {o, l, o}}, // back
        {{-l, o, o}, {o, o, l}, {o, l, o}},  // left
        {{l, o, o}, {o, o, -l}, {o, l, o}},  // right
        {{o, l, o}, {l, o, o}, {o, o, -l}},  // top
        {{o, -l, o}, {l, o, o}, {o, o, l}},  // bottom
    };
    out.positions.reserve(24);
    out.normals.reserve(24);
    out.texCoords.reserve(24);
    out.indices.reserve(36);
    for (const Face& f : order) {
        startPart(out, faces);
        const std::uint32_t base = static_cast<std::uint32_t>(out.positions.size());
        const double su[4] = {-1, 1, 1, -1}, sv[4] = {-1, -1, 1, 1};
        for (int k = 0; k < 4; ++k)
            addVertex(out, (f.n + su[k] * f.u + sv[k] * f.v) * half, f.n,
                      {0.5 + 0.5 * su[k], 0.5 + 0.5 * sv[k]});
        addQuad(out, base, base + 1, base + 2, base + 3);
    }
}

void buildSphereMesh(float radius, int slices, int stacks, Mesh& out) {
    clear(out);
    slices = std::max(slices, 3);
    stacks = std::max(stacks, 2);
    const double r = std::abs(double(radius));
    const std::vector<glm::dvec3> dirs = ringDirections(slices);
    const std::uint32_t rowSize = static_cast<std::uint32_t>(slices) + 1;
    for (int i = 0; i <= stacks; ++i) {
        const double theta = std::numbers::pi * i / stacks;
        // Exact poles and equator, so tests can rely on them.
        const double y = i == 0            ? 1.0
                         : i == stacks     ? -1.0
                         : 2 * i == stacks ? 0.0
                                           : std::cos(theta);
        const double s = (i == 0 || i == stacks) ? 0.0 : 2 * i == stacks ? 1.0 : std::sin(theta);
        const double t = 1.0 - double(i) / stacks;
        // The top pole's vertex j serves slice j - 1, the bottom pole's slice j.
        const double poleShift = i == 0 ? -0.5 : i == stacks ? 0.5 : 0.0;
        for (std::size_t j = 0; j < dirs.size(); ++j) {
            const glm::dvec3 n(s * dirs[j].x, y, s * dirs[j].z);
            addVertex(out, r * n, n, {(double(j) + poleShift) / slices, t});
        }
    }
    for (int i = 0; i < stacks; ++i) {
        for (int j = 0; j < slices; ++j) {
            const std::uint32_t a = static_cast<std::uint32_t>(i) * rowSize + j; // upper left
            const std::uint32_t d = a + 1;                                       // upper right
            const std::uint32_t b = a + rowSize;                                 // lower left
            const std::uint32_t c = b + 1;                                       // lower right
            // At the poles one triangle of the quad would have zero area: leave it out.
            if (i != 0) addTriangle(out, a, b, d);
            if (i != stacks - 1) addTriangle(out, d, b, c);
        }
    }
}

void buildConeMesh(float bottomRadius, float height, bool sides, bool bottom, int slices, Mesh& out,
                   PartStarts* parts) {
    clear(out);
    slices = std::max(slices, 3);
    const double r = std::abs(double(bottomRadius)), h = std::abs(double(height)), y0 = -0.5 * h,
                 y1 = 0.5 * h;
    const std::vector<glm::dvec3> dirs = ringDirections(slices);
    if (sides) {
        // The side's outward normal at angle phi is proportional to (h * radial, r).
        auto sideNormal = [&](const glm::dvec3& radial) {
            const glm::dvec3 n = h * radial + glm::dvec3(0.0, r, 0.0);
            const double len = glm::length(n);
            return len > 0.0 ? n / len : glm::dvec3(0.0, 1.0, 0.0);
        };
        startPart(out, parts);
        const std::uint32_t first = static_cast<std::uint32_t>(out.positions.size());
        for (std::size_t j = 0; j < dirs.size(); ++j)
            addVertex(out, r * dirs[j] + glm::dvec3(0.0, y0, 0.0), sideNormal(dirs[j]),
                      {ringS(j, dirs.size()), 0.0});
        for (int j = 0; j < slices; ++j) {
            const double mid = 2.0 * std::numbers::pi * (j + 0.5) / slices;
            const glm::dvec3 midDir(-std::sin(mid), 0.0, -std::cos(mid));
            const std::uint32_t apex =
                addVertex(out, {0.0, y1, 0.0}, sideNormal(midDir), {(j + 0.5) / slices, 1.0});
            const std::uint32_t b = first + static_cast<std::uint32_t>(j);
            addTriangle(out, b, b + 1, apex);
        }
    }
    if (bottom) {
        startPart(out, parts);
        addDisk(out, dirs, r, y0, false);
    }
}

void buildCylinderMesh(float radius, float height, bool sides, bool top, bool bottom, int slices,
                       Mesh& out, PartStarts* parts) {
    clear(out);
    slices = std::max(slices, 3);
    const double r = std::abs(double(radius)), h = std::abs(double(height));
    const double y0 = -0.5 * h, y1 = 0.5 * h;
    const std::vector<glm::dvec3> dirs = ringDirections(slices);
    if (sides) {
        startPart(out, parts);
        const std::uint32_t lower = static_cast<std::uint32_t>(out.positions.size());
        for (std::size_t j = 0; j < dirs.size(); ++j)
            addVertex(out, r * dirs[j] + glm::dvec3(0.0, y0, 0.0), dirs[j],
                      {ringS(j, dirs.size()), 0.0});
        const std::uint32_t upper = static_cast<std::uint32_t>(out.positions.size());
        for (std::size_t j = 0; j < dirs.size(); ++j)
            addVertex(out, r * dirs[j] + glm::dvec3(0.0, y1, 0.0), dirs[j],
                      {ringS(j, dirs.size()), 1.0});
        for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(slices); ++j)
            addQuad(out, lower + j, lower + j + 1, upper + j + 1, upper + j);
    }
    if (top) {
        startPart(out, parts);
        const std::size_t first = out.indices.size();
        addDisk(out, dirs, r, y1, true);
        outlineTriangles(out, first);
    }
    if (bottom) {
        startPart(out, parts);
        const std::size_t first = out.indices.size();
        addDisk(out, dirs, r, y0, false);
        outlineTriangles(out, first);
    }
}

namespace {

/// Coin's (int)(n * c) in float, as SoSphere, SoCone and SoCylinder compute it; a value that is
/// not finite counts as the default 0.5.
int coinCount(float n, float complexity, float highest) {
    const float c = std::isfinite(complexity) ? std::clamp(complexity, 0.0f, highest) : 0.5f;
    return int(n * c);
}

} // namespace

int sphereSlicesFor(float complexity) {
    return std::clamp(coinCount(30.0f, complexity, 1.0f), 4, 128);
}

int sphereStacksFor(float complexity) {
    return std::max(3, coinCount(30.0f, complexity, 1.0f)) - 1;
}

int roundSlicesFor(float complexity) {
    return std::clamp(coinCount(40.0f, complexity, 4.0f), 4, 128);
}

double sphereMeshDeviation(float radius, int slices, int stacks) {
    constexpr double pi = std::numbers::pi;
    return std::abs(double(radius)) *
           (1.0 - std::cos(pi / std::max(slices, 3)) * std::cos(pi / (2.0 * std::max(stacks, 1))));
}

double roundMeshDeviation(float radius, int slices) {
    constexpr double pi = std::numbers::pi;
    return std::abs(double(radius)) * (1.0 - std::cos(pi / std::max(slices, 3)));
}

std::vector<int> coarserSliceCounts(int slices, int minimum) {
    std::vector<int> out;
    for (int s = (2 * slices) / 3; slices > minimum; s = (2 * s) / 3) {
        slices = std::max(s, minimum);
        out.push_back(slices);
    }
    return out;
}

} // namespace volsg
