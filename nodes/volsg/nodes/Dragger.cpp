#include <volsg/actions/Action.h>
#include <volsg/core/Error.h>
#include <volsg/fields/Fields.h>
#include <volsg/io/InventorTypes.h>
#include <volsg/io/SceneReader.h>
#include <volsg/math/TransformParts.h>
#include <volsg/nodes/Coordinate3.h>
#include <volsg/nodes/Dragger.h>
#include <volsg/nodes/DraggerCatalog.h>
#include <volsg/nodes/MatrixTransform.h>
#include <volsg/nodes/Rotation.h>
#include <volsg/nodes/Scale.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/Switch.h>
#include <volsg/state/State.h>

#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

namespace volsg {

namespace {

// Coin 4's SoDragger subclasses.
constexpr std::array<const char*, 21> draggerTypeNames{"CenterballDragger",
                                                       "DirectionalLightDragger",
                                                       "DragPointDragger",
                                                       "HandleBoxDragger",
                                                       "JackDragger",
                                                       "PointLightDragger",
                                                       "RotateCylindricalDragger",
                                                       "RotateDiscDragger",
                                                       "RotateSphericalDragger",
                                                       "Scale1Dragger",
                                                       "Scale2Dragger",
                                                       "Scale2UniformDragger",
                                                       "ScaleUniformDragger",
                                                       "SpotLightDragger",
                                                       "TabBoxDragger",
                                                       "TabPlaneDragger",
                                                       "TrackballDragger",
                                                       "TransformBoxDragger",
                                                       "TransformerDragger",
                                                       "Translate1Dragger",
                                                       "Translate2Dragger"};

ref_ptr<Node> makeDraggerOfType(std::size_t index);

template <std::size_t... I>
constexpr std::array<NodeType::Factory, sizeof...(I)> makeFactories(std::index_sequence<I...>) {
    return {[]() -> ref_ptr<Node> { return makeDraggerOfType(I); }...};
}

/// One dragger type: its node type, its fields (the reader's table of Inventor types) and
/// its catalog (null for a type whose rest state volsg does not draw).
struct DraggerTypeInfo {
    std::unique_ptr<NodeType> type;
    const InventorType* fields = nullptr;
    const DraggerCatalog* catalog = nullptr;
};

const std::vector<DraggerTypeInfo>& draggerTypeInfos() {
    static const std::vector<DraggerTypeInfo> infos = [] {
        static constexpr auto factories =
            makeFactories(std::make_index_sequence<draggerTypeNames.size()>());
        std::vector<DraggerTypeInfo> out(draggerTypeNames.size());
        for (std::size_t i = 0; i < draggerTypeNames.size(); ++i) {
            out[i].type = std::make_unique<NodeType>(draggerTypeNames[i], &Dragger::classType(),
                                                     factories[i], true);
            out[i].fields = findInventorType(draggerTypeNames[i]);
            for (const DraggerCatalog& catalog : draggerCatalogs())
                if (catalog.typeName == draggerTypeNames[i]) out[i].catalog = &catalog;
        }
        return out;
    }();
    return infos;
}

ref_ptr<Node> makeDraggerOfType(std::size_t index) {
    return Dragger::createOfType(draggerTypeNames[index]);
}

/// The nodes named in a resource file (DEF name), read once.
using NamedNodes = std::unordered_map<std::string, ref_ptr<Node>>;

void collectNamed(Node& node, NamedNodes& out, std::unordered_set<const Node*>& seen) {
    if (!seen.insert(&node).second) return;
    if (!node.getName().empty()) out.emplace(node.getName(), ref_ptr<Node>(&node));
    if (const auto* children = node.children())
        for (const auto& child : *children)
            if (child) collectNamed(*child, out, seen);
}

const NamedNodes& resourceNodes(const std::string& fileName) {
    static std::mutex mutex;
    static std::map<std::string, NamedNodes> files;
    const std::lock_guard lock(mutex);
    auto [it, added] = files.try_emplace(fileName);
    if (added && !fileName.empty()) {
        const std::string_view text = draggerDefaultFile(fileName);
        if (text.empty()) throw Error("dragger defaults: no embedded file " + fileName);
        const ref_ptr<Node> root = readSceneFromString(text, "draggerDefaults/" + fileName);
        std::unordered_set<const Node*> seen;
        collectNamed(*root, it->second, seen);
    }
    return it->second;
}

/// The node an Inventor text describes, read once per text (catalog parts the constructors
/// make: Rotations, Transforms, AntiSquish).
ref_ptr<Node> inlineNode(const std::string& text) {
    static std::mutex mutex;
    static std::unordered_map<std::string, ref_ptr<Node>> nodes;
    const std::lock_guard lock(mutex);
    ref_ptr<Node>& node = nodes[text];
    if (!node) node = readSceneFromString("#Inventor V2.1 ascii\n" + text, "<dragger catalog>");
    return node;
}

Rotation rotationOf(const glm::dquat& q) {
    const glm::dvec3 axis = glm::axis(q);
    Rotation r;
    r.angle = float(glm::angle(q));
    if (r.angle != 0.0f) r.axis = glm::vec3(axis);
    return r;
}

const DraggerTypeInfo* infoOf(std::string_view name) {
    for (const DraggerTypeInfo& info : draggerTypeInfos())
        if (name == info.type->name()) return &info;
    return nullptr;
}

} // namespace

Dragger::Dragger(const DraggerCatalog* catalog, const NodeType& type)
    : catalog_(catalog), type_(&type) {}

Dragger::~Dragger() = default;

std::vector<const NodeType*> Dragger::draggerTypes() {
    std::vector<const NodeType*> out;
    for (const DraggerTypeInfo& info : draggerTypeInfos())
        out.push_back(info.type.get());
    return out;
}

ref_ptr<Dragger> Dragger::createOfType(std::string_view draggerTypeName) {
    const DraggerTypeInfo* info = infoOf(draggerTypeName);
    if (!info) return nullptr;
    ref_ptr<Dragger> d = create(info->catalog, *info->type);
    d->setFileTypeName(std::string(draggerTypeName));
    d->setDescription(Description::Inventor);
    if (info->fields)
        for (const auto& [name, fieldType] : info->fields->fields)
            d->addField(fieldType, name);
    return d;
}

const NodeType& Dragger::type() const {
    return type_ ? *type_ : classType();
}

void Dragger::setPartDefault(const std::string& path, ref_ptr<Node> node) {
    partDefaults_[path] = std::move(node);
    rest_ = nullptr;
}

glm::dmat4 Dragger::motionMatrix() const {
    glm::dmat4 base(1.0);
    if (const auto* part = dynamic_cast<const SFNode*>(findField("motionMatrix"));
        part && !part->isDefault())
        if (const auto* m = dynamic_cast<const MatrixTransform*>(part->getValue()))
            base = glm::dmat4(m->matrix());
    if (readVersion_ != 0 && version() == readVersion_) return base;
    // A field never set has Coin's default (the table's fields start at zero values).
    const auto vec3 = [this](const char* name, glm::dvec3 fallback) {
        const auto* f = dynamic_cast<const SFVec3f*>(findField(name));
        return f && !f->isDefault() ? glm::dvec3(f->getValue()) : fallback;
    };
    const auto rotation = [this](const char* name) {
        const auto* f = dynamic_cast<const SFRotation*>(findField(name));
        return f && !f->isDefault() ? f->getValue().quat() : glm::dquat(1.0, 0.0, 0.0, 0.0);
    };
    const glm::dvec3 center = vec3("center", glm::dvec3(0.0));
    TransformParts parts = decomposeTransform(base, center);
    if (findField("translation")) parts.translation = vec3("translation", glm::dvec3(0.0));
    if (findField("rotation")) parts.rotation = rotation("rotation");
    if (findField("scaleFactor")) parts.scaleFactor = vec3("scaleFactor", glm::dvec3(1.0));
    if (findField("scaleOrientation")) parts.scaleOrientation = rotation("scaleOrientation");
    return composeTransform(parts, center);
}

ref_ptr<Node> Dragger::buildPart(std::size_t index) {
    using Kind = DraggerPart::Kind;
    const DraggerPart& part = catalog_->parts[index];
    if (part.kind == Kind::Motion) {
        ref_ptr<MatrixTransform> motion = MatrixTransform::create();
        motion->matrix = glm::mat4(motionMatrix());
        return motion;
    }
    if (const auto* set = dynamic_cast<const SFNode*>(findField(part.name));
        set && !set->isDefault())
        return ref_ptr<Node>(set->getValue());
    if (const auto it = partDefaults_.find(part.name); it != partDefaults_.end()) return it->second;
    switch (part.kind) {
    case Kind::Separator:
    case Kind::Group:
    case Kind::Switch: {
        ref_ptr<Group> container;
        if (part.kind == Kind::Separator)
            container = Separator::create();
        else if (part.kind == Kind::Group)
            container = Group::create();
        else {
            ref_ptr<Switch> s = Switch::create();
            s->whichChild = part.switchValue;
            container = s;
        }
        // As in Coin, a part that is NULL is no child: a Switch's index counts the others.
        for (int child : part.children)
            if (ref_ptr<Node> node = buildPart(std::size_t(child))) container->addChild(node);
        return container;
    }
    case Kind::CenterMatrix: {
        ref_ptr<MatrixTransform> toCenter = MatrixTransform::create();
        if (const auto* f = dynamic_cast<const SFVec3f*>(findField("center")); f && !f->isDefault())
            toCenter->matrix = glm::translate(glm::mat4(1.0f), f->getValue());
        return toCenter;
    }
    case Kind::RotationInverse: {
        ref_ptr<RotationNode> inverse = RotationNode::create();
        inverse->rotation = rotationOf(glm::inverse(decomposeTransform(motionMatrix()).rotation));
        return inverse;
    }
    case Kind::BeamScale: {
        // Coin's constructor sets the beam for angle 1; the angle changes it when it changes.
        const auto* angle = dynamic_cast<const SFFloat*>(findField("angle"));
        const bool read =
            angle && !angle->isDefault() && !(readVersion_ != 0 && version() == readVersion_);
        const float across = std::tan(read ? angle->getValue() : 1.0f);
        ref_ptr<Scale> beam = Scale::create();
        beam->scaleFactor = glm::vec3(across, across, 1.0f);
        return beam;
    }
    case Kind::EdgeScaleCoords:
    case Kind::CornerScaleCoords: {
        ref_ptr<Coordinate3> coords = Coordinate3::create();
        (part.kind == Kind::EdgeScaleCoords ? edgeScaleCoords_ : cornerScaleCoords_) = coords;
        const glm::vec2 size = scaleTabSize_;
        scaleTabSize_ = glm::vec2(-1.0f);
        setScaleTabSize(size);
        return coords;
    }
    case Kind::Resource: {
        const NamedNodes& named = resourceNodes(catalog_->resourceFile);
        const auto it = named.find(part.value);
        return it == named.end() ? nullptr : it->second;
    }
    case Kind::Inline:
        return inlineNode(part.value);
    case Kind::ChildDragger: {
        ref_ptr<Dragger> child = createOfType(part.value);
        if (!child) return nullptr;
        const NamedNodes& named = resourceNodes(catalog_->resourceFile);
        for (const auto& [path, value] : part.childDefaults) {
            if (value == "{}") {
                child->setPartDefault(path, Separator::create());
            } else if (const auto it = named.find(value.substr(1)); it != named.end()) {
                child->setPartDefault(path, it->second);
            }
        }
        // The defaults this dragger was given for its child's parts ("child.part").
        const std::string prefix = part.name + ".";
        for (const auto& [path, node] : partDefaults_)
            if (path.starts_with(prefix)) child->setPartDefault(path.substr(prefix.size()), node);
        return child;
    }
    case Kind::Motion:
    case Kind::Null:
        break;
    }
    return nullptr;
}

Node* Dragger::restGraph() {
    if (!catalog_ || catalog_->parts.empty()) return nullptr;
    if (!rest_ || restVersion_ != version()) {
        rest_ = buildPart(0);
        restVersion_ = version();
    }
    return rest_.get();
}

void Dragger::setScaleTabSize(glm::vec2 size) {
    if (size == scaleTabSize_) return;
    scaleTabSize_ = size;
    // Coin's corners (SoTabPlaneDragger::reallyAdjustScaleTabSize), 0.01 in front of the plane.
    const float hx = size.x * 0.5f, hy = size.y * 0.5f, sx = size.x, sy = size.y, z = 0.01f;
    if (auto* edge = dynamic_cast<Coordinate3*>(edgeScaleCoords_.get()))
        edge->point = {{hx, 1, z},   {-hx, 1, z},  {-hx, 1 - sy, z},  {hx, 1 - sy, z},
                       {1, -hy, z},  {1, hy, z},   {1 - sx, hy, z},   {1 - sx, -hy, z},
                       {-hx, -1, z}, {hx, -1, z},  {hx, -1 + sy, z},  {-hx, -1 + sy, z},
                       {-1, hy, z},  {-1, -hy, z}, {-1 + sx, -hy, z}, {-1 + sx, hy, z}};
    if (auto* corner = dynamic_cast<Coordinate3*>(cornerScaleCoords_.get()))
        corner->point = {{1, 1, z},   {1 - sx, 1, z},   {1 - sx, 1 - sy, z},   {1, 1 - sy, z},
                         {1, -1, z},  {1, -1 + sy, z},  {1 - sx, -1 + sy, z},  {1 - sx, -1, z},
                         {-1, -1, z}, {-1 + sx, -1, z}, {-1 + sx, -1 + sy, z}, {-1, -1 + sy, z},
                         {-1, 1, z},  {-1, 1 - sy, z},  {-1 + sx, 1 - sy, z},  {-1 + sx, 1, z}};
}

void Dragger::adjustScaleTabs(const Action& action) {
    const StateView* view = action.state().view();
    if (!view || !view->projected || view->width <= 0) return;
    const glm::dmat4 toWorld = action.state().modelMatrix() * motionMatrix();
    const glm::dvec4 eye = view->view * toWorld * glm::dvec4(0.0, 0.0, 0.0, 1.0);
    // The view volume's width at the dragger's depth (SbViewVolume::getWorldToScreenScale),
    // times 10 pixels over the viewport's width.
    const bool perspective = view->projection[3][3] == 0.0;
    const double across =
        perspective ? 2.0 * std::abs(eye.z) / view->projection[0][0] : 2.0 / view->projection[0][0];
    const double size = across * 10.0 / double(view->width);
    const glm::dvec3 scale = decomposeTransform(toWorld).scaleFactor;
    if (scale.x == 0.0 || scale.y == 0.0 || !std::isfinite(size)) return;
    setScaleTabSize(glm::vec2(float(std::abs(size / scale.x)), float(std::abs(size / scale.y))));
}

void Dragger::readDone(const ReadContext&) {
    if (catalog_ && catalog_->readValuesIgnored) readVersion_ = version();
}

namespace {

/// The state a dragger's parts see, as Coin's SoDragger::updateElements sets it for rendering
/// and picking: counter-clockwise solid convex faces (back faces culled), a crease angle of
/// 0.5, Phong lighting, default bindings, no normals in scope, default complexity.
Node& draggerElements() {
    static const ref_ptr<Node> elements = inlineNode(
        "Group { ShapeHints { vertexOrdering COUNTERCLOCKWISE shapeType SOLID faceType CONVEX "
        "creaseAngle 0.5 } LightModel { model PHONG } MaterialBinding { value DEFAULT } "
        "NormalBinding { value DEFAULT } Normal { vector [ ] } Complexity { } }");
    return *elements;
}

/// The dragger's own scope (Coin pushes the state around its traversal).
class StateScope {
public:
    explicit StateScope(State& state) : state_(state) { state_.push(); }
    ~StateScope() { state_.pop(); }
    StateScope(const StateScope&) = delete;
    StateScope& operator=(const StateScope&) = delete;

private:
    State& state_;
};

} // namespace

void Dragger::doAction(Action& action) {
    const StateScope scope(action.state());
    action.traverse(draggerElements());
    if (const auto* callbacks = dynamic_cast<const SFNode*>(findField("callbackList")))
        if (Node* node = callbacks->getValue(); node && !action.isTerminated())
            action.traverse(*node);
    Node* rest = restGraph();
    if (edgeScaleCoords_ || cornerScaleCoords_) adjustScaleTabs(action);
    if (rest && !action.isTerminated()) action.traverse(*rest);
}

} // namespace volsg
