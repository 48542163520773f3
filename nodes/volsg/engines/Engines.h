#pragma once
// Inventor's engines (docs/SCENE-FORMAT.md section 1.10): each is evaluated by the evaluator
// (Evaluator.h) after its inputs' connections; its outputs feed fields connected to them.
// Inputs that are lists are used value by value: output i comes from value i of every input,
// an input with fewer values repeating its last one (none: its default).

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <volsg/engines/Engine.h>

namespace volsg {

/// Counts time while `on` and not `pause`: timeOut = elapsed time * speed, from its first
/// evaluation (Inventor counts from the engine's creation; here the scene's clock, so a scene
/// evaluated from time 0 gives timeOut = speed * t). `reset` restarts at 0. timeIn, when
/// connected, replaces the scene time.
class ElapsedTime : public Inherit<Engine, ElapsedTime> {
public:
    static constexpr const char* typeName = "ElapsedTime";
    static constexpr bool inventorBuiltin() { return true; }
    SFTime timeIn{this, "timeIn"};
    SFFloat speed{this, "speed", 1.0f};
    SFBool on{this, "on", true};
    SFBool pause{this, "pause", false};
    SFTrigger reset{this, "reset"};
    void evaluate(const EngineContext& context) override;

protected:
    ~ElapsedTime() override = default;
    std::vector<OutputSpec> outputSpecs() const override { return {{"timeOut", "SFTime"}}; }

private:
    bool started_ = false;
    double last_ = 0.0, elapsed_ = 0.0;
    std::uint64_t resets_ = 0;
};

/// Steps `output` from min to max by step, `frequency` cycles a second (each value for an
/// equal share of a cycle, or as `duty` weights them); syncOut fires at each cycle's start.
/// Time as ElapsedTime: from the first evaluation, while `on`. `reset` (a value) restarts the
/// cycle at it; syncIn restarts at min.
class TimeCounter : public Inherit<Engine, TimeCounter> {
public:
    static constexpr const char* typeName = "TimeCounter";
    static constexpr bool inventorBuiltin() { return true; }
    SFTime timeIn{this, "timeIn"};
    SFShort min{this, "min", 0};
    SFShort max{this, "max", 1};
    SFShort step{this, "step", 1};
    SFBool on{this, "on", true};
    SFFloat frequency{this, "frequency", 1.0f};
    MFFloat duty{this, "duty", {1.0f}};
    SFShort reset{this, "reset", 0};
    SFTrigger syncIn{this, "syncIn"};
    void evaluate(const EngineContext& context) override;
    /// The output at `phase` cycles from the start (for tests: the closed form).
    std::int16_t valueAt(double phase) const;

protected:
    ~TimeCounter() override = default;
    std::vector<OutputSpec> outputSpecs() const override {
        return {{"output", "SFShort"}, {"syncOut", "SFTrigger"}};
    }

private:
    bool started_ = false;
    double last_ = 0.0, phase_ = 0.0;
    std::uint64_t syncs_ = 0;
    bool resetSeen_ = false;
    std::int64_t cycle_ = -1;
};

/// Counts the `trigger` events: min, min + step, ... max, then min again; syncOut fires when
/// it wraps. Setting `reset` puts the output there.
class Counter : public Inherit<Engine, Counter> {
public:
    static constexpr const char* typeName = "Counter";
    static constexpr bool inventorBuiltin() { return true; }
    SFShort min{this, "min", 0};
    SFShort max{this, "max", 1};
    SFShort step{this, "step", 1};
    SFTrigger trigger{this, "trigger"};
    SFShort reset{this, "reset", 0};
    void evaluate(const EngineContext& context) override;

protected:
    ~Counter() override = default;
    std::vector<OutputSpec> outputSpecs() const override {
        return {{"output", "SFShort"}, {"syncOut", "SFTrigger"}};
    }

private:
    std::uint64_t triggers_ = 0;
    bool resetSeen_ = false;
    int value_ = 0;
    bool started_ = false;
};

/// Runs for `duration` seconds after each `trigger`: timeOut from 0 to duration, ramp from 0
/// to 1, isActive meanwhile. flags RETRIGGERABLE (a trigger while active restarts it) and
/// HOLD_FINAL (keep the final values afterwards instead of going back to 0).
class OneShot : public Inherit<Engine, OneShot> {
public:
    static constexpr const char* typeName = "OneShot";
    static constexpr bool inventorBuiltin() { return true; }
    enum Flags { RETRIGGERABLE = 1, HOLD_FINAL = 2 };
    static const EnumValues flagNames;
    SFTime timeIn{this, "timeIn"};
    SFTime duration{this, "duration", 1.0};
    SFTrigger trigger{this, "trigger"};
    SFBitMask flags{this, "flags", flagNames, 0};
    SFBool disable{this, "disable", false};
    void evaluate(const EngineContext& context) override;

protected:
    ~OneShot() override = default;
    std::vector<OutputSpec> outputSpecs() const override {
        return {{"timeOut", "SFTime"}, {"isActive", "SFBool"}, {"ramp", "SFFloat"}};
    }

private:
    std::uint64_t triggers_ = 0;
    bool active_ = false, ran_ = false;
    double start_ = 0.0;
};

/// isOn / isOff after the `on`, `off` and `toggle` events.
class OnOff : public Inherit<Engine, OnOff> {
public:
    static constexpr const char* typeName = "OnOff";
    static constexpr bool inventorBuiltin() { return true; }
    SFTrigger on{this, "on"};
    SFTrigger off{this, "off"};
    SFTrigger toggle{this, "toggle"};
    void evaluate(const EngineContext& context) override;

protected:
    ~OnOff() override = default;
    std::vector<OutputSpec> outputSpecs() const override {
        return {{"isOn", "SFBool"}, {"isOff", "SFBool"}};
    }

private:
    std::uint64_t seen_[3] = {0, 0, 0};
    bool state_ = false;
};

/// Fires `output` when any of its ten inputs fires.
class TriggerAny : public Inherit<Engine, TriggerAny> {
public:
    static constexpr const char* typeName = "TriggerAny";
    static constexpr bool inventorBuiltin() { return true; }
    SFTrigger input0{this, "input0"}, input1{this, "input1"}, input2{this, "input2"},
        input3{this, "input3"}, input4{this, "input4"}, input5{this, "input5"},
        input6{this, "input6"}, input7{this, "input7"}, input8{this, "input8"},
        input9{this, "input9"};
    void evaluate(const EngineContext& context) override;

protected:
    ~TriggerAny() override = default;
    std::vector<OutputSpec> outputSpecs() const override { return {{"output", "SFTrigger"}}; }

private:
    std::uint64_t seen_ = 0;
};

/// output[i] = operation[i] of a[i] and b[i]: CLEAR, SET, A, NOT_A, B, NOT_B, A_OR_B, ...
/// A_EQUALS_B, A_NOT_EQUALS_B (Inventor's 16 names); inverse is its negation.
class BoolOperation : public Inherit<Engine, BoolOperation> {
public:
    static constexpr const char* typeName = "BoolOperation";
    static constexpr bool inventorBuiltin() { return true; }
    MFBool a{this, "a", {false}};
    MFBool b{this, "b", {false}};
    MFEnumWord operation{this, "operation", {"A"}};
    void evaluate(const EngineContext& context) override;

protected:
    ~BoolOperation() override = default;
    std::vector<OutputSpec> outputSpecs() const override {
        return {{"output", "MFBool"}, {"inverse", "MFBool"}};
    }
};

/// The Compose engines: a vector from its components, a rotation from axis and angle or from
/// one direction to another, a matrix from a transform's parts (Inventor's SbMatrix::setTransform).
class ComposeVec2f : public Inherit<Engine, ComposeVec2f> {
public:
    static constexpr const char* typeName = "ComposeVec2f";
    static constexpr bool inventorBuiltin() { return true; }
    MFFloat x{this, "x", {0.0f}}, y{this, "y", {0.0f}};
    void evaluate(const EngineContext& context) override;

protected:
    ~ComposeVec2f() override = default;
    std::vector<OutputSpec> outputSpecs() const override { return {{"vector", "MFVec2f"}}; }
};
class ComposeVec3f : public Inherit<Engine, ComposeVec3f> {
public:
    static constexpr const char* typeName = "ComposeVec3f";
    static constexpr bool inventorBuiltin() { return true; }
    MFFloat x{this, "x", {0.0f}}, y{this, "y", {0.0f}}, z{this, "z", {0.0f}};
    void evaluate(const EngineContext& context) override;

protected:
    ~ComposeVec3f() override = default;
    std::vector<OutputSpec> outputSpecs() const override { return {{"vector", "MFVec3f"}}; }
};
class ComposeVec4f : public Inherit<Engine, ComposeVec4f> {
public:
    static constexpr const char* typeName = "ComposeVec4f";
    static constexpr bool inventorBuiltin() { return true; }
    MFFloat x{this, "x", {0.0f}}, y{this, "y", {0.0f}}, z{this, "z", {0.0f}}, w{this, "w", {0.0f}};
    void evaluate(const EngineContext& context) override;

protected:
    ~ComposeVec4f() override = default;
    std::vector<OutputSpec> outputSpecs() const override { return {{"vector", "MFVec4f"}}; }
};
class DecomposeVec2f : public Inherit<Engine, DecomposeVec2f> {
public:
    static constexpr const char* typeName = "DecomposeVec2f";
    static constexpr bool inventorBuiltin() { return true; }
    MFVec2f vector{this, "vector", {glm::vec2(0.0f)}};
    void evaluate(const EngineContext& context) override;

protected:
    ~DecomposeVec2f() override = default;
    std::vector<OutputSpec> outputSpecs() const override {
        return {{"x", "MFFloat"}, {"y", "MFFloat"}};
    }
};
class DecomposeVec3f : public Inherit<Engine, DecomposeVec3f> {
public:
    static constexpr const char* typeName = "DecomposeVec3f";
    static constexpr bool inventorBuiltin() { return true; }
    MFVec3f vector{this, "vector", {glm::vec3(0.0f)}};
    void evaluate(const EngineContext& context) override;

protected:
    ~DecomposeVec3f() override = default;
    std::vector<OutputSpec> outputSpecs() const override {
        return {{"x", "MFFloat"}, {"y", "MFFloat"}, {"z", "MFFloat"}};
    }
};
class DecomposeVec4f : public Inherit<Engine, DecomposeVec4f> {
public:
    static constexpr const char* typeName = "DecomposeVec4f";
    static constexpr bool inventorBuiltin() { return true; }
    MFVec4f vector{this, "vector", {glm::vec4(0.0f)}};
    void evaluate(const EngineContext& context) override;

protected:
    ~DecomposeVec4f() override = default;
    std::vector<OutputSpec> outputSpecs() const override {
        return {{"x", "MFFloat"}, {"y", "MFFloat"}, {"z", "MFFloat"}, {"w", "MFFloat"}};
    }
};
class ComposeRotation : public Inherit<Engine, ComposeRotation> {
public:
    static constexpr const char* typeName = "ComposeRotation";
    static constexpr bool inventorBuiltin() { return true; }
    MFVec3f axis{this, "axis", {glm::vec3(0.0f, 0.0f, 1.0f)}};
    MFFloat angle{this, "angle", {0.0f}};
    void evaluate(const EngineContext& context) override;

protected:
    ~ComposeRotation() override = default;
    std::vector<OutputSpec> outputSpecs() const override { return {{"rotation", "MFRotation"}}; }
};
class ComposeRotationFromTo : public Inherit<Engine, ComposeRotationFromTo> {
public:
    static constexpr const char* typeName = "ComposeRotationFromTo";
    static constexpr bool inventorBuiltin() { return true; }
    MFVec3f from{this, "from", {glm::vec3(0.0f, 0.0f, 1.0f)}};
    MFVec3f to{this, "to", {glm::vec3(0.0f, 0.0f, 1.0f)}};
    void evaluate(const EngineContext& context) override;

protected:
    ~ComposeRotationFromTo() override = default;
    std::vector<OutputSpec> outputSpecs() const override { return {{"rotation", "MFRotation"}}; }
};
class DecomposeRotation : public Inherit<Engine, DecomposeRotation> {
public:
    static constexpr const char* typeName = "DecomposeRotation";
    static constexpr bool inventorBuiltin() { return true; }
    MFRotation rotation{this, "rotation", {Rotation{}}};
    void evaluate(const EngineContext& context) override;

protected:
    ~DecomposeRotation() override = default;
    std::vector<OutputSpec> outputSpecs() const override {
        return {{"axis", "MFVec3f"}, {"angle", "MFFloat"}};
    }
};
class ComposeMatrix : public Inherit<Engine, ComposeMatrix> {
public:
    static constexpr const char* typeName = "ComposeMatrix";
    static constexpr bool inventorBuiltin() { return true; }
    MFVec3f translation{this, "translation", {glm::vec3(0.0f)}};
    MFRotation rotation{this, "rotation", {Rotation{}}};
    MFVec3f scaleFactor{this, "scaleFactor", {glm::vec3(1.0f)}};
    MFRotation scaleOrientation{this, "scaleOrientation", {Rotation{}}};
    MFVec3f center{this, "center", {glm::vec3(0.0f)}};
    void evaluate(const EngineContext& context) override;

protected:
    ~ComposeMatrix() override = default;
    std::vector<OutputSpec> outputSpecs() const override { return {{"matrix", "MFMatrix"}}; }
};
/// The inverse of ComposeMatrix for matrices made of translation, rotation and scale (a
/// shear is folded into scaleOrientation, as SbMatrix::getTransform does).
class DecomposeMatrix : public Inherit<Engine, DecomposeMatrix> {
public:
    static constexpr const char* typeName = "DecomposeMatrix";
    static constexpr bool inventorBuiltin() { return true; }
    MFMatrix matrix{this, "matrix", {glm::mat4(1.0f)}};
    MFVec3f center{this, "center", {glm::vec3(0.0f)}};
    void evaluate(const EngineContext& context) override;

protected:
    ~DecomposeMatrix() override = default;
    std::vector<OutputSpec> outputSpecs() const override {
        return {{"translation", "MFVec3f"},
                {"rotation", "MFRotation"},
                {"scaleFactor", "MFVec3f"},
                {"scaleOrientation", "MFRotation"}};
    }
};
/// point = vector * matrix (a point), direction (no translation), normalDirection (the
/// direction by the inverse transpose, normalised).
class TransformVec3f : public Inherit<Engine, TransformVec3f> {
public:
    static constexpr const char* typeName = "TransformVec3f";
    static constexpr bool inventorBuiltin() { return true; }
    MFVec3f vector{this, "vector", {glm::vec3(0.0f)}};
    MFMatrix matrix{this, "matrix", {glm::mat4(1.0f)}};
    void evaluate(const EngineContext& context) override;

protected:
    ~TransformVec3f() override = default;
    std::vector<OutputSpec> outputSpecs() const override {
        return {{"point", "MFVec3f"}, {"direction", "MFVec3f"}, {"normalDirection", "MFVec3f"}};
    }
};

/// output[i] = input0[i] * (1 - alpha) + input1[i] * alpha (rotations: spherical).
template <class MFType, const char* Name, const char* OutType>
class Interpolate : public Inherit<Engine, Interpolate<MFType, Name, OutType>> {
public:
    static constexpr const char* typeName = Name;
    static constexpr bool inventorBuiltin() { return true; }
    SFFloat alpha{this, "alpha", 0.0f};
    MFType input0{this, "input0"};
    MFType input1{this, "input1"};
    Interpolate();
    void evaluate(const EngineContext& context) override;

protected:
    ~Interpolate() override = default;
    std::vector<Engine::OutputSpec> outputSpecs() const override { return {{"output", OutType}}; }
};
inline constexpr char interpolateFloatName[] = "InterpolateFloat";
inline constexpr char interpolateVec2fName[] = "InterpolateVec2f";
inline constexpr char interpolateVec3fName[] = "InterpolateVec3f";
inline constexpr char interpolateVec4fName[] = "InterpolateVec4f";
inline constexpr char interpolateRotationName[] = "InterpolateRotation";
inline constexpr char mfFloatName[] = "MFFloat";
inline constexpr char mfVec2fName[] = "MFVec2f";
inline constexpr char mfVec3fName[] = "MFVec3f";
inline constexpr char mfVec4fName[] = "MFVec4f";
inline constexpr char mfRotationName[] = "MFRotation";
using InterpolateFloat = Interpolate<MFFloat, interpolateFloatName, mfFloatName>;
using InterpolateVec2f = Interpolate<MFVec2f, interpolateVec2fName, mfVec2fName>;
using InterpolateVec3f = Interpolate<MFVec3f, interpolateVec3fName, mfVec3fName>;
using InterpolateVec4f = Interpolate<MFVec4f, interpolateVec4fName, mfVec4fName>;
using InterpolateRotation = Interpolate<MFRotation, interpolateRotationName, mfRotationName>;

/// Engines whose input type is chosen in the file (`type MFFloat`): SelectOne, Gate and
/// Concatenate. `type` comes first; setting it makes the inputs and the output of that type.
class TypedEngine : public Inherit<Engine, TypedEngine> {
public:
    static constexpr const char* typeName = "TypedEngine";
    static constexpr bool inventorBuiltin() { return true; }
    SFName type{this, "type"};

