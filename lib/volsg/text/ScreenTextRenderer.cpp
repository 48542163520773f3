#include <volsg/text/ScreenTextRenderer.h>

#include <algorithm>
#include <cmath>

#include <volsg/gl/Shader.h>
#include <volsg/render/ShapeRenderer.h>

namespace volsg {

namespace {

constexpr const char* kVertex = R"GLSL(#version 330 core
layout(location = 0) in vec4 aVertex; // pixel x, y; texel u, v
uniform vec2 uViewport;
uniform float uDepth;
out vec2 vTexel;
void main() {
    gl_Position = vec4(aVertex.xy / uViewport * 2.0 - 1.0, uDepth, 1.0);
    vTexel = aVertex.zw;
}
)GLSL";

constexpr const char* kFragment = R"GLSL(#version 330 core
uniform sampler2D uAtlas;
uniform vec4 uColor;
in vec2 vTexel;
out vec4 fragColor;
void main() {
    float coverage = texture(uAtlas, vTexel).r;
    if (coverage <= 0.0) discard;
    fragColor = vec4(uColor.rgb, uColor.a * coverage);
}
)GLSL";

/// Pages hold at most this many textures across all atlases; past it they start again.
constexpr std::size_t kMaxAtlasPages = 32;

int pageSizeFor(int pixelSize) {
    int size = 1024;
    while (size < 4096 && size < 4 * pixelSize)
        size *= 2;
    return size;
}

} // namespace

ScreenTextPlacement placeScreenText(const glm::dmat4& viewProjection, int width, int height,
                                    const glm::dvec3& anchor, double anchorShift) {
    ScreenTextPlacement out;
    const glm::dvec4 clip = viewProjection * glm::dvec4(anchor, 1.0);
    if (!(clip.w > 0.0) || !std::isfinite(clip.w)) return out;
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    // Coin's raster position: valid between the near and far planes only.
    if (!(ndc.z >= -1.0 && ndc.z <= 1.0)) return out;
    out.anchorWindow = {(ndc.x + 1.0) * 0.5 * width, (ndc.y + 1.0) * 0.5 * height};
    const double x = std::floor(out.anchorWindow.x + anchorShift + 0.5);
    const double y = std::floor(out.anchorWindow.y + 0.5);
    if (!(std::abs(x) < 1e8 && std::abs(y) < 1e8)) return out;
    out.origin = {int(x), int(y)};
    out.ndcDepth = ndc.z;
    out.visible = true;
    return out;
}

std::size_t ScreenTextRenderer::atlasPages() const {
    std::size_t n = 0;
    for (const auto& [key, atlas] : atlases_)
        n += atlas.pages.size();
    return n;
}

ScreenTextRenderer::Slot& ScreenTextRenderer::slotFor(Atlas& atlas, const ScreenGlyph& glyph) {
    if (const auto it = atlas.slots.find(glyph.character); it != atlas.slots.end())
        return it->second;
    const int w = glyph.bitmap->width, h = glyph.bitmap->rows;
    Slot slot;
    if (w + 1 > atlas.pageSize || h + 1 > atlas.pageSize) // cannot happen below the size limit
        return atlas.slots.emplace(glyph.character, slot).first->second;
    if (atlas.pages.empty() || atlas.cursor.x + w + 1 > atlas.pageSize) {
        atlas.cursor = {0, atlas.cursor.y + atlas.shelfHeight};
        atlas.shelfHeight = 0;
    }
    if (atlas.pages.empty() || atlas.cursor.y + h + 1 > atlas.pageSize) {
        Texture page(GL_TEXTURE_2D);
        page.image2D(GL_R8, atlas.pageSize, atlas.pageSize, GL_RED, GL_UNSIGNED_BYTE, nullptr);
        page.setFilter(GL_NEAREST, GL_NEAREST);
        atlas.pages.push_back(std::move(page));
        atlas.cursor = {0, 0};
        atlas.shelfHeight = 0;
    }
    slot.page = int(atlas.pages.size()) - 1;
    slot.at = atlas.cursor;
    slot.size = {w, h};
    atlas.pages.back().subImage(slot.at.x, slot.at.y, 0, w, h, 1, GL_RED, GL_UNSIGNED_BYTE,
                                glyph.bitmap->coverage.data());
    atlas.cursor.x += w + 1; // a texel of space between glyphs
    atlas.shelfHeight = std::max(atlas.shelfHeight, h + 1);
    return atlas.slots.emplace(glyph.character, slot).first->second;
}

