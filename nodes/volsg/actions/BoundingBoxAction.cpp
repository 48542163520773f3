#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/gltf/GltfAsset.h>
#include <volsg/nodes/Cone.h>
#include <volsg/nodes/Cylinder.h>
#include <volsg/nodes/File.h>
#include <volsg/nodes/GltfModel.h>
#include <volsg/nodes/ObliqueSlice.h>
#include <volsg/nodes/OrthoSlice.h>
#include <volsg/nodes/ResetTransform.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/Shape.h>
#include <volsg/nodes/ShearWarpVolume.h>
#include <volsg/nodes/Sphere.h>
#include <volsg/nodes/Text2.h>
#include <volsg/nodes/Volume.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/volumescene/VolumeInScope.h>
#include <volsg/voxelfile/PackedVolume.h>

namespace volsg {

namespace {

/// The round primitives' tessellation lies inside them: their box is the analytic one
/// (Coin's computeBBox), whatever the complexity.
template <class Primitive> bool boundPrimitive(BoundingBoxAction& action, Shape& shape) {
    if (!shape.isA<Primitive>()) return false;
    if (!shape.meshBounds(action.state()).isEmpty())
        action.extendByLocal(static_cast<Primitive&>(shape).objectBox());
    return true;
}

void boundShape(BoundingBoxAction& action, Shape& shape) {
    if (boundPrimitive<Sphere>(action, shape) || boundPrimitive<Cone>(action, shape) ||
        boundPrimitive<Cylinder>(action, shape))
        return;
    action.extendByLocal(shape.meshBounds(action.state()));
}

void boundVolume(BoundingBoxAction& action, Volume&) {
    if (const VolumeData* data = action.state().nearestNode<VolumeData>())
        action.extendByLocal(data->localBounds());
}

void boundShearWarpVolume(BoundingBoxAction& action, ShearWarpVolume& node) {
    if (!node.voxelFile().empty()) {
        action.extendByLocal(PackedVolume::load(node.voxelFile(), node.directory()).localBounds());
        return;
    }
    if (const VolumeData* data = action.state().nearestNode<VolumeData>())
        action.extendByLocal(data->localBounds());
}

void boundOrthoSlice(BoundingBoxAction& action, OrthoSlice& slice) {
    if (const auto volume = gatherVolumeInScope(action.state()))
        action.extendByLocal(slice.localPlane(*volume->data).polygonBounds(volume->halfExtent()));
    slice.doAction(action);
}

void boundObliqueSlice(BoundingBoxAction& action, ObliqueSlice& slice) {
    const auto plane = slice.localPlane();
    if (!plane) return;
    if (const auto volume = gatherVolumeInScope(action.state()))
        action.extendByLocal(plane->polygonBounds(volume->halfExtent()));
}

void boundGltfModel(BoundingBoxAction& action, GltfModel& model) {
    action.extendByLocal(model.asset().bounds);
}

/// Text2's extent is in pixels: without a view (this action has no camera or viewport) its
/// box is its origin, the point Coin's SoText2::computeBBox builds its screen quad around.
void boundText2(BoundingBoxAction& action, Text2& text) {
    for (const std::string& s : text.string.getValues())
        if (!s.empty()) {
            Box3 origin;
            origin.extendBy(glm::dvec3(0.0));
            action.extendByLocal(origin);
            return;
        }
}

void boundResetTransform(BoundingBoxAction& action, ResetTransform& node) {
    if (node.whatToReset() & ResetTransform::BBOX) action.emptyBoxInScope();
    node.doAction(action);
}

/// A File whose file could not be read: its error, as a render's (the box would be wrong).
void boundFile(BoundingBoxAction& action, File& node) {
    node.update();
    if (node.readError()) throw *node.readError();
    node.doAction(action);
}

} // namespace

ActionMethods& BoundingBoxAction::methods() {
    static ActionMethods* table = [] {
        auto* t = new ActionMethods(); // never destroyed: methods may run during exit
        t->add(&boundShape);
        t->add(&boundVolume);
        t->add(&boundShearWarpVolume);
        t->add(&boundOrthoSlice);
        t->add(&boundObliqueSlice);
        t->add(&boundGltfModel);
        t->add(&boundResetTransform);
        t->add(&boundFile);
        t->add(&boundText2);
        return t;
    }();
    return *table;
}

void BoundingBoxAction::extendByLocal(const Box3& local) {
    box_.extendBy(local, state().modelMatrix());
}

void BoundingBoxAction::beginTraversal(Node& root) {
    box_ = Box3{};
    Action::beginTraversal(root);
}

void BoundingBoxAction::dispatch(Node& node) {
    if (!node.isA<Separator>()) {
        methods().apply(*this, node);
        return;
    }
    // A Separator's children start from an empty box and the box from before it is added back
    // after them, so emptyBoxInScope() inside it forgets only what its own children added.
    Box3 before = box_;
    box_ = Box3{};
    methods().apply(*this, node);
    before.extendBy(box_);
    box_ = before;
}

Box3 computeBoundingBox(Node& root) {
    BoundingBoxAction action;
    action.apply(root);
    return action.boundingBox();
}

} // namespace volsg
