// The play clock behind the viewer's series panel.
#include <doctest/doctest.h>

#include <volsg/series/SeriesPlayer.h>

using namespace volsg;

TEST_CASE("the player steps once per period in its direction and wraps when looping") {
    SeriesPlayer player;
    player.setStepsPerSecond(10.0);
    CHECK(player.advance(5.0, 3, 10, true) == 3); // paused
    player.play(0.0);
    CHECK(player.advance(0.05, 3, 10, true) == 3); // half a period
    CHECK(player.advance(0.11, 3, 10, true) == 4);
    CHECK(player.advance(0.15, 4, 10, true) == 4);
    CHECK(player.advance(0.21, 4, 10, true) == 5);
    CHECK(player.advance(0.31, 9, 10, true) == 0); // past the end: wraps
    player.setDirection(-1);
    CHECK(player.advance(0.41, 0, 10, true) == 9);
    CHECK(player.advance(0.51, 9, 10, true) == 8);
}

TEST_CASE("slow frames slow playback down instead of skipping steps") {
    SeriesPlayer player;
    player.setStepsPerSecond(10.0);
    player.play(0.0);
    CHECK(player.advance(1.0, 0, 100, true) == 1);  // ten periods late: still one step
    CHECK(player.advance(1.05, 1, 100, true) == 1); // the clock restarted at 1.0
    CHECK(player.advance(1.11, 1, 100, true) == 2);
}

TEST_CASE("without loop the player pauses at the last step") {
    SeriesPlayer player;
    player.play(0.0);
    CHECK(player.advance(0.11, 8, 10, false) == 9);
    CHECK(player.advance(0.21, 9, 10, false) == 9);
    CHECK_FALSE(player.playing());
    player.setStepsPerSecond(1000.0);
    CHECK(player.stepsPerSecond() == 120.0);
}
