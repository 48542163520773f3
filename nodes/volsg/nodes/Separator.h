#pragma once
// Separator: a Group that saves the traversal state before its children and restores it after.

#include <volsg/fields/Fields.h>
#include <volsg/nodes/Group.h>

namespace volsg {

class Separator : public Inherit<Group, Separator> {
public:
    static constexpr const char* typeName = "Separator";
    static constexpr bool inventorBuiltin() { return true; }
    enum Caching { OFF, ON, AUTO };
    static const EnumValues cachingNames;

    // Inventor's caching hints: read and written for compatibility; volsg caches per node.
    SFEnum renderCaching{this, "renderCaching", cachingNames, AUTO};
    SFEnum boundingBoxCaching{this, "boundingBoxCaching", cachingNames, AUTO};
    SFEnum renderCulling{this, "renderCulling", cachingNames, AUTO};
    SFEnum pickCulling{this, "pickCulling", cachingNames, AUTO};

    void doAction(Action& action) override;

protected:
    ~Separator() override = default;
};

} // namespace volsg
