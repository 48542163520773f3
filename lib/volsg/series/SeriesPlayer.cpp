#include <volsg/series/SeriesPlayer.h>

#include <algorithm>

namespace volsg {

void SeriesPlayer::play(double now) {
    playing_ = true;
    lastStepTime_ = now;
}

void SeriesPlayer::setStepsPerSecond(double stepsPerSecond) {
    stepsPerSecond_ = std::clamp(stepsPerSecond, 0.1, 120.0);
}

int SeriesPlayer::advance(double now, int current, int count, bool loop) {
    if (!playing_ || count < 2) return current;
    if (now - lastStepTime_ < 1.0 / stepsPerSecond_) return current;
    // Behind by more than a period (slow frames): restart the clock instead of catching up.
    lastStepTime_ =
        now - lastStepTime_ < 2.0 / stepsPerSecond_ ? lastStepTime_ + 1.0 / stepsPerSecond_ : now;
    int next = current + direction_;
    if (next < 0 || next >= count) {
        if (!loop) {
            playing_ = false;
            return current;
        }
        next = (next + count) % count;
    }
    return next;
}

} // namespace volsg
