// Inventor's vertex shapes from plain arrays: topologies (faces, parts, strips, quads, lines,
// points), the binding rules for materials, normals and texture coordinates, crease-angle
// normals, concave polygons and default texture coordinates, each against a hand-computed
// expectation.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>
#include <vector>

#include <volsg/geometry/VertexShapes.h>

using namespace volsg;

namespace {

/// The 8 corners of the unit cube [0,1]^3 and its 6 faces, counter-clockwise from outside.
const std::vector<glm::vec3> kCubePoints = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                            {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
const std::vector<std::int32_t> kCubeFaces = {0, 3, 2, 1, -1, 4, 5, 6, 7, -1, 0, 1, 5, 4, -1,
                                              2, 3, 7, 6, -1, 1, 2, 6, 5, -1, 0, 4, 7, 3, -1};

const std::vector<glm::vec4> kColors = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1},
                                        {1, 1, 0, 1}, {0, 1, 1, 1}, {1, 0, 1, 0.5f}};

double triangleArea(const Mesh& m) {
    double area = 0.0;
    for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3) {
        const glm::dvec3 a(m.positions[m.indices[i]]), b(m.positions[m.indices[i + 1]]),
            c(m.positions[m.indices[i + 2]]);
        area += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    return area;
}

} // namespace

TEST_CASE("an indexed face set is fanned into triangles with every corner its own vertex") {
    VertexAttributes a;
    a.points = kCubePoints;
    Mesh m;
    buildVertexShapeMesh(makeIndexedFaceSetTopology(kCubeFaces, kCubePoints.size()), a, m);
    CHECK(m.primitive == Mesh::Primitive::Triangles);
    CHECK(m.positions.size() == 24u);
    CHECK(m.indices.size() == 36u);
    CHECK(triangleArea(m) == doctest::Approx(6.0).epsilon(1e-12));
    // Flat generated normals (crease angle 0): each face's corners share its outward normal.
    for (std::size_t f = 0; f < 6; ++f) {
        const glm::vec3 n = m.normals[4 * f];
        for (std::size_t k = 1; k < 4; ++k)
            CHECK(glm::length(m.normals[4 * f + k] - n) < 1e-6f);
        const glm::vec3 centre = 0.25f * (m.positions[4 * f] + m.positions[4 * f + 1] +
                                          m.positions[4 * f + 2] + m.positions[4 * f + 3]);
        CHECK(glm::dot(n, centre - glm::vec3(0.5f)) > 0.49f); // outward, unit
    }
}

TEST_CASE("a crease angle smooths normals across faces exactly when they meet below it") {
    VertexAttributes a;
    a.points = kCubePoints;
    const ShapeTopology t = makeIndexedFaceSetTopology(kCubeFaces, kCubePoints.size());
    Mesh m;
    a.creaseAngle = 1.5f; // below the cube's 90 degree edges: still flat
    buildVertexShapeMesh(t, a, m);
    std::set<std::tuple<float, float, float>> distinct;
    for (const auto& n : m.normals)
        distinct.insert({n.x, n.y, n.z});
    CHECK(distinct.size() == 6u);
    a.creaseAngle = 1.6f; // above 90 degrees: every corner averages its three faces
    buildVertexShapeMesh(t, a, m);
    const float k = 1.0f / std::sqrt(3.0f);
    for (std::size_t v = 0; v < m.positions.size(); ++v) {
        const glm::vec3 expected = (2.0f * m.positions[v] - glm::vec3(1.0f)) * k;
        CHECK(glm::length(m.normals[v] - expected) < 1e-6f);
    }
}

