// Meshes of the shape nodes against Inventor's geometry: sizes, vertex placement, normals,
// winding, parts, and the indexed shapes' index and normal rules.
#include <doctest/doctest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <numbers>

#include <volsg/geometry/PrimitiveMeshes.h>
#include <volsg/geometry/VertexShapes.h>
#include <volsg/nodes/Complexity.h>
#include <volsg/nodes/Cone.h>
#include <volsg/nodes/Coordinate3.h>
#include <volsg/nodes/Cube.h>
#include <volsg/nodes/Cylinder.h>
#include <volsg/nodes/IndexedFaceSet.h>
#include <volsg/nodes/IndexedLineSet.h>
#include <volsg/nodes/Normal.h>
#include <volsg/nodes/Sphere.h>
#include <volsg/state/State.h>

using namespace volsg;

namespace {

glm::dvec3 d(const glm::vec3& v) {
    return glm::dvec3(v);
}

/// Every normal has unit length and every triangle turns counter-clockwise around the normals
/// of its corners (outward winding); returns the number of violations.
int windingAndNormalErrors(const Mesh& m) {
    int errors = 0;
    for (const auto& n : m.normals)
        if (std::abs(glm::length(d(n)) - 1.0) > 1e-6) ++errors;
    for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3) {
        const auto a = m.indices[i], b = m.indices[i + 1], c = m.indices[i + 2];
        const glm::dvec3 geometric = glm::cross(d(m.positions[b]) - d(m.positions[a]),
                                                d(m.positions[c]) - d(m.positions[a]));
        const glm::dvec3 shading = d(m.normals[a]) + d(m.normals[b]) + d(m.normals[c]);
        if (!(glm::dot(geometric, shading) > 0.0)) ++errors;
    }
    return errors;
}

bool indicesInRange(const Mesh& m) {
    for (auto i : m.indices)
        if (i >= m.positions.size()) return false;
    return true;
}

ref_ptr<Coordinate3> coordinates(std::vector<glm::vec3> points) {
    auto c = Coordinate3::create();
    c->point.setValues(std::move(points));
    return c;
}

/// The unit square in z = 0, counter-clockwise seen from +Z.
std::vector<glm::vec3> unitSquare() {
    return {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
}

} // namespace

TEST_CASE("default cube is 12 triangles spanning minus one to one") {
    auto cube = Cube::create();
    State state;
    const Mesh& m = cube->mesh(state);
    CHECK(m.primitive == Mesh::Primitive::Triangles);
    CHECK(m.primitiveCount() == 12);
    CHECK(m.positions.size() == 24);
    CHECK(m.normals.size() == 24);
    CHECK(indicesInRange(m));
    const Box3 b = m.bounds();
    CHECK(b.min == glm::dvec3(-1.0));
    CHECK(b.max == glm::dvec3(1.0));
    CHECK(windingAndNormalErrors(m) == 0);
}

TEST_CASE("cube faces are flat with outward axis normals at half the size") {
    auto cube = Cube::create();
    cube->width = 4.0f;
    cube->height = 2.0f;
    cube->depth = 6.0f;
    State state;
    const Mesh& m = cube->mesh(state);
    const glm::dvec3 half(2.0, 1.0, 3.0);
    CHECK(m.bounds().min == -half);
    CHECK(m.bounds().max == half);
    int facesPerAxis[3] = {0, 0, 0};
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        const glm::dvec3 n = d(m.normals[i]);
        int axis = -1;
        for (int a = 0; a < 3; ++a)
            if (std::abs(n[a]) == 1.0) axis = a;
        REQUIRE(axis >= 0);
        CHECK(glm::length(n) == 1.0); // exactly an axis
        // The vertex lies on the face plane the normal points out of.
        CHECK(d(m.positions[i])[axis] == n[axis] * half[axis]);
        ++facesPerAxis[axis];
    }
    CHECK(facesPerAxis[0] == 8); // two faces of four corners per axis
    CHECK(facesPerAxis[1] == 8);
    CHECK(facesPerAxis[2] == 8);
    CHECK(windingAndNormalErrors(m) == 0);
}

