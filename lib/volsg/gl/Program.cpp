#include <volsg/core/Error.h>
#include <volsg/gl/Program.h>
#include <volsg/gl/Shader.h>

#include <vector>

#include <glm/gtc/type_ptr.hpp>

namespace volsg {

namespace {
void deleteProgram(GLuint name) {
    glDeleteProgram(name);
}
} // namespace

Program::Program(std::initializer_list<const Shader*> shaders, std::string_view name)
    : debugName_(name) {
    const GLuint id = glCreateProgram();
    if (id == 0) throw Error("glCreateProgram failed for the program '" + debugName_ + "'");
    name_ = GlName(id, deleteProgram);
    for (const Shader* s : shaders)
        glAttachShader(id, s->id());
    glLinkProgram(id);
    for (const Shader* s : shaders)
        glDetachShader(id, s->id());
    GLint ok = GL_FALSE;
    glGetProgramiv(id, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        GLint logLength = 0;
        glGetProgramiv(id, GL_INFO_LOG_LENGTH, &logLength);
        std::vector<GLchar> log(std::size_t(logLength > 1 ? logLength : 1), '\0');
        glGetProgramInfoLog(id, GLsizei(log.size()), nullptr, log.data());
        throw Error("linking the program '" + debugName_ + "' failed: " + std::string(log.data()));
    }
}

void Program::use() const {
    glUseProgram(name_.get());
}

GLint Program::uniformLocation(std::string_view uniform) const {
    if (auto it = locations_.find(uniform); it != locations_.end()) return it->second;
    const std::string key(uniform);
    const GLint location = glGetUniformLocation(name_.get(), key.c_str());
    locations_.emplace(key, location);
    return location;
}

void Program::set(std::string_view u, int v) const {
    glUniform1i(uniformLocation(u), v);
}
void Program::set(std::string_view u, float v) const {
    glUniform1f(uniformLocation(u), v);
}
void Program::set(std::string_view u, const glm::vec2& v) const {
    glUniform2fv(uniformLocation(u), 1, glm::value_ptr(v));
}
void Program::set(std::string_view u, const glm::vec3& v) const {
    glUniform3fv(uniformLocation(u), 1, glm::value_ptr(v));
}
void Program::set(std::string_view u, const glm::vec4& v) const {
    glUniform4fv(uniformLocation(u), 1, glm::value_ptr(v));
}
void Program::set(std::string_view u, const glm::mat3& v) const {
    glUniformMatrix3fv(uniformLocation(u), 1, GL_FALSE, glm::value_ptr(v));
}
void Program::set(std::string_view u, const glm::mat4& v) const {
    glUniformMatrix4fv(uniformLocation(u), 1, GL_FALSE, glm::value_ptr(v));
}
void Program::set(std::string_view u, const glm::vec3* v, int count) const {
    if (count > 0) glUniform3fv(uniformLocation(u), count, glm::value_ptr(v[0]));
}
void Program::set(std::string_view u, const glm::vec4* v, int count) const {
    if (count > 0) glUniform4fv(uniformLocation(u), count, glm::value_ptr(v[0]));
}

} // namespace volsg
