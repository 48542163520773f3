#pragma once
// GLSL of the shape program: Inventor's fixed-function Phong model, per fragment, with its
// texture models, spot lights, environment (ambient light, attenuation, fog). With INSTANCED
// defined, the model matrix and the material come per instance (batched draws).
// Each stage follows the prelude and the shared surface code (SurfaceShaders.h).

namespace volsg::shaders {

inline constexpr const char* shapeVertex = R"GLSL(
layout(location = 2) in vec4 aColor;

uniform mat4 uView;
uniform mat4 uTextureMatrix;

out vec2 vTexCoord;
out float vEyeDistance;

#ifdef INSTANCED
// The material per instance (ShapeRenderer's batched draws).
layout(location = 8) in vec4 aEmissiveShininess;
layout(location = 9) in vec4 aAmbient;
layout(location = 10) in vec4 aDiffuseAlpha;
layout(location = 11) in vec4 aSpecular;
flat out vec4 vEmissiveShininess;
flat out vec3 vAmbient;
flat out vec4 vDiffuseAlpha;
flat out vec3 vSpecular;
#endif

void main() {
#ifdef INSTANCED
    vEmissiveShininess = aEmissiveShininess;
    vAmbient = aAmbient.rgb;
    vDiffuseAlpha = aDiffuseAlpha;
    vSpecular = aSpecular.rgb;
#endif
    vec4 world = transformVertex();
    vColor = aColor;
    vTexCoord = (uTextureMatrix * vec4(aTexCoord0, 0.0, 1.0)).xy;
    vEyeDistance = -(uView * world).z;
}
)GLSL";

inline constexpr const char* shapeFragment = R"GLSL(
in vec2 vTexCoord;
in float vEyeDistance;

uniform bool uLit;        // false for lines and points without normals: emissive (0 then) + diffuse
uniform bool uHasNormals; // else flat normals from the screen-space derivatives
uniform bool uHasColors;  // vertex colours replace the diffuse colour
uniform bool uTwoSided;   // a face seen from behind is lit on that side (ShapeHints)
uniform bool uCullByNormal; // polygon edges drawn as lines: drop a back face's (its normal)
#ifdef INSTANCED
flat in vec4 vEmissiveShininess;
flat in vec3 vAmbient;
flat in vec4 vDiffuseAlpha;
flat in vec3 vSpecular;
#define uEmissive vEmissiveShininess.rgb
#define uShininess vEmissiveShininess.a
#define uAmbient vAmbient
#define uDiffuse vDiffuseAlpha.rgb
#define uAlpha vDiffuseAlpha.a
#define uSpecular vSpecular
#else
uniform vec3 uEmissive;
uniform vec3 uAmbient;    // material ambient times the environment's ambient light
uniform vec3 uDiffuse;
uniform vec3 uSpecular;
uniform float uShininess; // the exponent: Inventor's shininess * 128
uniform float uAlpha;     // 1 - transparency
#endif
uniform mat4 uView;
uniform vec4 uSpot[MAX_LIGHTS];        // direction the spot points (xyz), cos of cut-off (w)
uniform float uSpotExponent[MAX_LIGHTS];
uniform vec3 uAttenuation;             // squared, linear, constant (SoEnvironment)
// Texture: -1 none, 0 MODULATE, 1 DECAL, 2 BLEND, 3 REPLACE.
uniform int uTextureModel;
uniform bool uSphereMap; // TextureCoordinateEnvironment: coordinates from the reflection
uniform sampler2D uTexture;
uniform vec3 uBlendColor;
// Fog: 0 none, 1 HAZE, 2 FOG, 3 SMOKE.
uniform int uFogType;
uniform vec3 uFogColor;
uniform float uFogVisibility;

out vec4 fragColor;

