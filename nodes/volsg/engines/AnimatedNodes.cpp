#include <volsg/actions/Action.h>
#include <volsg/engines/AnimatedNodes.h>

#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

namespace volsg {

double AnimationPhase::advance(double seconds, double speed, bool on) {
    if (!started_) {
        started_ = true;
        phase_ = on ? speed * seconds : 0.0;
    } else if (on) {
        phase_ += speed * (seconds - last_);
    }
    last_ = seconds;
    return phase_;
}

namespace {
// The fractional part keeps the angle exact for long runs.
double cyclesToRadians(double cycles) {
    return 2.0 * std::numbers::pi * (cycles - std::floor(cycles));
}

Rotation slerp(const Rotation& a, const Rotation& b, double t) {
    const glm::dquat q = glm::normalize(glm::slerp(a.quat(), b.quat(), t));
    const double w = std::min(1.0, std::max(-1.0, q.w));
    const double s = std::sqrt(std::max(0.0, 1.0 - w * w));
    Rotation r;
    if (s < 1e-12) return r;
    r.axis = glm::vec3(q.x / s, q.y / s, q.z / s);
    r.angle = float(2.0 * std::acos(w));
    return r;
}
} // namespace

void Rotor::animate(double seconds) {
    const bool first = !phase_.started();
    const double cycles = phase_.advance(seconds, double(speed()), on());
    if (first) {
        // The file's rotation is the angle at time 0.
        base_ = rotation();
        baseCycles_ = 0.0;
    } else if (!(rotation() == last_)) {
        // Set by someone else (an editor): it is the angle now, and turning goes on from it.
        base_ = rotation();
        baseCycles_ = cycles;
    }
    Rotation r = base_;
    r.angle = float(std::fmod(double(base_.angle) + cyclesToRadians(cycles - baseCycles_),
                              2.0 * std::numbers::pi));
    if (!(r == rotation())) rotation = r;
    last_ = rotation();
}

void Rotor::doAction(Action& action) {
    action.state().multModelMatrix(rotation().matrix());
}

void Pendulum::animate(double seconds) {
    const double cycles = phase_.advance(seconds, double(speed()), on());
    const double alpha = (1.0 - std::cos(cyclesToRadians(cycles))) * 0.5;
    const Rotation r = slerp(rotation0(), rotation1(), alpha);
    if (rotation.isDefault() || !(r == rotation())) rotation = r;
}

void Pendulum::doAction(Action& action) {
    action.state().multModelMatrix(rotation().matrix());
}

void Shuttle::animate(double seconds) {
    const double cycles = phase_.advance(seconds, double(speed()), on());
    const double alpha = (1.0 - std::cos(cyclesToRadians(cycles))) * 0.5;
    const glm::vec3 t =
        glm::vec3(glm::dvec3(translation0()) * (1.0 - alpha) + glm::dvec3(translation1()) * alpha);
    if (translation.isDefault() || t != translation()) translation = t;
}

void Shuttle::doAction(Action& action) {
    action.state().multModelMatrix(glm::translate(glm::dmat4(1.0), glm::dvec3(translation())));
}

int Blinker::childAt(double phase, std::size_t children) {
    if (children == 0) return SWITCH_NONE;
    // Inventor's Blinker counts from 0 to the last child; with one child from -1 (none) to 0.
    const int lo = children == 1 ? -1 : 0;
    const int count = children == 1 ? 2 : int(children);
    // A speed of infinity (set in code) makes the phase infinite: the first child, not an
    // int made of NaN.
    const double f = std::isfinite(phase) ? phase - std::floor(phase) : 0.0;
    return lo + std::min(count - 1, int(f * count));
}

void Blinker::animate(double seconds) {
    const double cycles = phase_.advance(seconds, double(speed()), on() && speed() > 0.0f);
    if (!on() || speed() <= 0.0f) return;
    const int which = childAt(cycles, getNumChildren());
    if (whichChild.isDefault() || which != whichChild()) whichChild = which;
}

} // namespace volsg
