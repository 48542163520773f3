#pragma once
// Structural equality of node graphs, for tests and round trips.

#include <string>

#include <volsg/core/Node.h>

namespace volsg {

/// Whether two graphs are the same scene: the same node types (for UnknownNodes, the same
/// type name in the file), names, fields (Field::equals unless both are default, default
/// state, ignore flag,
/// connection: its source compared as a graph and its field name, and the graphs under
/// SFNode/MFNode values), children, and the same sharing (a node reached twice in `a` matches
/// one node reached at the same places in `b`). On a difference, `why` says where and what.
/// With `relativeTolerance` > 0, numbers in fields may differ by that much of their magnitude
/// (fields/Fields.h valuesClose): for graphs read from text another program wrote.
bool graphsEqual(const Node& a, const Node& b, std::string* why = nullptr,
                 double relativeTolerance = 0.0);

} // namespace volsg
