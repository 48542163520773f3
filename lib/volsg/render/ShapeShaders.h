#pragma once
// GLSL of the shape program: Inventor's fixed-function Phong model, per fragment.
// Compiled with "#version 330 core" and the MAX_LIGHTS / MAX_CLIP_PLANES defines in front.

namespace volsg::shaders {

inline constexpr const char* shapeVertex = R"GLSL(
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec4 aColor;

uniform mat4 uModel;
uniform mat3 uNormalMatrix;
uniform mat4 uViewProjection;
uniform vec4 uClipPlanes[MAX_CLIP_PLANES]; // world (n, d): keep dot(n, p) >= d
uniform int uClipPlaneCount;

out vec3 vWorldPosition;
out vec3 vWorldNormal;
out vec4 vColor;
out float gl_ClipDistance[MAX_CLIP_PLANES];

void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vWorldPosition = world.xyz;
    vWorldNormal = uNormalMatrix * aNormal;
    vColor = aColor;
    for (int i = 0; i < MAX_CLIP_PLANES; ++i)
        gl_ClipDistance[i] =
            i < uClipPlaneCount ? dot(uClipPlanes[i].xyz, world.xyz) - uClipPlanes[i].w : 1.0;
    gl_Position = uViewProjection * world;
}
)GLSL";

inline constexpr const char* shapeFragment = R"GLSL(
in vec3 vWorldPosition;
in vec3 vWorldNormal;
in vec4 vColor;

uniform bool uLit;        // false for lines: emissive + diffuse
uniform bool uHasNormals; // else flat normals from the screen-space derivatives
uniform bool uHasColors;  // vertex colours replace the diffuse colour
uniform vec3 uEmissive;
uniform vec3 uAmbient;    // material ambient times the environment's 0.2
uniform vec3 uDiffuse;
uniform vec3 uSpecular;
uniform float uShininess; // the exponent: Inventor's shininess * 128
uniform float uAlpha;     // 1 - transparency
uniform vec4 uViewer;     // eye position (w = 1) or direction towards the viewer (w = 0)
uniform int uLightCount;
uniform vec4 uLightVector[MAX_LIGHTS]; // position (w = 1) or direction towards the light (w = 0)
uniform vec3 uLightColor[MAX_LIGHTS];  // intensity * colour

out vec4 fragColor;

void main() {
    vec3 diffuse = uHasColors ? vColor.rgb : uDiffuse;
    float alpha = uAlpha * (uHasColors ? vColor.a : 1.0);
    if (!uLit) {
        fragColor = vec4(uEmissive + diffuse, alpha);
        return;
    }
    vec3 V = normalize(uViewer.xyz - vWorldPosition * uViewer.w);
    vec3 N = uHasNormals ? vWorldNormal : vec3(0.0);
    if (dot(N, N) <= 0.0) N = cross(dFdx(vWorldPosition), dFdy(vWorldPosition));
    N = dot(N, N) > 0.0 ? normalize(N) : V;
    // Two-sided lighting: the side facing the viewer is lit, so open or inverted meshes are
    // not black inside.
    if (dot(N, V) < 0.0) N = -N;

    vec3 color = uEmissive + uAmbient;
    for (int i = 0; i < uLightCount; ++i) {
        vec3 L = normalize(uLightVector[i].xyz - vWorldPosition * uLightVector[i].w);
        float NdotL = dot(N, L);
        if (NdotL <= 0.0) continue; // no diffuse and, as in OpenGL, no specular
        float NdotH = max(dot(N, normalize(L + V)), 0.0);
        float specular = NdotH > 0.0 ? pow(NdotH, uShininess) : (uShininess == 0.0 ? 1.0 : 0.0);
        color += uLightColor[i] * (diffuse * NdotL + uSpecular * specular);
    }
    fragColor = vec4(color, alpha);
}
)GLSL";

} // namespace volsg::shaders
