#include <volsg/core/Node.h>
#include <volsg/state/State.h>

namespace volsg {

State::State() {
    reset();
}

void State::reset(const glm::dmat4& model) {
    models_.assign(1, model);
    entries_.clear();
    marks_.clear();
    hasView_ = false;
}

void State::push() {
    marks_.push_back({models_.size(), entries_.size()});
}

void State::pop() {
    if (marks_.empty()) return;
    models_.resize(marks_.back().models);
    entries_.resize(marks_.back().entries);
    marks_.pop_back();
}

void State::setModelMatrix(const glm::dmat4& m) {
    // Within one scope the top is replaced; a push() protects the outer value.
    if (!marks_.empty() && models_.size() > marks_.back().models)
        models_.back() = m;
    else if (marks_.empty() && models_.size() > 1)
        models_.back() = m;
    else
        models_.push_back(m);
}

void State::multModelMatrix(const glm::dmat4& m) {
    setModelMatrix(models_.back() * m);
}

void State::add(const Node& property) {
    entries_.push_back({&property, models_.back()});
}

} // namespace volsg
