#include <volsg/core/Error.h>
#include <volsg/gl/Renderbuffer.h>

namespace volsg {

namespace {
void deleteRenderbuffer(GLuint name) {
    glDeleteRenderbuffers(1, &name);
}
} // namespace

Renderbuffer::Renderbuffer(GLenum internalFormat, int width, int height, int samples)
    : internalFormat_(internalFormat), width_(width), height_(height) {
    GLuint name = 0;
    glGenRenderbuffers(1, &name);
    if (name == 0)
        throw Error("glGenRenderbuffers gave no renderbuffer (is a GL context current?)");
    name_ = GlName(name, deleteRenderbuffer);
    glBindRenderbuffer(GL_RENDERBUFFER, name);
    if (samples > 0)
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, internalFormat, width, height);
    else
        glRenderbufferStorage(GL_RENDERBUFFER, internalFormat, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
}

} // namespace volsg
