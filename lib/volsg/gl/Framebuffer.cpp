#include <volsg/core/Error.h>
#include <volsg/gl/Framebuffer.h>
#include <volsg/gl/Renderbuffer.h>
#include <volsg/gl/Texture.h>

#include <string>

namespace volsg {

namespace {

void deleteFramebuffer(GLuint name) {
    glDeleteFramebuffers(1, &name);
}

const char* statusName(GLenum status) {
    switch (status) {
    case GL_FRAMEBUFFER_COMPLETE:
        return "GL_FRAMEBUFFER_COMPLETE";
    case GL_FRAMEBUFFER_UNDEFINED:
        return "GL_FRAMEBUFFER_UNDEFINED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT:
        return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
        return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER:
        return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
    case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER:
        return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
    case GL_FRAMEBUFFER_UNSUPPORTED:
        return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE:
        return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
    case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS:
        return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
    default:
        return "unknown framebuffer status";
    }
}

} // namespace

Framebuffer Framebuffer::create() {
    GLuint name = 0;
    glGenFramebuffers(1, &name);
    if (name == 0) throw Error("glGenFramebuffers gave no framebuffer (is a GL context current?)");
    Framebuffer fb;
    fb.name_ = GlName(name, deleteFramebuffer);
    return fb;
}

void Framebuffer::bind(GLenum target) const {
    glBindFramebuffer(target, name_.get());
}

void Framebuffer::attach(GLenum attachment, const Texture& texture, GLint level) {
    if (texture.target() != GL_TEXTURE_2D)
        throw Error("Framebuffer::attach: only 2D textures can be attached");
    bind();
    glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, texture.id(), level);
}

void Framebuffer::attach(GLenum attachment, const Renderbuffer& renderbuffer) {
    bind();
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, attachment, GL_RENDERBUFFER, renderbuffer.id());
}

void Framebuffer::requireComplete(const char* what) const {
    bind();
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw Error(std::string(what) + ": framebuffer incomplete (" + statusName(status) + ")");
}

} // namespace volsg
