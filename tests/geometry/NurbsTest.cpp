// NURBS curves and surfaces against closed forms: bilinear patches, an exact rational quarter
// cylinder, a quadratic Bezier parabola, trimmed areas, Coin's sampling, and garbage that must
// draw nothing (or give one Error naming the node) and never crash.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <string>

#include <volsg/core/Error.h>
#include <volsg/geometry/Nurbs.h>
#include <volsg/geometry/PolygonTessellator.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/Complexity.h>
#include <volsg/nodes/Coordinate3.h>
#include <volsg/nodes/Coordinate4.h>
#include <volsg/nodes/NurbsCurve.h>
#include <volsg/nodes/NurbsSurface.h>
#include <volsg/nodes/Profile.h>
#include <volsg/nodes/ProfileCoordinate2.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/Shape.h>
#include <volsg/state/State.h>

using namespace volsg;

namespace {

double triangleArea(const Mesh& m) {
    double area = 0.0;
    for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3) {
        const glm::dvec3 a(m.positions[m.indices[i]]), b(m.positions[m.indices[i + 1]]),
            c(m.positions[m.indices[i + 2]]);
        area += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    return area;
}

bool indicesInRange(const Mesh& m) {
    for (auto i : m.indices)
        if (i >= m.positions.size()) return false;
    return true;
}

/// The mesh of the last shape of a Separator, built with the state its children set.
const Mesh& shapeMesh(Separator& root) {
    State state;
    Shape* shape = nullptr;
    for (const auto& child : *root.children()) {
        if (child->isA<Shape>())
            shape = static_cast<Shape*>(child.get());
        else
            state.add(*child);
    }
    REQUIRE(shape);
    return shape->mesh(state);
}

ref_ptr<Node> read(const std::string& body) {
    return readSceneFromString("#Inventor V2.1 ascii\nSeparator {\n" + body + "\n}\n", "<test>");
}

const Mesh& meshOf(const ref_ptr<Node>& root) {
    return shapeMesh(static_cast<Separator&>(*root));
}

/// A flat 4 x 4 square over the parameter square [0, 1]^2 (degree 1, 2 x 2 points).
const char* kFlatSquare = R"(
  Coordinate3 { point [ 0 0 0, 4 0 0, 0 4 0, 4 4 0 ] }
)";
const char* kFlatSurface = R"(
  NurbsSurface { numUControlPoints 2 numVControlPoints 2
                 uKnotVector [ 0, 0, 1, 1 ] vKnotVector [ 0, 0, 1, 1 ] }
)";

} // namespace

TEST_CASE("a degree-1 NurbsSurface of 2 x 2 points is the bilinear patch") {
    SUBCASE("planar corners: every vertex on the plane, the area of the square") {
        const auto root = read(std::string(kFlatSquare) + kFlatSurface);
        const Mesh& m = meshOf(root);
        REQUIRE(m.primitive == Mesh::Primitive::Triangles);
        REQUIRE(m.indices.size() >= 6);
        CHECK(indicesInRange(m));
        for (const auto& p : m.positions)
            CHECK(p.z == 0.0f);
        CHECK(triangleArea(m) == doctest::Approx(16.0).epsilon(1e-9));
        for (const auto& n : m.normals) // dS/du x dS/dv: +z for this orientation
            CHECK(glm::length(glm::dvec3(n) - glm::dvec3(0, 0, 1)) < 1e-6);
    }
    SUBCASE("a twisted patch: vertices on z = x y / 4 at a fine complexity") {
        const auto root = read(R"(
          Complexity { value 1 }
          Coordinate3 { point [ 0 0 0, 2 0 0, 0 2 0, 2 2 1 ] }
          NurbsSurface { numUControlPoints 2 numVControlPoints 2
                         uKnotVector [ 0, 0, 1, 1 ] vKnotVector [ 0, 0, 1, 1 ] }
        )");
        const Mesh& m = meshOf(root);
        REQUIRE(!m.positions.empty());
        for (const auto& p : m.positions)
            CHECK(std::abs(double(p.z) - double(p.x) * double(p.y) / 4.0) < 1e-6);
    }
}

