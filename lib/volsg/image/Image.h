#pragma once
// An RGBA image in linear floating point, row 0 at the top, and its file formats.

#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace volsg {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<glm::vec4> pixels; ///< width*height, row-major, row 0 is the top row

    Image() = default;
    Image(int w, int h, glm::vec4 fill = glm::vec4(0.0f))
        : width(w), height(h), pixels(std::size_t(w) * std::size_t(h), fill) {}
    glm::vec4& at(int x, int y) {
        return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
    const glm::vec4& at(int x, int y) const {
        return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
};

/// 8-bit RGB PNG, values clamped to [0,1] and rounded to nearest (no gamma). Throws Error.
void writePng(const std::string& path, const Image& image);
/// 32-bit float RGB PFM (bottom row first, as the format says). Throws Error.
void writePfm(const std::string& path, const Image& image);
/// Reads a PFM (colour "PF" or grey "Pf", either byte order). Throws Error naming the file.
Image readPfm(const std::string& path);
/// Reads an 8-bit RGB or RGBA PNG (values /255). Throws Error naming the file.
Image readPng(const std::string& path);
/// Writes by the file's extension: .png or .pfm.
void writeImage(const std::string& path, const Image& image);

} // namespace volsg
