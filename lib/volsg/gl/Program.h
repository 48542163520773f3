#pragma once
// A linked GLSL program with a cache of uniform locations.

#include <initializer_list>
#include <map>
#include <string>
#include <string_view>

#include <glm/glm.hpp>

#include <volsg/gl/GlName.h>

namespace volsg {

class Shader;

class Program {
public:
    Program() = default; ///< no program (no GL call)
    /// Links the shaders; a failed link throws Error naming `name`, with the info log.
    Program(std::initializer_list<const Shader*> shaders, std::string_view name);

    GLuint id() const { return name_.get(); }
    explicit operator bool() const { return bool(name_); }
    const std::string& name() const { return debugName_; }

    void use() const;

    /// The location of a uniform (-1 if the program has no active uniform of that name);
    /// looked up in GL once per name.
    GLint uniformLocation(std::string_view uniform) const;

    // Set a uniform of this program, which must be in use (GL 3.3 has no glProgramUniform
    // without ARB_separate_shader_objects). Unknown names are ignored, as GL does for -1.
    void set(std::string_view uniform, int value) const;
    void set(std::string_view uniform, float value) const;
    void set(std::string_view uniform, const glm::vec2& value) const;
    void set(std::string_view uniform, const glm::vec3& value) const;
    void set(std::string_view uniform, const glm::vec4& value) const;
    void set(std::string_view uniform, const glm::mat3& value) const;
    void set(std::string_view uniform, const glm::mat4& value) const;
    void set(std::string_view uniform, const glm::vec3* values, int count) const;
    void set(std::string_view uniform, const glm::vec4* values, int count) const;

private:
    GlName name_;
    std::string debugName_;
    mutable std::map<std::string, GLint, std::less<>> locations_;
};

} // namespace volsg