TEST_CASE("a rational degree-2 NurbsSurface that is an exact quarter cylinder stays on radius 1") {
    // The quarter circle from (1, 0) to (0, 1) with the middle point (1, 1) of weight
    // sqrt(2)/2 (Coordinate4 holds w * point, w), swept along z from 0 to 2.
    const double w = std::sqrt(0.5);
    std::vector<glm::vec4> points;
    for (const float z : {0.0f, 2.0f}) {
        points.emplace_back(1.0f, 0.0f, z, 1.0f);
        points.emplace_back(float(w), float(w), float(w) * z, float(w));
        points.emplace_back(0.0f, 1.0f, z, 1.0f);
    }
    auto root = Separator::create();
    auto complexity = Complexity::create();
    complexity->value = 1.0f;
    auto coords = Coordinate4::create();
    coords->point.setValues(points);
    auto surface = NurbsSurface::create();
    surface->numUControlPoints = 3;
    surface->numVControlPoints = 2;
    surface->uKnotVector.setValues({0, 0, 0, 1, 1, 1});
    surface->vKnotVector.setValues({0, 0, 1, 1});
    root->addChild(complexity);
    root->addChild(coords);
    root->addChild(surface);
    const Mesh& m = shapeMesh(*root);
    REQUIRE(m.positions.size() > 8);
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        const glm::dvec3 p(m.positions[i]);
        CHECK(std::abs(std::hypot(p.x, p.y) - 1.0) < 1e-4);
        // The normal is radial (either way round).
        const glm::dvec3 n(m.normals[i]);
        CHECK(std::abs(std::abs(glm::dot(n, glm::normalize(glm::dvec3(p.x, p.y, 0.0)))) - 1.0) <
              1e-4);
    }
    // The area approaches the quarter cylinder's (pi/2 x 2) from below as chords do.
    const double area = triangleArea(m);
    CHECK(area < std::numbers::pi);
    CHECK(area > std::numbers::pi * 0.995);
}

TEST_CASE("a NurbsCurve that is a quadratic Bezier lies on its parabola") {
    // (-1, 1), (0, -1), (1, 1): x = 2t - 1, y = (2t - 1)^2.
    const auto root = read(R"(
      Coordinate3 { point [ -1 1 0, 0 -1 0, 1 1 0 ] }
      NurbsCurve { numControlPoints 3 knotVector [ 0, 0, 0, 1, 1, 1 ] }
    )");
    const Mesh& m = meshOf(root);
    CHECK(m.primitive == Mesh::Primitive::Lines);
    CHECK(m.normals.empty()); // unlit
    REQUIRE(m.positions.size() >= 3);
    CHECK(m.positions.size() == 11); // Coin: 10 steps per unit at Complexity 0.5
    for (const auto& p : m.positions)
        CHECK(std::abs(double(p.y) - double(p.x) * double(p.x)) < 1e-6);
    CHECK(glm::dvec3(m.positions.front()) == glm::dvec3(-1, 1, 0));
    CHECK(glm::dvec3(m.positions.back()) == glm::dvec3(1, 1, 0));
    CHECK(m.indices.size() == 2 * (m.positions.size() - 1));

    SUBCASE("indexed: the same curve through coordIndex") {
        const auto indexed = read(R"(
          Coordinate3 { point [ 9 9 9, 1 1 0, 0 -1 0, -1 1 0 ] }
          IndexedNurbsCurve { numControlPoints 3 coordIndex [ 3, 2, 1 ]
                              knotVector [ 0, 0, 0, 1, 1, 1 ] }
        )");
        const Mesh& mi = meshOf(indexed);
        REQUIRE(mi.positions.size() == m.positions.size());
        for (std::size_t i = 0; i < mi.positions.size(); ++i)
            CHECK(glm::length(glm::dvec3(mi.positions[i]) - glm::dvec3(m.positions[i])) < 1e-6);
    }
}