TEST_CASE("material bindings give each corner its part's, face's or vertex's material") {
    const ShapeTopology t = makeIndexedFaceSetTopology(kCubeFaces, kCubePoints.size());
    VertexAttributes a;
    a.points = kCubePoints;
    a.colors = kColors;
    Mesh m;
    SUBCASE("PER_FACE: one colour per polygon, in order") {
        a.materialBinding = Binding::PerFace;
        buildVertexShapeMesh(t, a, m);
        REQUIRE(m.colors.size() == 24u);
        for (std::size_t v = 0; v < 24; ++v)
            CHECK(m.colors[v] == kColors[v / 4]);
    }
    SUBCASE("PER_FACE_INDEXED: materialIndex per polygon") {
        const std::vector<std::int32_t> index = {5, 4, 3, 2, 1, 0};
        ShapeTopology indexed = t;
        indexed.materialIndex = index;
        a.materialBinding = Binding::PerFaceIndexed;
        buildVertexShapeMesh(indexed, a, m);
        for (std::size_t v = 0; v < 24; ++v)
            CHECK(m.colors[v] == kColors[5 - v / 4]);
    }
    SUBCASE("PER_VERTEX_INDEXED without materialIndex: indexed by coordIndex") {
        std::vector<glm::vec4> byPoint;
        for (std::size_t i = 0; i < kCubePoints.size(); ++i)
            byPoint.emplace_back(float(i) / 8.0f, 0, 0, 1);
        a.colors = byPoint;
        a.materialBinding = Binding::PerVertexIndexed;
        buildVertexShapeMesh(t, a, m);
        for (std::size_t v = 0; v < 24; ++v) {
            const auto point = std::find(kCubePoints.begin(), kCubePoints.end(), m.positions[v]);
            CHECK(m.colors[v].r == float(point - kCubePoints.begin()) / 8.0f);
        }
    }
    SUBCASE("PER_VERTEX: one per corner in order; a short list repeats its last entry") {
        a.materialBinding = Binding::PerVertex;
        buildVertexShapeMesh(t, a, m);
        for (std::size_t v = 0; v < 24; ++v)
            CHECK(m.colors[v] == kColors[std::min<std::size_t>(v, 5)]);
    }
    SUBCASE("OVERALL: no per-vertex colours (the material applies whole)") {
        a.materialBinding = Binding::Overall;
        buildVertexShapeMesh(t, a, m);
        CHECK(m.colors.empty());
    }
}

TEST_CASE("triangle strips alternate their winding so every triangle faces the same way") {
    // A strip of 6 points zig-zagging along x in the z = 0 plane: 4 triangles, all facing +z.
    const std::vector<glm::vec3> points = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0},
                                           {1, 1, 0}, {2, 0, 0}, {2, 1, 0}};
    const std::vector<std::int32_t> counts = {6};
    VertexAttributes a;
    a.points = points;
    a.colors = kColors;
    a.materialBinding = Binding::PerFace; // per triangle
    Mesh m;
    buildVertexShapeMesh(makeTriangleStripSetTopology(counts, 0, points.size()), a, m);
    REQUIRE(m.indices.size() == 12u);
    for (std::size_t i = 0; i < 12; i += 3) {
        const glm::vec3 a0 = m.positions[m.indices[i]], b = m.positions[m.indices[i + 1]],
                        c = m.positions[m.indices[i + 2]];
        CHECK(glm::cross(b - a0, c - a0).z < 0.0f); // clockwise seen from +z: all alike
        CHECK(m.colors[m.indices[i]] == kColors[i / 3]);
    }
    CHECK(triangleArea(m) == doctest::Approx(2.0));
    // PER_PART: one material per strip.
    const std::vector<std::int32_t> twoStrips = {3, 3};
    a.materialBinding = Binding::PerPart;
    buildVertexShapeMesh(makeTriangleStripSetTopology(twoStrips, 0, points.size()), a, m);
    REQUIRE(m.colors.size() == 6u);
    CHECK(m.colors[0] == kColors[0]);
    CHECK(m.colors[3] == kColors[1]);
}

TEST_CASE("an indexed triangle strip set splits its strips at -1") {
    const std::vector<glm::vec3> points = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}};
    const std::vector<std::int32_t> index = {0, 1, 2, 3, -1, 3, 2, 1};
    VertexAttributes a;
    a.points = points;
    Mesh m;
    buildVertexShapeMesh(makeIndexedTriangleStripSetTopology(index, points.size()), a, m);
    CHECK(m.indices.size() == 9u); // 2 triangles, then 1
}

TEST_CASE("a quad mesh makes (rows - 1) x (columns - 1) quads, materials per row or quad") {
    // 3 rows of 4 points on the unit grid.
    std::vector<glm::vec3> points;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c)
            points.emplace_back(float(c), float(r), 0.0f);
    VertexAttributes a;
    a.points = points;
    a.colors = kColors;
    a.materialBinding = Binding::PerPart;
    Mesh m;
    buildVertexShapeMesh(makeQuadMeshTopology(4, 3, 0, points.size()), a, m);
    CHECK(m.positions.size() == 6u * 4u);
    CHECK(triangleArea(m) == doctest::Approx(6.0));
    for (std::size_t q = 0; q < 6; ++q)
        CHECK(m.colors[4 * q] == kColors[q / 3]); // rows of 3 quads
    a.materialBinding = Binding::PerFace;
    buildVertexShapeMesh(makeQuadMeshTopology(4, 3, 0, points.size()), a, m);
    for (std::size_t q = 0; q < 6; ++q)
        CHECK(m.colors[4 * q] == kColors[q]);
    // Too few points for the rows asked for: only whole rows that fit.
    buildVertexShapeMesh(makeQuadMeshTopology(4, 3, 0, 10), a, m);
    CHECK(m.positions.size() == 3u * 4u);
}

