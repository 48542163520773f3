// The viewer's frame-rate rule: slow interactive frames lower the plane scale, fast ones raise
// it back, still frames leave it alone.
#include <doctest/doctest.h>

#include <cmath>

#include "view/InteractiveQuality.h"

using volsg::InteractiveQuality;

TEST_CASE("a slow interactive frame lowers the plane scale in proportion") {
    InteractiveQuality q;
    CHECK(q.scale() == 1.0);
    q.frameDone(true, 160.0); // aim at 80 ms: half the planes
    CHECK(q.scale() == doctest::Approx(0.5).epsilon(1e-12));
    q.frameDone(true, 1000.0); // far too slow: at most a quarter per frame
    CHECK(q.scale() == doctest::Approx(0.125).epsilon(1e-12));
    for (int i = 0; i < 40; ++i)
        q.frameDone(true, 5000.0);
    CHECK(q.scale() == doctest::Approx(InteractiveQuality::minimumScale).epsilon(1e-12));
}

TEST_CASE("frames within the budget keep the scale and fast frames win it back") {
    InteractiveQuality q;
    q.frameDone(true, 99.0); // within budget, not fast: unchanged
    CHECK(q.scale() == 1.0);
    q.frameDone(true, 200.0);
    CHECK(q.scale() == doctest::Approx(0.4).epsilon(1e-12));
    q.frameDone(true, 20.0);
    CHECK(q.scale() == doctest::Approx(0.5).epsilon(1e-12));
    for (int i = 0; i < 10; ++i)
        q.frameDone(true, 20.0);
    CHECK(q.scale() == 1.0); // never above full
}

TEST_CASE("still frames do not change the interactive plane scale") {
    InteractiveQuality q;
    q.frameDone(false, 900.0); // a slow still frame is full quality by design
    CHECK(q.scale() == 1.0);
    q.frameDone(true, 400.0);
    const double learned = q.scale();
    q.frameDone(false, 10.0);
    CHECK(q.scale() == learned);
}

TEST_CASE("the cost goes into the resolution first, then into the planes") {
    InteractiveQuality q;
    CHECK(q.resolutionScale() == 1.0);
    CHECK(q.planeScale() == 1.0);
    q.frameDone(true, 160.0); // half the cost: sqrt(0.5) = 0.707 -> 12/16 of the width
    CHECK(q.resolutionScale() == 0.75);
    CHECK(q.planeScale() == doctest::Approx(0.5 / 0.5625).epsilon(1e-12));
    for (int i = 0; i < 40; ++i) // far too slow: the smallest cost
        q.frameDone(true, 5000.0);
    CHECK(q.scale() == InteractiveQuality::minimumScale);
    CHECK(q.resolutionScale() == 0.25);     // a quarter of the width and height
    CHECK(q.planeScale() == 0.25);          // and a quarter of the planes
    for (int step = 0; step < 40; ++step) { // on the way back: resolution x planes = cost
        q.frameDone(true, 20.0);
        CHECK(q.resolutionScale() >= 0.25);
        CHECK(q.resolutionScale() <= 1.0);
        CHECK(q.planeScale() >= 0.25);
        CHECK(q.planeScale() <= 1.0);
        CHECK(q.resolutionScale() * 16.0 == std::round(q.resolutionScale() * 16.0));
        if (q.scale() >= InteractiveQuality::minimumPixelFraction) // planes kept while it can
            CHECK(q.resolutionScale() * q.resolutionScale() * q.planeScale() ==
                  doctest::Approx(q.scale()).epsilon(1e-12));
    }
}
