#pragma once
// The image half of volsg-coin-compare: 8-bit images, silhouettes against a background, their
// intersection over union and the colour difference inside them, and the picture of a model's
// two renders side by side. No Coin and no GL here (tests/inventor/CoinCompareTest.cpp).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <volsg/image/Image.h>

namespace volsg::coincompare {

/// An 8-bit RGB colour.
using Rgb8 = std::array<std::uint8_t, 3>;

/// An 8-bit RGB image, row 0 at the top: what a PNG of the tool holds.
struct Image8 {
    int width = 0;
    int height = 0;
    std::vector<Rgb8> pixels; ///< width*height, row-major

    Image8() = default;
    Image8(int w, int h, Rgb8 fill = {0, 0, 0});
    Rgb8& at(int x, int y) { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
    const Rgb8& at(int x, int y) const {
        return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
    bool operator==(const Image8&) const = default;
};

/// [0,1] to 0..255 as volsg::writePng does: rounded to nearest, NaN and below 0 give 0.
std::uint8_t toByte(float v);
Rgb8 toRgb8(const glm::vec3& colour);
/// volsg's linear float image as the 8-bit image its PNG holds (alpha dropped).
Image8 fromVolsg(const volsg::Image& image);
/// An RGBA 8-bit buffer whose row 0 is the bottom (GL's and OSMesa's order), as an Image8.
Image8 fromBottomUpRgba(const std::uint8_t* rgba, int width, int height);

void writePng8(const std::string& path, const Image8& image); ///< throws volsg::Error
Image8 readPng8(const std::string& path);                     ///< throws volsg::Error

/// The pixels that differ from `background` in any channel (exactly, in 8 bits).
std::vector<bool> silhouette(const Image8& image, Rgb8 background);

/// How two renders of one scene compare.
struct Comparison {
    long long pixelsA = 0;      ///< |A|: silhouette of the first image
    long long pixelsB = 0;      ///< |B|
    long long intersection = 0; ///< |A ∩ B|
    long long unionCount = 0;   ///< |A ∪ B|
    /// |A∩B| / |A∪B|; 1 when both silhouettes are empty (the images agree that nothing is seen).
    double iou = 1.0;
    /// Mean over A∪B of the absolute colour difference, per channel in [0,1], averaged over R, G
    /// and B; 0 when the union is empty. Background pixels count with their background colour.
    double colourDifference = 0.0;
};

/// Compares two images of the same size, each against its own background (the two renderers
/// may round the same clear colour differently). Throws volsg::Error when the sizes differ.
Comparison compare(const Image8& a, Rgb8 backgroundA, const Image8& b, Rgb8 backgroundB);

/// The agreement thresholds of the comparison.
inline constexpr double minimumIoU = 0.9;
inline constexpr double maximumColourDifference = 0.08;
bool agrees(const Comparison& c);

/// The picture of one model for people: Coin's render, volsg's render and the two silhouettes
/// (grey where both cover a pixel, green Coin only, magenta volsg only), 4 grey pixels apart.
/// A missing render (nullptr) is drawn as a dark red panel.
Image8 sideBySide(const Image8* coin, Rgb8 coinBackground, const Image8* volsg,
                  Rgb8 volsgBackground, int width, int height);

} // namespace volsg::coincompare
