#include <volsg/render/ImageCompositor.h>

#include <algorithm>

#include <volsg/gl/Shader.h>
#include <volsg/render/RenderTarget.h>
#include <volsg/render/ShapeRenderer.h>

namespace volsg {

namespace {

constexpr const char* kCompositeVertex = R"GLSL(#version 330 core
void main() {
    vec2 corner = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
    gl_Position = vec4(corner, 0.0, 1.0);
}
)GLSL";

// Row 0 of the CPU image is the top row: flip y when fetching. Colour and depth are two
// programs: on llvmpipe one program with a uniform switch between them pays for the depth
// write's path on every colour fragment (the colour draw of the head CT's 230 x 284 pixels took
// 0.47 ms, 0.34 alone; shear-warp README, session 14).
constexpr const char* kColorFragment = R"GLSL(#version 330 core
uniform sampler2D uColor;
out vec4 fragColor;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    p.y = textureSize(uColor, 0).y - 1 - p.y;
    fragColor = texelFetch(uColor, p, 0);
}
)GLSL";
constexpr const char* kDepthFragment = R"GLSL(#version 330 core
uniform sampler2D uDepth;
out vec4 fragColor;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    p.y = textureSize(uDepth, 0).y - 1 - p.y;
    float d = texelFetch(uDepth, p, 0).r;
    if (d >= 1.0) discard;
    gl_FragDepth = d;
    fragColor = vec4(0.0);
}
)GLSL";

} // namespace

void ImageCompositor::blendOver(Image& target, const CpuImage& image) {
    if (!image.pixels) return;
    const glm::ivec4 d =
        glm::clamp(image.drawn, glm::ivec4(0),
                   glm::ivec4(target.width, target.height, target.width, target.height));
    for (int y = d.y; y < d.w; ++y) {
        const std::size_t row = std::size_t(y) * std::size_t(target.width);
        const glm::vec4* src = image.pixels + row;
        glm::vec4* dst = target.pixels.data() + row;
        // GL's blend of the Volume pass (ONE, ONE_MINUS_SRC_ALPHA), in the same float steps.
        for (int x = d.x; x < d.z; ++x)
            dst[x] = src[x] + dst[x] * (1.0f - src[x].a);
    }
}

void ImageCompositor::readOpaqueDepth(const FrameContext& frame, std::vector<float>& out) {
    out.clear();
    if (frame.cpuImage) return; // a CPU frame has no depth: nothing opaque is drawn in it
    // Only read when something drew into the depth buffer before (shapes, glTF, slices and
    // composited opaque results count their draws); otherwise it is all 1.
    if (frame.shapes.drawsLastFrame() == 0) return;
    const int width = frame.view.width, height = frame.view.height;
    frame.target.framebuffer().bind(GL_READ_FRAMEBUFFER);
    out.resize(std::size_t(width) * std::size_t(height));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, out.data());
    for (int y = 0; y < height / 2; ++y) // GL rows are bottom-up
        std::swap_ranges(out.begin() + std::ptrdiff_t(y) * width,
                         out.begin() + std::ptrdiff_t(y + 1) * width,
                         out.begin() + std::ptrdiff_t(height - 1 - y) * width);
}

void ImageCompositor::composite(FrameContext& frame, const CpuImage& image) {
    if (!colorProgram_) {
        const Shader vertex(GL_VERTEX_SHADER, kCompositeVertex, "CPU image composite");
        const Shader color(GL_FRAGMENT_SHADER, kColorFragment, "CPU image colour");
        const Shader depth(GL_FRAGMENT_SHADER, kDepthFragment, "CPU image depth");
        colorProgram_ = Program({&vertex, &color}, "CPU image colour");
        depthProgram_ = Program({&vertex, &depth}, "CPU image depth");
        vertexArray_ = VertexArray::create();
        color_ = Texture(GL_TEXTURE_2D);
        depth_ = Texture(GL_TEXTURE_2D);
        color_.setFilter(GL_NEAREST, GL_NEAREST);
        depth_.setFilter(GL_NEAREST, GL_NEAREST);
    }
    // Only the rectangle the image covers is uploaded and drawn: outside it the image is 0
    // (nothing to blend) and the depth 1.
    const glm::ivec4 drawn = image.drawn;
    if (drawn.x >= drawn.z || drawn.y >= drawn.w) return;
    const int frameWidth = frame.view.width, frameHeight = frame.view.height;
    if (frame.cpuImage) {
        // Opaque results must reach the depth buffer later geometry and volumes test.
        if (image.windowDepth) {
            frame.needsGl = true;
            return;
        }
        blendOver(*frame.cpuImage, image);
        return;
    }
    glActiveTexture(GL_TEXTURE0);
    if (size_ != glm::ivec2(frameWidth, frameHeight)) {
        color_.image2D(GL_RGBA32F, frameWidth, frameHeight, GL_RGBA, GL_FLOAT, nullptr);
        depth_.image2D(GL_R32F, frameWidth, frameHeight, GL_RED, GL_FLOAT, nullptr);
        size_ = glm::ivec2(frameWidth, frameHeight);
    }
    // The rectangle alone (texels outside it are never read: the draw is scissored to it).
    const std::size_t first = std::size_t(drawn.y) * std::size_t(frameWidth) + std::size_t(drawn.x);
    const int width = drawn.z - drawn.x, height = drawn.w - drawn.y;
    if (image.pixels)
        color_.subImage(drawn.x, drawn.y, 0, width, height, 1, GL_RGBA, GL_FLOAT,
                        image.pixels + first, frameWidth);
    if (image.windowDepth)
        depth_.subImage(drawn.x, drawn.y, 0, width, height, 1, GL_RED, GL_FLOAT,
                        image.windowDepth + first, frameWidth);
    frame.target.bind();
    const GLboolean scissorWasOn = glIsEnabled(GL_SCISSOR_TEST);
    GLint scissorBox[4];
    glGetIntegerv(GL_SCISSOR_BOX, scissorBox);
    glEnable(GL_SCISSOR_TEST);
    glScissor(drawn.x, frameHeight - drawn.w, width, height); // GL: bottom-up
    color_.bind(0);
    depth_.bind(1);
    vertexArray_.bind();
    if (image.pixels) {
        glDisable(GL_DEPTH_TEST);
        colorProgram_.use();
        colorProgram_.set("uColor", 0);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glEnable(GL_DEPTH_TEST);
    if (image.windowDepth) {
        glDepthFunc(GL_ALWAYS);
        glDepthMask(GL_TRUE);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        depthProgram_.use();
        depthProgram_.set("uDepth", 1);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDepthMask(GL_FALSE);
        glDepthFunc(GL_LESS);
        frame.shapes.countDraw(); // later volumes must read the depth written
    }
    if (!scissorWasOn) glDisable(GL_SCISSOR_TEST);
    glScissor(scissorBox[0], scissorBox[1], scissorBox[2], scissorBox[3]);
    VertexArray::unbind();
    glActiveTexture(GL_TEXTURE0);
}

} // namespace volsg