TEST_CASE("sphere vertices lie at the radius with radial unit normals") {
    auto sphere = Sphere::create();
    sphere->radius = 2.5f;
    State state;
    const Mesh& m = sphere->mesh(state);
    // Coin's sphere at complexity 0.5: 15 slices, 15 rings pole to pole (14 bands).
    CHECK(m.primitiveCount() == std::size_t(2 * 15 * (14 - 1)));
    CHECK(indicesInRange(m));
    double worstRadius = 0.0, worstNormal = 0.0;
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        const glm::dvec3 p = d(m.positions[i]);
        worstRadius = std::max(worstRadius, std::abs(glm::length(p) - 2.5));
        worstNormal = std::max(worstNormal, glm::length(d(m.normals[i]) - p / 2.5));
    }
    CHECK(worstRadius <= 1e-6);
    CHECK(worstNormal <= 1e-6);
    // The poles are exact; around Y the 15 slices reach the radius only at their vertices.
    const double sag = 2.5 * (1.0 - std::cos(std::numbers::pi / 15));
    CHECK(m.bounds().min.y == doctest::Approx(-2.5).epsilon(1e-7));
    CHECK(m.bounds().max.y == doctest::Approx(2.5).epsilon(1e-7));
    for (int axis : {0, 2}) {
        CHECK(m.bounds().min[axis] <= -2.5 + sag);
        CHECK(m.bounds().max[axis] >= 2.5 - sag);
    }
    CHECK(windingAndNormalErrors(m) == 0);
}

TEST_CASE("sphere triangles stay within the stated tessellation error") {
    // PrimitiveMeshes.h: the surface is at most r * (1 - cos(pi/slices) * cos(pi/(2 stacks)))
    // inside the true sphere; that is the distance of each triangle's plane from the centre.
    Mesh m;
    const int slices = 15, stacks = 14;
    buildSphereMesh(1.0f, slices, stacks, m);
    const double bound =
        1.0 - std::cos(std::numbers::pi / slices) * std::cos(std::numbers::pi / (2 * stacks));
    double worst = 0.0;
    for (std::size_t i = 0; i < m.indices.size(); i += 3) {
        const glm::dvec3 a = d(m.positions[m.indices[i]]), b = d(m.positions[m.indices[i + 1]]),
                         c = d(m.positions[m.indices[i + 2]]);
        const glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
        worst = std::max(worst, 1.0 - glm::dot(n, a));
    }
    CHECK(worst <= bound + 1e-7);
    CHECK(worst > 0.5 * bound); // the bound is not vacuous
}

TEST_CASE("cone apex is at half the height above a base circle of the bottom radius") {
    auto cone = Cone::create();
    cone->bottomRadius = 1.5f;
    cone->height = 3.0f;
    State state;
    const Mesh& m = cone->mesh(state);
    CHECK(indicesInRange(m));
    CHECK(windingAndNormalErrors(m) == 0);
    const Box3 b = m.bounds();
    CHECK(b.min.y == -1.5);
    CHECK(b.max.y == 1.5);
    CHECK(b.max.x == doctest::Approx(1.5).epsilon(1e-7));
    CHECK(b.min.z == doctest::Approx(-1.5).epsilon(1e-7));
    // Side normals lean up by atan(r/h): n.y = r / sqrt(r^2 + h^2).
    const double sideNy = 1.5 / std::sqrt(1.5 * 1.5 + 3.0 * 3.0);
    int apexCount = 0, baseCount = 0, bottomCount = 0;
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        const glm::dvec3 p = d(m.positions[i]), n = d(m.normals[i]);
        if (n == glm::dvec3(0, -1, 0)) {
            ++bottomCount;
            CHECK(p.y == -1.5);
            continue;
        }
        CHECK(n.y == doctest::Approx(sideNy).epsilon(1e-6));
        if (p.y == 1.5) {
            ++apexCount;
            CHECK(glm::length(glm::dvec2(p.x, p.z)) == 0.0);
        } else {
            ++baseCount;
            CHECK(p.y == -1.5);
            CHECK(glm::length(glm::dvec2(p.x, p.z)) == doctest::Approx(1.5).epsilon(1e-6));
            // Side normal points away from the axis, in the vertex's direction.
            CHECK(glm::dot(glm::dvec2(n.x, n.z), glm::dvec2(p.x, p.z)) > 0.0);
        }
    }
    const int sides = 20; // Coin's cone at complexity 0.5
    CHECK(apexCount == sides);
    CHECK(baseCount == sides + 1);
    CHECK(bottomCount == sides + 2); // centre plus the closed ring
    CHECK(m.primitiveCount() == std::size_t(2 * sides));
}

