#pragma once
// GLSL of the glTF program: metallic-roughness PBR (GGX) lit by the scene's Inventor lights.
// Each stage follows the prelude and the shared surface code
// (lib/volsg/render/SurfaceShaders.h).
// The model is written out in GltfRenderer.h.

namespace volsg::shaders {

inline constexpr const char* gltfVertex = R"GLSL(
layout(location = 2) in vec4 aTangent;
layout(location = 4) in vec2 aTexCoord1;
layout(location = 5) in vec4 aColor;

out vec4 vWorldTangent;
out vec2 vTexCoord0;
out vec2 vTexCoord1;

void main() {
    transformVertex();
    vWorldTangent = vec4(mat3(uModel) * aTangent.xyz, aTangent.w);
    vTexCoord0 = aTexCoord0;
    vTexCoord1 = aTexCoord1;
    vColor = aColor;
}
)GLSL";

inline constexpr const char* gltfFragment = R"GLSL(
in vec4 vWorldTangent;
in vec2 vTexCoord0;
in vec2 vTexCoord1;

// Textures: units 0..4; uUse* false means the texture is absent. uSet* picks TEXCOORD_0/1.
uniform sampler2D uBaseColorTexture, uMetallicRoughnessTexture, uNormalTexture,
    uOcclusionTexture, uEmissiveTexture;
uniform bool uUseBaseColorTexture, uUseMetallicRoughnessTexture, uUseNormalTexture,
    uUseOcclusionTexture, uUseEmissiveTexture;
uniform int uSetBaseColor, uSetMetallicRoughness, uSetNormal, uSetOcclusion, uSetEmissive;

uniform vec4 uBaseColorFactor;
uniform float uMetallicFactor;
uniform float uRoughnessFactor;
uniform float uNormalScale;
uniform float uOcclusionStrength;
uniform vec3 uEmissive;     // glTF emissiveFactor
uniform vec3 uExtraEmissive; // the Inventor Material's emissiveColor
uniform int uAlphaMode;     // 0 OPAQUE, 1 MASK, 2 BLEND
uniform float uAlphaCutoff;
uniform float uAlphaScale;  // 1 - Inventor transparency
uniform bool uUnlit;        // KHR_materials_unlit, points and lines
uniform bool uHasNormals;   // else flat normals from the screen-space derivatives
uniform bool uHasTangents;  // else a tangent frame from the derivatives of position and UV
uniform bool uHasColors;

uniform float uAmbient; // Inventor's environment: 0.2

uniform bool uBoxClip; // a BoxClip in scope: opacity inside and outside its box
uniform mat4 uBoxFromWorld;
uniform vec3 uBoxMin, uBoxMax;
uniform float uBoxInsideOpacity, uBoxOutsideOpacity;

out vec4 fragColor;

const float PI = 3.14159265358979;

vec2 texCoord(int set) { return set == 1 ? vTexCoord1 : vTexCoord0; }

