// Engines and animated nodes against closed forms, connections into node fields, chains,
// cycles, and versions that change only with values (nodes/volsg/engines).
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <volsg/core/Error.h>
#include <volsg/engines/AnimatedNodes.h>
#include <volsg/engines/Calculator.h>
#include <volsg/engines/Engines.h>
#include <volsg/engines/Evaluator.h>
#include <volsg/engines/GlobalField.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/Cube.h>
#include <volsg/nodes/Material.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/Switch.h>
#include <volsg/nodes/Transform.h>

using namespace volsg;

namespace {

constexpr double twoPi = 2.0 * std::numbers::pi;

ref_ptr<Node> read(const std::string& body) {
    return readSceneFromString("#Inventor V2.1 ascii\n" + body, "engines.iv");
}

template <class T> T* child(Node& root, std::size_t i) {
    return dynamic_cast<T*>((*root.children())[i].get());
}

/// Evaluates a lone engine at `seconds` (its inputs set directly).
void run(Engine& engine, double seconds = 0.0) {
    EngineContext context;
    context.seconds = seconds;
    engine.evaluate(context);
}

std::vector<float> floats(Engine& engine, const char* output) {
    return dynamic_cast<MFFloat&>(*engine.output(output)).getValues();
}

std::vector<glm::vec3> vecs(Engine& engine, const char* output) {
    return dynamic_cast<MFVec3f&>(*engine.output(output)).getValues();
}

/// The calculator's float output after evaluating `expression` with a, b (and A, B) set.
std::vector<float> calc(const std::string& expression, std::vector<float> a, std::vector<float> b,
                        const char* output = "oa") {
    auto c = Calculator::create();
    c->a = std::move(a);
    c->b = std::move(b);
    c->A = {glm::vec3(1, 0, 0)};
    c->B = {glm::vec3(0, 2, 0)};
    c->expression = {expression};
    run(*c);
    return floats(*c, output);
}

} // namespace

TEST_CASE("Rotor turns speed * 2 pi * t radians about its axis from the file's angle") {
    auto root = read("Separator { Rotor { rotation 0 0 1 0 speed 0.3 } Cube { } }");
    auto* rotor = child<Rotor>(*root, 0);
    REQUIRE(rotor);
    ConnectionEvaluator evaluator;
    for (double t : {0.0, 0.25, 1.0, 2.9, 10.0}) {
        evaluator.evaluate(*root, t);
        const double expected = std::fmod(0.3 * twoPi * t, twoPi);
        CHECK(rotor->rotation().angle == doctest::Approx(expected).epsilon(1e-5));
        CHECK(rotor->rotation().axis == glm::vec3(0, 0, 1));
    }
    // The same time again changes nothing: no version bump, so no cache rebuilds.
    const std::uint64_t version = rotor->version();
    CHECK(evaluator.evaluate(*root, 10.0) == 0);
    CHECK(rotor->version() == version);
    // Off: the rotation stays where it is.
    rotor->on = false;
    evaluator.evaluate(*root, 11.0);
    CHECK(rotor->rotation().angle == doctest::Approx(std::fmod(0.3 * twoPi * 10.0, twoPi)));
}

TEST_CASE("Pendulum, Shuttle and Blinker follow their closed forms") {
    auto root = read("Separator {"
                     "  Pendulum { rotation0 0 0 1 0 rotation1 0 0 1 1 speed 0.5 }"
                     "  Shuttle { translation0 0 0 0 translation1 4 0 0 speed 0.25 }"
                     "  Blinker { speed 1 Cube { } Cube { } Cube { } Cube { } }"
                     "}");
    auto* pendulum = child<Pendulum>(*root, 0);
    auto* shuttle = child<Shuttle>(*root, 1);
    auto* blinker = child<Blinker>(*root, 2);
    REQUIRE(pendulum);
    REQUIRE(shuttle);
    REQUIRE(blinker);
    ConnectionEvaluator evaluator;
    for (double t : {0.0, 0.3, 1.0, 1.7, 2.2}) {
        evaluator.evaluate(*root, t);
        const double alphaP = (1.0 - std::cos(twoPi * 0.5 * t)) / 2.0;
        CHECK(pendulum->rotation().angle == doctest::Approx(alphaP).epsilon(1e-5));
        const double alphaS = (1.0 - std::cos(twoPi * 0.25 * t)) / 2.0;
        CHECK(shuttle->translation().x == doctest::Approx(4.0 * alphaS).epsilon(1e-5));
        const double f = t - std::floor(t);
        CHECK(blinker->whichChild() == int(f * 4));
    }
    CHECK(Blinker::childAt(0.25, 1) == -1); // one child: off for the first half
    CHECK(Blinker::childAt(0.75, 1) == 0);
}

