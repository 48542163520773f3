#pragma once
// Inventor's draggers (SoDragger's 21 subclasses in Coin 4: Translate1Dragger, TrackballDragger,
// TransformBoxDragger, ...; docs/SCENE-FORMAT.md section 2.9), drawn at rest as Coin draws
// them. One class serves every dragger type: a type is a NodeType of its own (its name, parent
// Dragger, a factory) and a catalog (DraggerCatalog.cpp) that lists the dragger's parts in
// the order of Coin's catalog tree, which container holds each, the child a Switch shows at
// rest, and the default of each part: a node named in Coin's resource file for the type
// (draggerDefaults/, parsed with our reader at first use), a child dragger, or a node given in
// the catalog. The fields are those of the reader's table of Inventor types
// (io/InventorTypes.cpp), so a dragger keeps, reads and writes every field as before: it is an
// UnknownNode of a known type (fields made per instance, written under the type's name with no
// description); UnknownNode answers fieldCount/fieldAt, so the NodeType's own field table is
// never used.
//
// At rest a dragger draws its inactive parts placed by its motion matrix, which its value
// fields (translation, rotation, scaleFactor, scaleOrientation, center) make as Coin's
// SoDragger::workFieldsIntoTransform does from the motionMatrix part (identity unless a file
// sets it). A part set by the file (or code) replaces the default; a part set to NULL draws
// nothing. Draggers are not interactive in volsg.
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/io/UnknownNode.h>

namespace volsg {

struct DraggerCatalog;

class Dragger : public Inherit<UnknownNode, Dragger> {
public:
    static constexpr const char* typeName = "Dragger";
    static constexpr bool inventorBuiltin() { return true; }

    /// The node types of the 21 standard draggers, for the registry.
    static std::vector<const NodeType*> draggerTypes();
    /// A dragger of the type of that name with its fields (null for a name that is not a
    /// dragger type).
    static ref_ptr<Dragger> createOfType(std::string_view draggerTypeName);

    Dragger() = default;
    Dragger(const DraggerCatalog* catalog, const NodeType& type);

    const NodeType& type() const override;
    /// Parts are fields; a dragger has no children in a file.
    std::vector<ref_ptr<Node>>* children() override { return nullptr; }
    using Node::children;
    void doAction(Action& action) override;
    /// Notes the version the file left, for a type whose Coin dragger ignores the value
    /// fields read (DraggerCatalog::readValuesIgnored).
    void readDone(const ReadContext& context) override;

    /// The motion matrix at rest: the motionMatrix part's matrix (identity when unset) with
    /// the value fields worked in (SoDragger::workFieldsIntoTransform).
    glm::dmat4 motionMatrix() const;
    /// The graph drawn at rest (rebuilt when a field of the dragger changes): its parts in
    /// their containers, the motion matrix, the defaults of unset parts. Null for a type
    /// without a catalog.
    Node* restGraph();
    /// A default for a part, or for a part of a child dragger ("translator.translator"), as
    /// a composite dragger gives its children (Coin's setPartAsDefault): not a field value,
    /// so not written.
    void setPartDefault(const std::string& path, ref_ptr<Node> node);

protected:
    ~Dragger() override;

private:
    ref_ptr<Node> buildPart(std::size_t index);
    /// A TabPlaneDragger's scale tabs: 10 pixels on screen when the action has a projected
    /// view (Coin's reallyAdjustScaleTabSize at each render), 0.08 until then.
    void adjustScaleTabs(const Action& action);
    void setScaleTabSize(glm::vec2 size);
    const DraggerCatalog* catalog_ = nullptr;
    const NodeType* type_ = nullptr;
    std::unordered_map<std::string, ref_ptr<Node>> partDefaults_;
    ref_ptr<Node> rest_;
    std::uint64_t restVersion_ = 0;
    std::uint64_t readVersion_ = 0; ///< nonzero: the version when read, values ignored then
    ref_ptr<Node> edgeScaleCoords_, cornerScaleCoords_; ///< Coordinate3 of the rest graph
    glm::vec2 scaleTabSize_{0.08f};
};

} // namespace volsg