constexpr int kDefaultSides = 20; // cones and cylinders at complexity 0.5, as Coin's

TEST_CASE("cone parts bit mask selects sides and bottom") {
    auto cone = Cone::create();
    State state;
    cone->parts.setValue(Cone::SIDES);
    const Mesh& sides = cone->mesh(state);
    CHECK(sides.primitiveCount() == std::size_t(kDefaultSides));
    for (const auto& n : sides.normals)
        CHECK(n.y > 0.0f);

    cone->parts.setValue(Cone::BOTTOM);
    const Mesh& bottom = cone->mesh(state);
    CHECK(bottom.primitiveCount() == std::size_t(kDefaultSides));
    for (const auto& n : bottom.normals)
        CHECK(n == glm::vec3(0, -1, 0));
    CHECK(windingAndNormalErrors(bottom) == 0);

    cone->parts.setValue(0);
    CHECK(cone->mesh(state).primitiveCount() == 0);
}

TEST_CASE("cylinder parts select sides top and bottom with the right normals") {
    auto cylinder = Cylinder::create();
    cylinder->radius = 0.5f;
    cylinder->height = 4.0f;
    State state;
    const Mesh& all = cylinder->mesh(state);
    CHECK(all.primitiveCount() == std::size_t(4 * kDefaultSides));
    CHECK(windingAndNormalErrors(all) == 0);
    CHECK(all.bounds().min.y == -2.0);
    CHECK(all.bounds().max.y == 2.0);
    CHECK(all.bounds().max.z == doctest::Approx(0.5).epsilon(1e-7));
    for (std::size_t i = 0; i < all.positions.size(); ++i) {
        const glm::dvec3 p = d(all.positions[i]), n = d(all.normals[i]);
        if (n.y == 0.0) { // side: radial normal at the radius
            CHECK(glm::length(glm::dvec2(p.x, p.z)) == doctest::Approx(0.5).epsilon(1e-6));
            CHECK(glm::length(glm::dvec2(n.x, n.z) - glm::dvec2(p.x, p.z) / 0.5) <= 1e-6);
        } else {
            CHECK(std::abs(n.y) == 1.0);
            CHECK(p.y == 2.0 * n.y); // top faces up at +h/2, bottom down at -h/2
        }
    }

    cylinder->parts.setValue(Cylinder::TOP);
    const Mesh& top = cylinder->mesh(state);
    CHECK(top.primitiveCount() == std::size_t(kDefaultSides));
    for (const auto& n : top.normals)
        CHECK(n == glm::vec3(0, 1, 0));
    CHECK(windingAndNormalErrors(top) == 0);

    cylinder->parts.setValue(Cylinder::SIDES | Cylinder::BOTTOM);
    const Mesh& sidesBottom = cylinder->mesh(state);
    CHECK(sidesBottom.primitiveCount() == std::size_t(3 * kDefaultSides));
    for (const auto& n : sidesBottom.normals)
        CHECK(n.y <= 0.0f);
}

TEST_CASE("round primitives take Coin's slice counts for a complexity value") {
    // SoSphere: (int)(30 c) slices and rings (c clamped to [0, 1]), at least 4 slices and 3
    // rings; SoCone, SoCylinder: (int)(40 c) sides, 4 to 128 (c not clamped).
    CHECK(sphereSlicesFor(0.5f) == 15);
    CHECK(sphereStacksFor(0.5f) == 14);
    CHECK(sphereSlicesFor(1.0f) == 30);
    CHECK(sphereStacksFor(1.0f) == 29);
    CHECK(sphereSlicesFor(0.0f) == 4);
    CHECK(sphereStacksFor(0.0f) == 2);
    CHECK(sphereSlicesFor(7.0f) == 30);
    CHECK(roundSlicesFor(0.5f) == 20);
    CHECK(roundSlicesFor(0.3f) == 12);
    CHECK(roundSlicesFor(1.0f) == 40);
    CHECK(roundSlicesFor(2.0f) == 80);
    CHECK(roundSlicesFor(100.0f) == 128);
    CHECK(roundSlicesFor(-1.0f) == 4);
    CHECK(roundSlicesFor(std::nanf("")) == 20);

    auto complexity = Complexity::create();
    complexity->value = 0.2f;
    auto cone = Cone::create();
    cone->parts.setValue(Cone::SIDES);
    State state;
    state.add(*complexity);
    CHECK(cone->mesh(state).primitiveCount() == 8);
    complexity->type.setValue(Complexity::BOUNDING_BOX); // Coin's render takes 0.5
    CHECK(cone->mesh(state).primitiveCount() == 20);
}

