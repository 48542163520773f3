// The node kits: each traverses its parts in the order of its Coin catalog's tree, with the
// semantics of the private containers the catalog puts them in (BaseKit.h).
#include <volsg/actions/Action.h>
#include <volsg/nodes/AppearanceKit.h>
#include <volsg/nodes/BaseKit.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/CameraKit.h>
#include <volsg/nodes/Cube.h>
#include <volsg/nodes/Light.h>
#include <volsg/nodes/LightKit.h>
#include <volsg/nodes/NodeKitListPart.h>
#include <volsg/nodes/SceneKit.h>
#include <volsg/nodes/SeparatorKit.h>
#include <volsg/nodes/ShapeKit.h>
#include <volsg/nodes/WrapperKit.h>

namespace volsg {

namespace {

/// A Separator's work for the parts between its construction and destruction.
class SeparatorScope {
public:
    explicit SeparatorScope(Action& action) : state_(action.state()) { state_.push(); }
    ~SeparatorScope() { state_.pop(); }
    SeparatorScope(const SeparatorScope&) = delete;
    SeparatorScope& operator=(const SeparatorScope&) = delete;

private:
    State& state_;
};

/// A TransformSeparator's: only the model matrix comes back.
class TransformSeparatorScope {
public:
    explicit TransformSeparatorScope(Action& action)
        : state_(action.state()), saved_(state_.modelMatrix()) {}
    ~TransformSeparatorScope() { state_.setModelMatrix(saved_); }
    TransformSeparatorScope(const TransformSeparatorScope&) = delete;
    TransformSeparatorScope& operator=(const TransformSeparatorScope&) = delete;

private:
    State& state_;
    glm::dmat4 saved_;
};

/// Traverses `node` if there is one (a part's node, or its default).
void traverseNode(Action& action, Node* node) {
    if (node && !action.isTerminated()) action.traverse(*node);
}

} // namespace

void NodeKitListPart::doAction(Action& action) {
    if (Node* container = containerNode.getValue()) action.traverse(*container);
}

void BaseKit::traversePart(Action& action, const SFNode& part) {
    if (action.isTerminated()) return;
    if (Node* node = part.getValue()) action.traverse(*node);
}

Node* BaseKit::partOrDefault(const SFNode& part, ref_ptr<Node>& fallback, ref_ptr<Node> (*make)()) {
    if (!part.isDefault()) return part.getValue();
    if (!fallback) fallback = make();
    return fallback.get();
}

void BaseKit::doAction(Action& action) {
    traversePart(action, callbackList);
}

void AppearanceKit::doAction(Action& action) {
    traversePart(action, callbackList);
    for (const SFNode* part :
         {&lightModel, &environment, &drawStyle, &material, &complexity, &texture2, &font})
        traversePart(action, *part);
}

void SeparatorKit::traverseLeadingParts(Action& action) const {
    for (const SFNode* part : {&pickStyle, &appearance, &units, &transform, &texture2Transform})
        traversePart(action, *part);
}

void SeparatorKit::doAction(Action& action) {
    traversePart(action, callbackList);
    const SeparatorScope top(action);
    traverseLeadingParts(action);
    traversePart(action, childList);
}

ref_ptr<Node> ShapeKit::makeCube() {
    return Cube::create();
}

void ShapeKit::doAction(Action& action) {
    traversePart(action, callbackList);
    const SeparatorScope top(action);
    traverseLeadingParts(action);
    for (const SFNode* part :
         {&materialBinding, &normalBinding, &textureCoordinateBinding, &shapeHints, &coordinate3,
          &coordinate4, &normal, &textureCoordinate2, &profileCoordinate2, &profileCoordinate3,
          &profileList, &childList, &textureCoordinateFunction, &localTransform})
        traversePart(action, *part);
    const SeparatorScope shapeScope(action);
    traverseNode(action, shapeNode());
}

void WrapperKit::doAction(Action& action) {
    traversePart(action, callbackList);
    const SeparatorScope top(action);
    traverseLeadingParts(action);
    traversePart(action, childList);
    traversePart(action, localTransform);
    traversePart(action, contents);
}

ref_ptr<Node> LightKit::makeDirectionalLight() {
    return DirectionalLight::create();
}

void LightKit::doAction(Action& action) {
    traversePart(action, callbackList);
    const TransformSeparatorScope group(action);
    traversePart(action, transform);
    traverseNode(action, lightNode());
    const SeparatorScope iconScope(action);
    traversePart(action, icon);
}

ref_ptr<Node> CameraKit::makePerspectiveCamera() {
    return PerspectiveCamera::create();
}

void CameraKit::doAction(Action& action) {
    traversePart(action, callbackList);
    const TransformSeparatorScope group(action);
    traversePart(action, transform);
    traverseNode(action, cameraNode());
}

void SceneKit::doAction(Action& action) {
    traversePart(action, callbackList);
    const SeparatorScope top(action);
    traversePart(action, cameraList);
    traversePart(action, lightList);
    traversePart(action, childList);
}

} // namespace volsg
