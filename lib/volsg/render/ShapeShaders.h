#pragma once
// GLSL of the shape program: Inventor's fixed-function Phong model, with its texture models,
// spot lights, environment (ambient light, attenuation, fog). With INSTANCED defined, the
// model matrix and the material come per instance (batched draws). The lights are summed per
// fragment, or with VERTEX_LIGHTING defined per vertex, as Inventor's OpenGL does, where that
// matches within the stated tolerance (VertexLighting.h).
// Each stage follows the prelude and the shared surface code (SurfaceShaders.h); the lights'
// sum (shapeLighting) sits between a stage's declarations and its main. The program is
// specialised per draw (ShapeRenderer::variant): LIT, HAS_NORMALS, HAS_COLORS, TWO_SIDED,
// CULL_BY_NORMAL, TEXTURED, SPHERE_MAP and FOG are defined true or false, so that a software
// rasteriser runs no code a draw does not need (uniform branches cost it every fragment).

namespace volsg::shaders {

/// The sum over the lights in scope at world point P with unit normal N and unit V (towards
/// the viewer), without emissive and ambient (ShapeRenderer.h gives the model). Uses
/// LIGHT_COUNT, POSITIONAL_LIGHTS, SPECULAR, uLightVector, uLightColor, uSpot, uSpotExponent and
/// uAttenuation.
inline constexpr const char* shapeLighting = R"GLSL(
vec3 sumOfLights(vec3 P, vec3 N, vec3 V, vec3 diffuse, vec3 specularColor, float shininess) {
    vec3 color = vec3(0.0);
    // LIGHT_COUNT and POSITIONAL_LIGHTS are the draw's (ShapeRenderer::useVariant): a loop
    // of known length, and no attenuation or cone code for directional lights alone.
    for (int i = 0; i < LIGHT_COUNT; ++i) {
        vec3 toLight = uLightVector[i].xyz - P * uLightVector[i].w;
        // Directional lights come unit length (RenderAction::lightsInScope).
        vec3 L = POSITIONAL_LIGHTS ? normalize(toLight) : toLight;
        float NdotL = dot(N, L);
        if (NdotL <= 0.0) continue; // no diffuse and, as in OpenGL, no specular
        float strength = 1.0;
        if (POSITIONAL_LIGHTS && uLightVector[i].w != 0.0) {
            float d = length(toLight);
            float a = uAttenuation.z + uAttenuation.y * d + uAttenuation.x * d * d;
            strength = a > 0.0 ? 1.0 / a : 1.0;
            float spotCos = dot(-L, uSpot[i].xyz);
            if (spotCos < uSpot[i].w) continue; // outside the cone
            if (uSpotExponent[i] > 0.0) strength *= pow(max(spotCos, 0.0), uSpotExponent[i]);
        }
        vec3 lit = diffuse * NdotL;
        if (SPECULAR) { // false: the specular colour is black, no power to take
            float NdotH = max(dot(N, normalize(L + V)), 0.0);
            float specular =
                NdotH > 0.0 ? pow(NdotH, shininess) : (shininess == 0.0 ? 1.0 : 0.0);
            lit += specularColor * specular;
        }
        color += strength * uLightColor[i] * lit;
    }
    return color;
}
)GLSL";

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

#ifdef VERTEX_LIGHTING
uniform vec4 uViewer;
uniform int uLightCount;
uniform vec4 uLightVector[MAX_LIGHTS];
uniform vec3 uLightColor[MAX_LIGHTS];
uniform vec4 uSpot[MAX_LIGHTS];
uniform float uSpotExponent[MAX_LIGHTS];
uniform vec3 uAttenuation;
#ifdef INSTANCED
#define mEmissive aEmissiveShininess.rgb
#define mShininess aEmissiveShininess.a
#define mAmbient aAmbient.rgb
#define mDiffuse aDiffuseAlpha.rgb
#define mAlpha aDiffuseAlpha.a
#define mSpecular aSpecular.rgb
#else
uniform vec3 uEmissive;
uniform vec3 uAmbient;
uniform vec3 uDiffuse;
uniform vec3 uSpecular;
uniform float uShininess;
uniform float uAlpha;
#define mEmissive uEmissive
#define mShininess uShininess
#define mAmbient uAmbient
#define mDiffuse uDiffuse
#define mAlpha uAlpha
#define mSpecular uSpecular
#endif
out vec4 vFrontColor; // lit with the normal
out vec4 vBackColor;  // lit with the normal turned around (two-sided lighting)
#endif
)GLSL";

