#pragma once
// Label: a name for the part of the graph after it (Inventor's SoLabel). It does nothing in
// any action; the reader keeps it and the writer writes it back. Inventor's field is an
// SFName; here it is an SFString (written quoted, which Inventor readers take for a name).
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class Label : public Inherit<Node, Label> {
public:
    static constexpr const char* typeName = "Label";
    static constexpr bool inventorBuiltin() { return true; }
    SFString label{this, "label", "<Undefined label>"};

protected:
    ~Label() override = default;
};

} // namespace volsg
