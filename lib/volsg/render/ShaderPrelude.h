#pragma once
// What the programs that draw surfaces (shapes, glTF models) share: the GLSL prelude they are
// compiled with and their common code (SurfaceShaders.h), the values of its light and
// clip-plane uniforms for one draw, and how many clip planes this OpenGL lets a vertex shader
// write.

#include <array>
#include <span>
#include <string>
#include <string_view>

#include <glm/glm.hpp>

#include <volsg/gl/Program.h>
#include <volsg/render/FrameContext.h>

namespace volsg {

/// The most lights a surface is lit by (MAX_LIGHTS).
inline constexpr int kMaxSurfaceLights = 8;
/// The most clip planes a surface program takes; MAX_CLIP_PLANES is GL_MAX_CLIP_DISTANCES up
/// to this.
inline constexpr int kMaxSurfaceClipPlanes = 16;

/// GL_MAX_CLIP_DISTANCES of the current context (8 if it says nothing), within [1, limit].
int queryMaxClipPlanes(int limit);

/// The lights and clip planes of one draw, as the shared GLSL's uniforms take them (world).
struct SurfaceScope {
    int lightCount = 0;
    std::array<glm::vec4, kMaxSurfaceLights> lightVectors{};
    std::array<glm::vec3, kMaxSurfaceLights> lightColors{};
    int clipPlaneCount = 0;
    std::array<glm::vec4, kMaxSurfaceClipPlanes> clipPlanes{};

    /// Takes `lights`; more than kMaxSurfaceLights throw Error "N lights are in scope of
    /// `what`; at most 8 light `object`".
    void setLights(std::span<const SceneLight> lights, std::string_view what,
                   std::string_view object);
    /// Takes `planes`; more than `maxClipPlanes` throw Error "N ClipPlanes are in scope of
    /// `what`, but this OpenGL clips with at most M (GL_MAX_CLIP_DISTANCES)".
    void setClipPlanes(std::span<const glm::dvec4> planes, int maxClipPlanes,
                       std::string_view what);

    /// Where a program keeps these uniforms.
    struct Locations {
        GLint lightCount, lightVector, lightColor, clipPlaneCount, clipPlanes;
        static Locations of(const Program& program);
    };
    /// Sets them in the program in use (which `at` belongs to).
    void upload(const Locations& at) const;
};

namespace shaders {

/// "#version 330 core" and the MAX_LIGHTS and MAX_CLIP_PLANES defines, in front of every stage.
std::string prelude(int maxClipPlanes);

/// A surface program: each stage is the prelude, `defines` ("#define INSTANCED\n"), the shared
/// code (SurfaceShaders.h:
/// surfaceVertex, surfaceFragment) and the stage's own source. A failed compile or link throws
/// Error naming `name`.
Program surfaceProgram(const char* vertex, const char* fragment, int maxClipPlanes,
                       std::string_view name, std::string_view defines = {});

} // namespace shaders

} // namespace volsg
