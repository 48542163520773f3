#include <volsg/core/Error.h>
#include <volsg/gl/Buffer.h>
#include <volsg/gl/VertexArray.h>

namespace volsg {

namespace {
void deleteVertexArray(GLuint name) {
    glDeleteVertexArrays(1, &name);
}
} // namespace

VertexArray VertexArray::create() {
    GLuint name = 0;
    glGenVertexArrays(1, &name);
    if (name == 0) throw Error("glGenVertexArrays gave no vertex array (is a GL context current?)");
    VertexArray vao;
    vao.name_ = GlName(name, deleteVertexArray);
    return vao;
}

void VertexArray::bind() const {
    glBindVertexArray(name_.get());
}
void VertexArray::unbind() {
    glBindVertexArray(0);
}

void VertexArray::setAttribute(GLuint index, const Buffer& buffer, GLint components, GLenum type,
                               bool normalized, GLsizei stride, std::size_t offset) {
    bind();
    glBindBuffer(GL_ARRAY_BUFFER, buffer.id());
    glEnableVertexAttribArray(index);
    glVertexAttribPointer(index, components, type, normalized ? GL_TRUE : GL_FALSE, stride,
                          reinterpret_cast<const void*>(offset));
}

void VertexArray::disableAttribute(GLuint index, const glm::vec4& value) {
    bind();
    glDisableVertexAttribArray(index);
    // The constant value is context state, not VAO state: set it again before drawing too.
    glVertexAttrib4f(index, value.x, value.y, value.z, value.w);
}

void VertexArray::setIndexBuffer(const Buffer& buffer) {
    bind();
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffer.id());
}

} // namespace volsg
