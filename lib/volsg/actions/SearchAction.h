#pragma once
// Finds nodes by type and/or name, returning their paths from the root.

#include <string>
#include <vector>

#include <volsg/actions/Action.h>

namespace volsg {

/// Inventor's SoSearchAction. A node matches when it passes every criterion that is set (no
/// criterion set: every node matches). Traversal follows what a render would visit: a Switch
/// shows only its selected child unless setSearchingAll(true).
class SearchAction : public Action {
public:
    enum class Interest {
        First, ///< the first match in traversal order; the search stops there
        Last,  ///< the last match in traversal order
        All    ///< every match, in traversal order (a node USEd twice gives two paths)
    };

    void setType(const NodeType* type, bool derivedToo = true); ///< null: any type
    void setName(std::string name);                             ///< empty: any name
    void setInterest(Interest interest) { interest_ = interest; }
    /// Also look under Switch children that are not selected (Inventor's searchingAll).
    void setSearchingAll(bool all) { searchingAll_ = all; }

    /// The paths found (one for First/Last), each from the root to the node inclusive.
    const std::vector<std::vector<Node*>>& paths() const { return paths_; }
    bool traversesAllChildren() const override { return searchingAll_; }

protected:
    void beginTraversal(Node& root) override;
    void dispatch(Node& node) override;

private:
    bool matches(const Node& node) const;

    const NodeType* type_ = nullptr;
    bool derivedToo_ = true;
    std::string name_;
    Interest interest_ = Interest::First;
    bool searchingAll_ = false;
    std::vector<std::vector<Node*>> paths_;
};

/// Every node of `type` or a type derived from it, in traversal order, each node once even if
/// it is USEd several times. `searchingAll` also looks under unselected Switch children.
std::vector<Node*> findAll(Node& root, const NodeType& type, bool searchingAll = false);

/// The first node named `name` in traversal order (Switch children that are not selected
/// included, as a name lookup is about the graph, not what is shown), or null.
Node* findByName(Node& root, const std::string& name);

} // namespace volsg
