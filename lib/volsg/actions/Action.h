#pragma once
// Base of the verbs that traverse a scene graph: render, bounding box, pick, search, write.

#include <cstdint>
#include <vector>

#include <volsg/core/Node.h>
#include <volsg/state/State.h>

namespace volsg {

/// Traverses a graph depth first, keeping the path from the root and the State. Each action
/// calls its own hook on every node it reaches (Node::render for RenderAction, ...); groups
/// call traverse() on their children.
class Action {
public:
    virtual ~Action() = default;

    /// Runs the action on a graph: resets state and path, then traverses the root.
    void apply(Node& root);
    /// Visits one node (called by groups for their children). Throws Error when one traversal
    /// reaches more than limits::maxTraversalInstances nodes (a graph whose USEs multiply: each
    /// instance counts, not each node). An error thrown at a node read from a file is said of
    /// that node: "file:line:column: Type 'name': what went wrong".
    void traverse(Node& node);
    /// Nodes this traversal has reached so far (every instance of a shared node counts).
    std::uint64_t instances() const { return instances_; }

    State& state() { return state_; }
    const State& state() const { return state_; }
    /// Nodes from the root to the one being visited, inclusive.
    const std::vector<Node*>& path() const { return path_; }

    /// Stops the traversal early (a search that found what it wanted).
    void terminate() { terminated_ = true; }
    bool isTerminated() const { return terminated_; }

    /// Whether a Switch traverses all its children for this action regardless of whichChild
    /// (Inventor's SoSearchAction::setSearchingAll).
    virtual bool traversesAllChildren() const { return false; }

protected:
    virtual void beginTraversal(Node& root);
    /// Calls this action's hook on `node`.
    virtual void dispatch(Node& node) = 0;

private:
    State state_;
    std::vector<Node*> path_;
    bool terminated_ = false;
    std::uint64_t instances_ = 0;
};

} // namespace volsg
