#pragma once
// Fonts for Inventor's text nodes, from FreeType and the DejaVu faces (Debian's
// fonts-dejavu-core): Inventor and Coin font names map to a DejaVu file found at run time, its
// glyphs give outlines in em units (Text3, AsciiText) and antialiased bitmaps at pixel sizes
// (Text2). FreeType stays inside the .cpp.

#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace volsg {

/// The font file an Inventor font name stands for.
struct FontFile {
    std::string path;
    /// The name asked for an italic face the system does not have: the upright face is
    /// slanted instead (as FreeType's FT_GlyphSlot_Oblique, by 0.2 of the height).
    bool synthesizeOblique = false;
};

/// Maps a font name as Inventor and Coin write it to a DejaVu face:
/// - "Times-Roman", "Times", any name with "Times" or "Serif" (but not "Sans"): DejaVu Serif;
///   "Courier", names with "Courier", "Mono" or "Fixed": DejaVu Sans Mono; anything else
///   ("defaultFont", "Helvetica", "Arial", ...): DejaVu Sans.
/// - "Bold" anywhere in the name: the bold face; "Italic" or "Oblique": the italic or oblique
///   face (Coin's "Family:Bold Italic" style suffix reads the same way).
/// - A name ending in ".ttf", ".otf" or ".pfb" that names an existing file is that file.
/// The files are looked for in the usual font folders (/usr/share/fonts/truetype/dejavu,
/// /usr/share/fonts/dejavu, /usr/share/fonts/TTF, /usr/local/share/fonts, ...) and then, once,
/// anywhere below /usr/share/fonts and /usr/local/share/fonts. A face that is missing falls
/// back to its family's regular face, then to DejaVu Sans. Throws Error (one line) when no
/// DejaVu file is found at all.
FontFile findFontFile(std::string_view inventorName);
/// The same mapping, looking only in `folders` (no search below them): for tests and for
/// programs that ship their own fonts.
FontFile findFontFile(std::string_view inventorName, std::span<const std::string> folders);

/// One glyph's outline in em units (1 = the font's em square), unhinted: closed contours of
/// line, conic and cubic segments as FreeType decomposes them.
struct GlyphOutline {
    struct Segment {
        int degree = 1;     ///< 1 line, 2 conic, 3 cubic
        glm::dvec2 c1{0.0}; ///< first control point (conic, cubic)
        glm::dvec2 c2{0.0}; ///< second control point (cubic)
        glm::dvec2 to{0.0}; ///< end point
    };
    struct Contour {
        glm::dvec2 start{0.0};
        std::vector<Segment> segments;
    };
    std::vector<Contour> contours;
    bool evenOddFill = false;  ///< FT_OUTLINE_EVEN_ODD_FILL; otherwise non-zero winding
    bool filledOnRight = true; ///< TrueType orientation: the filled area lies right of travel
    double advance = 0.0;      ///< horizontal advance, em
    glm::dvec2 bboxMin{0.0}, bboxMax{0.0}; ///< exact box of the outline (FT_Outline_Get_BBox), em

    /// The contours as polygons: each conic and cubic cut into `steps` equal parameter steps
    /// (Coin: 16 x Complexity), the closing point not repeated.
    std::vector<std::vector<glm::dvec2>> flatten(int steps) const;
};

/// A glyph rendered for Text2: 8-bit coverage, row 0 at the top.
struct GlyphBitmap {
    int width = 0, rows = 0;
    int left = 0;    ///< from the pen to the bitmap's left edge, pixels
    int top = 0;     ///< from the baseline up to the bitmap's top row, pixels
    int advance = 0; ///< pixels (FreeType's hinted advance, truncated as Coin does)
    std::vector<std::uint8_t> coverage;
};

/// An open font file. Thread-safe (one lock per face); glyphs are cached.
class FontFace {
public:
    /// The face for `file`, opened once per process and kept. Throws Error naming the file if
    /// FreeType cannot open it.
    static std::shared_ptr<FontFace> open(const FontFile& file);
    ~FontFace();
    FontFace(const FontFace&) = delete;
    FontFace& operator=(const FontFace&) = delete;

    const std::string& path() const { return file_.path; }
    bool synthesizedOblique() const { return file_.synthesizeOblique; }

    /// The outline of the character (the .notdef glyph for one the font lacks).
    std::shared_ptr<const GlyphOutline> outline(char32_t character);
    /// Kerning between two characters, em (FreeType's FT_KERNING_UNSCALED over units per em).
    double kerning(char32_t left, char32_t right);

    /// The character rendered at `pixelSize` pixels per em (hinted, antialiased).
    std::shared_ptr<const GlyphBitmap> bitmap(char32_t character, int pixelSize);
    /// Kerning at `pixelSize`, whole pixels (truncated, as Coin).
    int kerningPixels(char32_t left, char32_t right, int pixelSize);

    struct Impl;

private:
    explicit FontFace(FontFile file);
    FontFile file_;
    std::unique_ptr<Impl> impl_;
    std::mutex mutex_;
};

/// Decodes UTF-8 (Inventor strings); a malformed byte becomes U+FFFD.
std::u32string decodeUtf8(std::string_view text);

} // namespace volsg