    std::size_t fieldCount() const override;
    Field* fieldAt(std::size_t i) override;
    using Node::fieldAt;

protected:
    ~TypedEngine() override;
    /// Names of the dynamic inputs (after the fixed fields), all of `type`.
    virtual std::vector<const char*> inputNames() const = 0;
    /// The output's type for an input type (SelectOne: SF, the others: MF).
    virtual std::string outputType(const std::string& inputType) const = 0;
    std::vector<OutputSpec> outputSpecs() const override;
    Field* input(std::size_t i);
    void syncType() const;

private:
    mutable std::string madeFor_;
    mutable std::string outputType_;
    mutable std::vector<std::unique_ptr<Field>> inputs_;
};

/// output = input[index] (a single value of the input's type).
class SelectOne : public Inherit<TypedEngine, SelectOne> {
public:
    static constexpr const char* typeName = "SelectOne";
    static constexpr bool inventorBuiltin() { return true; }
    SFInt32 index{this, "index", 0};
    void evaluate(const EngineContext& context) override;

protected:
    ~SelectOne() override = default;
    std::vector<const char*> inputNames() const override { return {"input"}; }
    std::string outputType(const std::string& inputType) const override {
        return "SF" + inputType.substr(2);
    }
};

/// output = input while `enable`; `trigger` copies it once.
class Gate : public Inherit<TypedEngine, Gate> {
public:
    static constexpr const char* typeName = "Gate";
    static constexpr bool inventorBuiltin() { return true; }
    SFBool enable{this, "enable", false};
    SFTrigger trigger{this, "trigger"};
    void evaluate(const EngineContext& context) override;

protected:
    ~Gate() override = default;
    std::vector<const char*> inputNames() const override { return {"input"}; }
    std::string outputType(const std::string& inputType) const override { return inputType; }

private:
    std::uint64_t triggers_ = 0;
};

/// output = input0 followed by input1 ... input9.
class Concatenate : public Inherit<TypedEngine, Concatenate> {
public:
    static constexpr const char* typeName = "Concatenate";
    static constexpr bool inventorBuiltin() { return true; }
    void evaluate(const EngineContext& context) override;

protected:
    ~Concatenate() override = default;
    std::vector<const char*> inputNames() const override {
        return {"input0", "input1", "input2", "input3", "input4",
                "input5", "input6", "input7", "input8", "input9"};
    }
    std::string outputType(const std::string& inputType) const override { return inputType; }
};

} // namespace volsg
