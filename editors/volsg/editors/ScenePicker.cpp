#include <volsg/editors/ScenePicker.h>

#include <algorithm>

#include <volsg/actions/PickAction.h>
#include <volsg/nodes/Camera.h> // PickAction holds a ref_ptr<Camera>
#include <volsg/nodes/ShearWarpVolume.h>
#include <volsg/nodes/Volume.h>
#include <volsg/reference/ReferenceRayCaster.h>
#include <volsg/volumescene/ReferenceScene.h>
#include <volsg/volumescene/ShearWarpObjects.h>

namespace volsg {

namespace {

/// Visits the graph as a render would and picks each Volume (and ShearWarpVolume) by its
/// content: the first point along the ray where the reference ray caster's classification of
/// the volume's data is visible (ReferenceRayCaster::firstVisibleDistance).
class VolumeContentPickAction final : public Action {
public:
    VolumeContentPickAction(const Ray& ray, double nearDistance, double farDistance)
        : ray_(ray), near_(nearDistance), far_(farDistance) {}
    std::optional<ScenePick> hit;

protected:
    void dispatch(Node& node) override {
        // As collectVolumes() does: a ShearWarpVolume before its doAction (its children are
        // its state), a Volume after.
        if (node.isA<ShearWarpVolume>()) {
            std::optional<RayCastVolume> volume;
            try {
                volume = describeShearWarpVolume(static_cast<ShearWarpVolume&>(node), state());
            } catch (const std::exception&) {
                // data that does not load is not drawn, so not picked
            }
            if (volume) consider(node, *volume);
        }
        node.doAction(*this);
        if (node.isA<Volume>()) {
            std::optional<RayCastVolume> volume;
            try {
                volume = describeVolume(static_cast<const Volume&>(node), state());
            } catch (const std::exception&) {
                // no VolumeData in scope, or data that does not load: nothing drawn to pick
            }
            if (volume && volume->data) consider(node, *volume);
        }
    }

private:
    void consider(Node& node, const RayCastVolume& volume) {
        const double farthest = hit ? std::min(far_, hit->distance) : far_;
        std::optional<double> distance;
        try {
            distance = ReferenceRayCaster::firstVisibleDistance(volume, ray_, near_, farthest);
        } catch (const std::exception&) {
            return; // a volume the reference cannot describe (singular model, ...)
        }
        if (!distance || (hit && hit->distance <= *distance)) return;
        hit = ScenePick{&node, path(), ray_.at(*distance), *distance, true};
    }

    Ray ray_;
    double near_, far_;
};

class ScopeProbeAction final : public Action {
public:
    ScopeProbeAction(const Node& target, const NodeType& type) : target_(target), type_(type) {}
    Node* found = nullptr;

protected:
    void dispatch(Node& node) override {
        if (&node == &target_) {
            const auto& entries = state().entries();
            for (auto it = entries.rbegin(); it != entries.rend(); ++it)
                if (it->node->isOfType(type_)) {
                    found = const_cast<Node*>(it->node);
                    break;
                }
            terminate();
            return;
        }
        node.doAction(*this);
    }

private:
    const Node& target_;
    const NodeType& type_;
};

} // namespace

std::optional<ScenePick> pickScene(Node& root, const Ray& worldRay, double nearDistance,
                                   double farDistance) {
    Ray ray = worldRay;
    ray.direction = glm::normalize(ray.direction);
    PickAction shapes;
    shapes.setRay(ray, nearDistance, farDistance);
    shapes.apply(root);
    VolumeContentPickAction volumes(ray, nearDistance, farDistance);
    volumes.apply(root);
    std::optional<ScenePick> best = volumes.hit;
    if (const auto& p = shapes.picked(); p && !p->path.empty()) {
        if (!best || p->distance < best->distance)
            best = ScenePick{p->path.back(), p->path, p->point, p->distance, false};
    }
    return best;
}

Node* nearestInScope(Node& root, const Node& target, const NodeType& type) {
    ScopeProbeAction probe(target, type);
    probe.apply(root);
    return probe.found;
}

} // namespace volsg
