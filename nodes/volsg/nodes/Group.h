#pragma once
// Group: children traversed in order, state not restored (Inventor SoGroup).

#include <volsg/core/Node.h>

namespace volsg {

class Group : public Inherit<Node, Group> {
public:
    static constexpr const char* typeName = "Group";
    static constexpr bool inventorBuiltin() { return true; }

    void addChild(ref_ptr<Node> child);
    void insertChild(ref_ptr<Node> child, std::size_t index);
    void removeChild(std::size_t index);
    void removeAllChildren();
    std::size_t getNumChildren() const { return children_.size(); }
    Node* getChild(std::size_t i) const { return children_[i].get(); }

    std::vector<ref_ptr<Node>>* children() override { return &children_; }
    void doAction(Action& action) override;

protected:
    ~Group() override = default;

private:
    std::vector<ref_ptr<Node>> children_;
};

} // namespace volsg
