#include <volsg/nodes/NodeNames.h>

#include <volsg/core/Node.h>

namespace volsg {

std::string describeNode(const Node& node) {
    std::string out = node.type().name();
    if (!node.getName().empty()) out += " '" + node.getName() + "'";
    return out;
}

} // namespace volsg
