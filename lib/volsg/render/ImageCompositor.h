#pragma once
// Composites an image rendered on the CPU (shear-warp) into the frame's target.

#include <vector>

#include <glm/glm.hpp>

#include <volsg/gl/Program.h>
#include <volsg/gl/Texture.h>
#include <volsg/gl/VertexArray.h>
#include <volsg/image/Image.h>
#include <volsg/render/FrameContext.h>

namespace volsg {

/// A premultiplied RGBA float image of the frame's size (row 0 at the top), and optionally the
/// window depth of its opaque results, of which only the rectangle `drawn` is set.
struct CpuImage {
    const glm::vec4* pixels = nullptr;  ///< null: depth only (windowDepth), no colour
    const float* windowDepth = nullptr; ///< null: no opaque results (all 1)
    glm::ivec4 drawn{0};                ///< (x0, y0, x1, y1), exclusive, row 0 at the top
};

/// One per owner and context (kept in the RenderCache): two programs and two textures.
class ImageCompositor {
public:
    /// The window depth the frame's opaque geometry wrote so far (row 0 at the top, 1 where
    /// nothing), into `out`; empty when nothing opaque was drawn yet (FrameContext::shapes
    /// counts the draws).
    static void readOpaqueDepth(const FrameContext& frame, std::vector<float>& out);

    /// Blends the image's rectangle over the target with the Volume pass's blending
    /// (premultiplied: ONE, ONE_MINUS_SRC_ALPHA), then writes the depth of its opaque results
    /// so later geometry and volumes mix with them (counted as a draw). Leaves the GL state of
    /// the pass as it found it.
    /// On a CPU frame (FrameContext::cpuImage) the colour is blended there by blendOver, and
    /// an image with opaque results asks for the GL frame instead (FrameContext::needsGl).
    void composite(FrameContext& frame, const CpuImage& image);
    /// The image's rectangle blended over `target` (of the frame's size) as composite blends it.
    static void blendOver(Image& target, const CpuImage& image);

private:
    Program colorProgram_, depthProgram_;
    VertexArray vertexArray_;
    Texture color_, depth_;
    glm::ivec2 size_{0}; ///< of the textures' storage
};

} // namespace volsg
