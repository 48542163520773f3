// Random garbage through the text and NURBS nodes: counts, knots, weights, indices, trim
// profiles, strings, sizes. Every mesh is either built (indices in range, points finite) or
// refused with one volsg::Error; nothing else may happen (a crash, another exception, a
// sanitizer report).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include <volsg/core/Error.h>
#include <volsg/nodes/AsciiText.h>
#include <volsg/nodes/Complexity.h>
#include <volsg/nodes/Coordinate3.h>
#include <volsg/nodes/Coordinate4.h>
#include <volsg/nodes/Font.h>
#include <volsg/nodes/NurbsCurve.h>
#include <volsg/nodes/NurbsSurface.h>
#include <volsg/nodes/Profile.h>
#include <volsg/nodes/ProfileCoordinate2.h>
#include <volsg/nodes/ProfileCoordinate3.h>
#include <volsg/nodes/ShapeHints.h>
#include <volsg/nodes/Text3.h>
#include <volsg/state/State.h>

using namespace volsg;

namespace {

class Random {
public:
    explicit Random(unsigned seed) : rng_(seed) {}
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
    float real(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng_); }
    bool chance(double p) { return std::bernoulli_distribution(p)(rng_); }

    /// Mostly valid knot vectors (non-decreasing, some repeated), sometimes garbage.
    std::vector<float> knots(int count) {
        std::vector<float> k;
        float at = real(-2.0f, 2.0f);
        for (int i = 0; i < count; ++i) {
            if (chance(0.6)) at += real(0.0f, 1.0f);
            k.push_back(at);
        }
        if (chance(0.8))
            std::sort(k.begin(), k.end());
        else if (!k.empty())
            k[std::size_t(integer(0, count - 1))] = real(-3.0f, 3.0f);
        return k;
    }
    std::vector<std::int32_t> indices(int count, int range) {
        std::vector<std::int32_t> v;
        for (int i = 0; i < count; ++i)
            v.push_back(integer(-2, range + 2));
        return v;
    }
    std::string bytes(int length) {
        std::string s;
        for (int i = 0; i < length; ++i)
            s += char(chance(0.8) ? integer(32, 126) : integer(0, 255));
        return s;
    }

private:
    std::mt19937 rng_;
};

/// Builds the mesh of `shape` with `properties` in scope; Error is allowed, nothing else.
void check(const std::vector<ref_ptr<Node>>& properties, Shape& shape, int& built, int& refused) {
    State state;
    for (const auto& p : properties)
        state.add(*p);
    try {
        const Mesh& m = shape.mesh(state);
        for (const auto i : m.indices)
            REQUIRE(i < m.positions.size());
        for (const auto& p : m.positions)
            REQUIRE((std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)));
        for (const auto& n : m.normals)
            REQUIRE((std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z)));
        ++built;
    } catch (const Error& e) {
        const std::string what = e.what();
        CHECK(what.find('\n') == std::string::npos);
        ++refused;
    }
}

std::vector<ref_ptr<Node>> randomProfiles(Random& r) {
    std::vector<ref_ptr<Node>> out;
    if (r.chance(0.5)) {
        auto c = ProfileCoordinate2::create();
        std::vector<glm::vec2> pts;
        for (int i = 0, n = r.integer(0, 12); i < n; ++i)
            pts.emplace_back(r.real(-0.5f, 1.5f), r.real(-0.5f, 1.5f));
        c->point.setValues(pts);
        out.push_back(c);
    } else {
        auto c = ProfileCoordinate3::create();
        std::vector<glm::vec3> pts;
        for (int i = 0, n = r.integer(0, 12); i < n; ++i)
            pts.emplace_back(r.real(-0.5f, 1.5f), r.real(-0.5f, 1.5f), r.real(-0.5f, 2.0f));
        c->point.setValues(pts);
        out.push_back(c);
    }
    for (int i = 0, n = r.integer(0, 3); i < n; ++i) {
        ref_ptr<Profile> p;
        if (r.chance(0.5)) {
            p = LinearProfile::create();
        } else {
            auto np = NurbsProfile::create();
            np->knotVector.setValues(r.knots(r.integer(0, 10)));
            p = np;
        }
        p->index.setValues(r.indices(r.integer(0, 8), 12));
        p->linkage = r.integer(0, 2);
        out.push_back(p);
    }
    return out;
}

} // namespace

