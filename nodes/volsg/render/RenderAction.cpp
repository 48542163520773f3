#include <volsg/nodes/ClipPlane.h>
#include <volsg/nodes/Light.h>
#include <volsg/render/BuiltinRendering.h>
#include <volsg/render/RenderAction.h>

namespace volsg {

ActionMethods& RenderAction::methods() {
    static ActionMethods* table = [] {
        auto* t = new ActionMethods(); // never destroyed: methods may run during exit
        addBuiltinRenderMethods(*t);
        return t;
    }();
    return *table;
}

void RenderAction::dispatch(Node& node) {
    methods().apply(*this, node);
}

void RenderAction::lightsInScope(std::vector<SceneLight>& out) const {
    out.clear();
    if (frame_.view.headlight) {
        // Along the view direction: towards the light is towards the viewer.
        const glm::dvec3 back =
            glm::dvec3(glm::inverse(frame_.view.view) * glm::dvec4(0, 0, 1, 0));
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