void main() {
    float boxOpacity = 1.0;
    if (uBoxClip) {
        vec3 p = (uBoxFromWorld * vec4(vWorldPosition, 1.0)).xyz;
        bool inside = all(greaterThanEqual(p, uBoxMin)) && all(lessThanEqual(p, uBoxMax));
        boxOpacity = inside ? uBoxInsideOpacity : uBoxOutsideOpacity;
        if (boxOpacity <= 0.0) discard;
    }

    vec4 base = uBaseColorFactor;
    if (uUseBaseColorTexture) base *= texture(uBaseColorTexture, texCoord(uSetBaseColor));
    if (uHasColors) base *= vColor;
    float alpha = base.a;
    if (uAlphaMode == 1 && alpha < uAlphaCutoff) discard;
    alpha = uAlphaMode == 0 || uAlphaMode == 1 ? 1.0 : alpha;
    alpha *= uAlphaScale * min(boxOpacity, 1.0);

    vec3 emissive = uEmissive;
    if (uUseEmissiveTexture) emissive *= texture(uEmissiveTexture, texCoord(uSetEmissive)).rgb;
    emissive += uExtraEmissive;

    if (uUnlit) {
        fragColor = vec4(base.rgb + uExtraEmissive, alpha);
        return;
    }

    vec3 V = towardsViewer();
    vec3 dpdx = dFdx(vWorldPosition), dpdy = dFdy(vWorldPosition);
    // The derivatives' cross product faces the viewer on either side; as the front face's
    // normal it points the other way on a back face.
    vec3 faceNormal = cross(dpdx, dpdy);
    faceNormal = dot(faceNormal, faceNormal) > 0.0 ? normalize(faceNormal) : V;
    if (!gl_FrontFacing) faceNormal = -faceNormal;
    vec3 Ng = uHasNormals && dot(vWorldNormal, vWorldNormal) > 0.0 ? normalize(vWorldNormal)
                                                                   : faceNormal;
    vec3 N = Ng;
    if (uUseNormalTexture) {
        // glTF's tangent frame: T along +u (the TANGENT attribute or, without one, from the
        // derivatives of position and UV), B = (N x T) * w.
        vec2 uv = texCoord(uSetNormal);
        vec3 t;
        float w = 1.0;
        if (uHasTangents) {
            t = vWorldTangent.xyz;
            w = vWorldTangent.w < 0.0 ? -1.0 : 1.0;
        } else {
            vec2 duvdx = dFdx(uv), duvdy = dFdy(uv);
            t = (duvdy.y * dpdx - duvdx.y * dpdy) / (duvdx.x * duvdy.y - duvdy.x * duvdx.y);
        }
        vec3 T = t - Ng * dot(Ng, t);
        T = dot(T, T) > 0.0 ? normalize(T) : normalize(cross(abs(Ng.x) < 0.9 ? vec3(1, 0, 0)
                                                                              : vec3(0, 1, 0), Ng));
        vec3 B = cross(Ng, T) * w;
        vec3 n = texture(uNormalTexture, uv).xyz * 2.0 - 1.0;
        n.xy *= uNormalScale;
        vec3 mapped = mat3(T, B, Ng) * n;
        if (dot(mapped, mapped) > 0.0) N = normalize(mapped);
    }
    // Double-sided or not (single-sided back faces are culled): light the side facing us.
    if (!gl_FrontFacing) N = -N;

    float metallic = uMetallicFactor, roughness = uRoughnessFactor;
    if (uUseMetallicRoughnessTexture) {
        vec4 mr = texture(uMetallicRoughnessTexture, texCoord(uSetMetallicRoughness));
        roughness *= mr.g;
        metallic *= mr.b;
    }
    metallic = clamp(metallic, 0.0, 1.0);
    roughness = clamp(roughness, 0.0, 1.0);
    float a = max(roughness * roughness, 1e-3); // alpha roughness; 0 would be a delta
    float a2 = a * a;
    vec3 diffuseColor = base.rgb * (1.0 - metallic);
    vec3 F0 = mix(vec3(0.04), base.rgb, metallic);

    float occlusion = 1.0;
    if (uUseOcclusionTexture)
        occlusion = 1.0 + uOcclusionStrength *
                              (texture(uOcclusionTexture, texCoord(uSetOcclusion)).r - 1.0);

    vec3 color = emissive + uAmbient * base.rgb * occlusion;
    float NdotV = max(dot(N, V), 1e-4);
    for (int i = 0; i < uLightCount; ++i) {
        vec3 L = normalize(lightVector(i));
        float NdotL = dot(N, L);
        if (NdotL <= 0.0) continue;
        vec3 H = normalize(L + V);
        float NdotH = max(dot(N, H), 0.0);
        float VdotH = max(dot(V, H), 0.0);
        vec3 F = F0 + (1.0 - F0) * pow(1.0 - VdotH, 5.0);
        float d = NdotH * NdotH * (a2 - 1.0) + 1.0;
        float D = a2 / (PI * d * d);
        float Vis = 0.5 / (NdotL * sqrt(NdotV * NdotV * (1.0 - a2) + a2) +
                           NdotV * sqrt(NdotL * NdotL * (1.0 - a2) + a2));
        vec3 brdf = (1.0 - F) * diffuseColor / PI + F * D * Vis;
        // Inventor intensity is a radiance scale: times PI, a light facing a rough white
        // dielectric gives about its base colour, as Inventor's Lambert term would.
        color += PI * brdf * NdotL * uLightColor[i];
    }
    fragColor = vec4(color, alpha);
}
)GLSL";

} // namespace volsg::shaders
