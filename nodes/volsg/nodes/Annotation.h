#pragma once
// Annotation: a Separator whose children are drawn after the rest of the scene, with no depth
// test, so they are always visible (Inventor's SoAnnotation). Bounding boxes, picking and
// searches see it as a Separator; the render method is in
// nodes/volsg/render/InventorRendering.cpp.
#include <volsg/nodes/Separator.h>

namespace volsg {

class Annotation : public Inherit<Separator, Annotation> {
public:
    static constexpr const char* typeName = "Annotation";
    static constexpr bool inventorBuiltin() { return true; }

protected:
    ~Annotation() override = default;
};

} // namespace volsg
