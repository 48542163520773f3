#include <volsg/core/Node.h>
#include <volsg/core/NodeType.h>
#include <volsg/fields/Field.h>

#include <algorithm>

namespace volsg {

namespace {
// The field table being recorded on this thread, while a prototype is constructed.
thread_local std::vector<NodeType::FieldEntry>* recording = nullptr;
} // namespace

NodeType::NodeType(const char* name, const NodeType* parent, Factory factory, bool inventorBuiltin)
    : name_(name), parent_(parent), factory_(factory), inventorBuiltin_(inventorBuiltin) {}

bool NodeType::isDerivedFrom(const NodeType& other) const {
    for (const NodeType* t = this; t; t = t->parent_)
        if (t == &other) return true;
    return false;
}

ref_ptr<Node> NodeType::create() const {
    return factory_ ? factory_() : nullptr;
}

const std::vector<NodeType::FieldEntry>& NodeType::fields() const {
    std::call_once(fieldsOnce_, [this] {
        if (!factory_) return;
        std::vector<FieldEntry>* saved = recording;
        recording = &fields_;
        ref_ptr<Node> prototype = factory_();
        recording = saved;
    });
    return fields_;
}

void NodeType::recordField(const Node* owner, const Field* field, const char* name) {
    if (!recording) return;
    auto offset = reinterpret_cast<const char*>(field) - reinterpret_cast<const char*>(owner);
    recording->push_back({name, offset});
}

NodeRegistry& NodeRegistry::instance() {
    static NodeRegistry registry;
    return registry;
}

NodeRegistry::NodeRegistry() = default;

void NodeRegistry::add(const NodeType& type) {
    std::lock_guard lock(mutex_);
    auto same = [&](const NodeType* t) { return std::string_view(t->name()) == type.name(); };
    auto it = std::find_if(types_.begin(), types_.end(), same);
    if (it != types_.end())
        *it = &type;
    else
        types_.push_back(&type);
}

const NodeType* NodeRegistry::find(std::string_view name) const {
    std::lock_guard lock(mutex_);
    for (const NodeType* t : types_)
        if (name == t->name()) return t;
    return nullptr;
}

std::vector<const NodeType*> NodeRegistry::all() const {
    std::lock_guard lock(mutex_);
    return types_;
}

} // namespace volsg
