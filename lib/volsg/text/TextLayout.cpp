#include <volsg/text/TextLayout.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include <volsg/core/Error.h>
#include <volsg/geometry/PolygonTessellator.h>

namespace volsg {

namespace {

std::vector<std::u32string> decodeLines(std::span<const std::string> strings) {
    std::size_t bytes = 0;
    for (const std::string& s : strings)
        bytes += s.size();
    if (bytes > kMaxTextCharacters)
        throw Error("text of " + std::to_string(bytes) + " bytes exceeds the limit of " +
                    std::to_string(kMaxTextCharacters) + " characters");
    std::vector<std::u32string> lines;
    lines.reserve(strings.size());
    for (const std::string& s : strings)
        lines.push_back(decodeUtf8(s));
    return lines;
}

/// One character's geometry at the build's curve steps, in em units.
struct GlyphGeometry {
    std::shared_ptr<const GlyphOutline> outline;
    std::vector<std::vector<glm::dvec2>> contours;
    Triangulation face;
};

/// Unit outward normal of edge a -> b of a contour whose filled area is on `filledOnRight`.
glm::dvec2 outwardNormal(glm::dvec2 a, glm::dvec2 b, bool filledOnRight) {
    const glm::dvec2 d = b - a;
    const double len = glm::length(d);
    if (!(len > 0.0)) return glm::dvec2(0.0);
    const glm::dvec2 left(-d.y / len, d.x / len);
    return filledOnRight ? left : -left;
}

double angleBetween(glm::dvec2 a, glm::dvec2 b) {
    return std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
}

glm::dvec2 smoothed(glm::dvec2 a, glm::dvec2 b, double crease, glm::dvec2 flat) {
    const glm::dvec2 sum = a + b;
    if (angleBetween(a, b) <= crease && glm::length(sum) > 1e-12) return glm::normalize(sum);
    return flat;
}

/// Accumulates the mesh; every part has its own vertices (its own normals).
struct Emitter {
    Mesh& mesh;
    const TextMeshDescription& text;
    std::size_t vertex(glm::dvec3 p, glm::dvec3 n, int part) {
        mesh.positions.emplace_back(p);
        mesh.normals.emplace_back(n);
        if (text.partColors) mesh.colors.push_back(text.colors[std::size_t(part)]);
        if (text.textureCoords) mesh.texCoords.emplace_back(glm::dvec2(p) / text.size);
        return mesh.positions.size() - 1;
    }
    void triangle(std::size_t a, std::size_t b, std::size_t c) {
        mesh.indices.insert(mesh.indices.end(),
                            {std::uint32_t(a), std::uint32_t(b), std::uint32_t(c)});
    }
};

} // namespace

std::vector<double> textLineWidths(FontFace& face, std::span<const std::string> strings,
                                   double size) {
    const std::vector<std::u32string> lines = decodeLines(strings);
    std::vector<double> widths;
    widths.reserve(lines.size());
    for (const std::u32string& line : lines) {
        double w = 0.0;
        std::shared_ptr<const GlyphOutline> last;
        for (std::size_t k = 0; k < line.size(); ++k) {
            if (k > 0) w += face.kerning(line[k - 1], line[k]);
            last = face.outline(line[k]);
            w += last->advance;
        }
        // Italic glyphs may end past their advance: their ink counts (Coin's setUpGlyphs).
        if (last && last->bboxMax.x > last->advance) w += last->bboxMax.x - last->advance;
        widths.push_back(w * size);
    }
    return widths;
}

void buildTextMesh(FontFace& face, const TextMeshDescription& text, Mesh& out) {
    out = Mesh{};
    if (!std::isfinite(text.size) || !std::isfinite(text.spacing))
        throw Error("the font size and spacing must be finite numbers");
    if (std::abs(text.size) > 1e15 || std::abs(text.spacing) > 1e15)
        throw Error("font size " + std::to_string(text.size) + " x spacing " +
                    std::to_string(text.spacing) + " is beyond 1e15 object units");
    if (!(text.size > 0.0) || !(text.front || text.sides || text.back)) return;
    const std::vector<std::u32string> lines = decodeLines(text.strings);
    const int steps = std::clamp(text.curveSteps, 1, 64);

    // The profile: (depth, offset) from the front to the back; Coin's extrusion without one.
    std::vector<glm::dvec2> profile(text.profile.begin(), text.profile.end());
    if (profile.empty()) profile = {{0.0, 0.0}, {1.0, 0.0}};
    for (const glm::dvec2& p : profile)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || std::abs(p.x) > 1e15 ||
            std::abs(p.y) > 1e15)
            throw Error("a profile coordinate is not a finite number below 1e15");
    const double nearZ = -profile.front().x, farZ = -profile.back().x;
    std::vector<std::size_t> segments; // profile segments with a length
    for (std::size_t j = 0; j + 1 < profile.size(); ++j)
        if (profile[j + 1] != profile[j]) segments.push_back(j);

