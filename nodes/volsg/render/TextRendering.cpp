// Text2 draws its glyphs in screen space (lib/volsg/text/ScreenTextRenderer): at the projected
// local origin, unlit in the diffuse colour and opacity of the material in scope (as Coin's
// SoText2), in the Opaque pass. Text3 and AsciiText are shapes: ShapeRendering draws them.
#include <vector>

#include <volsg/nodes/DrawStyle.h>
#include <volsg/nodes/ShapeState.h>
#include <volsg/nodes/Text2.h>
#include <volsg/nodes/TextFont.h>
#include <volsg/render/BuiltinRendering.h>
#include <volsg/render/RenderAction.h>
#include <volsg/text/ScreenTextRenderer.h>

namespace volsg {

namespace {

void renderText2(RenderAction& action, Text2& text) {
    if (action.pass() != RenderPass::Opaque) return;
    const State& state = action.state();
    const ShapeState scope = gatherShapeState(state, nullptr);
    if (scope.drawStyle && scope.drawStyle->style() == DrawStyle::INVISIBLE) return;
    std::shared_ptr<FontFace> face;
    const ScreenText layout = screenTextInScope(text, state, face);
    action.countTextGlyphs(layout.glyphs.size());
    if (layout.glyphs.empty()) return;
    const glm::dvec3 anchor(state.modelMatrix() * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    // A ClipPlane that removes the origin removes the text (Coin's raster position).
    thread_local std::vector<glm::dvec4> planes;
    action.clipPlanesInScope(planes);
    for (const glm::dvec4& p : planes)
        if (glm::dot(glm::dvec3(p), anchor) < p.w) return;
    ScreenTextDraw draw;
    draw.anchor = anchor;
    draw.color = materialColor(scope, 0);
    draw.text = &layout;
    draw.face = face.get();
    action.frame().cache.shared<ScreenTextRenderer>().draw(action.frame(), draw);
}

} // namespace

void addTextRenderMethods(ActionMethods& methods) {
    methods.add(&renderText2);
}

} // namespace volsg