TEST_CASE("ElapsedTime feeds a node field through a second engine (a chain)") {
    auto root = read("Separator { Transform { translation 0 0 0 = ComposeVec3f {"
                     "  x 0 = ElapsedTime { speed 2 } . timeOut  y 1  z 2 } . vector } }");
    auto* transform = child<Transform>(*root, 0);
    REQUIRE(transform);
    ConnectionEvaluator evaluator;
    evaluator.evaluate(*root, 0.0);
    CHECK(transform->translation() == glm::vec3(0, 1, 2));
    evaluator.evaluate(*root, 1.25);
    CHECK(transform->translation().x == doctest::Approx(2.5));
    evaluator.evaluate(*root, 3.0);
    CHECK(transform->translation().x == doctest::Approx(6.0));
    CHECK(transform->translation().y == 1.0f);
}

TEST_CASE("ElapsedTime counts while on and not paused, and restarts on reset") {
    auto e = ElapsedTime::create();
    e->speed = 0.5f;
    run(*e, 10.0); // starts here
    run(*e, 14.0);
    CHECK(dynamic_cast<SFTime&>(*e->output("timeOut"))() == doctest::Approx(2.0));
    e->pause = true;
    run(*e, 20.0);
    CHECK(dynamic_cast<SFTime&>(*e->output("timeOut"))() == doctest::Approx(2.0));
    e->pause = false;
    run(*e, 22.0);
    CHECK(dynamic_cast<SFTime&>(*e->output("timeOut"))() == doctest::Approx(3.0));
    e->reset.touch();
    run(*e, 23.0);
    CHECK(dynamic_cast<SFTime&>(*e->output("timeOut"))() == 0.0);
    run(*e, 25.0);
    CHECK(dynamic_cast<SFTime&>(*e->output("timeOut"))() == doctest::Approx(1.0));
}

TEST_CASE("TimeCounter steps min to max frequency times a second, syncOut each cycle") {
    auto c = TimeCounter::create();
    c->min = std::int16_t(0);
    c->max = std::int16_t(6);
    c->step = std::int16_t(2); // 0 2 4 6
    c->frequency = 2.0f;       // a cycle every half second
    run(*c, 0.0);
    const auto output = [&] { return int(dynamic_cast<SFShort&>(*c->output("output"))()); };
    const auto syncs = [&] { return dynamic_cast<SFTrigger&>(*c->output("syncOut")).count(); };
    CHECK(output() == 0);
    const std::uint64_t before = syncs();
    for (double t : {0.05, 0.13, 0.26, 0.40, 0.55, 0.9}) {
        run(*c, t);
        const double phase = 2.0 * t;
        CHECK(output() == 2 * int((phase - std::floor(phase)) * 4));
    }
    CHECK(syncs() == before + 1); // one new cycle began (at 0.5 s)
    CHECK(c->valueAt(0.6) == 4);
    // Duty weights: the first value holds for 3 of 4 parts of the cycle.
    c->duty = {3.0f, 1.0f / 3, 1.0f / 3, 1.0f / 3};
    CHECK(c->valueAt(0.7) == 0);
    CHECK(c->valueAt(0.8) == 2);
}

TEST_CASE("TimeCounter at a frequency no clock can count stays in range") {
    // fuzz-binaryscene: frequency and time whose product overflows an int64 cycle count (UB
    // before), and a product that is not a number.
    for (const float frequency : {3.0e38f, std::numeric_limits<float>::infinity()}) {
        auto c = TimeCounter::create();
        c->min = std::int16_t(1);
        c->max = std::int16_t(5);
        c->frequency = frequency;
        const auto output = [&] { return int(dynamic_cast<SFShort&>(*c->output("output"))()); };
        for (double t : {0.0, 0.25, 1.5, 1.0e9, 1.0e9})
            run(*c, t);
        CHECK(output() >= 1);
        CHECK(output() <= 5);
    }
}

