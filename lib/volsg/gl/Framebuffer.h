#pragma once
// A GL framebuffer object: the offscreen target every render draws into.

#include <volsg/gl/GlName.h>

namespace volsg {

class Texture;
class Renderbuffer;

class Framebuffer {
public:
    Framebuffer() = default; ///< no framebuffer (no GL call)
    static Framebuffer create();

    GLuint id() const { return name_.get(); }
    explicit operator bool() const { return bool(name_); }

    /// Binds to GL_FRAMEBUFFER (draw and read), GL_DRAW_FRAMEBUFFER or GL_READ_FRAMEBUFFER.
    void bind(GLenum target = GL_FRAMEBUFFER) const;
    /// Attaches level `level` of a 2D texture (binds this framebuffer).
    void attach(GLenum attachment, const Texture& texture, GLint level = 0);
    void attach(GLenum attachment, const Renderbuffer& renderbuffer);
    /// Throws Error naming `what` and the status (GL_FRAMEBUFFER_INCOMPLETE_...) unless the
    /// framebuffer is complete (binds this framebuffer).
    void requireComplete(const char* what) const;

private:
    GlName name_;
};

} // namespace volsg
