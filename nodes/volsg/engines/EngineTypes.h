#pragma once
// Registration of the engine types and of the nodes that animate themselves.

#include <volsg/core/NodeType.h>

namespace volsg {

/// Adds the engine types (ElapsedTime, TimeCounter, Calculator, the Compose, Decompose and
/// Interpolate engines, Gate, OneShot, Counter, BoolOperation, SelectOne, Concatenate, OnOff,
/// TriggerAny, TransformVec3f) and GlobalField, where the registry has no type of that name.
/// The reader calls it; an engine is only read as the source of a field connection.
void addEngineTypes(NodeRegistry& registry);

/// Adds the nodes that animate themselves (Rotor, Pendulum, Shuttle, Blinker), where the
/// registry has no type of that name. The reader calls it; BuiltinNodes.cpp may call it too
/// (`addAnimatedNodeTypes(r);`) so that nodeTypes() lists them.
void addAnimatedNodeTypes(NodeRegistry& registry);

} // namespace volsg
