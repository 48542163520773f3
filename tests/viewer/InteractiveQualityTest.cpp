// The viewer's frame-rate rule: slow interactive frames lower the plane scale, fast ones raise
// it back, still frames leave it alone.
#include <doctest/doctest.h>

#include "view/InteractiveQuality.h"

using volsg::InteractiveQuality;

TEST_CASE("a slow interactive frame lowers the plane scale in proportion") {
    InteractiveQuality q;
    CHECK(q.scale() == 1.0);
    q.frameDone(true, 160.0); // aim at 80 ms: half the planes
    CHECK(q.scale() == doctest::Approx(0.5).epsilon(1e-12));
    q.frameDone(true, 1000.0); // far too slow: at most a quarter per frame
    CHECK(q.scale() == doctest::Approx(0.125).epsilon(1e-12));
    for (int i = 0; i < 20; ++i)
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
