#pragma once
// A GL renderbuffer: an image a framebuffer draws into but nobody samples (depth, MSAA).

#include <volsg/gl/GlName.h>

namespace volsg {

class Renderbuffer {
public:
    Renderbuffer() = default; ///< no renderbuffer (no GL call)
    /// Storage of `internalFormat` (GL_DEPTH_COMPONENT24, GL_RGBA8, ...), multisampled when
    /// `samples` > 0.
    Renderbuffer(GLenum internalFormat, int width, int height, int samples = 0);

    GLuint id() const { return name_.get(); }
    explicit operator bool() const { return bool(name_); }
    int width() const { return width_; }
    int height() const { return height_; }
    GLenum internalFormat() const { return internalFormat_; }

private:
    GlName name_;
    GLenum internalFormat_ = 0;
    int width_ = 0, height_ = 0;
};

} // namespace volsg
