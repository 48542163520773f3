#include <volsg/text/Font.h>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_BBOX_H
#include FT_OUTLINE_H

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <optional>
#include <system_error>
#include <unordered_map>

#include <volsg/core/Error.h>

namespace volsg {

namespace fs = std::filesystem;

// ---- font files ----------------------------------------------------------------------------

namespace {

/// Folders where distributions put the DejaVu files (Debian and Ubuntu first).
const char* const kFontFolders[] = {
    "/usr/share/fonts/truetype/dejavu",        // Debian, Ubuntu (fonts-dejavu-core)
    "/usr/share/fonts/dejavu",                 // older Fedora, openSUSE
    "/usr/share/fonts/dejavu-sans-fonts",      // Fedora
    "/usr/share/fonts/dejavu-serif-fonts",     // Fedora
    "/usr/share/fonts/dejavu-sans-mono-fonts", // Fedora
    "/usr/share/fonts/TTF",                    // Arch
    "/usr/share/fonts/truetype",               //
    "/usr/local/share/fonts",                  // FreeBSD, local installs
    "/usr/local/share/fonts/dejavu",           //
    "/usr/share/fonts",                        //
    "/opt/homebrew/share/fonts",               // macOS (Homebrew)
    "/Library/Fonts",                          // macOS
};
/// Searched below, once, when the file is in none of the folders above.
const char* const kFontRoots[] = {"/usr/share/fonts", "/usr/local/share/fonts"};

bool isRegularFile(const fs::path& p) {
    std::error_code ec;
    return fs::is_regular_file(p, ec);
}

std::mutex& fileMutex() {
    static std::mutex m;
    return m;
}

/// Every DejaVu*.ttf below the roots, by file name (found once, depth and count bounded).
const std::map<std::string, std::string>& scannedDejaVuFiles() {
    static const std::map<std::string, std::string> files = [] {
        std::map<std::string, std::string> out;
        std::size_t seen = 0;
        for (const char* root : kFontRoots) {
            std::error_code ec;
            fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied,
                                                ec);
            for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
                if (++seen > 200000) break;
                if (it.depth() > 6) {
                    it.disable_recursion_pending();
                    continue;
                }
                const std::string name = it->path().filename().string();
                if (name.rfind("DejaVu", 0) == 0 && isRegularFile(it->path()))
                    out.emplace(name, it->path().string());
            }
        }
        return out;
    }();
    return files;
}

std::optional<std::string> locate(const std::string& fileName) {
    static std::map<std::string, std::optional<std::string>> cache;
    std::lock_guard lock(fileMutex());
    if (const auto it = cache.find(fileName); it != cache.end()) return it->second;
    std::optional<std::string> found;
    for (const char* folder : kFontFolders) {
        const fs::path p = fs::path(folder) / fileName;
        if (isRegularFile(p)) {
            found = p.string();
            break;
        }
    }
    if (!found) {
        const auto& scanned = scannedDejaVuFiles();
        if (const auto it = scanned.find(fileName); it != scanned.end()) found = it->second;
    }
    cache.emplace(fileName, found);
    return found;
}

std::optional<std::string> locateIn(const std::string& fileName,
                                    std::span<const std::string> folders) {
    for (const std::string& folder : folders) {
        const fs::path p = fs::path(folder) / fileName;
        if (isRegularFile(p)) return p.string();
    }
    return std::nullopt;
}

