#pragma once
// Base of all scene-graph nodes: identity, name, typed fields, version, action hooks.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include <volsg/core/NodeType.h>
#include <volsg/core/Object.h>

namespace volsg {

class Action;
class Field;
struct ReadContext;

/// Where a node was read from: the scene file and the line and column of its type name.
struct SourcePlace {
    std::shared_ptr<const std::string> file; ///< null: made in code
    int line = 0, column = 0;
};

/// A scene-graph node. Nodes hold fields and do their state work (doAction); what a node
/// type does in each action (draw, bound, pick) is that action's method for the type
/// (ActionMethods), and the heavy work lives in lib/ engines. Construct with `T::create()`,
/// hold with `ref_ptr`.
///
/// Every field change bumps `version()`, drawn from one global counter, so caches built from
/// a node (tables, textures, meshes) compare versions and rebuild lazily.
class Node : public Object {
public:
    static const NodeType& classType();
    virtual const NodeType& type() const { return classType(); }
    bool isOfType(const NodeType& t) const { return type().isDerivedFrom(t); }
    template <class T> bool isA() const { return isOfType(T::classType()); }

    const std::string& getName() const { return name_; }
    void setName(std::string name) { name_ = std::move(name); }

    /// Where the reader found the node (empty for nodes made in code): errors while an action
    /// is at the node name this place (Action::traverse).
    const SourcePlace& sourcePlace() const { return place_; }
    void setSourcePlace(SourcePlace place) { place_ = std::move(place); }
    /// The node as messages name it: its type, and its name when it has one ("Volume 'CT'").
    std::string description() const;

    std::uint64_t version() const { return version_; }
    void touch(); ///< marks the node changed (called by its fields)

    // Fields, in declaration order. Opaque (self-described unknown) nodes override these.
    virtual std::size_t fieldCount() const;
    virtual Field* fieldAt(std::size_t i);
    const Field* fieldAt(std::size_t i) const { return const_cast<Node*>(this)->fieldAt(i); }
    Field* field(std::string_view name);
    const Field* field(std::string_view name) const { return const_cast<Node*>(this)->field(name); }

    // Children, for groups; empty for other nodes.
    virtual std::vector<ref_ptr<Node>>* children() { return nullptr; }
    const std::vector<ref_ptr<Node>>* children() const {
        return const_cast<Node*>(this)->children();
    }

    /// Called by the scene reader once the node's fields and children are read. Nodes that
    /// name files (VolumeData, GltfModel) keep `context.directory` (or resolve their names
    /// with `context.resolve()`, io/ReadContext.h) so relative names resolve against the
    /// scene file's folder.
    virtual void readDone(const ReadContext& /*context*/) {}

    /// What the node does in every action that has no method of its own for its type:
    /// state-changing nodes (Transform, Material, ...) and groups act here once for all.
    virtual void doAction(Action& action);

protected:
    Node();
    ~Node() override; // nodes live in ref_ptr only

private:
    std::string name_;
    std::uint64_t version_;
    SourcePlace place_;
};

/// Writes the per-type boilerplate once (as VulkanSceneGraph's Inherit):
/// `class Cube : public Inherit<Shape, Cube> { static constexpr const char* typeName = "Cube"; ...
/// }`.
template <class Parent, class Self> class Inherit : public Parent {
public:
    template <class... Args> static ref_ptr<Self> create(Args&&... args) {
        return ref_ptr<Self>(new Self(std::forward<Args>(args)...));
    }
    static const NodeType& classType() {
        static const NodeType type(Self::typeName, &Parent::classType(), factory(),
                                   Self::inventorBuiltin());
        return type;
    }
    const NodeType& type() const override { return classType(); }

    /// Whether a standard Inventor reader knows this type (written without `fields [...]`).
    /// Our own node types say false by not declaring it.
    static constexpr bool inventorBuiltin() { return false; }

    using Parent::Parent;

private:
    static NodeType::Factory factory() {
        if constexpr (std::is_abstract_v<Self>)
            return nullptr;
        else
            return []() -> ref_ptr<Node> { return ref_ptr<Node>(new Self()); };
    }
};

} // namespace volsg
