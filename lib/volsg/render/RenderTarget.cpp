#include <volsg/core/Error.h>
#include <volsg/render/RenderTarget.h>

#include <string>

namespace volsg {

void RenderTarget::resize(int width, int height) {
    if (width == width_ && height == height_ && framebuffer_) return;
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (width <= 0 || height <= 0 || width > maxSize || height > maxSize)
        throw Error("render size " + std::to_string(width) + "x" + std::to_string(height) +
                    " is outside 1.." + std::to_string(maxSize));
    if (!framebuffer_) {
        framebuffer_ = Framebuffer::create();
        color_ = Texture(GL_TEXTURE_2D);
        depth_ = Texture(GL_TEXTURE_2D);
        color_.setFilter(GL_NEAREST, GL_NEAREST);
        depth_.setFilter(GL_NEAREST, GL_NEAREST);
    }
    color_.image2D(GL_RGBA32F, width, height, GL_RGBA, GL_FLOAT, nullptr);
    depth_.image2D(GL_DEPTH_COMPONENT32F, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    framebuffer_.attach(GL_COLOR_ATTACHMENT0, color_);
    framebuffer_.attach(GL_DEPTH_ATTACHMENT, depth_);
    framebuffer_.requireComplete("render target");
    width_ = width;
    height_ = height;
}

} // namespace volsg
