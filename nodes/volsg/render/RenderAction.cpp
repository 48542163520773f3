#include <volsg/nodes/ClipPlane.h>
#include <volsg/nodes/File.h>
#include <volsg/nodes/LOD.h>
#include <volsg/nodes/LevelOfDetail.h>
#include <volsg/nodes/Light.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/ShearWarpVolume.h>
#include <volsg/render/BuiltinRendering.h>
#include <volsg/render/RenderAction.h>
#include <volsg/render/RenderCaching.h>

#include <algorithm>
#include <string>

#include <cmath>
#include <volsg/core/Error.h>
#include <volsg/core/Limits.h>

namespace volsg {

ActionMethods& RenderAction::methods() {
    static ActionMethods* table = [] {
        auto* t = new ActionMethods(); // never destroyed: methods may run during exit
        addBuiltinRenderMethods(*t);
        return t;
    }();
    return *table;
}

void RenderAction::beginTraversal(Node& root) {
    StateView view;
    view.eye = glm::dvec3(glm::inverse(frame_.view.view) * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    view.projected = true;
    view.view = frame_.view.view;
    view.projection = frame_.view.projection;
    view.width = frame_.view.width;
    view.height = frame_.view.height;
    state().setView(view);
    Action::beginTraversal(root);
}

namespace {

/// Whether nodes of `type` may be traversed in a CPU frame (FrameContext::cpuImage): those
/// that draw nothing themselves, and ShearWarpVolume, which composites a CPU image. Any other
/// render method draws with GL. Asked of the methods themselves, so a node type added later
/// with a render method of its own is drawn on GL.
bool drawsInCpuFrames(const NodeType& type) {
    const ActionMethods& m = RenderAction::methods();
    if (!m.hasMethod(type)) return true;
    for (const NodeType* t :
         {&Separator::classType(), &LOD::classType(), &LevelOfDetail::classType(),
          &File::classType(), &ShearWarpVolume::classType()})
        if (m.runsMethodOf(type, *t)) return true;
    return false;
}

} // namespace

void RenderAction::dispatch(Node& node) {
    if (frame_.cpuImage && !drawsInCpuFrames(node.type())) {
        frame_.needsGl = true;
        terminate();
        return;
    }
    if (frame_.recording) noteForCache(*frame_.recording, node);
    methods().apply(*this, node);
}

void RenderAction::countVolumeInstance() {
    if (++frame_.volumeInstances > limits::maxVolumeInstances)
        throw Error("more than " + std::to_string(limits::maxVolumeInstances) +
                    " volume instances in one frame (every USE of a volume draws it again)");
}

void RenderAction::countTextGlyphs(std::size_t glyphs) {
    frame_.textGlyphs += glyphs;
    if (frame_.textGlyphs > limits::maxFrameTextGlyphs)
        throw Error("more than " + std::to_string(limits::maxFrameTextGlyphs) +
                    " screen-text characters in one frame (every USE of a Text2 lays it out "
                    "again)");
}

void RenderAction::lightsInScope(std::vector<SceneLight>& out) const {
    out.clear();
    if (frame_.view.headlight) {
        // Along the view direction: towards the light is towards the viewer.
        const glm::dvec3 back = glm::dvec3(glm::inverse(frame_.view.view) * glm::dvec4(0, 0, 1, 0));
        out.push_back({glm::vec4(glm::vec3(glm::normalize(back)), 0.0f), glm::vec3(1.0f)});
    }
    // Walks the entries directly: State::all() would allocate for every shape.
    for (const StateEntry& entry : state().entries()) {
        if (!entry.node->isA<Light>()) continue;
        const StateEntry* e = &entry;
        const auto& light = static_cast<const Light&>(*e->node);
        const glm::vec3 color = light.intensity() * light.color();
        if (e->node->isA<DirectionalLight>()) {
            const auto& d = static_cast<const DirectionalLight&>(light);
            const glm::dvec3 w = glm::dvec3(e->model * glm::dvec4(glm::dvec3(d.direction()), 0.0));
            if (!(glm::length(w) > 0.0)) continue; // a zero direction lights nothing
            out.push_back({glm::vec4(glm::vec3(-glm::normalize(w)), 0.0f), color});
        } else if (e->node->isA<PointLight>()) {
            const auto& p = static_cast<const PointLight&>(light);
            const glm::dvec3 w = glm::dvec3(e->model * glm::dvec4(glm::dvec3(p.location()), 1.0));
            out.push_back({glm::vec4(glm::vec3(w), 1.0f), color});
        } else if (e->node->isA<SpotLight>()) {
            const auto& s = static_cast<const SpotLight&>(light);
            const glm::dvec3 w = glm::dvec3(e->model * glm::dvec4(glm::dvec3(s.location()), 1.0));
            const glm::dvec3 d = glm::dvec3(e->model * glm::dvec4(glm::dvec3(s.direction()), 0.0));
            if (!(glm::length(d) > 0.0)) continue; // a zero direction lights nothing
            SceneLight spot{glm::vec4(glm::vec3(w), 1.0f), color};
            spot.spotDirection = glm::vec3(glm::normalize(d));
            // Inventor's cut-off is the half angle of the cone; above pi/2 it lights all around.
            const double cutOff = std::clamp(double(s.cutOffAngle()), 0.0, 3.14159265358979);
            spot.spotCosCutOff = cutOff >= 3.14159265358979 / 2.0 ? -2.0f : float(std::cos(cutOff));
            spot.spotExponent = std::clamp(s.dropOffRate(), 0.0f, 1.0f) * 128.0f;
            out.push_back(spot);
        }
    }
}

void RenderAction::clipPlanesInScope(std::vector<glm::dvec4>& out) const {
    out.clear();
    for (const StateEntry& e : state().entries())
        if (e.node->isA<ClipPlane>())
            out.push_back(
                ClipPlane::worldPlane(static_cast<const ClipPlane&>(*e.node).plane(), e.model));
}

} // namespace volsg
