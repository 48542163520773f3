#pragma once
// The play clock of a series (the viewer's play/pause and speed), free of UI and nodes.

namespace volsg {

/// Plays steps at a speed in steps per second. A frame shows at most one new step: when
/// frames are slower than the speed, playback slows down rather than skipping steps (every
/// step is seen, and prefetching stays one step ahead of what is shown).
class SeriesPlayer {
public:
    void play(double now);
    void pause() { playing_ = false; }
    bool playing() const { return playing_; }
    /// Clamped to [0.1, 120].
    void setStepsPerSecond(double stepsPerSecond);
    double stepsPerSecond() const { return stepsPerSecond_; }
    /// +1 forward, -1 backward.
    void setDirection(int direction) { direction_ = direction < 0 ? -1 : 1; }
    int direction() const { return direction_; }

    /// The step to show at time `now` (seconds, any clock) given the shown `current` of
    /// `count` steps: the next one in the direction of play when a period has passed since the
    /// last step, else `current`. At an end: wraps when `loop`, else pauses there.
    int advance(double now, int current, int count, bool loop);

private:
    bool playing_ = false;
    double stepsPerSecond_ = 10.0;
    int direction_ = 1;
    double lastStepTime_ = 0.0;
};

} // namespace volsg
