#pragma once
// How messages name a node: its type, and its name when it has one.
#include <string>

namespace volsg {

class Node;

/// "Text3" or "Text3 'title'".
std::string describeNode(const Node& node);

} // namespace volsg
