#pragma once
// A 1D, 2D or 3D GL texture: transfer tables, volume bricks, render targets.

#include <volsg/gl/GlName.h>

namespace volsg {

/// Created with linear filtering and clamp-to-edge wrapping (GL's default minification
/// filter wants mipmaps and would leave a single-level texture incomplete).
class Texture {
public:
    Texture() = default; ///< no texture (no GL call)
    /// A new texture for GL_TEXTURE_1D, GL_TEXTURE_2D or GL_TEXTURE_3D.
    explicit Texture(GLenum target);

    GLuint id() const { return name_.get(); }
    GLenum target() const { return target_; }
    explicit operator bool() const { return bool(name_); }
    int width() const { return width_; }
    int height() const { return height_; }
    int depth() const { return depth_; }
    GLenum internalFormat() const { return internalFormat_; }

    /// Binds to texture unit `unit` (and leaves that unit active).
    void bind(GLuint unit = 0) const;

    // (Re)allocate level 0 and upload `data` (null: leave undefined). Rows are tightly packed.
    void image1D(GLenum internalFormat, int width, GLenum format, GLenum type, const void* data);
    void image2D(GLenum internalFormat, int width, int height, GLenum format, GLenum type,
                 const void* data);
    void image3D(GLenum internalFormat, int width, int height, int depth, GLenum format,
                 GLenum type, const void* data);
    /// Overwrites a box of level 0 (for 1D and 2D, the unused extents are 1 and offsets 0).
    /// `rowLength`: pixels from one row of `data` to the next (0: the box's width), so a
    /// rectangle of a larger image uploads without a copy.
    void subImage(int x, int y, int z, int width, int height, int depth, GLenum format, GLenum type,
                  const void* data, int rowLength = 0);

    void setFilter(GLenum minFilter, GLenum magFilter);
    void setWrap(GLenum mode); ///< on every axis

private:
    void requireTarget(GLenum target, const char* what) const;

    GlName name_;
    GLenum target_ = GL_TEXTURE_2D;
    GLenum internalFormat_ = 0;
    int width_ = 0, height_ = 0, depth_ = 0;
};

} // namespace volsg
