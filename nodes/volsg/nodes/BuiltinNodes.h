#pragma once
// The node types of the library, by name, for the reader.

#include <volsg/core/NodeType.h>

namespace volsg {

/// NodeRegistry::instance() with every node type of the library in it (added on the first
/// call). Applications add their own types to the same registry.
NodeRegistry& nodeTypes();

} // namespace volsg
