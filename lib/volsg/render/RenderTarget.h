#pragma once
// The offscreen target of a render: 8-bit or float colour, float depth, resized on demand.

#include <volsg/gl/Framebuffer.h>
#include <volsg/gl/Renderbuffer.h>
#include <volsg/gl/Texture.h>

namespace volsg {

/// A framebuffer with a colour texture, GL_RGBA32F (linear values, unclamped, so blending and
/// volume compositing do not quantise) or GL_RGBA8 (what a window holds: a quarter of the
/// bytes to clear, blend and resolve, for frames without volumes), and a GL_DEPTH_COMPONENT32F
/// depth texture (textures, not renderbuffers, so that later passes can sample the opaque depth).
/// Sampling the depth texture while it is attached to the bound framebuffer is a feedback loop
/// (undefined in GL): copy it first, or detach it for that draw.
class RenderTarget {
public:
    /// Makes the target width x height with float (GL_RGBA32F) or 8-bit (GL_RGBA8) colour,
    /// reallocating only when the size or the format changes.
    void resize(int width, int height, bool floatColor = true);
    bool floatColor() const { return floatColor_; }
    /// Binds for drawing and reading.
    void bind() const { framebuffer_.bind(); }

    int width() const { return width_; }
    int height() const { return height_; }
    const Framebuffer& framebuffer() const { return framebuffer_; }
    const Texture& colorTexture() const { return color_; }
    const Texture& depthTexture() const { return depth_; }

    /// A multisampled companion of the same size (colour of the same format and
    /// GL_DEPTH_COMPONENT32F depth renderbuffers) for a pass drawn with multisample antialiasing,
    /// then resolved into this target. `samples` is clamped to what GL allows for both formats
    /// (GL_MAX_SAMPLES, 4 on llvmpipe); <= 1 frees it. Call after resize(). Returns the sample
    /// count in use.
    int setMultisample(int samples);
    int samples() const { return samples_; }
    /// Binds the multisampled framebuffer for drawing and reading (setMultisample first).
    void bindMultisample() const { multisampleFramebuffer_.bind(); }
    /// Resolves the multisampled colour (the mean of each pixel's samples) and depth (one
    /// sample's, as glBlitFramebuffer resolves depth) into this target's textures, and binds
    /// this target.
    void resolveMultisample();

private:
    GLenum colorFormat() const { return floatColor_ ? GL_RGBA32F : GL_RGBA8; }

    Framebuffer framebuffer_;
    Texture color_;
    Texture depth_;
    int width_ = 0, height_ = 0;
    bool floatColor_ = true;
    Framebuffer multisampleFramebuffer_;
    Renderbuffer multisampleColor_, multisampleDepth_;
    int samples_ = 0;
};

} // namespace volsg
