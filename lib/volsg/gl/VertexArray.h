#pragma once
// A vertex array object: which buffers feed which vertex attributes, and the index buffer.

#include <cstddef>

#include <glm/glm.hpp>

#include <volsg/gl/GlName.h>

namespace volsg {

class Buffer;

class VertexArray {
public:
    VertexArray() = default;     ///< no VAO (no GL call)
    static VertexArray create(); ///< a new VAO

    GLuint id() const { return name_.get(); }
    explicit operator bool() const { return bool(name_); }

    void bind() const;
    static void unbind();

    /// Feeds float attribute `index` from `buffer` (`components` values of `type` per vertex).
    /// Leaves this VAO bound.
    void setAttribute(GLuint index, const Buffer& buffer, GLint components, GLenum type = GL_FLOAT,
                      bool normalized = false, GLsizei stride = 0, std::size_t offset = 0);
    /// Turns attribute `index` off; shaders then read the constant `value`.
    void disableAttribute(GLuint index, const glm::vec4& value);
    /// Uses `buffer` as this VAO's GL_ELEMENT_ARRAY_BUFFER. Leaves this VAO bound.
    void setIndexBuffer(const Buffer& buffer);

private:
    GlName name_;
};

} // namespace volsg
