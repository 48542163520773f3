// The text nodes: Font in scope, and the meshes of Text3 and AsciiText (lib/volsg/text).
#include <volsg/nodes/AsciiText.h>
#include <volsg/nodes/Font.h>
#include <volsg/nodes/Text2.h>
#include <volsg/nodes/Text3.h>
#include <volsg/nodes/TextFont.h>

#include <algorithm>
#include <cmath>

#include <volsg/actions/Action.h>
#include <volsg/core/Error.h>
#include <volsg/geometry/MeshKey.h>
#include <volsg/nodes/Bindings.h>
#include <volsg/nodes/Profile.h>
#include <volsg/nodes/ShapeHints.h>
#include <volsg/nodes/ShapeState.h>
#include <volsg/nodes/VertexProperty.h>
#include <volsg/state/State.h>
#include <volsg/text/Font.h>
#include <volsg/text/TextLayout.h>

namespace volsg {

const EnumValues Text2::justificationNames{{"LEFT", LEFT}, {"RIGHT", RIGHT}, {"CENTER", CENTER}};
const EnumValues Text3::justificationNames{{"LEFT", LEFT}, {"RIGHT", RIGHT}, {"CENTER", CENTER}};
const EnumValues Text3::partNames{{"FRONT", FRONT}, {"SIDES", SIDES}, {"BACK", BACK}, {"ALL", ALL}};
const EnumValues AsciiText::justificationNames{
    {"LEFT", LEFT}, {"RIGHT", RIGHT}, {"CENTER", CENTER}};

void Font::doAction(Action& action) {
    action.state().add(*this);
}

std::uint64_t FontInScope::key() const {
    const std::uint64_t key = combineMeshKey(0xf0e7u, reinterpret_cast<std::uintptr_t>(node));
    return combineMeshKey(key, node ? node->version() : 0);
}

FontInScope fontInScope(const State& state) {
    FontInScope out;
    if (const Font* font = state.nearestNode<Font>()) {
        out.node = font;
        out.name = font->name();
        out.size = font->size();
    }
    return out;
}

std::shared_ptr<FontFace> openFontFor(const Node& textNode, const FontInScope& font) {
    try {
        return FontFace::open(findFontFile(font.name));
    } catch (const Error& e) {
        throw Error(describeNode(textNode) + ": " + e.message());
    }
}

void Text2::buildMesh(const State&, Mesh& out) const {
    out = Mesh{};
}

ScreenText screenTextInScope(const Text2& text, const State& state,
                             std::shared_ptr<FontFace>& face) {
    const FontInScope font = fontInScope(state);
    if (!std::isfinite(font.size))
        throw Error(describeNode(text) + ": the Font size is not a finite number");
    if (font.size > float(kMaxScreenTextPixels))
        throw Error(describeNode(text) + ": Font size " + std::to_string(font.size) +
                    " is beyond the " + std::to_string(kMaxScreenTextPixels) +
                    " pixels Text2 draws");
    const int pixels = int(std::lround(font.size));
    if (pixels < 1) return {};
    face = openFontFor(text, font);
    const TextJustification justification =
        text.justification() == Text2::RIGHT    ? TextJustification::Right
        : text.justification() == Text2::CENTER ? TextJustification::Center
                                                : TextJustification::Left;
    try {
        return layoutScreenText(*face, text.string.getValues(), pixels, text.spacing(),
                                justification);
    } catch (const Error& e) {
        throw Error(describeNode(text) + ": " + e.message());
    }
}

namespace {

TextJustification justificationOf(int value) {
    return value == Text3::RIGHT    ? TextJustification::Right
           : value == Text3::CENTER ? TextJustification::Center
                                    : TextJustification::Left;
}

bool materialsPerPart(const ShapeState& scope) {
    if (!scope.materialBinding) return false;
    int value = OVERALL;
    if (scope.materialBinding->isA<MaterialBinding>())
        value = static_cast<const MaterialBinding*>(scope.materialBinding)->value();
    else if (scope.materialBinding->isA<VertexProperty>())
        value = static_cast<const VertexProperty*>(scope.materialBinding)->materialBinding();
    return value != OVERALL;
}

/// What Text3 and AsciiText take from the state alike.
struct TextSetup {
    std::shared_ptr<FontFace> face;
    TextMeshDescription description;
    float complexity = 0.5f;
};
TextSetup setUp(const Node& node, const State& state) {
    const ShapeState scope = gatherShapeState(state, nullptr);
    const FontInScope font = fontInScope(state);
    if (!std::isfinite(font.size))
        throw Error(describeNode(node) + ": the Font size is not a finite number");
    TextSetup s;
    s.face = openFontFor(node, font);
    s.complexity = scope.complexityValue();
    TextMeshDescription& d = s.description;
    d.size = font.size;
    // Coin flattens each curved piece of an outline into 16 x Complexity steps.
    d.curveSteps = std::max(1, int(16.0f * s.complexity));
    d.creaseAngle = scope.hints ? double(scope.hints->creaseAngle()) : 0.0;
    d.textureCoords = scope.textured();
    if (materialsPerPart(scope)) {
        // Coin sends material 1 to the sides and 2 to the back when there are that many; a
        // part without its own keeps the material sent last.
        const std::size_t n = materialCount(scope);
        d.partColors = true;
        d.colors[0] = materialColor(scope, 0);
        d.colors[1] = n > 1 ? materialColor(scope, 1) : d.colors[0];
        d.colors[2] = n > 2 ? materialColor(scope, 2) : d.colors[1];
    }
    return s;
}

} // namespace

std::uint64_t Text3::meshKey(const State& state) const {
    std::uint64_t key = Shape::meshKey(state);
    key = combineMeshKey(key, fontInScope(state).key());
    return combineMeshKey(key, gatherProfiles(state).key());
}

void Text3::buildMesh(const State& state, Mesh& out) const {
    out = Mesh{};
    TextSetup s = setUp(*this, state);
    try {
        const std::vector<glm::dvec2> profile = textProfile(gatherProfiles(state), s.complexity);
        TextMeshDescription& d = s.description;
        d.strings = string.getValues();
        d.spacing = spacing();
        d.justification = justificationOf(justification());
        d.front = (parts() & FRONT) != 0;
        d.sides = (parts() & SIDES) != 0;
        d.back = (parts() & BACK) != 0;
        d.profile = profile;
        buildTextMesh(*s.face, d, out);
    } catch (const Error& e) {
        throw Error(describeNode(*this) + ": " + e.message());
    }
}

std::uint64_t AsciiText::meshKey(const State& state) const {
    return combineMeshKey(Shape::meshKey(state), fontInScope(state).key());
}

void AsciiText::buildMesh(const State& state, Mesh& out) const {
    out = Mesh{};
    TextSetup s = setUp(*this, state);
    TextMeshDescription& d = s.description;
    d.strings = string.getValues();
    d.spacing = spacing();
    d.justification = justificationOf(justification());
    d.widths = width.getValues();
    d.partColors = false; // one part
    try {
        buildTextMesh(*s.face, d, out);
    } catch (const Error& e) {
        throw Error(describeNode(*this) + ": " + e.message());
    }
}

} // namespace volsg
