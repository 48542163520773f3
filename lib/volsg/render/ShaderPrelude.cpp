#include <volsg/render/ShaderPrelude.h>

#include <algorithm>

#include <glm/gtc/type_ptr.hpp>

#include <volsg/core/Error.h>
#include <volsg/gl/Shader.h>
#include <volsg/render/SurfaceShaders.h>

namespace volsg {

int queryMaxClipPlanes(int limit) {
    GLint maxDistances = 8;
    glGetIntegerv(GL_MAX_CLIP_DISTANCES, &maxDistances);
    return std::clamp(int(maxDistances), 1, limit);
}

void SurfaceScope::setLights(std::span<const SceneLight> lights, std::string_view what,
                             std::string_view object) {
    if (lights.size() > std::size_t(kMaxSurfaceLights))
        throw Error(std::to_string(lights.size()) + " lights are in scope of " + std::string(what) +
                    "; at most " + std::to_string(kMaxSurfaceLights) + " light " +
                    std::string(object));
    lightCount = int(lights.size());
    for (std::size_t i = 0; i < lights.size(); ++i) {
        lightVectors[i] = lights[i].vector;
        lightColors[i] = lights[i].color;
    }
}

void SurfaceScope::setClipPlanes(std::span<const glm::dvec4> planes, int maxClipPlanes,
                                 std::string_view what) {
    if (planes.size() > std::size_t(maxClipPlanes))
        throw Error(std::to_string(planes.size()) + " ClipPlanes are in scope of " +
                    std::string(what) + ", but this OpenGL clips with at most " +
                    std::to_string(maxClipPlanes) + " (GL_MAX_CLIP_DISTANCES)");
    clipPlaneCount = int(planes.size());
    for (std::size_t i = 0; i < planes.size(); ++i)
        clipPlanes[i] = glm::vec4(planes[i]);
}

SurfaceScope::Locations SurfaceScope::Locations::of(const Program& program) {
    return {program.uniformLocation("uLightCount"), program.uniformLocation("uLightVector"),
            program.uniformLocation("uLightColor"), program.uniformLocation("uClipPlaneCount"),
            program.uniformLocation("uClipPlanes")};
}

void SurfaceScope::upload(const Locations& at) const {
    glUniform1i(at.lightCount, lightCount);
    if (lightCount > 0) {
        glUniform4fv(at.lightVector, lightCount, glm::value_ptr(lightVectors[0]));
        glUniform3fv(at.lightColor, lightCount, glm::value_ptr(lightColors[0]));
    }
    glUniform1i(at.clipPlaneCount, clipPlaneCount);
    if (clipPlaneCount > 0)
        glUniform4fv(at.clipPlanes, clipPlaneCount, glm::value_ptr(clipPlanes[0]));
}

namespace shaders {

std::string prelude(int maxClipPlanes) {
    return "#version 330 core\n#define MAX_LIGHTS " + std::to_string(kMaxSurfaceLights) +
           "\n#define MAX_CLIP_PLANES " + std::to_string(maxClipPlanes) + "\n";
}

Program surfaceProgram(const char* vertex, const char* fragment, int maxClipPlanes,
                       std::string_view name, std::string_view defines) {
    const std::string p = prelude(maxClipPlanes) + std::string(defines);
    const Shader vertexShader(GL_VERTEX_SHADER, p + surfaceVertex + vertex, name);
    const Shader fragmentShader(GL_FRAGMENT_SHADER, p + surfaceFragment + fragment, name);
    return Program({&vertexShader, &fragmentShader}, name);
}

} // namespace shaders

} // namespace volsg
