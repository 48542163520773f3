#pragma once
// Draws screen-aligned text (Inventor's SoText2) into the frame: glyph quads of whole pixels
// from glyph atlases (8-bit coverage textures), at the depth of the text's anchor point.

#include <cstdint>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/gl/Buffer.h>
#include <volsg/gl/Program.h>
#include <volsg/gl/Texture.h>
#include <volsg/gl/VertexArray.h>
#include <volsg/render/FrameContext.h>
#include <volsg/text/TextLayout.h>

namespace volsg {

/// One text to draw.
struct ScreenTextDraw {
    glm::dvec3 anchor{0.0}; ///< world position of the text's origin
    /// Colour and opacity: coverage x alpha is blended over the frame (Coin draws SoText2 in
    /// the diffuse colour of the material in scope, unlit).
    glm::vec4 color{1.0f};
    const ScreenText* text = nullptr;
    const FontFace* face = nullptr; ///< what the glyph bitmaps came from (the atlas key)
};

/// Where a text lands in the viewport: the pixel the layout's origin maps to (window
/// coordinates, y up), and the anchor's window depth. Not `visible` when the anchor is behind
/// the eye or outside the near and far planes (as Coin's raster position, nothing is drawn).
struct ScreenTextPlacement {
    bool visible = false;
    glm::ivec2 origin{0};
    double ndcDepth = 0.0;
    glm::dvec2 anchorWindow{0.0}; ///< the projected anchor, before rounding
};
ScreenTextPlacement placeScreenText(const glm::dmat4& viewProjection, int width, int height,
                                    const glm::dvec3& anchor, double anchorShift);

/// One per GL context (RenderCache::shared): the program, the atlases and the vertex buffer.
/// Draws in the Opaque pass with the depth test of the pass and depth writes on, blending the
/// glyph coverage (texels with no coverage are discarded); restores blending off.
class ScreenTextRenderer {
public:
    void draw(FrameContext& frame, const ScreenTextDraw& draw);
    std::size_t atlasPages() const; ///< textures the atlases hold now

private:
    struct Slot {
        int page = -1;
        glm::ivec2 at{0}, size{0};
    };
    struct Atlas {
        int pageSize = 1024;
        std::vector<Texture> pages;
        glm::ivec2 cursor{0}; ///< next free place on the last page's current shelf
        int shelfHeight = 0;
        std::map<char32_t, Slot> slots;
    };
    Slot& slotFor(Atlas& atlas, const ScreenGlyph& glyph);

    Program program_;
    VertexArray vertexArray_;
    Buffer vertices_;
    std::map<std::pair<const FontFace*, int>, Atlas> atlases_;
    std::vector<float> scratch_;
};

} // namespace volsg
