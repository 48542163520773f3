#include <volsg/core/Error.h>
#include <volsg/gl/Texture.h>

#include <string>

namespace volsg {

namespace {

void deleteTexture(GLuint name) {
    glDeleteTextures(1, &name);
}

/// Tightly packed rows for the duration of an upload, whatever the caller had set.
class TightUnpacking {
public:
    explicit TightUnpacking(int rowLength = 0) {
        glGetIntegerv(GL_UNPACK_ALIGNMENT, &previous_);
        glGetIntegerv(GL_UNPACK_ROW_LENGTH, &previousRowLength_);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, rowLength);
    }
    ~TightUnpacking() {
        glPixelStorei(GL_UNPACK_ALIGNMENT, previous_);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, previousRowLength_);
    }
    TightUnpacking(const TightUnpacking&) = delete;
    TightUnpacking& operator=(const TightUnpacking&) = delete;

private:
    GLint previous_ = 4, previousRowLength_ = 0;
};

} // namespace

Texture::Texture(GLenum target) : target_(target) {
    if (target != GL_TEXTURE_1D && target != GL_TEXTURE_2D && target != GL_TEXTURE_3D)
        throw Error("Texture: target must be GL_TEXTURE_1D, GL_TEXTURE_2D or GL_TEXTURE_3D");
    GLuint name = 0;
    glGenTextures(1, &name);
    if (name == 0) throw Error("glGenTextures gave no texture (is a GL context current?)");
    name_ = GlName(name, deleteTexture);
    setFilter(GL_LINEAR, GL_LINEAR);
    setWrap(GL_CLAMP_TO_EDGE);
}

void Texture::bind(GLuint unit) const {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(target_, name_.get());
}

void Texture::requireTarget(GLenum target, const char* what) const {
    if (target_ != target)
        throw Error(std::string("Texture::") + what + " on a texture of another dimension");
}

void Texture::image1D(GLenum internalFormat, int width, GLenum format, GLenum type,
                      const void* data) {
    requireTarget(GL_TEXTURE_1D, "image1D");
    TightUnpacking tight;
    glBindTexture(target_, name_.get());
    glTexImage1D(target_, 0, GLint(internalFormat), width, 0, format, type, data);
    internalFormat_ = internalFormat;
    width_ = width;
    height_ = depth_ = 1;
}

void Texture::image2D(GLenum internalFormat, int width, int height, GLenum format, GLenum type,
                      const void* data) {
    requireTarget(GL_TEXTURE_2D, "image2D");
    TightUnpacking tight;
    glBindTexture(target_, name_.get());
    glTexImage2D(target_, 0, GLint(internalFormat), width, height, 0, format, type, data);
    internalFormat_ = internalFormat;
    width_ = width;
    height_ = height;
    depth_ = 1;
}

void Texture::image3D(GLenum internalFormat, int width, int height, int depth, GLenum format,
                      GLenum type, const void* data) {
    requireTarget(GL_TEXTURE_3D, "image3D");
    TightUnpacking tight;
    glBindTexture(target_, name_.get());
    glTexImage3D(target_, 0, GLint(internalFormat), width, height, depth, 0, format, type, data);
    internalFormat_ = internalFormat;
    width_ = width;
    height_ = height;
    depth_ = depth;
}

void Texture::subImage(int x, int y, int z, int width, int height, int depth, GLenum format,
                       GLenum type, const void* data, int rowLength) {
    if (x < 0 || y < 0 || z < 0 || x + width > width_ || y + height > height_ || z + depth > depth_)
        throw Error("Texture::subImage: the box lies outside the texture");
    if (rowLength != 0 && rowLength < width)
        throw Error("Texture::subImage: rows of the data are shorter than the box");
    TightUnpacking tight(rowLength);
    glBindTexture(target_, name_.get());
    if (target_ == GL_TEXTURE_1D)
        glTexSubImage1D(target_, 0, x, width, format, type, data);
    else if (target_ == GL_TEXTURE_2D)
        glTexSubImage2D(target_, 0, x, y, width, height, format, type, data);
    else
        glTexSubImage3D(target_, 0, x, y, z, width, height, depth, format, type, data);
}

void Texture::setFilter(GLenum minFilter, GLenum magFilter) {
    glBindTexture(target_, name_.get());
    glTexParameteri(target_, GL_TEXTURE_MIN_FILTER, GLint(minFilter));
    glTexParameteri(target_, GL_TEXTURE_MAG_FILTER, GLint(magFilter));
}

void Texture::setWrap(GLenum mode) {
    glBindTexture(target_, name_.get());
    glTexParameteri(target_, GL_TEXTURE_WRAP_S, GLint(mode));
    if (target_ != GL_TEXTURE_1D) glTexParameteri(target_, GL_TEXTURE_WRAP_T, GLint(mode));
    if (target_ == GL_TEXTURE_3D) glTexParameteri(target_, GL_TEXTURE_WRAP_R, GLint(mode));
}

} // namespace volsg
