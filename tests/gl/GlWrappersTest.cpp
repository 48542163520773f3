// RAII wrappers and GL error reporting, under an OSMesa context.
#include <doctest/doctest.h>

#include <volsg/context/OSMesaContext.h>
#include <volsg/core/Error.h>
#include <volsg/gl/Buffer.h>
#include <volsg/gl/Framebuffer.h>
#include <volsg/gl/GlDebug.h>
#include <volsg/gl/Program.h>
#include <volsg/gl/Renderbuffer.h>
#include <volsg/gl/Shader.h>
#include <volsg/gl/Texture.h>
#include <volsg/gl/VertexArray.h>

#include <array>
#include <utility>
#include <vector>

using namespace volsg;

namespace {

const char* kVertex = R"(#version 330 core
layout(location = 0) in vec2 aPosition;
void main() { gl_Position = vec4(aPosition, 0.0, 1.0); }
)";

/// Samples a 3D texture at a uniform coordinate and writes the red channel everywhere.
const char* kSample3D = R"(#version 330 core
uniform sampler3D uVolume;
uniform vec3 uCoord;
uniform vec4 uScale;
out vec4 color;
void main() { color = vec4(texture(uVolume, uCoord).r) * uScale; }
)";

struct FloatTarget {
    Renderbuffer color{GL_RGBA32F, 8, 8};
    Framebuffer fb = Framebuffer::create();
    FloatTarget() {
        fb.attach(GL_COLOR_ATTACHMENT0, color);
        fb.requireComplete("FloatTarget");
        glViewport(0, 0, 8, 8);
    }
    glm::vec4 read(int x, int y) const {
        glm::vec4 v(-1.0f);
        glReadPixels(x, y, 1, 1, GL_RGBA, GL_FLOAT, &v[0]);
        return v;
    }
};

} // namespace

TEST_CASE("a shader that does not compile throws an Error with the info log") {
    OSMesaContext context;
    const char* broken = "#version 330 core\nvoid main() { this_is_not_glsl = 1; }\n";
    try {
        Shader shader(GL_FRAGMENT_SHADER, broken, "broken");
        FAIL("no error");
    } catch (const Error& e) {
        const std::string what = e.what();
        CHECK(what.find("fragment shader 'broken'") != std::string::npos);
        CHECK(what.find("this_is_not_glsl") != std::string::npos); // the driver's log
    }
}

TEST_CASE("a program that does not link throws an Error naming it") {
    OSMesaContext context;
    const Shader vertex(GL_VERTEX_SHADER, kVertex, "vertex");
    const Shader fragment(GL_FRAGMENT_SHADER,
                          "#version 330 core\nvoid helper();\nout vec4 c;\n"
                          "void main() { helper(); c = vec4(1.0); }\n",
                          "missing-helper");
    CHECK_THROWS_WITH_AS(Program({&vertex, &fragment}, "unlinkable"),
                         doctest::Contains("linking the program 'unlinkable' failed"), Error);
}

TEST_CASE("a program draws a triangle from a buffer through a vertex array") {
    OSMesaContext context;
    FloatTarget target;
    const Shader vertex(GL_VERTEX_SHADER, kVertex, "vertex");
    const Shader fragment(GL_FRAGMENT_SHADER,
                          "#version 330 core\nuniform vec4 uColor;\nout vec4 c;\n"
                          "void main() { c = uColor; }\n",
                          "flat");
    Program program({&vertex, &fragment}, "flat");
    // A triangle covering the left half of the viewport: x <= 0 in clip space.
    const std::vector<glm::vec2> corners{{-1, -1}, {0, -1}, {0, 3}, {-1, 3}};
    const std::vector<std::uint32_t> indices{0, 1, 2, 0, 2, 3};
    Buffer positions(GL_ARRAY_BUFFER);
    positions.setData(corners);
    CHECK(positions.size() == corners.size() * sizeof(glm::vec2));
    Buffer elements(GL_ELEMENT_ARRAY_BUFFER);
    VertexArray vao = VertexArray::create();
    vao.setAttribute(0, positions, 2);
    vao.setIndexBuffer(elements);
    elements.setData(indices);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    program.use();
    program.set("uColor", glm::vec4(0.25f, 0.5f, 0.75f, 1.0f));
    CHECK(program.uniformLocation("uColor") >= 0);
    CHECK(program.uniformLocation("uNoSuchUniform") == -1);
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_INT, nullptr);
    checkGlError("draw");
    CHECK(target.read(1, 4) == glm::vec4(0.25f, 0.5f, 0.75f, 1.0f));
    CHECK(target.read(6, 4) == glm::vec4(0.0f));
}