TEST_CASE("Counter counts triggers and wraps with syncOut") {
    auto c = Counter::create();
    c->min = std::int16_t(1);
    c->max = std::int16_t(3);
    run(*c);
    const auto output = [&] { return int(dynamic_cast<SFShort&>(*c->output("output"))()); };
    CHECK(output() == 1);
    std::vector<int> seen;
    for (int i = 0; i < 4; ++i) {
        c->trigger.touch();
        run(*c);
        seen.push_back(output());
    }
    CHECK(seen == std::vector<int>{2, 3, 1, 2});
    CHECK(dynamic_cast<SFTrigger&>(*c->output("syncOut")).count() == 1);
}

TEST_CASE("OneShot runs for its duration after a trigger") {
    auto o = OneShot::create();
    o->duration = 2.0;
    run(*o, 0.0);
    o->trigger.touch();
    run(*o, 1.0);
    run(*o, 2.0);
    CHECK(dynamic_cast<SFTime&>(*o->output("timeOut"))() == doctest::Approx(1.0));
    CHECK(dynamic_cast<SFFloat&>(*o->output("ramp"))() == doctest::Approx(0.5));
    CHECK(dynamic_cast<SFBool&>(*o->output("isActive"))());
    run(*o, 3.5);
    CHECK_FALSE(dynamic_cast<SFBool&>(*o->output("isActive"))());
    CHECK(dynamic_cast<SFTime&>(*o->output("timeOut"))() == 0.0);
}

TEST_CASE("Calculator evaluates its expression language") {
    CHECK(calc("oa = a + b * 2", {1}, {3}) == std::vector<float>{7});
    CHECK(calc("oa = (a > b) ? a : b", {4}, {9}) == std::vector<float>{9});
    CHECK(calc("oa = a - -b; ob = a % b", {7}, {3}) == std::vector<float>{10});
    CHECK(calc("oa = a - -b; ob = a % b", {7}, {3}, "ob") == std::vector<float>{1});
    CHECK(calc("ta = sin(M_PI / 2); oc = ta * 3 + pow(2, 3) + fmod(7, 4)", {0}, {0}, "oc") ==
          std::vector<float>{14});
    CHECK(calc("od = (a == 1 && b != 1) || !(a < b) ? 1 : 0", {1}, {2}, "od") ==
          std::vector<float>{1});
    CHECK(calc("oa = A[0] + B[1] + length(B) + dot(A, B)", {0}, {0}) == std::vector<float>{5});
    CHECK(calc("oa = floor(2.7) + ceil(0.2) + fabs(-3) + sqrt(16) + atan2(0, 1) + exp(0)", {0},
               {0}) == std::vector<float>{11});
    // Per index: the longest input sets the count, shorter ones repeat their last value.
    CHECK(calc("oa = a + b", {1, 2, 3}, {10}) == std::vector<float>{11, 12, 13});
    // Vectors: vec3f, cross, normalize, scaling, components of an output.
    auto c = Calculator::create();
    c->a = {2.0f};
    c->A = {glm::vec3(1, 0, 0)};
    c->B = {glm::vec3(0, 1, 0)};
    c->expression = {"oA = cross(A, B) * a; oB = normalize(vec3f(3, 0, 4)); oC = A + B - A / 2",
                     "oD[2] = 5; oD[0] = oA[2]"};
    run(*c);
    CHECK(vecs(*c, "oA") == std::vector<glm::vec3>{glm::vec3(0, 0, 2)});
    CHECK(vecs(*c, "oB")[0].x == doctest::Approx(0.6));
    CHECK(vecs(*c, "oC") == std::vector<glm::vec3>{glm::vec3(0.5f, 1, 0)});
    CHECK(vecs(*c, "oD") == std::vector<glm::vec3>{glm::vec3(2, 0, 5)});
    // Malformed expressions are errors naming the place.
    CHECK_THROWS_WITH_AS(Calculator::check("oa = a +"), doctest::Contains("at character 9"), Error);
    CHECK_THROWS_WITH_AS(Calculator::check("a = 1"), doctest::Contains("only outputs"), Error);
    CHECK_THROWS_WITH_AS(Calculator::check("oa = A"), doctest::Contains("vector"), Error);
    CHECK_THROWS_WITH_AS(Calculator::check("oa = nosuch(1)"), doctest::Contains("unknown name"),
                         Error);
    CHECK_THROWS_AS(read("Cube { width 1 = Calculator { expression \"oa = (\" } . oa }"), Error);
}

