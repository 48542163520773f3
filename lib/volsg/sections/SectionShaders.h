#pragma once
// GLSL of the planar sections. Compiled with "#version 330 core", the defines ENTRIES and
// MAX_CLIP_PLANES, and shaders::sliceCommon (the Volume slicer's reconstruction and
// transfer-table lookup, so both classify a data value identically).

namespace volsg::shaders {

inline constexpr const char* sectionVertex = R"GLSL(
layout(location = 0) in vec3 aLocal;
uniform mat4 uModelViewProjection; // volume-local -> clip
out vec3 vLocal;
void main() {
    vLocal = aLocal;
    gl_Position = uModelViewProjection * vec4(aLocal, 1.0);
}
)GLSL";

inline constexpr const char* sectionFragment = R"GLSL(
in vec3 vLocal;
out vec4 fragColor;

uniform sampler3D uData;     // the whole volume, linear filter
uniform usampler3D uTags;
uniform usampler2D uTagRows; // tag -> transfer-table row, 256 x 256
uniform bool uTagged;
uniform vec3 uHalfExtent;    // the volume box is [-uHalfExtent, uHalfExtent] (local)
uniform vec3 uInvSpacing;
uniform vec3 uVoxelCount;
uniform float uDataScale;    // data = texel * uDataScale + uDataOffset
uniform float uDataOffset;
uniform bool uLinear;        // trilinear; else the nearest voxel
uniform int uAlphaUse;       // 0 as is, 1 opaque, 2 binary
uniform int uClipPlaneCount;
uniform vec4 uClipPlanes[MAX_CLIP_PLANES]; // local (n, d): keep dot(n, p) >= d

void main() {
    for (int i = 0; i < uClipPlaneCount; ++i)
        if (dot(uClipPlanes[i].xyz, vLocal) < uClipPlanes[i].w) discard;
    // Voxel coordinates: voxel i's cell is [i, i + 1), its centre at i + 0.5, which is also
    // where the texture has its texel centres.
    vec3 u = (vLocal + uHalfExtent) * uInvSpacing;
    ivec3 cell = clamp(ivec3(floor(u)), ivec3(0), ivec3(uVoxelCount) - 1);
    float texel = uLinear ? texture(uData, u / uVoxelCount).r : texelFetch(uData, cell, 0).r;
    float d = texel * uDataScale + uDataOffset;
    int row = 0;
    if (uTagged) {
        uint tag = texelFetch(uTags, cell, 0).r;
        row = int(texelFetch(uTagRows, ivec2(int(tag & 255u), int(tag >> 8)), 0).r);
    }
    vec4 c = classify(normalised(d, rangeOf(row)), row);
    float alpha = opacityOf(c.a); // the table holds tau L0 = -ln(1 - A)
    if (uAlphaUse == 1) alpha = 1.0;
    else if (uAlphaUse == 2) alpha = c.a > 0.0 ? 1.0 : 0.0;
    if (alpha <= 0.0) discard;
    fragColor = vec4(c.rgb, alpha);
}
)GLSL";

} // namespace volsg::shaders
