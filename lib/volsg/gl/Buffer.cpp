#include <volsg/core/Error.h>
#include <volsg/gl/Buffer.h>

#include <string>

namespace volsg {

namespace {
void deleteBuffer(GLuint name) {
    glDeleteBuffers(1, &name);
}
} // namespace

Buffer::Buffer(GLenum target) : target_(target) {
    GLuint name = 0;
    glGenBuffers(1, &name);
    if (name == 0) throw Error("glGenBuffers gave no buffer (is a GL context current?)");
    name_ = GlName(name, deleteBuffer);
}

void Buffer::bind() const {
    glBindBuffer(target_, name_.get());
}

void Buffer::setData(const void* data, std::size_t bytes, GLenum usage) {
    bind();
    glBufferData(target_, static_cast<GLsizeiptr>(bytes), data, usage);
    size_ = bytes;
}

void Buffer::setSubData(std::size_t offset, const void* data, std::size_t bytes) {
    if (offset + bytes > size_)
        throw Error("Buffer::setSubData: " + std::to_string(offset + bytes) +
                    " bytes exceed the buffer's " + std::to_string(size_));
    bind();
    glBufferSubData(target_, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
}

} // namespace volsg
