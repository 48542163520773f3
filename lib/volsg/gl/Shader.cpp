#include <volsg/core/Error.h>
#include <volsg/gl/Shader.h>

#include <vector>

namespace volsg {

namespace {
void deleteShader(GLuint name) {
    glDeleteShader(name);
}
} // namespace

const char* Shader::stageName(GLenum stage) {
    switch (stage) {
    case GL_VERTEX_SHADER:
        return "vertex";
    case GL_FRAGMENT_SHADER:
        return "fragment";
    case GL_GEOMETRY_SHADER:
        return "geometry";
    case GL_COMPUTE_SHADER:
        return "compute";
    case GL_TESS_CONTROL_SHADER:
        return "tessellation control";
    case GL_TESS_EVALUATION_SHADER:
        return "tessellation evaluation";
    default:
        return "unknown-stage";
    }
}

Shader::Shader(GLenum stage, std::string_view source, std::string_view name) : stage_(stage) {
    const GLuint id = glCreateShader(stage);
    if (id == 0)
        throw Error("glCreateShader failed for the " + std::string(stageName(stage)) + " shader '" +
                    std::string(name) + "'");
    name_ = GlName(id, deleteShader);
    const GLchar* text = source.data();
    const GLint length = GLint(source.size());
    glShaderSource(id, 1, &text, &length);
    glCompileShader(id);
    GLint ok = GL_FALSE;
    glGetShaderiv(id, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        GLint logLength = 0;
        glGetShaderiv(id, GL_INFO_LOG_LENGTH, &logLength);
        std::vector<GLchar> log(std::size_t(logLength > 1 ? logLength : 1), '\0');
        glGetShaderInfoLog(id, GLsizei(log.size()), nullptr, log.data());
        throw Error("compiling the " + std::string(stageName(stage)) + " shader '" +
                    std::string(name) + "' failed: " + std::string(log.data()));
    }
}

} // namespace volsg
