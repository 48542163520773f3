#include <volsg/editors/ScenePicker.h>

#include <volsg/actions/PickAction.h>
#include <volsg/manipulators/DragMath.h>
#include <volsg/nodes/Camera.h> // PickAction holds a ref_ptr<Camera>
#include <volsg/nodes/Volume.h>
#include <volsg/nodes/VolumeData.h>

namespace volsg {

namespace {

/// Visits the graph as a render would, meeting each Volume with its VolumeData in scope.
class VolumeBoxPickAction final : public Action {
public:
    VolumeBoxPickAction(const Ray& ray, double nearDistance, double farDistance)
        : ray_(ray), near_(nearDistance), far_(farDistance) {}
    std::optional<ScenePick> hit;

protected:
    void dispatch(Node& node) override {
        if (!node.isA<Volume>()) {
            node.doAction(*this);
            return;
        }
        const VolumeData* data = state().nearestNode<VolumeData>();
        if (!data) return;
        ref_ptr<const VolumeGrid> grid;
        try {
            grid = data->grid();
        } catch (const std::exception&) {
            return; // data that does not load is not drawn, so not picked
        }
        if (!grid) return;
        const glm::dvec3 half = 0.5 * grid->extent();
        Box3 box;
        box.extendBy(-half);
        box.extendBy(half);
        const glm::dmat4 model = state().modelMatrix();
        const auto boxHit = intersectRayBox(ray_.transformed(glm::inverse(model)), box);
        if (!boxHit) return;
        const glm::dvec3 point = ray_.at(boxHit->t); // t is preserved by the transform
        const double distance = glm::length(point - ray_.origin);
        if (distance < near_ || distance > far_ || (hit && hit->distance <= distance)) return;
        hit = ScenePick{&node, path(), point, distance, true};
    }

private:
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
    VolumeBoxPickAction volumes(ray, nearDistance, farDistance);
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