TEST_CASE("Interpolate engines blend at alpha, rotations spherically") {
    auto f = InterpolateFloat::create();
    f->alpha = 0.25f;
    f->input0 = {0.0f, 10.0f};
    f->input1 = {4.0f, 20.0f};
    run(*f);
    CHECK(floats(*f, "output") == std::vector<float>{1.0f, 12.5f});
    auto v = InterpolateVec3f::create();
    v->alpha = 0.5f;
    v->input0 = {glm::vec3(0, 0, 0)};
    v->input1 = {glm::vec3(2, 4, 6)};
    run(*v);
    CHECK(vecs(*v, "output") == std::vector<glm::vec3>{glm::vec3(1, 2, 3)});
    auto r = InterpolateRotation::create();
    r->alpha = 0.5f;
    r->input0 = {Rotation{glm::vec3(0, 0, 1), 0.0f}};
    r->input1 = {Rotation{glm::vec3(0, 0, 1), float(std::numbers::pi / 2)}};
    run(*r);
    const Rotation half = dynamic_cast<MFRotation&>(*r->output("output"))[0];
    CHECK(half.angle == doctest::Approx(std::numbers::pi / 4));
    CHECK(half.axis.z == doctest::Approx(1.0));
}

TEST_CASE("Compose and Decompose engines invert each other") {
    auto compose = ComposeMatrix::create();
    compose->translation = {glm::vec3(1, 2, 3)};
    compose->rotation = {Rotation{glm::normalize(glm::vec3(1, 1, 0)), 0.7f}};
    compose->scaleFactor = {glm::vec3(2, 3, 4)};
    compose->center = {glm::vec3(0.5f, 0, 0)};
    run(*compose);
    const glm::mat4 m = dynamic_cast<MFMatrix&>(*compose->output("matrix"))[0];
    auto decompose = DecomposeMatrix::create();
    decompose->matrix = {m};
    decompose->center = {glm::vec3(0.5f, 0, 0)};
    run(*decompose);
    auto again = ComposeMatrix::create();
    again->translation = dynamic_cast<MFVec3f&>(*decompose->output("translation")).getValues();
    again->rotation = dynamic_cast<MFRotation&>(*decompose->output("rotation")).getValues();
    again->scaleFactor = dynamic_cast<MFVec3f&>(*decompose->output("scaleFactor")).getValues();
    again->scaleOrientation =
        dynamic_cast<MFRotation&>(*decompose->output("scaleOrientation")).getValues();
    again->center = {glm::vec3(0.5f, 0, 0)};
    run(*again);
    const glm::mat4 m2 = dynamic_cast<MFMatrix&>(*again->output("matrix"))[0];
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 4; ++k)
            CHECK(m2[i][k] == doctest::Approx(m[i][k]).epsilon(1e-4));
    CHECK(dynamic_cast<MFVec3f&>(*decompose->output("translation"))[0].y == doctest::Approx(2.0));

    auto fromTo = ComposeRotationFromTo::create();
    fromTo->from = {glm::vec3(1, 0, 0)};
    fromTo->to = {glm::vec3(0, 1, 0)};
    run(*fromTo);
    const Rotation r = dynamic_cast<MFRotation&>(*fromTo->output("rotation"))[0];
    CHECK(r.angle == doctest::Approx(std::numbers::pi / 2));
    CHECK(r.axis.z == doctest::Approx(1.0));
    auto split = DecomposeVec3f::create();
    split->vector = {glm::vec3(1, 2, 3), glm::vec3(4, 5, 6)};
    run(*split);
    CHECK(floats(*split, "z") == std::vector<float>{3, 6});
}

