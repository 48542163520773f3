#pragma once
// Info: a comment kept in the scene graph (Inventor's SoInfo). It does nothing in any action;
// the reader keeps it and the writer writes it back.
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class Info : public Inherit<Node, Info> {
public:
    static constexpr const char* typeName = "Info";
    static constexpr bool inventorBuiltin() { return true; }
    SFString string{this, "string", "<Undefined info>"};

protected:
    ~Info() override = default;
};

} // namespace volsg