TEST_CASE("trim loops cut the parameter square as GLU does") {
    const std::string square = std::string(kFlatSquare);
    SUBCASE("an outer counter-clockwise loop and a clockwise square hole: full minus the hole") {
        for (const char* complexity : {"0", "0.5", "1"}) {
            const auto root =
                read("Complexity { value " + std::string(complexity) + " }" + square + R"(
              ProfileCoordinate2 { point [ 0 0, 1 0, 1 1, 0 1,
                                           0.25 0.25, 0.25 0.75, 0.75 0.75, 0.75 0.25 ] }
              LinearProfile { index [ 0, 1, 2, 3, 0 ] }
              LinearProfile { index [ 4, 5, 6, 7, 4 ] linkage START_NEW }
            )" + kFlatSurface);
            const Mesh& m = meshOf(root);
            CAPTURE(complexity);
            CHECK(indicesInRange(m));
            // 16 - (2 x 2): exact on a flat surface, whatever the sampling.
            CHECK(triangleArea(m) == doctest::Approx(12.0).epsilon(1e-9));
            // No triangle covers the hole's centre (2, 2).
            for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3) {
                const glm::dvec2 a(m.positions[m.indices[i]]), b(m.positions[m.indices[i + 1]]),
                    c(m.positions[m.indices[i + 2]]);
                const glm::dvec2 p(2.0, 2.0);
                auto side = [](glm::dvec2 u, glm::dvec2 v, glm::dvec2 q) {
                    return (v.x - u.x) * (q.y - u.y) - (q.x - u.x) * (v.y - u.y);
                };
                const bool inside = side(a, b, p) > 0 && side(b, c, p) > 0 && side(c, a, p) > 0;
                CHECK(!inside);
            }
        }
    }
    SUBCASE("a counter-clockwise loop alone keeps its inside; a clockwise one alone nothing") {
        const auto inner = read(square + R"(
          ProfileCoordinate2 { point [ 0.25 0.25, 0.75 0.25, 0.75 0.75, 0.25 0.75 ] }
          LinearProfile { index [ 0, 1, 2, 3, 0 ] }
        )" + kFlatSurface);
        CHECK(triangleArea(meshOf(inner)) == doctest::Approx(4.0).epsilon(1e-9));
        const auto hole = read(square + R"(
          ProfileCoordinate2 { point [ 0.25 0.25, 0.25 0.75, 0.75 0.75, 0.75 0.25 ] }
          LinearProfile { index [ 0, 1, 2, 3, 0 ] }
        )" + kFlatSurface);
        CHECK(meshOf(hole).indices.empty());
    }
    SUBCASE("ADD_TO_CURRENT continues a loop: two halves make the same square") {
        const auto root = read(square + R"(
          ProfileCoordinate2 { point [ 0.25 0.25, 0.75 0.25, 0.75 0.75, 0.25 0.75 ] }
          LinearProfile { index [ 0, 1, 2 ] }
          LinearProfile { index [ 2, 3, 0 ] linkage ADD_TO_CURRENT }
        )" + kFlatSurface);
        CHECK(triangleArea(meshOf(root)) == doctest::Approx(4.0).epsilon(1e-9));
    }
    SUBCASE("a circular NurbsProfile hole in a curved surface") {
        // Rational quadratic circle of radius 0.25 around (0.5, 0.5), clockwise (a hole), in
        // nine points; the outer boundary counter-clockwise.
        const double r = 0.25, w = std::sqrt(0.5);
        std::string circle;
        const double px[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, py[9] = {0, -1, -1, -1, 0, 1, 1, 1, 0};
        for (int i = 0; i < 9; ++i) {
            const double weight = i % 2 ? w : 1.0;
            circle += std::to_string((0.5 + r * px[i]) * weight) + " " +
                      std::to_string((0.5 + r * py[i]) * weight) + " " + std::to_string(weight) +
                      ", ";
        }
        // Through the nodes: the outer square and the circle in one ProfileCoordinate3
        // (profiles read the coordinates in scope at the surface, as in Inventor).
        const auto root = read(square + R"(
          Complexity { value 1 }
          ProfileCoordinate3 { point [ )" +
                               circle + R"( 0 0 1, 1 0 1, 1 1 1, 0 1 1 ] }
          LinearProfile { index [ 9, 10, 11, 12, 9 ] }
          NurbsProfile { index [ 0, 1, 2, 3, 4, 5, 6, 7, 8 ] linkage START_NEW
                         knotVector [ 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4 ] }
        )" + kFlatSurface);
        const double exactHole = std::numbers::pi * r * r;
        CHECK(triangleArea(meshOf(root)) ==
              doctest::Approx(16.0 * (1.0 - exactHole)).epsilon(2e-4));

        // Through the engine, against the shoelace area of the sampled circle.
        std::vector<std::vector<glm::dvec2>> loops{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
        std::vector<glm::dvec4> cp;
        for (int i = 0; i < 9; ++i) {
            const double weight = i % 2 ? w : 1.0;
            cp.emplace_back((0.5 + r * px[i]) * weight, (0.5 + r * py[i]) * weight, 0.0, weight);
        }
        const std::vector<float> knots{0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
        NurbsCurveData c{3, knots, cp};
        loops.push_back(sampleNurbsCurve2D(c, 64.0, 1 << 20));
        for (const auto& p : loops.back())
            CHECK(std::abs(glm::length(p - glm::dvec2(0.5)) - r) < 1e-9);
        // The hole's polygon area, by the shoelace formula.
        const double holeArea = std::abs(twiceSignedArea(loops.back())) / 2.0;
        CHECK(holeArea == doctest::Approx(std::numbers::pi * r * r).epsilon(1e-3));

        std::vector<glm::dvec4> flat{{0, 0, 0, 1}, {4, 0, 0, 1}, {0, 4, 0, 1}, {4, 4, 0, 1}};
        const std::vector<float> k01{0, 0, 1, 1};
        NurbsSurfaceData s;
        s.countU = s.countV = 2;
        s.knotsU = s.knotsV = k01;
        s.points = flat;
        NurbsSurfaceMeshOptions options;
        options.rateU = options.rateV = 7.0;
        options.trimLoops = loops;
        Mesh m;
        buildNurbsSurfaceMesh(s, options, m);
        CHECK(triangleArea(m) == doctest::Approx(16.0 * (1.0 - holeArea)).epsilon(1e-6));
    }
}

TEST_CASE("trimmed cells join without cracks: every cut point is shared by the cells beside it") {
    // A diagonal hole crossing many cells: every edge of the mesh that lies inside the kept
    // region belongs to two triangles (only boundary edges belong to one).
    std::vector<glm::dvec4> flat{{0, 0, 0, 1}, {1, 0, 0, 1}, {0, 1, 0, 1}, {1, 1, 0, 1}};
    const std::vector<float> k01{0, 0, 1, 1};
    NurbsSurfaceData s;
    s.countU = s.countV = 2;
    s.knotsU = s.knotsV = k01;
    s.points = flat;
    std::vector<std::vector<glm::dvec2>> loops{
        {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0.21, 0.5}, {0.5, 0.83}, {0.77, 0.52}, {0.48, 0.19}}};
    NurbsSurfaceMeshOptions options;
    options.rateU = options.rateV = 10.0;
    options.trimLoops = loops;
    Mesh m;
    buildNurbsSurfaceMesh(s, options, m);
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3)
        for (int k = 0; k < 3; ++k) {
            std::uint32_t a = m.indices[i + std::size_t(k)],
                          b = m.indices[i + std::size_t((k + 1) % 3)];
            if (a > b) std::swap(a, b);
            ++edges[{a, b}];
        }
    int open = 0;
    for (const auto& [edge, count] : edges) {
        CHECK(count <= 2);
        if (count != 1) continue;
        // A boundary edge lies on the square's border or on the hole's.
        const glm::dvec2 a(m.positions[edge.first]), b(m.positions[edge.second]);
        auto onBorder = [](glm::dvec2 p) {
            return p.x == 0.0 || p.x == 1.0 || p.y == 0.0 || p.y == 1.0;
        };
        auto onHole = [&](glm::dvec2 p) {
            const auto& h = loops[1];
            for (std::size_t i = 0; i < h.size(); ++i) {
                const glm::dvec2 u = h[i], v = h[(i + 1) % h.size()];
                const double cross = (v.x - u.x) * (p.y - u.y) - (p.x - u.x) * (v.y - u.y);
                const double t = glm::dot(p - u, v - u) / glm::dot(v - u, v - u);
                if (std::abs(cross) < 1e-6 && t >= -1e-6 && t <= 1 + 1e-6) return true;
            }
            return false;
        };
        if (!((onBorder(a) && onBorder(b)) || (onHole(a) && onHole(b)))) {
            ++open;
            MESSAGE("open edge (" << a.x << ", " << a.y << ") - (" << b.x << ", " << b.y << ")");
        }
    }
    CHECK(open == 0);
    const double hole = std::abs(twiceSignedArea(loops[1])) / 2.0;
    CHECK(triangleArea(m) == doctest::Approx(1.0 - hole).epsilon(1e-6));
}

TEST_CASE("Coin's sampling: steps per knot span from Complexity") {
    // A bicubic Bezier patch over a knot range of 0.25 (the teapot's): Coin asks GLU for
    // ((4 - 3) x 5 + 1) / 0.25 = 24 steps per unit of parameter at Complexity 0.5, so 6 steps
    // across the span.
    const std::vector<float> knots{0, 0, 0, 0, 0.25f, 0.25f, 0.25f, 0.25f};
    const double rate = nurbsSurfaceRate(4, 8, false, 0.25, 0.5f);
    CHECK(rate == 24.0);
    CHECK(nurbsSampleParameters(knots, 4, rate, 1000).size() == 7);
    // Linear directions take one step; a wide knot range a rate below 1, one step per span.
    CHECK(nurbsSurfaceRate(2, 4, false, 1.0, 0.5f) == 1.0);
    const std::vector<float> wide{0, 0, 0, 0, 10, 10, 10, 10};
    CHECK(nurbsSampleParameters(wide, 4, nurbsSurfaceRate(4, 8, false, 10.0, 0.5f), 1000).size() ==
          2);
    // Each non-empty span gets its own steps; repeated knots add no span.
    const std::vector<float> two{0, 0, 0, 1, 1, 2, 2, 2};
    const auto us = nurbsSampleParameters(two, 3, 3.0, 1000);
    const std::vector<double> expected{0, 1.0 / 3, 2.0 / 3, 1, 4.0 / 3, 5.0 / 3, 2};
    REQUIRE(us.size() == expected.size());
    for (std::size_t i = 0; i < us.size(); ++i)
        CHECK(us[i] == doctest::Approx(expected[i]).epsilon(1e-15));
    CHECK_THROWS_AS(nurbsSampleParameters(two, 3, 1e12, 1000), Error);
}

TEST_CASE("NURBS garbage draws nothing and never crashes") {
    const std::string points = "Coordinate3 { point [ 0 0 0, 1 0 0, 0 1 0, 1 1 0 ] }";
    const char* surfaces[] = {
        // knot vector of the wrong length (order 1, then order 30)
        "NurbsSurface { numUControlPoints 2 numVControlPoints 2 uKnotVector [ 0, 1, 1 ] "
        "vKnotVector [ 0, 0, 1, 1 ] }",
        "NurbsSurface { numUControlPoints 2 numVControlPoints 2 uKnotVector [ 0, 0, 0, 0, 0, 0, "
        "0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1 ] "
        "vKnotVector [ 0, 0, 1, 1 ] }",
        // decreasing knots
        "NurbsSurface { numUControlPoints 2 numVControlPoints 2 uKnotVector [ 0, 1, 0, 1 ] "
        "vKnotVector [ 0, 0, 1, 1 ] }",
        // an empty domain
        "NurbsSurface { numUControlPoints 2 numVControlPoints 2 uKnotVector [ 1, 1, 1, 1 ] "
        "vKnotVector [ 0, 0, 1, 1 ] }",
        // fewer control points than the order
        "NurbsSurface { numUControlPoints 1 numVControlPoints 2 uKnotVector [ 0, 0, 0, 1, 1 ] "
        "vKnotVector [ 0, 0, 1, 1 ] }",
        // more control points than the coordinates hold, absurd and negative counts
        "NurbsSurface { numUControlPoints 3 numVControlPoints 2 uKnotVector [ 0, 0, 0.5, 1, 1 ] "
        "vKnotVector [ 0, 0, 1, 1 ] }",
        "NurbsSurface { numUControlPoints 2147483647 numVControlPoints 2147483647 "
        "uKnotVector [ 0, 0, 1, 1 ] vKnotVector [ 0, 0, 1, 1 ] }",
        "NurbsSurface { numUControlPoints -2 numVControlPoints -2 uKnotVector [ 0, 0, 1, 1 ] "
        "vKnotVector [ 0, 0, 1, 1 ] }",
        // the defaults
        "NurbsSurface { }",
        "IndexedNurbsSurface { }",
        // an index out of range
        "IndexedNurbsSurface { numUControlPoints 2 numVControlPoints 2 coordIndex [ 0, 1, 2, 9 ] "
        "uKnotVector [ 0, 0, 1, 1 ] vKnotVector [ 0, 0, 1, 1 ] }",
        "IndexedNurbsSurface { numUControlPoints 2 numVControlPoints 2 coordIndex [ 0, 1, -5, 3 ] "
        "uKnotVector [ 0, 0, 1, 1 ] vKnotVector [ 0, 0, 1, 1 ] }",
        "NurbsCurve { numControlPoints 3 knotVector [ 0, 0, 1, 1 ] }",
        "NurbsCurve { numControlPoints 9 knotVector [ 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1 ] }",
        "NurbsCurve { }",
        "IndexedNurbsCurve { }",
        "IndexedNurbsCurve { numControlPoints 2 coordIndex [ 0, 77 ] knotVector [ 0, 0, 1, 1 ] }",
    };
    for (const char* s : surfaces) {
        CAPTURE(s);
        const auto root = read(points + s);
        const Mesh* m = nullptr;
        CHECK_NOTHROW(m = &meshOf(root));
        if (m) CHECK(m->indices.empty());
    }
    SUBCASE("trim garbage: an open loop, a bad NurbsProfile, indices out of range") {
        const char* trims[] = {
            "ProfileCoordinate2 { point [ 0.2 0.2, 0.8 0.2 ] } LinearProfile { index [ 0, 1 ] }",
            ("ProfileCoordinate2 { point [ 0 0, 1 0, 1 1 ] } NurbsProfile { index [ 0, 1, 2 ] "
             "knotVector [ 1, 0, 0, 1, 1 ] }"),
            "ProfileCoordinate2 { point [ 0 0 ] } LinearProfile { index [ 5, 6, 7, -1 ] }",
        };
        for (const char* t : trims) {
            CAPTURE(t);
            const auto root = read(std::string(kFlatSquare) + t + kFlatSurface);
            const Mesh* m = nullptr;
            CHECK_NOTHROW(m = &meshOf(root));
            if (m) CHECK(m->indices.empty());
        }
    }
}

TEST_CASE("NaN control points and knots give one Error naming the node") {
    auto root = Separator::create();
    auto coords = Coordinate3::create();
    coords->point.setValues({{0, 0, 0}, {1, 0, 0}, {0, std::nanf(""), 0}, {1, 1, 0}});
    auto surface = NurbsSurface::create();
    surface->setName("patch");
    surface->numUControlPoints = 2;
    surface->numVControlPoints = 2;
    surface->uKnotVector.setValues({0, 0, 1, 1});
    surface->vKnotVector.setValues({0, 0, 1, 1});
    root->addChild(coords);
    root->addChild(surface);
    try {
        shapeMesh(*root);
        FAIL("no error");
    } catch (const Error& e) {
        const std::string what = e.what();
        CHECK(what.find("NurbsSurface 'patch'") != std::string::npos);
        CHECK(what.find("control point 2 is not a finite number") != std::string::npos);
        CHECK(what.find('\n') == std::string::npos);
    }
    coords->point.setValues({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}});
    surface->uKnotVector.setValues({0, 0, std::numeric_limits<float>::infinity(), 1});
    CHECK_THROWS_WITH_AS(shapeMesh(*root),
                         doctest::Contains("NurbsSurface 'patch': uKnotVector value 2"), Error);
}

TEST_CASE("the polygon tessellator keeps holes and refuses what is not finite") {
    const std::vector<std::vector<glm::dvec2>> ring{{{0, 0}, {4, 0}, {4, 4}, {0, 4}},
                                                    {{1, 1}, {1, 3}, {3, 3}, {3, 1}}};
    Triangulation t;
    REQUIRE(triangulatePolygons(ring, WindingRule::NonZero, t));
    double area = 0.0;
    for (std::size_t i = 0; i + 2 < t.triangles.size(); i += 3) {
        const glm::dvec2 a = t.points[t.triangles[i]], b = t.points[t.triangles[i + 1]],
                         c = t.points[t.triangles[i + 2]];
        const double twice = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
        CHECK(twice > 0.0); // counter-clockwise
        area += twice / 2.0;
    }
    CHECK(area == doctest::Approx(12.0));
    const std::vector<std::vector<glm::dvec2>> bad{{{0, 0}, {1, 0}, {0, std::nan("")}}};
    CHECK(!triangulatePolygons(bad, WindingRule::Odd, t));
    CHECK(t.triangles.empty());
}
