#include "SvgWriter.h"

#include <cstdio>
#include <fstream>

#include <volsg/core/Error.h>
#include <volsg/io/AtomicFile.h>

namespace volsg::bench {

namespace {
// Coordinates with two decimals: exact enough for a plot, and a compact file.
std::string num(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.2f", v);
    return buffer;
}
} // namespace

SvgWriter::SvgWriter(double width, double height) : width_(width), height_(height) {}

std::string SvgWriter::escape(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

void SvgWriter::rect(double x, double y, double w, double h, const std::string& fill,
                     const std::string& stroke) {
    body_ += "<rect x=\"" + num(x) + "\" y=\"" + num(y) + "\" width=\"" + num(w) + "\" height=\"" +
             num(h) + "\" fill=\"" + fill + "\" stroke=\"" + stroke + "\"/>\n";
}

void SvgWriter::line(double x1, double y1, double x2, double y2, const std::string& stroke,
                     double width, const std::string& dash) {
    body_ += "<line x1=\"" + num(x1) + "\" y1=\"" + num(y1) + "\" x2=\"" + num(x2) + "\" y2=\"" +
             num(y2) + "\" stroke=\"" + stroke + "\" stroke-width=\"" + num(width) + "\"";
    if (!dash.empty()) body_ += " stroke-dasharray=\"" + dash + "\"";
    body_ += "/>\n";
}

void SvgWriter::polyline(const std::vector<std::pair<double, double>>& points,
                         const std::string& stroke, double width) {
    body_ += "<polyline fill=\"none\" stroke=\"" + stroke + "\" stroke-width=\"" + num(width) +
             "\" points=\"";
    for (const auto& [x, y] : points)
        body_ += num(x) + "," + num(y) + " ";
    body_ += "\"/>\n";
}

void SvgWriter::circle(double cx, double cy, double r, const std::string& fill,
                       const std::string& stroke) {
    body_ += "<circle cx=\"" + num(cx) + "\" cy=\"" + num(cy) + "\" r=\"" + num(r) + "\" fill=\"" +
             fill + "\" stroke=\"" + stroke + "\"/>\n";
}

void SvgWriter::marker(int shape, double cx, double cy, double size, const std::string& colour,
                       bool filled) {
    const std::string fill = filled ? colour : "white";
    const double h = 0.5 * size;
    std::string points;
    switch (shape % 4) {
    case 0:
        circle(cx, cy, h, fill, colour);
        return;
    case 1:
        rect(cx - h, cy - h, size, size, fill, colour);
        return;
    case 2:
        points = num(cx) + "," + num(cy - h) + " " + num(cx + h) + "," + num(cy + h) + " " +
                 num(cx - h) + "," + num(cy + h);
        break;
    default:
        points = num(cx) + "," + num(cy - h) + " " + num(cx + h) + "," + num(cy) + " " + num(cx) +
                 "," + num(cy + h) + " " + num(cx - h) + "," + num(cy);
        break;
    }
    body_ +=
        "<polygon points=\"" + points + "\" fill=\"" + fill + "\" stroke=\"" + colour + "\"/>\n";
}

void SvgWriter::text(double x, double y, const std::string& content, double size,
                     const std::string& anchor, const std::string& fill, double rotate, bool bold) {
    body_ += "<text x=\"" + num(x) + "\" y=\"" + num(y) + "\" font-size=\"" + num(size) +
             "\" text-anchor=\"" + anchor + "\" fill=\"" + fill + "\"";
    if (bold) body_ += " font-weight=\"bold\"";
    if (rotate != 0.0)
        body_ += " transform=\"rotate(" + num(rotate) + " " + num(x) + " " + num(y) + ")\"";
    body_ += ">" + escape(content) + "</text>\n";
}

std::string SvgWriter::str() const {
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
           "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
           num(width_) + "\" height=\"" + num(height_) + "\" viewBox=\"0 0 " + num(width_) + " " +
           num(height_) + "\" font-family=\"sans-serif\">\n" + body_ + "</svg>\n";
}

void SvgWriter::save(const std::string& path) const {
    writeFileAtomically(path, str()); // a failed save keeps the previous plot
}

} // namespace volsg::bench