vec4 textured(vec4 lit, vec3 N) {
    if (uTextureModel < 0) return lit;
    vec2 st = vTexCoord;
    if (uSphereMap) {
        vec3 u = normalize((uView * vec4(vWorldPosition, 1.0)).xyz);
        vec3 n = normalize(mat3(uView) * N);
        vec3 r = reflect(u, n);
        float m = 2.0 * sqrt(r.x * r.x + r.y * r.y + (r.z + 1.0) * (r.z + 1.0));
        st = m > 0.0 ? r.xy / m + 0.5 : vec2(0.5);
    }
    vec4 t = texture(uTexture, st);
    if (uTextureModel == 0) return lit * t;
    if (uTextureModel == 1) return vec4(mix(lit.rgb, t.rgb, t.a), lit.a);
    if (uTextureModel == 2) return vec4(mix(lit.rgb, uBlendColor, t.rgb), lit.a * t.a);
    return t;
}

vec3 fogged(vec3 color) {
    if (uFogType == 0) return color;
    float v = uFogVisibility;
    float d = max(vEyeDistance, 0.0);
    float f; // how much of the colour remains
    if (uFogType == 1) f = v > 0.0 ? clamp(1.0 - d / v, 0.0, 1.0) : 1.0;
    else if (uFogType == 2) f = v > 0.0 ? exp(-4.0 * d / v) : 1.0;
    else f = v > 0.0 ? exp(-(2.0 * d / v) * (2.0 * d / v)) : 1.0;
    return mix(uFogColor, color, f);
}

void main() {
    vec3 diffuse = uHasColors ? vColor.rgb : uDiffuse;
    // Per-vertex colours carry their material's alpha (ShapeState's materialColor).
    float alpha = uHasColors ? vColor.a : uAlpha;
    vec3 V = towardsViewer();
    if (uCullByNormal && dot(vWorldNormal, V) < 0.0) discard;
    vec3 N = uHasNormals ? vWorldNormal : vec3(0.0);
    bool derived = dot(N, N) <= 0.0;
    if (derived) N = cross(dFdx(vWorldPosition), dFdy(vWorldPosition));
    N = dot(N, N) > 0.0 ? normalize(N) : V;
    // Two-sided lighting lights the side facing the viewer. One-sided (Inventor's default,
    // as Coin) keeps the given normal, so the inside of an open mesh is dark; a normal derived
    // from the screen has no side and always faces the viewer.
    if ((uTwoSided || derived) && dot(N, V) < 0.0) N = -N;
    if (!uLit) {
        vec4 unlit = textured(vec4(uEmissive + diffuse, alpha), N);
        fragColor = vec4(fogged(unlit.rgb), unlit.a);
        return;
    }

    vec3 color = uEmissive + uAmbient;
    for (int i = 0; i < uLightCount; ++i) {
        vec3 toLight = lightVector(i);
        vec3 L = normalize(toLight);
        float NdotL = dot(N, L);
        if (NdotL <= 0.0) continue; // no diffuse and, as in OpenGL, no specular
        float strength = 1.0;
        if (uLightVector[i].w != 0.0) {
            float d = length(toLight);
            float a = uAttenuation.z + uAttenuation.y * d + uAttenuation.x * d * d;
            strength = a > 0.0 ? 1.0 / a : 1.0;
            float spotCos = dot(-L, uSpot[i].xyz);
            if (spotCos < uSpot[i].w) continue; // outside the cone
            if (uSpotExponent[i] > 0.0) strength *= pow(max(spotCos, 0.0), uSpotExponent[i]);
        }
        float NdotH = max(dot(N, normalize(L + V)), 0.0);
        float specular = NdotH > 0.0 ? pow(NdotH, uShininess) : (uShininess == 0.0 ? 1.0 : 0.0);
        color += strength * uLightColor[i] * (diffuse * NdotL + uSpecular * specular);
    }
    vec4 lit = textured(vec4(color, alpha), N);
    fragColor = vec4(fogged(lit.rgb), lit.a);
}
)GLSL";

} // namespace volsg::shaders
