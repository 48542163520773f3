#pragma once
// Nodes that animate themselves with the scene time (docs/SCENE-FORMAT.md section 1.10):
// Inventor's Rotor, Pendulum, Shuttle and Blinker. The evaluator (Evaluator.h) calls animate()
// on each one in the graph once per evaluation.

#include <cstdint>

#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>
#include <volsg/nodes/Switch.h>

namespace volsg {

/// A node whose fields follow the scene time.
class Animated {
public:
    virtual ~Animated() = default;
    /// Brings the node's fields to `seconds` (scene time); sets them only when they change.
    virtual void animate(double seconds) = 0;
};

/// Keeps the phase (cycles) of an animation running at `speed` cycles a second while on:
/// speed * t from time 0 when always on, continuing where it was after a pause.
class AnimationPhase {
public:
    double advance(double seconds, double speed, bool on);
    bool started() const { return started_; }

private:
    bool started_ = false;
    double last_ = 0.0;
    double phase_ = 0.0;
};

/// A rotation that turns about its axis: at scene time t the angle is the file's angle plus
/// speed * 2 pi * t (speed in turns a second), while `on`. Multiplies the model matrix by the
/// rotation, as a Rotation node does.
class Rotor : public Inherit<Node, Rotor>, public Animated {
public:
    static constexpr const char* typeName = "Rotor";
    static constexpr bool inventorBuiltin() { return true; }
    SFRotation rotation{this, "rotation"};
    SFFloat speed{this, "speed", 1.0f};
    SFBool on{this, "on", true};

    void animate(double seconds) override;
    void doAction(Action& action) override;

protected:
    ~Rotor() override = default;

private:
    AnimationPhase phase_;
    Rotation base_, last_;
    double baseCycles_ = 0.0;
};

/// Swings between rotation0 and rotation1: rotation = slerp(rotation0, rotation1, alpha) with
/// alpha = (1 - cos(2 pi speed t)) / 2, while `on`.
class Pendulum : public Inherit<Node, Pendulum>, public Animated {
public:
    static constexpr const char* typeName = "Pendulum";
    static constexpr bool inventorBuiltin() { return true; }
    SFRotation rotation{this, "rotation"};
    SFRotation rotation0{this, "rotation0"};
    SFRotation rotation1{this, "rotation1"};
    SFFloat speed{this, "speed", 1.0f};
    SFBool on{this, "on", true};

    void animate(double seconds) override;
    void doAction(Action& action) override;

protected:
    ~Pendulum() override = default;

private:
    AnimationPhase phase_;
};

/// Moves between translation0 and translation1 as a Pendulum swings; translates the model
/// matrix, as a Translation node does.
class Shuttle : public Inherit<Node, Shuttle>, public Animated {
public:
    static constexpr const char* typeName = "Shuttle";
    static constexpr bool inventorBuiltin() { return true; }
    SFVec3f translation{this, "translation", glm::vec3(0.0f)};
    SFVec3f translation0{this, "translation0", glm::vec3(0.0f)};
    SFVec3f translation1{this, "translation1", glm::vec3(0.0f)};
    SFFloat speed{this, "speed", 1.0f};
    SFBool on{this, "on", true};

    void animate(double seconds) override;
    void doAction(Action& action) override;

protected:
    ~Shuttle() override = default;

private:
    AnimationPhase phase_;
};

/// A Switch that shows its children in turn, `speed` cycles through all of them a second
/// (one child: on for half a cycle, off for the other half), while `on`.
class Blinker : public Inherit<Switch, Blinker>, public Animated {
public:
    static constexpr const char* typeName = "Blinker";
    static constexpr bool inventorBuiltin() { return true; }
    SFFloat speed{this, "speed", 1.0f};
    SFBool on{this, "on", true};

    void animate(double seconds) override;
    /// whichChild at `phase` cycles for `children` children.
    static int childAt(double phase, std::size_t children);

protected:
    ~Blinker() override = default;

private:
    AnimationPhase phase_;
};

} // namespace volsg
