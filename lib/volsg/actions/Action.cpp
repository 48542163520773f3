#include <volsg/actions/Action.h>

#include <exception>
#include <string>

#include <volsg/core/Error.h>
#include <volsg/core/Limits.h>

namespace volsg {

void Action::apply(Node& root) {
    state_.reset();
    path_.clear();
    terminated_ = false;
    instances_ = 0;
    beginTraversal(root);
}

void Action::beginTraversal(Node& root) {
    traverse(root);
}

namespace {

/// The path's last node is popped however the visit ends.
struct PathEntry {
    std::vector<Node*>& path;
    PathEntry(std::vector<Node*>& p, Node& node) : path(p) { path.push_back(&node); }
    ~PathEntry() { path.pop_back(); }
    PathEntry(const PathEntry&) = delete;
    PathEntry& operator=(const PathEntry&) = delete;
};

[[noreturn]] void failAtNode(const Node& node, const std::exception& e) {
    const SourcePlace& place = node.sourcePlace();
    throw Error::atSceneNode(e, node.description(), *place.file, place.line, place.column);
}

} // namespace

void Action::traverse(Node& node) {
    if (terminated_) return;
    const PathEntry entry(path_, node);
    try {
        if (++instances_ > limits::maxTraversalInstances)
            throw Error("the scene reaches more than " +
                        std::to_string(limits::maxTraversalInstances) +
                        " node instances in one traversal (USEs that share groups multiply)");
        dispatch(node);
    } catch (const Error& e) {
        // Already at a place in the scene (this node's file, or a node below it): as it is.
        const SourcePlace& place = node.sourcePlace();
        if (e.namesSceneNode() || !place.file || (e.line() > 0 && e.file() == *place.file)) throw;
        failAtNode(node, e);
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception& e) {
        if (!node.sourcePlace().file) throw;
        failAtNode(node, e);
    }
}

} // namespace volsg
