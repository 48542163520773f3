#include <volsg/engines/AnimatedNodes.h>
#include <volsg/engines/Calculator.h>
#include <volsg/engines/EngineTypes.h>
#include <volsg/engines/Engines.h>
#include <volsg/engines/GlobalField.h>

namespace volsg {

namespace {
void addIfMissing(NodeRegistry& r, const NodeType& type) {
    if (!r.find(type.name())) r.add(type);
}
} // namespace

void addEngineTypes(NodeRegistry& r) {
    for (const NodeType* t : {&ElapsedTime::classType(),
                              &TimeCounter::classType(),
                              &Counter::classType(),
                              &OneShot::classType(),
                              &OnOff::classType(),
                              &TriggerAny::classType(),
                              &BoolOperation::classType(),
                              &Calculator::classType(),
                              &ComposeVec2f::classType(),
                              &ComposeVec3f::classType(),
                              &ComposeVec4f::classType(),
                              &DecomposeVec2f::classType(),
                              &DecomposeVec3f::classType(),
                              &DecomposeVec4f::classType(),
                              &ComposeRotation::classType(),
                              &ComposeRotationFromTo::classType(),
                              &DecomposeRotation::classType(),
                              &ComposeMatrix::classType(),
                              &DecomposeMatrix::classType(),
                              &TransformVec3f::classType(),
                              &InterpolateFloat::classType(),
                              &InterpolateVec2f::classType(),
                              &InterpolateVec3f::classType(),
                              &InterpolateVec4f::classType(),
                              &InterpolateRotation::classType(),
                              &SelectOne::classType(),
                              &Gate::classType(),
                              &Concatenate::classType(),
                              &GlobalField::classType()})
        addIfMissing(r, *t);
}

void addAnimatedNodeTypes(NodeRegistry& r) {
    for (const NodeType* t : {&Rotor::classType(), &Pendulum::classType(), &Shuttle::classType(),
                              &Blinker::classType()})
        addIfMissing(r, *t);
}

} // namespace volsg