TEST_CASE("random NURBS input builds a sane mesh or gives one Error, never anything else") {
    Random r(1234);
    int built = 0, refused = 0, drawn = 0;
    for (int iteration = 0; iteration < 600; ++iteration) {
        std::vector<ref_ptr<Node>> properties;
        auto complexity = Complexity::create();
        complexity->value = r.real(-0.5f, 1.5f);
        properties.push_back(complexity);
        const int points = r.integer(0, 40);
        if (r.chance(0.5)) {
            auto c = Coordinate3::create();
            std::vector<glm::vec3> p;
            for (int i = 0; i < points; ++i)
                p.emplace_back(r.real(-10, 10), r.real(-10, 10), r.real(-10, 10));
            c->point.setValues(p);
            properties.push_back(c);
        } else {
            auto c = Coordinate4::create();
            std::vector<glm::vec4> p;
            for (int i = 0; i < points; ++i)
                p.emplace_back(r.real(-10, 10), r.real(-10, 10), r.real(-10, 10),
                               r.chance(0.9) ? r.real(0.1f, 2.0f) : r.real(-1.0f, 1.0f));
            c->point.setValues(p);
            properties.push_back(c);
        }
        if (r.chance(0.5))
            for (auto& p : randomProfiles(r))
                properties.push_back(p);

        const int nu = r.integer(-1, 6), nv = r.integer(-1, 6);
        ref_ptr<Shape> shape;
        switch (r.integer(0, 3)) {
        case 0: {
            auto s = NurbsSurface::create();
            s->numUControlPoints = nu;
            s->numVControlPoints = nv;
            s->uKnotVector.setValues(r.knots(nu + r.integer(-1, 5)));
            s->vKnotVector.setValues(r.knots(nv + r.integer(-1, 5)));
            shape = s;
            break;
        }
        case 1: {
            auto s = IndexedNurbsSurface::create();
            s->numUControlPoints = nu;
            s->numVControlPoints = nv;
            s->coordIndex.setValues(r.indices(std::max(0, nu * nv + r.integer(-2, 2)), points));
            s->uKnotVector.setValues(r.knots(nu + r.integer(-1, 5)));
            s->vKnotVector.setValues(r.knots(nv + r.integer(-1, 5)));
            shape = s;
            break;
        }
        case 2: {
            auto s = NurbsCurve::create();
            s->numControlPoints = nu * 2;
            s->knotVector.setValues(r.knots(nu * 2 + r.integer(-1, 5)));
            shape = s;
            break;
        }
        default: {
            auto s = IndexedNurbsCurve::create();
            s->numControlPoints = nu * 2;
            s->coordIndex.setValues(r.indices(std::max(0, nu * 2), points));
            s->knotVector.setValues(r.knots(nu * 2 + r.integer(-1, 5)));
            shape = s;
            break;
        }
        }
        const int before = built;
        check(properties, *shape, built, refused);
        if (built > before) {
            State state;
            for (const auto& p : properties)
                state.add(*p);
            if (!shape->mesh(state).indices.empty()) ++drawn;
        }
    }
    MESSAGE(built << " meshes built (" << drawn << " drawing something), " << refused
                  << " refused");
    CHECK(drawn > 25);
}

TEST_CASE("random text input builds a sane mesh or gives one Error, never anything else") {
    Random r(99);
    int built = 0, refused = 0;
    for (int iteration = 0; iteration < 150; ++iteration) {
        std::vector<ref_ptr<Node>> properties;
        auto font = Font::create();
        static const char* names[] = {
            "defaultFont", "Times-Roman", "Courier-BoldOblique", "Helvetica-Italic", "",
            "\xff\xfe"};
        font->name = std::string(names[r.integer(0, 5)]);
        font->size = r.chance(0.1) ? r.real(-1e20f, 1e20f) : r.real(-2.0f, 20.0f);
        properties.push_back(font);
        auto complexity = Complexity::create();
        complexity->value = r.real(-0.5f, 1.5f);
        properties.push_back(complexity);
        auto hints = ShapeHints::create();
        hints->creaseAngle = r.real(0.0f, 3.2f);
        properties.push_back(hints);
        if (r.chance(0.5))
            for (auto& p : randomProfiles(r))
                properties.push_back(p);
        std::vector<std::string> strings;
        for (int i = 0, n = r.integer(0, 3); i < n; ++i)
            strings.push_back(r.bytes(r.integer(0, 12)));
        if (r.chance(0.5)) {
            auto t = Text3::create();
            t->string.setValues(strings);
            t->spacing = r.real(-3.0f, 3.0f);
            t->justification = r.integer(0, 4);
            t->parts.setValue(r.integer(0, 7));
            check(properties, *t, built, refused);
        } else {
            auto t = AsciiText::create();
            t->string.setValues(strings);
            t->spacing = r.real(-3.0f, 3.0f);
            t->justification = r.integer(0, 4);
            std::vector<float> widths;
            for (int i = 0, n = r.integer(0, 3); i < n; ++i)
                widths.push_back(r.real(-5.0f, 50.0f));
            t->width.setValues(widths);
            check(properties, *t, built, refused);
        }
    }
    MESSAGE(built << " text meshes built, " << refused << " refused");
    CHECK(built > 50);
}
