#pragma once
// Node kits (Inventor's SoBaseKit and its standard subclasses, docs/SCENE-FORMAT.md section
// 2.6): nodes whose parts are SFNode fields, declared in the order of Coin's catalogs. A kit
// is drawn by traversing its parts in the order of its catalog's tree, with the semantics of
// the containers that the catalog puts them in (a Separator for topSeparator, a
// TransformSeparator for transformGroup); the containers themselves are private parts that
// files rarely name. Parts are read, kept and written back like any field: a part set by a
// file or by code is written, a part never set is not. Inventor's default parts (ShapeKit's
// Cube, LightKit's DirectionalLight, CameraKit's PerspectiveCamera) are traversed while the
// part is not set: the kit makes that node when first needed and keeps it apart from the field
// (a node made in a constructor would record its fields into the kit's field table,
// NodeType::fields()), so the field stays NULL and unset and is not written, as in Inventor.
// Part types are not checked.
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

/// The root of the kits: one part, the callbackList (a NodeKitListPart). Its doAction
/// traverses the parts, so every action (render, bounding box, pick, search) goes through
/// them.
class BaseKit : public Inherit<Node, BaseKit> {
public:
    static constexpr const char* typeName = "BaseKit";
    static constexpr bool inventorBuiltin() { return true; }

    SFNode callbackList{this, "callbackList"};

    void doAction(Action& action) override;

protected:
    ~BaseKit() override = default;
    /// Traverses the node a part holds, if any.
    static void traversePart(Action& action, const SFNode& part);
    /// The node a part with a default node stands for: the field's node once the part is set
    /// (NULL too), else `fallback`, made by `make` the first time.
    static Node* partOrDefault(const SFNode& part, ref_ptr<Node>& fallback,
                               ref_ptr<Node> (*make)());
};

} // namespace volsg