TEST_CASE("a quad mesh winds its quads as Coin's quad strips do") {
    // Coin sends (r, c) then (r+1, c) along a row's GL_QUAD_STRIP, so each quad runs (r, c)
    // (r+1, c) (r+1, c+1) (r, c+1): with x along a row and y down the columns that is
    // clockwise seen from +z, and SOLID culls the side facing +z.
    const std::vector<glm::vec3> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    VertexAttributes a;
    a.points = points;
    Mesh m;
    buildVertexShapeMesh(makeQuadMeshTopology(2, 2, 0, points.size()), a, m);
    REQUIRE(m.positions.size() == 4u);
    for (const glm::vec3& n : m.normals)
        CHECK(glm::length(n - glm::vec3(0, 0, -1)) < 1e-6f);
    REQUIRE(m.indices.size() == 6u);
    const glm::vec3 e1 = m.positions[m.indices[1]] - m.positions[m.indices[0]];
    const glm::vec3 e2 = m.positions[m.indices[2]] - m.positions[m.indices[0]];
    CHECK(glm::cross(e1, e2).z < 0.0f);
}

TEST_CASE("line sets: PER_PART is per segment, PER_FACE per polyline") {
    const std::vector<glm::vec3> points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    const std::vector<std::int32_t> counts = {3, 2};
    VertexAttributes a;
    a.points = points;
    a.colors = kColors;
    Mesh m;
    a.materialBinding = Binding::PerPart;
    buildVertexShapeMesh(makeLineSetTopology(counts, 0, points.size()), a, m);
    CHECK(m.primitive == Mesh::Primitive::Lines);
    REQUIRE(m.indices.size() == 6u); // 3 segments
    CHECK(m.colors[m.indices[0]] == kColors[0]);
    CHECK(m.colors[m.indices[2]] == kColors[1]);
    CHECK(m.colors[m.indices[4]] == kColors[2]);
    a.materialBinding = Binding::PerFace;
    buildVertexShapeMesh(makeLineSetTopology(counts, 0, points.size()), a, m);
    CHECK(m.colors[m.indices[0]] == kColors[0]);
    CHECK(m.colors[m.indices[2]] == kColors[0]);
    CHECK(m.colors[m.indices[4]] == kColors[1]);
    CHECK(m.normals.empty());
}

TEST_CASE("a point set draws numPoints points from startIndex") {
    const std::vector<glm::vec3> points(10, glm::vec3(0.0f));
    VertexAttributes a;
    a.points = points;
    Mesh m;
    buildVertexShapeMesh(makePointSetTopology(4, 3, points.size()), a, m);
    CHECK(m.primitive == Mesh::Primitive::Points);
    CHECK(m.indices.size() == 4u);
    buildVertexShapeMesh(makePointSetTopology(-1, 3, points.size()), a, m);
    CHECK(m.indices.size() == 7u);
    buildVertexShapeMesh(makePointSetTopology(100, 8, points.size()), a, m);
    CHECK(m.indices.size() == 2u); // never beyond the points
}

TEST_CASE("face sets take numVertices consecutive points, -1 takes the rest") {
    VertexAttributes a;
    a.points = kCubePoints;
    const std::vector<std::int32_t> counts = {4, -1};
    Mesh m;
    buildVertexShapeMesh(makeFaceSetTopology(counts, 0, kCubePoints.size()), a, m);
    CHECK(m.positions.size() == 8u);
    CHECK(triangleArea(m) == doctest::Approx(2.0));
}

TEST_CASE("a concave polygon is cut into triangles covering exactly its area") {
    // A C of area 7: the 3x3 square without the unit cells (1..3, 1..2).
    const std::vector<glm::vec3> points = {{0, 0, 0}, {3, 0, 0}, {3, 1, 0}, {1, 1, 0},
                                           {1, 2, 0}, {3, 2, 0}, {3, 3, 0}, {0, 3, 0}};
    const std::vector<std::int32_t> index = {0, 1, 2, 3, 4, 5, 6, 7, -1};
    VertexAttributes a;
    a.points = points;
    Mesh m;
    a.convexFaces = false;
    buildVertexShapeMesh(makeIndexedFaceSetTopology(index, points.size()), a, m);
    CHECK(triangleArea(m) == doctest::Approx(7.0).epsilon(1e-12));
    // The same polygon fanned as if convex covers area outside it (the fan from corner 0
    // overlaps itself: 11 by hand), which is why SoShapeHints faceType matters.
    a.convexFaces = true;
    buildVertexShapeMesh(makeIndexedFaceSetTopology(index, points.size()), a, m);
    CHECK(triangleArea(m) == doctest::Approx(11.0));
}

