#pragma once
// One compiled GLSL shader stage.

#include <string>
#include <string_view>

#include <volsg/gl/GlName.h>

namespace volsg {

class Shader {
public:
    Shader() = default; ///< no shader (no GL call)
    /// Compiles `source` for `stage` (GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, ...). A failed
    /// compile throws Error naming `name` and the stage, with the driver's info log.
    Shader(GLenum stage, std::string_view source, std::string_view name);

    GLuint id() const { return name_.get(); }
    GLenum stage() const { return stage_; }
    explicit operator bool() const { return bool(name_); }

    /// "vertex", "fragment", ... for messages.
    static const char* stageName(GLenum stage);

private:
    GlName name_;
    GLenum stage_ = 0;
};

} // namespace volsg