void ScreenTextRenderer::draw(FrameContext& frame, const ScreenTextDraw& draw) {
    if (!draw.text || draw.text->glyphs.empty() || !(draw.color.a > 0.0f)) return;
    const RenderView& view = frame.view;
    const ScreenTextPlacement place = placeScreenText(
        view.projection * view.view, view.width, view.height, draw.anchor, draw.text->anchorShift);
    if (!place.visible) return;

    if (!program_) {
        const Shader vertex(GL_VERTEX_SHADER, kVertex, "screen text");
        const Shader fragment(GL_FRAGMENT_SHADER, kFragment, "screen text");
        program_ = Program({&vertex, &fragment}, "screen text");
        vertexArray_ = VertexArray::create();
        vertices_ = Buffer(GL_ARRAY_BUFFER);
    }
    if (atlasPages() > kMaxAtlasPages) atlases_.clear(); // bounded: glyphs upload again
    Atlas& atlas = atlases_[{draw.face, draw.text->pixelSize}];
    if (atlas.pages.empty()) atlas.pageSize = pageSizeFor(draw.text->pixelSize);

    // Quads per page, in whole pixels; texel rows run with the bitmap's rows (top first).
    std::vector<std::vector<float>> perPage;
    for (const ScreenGlyph& g : draw.text->glyphs) {
        const int w = g.bitmap->width, h = g.bitmap->rows;
        if (w <= 0 || h <= 0) continue;
        const double x0 = double(place.origin.x) + g.origin.x,
                     y0 = double(place.origin.y) + g.origin.y;
        if (x0 + w < 0.0 || y0 + h < 0.0 || x0 > view.width || y0 > view.height) continue;
        const Slot& slot = slotFor(atlas, g);
        if (slot.page < 0) continue;
        if (perPage.size() <= std::size_t(slot.page)) perPage.resize(std::size_t(slot.page) + 1);
        const float size = float(atlas.pageSize);
        const float u0 = float(slot.at.x) / size, u1 = float(slot.at.x + w) / size;
        const float vTop = float(slot.at.y) / size, vBottom = float(slot.at.y + h) / size;
        const float X0 = float(x0), Y0 = float(y0), X1 = float(x0 + w), Y1 = float(y0 + h);
        perPage[std::size_t(slot.page)].insert(perPage[std::size_t(slot.page)].end(),
                                               {X0, Y0, u0, vBottom, X1, Y0, u1, vBottom,
                                                X1, Y1, u1, vTop,    X0, Y0, u0, vBottom,
                                                X1, Y1, u1, vTop,    X0, Y1, u0, vTop});
    }
    if (perPage.empty()) return;

    frame.shapes.setClipDistances(0); // this program writes no clip distances
    GLint blend[4];
    glGetIntegerv(GL_BLEND_SRC_RGB, &blend[0]);
    glGetIntegerv(GL_BLEND_DST_RGB, &blend[1]);
    glGetIntegerv(GL_BLEND_SRC_ALPHA, &blend[2]);
    glGetIntegerv(GL_BLEND_DST_ALPHA, &blend[3]);
    const GLboolean blendWasOn = glIsEnabled(GL_BLEND);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);

    program_.use();
    program_.set("uViewport", glm::vec2(float(view.width), float(view.height)));
    program_.set("uDepth", float(place.ndcDepth));
    program_.set("uColor", draw.color);
    program_.set("uAtlas", 0);
    vertexArray_.bind();
    for (std::size_t page = 0; page < perPage.size(); ++page) {
        const std::vector<float>& quads = perPage[page];
        if (quads.empty()) continue;
        atlas.pages[page].bind(0);
        vertices_.setData(quads, GL_STREAM_DRAW);
        vertexArray_.setAttribute(0, vertices_, 4);
        glDrawArrays(GL_TRIANGLES, 0, GLsizei(quads.size() / 4));
        frame.shapes.countDraw();
    }
    VertexArray::unbind();
    glBlendFuncSeparate(GLenum(blend[0]), GLenum(blend[1]), GLenum(blend[2]), GLenum(blend[3]));
    if (!blendWasOn) glDisable(GL_BLEND);
}

} // namespace volsg