    // Each character once: its outline flattened and its face triangulated.
    std::unordered_map<char32_t, GlyphGeometry> glyphs;
    double vertices = 0.0;
    for (const std::u32string& line : lines)
        for (const char32_t c : line) {
            auto [it, added] = glyphs.try_emplace(c);
            GlyphGeometry& g = it->second;
            if (added) {
                g.outline = face.outline(c);
                g.contours = g.outline->flatten(steps);
                if ((text.front || text.back) &&
                    !triangulatePolygons(
                        g.contours,
                        g.outline->evenOddFill ? WindingRule::Odd : WindingRule::NonZero, g.face))
                    g.face = {};
            }
            double n = 0.0;
            if (text.front) n += double(g.face.points.size());
            if (text.back) n += double(g.face.points.size());
            if (text.sides)
                for (const auto& contour : g.contours)
                    n += 4.0 * double(contour.size()) * double(segments.size());
            vertices += n;
            if (vertices > double(kMaxTextVertices))
                throw Error("the text's mesh would have more than " +
                            std::to_string(kMaxTextVertices) + " vertices");
        }
    out.positions.reserve(std::size_t(vertices));
    out.normals.reserve(std::size_t(vertices));

    std::vector<double> widths = textLineWidths(face, text.strings, 1.0);
    Emitter emit{out, text};
    const double size = text.size;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::u32string& line = lines[i];
        double width = widths[i] * size, stretch = 1.0;
        if (i < text.widths.size() && text.widths[i] > 0.0f && width > 0.0 && !line.empty()) {
            stretch = double(text.widths[i]) / width;
            width = double(text.widths[i]);
        }
        double x = text.justification == TextJustification::Right    ? -width
                   : text.justification == TextJustification::Center ? -0.5 * width
                                                                     : 0.0;
        const double y = -double(i) * size * text.spacing;
        for (std::size_t k = 0; k < line.size(); ++k) {
            if (k > 0) x += face.kerning(line[k - 1], line[k]) * size * stretch;
            const GlyphGeometry& g = glyphs.at(line[k]);
            const glm::dvec2 pen(x, y);
            auto place = [&](glm::dvec2 em) { return pen + em * size; };

            if (text.front || text.back) {
                for (const int part : {0, 2}) {
                    if ((part == 0 && !text.front) || (part == 2 && !text.back)) continue;
                    const double z = part == 0 ? nearZ : farZ;
                    const glm::dvec3 normal(0.0, 0.0, part == 0 ? 1.0 : -1.0);
                    const std::size_t first = out.positions.size();
                    for (const glm::dvec2& p : g.face.points)
                        emit.vertex(glm::dvec3(place(p), z), normal, part);
                    for (std::size_t t = 0; t + 2 < g.face.triangles.size(); t += 3) {
                        const std::size_t a = first + g.face.triangles[t],
                                          b = first + g.face.triangles[t + 1],
                                          c = first + g.face.triangles[t + 2];
                        if (part == 0)
                            emit.triangle(a, b, c);
                        else
                            emit.triangle(a, c, b);
                    }
                }
            }

            if (text.sides && !segments.empty()) {
                for (const auto& contour : g.contours) {
                    const std::size_t m = contour.size();
                    std::vector<glm::dvec2> normals(m), miters(m);
                    for (std::size_t e = 0; e < m; ++e)
                        normals[e] = outwardNormal(contour[e], contour[(e + 1) % m],
                                                   g.outline->filledOnRight);
                    for (std::size_t v = 0; v < m; ++v) {
                        const glm::dvec2 before = normals[(v + m - 1) % m], after = normals[v];
                        const glm::dvec2 sum = before + after;
                        if (glm::length(sum) < 1e-9) {
                            miters[v] = after;
                            continue;
                        }
                        const glm::dvec2 dir = glm::normalize(sum);
                        miters[v] = dir / std::max(glm::dot(dir, after), 0.5);
                    }
                    for (std::size_t e = 0; e < m; ++e) {
                        const std::size_t a = e, b = (e + 1) % m;
                        const glm::dvec2 n = normals[e];
                        const glm::dvec2 na =
                            smoothed(normals[(e + m - 1) % m], n, text.creaseAngle, n);
                        const glm::dvec2 nb = smoothed(n, normals[b], text.creaseAngle, n);
                        for (std::size_t s = 0; s < segments.size(); ++s) {
                            const std::size_t j = segments[s];
                            const glm::dvec2 p0 = profile[j], p1 = profile[j + 1];
                            const glm::dvec2 q = glm::normalize(p1 - p0);
                            glm::dvec2 q0 = q, q1 = q;
                            if (s > 0 && segments[s - 1] + 1 == j)
                                q0 = smoothed(glm::normalize(profile[j] - profile[j - 1]), q,
                                              text.creaseAngle, q);
                            if (s + 1 < segments.size() && segments[s + 1] == j + 1)
                                q1 = smoothed(q, glm::normalize(profile[j + 2] - profile[j + 1]),
                                              text.creaseAngle, q);
                            auto point = [&](std::size_t v, glm::dvec2 prof) {
                                return glm::dvec3(place(contour[v] + prof.y / size * miters[v]),
                                                  -prof.x);
                            };
                            auto normal = [](glm::dvec2 outline, glm::dvec2 prof) {
                                const glm::dvec3 v(prof.x * outline, prof.y);
                                const double len = glm::length(v);
                                return len > 0.0 ? v / len : glm::dvec3(outline, 0.0);
                            };
                            const glm::dvec3 A = point(a, p0), B = point(b, p0), C = point(b, p1),
                                             D = point(a, p1);
                            const std::size_t ia = emit.vertex(A, normal(na, q0), 1),
                                              ib = emit.vertex(B, normal(nb, q0), 1),
                                              ic = emit.vertex(C, normal(nb, q1), 1),
                                              id = emit.vertex(D, normal(na, q1), 1);
                            const glm::dvec3 facing = normal(n, q);
                            const glm::dvec3 geometric =
                                glm::cross(B - A, C - A) + glm::cross(C - A, D - A);
                            if (glm::dot(geometric, facing) >= 0.0) {
                                emit.triangle(ia, ib, ic);
                                emit.triangle(ia, ic, id);
                            } else {
                                emit.triangle(ia, ic, ib);
                                emit.triangle(ia, id, ic);
                            }
                        }
                    }
                }
            }
            x += g.outline->advance * size * stretch;
        }
    }
}

