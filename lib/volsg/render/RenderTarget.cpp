#include <volsg/core/Error.h>
#include <volsg/render/RenderTarget.h>

#include <algorithm>
#include <string>

namespace volsg {

void RenderTarget::resize(int width, int height, bool floatColor) {
    if (width == width_ && height == height_ && floatColor == floatColor_ && framebuffer_) return;
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
    color_.image2D(floatColor ? GL_RGBA32F : GL_RGBA8, width, height, GL_RGBA,
                   floatColor ? GL_FLOAT : GL_UNSIGNED_BYTE, nullptr);
    depth_.image2D(GL_DEPTH_COMPONENT32F, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    framebuffer_.attach(GL_COLOR_ATTACHMENT0, color_);
    framebuffer_.attach(GL_DEPTH_ATTACHMENT, depth_);
    framebuffer_.requireComplete("render target");
    width_ = width;
    height_ = height;
    floatColor_ = floatColor;
    samples_ = 0; // the multisampled companion no longer matches: setMultisample remakes it
}

int RenderTarget::setMultisample(int samples) {
    if (samples > 1) {
        GLint maxSamples = 0, colorSamples = 0, depthSamples = 0;
        glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
        glGetInternalformativ(GL_RENDERBUFFER, colorFormat(), GL_SAMPLES, 1, &colorSamples);
        glGetInternalformativ(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, GL_SAMPLES, 1, &depthSamples);
        samples = std::min({samples, int(maxSamples), int(colorSamples), int(depthSamples)});
    }
    if (samples <= 1) {
        multisampleFramebuffer_ = Framebuffer();
        multisampleColor_ = Renderbuffer();
        multisampleDepth_ = Renderbuffer();
        samples_ = 0;
        return 0;
    }
    if (samples == samples_ && multisampleColor_.width() == width_ &&
        multisampleColor_.height() == height_)
        return samples_;
    multisampleColor_ = Renderbuffer(colorFormat(), width_, height_, samples);
    multisampleDepth_ = Renderbuffer(GL_DEPTH_COMPONENT32F, width_, height_, samples);
    if (!multisampleFramebuffer_) multisampleFramebuffer_ = Framebuffer::create();
    multisampleFramebuffer_.attach(GL_COLOR_ATTACHMENT0, multisampleColor_);
    multisampleFramebuffer_.attach(GL_DEPTH_ATTACHMENT, multisampleDepth_);
    multisampleFramebuffer_.requireComplete("multisample render target");
    samples_ = samples;
    return samples_;
}

void RenderTarget::resolveMultisample() {
    if (samples_ <= 1) {
        bind();
        return;
    }
    multisampleFramebuffer_.bind(GL_READ_FRAMEBUFFER);
    framebuffer_.bind(GL_DRAW_FRAMEBUFFER);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_,
                      GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    bind();
}

} // namespace volsg
