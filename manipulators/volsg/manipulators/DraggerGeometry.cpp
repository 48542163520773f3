#include <volsg/manipulators/DraggerGeometry.h>

#include <algorithm>
#include <cmath>

#include <volsg/manipulators/DragMath.h>
#include <volsg/nodes/Material.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/Transform.h>

namespace volsg {

namespace {
const glm::vec3 highlightColor(1.0f, 0.85f, 0.1f);

} // namespace

DraggerGeometry::DraggerGeometry() : root_(Separator::create()) {}
DraggerGeometry::~DraggerGeometry() = default;

int DraggerGeometry::addPart(ref_ptr<Node> shape, const glm::vec3& color, float transparency) {
    Part p;
    p.group = Separator::create();
    p.transform = Transform::create();
    p.material = Material::create();
    p.material->diffuseColor = {glm::vec3(0.0f)};
    p.material->ambientColor = {glm::vec3(0.0f)};
    p.material->emissiveColor = {color};
    p.material->transparency = {transparency};
    p.shape = shape;
    p.color = color;
    p.group->addChild(p.transform);
    p.group->addChild(p.material);
    p.group->addChild(shape);
    root_->addChild(p.group);
    parts_.push_back(std::move(p));
    return int(parts_.size()) - 1;
}

void DraggerGeometry::place(int id, const glm::dvec3& position, const glm::dquat& rotation) {
    Part& p = parts_.at(std::size_t(id));
    const glm::vec3 t(position);
    if (p.transform->translation() != t) p.transform->translation = t;
    const Rotation r = rotationFromQuat(rotation);
    if (!(p.transform->rotation() == r)) p.transform->rotation = r;
}

Node& DraggerGeometry::shape(int id) const {
    return *parts_.at(std::size_t(id)).shape;
}

void DraggerGeometry::highlight(int id) {
    if (id == highlighted_) return;
    if (highlighted_ >= 0 && std::size_t(highlighted_) < parts_.size()) {
        Part& old = parts_[std::size_t(highlighted_)];
        old.material->emissiveColor = {old.color};
    }
    highlighted_ = id;
    if (id >= 0 && std::size_t(id) < parts_.size())
        parts_[std::size_t(id)].material->emissiveColor = {highlightColor};
}

int DraggerGeometry::partOnPath(const std::vector<Node*>& path) const {
    for (const Node* n : path)
        for (std::size_t i = 0; i < parts_.size(); ++i)
            if (parts_[i].group.get() == n) return int(i);
    return -1;
}

Node& DraggerGeometry::root() const {
    return *root_;
}

} // namespace volsg
