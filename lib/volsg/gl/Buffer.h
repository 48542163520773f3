#pragma once
// A GL buffer object (vertex data, indices, uniforms).

#include <cstddef>
#include <vector>

#include <volsg/gl/GlName.h>

namespace volsg {

class Buffer {
public:
    Buffer() = default; ///< no buffer (no GL call)
    /// A new buffer meant for `target` (GL_ARRAY_BUFFER, GL_ELEMENT_ARRAY_BUFFER, ...).
    explicit Buffer(GLenum target);

    GLuint id() const { return name_.get(); }
    GLenum target() const { return target_; }
    explicit operator bool() const { return bool(name_); }
    std::size_t size() const { return size_; } ///< bytes

    void bind() const;
    /// Replaces the whole contents (the buffer stays bound to its target).
    void setData(const void* data, std::size_t bytes, GLenum usage = GL_STATIC_DRAW);
    template <class T> void setData(const std::vector<T>& values, GLenum usage = GL_STATIC_DRAW) {
        setData(values.data(), values.size() * sizeof(T), usage);
    }
    /// Overwrites part of the contents; offset + bytes must be within size().
    void setSubData(std::size_t offset, const void* data, std::size_t bytes);

private:
    GlName name_;
    GLenum target_ = GL_ARRAY_BUFFER;
    std::size_t size_ = 0;
};

} // namespace volsg
