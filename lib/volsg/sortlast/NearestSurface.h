#pragma once
// The depth composite of opaque images: per pixel, the surface nearest the eye. Sort-last
// shares a scene's opaque shapes among processes (lib/volsg/sortlast/README.md); each draws
// its share with depth, and this operator, applied in any grouping, gives every pixel the
// colour and depth one process drawing all of them would.

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

namespace volsg {

/// One pixel of an opaque image: window depth (1 where nothing was drawn) and colour.
struct SurfacePixel {
    float depth;
    float red, green, blue, alpha;
};

/// inout[i] = the nearer of in[i] and inout[i]; on equal depth in[i] (the lower rank: a
/// deterministic choice, as MPI applies a non-commutative operator in rank order).
void keepNearest(const SurfacePixel* in, SurfacePixel* inout, std::size_t count);

/// An image's colour (row 0 at the top) and window depth as SurfacePixels, and back.
std::vector<SurfacePixel> surfacePixels(const std::vector<glm::vec4>& color,
                                        const std::vector<float>& depth);
void splitSurfacePixels(const std::vector<SurfacePixel>& pixels, std::vector<glm::vec4>& color,
                        std::vector<float>& depth);

} // namespace volsg
