#include <volsg/sortlast/NearestSurface.h>

#include <stdexcept>

namespace volsg {

void keepNearest(const SurfacePixel* in, SurfacePixel* inout, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i)
        if (in[i].depth <= inout[i].depth) inout[i] = in[i];
}

std::vector<SurfacePixel> surfacePixels(const std::vector<glm::vec4>& color,
                                        const std::vector<float>& depth) {
    if (color.size() != depth.size())
        throw std::invalid_argument("an opaque image's colour and depth differ in size");
    std::vector<SurfacePixel> pixels(color.size());
    for (std::size_t i = 0; i < pixels.size(); ++i)
        pixels[i] = {depth[i], color[i].r, color[i].g, color[i].b, color[i].a};
    return pixels;
}

void splitSurfacePixels(const std::vector<SurfacePixel>& pixels, std::vector<glm::vec4>& color,
                        std::vector<float>& depth) {
    color.resize(pixels.size());
    depth.resize(pixels.size());
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        const SurfacePixel& p = pixels[i];
        depth[i] = p.depth;
        color[i] = glm::vec4(p.red, p.green, p.blue, p.alpha);
    }
}

} // namespace volsg
