#include <volsg/actions/Action.h>
#include <volsg/core/Node.h>
#include <volsg/fields/Field.h>

#include <atomic>
#include <cstring>

namespace volsg {

namespace {
std::atomic<std::uint64_t> versionCounter{1};
std::uint64_t nextVersion() {
    return versionCounter.fetch_add(1, std::memory_order_relaxed);
}
} // namespace

const NodeType& Node::classType() {
    static const NodeType type("Node", nullptr, nullptr, true);
    return type;
}

Node::Node() : version_(nextVersion()) {}
Node::~Node() = default;

std::string Node::description() const {
    std::string out = type().name();
    if (!name_.empty()) out += " '" + name_ + "'";
    return out;
}

void Node::touch() {
    version_ = nextVersion();
}

std::size_t Node::fieldCount() const {
    return type().fields().size();
}

Field* Node::fieldAt(std::size_t i) {
    const auto& entries = type().fields();
    if (i >= entries.size()) return nullptr;
    return reinterpret_cast<Field*>(reinterpret_cast<char*>(this) + entries[i].offset);
}

Field* Node::field(std::string_view name) {
    for (std::size_t i = 0, n = fieldCount(); i < n; ++i) {
        Field* f = fieldAt(i);
        if (f && name == f->name()) return f;
    }
    return nullptr;
}

void Node::doAction(Action&) {}

Field::Field(Node* owner, const char* name) : owner_(owner), name_(name) {
    NodeType::recordField(owner, this, name);
}

void Field::changed() {
    isDefault_ = false;
    if (owner_) owner_->touch();
}

} // namespace volsg
