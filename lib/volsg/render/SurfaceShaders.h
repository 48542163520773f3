#pragma once
// GLSL that the surface programs (ShapeShaders.h, lib/volsg/gltf/GltfShaders.h) share, compiled
// after the prelude and before each program's own source (shaders::surfaceProgram,
// ShaderPrelude.h).

namespace volsg::shaders {

/// Vertex stage, after the prelude: the attributes both programs have (position 0, normal 1,
/// first texture coordinates 3), the model (a uniform, or with INSTANCED defined a per-instance
/// attribute at 4), normal and view-projection matrices and the clip planes; transformVertex()
/// writes the world position and normal, gl_ClipDistance and gl_Position, and returns the world
/// position (and, unless NO_CLIP_PLANES is defined, the clip distances). The program sets
/// vColor.
inline constexpr const char* surfaceVertex = R"GLSL(
#ifdef INSTANCED
layout(location = 4) in mat4 aModel; // per instance (locations 4 to 7)
#else
uniform mat4 uModel;
uniform mat3 uNormalMatrix;
#endif
uniform mat4 uViewProjection;
uniform vec4 uClipPlanes[MAX_CLIP_PLANES]; // world (n, d): keep dot(n, p) >= d
uniform int uClipPlaneCount;

out vec3 vWorldPosition;
out vec3 vWorldNormal;
out vec4 vColor;
out float gl_ClipDistance[MAX_CLIP_PLANES];

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 3) in vec2 aTexCoord0;

vec4 transformVertex() {
#ifdef INSTANCED
    // The cofactor matrix of the model's 3x3 part maps normals (ShapeRenderer.cpp says why).
    mat4 uModel = aModel;
    mat3 m = mat3(aModel);
    mat3 uNormalMatrix = mat3(cross(m[1], m[2]), cross(m[2], m[0]), cross(m[0], m[1]));
#endif
    vec4 world = uModel * vec4(aPosition, 1.0);
    vWorldPosition = world.xyz;
    vWorldNormal = uNormalMatrix * aNormal;
#ifndef NO_CLIP_PLANES
    // Planes beyond the count read 1: harmless if a shape left their switch on.
    for (int i = 0; i < MAX_CLIP_PLANES; ++i)
        gl_ClipDistance[i] =
            i < uClipPlaneCount ? dot(uClipPlanes[i].xyz, world.xyz) - uClipPlanes[i].w : 1.0;
#endif
    gl_Position = uViewProjection * world;
    return world;
}
)GLSL";

/// Fragment stage, after the prelude: the world position, normal and colour, the viewer and the
/// scene's lights; towardsViewer() is the unit vector from the fragment to the viewer,
/// lightVector(i) the vector from it to light i (its direction for a directional light).
inline constexpr const char* surfaceFragment = R"GLSL(
in vec3 vWorldPosition;
in vec3 vWorldNormal;
in vec4 vColor;

uniform vec4 uViewer; // eye position (w = 1) or direction towards the viewer (w = 0)
uniform int uLightCount;
uniform vec4 uLightVector[MAX_LIGHTS]; // position (w = 1) or direction towards the light (w = 0)
uniform vec3 uLightColor[MAX_LIGHTS];  // intensity * colour

vec3 towardsViewer() { return normalize(uViewer.xyz - vWorldPosition * uViewer.w); }

vec3 lightVector(int i) { return uLightVector[i].xyz - vWorldPosition * uLightVector[i].w; }
)GLSL";

} // namespace volsg::shaders
