#pragma once
// NodeKitListPart: the list parts of node kits (childList, callbackList, ...): a container node
// of a group type whose children are the list's items (Inventor's SoNodeKitListPart). It
// traverses its containerNode; the type names are kept for the kit's rules and written back.
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class NodeKitListPart : public Inherit<Node, NodeKitListPart> {
public:
    static constexpr const char* typeName = "NodeKitListPart";
    static constexpr bool inventorBuiltin() { return true; }

    // Inventor's SFName and MFName fields, as strings (written quoted).
    SFString containerTypeName{this, "containerTypeName", "Group"};
    MFString childTypeNames{this, "childTypeNames", {"Node"}};
    /// The group that holds the items. NULL until a file or code sets one, which is Inventor's
    /// empty default Group for every action.
    SFNode containerNode{this, "containerNode"};

    void doAction(Action& action) override;

protected:
    ~NodeKitListPart() override = default;
};

} // namespace volsg