std::string lowercase(std::string_view s) {
    std::string out(s);
    for (char& c : out)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

bool endsWith(const std::string& s, std::string_view suffix) {
    return s.size() >= suffix.size() &&
           s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

} // namespace

namespace {

/// The font files a name stands for, best first, with whether each needs a synthetic slant.
struct Candidate {
    std::string file;
    bool oblique;
};
std::vector<Candidate> candidatesFor(std::string_view inventorName) {
    const std::string name = lowercase(inventorName);
    enum Family { Sans, Serif, Mono };
    Family family = Sans;
    const auto has = [&name](const char* word) { return name.find(word) != std::string::npos; };
    if (has("courier") || has("mono") || has("fixed") || has("typewriter"))
        family = Mono;
    else if ((has("times") || has("serif")) && !has("sans"))
        family = Serif;
    const bool bold = has("bold");
    const bool italic = has("italic") || has("oblique");
    const std::string base = family == Serif  ? "DejaVuSerif"
                             : family == Mono ? "DejaVuSansMono"
                                              : "DejaVuSans";
    const std::string slant = family == Serif ? "Italic" : "Oblique";
    std::vector<Candidate> out;
    if (bold && italic) out.push_back({base + "-Bold" + slant + ".ttf", false});
    if (bold) out.push_back({base + "-Bold.ttf", italic});
    if (italic && !bold) out.push_back({base + "-" + slant + ".ttf", false});
    out.push_back({base + ".ttf", italic});
    if (family != Sans) out.push_back({"DejaVuSans.ttf", italic});
    return out;
}

std::optional<FontFile> explicitFile(std::string_view inventorName) {
    const std::string name = lowercase(inventorName);
    if ((endsWith(name, ".ttf") || endsWith(name, ".otf") || endsWith(name, ".pfb")) &&
        isRegularFile(fs::path(std::string(inventorName))))
        return FontFile{std::string(inventorName), false};
    return std::nullopt;
}

[[noreturn]] void noFontFile(std::string_view inventorName, const std::vector<Candidate>& tried,
                             const std::string& where) {
    const bool sans = tried.front().file == "DejaVuSans.ttf";
    throw Error("font '" + std::string(inventorName) + "': no font file found (" +
                tried.front().file + (sans ? " is" : " and DejaVuSans.ttf are") + " in none of " +
                where + "; install Debian's fonts-dejavu-core)");
}

} // namespace

FontFile findFontFile(std::string_view inventorName) {
    if (auto file = explicitFile(inventorName)) return *file;
    const std::vector<Candidate> candidates = candidatesFor(inventorName);
    for (const Candidate& c : candidates)
        if (auto path = locate(c.file)) return {*path, c.oblique};
    std::string folders;
    for (const char* folder : kFontFolders)
        folders += std::string(folders.empty() ? "" : ", ") + folder;
    noFontFile(inventorName, candidates, folders + " nor below /usr/share/fonts");
}

FontFile findFontFile(std::string_view inventorName, std::span<const std::string> folders) {
    if (auto file = explicitFile(inventorName)) return *file;
    const std::vector<Candidate> candidates = candidatesFor(inventorName);
    for (const Candidate& c : candidates)
        if (auto path = locateIn(c.file, folders)) return {*path, c.oblique};
    std::string list;
    for (const std::string& folder : folders)
        list += (list.empty() ? "" : ", ") + folder;
    noFontFile(inventorName, candidates, list.empty() ? std::string("no folder") : list);
}

// ---- FreeType ------------------------------------------------------------------------------

namespace {

FT_Library library() {
    static FT_Library lib = [] {
        FT_Library l = nullptr;
        if (FT_Init_FreeType(&l) != 0) throw Error("FreeType could not be initialised");
        return l; // kept for the process's life: faces may be used during exit
    }();
    return lib;
}

/// FreeType's synthetic oblique (FT_GlyphSlot_Oblique): x += 0.2126 y.
const FT_Matrix kShear{0x10000, 0x0366A, 0, 0x10000};

struct OutlineBuilder {
    GlyphOutline* out = nullptr;
    double scale = 1.0;
    glm::dvec2 at(const FT_Vector* v) const {
        return glm::dvec2(double(v->x), double(v->y)) * scale;
    }
};

int moveTo(const FT_Vector* to, void* user) {
    auto& b = *static_cast<OutlineBuilder*>(user);
    b.out->contours.push_back({b.at(to), {}});
    return 0;
}
int lineTo(const FT_Vector* to, void* user) {
    auto& b = *static_cast<OutlineBuilder*>(user);
    if (b.out->contours.empty()) return 1;
    b.out->contours.back().segments.push_back({1, {}, {}, b.at(to)});
    return 0;
}
int conicTo(const FT_Vector* control, const FT_Vector* to, void* user) {
    auto& b = *static_cast<OutlineBuilder*>(user);
    if (b.out->contours.empty()) return 1;
    b.out->contours.back().segments.push_back({2, b.at(control), {}, b.at(to)});
    return 0;
}
int cubicTo(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
    auto& b = *static_cast<OutlineBuilder*>(user);
    if (b.out->contours.empty()) return 1;
    b.out->contours.back().segments.push_back({3, b.at(c1), b.at(c2), b.at(to)});
    return 0;
}

struct BitmapKey {
    char32_t character;
    int size;
    bool operator<(const BitmapKey& o) const {
        return character != o.character ? character < o.character : size < o.size;
    }
};

} // namespace

struct FontFace::Impl {
    FT_Face face = nullptr;
    std::unordered_map<char32_t, std::shared_ptr<const GlyphOutline>> outlines;
    std::map<BitmapKey, std::shared_ptr<const GlyphBitmap>> bitmaps;
    int pixelSize = 0; ///< set on the face now (0: none)

    ~Impl() {
        if (face) FT_Done_Face(face);
    }
    void setPixelSize(int size) {
        if (pixelSize == size) return;
        if (FT_Set_Pixel_Sizes(face, 0, FT_UInt(size)) != 0)
            throw Error("font '" + std::string(face->family_name ? face->family_name : "?") +
                        "': cannot be drawn at " + std::to_string(size) + " pixels");
        pixelSize = size;
    }
};

FontFace::FontFace(FontFile file) : file_(std::move(file)), impl_(std::make_unique<Impl>()) {}
FontFace::~FontFace() = default;

std::shared_ptr<FontFace> FontFace::open(const FontFile& file) {
    static std::map<std::pair<std::string, bool>, std::shared_ptr<FontFace>> faces;
    std::lock_guard lock(fileMutex());
    const auto key = std::make_pair(file.path, file.synthesizeOblique);
    if (const auto it = faces.find(key); it != faces.end()) return it->second;
    std::shared_ptr<FontFace> face(new FontFace(file));
    if (FT_New_Face(library(), file.path.c_str(), 0, &face->impl_->face) != 0 || !face->impl_->face)
        throw Error(file.path + ": FreeType cannot read this font file");
    if (!FT_IS_SCALABLE(face->impl_->face) || face->impl_->face->units_per_EM == 0)
        throw Error(file.path + ": not a scalable (outline) font");
    FT_Select_Charmap(face->impl_->face, FT_ENCODING_UNICODE);
    faces.emplace(key, face);
    return face;
}

std::shared_ptr<const GlyphOutline> FontFace::outline(char32_t character) {
    std::lock_guard lock(mutex_);
    if (const auto it = impl_->outlines.find(character); it != impl_->outlines.end())
        return it->second;
    FT_Face face = impl_->face;
    auto glyph = std::make_shared<GlyphOutline>();
    const FT_UInt index = FT_Get_Char_Index(face, FT_ULong(character));
    if (FT_Load_Glyph(face, index, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) ==
            0 &&
        face->glyph->format == FT_GLYPH_FORMAT_OUTLINE) {
        const double scale = 1.0 / double(face->units_per_EM);
        FT_Outline* outline = &face->glyph->outline;
        if (file_.synthesizeOblique) FT_Outline_Transform(outline, &kShear);
        OutlineBuilder builder{glyph.get(), scale};
        FT_Outline_Funcs funcs{};
        funcs.move_to = &moveTo;
        funcs.line_to = &lineTo;
        funcs.conic_to = &conicTo;
        funcs.cubic_to = &cubicTo;
        if (FT_Outline_Decompose(outline, &funcs, &builder) != 0) glyph->contours.clear();
        glyph->evenOddFill = (outline->flags & FT_OUTLINE_EVEN_ODD_FILL) != 0;
        glyph->filledOnRight = FT_Outline_Get_Orientation(outline) != FT_ORIENTATION_POSTSCRIPT;
        glyph->advance = double(face->glyph->metrics.horiAdvance) * scale;
        FT_BBox box;
        if (outline->n_points > 0 && FT_Outline_Get_BBox(outline, &box) == 0) {
            glyph->bboxMin = glm::dvec2(double(box.xMin), double(box.yMin)) * scale;
            glyph->bboxMax = glm::dvec2(double(box.xMax), double(box.yMax)) * scale;
        }
    }
    impl_->outlines.emplace(character, glyph);
    return glyph;
}

double FontFace::kerning(char32_t left, char32_t right) {
    std::lock_guard lock(mutex_);
    FT_Face face = impl_->face;
    if (!FT_HAS_KERNING(face)) return 0.0;
    FT_Vector delta{0, 0};
    if (FT_Get_Kerning(face, FT_Get_Char_Index(face, FT_ULong(left)),
                       FT_Get_Char_Index(face, FT_ULong(right)), FT_KERNING_UNSCALED, &delta) != 0)
        return 0.0;
    return double(delta.x) / double(face->units_per_EM);
}

std::shared_ptr<const GlyphBitmap> FontFace::bitmap(char32_t character, int pixelSize) {
    std::lock_guard lock(mutex_);
    const BitmapKey key{character, pixelSize};
    if (const auto it = impl_->bitmaps.find(key); it != impl_->bitmaps.end()) return it->second;
    if (impl_->bitmaps.size() > 65536) impl_->bitmaps.clear(); // bounded: rebuilt on demand
    impl_->setPixelSize(pixelSize);
    FT_Face face = impl_->face;
    auto glyph = std::make_shared<GlyphBitmap>();
    const FT_UInt index = FT_Get_Char_Index(face, FT_ULong(character));
    const FT_Int32 flags =
        file_.synthesizeOblique ? FT_LOAD_DEFAULT | FT_LOAD_NO_BITMAP : FT_LOAD_DEFAULT;
    if (FT_Load_Glyph(face, index, flags) == 0) {
        FT_GlyphSlot slot = face->glyph;
        if (file_.synthesizeOblique && slot->format == FT_GLYPH_FORMAT_OUTLINE)
            FT_Outline_Transform(&slot->outline, &kShear);
        glyph->advance = int(slot->advance.x / 64);
        if (FT_Render_Glyph(slot, FT_RENDER_MODE_NORMAL) == 0) {
            const FT_Bitmap& bm = slot->bitmap;
            glyph->width = int(bm.width);
            glyph->rows = int(bm.rows);
            glyph->left = slot->bitmap_left;
            glyph->top = slot->bitmap_top;
            glyph->coverage.resize(std::size_t(bm.width) * bm.rows);
            for (unsigned y = 0; y < bm.rows; ++y) {
                const unsigned char* row =
                    bm.buffer + (bm.pitch >= 0 ? std::ptrdiff_t(y) * bm.pitch
                                               : std::ptrdiff_t(bm.rows - 1 - y) * -bm.pitch);
                for (unsigned x = 0; x < bm.width; ++x) {
                    std::uint8_t v = 0;
                    if (bm.pixel_mode == FT_PIXEL_MODE_GRAY)
                        v = std::uint8_t(bm.num_grays == 256
                                             ? row[x]
                                             : row[x] * 255 / std::max(1, bm.num_grays - 1));
                    else if (bm.pixel_mode == FT_PIXEL_MODE_MONO)
                        v = (row[x / 8] & (0x80 >> (x % 8))) ? 255 : 0;
                    glyph->coverage[std::size_t(y) * bm.width + x] = v;
                }
            }
        }
    }
    impl_->bitmaps.emplace(key, glyph);
    return glyph;
}

int FontFace::kerningPixels(char32_t left, char32_t right, int pixelSize) {
    std::lock_guard lock(mutex_);
    FT_Face face = impl_->face;
    if (!FT_HAS_KERNING(face)) return 0;
    impl_->setPixelSize(pixelSize);
    FT_Vector delta{0, 0};
    if (FT_Get_Kerning(face, FT_Get_Char_Index(face, FT_ULong(left)),
                       FT_Get_Char_Index(face, FT_ULong(right)), FT_KERNING_DEFAULT, &delta) != 0)
        return 0;
    return int(delta.x / 64);
}

// ---- outlines ------------------------------------------------------------------------------

std::vector<std::vector<glm::dvec2>> GlyphOutline::flatten(int steps) const {
    steps = std::max(1, steps);
    std::vector<std::vector<glm::dvec2>> out;
    out.reserve(contours.size());
    for (const Contour& c : contours) {
        std::vector<glm::dvec2> poly;
        poly.push_back(c.start);
        glm::dvec2 from = c.start;
        for (const Segment& s : c.segments) {
            if (s.degree >= 2)
                for (int i = 1; i < steps; ++i) {
                    const double t = double(i) / double(steps), r = 1.0 - t;
                    poly.push_back(s.degree == 2 ? r * r * from + 2.0 * r * t * s.c1 + t * t * s.to
                                                 : r * r * r * from + 3.0 * r * r * t * s.c1 +
                                                       3.0 * r * t * t * s.c2 + t * t * t * s.to);
                }
            poly.push_back(s.to);
            from = s.to;
        }
        // Drop repeated points and the closing point (it is the start again).
        std::vector<glm::dvec2> clean;
        clean.reserve(poly.size());
        for (const glm::dvec2& p : poly)
            if (clean.empty() || clean.back() != p) clean.push_back(p);
        while (clean.size() > 1 && clean.back() == clean.front())
            clean.pop_back();
        if (clean.size() >= 3) out.push_back(std::move(clean));
    }
    return out;
}

std::u32string decodeUtf8(std::string_view text) {
    std::u32string out;
    out.reserve(text.size());
    const auto* s = reinterpret_cast<const unsigned char*>(text.data());
    const std::size_t n = text.size();
    static constexpr char32_t minimum[4] = {0, 0x80, 0x800, 0x10000};
    for (std::size_t i = 0; i < n;) {
        const unsigned char c = s[i];
        std::size_t extra = 0;
        char32_t cp = c;
        if (c < 0x80) {
            out.push_back(c);
            ++i;
            continue;
        }
        if ((c & 0xE0) == 0xC0) {
            extra = 1;
            cp = c & 0x1F;
        } else if ((c & 0xF0) == 0xE0) {
            extra = 2;
            cp = c & 0x0F;
        } else if ((c & 0xF8) == 0xF0) {
            extra = 3;
            cp = c & 0x07;
        }
        bool ok = extra > 0 && i + extra < n;
        for (std::size_t k = 1; ok && k <= extra; ++k) {
            const unsigned char cc = s[i + k];
            if ((cc & 0xC0) != 0x80) ok = false;
            cp = (cp << 6) | (cc & 0x3F);
        }
        if (!ok || cp < minimum[extra] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) {
            out.push_back(0xFFFD); // a malformed byte: skip it alone
            ++i;
            continue;
        }
        out.push_back(cp);
        i += extra + 1;
    }
    return out;
}

} // namespace volsg