TEST_CASE("SCREEN_SPACE complexity follows the projected size as Coin's") {
    // An orthographic view 20 units across on 500 x 500 pixels: 25 pixels a unit. Coin's
    // value: sqrt(the larger side of the projected box in pixels) * 0.4 * value.
    auto complexity = Complexity::create();
    complexity->type.setValue(Complexity::SCREEN_SPACE);
    complexity->value = 0.5f;
    auto sphere = Sphere::create();
    State state;
    state.add(*complexity);
    StateView view;
    view.projected = true;
    view.projection = glm::dmat4(1.0);
    view.projection[0][0] = view.projection[1][1] = view.projection[2][2] = 0.1;
    view.width = view.height = 500;
    state.setView(view);
    // Radius 0.1: 5 pixels, sqrt(5) * 0.2 = 0.447: 13 slices, 13 rings (12 bands).
    sphere->radius = 0.1f;
    CHECK(sphere->mesh(state).primitiveCount() == std::size_t(2 * 13 * (12 - 1)));
    // Radius 1: 50 pixels, 1.41 clamped to 1: 30 x 29.
    sphere->radius = 1.0f;
    CHECK(sphere->mesh(state).primitiveCount() == std::size_t(2 * 30 * (29 - 1)));
    state.setModelMatrix(glm::scale(glm::dmat4(1.0), glm::dvec3(0.2)));
    // 10 pixels: sqrt(10) * 0.2 = 0.632: 18 slices, 18 rings.
    CHECK(sphere->mesh(state).primitiveCount() == std::size_t(2 * 18 * (17 - 1)));
    // A cone of radius 1 and height 2 at that scale: 10 pixels, 0.632 * 40 = 25 sides.
    auto cone = Cone::create();
    cone->parts.setValue(Cone::SIDES);
    CHECK(cone->mesh(state).primitiveCount() == 25);
}

TEST_CASE("shape mesh is rebuilt when a field changes") {
    auto sphere = Sphere::create();
    State state;
    CHECK(sphere->mesh(state).bounds().max.y == doctest::Approx(1.0).epsilon(1e-7));
    sphere->radius = 3.0f;
    CHECK(sphere->mesh(state).bounds().max.y == doctest::Approx(3.0).epsilon(1e-7));
}

TEST_CASE("face set quad gives two triangles with the Newell normal") {
    auto coords = coordinates(unitSquare());
    auto faces = IndexedFaceSet::create();
    faces->coordIndex.setValues({0, 1, 2, 3, -1});
    State state;
    state.add(*coords);
    const Mesh& m = faces->mesh(state);
    CHECK(m.primitiveCount() == 2);
    CHECK(indicesInRange(m));
    for (const auto& n : m.normals)
        CHECK(n == glm::vec3(0, 0, 1));
    CHECK(windingAndNormalErrors(m) == 0);
    CHECK(m.bounds().min == glm::dvec3(0, 0, 0));
    CHECK(m.bounds().max == glm::dvec3(1, 1, 0));
    // Clockwise order flips the normal: the winding is kept.
    faces->coordIndex.setValues({3, 2, 1, 0, -1});
    for (const auto& n : faces->mesh(state).normals)
        CHECK(n == glm::vec3(0, 0, -1));
}

