#pragma once
// Finds nodes by type and/or name, returning their paths from the root.

#include <string>
#include <vector>

#include <volsg/actions/Action.h>

namespace volsg {

class SearchAction : public Action {
public:
    enum class Interest { First, Last, All };

    void setType(const NodeType* type, bool derivedToo = true); ///< null: any type
    void setName(std::string name);                            ///< empty: any name
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
    const NodeType* type_ = nullptr;
    bool derivedToo_ = true;
    std::string name_;
    Interest interest_ = Interest::First;
    bool searchingAll_ = false;
    std::vector<std::vector<Node*>> paths_;
};

} // namespace volsg
