#pragma once
// What an action does for each node type (Inventor's SoAction method lists): the verbs live
// with their action, above the node types, and nodes stay data.

#include <mutex>
#include <unordered_map>

#include <volsg/core/NodeType.h>

namespace volsg {

class Action;
class Node;

/// One table per action class. A node type without a method of its own takes its nearest
/// ancestor type's; with none at all, the action calls Node::doAction (groups traverse,
/// property nodes put themselves in scope). Add methods before traversals run (the built-in
/// ones are added when the table is made); lookups are thread-safe.
class ActionMethods {
public:
    /// `method` runs for nodes of type N (and types derived from it without their own).
    template <class A, class N> void add(void (*method)(A&, N&)) {
        addErased(N::classType(), reinterpret_cast<ErasedFunction>(method), &trampoline<A, N>);
    }
    /// Runs the method for `node`'s type, or node.doAction(action) if there is none.
    void apply(Action& action, Node& node) const;
    /// Whether nodes of `type` run `method` (added for their type or the nearest ancestor).
    template <class A, class N> bool runs(const NodeType& type, void (*method)(A&, N&)) const {
        return find(type).function == reinterpret_cast<ErasedFunction>(method);
    }
    /// Whether nodes of `type` run a method (false: Node::doAction).
    bool hasMethod(const NodeType& type) const { return find(type).function != nullptr; }
    /// Whether nodes of `type` run the method that nodes of `base` run (and there is one).
    bool runsMethodOf(const NodeType& type, const NodeType& base) const {
        const ErasedFunction f = find(type).function;
        return f != nullptr && f == find(base).function;
    }

private:
    using ErasedFunction = void (*)();
    using Trampoline = void (*)(ErasedFunction, Action&, Node&);
    struct Method {
        ErasedFunction function = nullptr;
        Trampoline call = nullptr;
    };
    template <class A, class N> static void trampoline(ErasedFunction f, Action& a, Node& n) {
        reinterpret_cast<void (*)(A&, N&)>(f)(static_cast<A&>(a), static_cast<N&>(n));
    }
    void addErased(const NodeType& type, ErasedFunction function, Trampoline call);
    Method find(const NodeType& type) const;

    mutable std::mutex mutex_;
    std::unordered_map<const NodeType*, Method> added_;
    mutable std::unordered_map<const NodeType*, Method> resolved_; ///< by nearest ancestor
};

} // namespace volsg