inline constexpr const char* shapeVertexMain = R"GLSL(
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
#ifdef VERTEX_LIGHTING
    // Chosen only for meshes with nonzero normals (VertexLighting.h).
    vec3 N = normalize(vWorldNormal);
    // ORTHOGRAPHIC: the viewer is a unit direction (Renderer).
    vec3 V = ORTHOGRAPHIC ? uViewer.xyz : normalize(uViewer.xyz - world.xyz * uViewer.w);
    vec3 diffuse = HAS_COLORS ? aColor.rgb : mDiffuse;
    float alpha = HAS_COLORS ? aColor.a : mAlpha;
    vec3 base = mEmissive + mAmbient;
    vFrontColor = vec4(base + sumOfLights(world.xyz, N, V, diffuse, mSpecular, mShininess), alpha);
    vBackColor = TWO_SIDED
        ? vec4(base + sumOfLights(world.xyz, -N, V, diffuse, mSpecular, mShininess), alpha)
        : vFrontColor;
#endif
}
)GLSL";

inline constexpr const char* shapeFragment = R"GLSL(
in vec2 vTexCoord;
#ifdef VERTEX_LIGHTING
in vec4 vFrontColor;
in vec4 vBackColor;
#endif
in float vEyeDistance;

// LIT: false for lines and points without normals: emissive (0 then) + diffuse.
// HAS_NORMALS: else flat normals from the screen-space derivatives (NONZERO_NORMALS: none of
// them is zero).
// SPECULAR: the specular colour is not black. ORTHOGRAPHIC: the view's.
// HAS_COLORS: vertex colours replace the diffuse colour.
// TWO_SIDED: a face seen from behind is lit on that side (ShapeHints).
// CULL_BY_NORMAL: polygon edges drawn as lines: drop a back face's (by its normal).
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
// Texture (TEXTURED): 0 MODULATE, 1 DECAL, 2 BLEND, 3 REPLACE; SPHERE_MAP:
// TextureCoordinateEnvironment, coordinates from the reflection.
uniform int uTextureModel;
uniform sampler2D uTexture;
uniform vec3 uBlendColor;
// Fog (FOG): 1 HAZE, 2 FOG, 3 SMOKE.
uniform int uFogType;
uniform vec3 uFogColor;
uniform float uFogVisibility;

out vec4 fragColor;
)GLSL";

inline constexpr const char* shapeFragmentMain = R"GLSL(
vec4 textured(vec4 lit, vec3 N) {
    if (!TEXTURED) return lit;
    vec2 st = vTexCoord;
    if (SPHERE_MAP) {
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
    if (!FOG) return color;
    float v = uFogVisibility;
    float d = max(vEyeDistance, 0.0);
    float f; // how much of the colour remains
    if (uFogType == 1) f = v > 0.0 ? clamp(1.0 - d / v, 0.0, 1.0) : 1.0;
    else if (uFogType == 2) f = v > 0.0 ? exp(-4.0 * d / v) : 1.0;
    else f = v > 0.0 ? exp(-(2.0 * d / v) * (2.0 * d / v)) : 1.0;
    return mix(uFogColor, color, f);
}

void main() {
    vec3 V = ORTHOGRAPHIC ? uViewer.xyz : towardsViewer();
    if (CULL_BY_NORMAL && dot(vWorldNormal, V) < 0.0) discard;
#ifdef VERTEX_LIGHTING
    // Lit per vertex only with nonzero normals (VertexLighting.h): none is derived here.
    vec3 N = vWorldNormal;
    bool back = TWO_SIDED && dot(N, V) < 0.0;
    if (back) N = -N;
    if (SPHERE_MAP) N = normalize(N);
    vec4 lit = textured(back ? vBackColor : vFrontColor, N);
#else
    vec3 diffuse = HAS_COLORS ? vColor.rgb : uDiffuse;
    // Per-vertex colours carry their material's alpha (ShapeState's materialColor).
    float alpha = HAS_COLORS ? vColor.a : uAlpha;
    vec3 N = HAS_NORMALS ? vWorldNormal : vec3(0.0);
    // NONZERO_NORMALS: the mesh has no zero normal, none is derived from the screen.
    bool derived = !NONZERO_NORMALS && dot(N, N) <= 0.0;
    if (derived) N = cross(dFdx(vWorldPosition), dFdy(vWorldPosition));
    N = dot(N, N) > 0.0 ? normalize(N) : V;
    // Two-sided lighting lights the side facing the viewer. One-sided (Inventor's default,
    // as Coin) keeps the given normal, so the inside of an open mesh is dark; a normal derived
    // from the screen has no side and always faces the viewer.
    if ((TWO_SIDED || derived) && dot(N, V) < 0.0) N = -N;
    if (!LIT) {
        vec4 unlit = textured(vec4(uEmissive + diffuse, alpha), N);
        fragColor = vec4(fogged(unlit.rgb), unlit.a);
        return;
    }
    vec3 color = uEmissive + uAmbient + sumOfLights(vWorldPosition, N, V, diffuse, uSpecular,
                                                    uShininess);
    vec4 lit = textured(vec4(color, alpha), N);
#endif
    fragColor = vec4(fogged(lit.rgb), lit.a);
}
)GLSL";

} // namespace volsg::shaders
