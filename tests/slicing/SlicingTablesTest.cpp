// The tables the slicer bakes: transfer-function rows with their data ranges, the tag map,
// emptiness under the functions, and the pre-integration table.
#include <doctest/doctest.h>

#include <cmath>

#include <volsg/core/Error.h>
#include <volsg/slicing/PreIntegrationTable.h>
#include <volsg/slicing/TransferTable.h>

using namespace volsg;

namespace {

TransferFunction1D withAlpha(std::vector<PiecewiseLinear::Point> alpha) {
    TransferFunction1D tf;
    tf.setChannel(TransferFunction1D::Alpha, std::move(alpha));
    return tf;
}

glm::vec4 texel(const TransferTable& t, int row, int column) {
    const float* p = t.texels().data() + (std::size_t(row) * TransferTable::kWidth + column) * 4;
    return {p[0], p[1], p[2], p[3]};
}

} // namespace

TEST_CASE("transfer table rows sample each function and carry its data range") {
    std::map<int, TransferFunction1D> functions;
    TransferFunction1D fallback = withAlpha({{0, 0}, {0.5, 1}, {1, 0}});
    fallback.setChannel(TransferFunction1D::Red, {{0, 1}, {1, 0}});
    functions[-1] = fallback;
    TransferFunction1D tagged = withAlpha({{0, 0.25}, {1, 0.25}});
    tagged.setDataRange(100.0, 300.0);
    functions[4000] = tagged;
    functions[7] = withAlpha({{0, 1}, {1, 1}});
    TransferTable table;
    table.build(functions, {0.0, 65535.0});
    REQUIRE(table.rows() == 3); // default, tag 7, tag 4000
    CHECK(table.texels().size() == std::size_t(3) * TransferTable::kWidth * 4);
    // Row 0: the tag -1 function at v = i / 4095 as (r, g, b, tau L0), the last sample again,
    // then its (natural) range.
    const int half = (TransferTable::kEntries - 1) / 2; // v = 2047 / 4095, just below 0.5
    const double A = 2.0 * 2047.0 / 4095.0;
    CHECK(texel(table, 0, half).a == doctest::Approx(-std::log(1.0 - A)).epsilon(1e-6));
    CHECK(texel(table, 0, 0).r == 1.0f);
    CHECK(texel(table, 0, TransferTable::kEntries - 1).r == 0.0f);
    CHECK(texel(table, 0, TransferTable::kEntries) == texel(table, 0, TransferTable::kEntries - 1));
    CHECK(texel(table, 0, TransferTable::kRangeColumn) == glm::vec4(0.0f, 65535.0f, 0.0f, 0.0f));
    // Rows in tag order, with their own ranges; A = 1 is clamped to 1 - 1e-6.
    CHECK(texel(table, 1, 10).a == doctest::Approx(-std::log(1e-6)).epsilon(1e-6));
    CHECK(texel(table, 2, 10).a == doctest::Approx(-std::log(0.75)).epsilon(1e-6));
    CHECK(texel(table, 2, TransferTable::kRangeColumn) == glm::vec4(100.0f, 300.0f, 0.0f, 0.0f));
    CHECK(table.dataRange(2) == glm::dvec2(100.0, 300.0));
    // The tag map: every tag without a function uses row 0.
    REQUIRE(table.tagRows().size() == 65536);
    CHECK(table.tagRows()[7] == 1);
    CHECK(table.tagRows()[4000] == 2);
    CHECK(table.tagRows()[0] == 0);
    CHECK(table.tagRows()[65535] == 0);
}

TEST_CASE("without a tag -1 function row 0 is the identity ramp over the natural range") {
    TransferTable table;
    table.build({}, {-32768.0, 32767.0});
    REQUIRE(table.rows() == 1);
    CHECK(glm::vec3(texel(table, 0, TransferTable::kEntries - 1)) == glm::vec3(1.0f));
    CHECK(texel(table, 0, 0) == glm::vec4(0.0f));
    CHECK(texel(table, 0, TransferTable::kRangeColumn).x == -32768.0f);
    CHECK_THROWS_AS(table.build({{-2, TransferFunction1D()}}, {0.0, 1.0}), Error);
    CHECK_THROWS_AS(table.build({{65536, TransferFunction1D()}}, {0.0, 1.0}), Error);
}

