#include <volsg/actions/SearchAction.h>

#include <unordered_set>

namespace volsg {

void SearchAction::setType(const NodeType* type, bool derivedToo) {
    type_ = type;
    derivedToo_ = derivedToo;
}

void SearchAction::setName(std::string name) {
    name_ = std::move(name);
}

void SearchAction::beginTraversal(Node& root) {
    paths_.clear();
    Action::beginTraversal(root);
}

bool SearchAction::matches(const Node& node) const {
    if (type_ && !(derivedToo_ ? node.isOfType(*type_) : &node.type() == type_)) return false;
    if (!name_.empty() && node.getName() != name_) return false;
    return true;
}

void SearchAction::dispatch(Node& node) {
    if (matches(node)) {
        switch (interest_) {
        case Interest::First:
            paths_.assign(1, path());
            terminate();
            return;
        case Interest::Last:
            paths_.assign(1, path());
            break;
        case Interest::All:
            paths_.push_back(path());
            break;
        }
    }
    // Groups traverse their children; property nodes only touch the (unused) state.
    node.doAction(*this);
}

std::vector<Node*> findAll(Node& root, const NodeType& type, bool searchingAll) {
    SearchAction search;
    search.setType(&type, true);
    search.setInterest(SearchAction::Interest::All);
    search.setSearchingAll(searchingAll);
    search.apply(root);
    std::vector<Node*> nodes;
    std::unordered_set<const Node*> seen;
    for (const auto& path : search.paths())
        if (seen.insert(path.back()).second) nodes.push_back(path.back());
    return nodes;
}

Node* findByName(Node& root, const std::string& name) {
    if (name.empty()) return nullptr;
    SearchAction search;
    search.setName(name);
    search.setInterest(SearchAction::Interest::First);
    search.setSearchingAll(true);
    search.apply(root);
    return search.paths().empty() ? nullptr : search.paths().front().back();
}

} // namespace volsg
