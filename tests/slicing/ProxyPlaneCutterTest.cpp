#include <doctest/doctest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <volsg/slicing/ProxyPlaneCutter.h>

using namespace volsg;

namespace {

double triangleArea(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    return 0.5 * glm::length(glm::cross(glm::dvec3(b - a), glm::dvec3(c - a)));
}

double sliceArea(const ProxySlices& s, int slice) {
    const std::size_t begin = s.firsts[std::size_t(slice)];
    const std::size_t end =
        slice + 1 < s.count() ? s.firsts[std::size_t(slice) + 1] : s.vertices.size();
    double area = 0.0;
    for (std::size_t i = begin; i < end; i += 3)
        area += triangleArea(s.vertices[i], s.vertices[i + 1], s.vertices[i + 2]);
    return area;
}

glm::dmat4 lookFrom(const glm::dvec3& eye) {
    return glm::lookAt(eye, glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0));
}

} // namespace

TEST_CASE("planes through an axis-aligned box seen along Z are its cross-sections") {
    const glm::dvec3 lo(-1, -2, -3), hi(1, 2, 3);
    const glm::dmat4 mv = lookFrom({0, 0, 10});
    const glm::dvec2 range = ProxyPlaneCutter::depthRange(lo, hi, mv);
    CHECK(range.x == doctest::Approx(7.0));
    CHECK(range.y == doctest::Approx(13.0));
    const PlaneLayout layout = PlaneLayout::over(range, 0.5);
    CHECK(layout.count == 12);
    const ProxySlices s = ProxyPlaneCutter::cut(lo, hi, mv, layout);
    REQUIRE(s.count() == 12);
    for (int k = 0; k < s.count(); ++k)
        CHECK(sliceArea(s, k) == doctest::Approx(2.0 * 4.0).epsilon(1e-9));
    // Back to front: the first slice is the farthest (smallest z in box coordinates here).
    CHECK(s.vertices.front().z == doctest::Approx(-2.75));
    CHECK(s.vertices.back().z == doctest::Approx(2.75));
}

TEST_CASE("slab areas of an obliquely seen box add up to its volume") {
    const glm::dvec3 lo(-0.5, -0.75, -1.0), hi(0.5, 0.75, 1.0);
    const glm::dmat4 mv =
        lookFrom({3, 4, 5}) * glm::rotate(glm::dmat4(1.0), 0.3, glm::dvec3(1, 1, 0));
    const PlaneLayout layout = PlaneLayout::over(ProxyPlaneCutter::depthRange(lo, hi, mv), 0.002);
    const ProxySlices s = ProxyPlaneCutter::cut(lo, hi, mv, layout);
    double volume = 0.0;
    for (int k = 0; k < s.count(); ++k)
        volume += sliceArea(s, k) * s.spacing;
    // Midpoint rule on a piecewise quadratic area function: error O(spacing^2).
    CHECK(volume == doctest::Approx(1.0 * 1.5 * 2.0).epsilon(1e-4));
}

TEST_CASE("every slice vertex lies on its plane and inside the box") {
    const glm::dvec3 lo(0, 0, 0), hi(37, 23, 19);
    const glm::dmat4 mv = lookFrom({60, -40, 80}) * glm::translate(glm::dmat4(1.0), -hi * 0.5);
    const PlaneLayout layout = PlaneLayout::over(ProxyPlaneCutter::depthRange(lo, hi, mv), 1.0);
    const ProxySlices s = ProxyPlaneCutter::cut(lo, hi, mv, layout);
    REQUIRE(s.count() > 10);
    for (int k = 0; k < s.count(); ++k) {
        const std::size_t end =
            k + 1 < s.count() ? s.firsts[std::size_t(k) + 1] : s.vertices.size();
        const double depth0 =
            -(mv * glm::dvec4(glm::dvec3(s.vertices[s.firsts[std::size_t(k)]]), 1.0)).z;
        for (std::size_t i = s.firsts[std::size_t(k)]; i < end; ++i) {
            const glm::dvec3 p(s.vertices[i]);
            CHECK(-(mv * glm::dvec4(p, 1.0)).z == doctest::Approx(depth0).epsilon(1e-5));
            for (int a = 0; a < 3; ++a) {
                CHECK(p[a] >= lo[a] - 1e-4);
                CHECK(p[a] <= hi[a] + 1e-4);
            }
        }
    }
}

TEST_CASE("a camera inside the box gets only the planes in front of its near distance") {
    const glm::dvec3 lo(-1), hi(1);
    const glm::dmat4 mv = lookFrom({0, 0, 0.25}); // eye inside, looking at the centre
    const glm::dvec2 range = ProxyPlaneCutter::depthRange(lo, hi, mv);
    CHECK(range.x < 0.0);
    const PlaneLayout layout = PlaneLayout::over(range, 0.1);
    const ProxySlices s = ProxyPlaneCutter::cut(lo, hi, mv, layout, 0.05);
    REQUIRE(s.count() > 0);
    for (const auto& p : s.vertices)
        CHECK(-(mv * glm::dvec4(glm::dvec3(p), 1.0)).z >= 0.05 - 1e-6);
}

TEST_CASE("bricks sharing one layout cut planes at the same depths") {
    const glm::dmat4 mv = lookFrom({2, 3, 9});
    const glm::dvec3 lo(-1), hi(1), splitHi(1, 1, 0), splitLo(-1, -1, 0);
    const PlaneLayout layout = PlaneLayout::over(ProxyPlaneCutter::depthRange(lo, hi, mv), 0.05);
    const ProxySlices whole = ProxyPlaneCutter::cut(lo, hi, mv, layout);
    const ProxySlices a = ProxyPlaneCutter::cut(lo, splitHi, mv, layout);
    const ProxySlices b = ProxyPlaneCutter::cut(splitLo, hi, mv, layout);
    double areaWhole = 0, areaParts = 0;
    for (int k = 0; k < whole.count(); ++k)
        areaWhole += sliceArea(whole, k);
    for (int k = 0; k < a.count(); ++k)
        areaParts += sliceArea(a, k);
    for (int k = 0; k < b.count(); ++k)
        areaParts += sliceArea(b, k);
    CHECK(areaParts == doctest::Approx(areaWhole).epsilon(1e-6)); // float vertices
}