ScreenText layoutScreenText(FontFace& face, std::span<const std::string> strings, int pixelSize,
                            double spacing, TextJustification justification) {
    ScreenText out;
    out.pixelSize = pixelSize;
    const std::vector<std::u32string> lines = decodeLines(strings);
    if (!std::isfinite(spacing)) throw Error("the text spacing must be a finite number");
    const double step = double(pixelSize) * spacing;
    if (std::abs(step) * double(lines.size()) > 1e7)
        throw Error("lines spaced " + std::to_string(step) + " pixels apart are beyond the screen");
    const int lineStep = int(step);

    // Pen positions per line first (widths decide the justification).
    struct Placed {
        std::shared_ptr<const GlyphBitmap> bitmap;
        char32_t character;
        int x, y;
    };
    std::vector<std::vector<Placed>> placed(lines.size());
    int maxWidth = 0;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        int pen = 0;
        const int y = -int(i) * lineStep;
        for (std::size_t k = 0; k < lines[i].size(); ++k) {
            const char32_t c = lines[i][k];
            auto bitmap = face.bitmap(c, pixelSize);
            const int kerning = k > 0 ? face.kerningPixels(lines[i][k - 1], c, pixelSize) : 0;
            const int x = pen + kerning + bitmap->left;
            placed[i].push_back({bitmap, c, x, y + bitmap->top - bitmap->rows});
            pen += bitmap->advance + kerning;
        }
        out.lineWidths.push_back(pen);
        maxWidth = std::max(maxWidth, pen);
    }
    out.anchorShift = justification == TextJustification::Right    ? -double(maxWidth)
                      : justification == TextJustification::Center ? -0.5 * double(maxWidth)
                                                                   : 0.0;
    bool any = false;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const int lineStart =
            justification == TextJustification::Right    ? maxWidth - out.lineWidths[i]
            : justification == TextJustification::Center ? (maxWidth - out.lineWidths[i]) / 2
                                                         : 0;
        for (const Placed& p : placed[i]) {
            ScreenGlyph g;
            g.bitmap = p.bitmap;
            g.character = p.character;
            g.origin = {lineStart + p.x, p.y};
            if (p.bitmap->width > 0 && p.bitmap->rows > 0) {
                const glm::ivec2 lo = g.origin,
                                 hi = g.origin + glm::ivec2(p.bitmap->width, p.bitmap->rows);
                out.boxMin = any ? glm::min(out.boxMin, lo) : lo;
                out.boxMax = any ? glm::max(out.boxMax, hi) : hi;
                any = true;
            }
            out.glyphs.push_back(std::move(g));
        }
    }
    return out;
}

} // namespace volsg