TEST_CASE("face set splits polygons at minus one and counts a final polygon without it") {
    auto coords = coordinates({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5f, 2, 0}});
    auto faces = IndexedFaceSet::create();
    faces->coordIndex.setValues({0, 1, 2, -1, 0, 2, 3, -1, -1, 3, 2, 4});
    State state;
    state.add(*coords);
    const Mesh& m = faces->mesh(state);
    CHECK(m.primitiveCount() == 3);
    CHECK(m.positions.size() == 9);
    CHECK(m.bounds().max.y == 2.0);

    // A pentagon fans into three triangles around its first corner.
    faces->coordIndex.setValues({0, 1, 2, 4, 3});
    const Mesh& pentagon = faces->mesh(state);
    CHECK(pentagon.primitiveCount() == 3);
    for (std::size_t i = 0; i < pentagon.indices.size(); i += 3)
        CHECK(pentagon.positions[pentagon.indices[i]] == glm::vec3(0, 0, 0));
}

TEST_CASE("face set skips polygons with bad indices and keeps the rest") {
    auto coords = coordinates(unitSquare());
    auto faces = IndexedFaceSet::create();
    State state;
    state.add(*coords);
    faces->coordIndex.setValues({0, 1, 2, -1, 0, 1, 99, -1, 0, -5, 2, -1, 0, 2, 3, -1, 1, 2});
    const Mesh& m = faces->mesh(state);
    CHECK(m.primitiveCount() == 2); // the polygons with 99, -5 and only two corners are dropped
    CHECK(indicesInRange(m));

    for (std::vector<std::int32_t> bad : {std::vector<std::int32_t>{},
                                          {-1},
                                          {-1, -1, -1},
                                          {2147483647, 0, 1},
                                          {-2147483647 - 1},
                                          {0, 1},
                                          {4, 5, 6, 7}}) {
        faces->coordIndex.setValues(bad);
        const Mesh& empty = faces->mesh(state);
        CHECK(empty.primitiveCount() == 0);
        CHECK(empty.positions.empty());
    }

    // Normals that do not cover every corner (an index beyond them, or normalIndex too short)
    // are not used: the shape keeps all its polygons and generates its normals, as Coin does
    // when the normals in scope do not fit the shape.
    auto normals = Normal::create();
    normals->vector.setValues({{1, 0, 0}});
    state.add(*normals);
    faces->coordIndex.setValues({0, 1, 2, -1, 0, 2, 3, -1});
    for (std::vector<std::int32_t> normalIndex :
         {std::vector<std::int32_t>{0, 0, 0, -1, 0, 7, 0, -1}, {0, 0, 0}}) {
        faces->normalIndex.setValues(normalIndex);
        const Mesh& m = faces->mesh(state);
        CHECK(m.primitiveCount() == 2);
        for (const glm::vec3& n : m.normals)
            CHECK(std::abs(n.z) == doctest::Approx(1.0)); // the square's own, not (1, 0, 0)
    }
    faces->normalIndex.setValues({0, 0, 0, -1, 0, 0, 0, -1}); // covering: used as given
    for (const glm::vec3& n : faces->mesh(state).normals)
        CHECK(n == glm::vec3(1, 0, 0));
}

TEST_CASE("face set without coordinates in scope is empty") {
    auto faces = IndexedFaceSet::create();
    faces->coordIndex.setValues({0, 1, 2, -1});
    State state;
    CHECK(faces->mesh(state).primitiveCount() == 0);
}

