#pragma once
// SeparatorKit: a kit whose parts are under a separator (topSeparator): pickStyle, appearance,
// units, transform, texture2Transform, then childList, whose container holds child kits
// (Inventor's SoSeparatorKit). The caching fields are Separator's, kept and written back.
#include <volsg/nodes/BaseKit.h>
#include <volsg/nodes/Separator.h>

namespace volsg {

class SeparatorKit : public Inherit<BaseKit, SeparatorKit> {
public:
    static constexpr const char* typeName = "SeparatorKit";
    static constexpr bool inventorBuiltin() { return true; }

    // Inventor's caching hints, with Separator's names and values: kept and written back.
    SFEnum renderCaching{this, "renderCaching", Separator::cachingNames, Separator::AUTO};
    SFEnum boundingBoxCaching{this, "boundingBoxCaching", Separator::cachingNames, Separator::AUTO};
    SFEnum renderCulling{this, "renderCulling", Separator::cachingNames, Separator::AUTO};
    SFEnum pickCulling{this, "pickCulling", Separator::cachingNames, Separator::AUTO};

    SFNode topSeparator{this, "topSeparator"}; ///< private container (2.6): kept, not traversed
    SFNode pickStyle{this, "pickStyle"};
    SFNode appearance{this, "appearance"};
    SFNode units{this, "units"};
    SFNode transform{this, "transform"};
    SFNode texture2Transform{this, "texture2Transform"};
    SFNode childList{this, "childList"};

    void doAction(Action& action) override;

protected:
    ~SeparatorKit() override = default;
    /// pickStyle, appearance, units, transform and texture2Transform (the parts every
    /// separator kit starts its topSeparator with).
    void traverseLeadingParts(Action& action) const;
};

} // namespace volsg
