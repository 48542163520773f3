#include <volsg/manipulators/Manipulator.h>

#include <cmath>
#include <mutex>
#include <unordered_set>

#include <volsg/actions/Action.h>
#include <volsg/actions/PickAction.h>
#include <volsg/fields/Field.h>
#include <volsg/manipulators/BoxClipManip.h>
#include <volsg/manipulators/ClipPlaneManip.h>
#include <volsg/manipulators/TransformManip.h>
#include <volsg/render/RenderAction.h>
#include <volsg/state/State.h>

namespace volsg {

void copyFieldValues(const Node& from, Node& to) {
    for (std::size_t i = 0; i < from.fieldCount(); ++i) {
        const Field* source = from.fieldAt(i);
        Field* target = to.field(source->name());
        if (!target) continue;
        if (!target->equals(*source)) target->copyFrom(*source);
        target->setDefault(source->isDefault());
    }
}

namespace {
int replaceUnder(Node& group, const Node& from, const ref_ptr<Node>& to,
                 std::unordered_set<const Node*>& visited) {
    if (!visited.insert(&group).second) return 0;
    std::vector<ref_ptr<Node>>* children = group.children();
    if (!children) return 0;
    int count = 0;
    bool changed = false;
    for (ref_ptr<Node>& child : *children) {
        if (child.get() == &from) {
            child = to;
            ++count;
            changed = true;
        } else if (child) {
            count += replaceUnder(*child, from, to, visited);
        }
    }
    if (changed) group.touch();
    return count;
}
} // namespace

int replaceNodeInGraph(Node& root, const Node& from, const ref_ptr<Node>& to) {
    std::unordered_set<const Node*> visited;
    return replaceUnder(root, from, to, visited);
}

bool Manipulator::attach(Node& root, Node& original) {
    if (isAttached()) detach();
    copyFieldValues(original, node());
    const ref_ptr<Node> keepOriginal(&original); // the graph may hold the last reference
    if (replaceNodeInGraph(root, original, ref_ptr<Node>(&node())) == 0) return false;
    original_ = keepOriginal;
    root_ = &root;
    return true;
}

void Manipulator::detach() {
    if (!isAttached()) return;
    endDrag();
    writeBack();
    const ref_ptr<Node> keepSelf(&node()); // the graph may hold the last reference to us
    replaceNodeInGraph(*root_, node(), original_);
    original_ = nullptr;
    root_ = nullptr;
}

void Manipulator::writeBack() {
    if (original_) copyFieldValues(node(), *original_);
}

bool Manipulator::beginDrag(const Ray& worldRay, const std::vector<Node*>& pickPath) {
    if (!handles_) return false; // never drawn, so never picked
    const int part = handles_->partOnPath(pickPath);
    if (part < 0) return false;
    activePart_ = part;
    handles().highlight(part);
    startDrag(part, toLocal(worldRay));
    return true;
}

void Manipulator::drag(const Ray& worldRay) {
    if (activePart_ < 0) return;
    continueDrag(activePart_, toLocal(worldRay));
    writeBack();
}

void Manipulator::endDrag() {
    activePart_ = -1;
    if (handles_) handles_->highlight(-1);
}

DraggerGeometry& Manipulator::handles() {
    if (!handles_) {
        handles_ = std::make_unique<DraggerGeometry>();
        buildHandles(*handles_);
    }
    return *handles_;
}

namespace {

template <class A, class M> void handlesThenState(A& action, M& manipulator) {
    manipulator.handlesThenState(action);
}

template <class M> void addMethods() {
    RenderAction::methods().add(&handlesThenState<RenderAction, M>);
    PickAction::methods().add(&handlesThenState<PickAction, M>);
}

} // namespace

Manipulator::Manipulator() {
    static std::once_flag once;
    std::call_once(once, [] {
        addMethods<BoxClipManip>();
        addMethods<ClipPlaneManip>();
        addMethods<TransformManip>();
    });
}

void Manipulator::handlesThenState(Action& action) {
    drawHandles(action);
    node().doAction(action);
}

void Manipulator::drawHandles(Action& action) {
    model_ = action.state().modelMatrix();
    placeHandles();
    // The handles ignore the ClipPlanes and BoxClip in scope (the render skips clipped shapes,
    // the pick drops clipped hits): a handle must stay visible and grabbable wherever it is.
    const State scope = action.state();
    action.state().reset(model_);
    action.traverse(handles().root());
    action.state() = scope;
}

double Manipulator::localHandleSize() const {
    // World size over the model's mean scale (cube root of the volume change).
    const double det = std::abs(glm::determinant(glm::dmat3(model_)));
    const double scale = det > 0.0 ? std::cbrt(det) : 1.0;
    return handleSize_ / scale;
}

glm::dvec3 Manipulator::localAnchor() const {
    return glm::dvec3(glm::inverse(model_) * glm::dvec4(anchor_, 1.0));
}

Ray Manipulator::toLocal(const Ray& worldRay) const {
    return worldRay.transformed(glm::inverse(model_));
}

} // namespace volsg
