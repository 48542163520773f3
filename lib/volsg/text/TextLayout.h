#pragma once
// Text laid out from a font: Inventor's 3D text (SoText3, SoAsciiText) as a triangle mesh in
// object units, and its screen text (SoText2) as glyph bitmaps placed in pixels. Positions
// follow Coin: the origin is on the baseline of the first line, lines go down by
// spacing x size, and each line is aligned on the origin by the justification.

#include <array>
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/geometry/Mesh.h>
#include <volsg/text/Font.h>

namespace volsg {

enum class TextJustification { Left, Right, Center };

/// Most characters one text node lays out (all its strings together).
inline constexpr std::size_t kMaxTextCharacters = std::size_t(1) << 20;
/// Most vertices of one 3D text mesh, counted before anything is allocated: 2^22, a mesh of
/// about 200 MB with its indices and GPU copy (2^24 let one fuzz-found Text3 take 2 GB).
inline constexpr std::size_t kMaxTextVertices = std::size_t(1) << 22;

/// What a 3D text node asks for.
struct TextMeshDescription {
    std::span<const std::string> strings;
    double size = 10.0;   ///< the em square, object units (Font size)
    double spacing = 1.0; ///< baseline to baseline, in sizes
    TextJustification justification = TextJustification::Left;
    bool front = true, sides = false, back = false;
    int curveSteps = 8; ///< per conic or cubic piece of an outline (Coin: 16 x Complexity)
    /// The bevel profile (Text3 with profiles in scope): points (x, y) where x is the depth
    /// (z = -x) and y the distance out from the outline. Empty: Coin's plain extrusion from
    /// z = 0 to z = -1 (one object unit, whatever the size).
    std::span<const glm::dvec2> profile;
    /// Side normals are smoothed across outline (and profile) corners up to this angle.
    double creaseAngle = 0.0;
    /// AsciiText: line i is stretched to widths[i] when that is > 0 (the pen positions scale,
    /// the glyphs keep their shape).
    std::span<const float> widths;
    bool textureCoords = false; ///< (x, y) / size, as Coin
    /// Per-part colours (front, sides, back) as vertex colours; unset: the material's.
    bool partColors = false;
    std::array<glm::vec4, 3> colors{glm::vec4(1.0f), glm::vec4(1.0f), glm::vec4(1.0f)};
};

/// The mesh of the text: front faces at z = -profile[0].x (0 without a profile) facing +z,
/// back faces at z = -profile.back().x (-1 without) facing -z, both the glyphs' outlines
/// triangulated with their holes by the font's fill rule (GLU's tessellator), and the sides
/// swept along the profile with outward normals. Throws Error past kMaxTextCharacters or
/// kMaxTextVertices, or for a size that is not finite.
void buildTextMesh(FontFace& face, const TextMeshDescription& text, Mesh& out);

/// The width of each line of 3D text in object units (advances and kerning; the last glyph's
/// ink past its advance counts, as Coin), before stretching.
std::vector<double> textLineWidths(FontFace& face, std::span<const std::string> strings,
                                   double size);

/// Screen text (SoText2) in pixels, y up, relative to the anchor pixel.
struct ScreenGlyph {
    std::shared_ptr<const GlyphBitmap> bitmap;
    char32_t character = 0;
    glm::ivec2 origin{0}; ///< the bitmap's bottom-left pixel
};
struct ScreenText {
    std::vector<ScreenGlyph> glyphs;
    /// Added to the projected anchor's x before it is rounded to a pixel: 0 for LEFT, the
    /// widest line's width negated for RIGHT, half of it for CENTER (Coin's placement).
    double anchorShift = 0.0;
    glm::ivec2 boxMin{0}, boxMax{0}; ///< every glyph's pixels (exclusive max); empty if equal
    std::vector<int> lineWidths;     ///< advances and kerning of each line, pixels
    int pixelSize = 0;
};
/// Lays out the strings at `pixelSize` pixels per em: glyph i of a line at the pen plus its
/// kerning and bitmap offset, the pen moving by whole-pixel advances, line k's baseline
/// k x int(pixelSize x spacing) pixels down. Throws Error past kMaxTextCharacters.
ScreenText layoutScreenText(FontFace& face, std::span<const std::string> strings, int pixelSize,
                            double spacing, TextJustification justification);

} // namespace volsg