TEST_CASE("face set takes normals by normal index then by coord index else flat") {
    auto coords = coordinates(unitSquare());
    auto normals = Normal::create();
    // Not unit length on purpose: normals are normalized.
    normals->vector.setValues({{0, 0, 2}, {0, 3, 0}, {4, 0, 0}, {0, 0, -5}});
    auto faces = IndexedFaceSet::create();
    faces->coordIndex.setValues({0, 1, 2, 3, -1});
    State state;
    state.add(*coords);
    state.add(*normals);

    // 1. normalIndex parallel to coordIndex.
    faces->normalIndex.setValues({2, 2, 1, 1, -1});
    const Mesh& indexed = faces->mesh(state);
    REQUIRE(indexed.normals.size() == 4);
    CHECK(indexed.normals[0] == glm::vec3(1, 0, 0));
    CHECK(indexed.normals[1] == glm::vec3(1, 0, 0));
    CHECK(indexed.normals[2] == glm::vec3(0, 1, 0));
    CHECK(indexed.normals[3] == glm::vec3(0, 1, 0));

    // 2. Default normalIndex [-1]: normal i goes with point i.
    faces->normalIndex.setValues({-1});
    faces->coordIndex.setValues({3, 0, 1, 2, -1});
    const Mesh& byCoord = faces->mesh(state);
    REQUIRE(byCoord.normals.size() == 4);
    CHECK(byCoord.normals[0] == glm::vec3(0, 0, -1));
    CHECK(byCoord.normals[1] == glm::vec3(0, 0, 1));
    CHECK(byCoord.normals[2] == glm::vec3(0, 1, 0));
    CHECK(byCoord.normals[3] == glm::vec3(1, 0, 0));

    // 3. Too few normals for the points used: flat normals.
    normals->vector.setValues({{1, 0, 0}, {1, 0, 0}});
    const Mesh& flat = faces->mesh(state);
    REQUIRE(flat.normals.size() == 4);
    for (const auto& n : flat.normals)
        CHECK(n == glm::vec3(0, 0, 1));
}

TEST_CASE("face set Newell normal of a tilted pentagon is the plane normal") {
    // A regular pentagon in the plane through the origin with normal (1, 2, 2) / 3.
    const glm::dvec3 n = glm::dvec3(1, 2, 2) / 3.0;
    const glm::dvec3 u = glm::normalize(glm::cross(n, glm::dvec3(0, 0, 1)));
    const glm::dvec3 v = glm::cross(n, u);
    std::vector<glm::vec3> points;
    for (int k = 0; k < 5; ++k) {
        const double a = 2.0 * std::numbers::pi * k / 5;
        points.emplace_back(std::cos(a) * u + std::sin(a) * v);
    }
    Mesh m;
    const std::vector<std::int32_t> index = {0, 1, 2, 3, 4};
    VertexAttributes attributes;
    attributes.points = points;
    buildVertexShapeMesh(makeIndexedFaceSetTopology(index, points.size()), attributes, m);
    CHECK(m.primitiveCount() == 3);
    for (const auto& normal : m.normals)
        CHECK(glm::length(d(normal) - n) <= 1e-6);
}

TEST_CASE("face set mesh follows the Coordinate3 in scope") {
    auto a = coordinates(unitSquare());
    auto b = coordinates({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}});
    auto faces = IndexedFaceSet::create();
    faces->coordIndex.setValues({0, 1, 2, 3, -1});
    State withA, withB;
    withA.add(*a);
    withB.add(*b);
    CHECK(faces->mesh(withA).bounds().max.x == 1.0);
    CHECK(faces->mesh(withB).bounds().max.x == 2.0); // another node in scope
    CHECK(faces->mesh(withA).bounds().max.x == 1.0);
    a->point.set1Value(1, glm::vec3(5, 0, 0)); // the same node, changed
    CHECK(faces->mesh(withA).bounds().max.x == 5.0);
}

TEST_CASE("line set makes segments from polylines split at minus one") {
    auto coords = coordinates(unitSquare());
    auto lines = IndexedLineSet::create();
    lines->coordIndex.setValues({0, 1, 2, -1, 2, 3, -1, 0, 9, -1, 3});
    State state;
    state.add(*coords);
    const Mesh& m = lines->mesh(state);
    CHECK(m.primitive == Mesh::Primitive::Lines);
    CHECK(m.primitiveCount() == 3); // 2 + 1; the polyline with 9 and the lone point give none
    CHECK(m.normals.empty());
    CHECK(indicesInRange(m));
    REQUIRE(m.indices.size() == 6);
    CHECK(m.positions[m.indices[0]] == glm::vec3(0, 0, 0));
    CHECK(m.positions[m.indices[1]] == glm::vec3(1, 0, 0));
    CHECK(m.positions[m.indices[4]] == glm::vec3(1, 1, 0));
    CHECK(m.positions[m.indices[5]] == glm::vec3(0, 1, 0));
    coords->point.setValues({{0, 0, 0}});
    CHECK(lines->mesh(state).primitiveCount() == 0);
}
