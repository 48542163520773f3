#pragma once
// A small SVG document builder for the benchmark's plots: shapes and text in user units, no
// dependencies.

#include <string>
#include <utility>
#include <vector>

namespace volsg::bench {

/// Appends SVG elements to a document of a fixed size; str() gives the file's text. Text is
/// escaped; colours are any SVG colour ("#1f77b4", "black").
class SvgWriter {
public:
    SvgWriter(double width, double height);

    void rect(double x, double y, double w, double h, const std::string& fill,
              const std::string& stroke = "none");
    void line(double x1, double y1, double x2, double y2, const std::string& stroke,
              double width = 1.0, const std::string& dash = {});
    void polyline(const std::vector<std::pair<double, double>>& points, const std::string& stroke,
                  double width = 1.5);
    void circle(double cx, double cy, double r, const std::string& fill,
                const std::string& stroke = "none");
    /// A marker of one of four shapes (0 circle, 1 square, 2 triangle, 3 diamond), filled or
    /// hollow, so series stay apart without colour.
    void marker(int shape, double cx, double cy, double size, const std::string& colour,
                bool filled);
    /// `anchor`: "start", "middle" or "end"; `rotate` in degrees about (x, y).
    void text(double x, double y, const std::string& content, double size = 12.0,
              const std::string& anchor = "start", const std::string& fill = "black",
              double rotate = 0.0, bool bold = false);

    std::string str() const;
    void save(const std::string& path) const; ///< throws Error when the file cannot be written

    static std::string escape(const std::string& text);

private:
    double width_, height_;
    std::string body_;
};

} // namespace volsg::bench
