#include "ImageCompare.h"

#include <cmath>
#include <cstdlib>

#include <volsg/core/Error.h>

namespace volsg::coincompare {

Image8::Image8(int w, int h, Rgb8 fill)
    : width(w), height(h), pixels(std::size_t(w) * std::size_t(h), fill) {}

std::uint8_t toByte(float v) {
    if (!(v > 0.0f)) return 0; // NaN too
    if (v >= 1.0f) return 255;
    return static_cast<std::uint8_t>(std::floor(v * 255.0f + 0.5f));
}

Rgb8 toRgb8(const glm::vec3& colour) {
    return {toByte(colour.r), toByte(colour.g), toByte(colour.b)};
}

Image8 fromVolsg(const volsg::Image& image) {
    Image8 out(image.width, image.height);
    for (std::size_t i = 0; i < out.pixels.size(); ++i)
        out.pixels[i] = toRgb8(glm::vec3(image.pixels[i]));
    return out;
}

Image8 fromBottomUpRgba(const std::uint8_t* rgba, int width, int height) {
    Image8 out(width, height);
    for (int y = 0; y < height; ++y) {
        const std::uint8_t* row = rgba + std::size_t(height - 1 - y) * std::size_t(width) * 4;
        for (int x = 0; x < width; ++x)
            out.at(x, y) = {row[4 * x], row[4 * x + 1], row[4 * x + 2]};
    }
    return out;
}

void writePng8(const std::string& path, const Image8& image) {
    volsg::Image out(image.width, image.height);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        const Rgb8& p = image.pixels[i];
        out.pixels[i] =
            glm::vec4(float(p[0]) / 255.0f, float(p[1]) / 255.0f, float(p[2]) / 255.0f, 1.0f);
    }
    volsg::writePng(path, out); // rounds back to exactly the same bytes
}

Image8 readPng8(const std::string& path) {
    return fromVolsg(volsg::readPng(path));
}

std::vector<bool> silhouette(const Image8& image, Rgb8 background) {
    std::vector<bool> out(image.pixels.size());
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        out[i] = image.pixels[i] != background;
    return out;
}

Comparison compare(const Image8& a, Rgb8 backgroundA, const Image8& b, Rgb8 backgroundB) {
    if (a.width != b.width || a.height != b.height)
        throw volsg::Error("images of different sizes (" + std::to_string(a.width) + "x" +
                           std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                           std::to_string(b.height) + ")");
    const std::vector<bool> inA = silhouette(a, backgroundA);
    const std::vector<bool> inB = silhouette(b, backgroundB);
    Comparison c;
    long long differenceSum = 0; // in 1/255 units, summed over the three channels
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        c.pixelsA += inA[i];
        c.pixelsB += inB[i];
        if (inA[i] && inB[i]) ++c.intersection;
        if (!inA[i] && !inB[i]) continue;
        ++c.unionCount;
        for (int k = 0; k < 3; ++k)
            differenceSum += std::abs(int(a.pixels[i][k]) - int(b.pixels[i][k]));
    }
    if (c.unionCount > 0) {
        c.iou = double(c.intersection) / double(c.unionCount);
        c.colourDifference = double(differenceSum) / (255.0 * 3.0 * double(c.unionCount));
    }
    return c;
}

bool agrees(const Comparison& c) {
    return c.iou >= minimumIoU && c.colourDifference <= maximumColourDifference;
}

Image8 sideBySide(const Image8* coin, Rgb8 coinBackground, const Image8* volsg,
                  Rgb8 volsgBackground, int width, int height) {
    const int gap = 4;
    const Rgb8 gapColour{128, 128, 128};
    const Rgb8 missing{80, 0, 0};
    Image8 out(3 * width + 2 * gap, height, gapColour);
    auto paste = [&](const Image8* image, int x0) {
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const bool have = image && x < image->width && y < image->height;
                out.at(x0 + x, y) = have ? image->at(x, y) : missing;
            }
    };
    paste(coin, 0);
    paste(volsg, width + gap);
    const int x0 = 2 * (width + gap);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const bool a =
                coin && x < coin->width && y < coin->height && coin->at(x, y) != coinBackground;
            const bool b = volsg && x < volsg->width && y < volsg->height &&
                           volsg->at(x, y) != volsgBackground;
            Rgb8 c{0, 0, 0};
            if (a && b)
                c = {160, 160, 160};
            else if (a)
                c = {0, 200, 0};
            else if (b)
                c = {220, 0, 220};
            out.at(x0 + x, y) = c;
        }
    return out;
}

} // namespace volsg::coincompare
