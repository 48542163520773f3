#pragma once
// The offscreen target of a render: float colour and depth, resized on demand.

#include <volsg/gl/Framebuffer.h>
#include <volsg/gl/Renderbuffer.h>
#include <volsg/gl/Texture.h>

namespace volsg {

/// A framebuffer with a GL_RGBA32F colour texture (linear values, unclamped, so blending and
/// volume compositing do not quantise) and a GL_DEPTH_COMPONENT32F depth texture (textures,
/// not renderbuffers, so that later passes can sample the opaque depth). Sampling the depth
/// texture while it is attached to the bound framebuffer is a feedback loop (undefined in
/// GL): copy it first, or detach it for that draw.
class RenderTarget {
public:
    /// Makes the target width x height (reallocating only when the size changes).
    void resize(int width, int height);
    /// Binds for drawing and reading.
    void bind() const { framebuffer_.bind(); }

    int width() const { return width_; }
    int height() const { return height_; }
    const Framebuffer& framebuffer() const { return framebuffer_; }
    const Texture& colorTexture() const { return color_; }
    const Texture& depthTexture() const { return depth_; }

    /// A multisampled companion of the same size (GL_RGBA32F colour and GL_DEPTH_COMPONENT32F
    /// depth renderbuffers) for a pass drawn with multisample antialiasing, then resolved into
    /// this target. `samples` is clamped to what GL allows for both formats (GL_MAX_SAMPLES,
    /// 4 on llvmpipe); <= 1 frees it. Call after resize(). Returns the sample count in use.
    int setMultisample(int samples);
    int samples() const { return samples_; }
    /// Binds the multisampled framebuffer for drawing and reading (setMultisample first).
    void bindMultisample() const { multisampleFramebuffer_.bind(); }
    /// Resolves the multisampled colour (the mean of each pixel's samples) and depth (one
    /// sample's, as glBlitFramebuffer resolves depth) into this target's textures, and binds
    /// this target.
    void resolveMultisample();

private:
    Framebuffer framebuffer_;
    Texture color_;
    Texture depth_;
    int width_ = 0, height_ = 0;
    Framebuffer multisampleFramebuffer_;
    Renderbuffer multisampleColor_, multisampleDepth_;
    int samples_ = 0;
};

} // namespace volsg