TEST_CASE("given normals bind by coordIndex, normalIndex or per face, too few generate") {
    const ShapeTopology t = makeIndexedFaceSetTopology(kCubeFaces, kCubePoints.size());
    VertexAttributes a;
    a.points = kCubePoints;
    const std::vector<glm::vec3> up(6, glm::vec3(0, 1, 0));
    a.normals = up;
    a.normalBinding = Binding::PerFace;
    Mesh m;
    buildVertexShapeMesh(t, a, m);
    for (const auto& n : m.normals)
        CHECK(n == glm::vec3(0, 1, 0));
    // PER_VERTEX_INDEXED with normalIndex [-1]: one per point, and there are only 6 of 8.
    a.normalBinding = Binding::PerVertexIndexed;
    buildVertexShapeMesh(t, a, m);
    CHECK(m.normals[0] != glm::vec3(0, 1, 0)); // generated instead
}

TEST_CASE("texture coordinates: given, plane functions and Coin's default mapping") {
    VertexAttributes a;
    a.points = kCubePoints;
    const ShapeTopology t = makeIndexedFaceSetTopology(kCubeFaces, kCubePoints.size());
    Mesh m;
    a.defaultTextureCoords = true;
    buildVertexShapeMesh(t, a, m);
    REQUIRE(m.texCoords.size() == m.positions.size());
    for (std::size_t v = 0; v < m.positions.size(); ++v) // a cube's ties: s along z, t along y
        CHECK(m.texCoords[v] == glm::vec2(m.positions[v].z, m.positions[v].y));
    // Coin (SoTextureCoordinateBundle::initDefaultCallback): the two larger axes, the longer
    // first, each over its own side.
    CHECK(defaultTextureCoord({1, 2, 3}, {0, 0, 0}, {2, 4, 1}) == glm::vec2(0.5f, 0.5f));
    CHECK(defaultTextureCoord({1, 2, 3}, {0, 0, 0}, {4, 2, 1}) == glm::vec2(0.25f, 1.0f));
    CHECK(defaultTextureCoord({1, 2, 3}, {0, 0, 0}, {4, 0, 8}) == glm::vec2(0.375f, 0.25f));
    a.planeTextureCoords = true;
    a.planeS = {0, 0, 2};
    a.planeT = {1, 1, 0};
    buildVertexShapeMesh(t, a, m);
    for (std::size_t v = 0; v < m.positions.size(); ++v)
        CHECK(m.texCoords[v] ==
              glm::vec2(2 * m.positions[v].z, m.positions[v].x + m.positions[v].y));
}

TEST_CASE("bad indices and counts leave shapes out, never read beyond the points") {
    VertexAttributes a;
    a.points = kCubePoints;
    const std::vector<std::int32_t> bad = {0, 1, 99, -1, 0, 1, 2, -1, 0, -7, 2, 3};
    Mesh m;
    buildVertexShapeMesh(makeIndexedFaceSetTopology(bad, kCubePoints.size()), a, m);
    CHECK(m.positions.size() == 3u); // only the middle triangle
    const std::vector<std::int32_t> counts = {3, -5, 1000000};
    buildVertexShapeMesh(makeFaceSetTopology(counts, -4, kCubePoints.size()), a, m);
    CHECK(m.positions.size() == 8u); // 3, then the remaining 5 as one polygon
    buildVertexShapeMesh(makeTriangleStripSetTopology(counts, 1 << 30, kCubePoints.size()), a, m);
    CHECK(m.positions.empty());
}

TEST_CASE("a quad mesh's generated normals are smooth whatever the crease angle") {
    // A 3 x 2 grid folded along x = 1 like a roof: the ridge vertices average both slopes.
    const std::vector<glm::vec3> points = {{0, 0, 0}, {1, 1, 0}, {2, 0, 0},
                                           {0, 0, 1}, {1, 1, 1}, {2, 0, 1}};
    VertexAttributes a;
    a.points = points;
    Mesh m;
    buildVertexShapeMesh(makeQuadMeshTopology(3, 2, 0, points.size()), a, m);
    REQUIRE(m.positions.size() == 8u);
    for (std::size_t v = 0; v < m.positions.size(); ++v) {
        const glm::vec3 n = glm::abs(m.normals[v]);
        if (m.positions[v].x == 1.0f) // the ridge: straight up
            CHECK(glm::length(n - glm::vec3(0, 1, 0)) < 1e-6f);
        else // the eaves: their own slope
            CHECK(glm::length(n - glm::vec3(1, 1, 0) / std::sqrt(2.0f)) < 1e-6f);
    }
}