TEST_CASE("a 3D float texture samples trilinearly between texel centres") {
    OSMesaContext context;
    FloatTarget target;
    // 2x2x2 texels with value = x + 2y + 4z.
    std::array<float, 8> values{};
    for (int i = 0; i < 8; ++i)
        values[std::size_t(i)] = float(i);
    Texture volume(GL_TEXTURE_3D);
    volume.image3D(GL_R32F, 2, 2, 2, GL_RED, GL_FLOAT, values.data());
    CHECK(volume.width() == 2);
    CHECK(volume.depth() == 2);
    const Shader vertex(GL_VERTEX_SHADER, kVertex, "vertex");
    const Shader fragment(GL_FRAGMENT_SHADER, kSample3D, "sample3d");
    Program program({&vertex, &fragment}, "sample3d");
    Buffer quad(GL_ARRAY_BUFFER);
    quad.setData(std::vector<glm::vec2>{{-1, -1}, {3, -1}, {-1, 3}});
    VertexArray vao = VertexArray::create();
    vao.setAttribute(0, quad, 2);
    program.use();
    volume.bind(0);
    program.set("uVolume", 0);
    program.set("uScale", glm::vec4(1.0f));
    // Texel centres are at 0.25 and 0.75. The box centre is the mean of all eight (3.5);
    // (0.5, 0.25, 0.25) lies halfway between texels x = 0 and 1 of the first row: 0.5.
    program.set("uCoord", glm::vec3(0.5f));
    glDrawArrays(GL_TRIANGLES, 0, 3);
    CHECK(target.read(3, 3).r == doctest::Approx(3.5f).epsilon(1e-5));
    program.set("uCoord", glm::vec3(0.5f, 0.25f, 0.25f));
    glDrawArrays(GL_TRIANGLES, 0, 3);
    CHECK(target.read(3, 3).r == doctest::Approx(0.5f).epsilon(1e-5));
    // Replacing one texel with subImage changes the corner value (clamped to the edge).
    const float nine = 9.0f;
    volume.subImage(1, 1, 1, 1, 1, 1, GL_RED, GL_FLOAT, &nine);
    program.set("uCoord", glm::vec3(1.0f));
    glDrawArrays(GL_TRIANGLES, 0, 3);
    CHECK(target.read(3, 3).r == doctest::Approx(9.0f).epsilon(1e-6));
    checkGlError("sampling");
    CHECK_THROWS_AS(volume.subImage(1, 1, 1, 2, 1, 1, GL_RED, GL_FLOAT, &nine), Error);
}

TEST_CASE("subImage uploads a rectangle of a larger image by its row length") {
    OSMesaContext context;
    Texture texture(GL_TEXTURE_2D);
    const std::vector<float> zeros(4 * 3, 0.0f);
    texture.image2D(GL_R32F, 4, 3, GL_RED, GL_FLOAT, zeros.data());
    // A 5 x 3 image whose texel (x, y) holds 10 y + x; its 2 x 2 rectangle at (2, 1) goes to
    // texels (1, 1)-(2, 2).
    std::vector<float> image(5 * 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x)
            image[std::size_t(y * 5 + x)] = float(10 * y + x);
    texture.subImage(1, 1, 0, 2, 2, 1, GL_RED, GL_FLOAT, image.data() + 1 * 5 + 2, 5);
    GLint rowLength = -1;
    glGetIntegerv(GL_UNPACK_ROW_LENGTH, &rowLength);
    CHECK(rowLength == 0); // restored
    std::vector<float> read(4 * 3, -1.0f);
    texture.bind(0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RED, GL_FLOAT, read.data());
    checkGlError("read back");
    const std::vector<float> expected{0, 0,  0,  0, //
                                      0, 12, 13, 0, //
                                      0, 22, 23, 0};
    CHECK(read == expected);
    CHECK_THROWS_AS(texture.subImage(0, 0, 0, 3, 1, 1, GL_RED, GL_FLOAT, image.data(), 2), Error);
}

TEST_CASE("an incomplete framebuffer throws an Error with its status") {
    OSMesaContext context;
    Framebuffer fb = Framebuffer::create();
    CHECK_THROWS_WITH_AS(fb.requireComplete("empty"),
                         doctest::Contains("GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT"), Error);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_CASE("GL error checking turns a bad GL call into an Error") {
    OSMesaContext context;
    CHECK(enableGlErrorChecking());
    checkGlError("before"); // nothing pending
    glEnable(GL_NONE);      // GL_INVALID_ENUM
    try {
        checkGlError("after glEnable(GL_NONE)");
        FAIL("no error");
    } catch (const Error& e) {
        const std::string what = e.what();
        CHECK(what.find("after glEnable(GL_NONE)") != std::string::npos);
        CHECK(what.find("GL_INVALID_ENUM") != std::string::npos);
        CHECK(what.find("GL debug error") != std::string::npos); // the KHR_debug message
    }
    checkGlError("cleared"); // reported once, then gone
}

TEST_CASE("wrappers delete their GL objects and move ownership") {
    OSMesaContext context;
    GLuint name = 0;
    {
        Texture a(GL_TEXTURE_2D);
        name = a.id();
        CHECK(glIsTexture(name) == GL_TRUE);
        Texture b = std::move(a);
        CHECK(b.id() == name);
        CHECK_FALSE(a);
        CHECK(glIsTexture(name) == GL_TRUE);
    }
    CHECK(glIsTexture(name) == GL_FALSE);
    Buffer empty;
    CHECK_FALSE(empty);
    CHECK(empty.id() == 0u);
}