TEST_CASE("a region is empty only when no function that applies to it is opaque there") {
    std::map<int, TransferFunction1D> functions;
    functions[-1] = withAlpha({{0, 0}, {0.5, 0}, {0.6, 1}, {1, 1}}); // opaque above 0.5
    TransferFunction1D tag3 = withAlpha({{0, 0.5}, {1, 0.5}});       // opaque everywhere
    functions[3] = tag3;
    TransferTable table;
    table.build(functions, {0.0, 255.0});
    CHECK_FALSE(table.mayEmit(0.0, 100.0, false, 0, 0)); // v <= 0.39: transparent
    CHECK(table.mayEmit(0.0, 130.0, false, 0, 0));       // reaches v = 0.51
    CHECK(table.mayEmit(0.0, 100.0, true, 2, 5));        // tag 3 may be there
    CHECK_FALSE(table.mayEmit(0.0, 100.0, true, 4, 9));  // tag 3 is not
    CHECK_FALSE(table.mayEmit(0.0, 100.0, true, 0, 2));
}

TEST_CASE("pre-integration of a constant function is the homogeneous slab") {
    TransferFunction1D tf = withAlpha({{0, 0.3}, {1, 0.3}});
    tf.setChannel(TransferFunction1D::Green, {{0, 0.7}, {1, 0.7}});
    PreIntegrationTable table;
    table.build(tf);
    const double tauL0 = -std::log(1.0 - 0.3);
    for (const auto& [f, b] : {std::pair(0.0, 1.0), std::pair(0.3, 0.3), std::pair(0.9, 0.1)}) {
        const glm::dvec4 s = table.segment(f, b);
        CHECK(s.a == doctest::Approx(tauL0).epsilon(1e-9));
        CHECK(s.g == doctest::Approx(0.7).epsilon(1e-9));
    }
}

TEST_CASE("pre-integration averages a spike's extinction over the segment it crosses") {
    // Alpha 0 except a triangle of height 0.9 and half-width 0.02 around v = 0.5.
    TransferFunction1D tf = withAlpha({{0, 0}, {0.48, 0}, {0.5, 0.9}, {0.52, 0}, {1, 0}});
    tf.setChannel(TransferFunction1D::Red, {{0, 0.2}, {0.5, 1.0}, {1, 0.2}});
    PreIntegrationTable table;
    table.build(tf);
    // The integral of -ln(1 - A(v)) over the spike, by a fine midpoint sum.
    double integral = 0.0, weightedRed = 0.0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        const double v = 0.4 + 0.2 * (i + 0.5) / n;
        const double tau = -std::log(1.0 - tf.evaluate(TransferFunction1D::Alpha, v));
        integral += tau * 0.2 / n;
        weightedRed += tau * tf.evaluate(TransferFunction1D::Red, v) * 0.2 / n;
    }
    // A segment from v = 0.3 to 0.7 crosses the whole spike: mean = integral / 0.4.
    const glm::dvec4 across = table.segment(0.3, 0.7);
    CHECK(across.a == doctest::Approx(integral / 0.4).epsilon(1e-3));
    CHECK(across.r == doctest::Approx(weightedRed / integral).epsilon(1e-3));
    CHECK(table.segment(0.7, 0.3).a == doctest::Approx(across.a).epsilon(1e-12));
    // Segments that miss the spike are clear; point samples there see nothing either.
    CHECK(table.segment(0.1, 0.4).a == 0.0);
    CHECK(table.segment(0.6, 0.6).a == 0.0);
    // The table's texels hold the same values at its grid points.
    const int i = 77, j = 179; // v = i / 255 and j / 255
    const float* t =
        table.texels().data() + (std::size_t(j) * PreIntegrationTable::kSize + std::size_t(i)) * 4;
    const glm::dvec4 s = table.segment(i / 255.0, j / 255.0);
    CHECK(t[3] == doctest::Approx(s.a).epsilon(1e-6));
    CHECK(t[0] == doctest::Approx(s.r).epsilon(1e-6));
}

TEST_CASE("an absorbing segment is the segment, and a transparent one is zero") {
    // A spike with transparent space on both sides and an opaque plateau, so every branch is
    // crossed: point segments inside and outside, segments across and beside the features.
    TransferFunction1D tf =
        withAlpha({{0, 0}, {0.3, 0}, {0.35, 0.8}, {0.4, 0}, {0.7, 0}, {0.8, 0.5}});
    tf.setChannel(TransferFunction1D::Blue, {{0, 0.1}, {1, 0.9}});
    PreIntegrationTable table;
    table.build(tf);
    int absorbing = 0, transparent = 0;
    for (int i = 0; i <= 40; ++i)
        for (int j = 0; j <= 40; ++j) {
            const double f = i / 40.0, b = j / 40.0;
            const glm::dvec4 full = table.segment(f, b);
            const glm::dvec4 got = table.absorbingSegment(f, b);
            if (full.a > 1e-12) {
                ++absorbing;
                CHECK(got == full); // bit for bit: the model's predictions must not move
            } else {
                ++transparent;
                CHECK(got == glm::dvec4(0.0));
            }
        }
    CHECK(absorbing > 100);
    CHECK(transparent > 100);
}
