#include <volsg/editors/EditHistory.h>

#include <cstring>

#include <volsg/editors/FieldText.h>
#include <volsg/fields/Field.h>

namespace volsg {

void EditHistory::begin(std::string label, const std::vector<Field*>& fields) {
    if (open_) commit();
    pending_ = Edit{std::move(label), {}};
    open_ = true;
    include(fields);
}

void EditHistory::include(const std::vector<Field*>& fields) {
    if (!open_) {
        begin("edit", fields);
        return;
    }
    for (Field* f : fields) {
        if (!f || !f->owner() || !isTextField(*f)) continue;
        bool known = false;
        for (const FieldState& s : pending_.fields)
            if (s.node.get() == f->owner() && s.field == f->name()) known = true;
        if (known) continue;
        FieldState s;
        s.node = ref_ptr<Node>(f->owner());
        s.field = f->name();
        s.before = fieldValueText(*f);
        s.beforeDefault = f->isDefault();
        pending_.fields.push_back(std::move(s));
    }
}

void EditHistory::commit() {
    if (!open_) return;
    open_ = false;
    bool changed = false;
    for (FieldState& s : pending_.fields) {
        const Field* f = s.node->field(s.field);
        s.after = fieldValueText(*f);
        s.afterDefault = f->isDefault();
        changed = changed || s.after != s.before || s.afterDefault != s.beforeDefault;
    }
    if (!changed) return;
    edits_.resize(done_);
    edits_.push_back(std::move(pending_));
    done_ = edits_.size();
    ++changes_;
    pending_ = Edit{};
}

void EditHistory::cancel() {
    if (!open_) return;
    open_ = false;
    for (const FieldState& s : pending_.fields)
        restore(s, false);
    pending_ = Edit{};
}

void EditHistory::restore(const FieldState& s, bool after) {
    Field* f = s.node->field(s.field);
    if (!f) return;
    const std::string& text = after ? s.after : s.before;
    if (fieldValueText(*f) != text) setFieldFromText(*f, text);
    f->setDefault(after ? s.afterDefault : s.beforeDefault);
}

bool EditHistory::undo() {
    if (open_) commit();
    if (done_ == 0) return false;
    --done_;
    ++changes_;
    const Edit& e = edits_[done_];
    for (auto it = e.fields.rbegin(); it != e.fields.rend(); ++it)
        restore(*it, false);
    return true;
}

bool EditHistory::redo() {
    if (open_) commit();
    if (done_ >= edits_.size()) return false;
    for (const FieldState& s : edits_[done_].fields)
        restore(s, true);
    ++done_;
    ++changes_;
    return true;
}

std::string EditHistory::undoLabel() const {
    return done_ > 0 ? edits_[done_ - 1].label : std::string();
}

void EditHistory::clear() {
    edits_.clear();
    done_ = 0;
    pending_ = Edit{};
    open_ = false;
}

} // namespace volsg