TEST_CASE("BoolOperation, SelectOne, Gate and Concatenate") {
    auto b = BoolOperation::create();
    b->a = {true, true, false};
    b->b = {false, true, false};
    b->operation = {"A_AND_B", "A_EQUALS_B", "NOT_A_AND_NOT_B"};
    run(*b);
    CHECK(dynamic_cast<MFBool&>(*b->output("output")).getValues() ==
          std::vector<bool>{false, true, true});
    CHECK(dynamic_cast<MFBool&>(*b->output("inverse")).getValues() ==
          std::vector<bool>{true, false, false});

    auto root = read("Separator {"
                     "  Cube { width 1 = SelectOne { type MFFloat input [ 5, 6, 7 ] index 2 } . "
                     "output }"
                     "  Coordinate3 { point [ ] = Concatenate { type MFVec3f input0 [ 1 1 1 ] "
                     "input1 [ 2 2 2, 3 3 3 ] } . output }"
                     "  Cube { height 1 = Gate { type MFFloat input 9 enable FALSE } . output }"
                     "}");
    ConnectionEvaluator evaluator;
    evaluator.evaluate(*root, 0.0);
    CHECK(child<Cube>(*root, 0)->width() == 7.0f);
    CHECK(dynamic_cast<MFVec3f*>((*root->children())[1]->field("point"))->size() == 3);
    // A closed gate passes nothing: the field keeps its value.
    CHECK(child<Cube>(*root, 2)->height() == 1.0f);
}

TEST_CASE("the global field realTime is the scene time") {
    auto root = read("Cube { width 0 = GlobalField { type SFTime realTime 0 } . realTime }");
    auto* cube = dynamic_cast<Cube*>(root.get());
    REQUIRE(cube);
    evaluateConnections(*root, 2.5);
    CHECK(cube->width() == 2.5f);
}

TEST_CASE("a node field connected to another node's field follows it, versions change only "
          "with values") {
    auto root = read("Separator { DEF a Transform { translation 1 2 3 }"
                     "  Transform { translation 0 0 0 = USE a.translation }"
                     "  Material { diffuseColor 0 0 0 = ComposeVec3f { x 1 } . vector } }");
    auto* a = child<Transform>(*root, 0);
    auto* b = child<Transform>(*root, 1);
    auto* m = child<Material>(*root, 2);
    ConnectionEvaluator evaluator;
    evaluator.evaluate(*root, 0.0);
    CHECK(b->translation() == glm::vec3(1, 2, 3));
    CHECK(m->diffuseColor() == std::vector<glm::vec3>{glm::vec3(1, 0, 0)});
    const std::uint64_t vb = b->version(), vm = m->version();
    CHECK(evaluator.evaluate(*root, 1.0) == 0);
    CHECK(b->version() == vb);
    CHECK(m->version() == vm);
    a->translation = glm::vec3(4, 5, 6);
    CHECK(evaluator.evaluate(*root, 2.0) == 1);
    CHECK(b->translation() == glm::vec3(4, 5, 6));
    CHECK(m->version() == vm);
}

TEST_CASE("a warning about a node read from a file names the file, line and column") {
    // Line 3 of engines.iv (the header is line 1): a translation fed booleans, which the
    // reader cannot check (an engine's output type is known when it runs).
    const ref_ptr<Node> root = read("Separator {\n"
                                    "  Transform { translation = BoolOperation { } . output }\n"
                                    "}\n");
    std::vector<std::string> warnings;
    ConnectionEvaluator evaluator([&](const std::string& w) { warnings.push_back(w); });
    evaluator.evaluate(*root, 0.0);
    REQUIRE(warnings.size() == 1);
    CHECK(warnings[0].starts_with("engines.iv:3:3: field 'translation' of Transform: "));
}

TEST_CASE("a cycle of connections is broken with one warning") {
    auto c1 = Calculator::create();
    auto c2 = Calculator::create();
    c1->expression = {"oa = a + 1"};
    c2->expression = {"oa = a + 1"};
    c1->a.connectFrom(c2, "oa");
    c2->a.connectFrom(c1, "oa");
    auto root = Separator::create();
    auto cube = Cube::create();
    cube->width.connectFrom(c1, "oa");
    root->addChild(cube);
    std::vector<std::string> warnings;
    ConnectionEvaluator evaluator([&](const std::string& w) { warnings.push_back(w); });
    evaluator.evaluate(*root, 0.0);
    REQUIRE(warnings.size() == 1);
    CHECK(warnings[0].find("connection cycle") != std::string::npos);
    CHECK(warnings[0].find('\n') == std::string::npos);
    const float first = cube->width();
    evaluator.evaluate(*root, 1.0);
    CHECK(warnings.size() == 1);   // once per evaluator
    CHECK(cube->width() == first); // the broken link keeps the values still
    // Break the cycle so the engines can be freed.
    c1->a.disconnect();
    c2->a.disconnect();
}
