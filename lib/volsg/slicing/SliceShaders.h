#pragma once
// GLSL of the 3D-texture slicer. Compiled with "#version 330 core" and defines in front:
// MODE (0 DVR, 1 MIP, 2 MINIP, 3 AVERAGE), TAGGED, LIGHTING, PREINTEGRATED, and the sizes
// ENTRIES (transfer-table samples per row), PRE_SIZE, PLANE_OPACITY_SIZE, MAX_CLIP_PLANES,
// MAX_LIGHTS.

namespace volsg::shaders {

/// Proxy polygons: box-local positions, passed on in local coordinates.
inline constexpr const char* sliceVertex = R"GLSL(
layout(location = 0) in vec3 aLocal;
uniform mat4 uModelView;  // volume-local -> eye
uniform mat4 uProjection;
out vec3 vLocal;
void main() {
    vLocal = aLocal;
    gl_Position = uProjection * (uModelView * vec4(aLocal, 1.0));
}
)GLSL";

/// What the slice and composite programs share: data reconstruction, normalisation, the
/// transfer-table lookup and the careful float maths of opacity.
inline constexpr const char* sliceCommon = R"GLSL(
// Per row: ENTRIES samples of (r, g, b, tau L0) over v, a copy of the last one (so that the
// linear filter never reaches further), then (lo, hi) of the row's dataRange.
uniform sampler2D uTable;
uniform sampler1D uTableRow; // its row 0 alone (the lean DVR loop: two texels per lookup, not four)

vec2 rangeOf(int row) { return texelFetch(uTable, ivec2(ENTRIES + 1, row), 0).rg; }

// docs/SCENE-FORMAT.md 4: v = clamp((d - lo) / (hi - lo), 0, 1); hi == lo is a step at lo.
float normalised(float d, vec2 range) {
    if (range.x == range.y) return d >= range.x ? 1.0 : 0.0;
    return clamp((d - range.x) / (range.y - range.x), 0.0, 1.0);
}

// (C, tau L0) at v: the filter interpolates linearly between neighbouring samples of the row
// (float weights on float textures); sampling at the row's centre keeps other rows out.
vec4 classify(float v, int row) {
    vec2 size = vec2(textureSize(uTable, 0));
    return texture(uTable, vec2((clamp(v, 0.0, 1.0) * float(ENTRIES - 1) + 0.5) / size.x,
                                (float(row) + 0.5) / size.y));
}

// 1 - e^-D: a series where exp(-D) would round away a tiny D; 1 (never NaN) for huge D.
float opacityOf(float D) {
    if (D < 0.01) return D * (1.0 - D * (0.5 - D * (1.0 / 6.0 - D * (1.0 / 24.0))));
    return 1.0 - exp(-D);
}
)GLSL";

inline constexpr const char* sliceFragment = R"GLSL(
in vec3 vLocal;
out vec4 fragColor;

uniform sampler3D uData;
uniform usampler3D uTags;
uniform usampler2D uTagRows;      // tag -> row, 256 x 256
// (mean colour, mean optical depth per L0) over (v_front, v_back): one PRE_SIZE x PRE_SIZE table
// per transfer-table row, stacked along y (uPreRows of them).
uniform sampler2D uPreIntegrated;
uniform int uPreRows;
uniform sampler1D uPlaneOpacity;  // m(t), PLANE_OPACITY_SIZE samples over t in [0, 1]
uniform sampler2D uOpaqueDepth;   // a copy of the opaque pass's depth (window depth, 0..1)
uniform usampler3D uCells;        // 1 per cell of EmptyCells::kCellSize^3 voxels that may emit

uniform vec3 uHalfExtent;   // the volume box is [-uHalfExtent, uHalfExtent] (local)
uniform vec3 uInvSpacing;   // local -> voxel coordinates: u = (p + uHalfExtent) * uInvSpacing
uniform vec3 uVoxelCount;   // the volume's dimensions
uniform vec3 uTexOrigin;    // voxel index of the brick texture's first texel
uniform vec3 uTexSize;      // texels of the brick texture
uniform vec3 uOwnMin;       // the part of the volume box this brick draws (local)
uniform vec3 uOwnMax;
uniform vec3 uSlabMin;      // where slabs end (local): the volume box, or the brick's box
uniform vec3 uSlabMax;      // (SlicePlan::slabsEndAtBricks) so samples stay in its texture
uniform float uDataScale;   // data = texel * uDataScale + uDataOffset
uniform float uDataOffset;
uniform bool uOrthographic;
uniform vec3 uEyeLocal;     // perspective: the eye in local coordinates
uniform vec3 uViewDirLocal; // orthographic: the (unit) direction of every ray, local
uniform vec4 uDepthPlane;   // eye depth of local point p: dot(uDepthPlane.xyz, p) + uDepthPlane.w
uniform bool uHasOpaqueDepth;
uniform float uPlaneSpacing; // eye units between neighbouring planes along the view axis
uniform float uInvL0;        // 1 / smallest voxel spacing (local units)
uniform float uNear;         // eye depths of the camera's near and far planes
uniform float uFar;
uniform bool uHasPlaneOpacity;
uniform float uBoxNear;      // eye depths of the nearest and farthest volume-box corner
uniform float uBoxFar;
uniform int uClipPlaneCount;
uniform vec4 uClipPlanes[MAX_CLIP_PLANES]; // local (n, d): keep dot(n, p) >= d
uniform bool uHasBoxClip;
uniform mat4 uLocalToBox;    // volume-local -> BoxClip coordinates
uniform vec3 uBoxMin;
uniform vec3 uBoxMax;
uniform vec2 uRegionOpacity; // extinction multiplier outside (x) and inside (y) the BoxClip box
uniform vec3 uRegionColor[2];
uniform vec2 uRegionWeight;
uniform uint uInfoMask;      // MIP/MINIP: low key bits that carry row * 2 + region
uniform bool uFacePass;      // drawing the volume box's front faces, for slivers (see main)
uniform int uSlabSamples;    // samples per plane's slab, taken inside the fragment
uniform bool uRefinePeaks;   // MIP/MINIP: the extreme from the parabola through the top sample
uniform bool uMipPeaks;      // MIP/MINIP: also sample every voxel-centre crossing in the slab
uniform bool uSkipCells;     // skip cells that cannot emit (one-sample discard, lean trims)
uniform float uCellScale;    // 1 / voxels per cell
uniform float uLayoutNear;   // eye depth of the plane layout's start: plane k at
                             // uLayoutNear + (k + 0.5) * uPlaneSpacing

#ifdef LIGHTING
uniform mat4 uModel;         // local -> world
uniform mat3 uNormalMatrix;  // local covectors -> world (inverse transpose)
uniform vec4 uViewer;        // eye position (w = 1) or direction towards the viewer (w = 0)
uniform int uLightCount;
uniform vec4 uLightVector[MAX_LIGHTS]; // position (w = 1) or direction towards it (w = 0)
uniform vec3 uLightColor[MAX_LIGHTS];
uniform float uAmbient;
uniform vec3 uSpecular;
uniform float uShininess;
#endif

vec3 voxelCoord(vec3 local) { return (local + uHalfExtent) * uInvSpacing; }
vec3 texCoord(vec3 local) { return (voxelCoord(local) - uTexOrigin) / uTexSize; }
float dataAt(vec3 tc) { return texture(uData, tc).r * uDataScale + uDataOffset; }

// Whether the cell of a sample at `local` may emit: a trilinear sample reads only voxels
// of its cell and the layer around it, whose range EmptyCells measured.
bool cellMayEmit(vec3 local) {
    ivec3 cell = ivec3(floor(voxelCoord(local) * uCellScale));
    cell = clamp(cell, ivec3(0), textureSize(uCells, 0) - 1);
    return texelFetch(uCells, cell, 0).r != 0u;
}

// One end of a row of `count` evenly spaced samples (voxel coordinates u0 + j du) moved
// inwards past the samples that lie in cells which cannot emit, a whole cell per step; from
// the front (`fromBack` false: the first sample that may emit, or count) or from the back (the
// last, or -1). Samples in such cells add nothing, so a slab's leading and trailing air costs
// one integer fetch per cell instead of a filtered fetch per sample.
int emittingEnd(vec3 u0, vec3 du, int count, bool fromBack) {
    vec3 along = fromBack ? -du : du;
    vec3 inv = 1.0 / mix(along, vec3(1e-30), equal(along, vec3(0.0)));
    ivec3 lastCell = textureSize(uCells, 0) - 1;
    float cellSize = 1.0 / uCellScale;
    int j = fromBack ? count - 1 : 0;
    for (int guard = 0; guard < 256 && j >= 0 && j < count; ++guard) {
        vec3 u = u0 + float(j) * du;
        ivec3 cell = clamp(ivec3(floor(u * uCellScale)), ivec3(0), lastCell);
        if (texelFetch(uCells, cell, 0).r != 0u) break;
        // Samples to the face the row leaves the cell by (a little short of it, so rounding
        // never steps over a sample in the next cell).
        vec3 face = (vec3(cell) + step(0.0, along)) * cellSize;
        vec3 t = (face - u) * inv;
        int n = max(1, int(ceil(min(min(t.x, t.y), t.z) - 1e-2)));
        j += fromBack ? -n : n;
    }
    return j;
}

int rowAt(vec3 local) {
#ifdef TAGGED
    // Nearest neighbour: the voxel whose cell holds the point, never interpolated.
    ivec3 voxel = ivec3(floor(voxelCoord(local))) - ivec3(uTexOrigin);
    voxel = clamp(voxel, ivec3(0), ivec3(uTexSize) - 1);
    uint tag = texelFetch(uTags, voxel, 0).r;
    return int(texelFetch(uTagRows, ivec2(int(tag & 255u), int(tag >> 8u)), 0).r);
#else
    return 0;
#endif
}

// Where origin + t dir is inside the box [lo, hi]: t in [range.x, range.y] (empty when
// range.x > range.y). Vector arithmetic: a zero direction component divides by a tiny number
// instead, which gives -+huge on the two sides of an inside point.
vec2 slabInterval(vec3 origin, vec3 dir, vec3 lo, vec3 hi) {
    vec3 inv = 1.0 / mix(dir, vec3(1e-30), equal(dir, vec3(0.0)));
    vec3 ta = (lo - origin) * inv;
    vec3 tb = (hi - origin) * inv;
    vec3 tNear = min(ta, tb);
    vec3 tFar = max(ta, tb);
    return vec2(max(max(tNear.x, tNear.y), tNear.z), min(min(tFar.x, tFar.y), tFar.z));
}

#ifdef TAGGED
// The slab [origin - front, origin + back] along `dir`, split at the faces of the tag cell of
// origin: each part is classified with its own cell's tag and data at its middle, so tag
// boundaries (steps of the transfer function) fall where the cell faces are, as in the
// reference, rather than where the planes are. Gives the length-weighted mean tau L0 and the
// extinction-weighted colour of the slab.
void classifySlab(vec3 origin, vec3 dir, float front, float back, out vec3 color,
                  out float tauL0) {
    vec3 u0 = voxelCoord(origin);
    vec3 cell = clamp(floor(u0), vec3(0.0), uVoxelCount - 1.0);
    vec2 inCell = slabInterval(u0, dir * uInvSpacing, cell, cell + 1.0);
    float cut[4] = float[4](-front, clamp(inCell.x, -front, back), 0.0, back);
    cut[2] = clamp(inCell.y, cut[1], back);
    vec3 emitted = vec3(0.0);
    float depthSum = 0.0;
    vec3 fallback = vec3(0.0);
    for (int i = 0; i < 3; ++i) {
        float length = cut[i + 1] - cut[i];
        if (!(length > 0.0) && i != 1) continue;
        vec3 x = origin + dir * (0.5 * (cut[i] + cut[i + 1]));
        int row = rowAt(x);
        vec4 rgba = classify(normalised(dataAt(texCoord(x)), rangeOf(row)), row);
        float tau = rgba.a * max(length, 0.0);
        emitted += tau * rgba.rgb;
        depthSum += tau;
        if (i == 1) fallback = rgba.rgb;
    }
    float thickness = front + back;
    tauL0 = thickness > 0.0 ? depthSum / thickness : 0.0;
    color = depthSum > 0.0 ? emitted / depthSum : fallback;
}
#endif

#ifdef PREINTEGRATED
// Row `row`'s segment from v_front to v_back (texel centres at v = i / (PRE_SIZE - 1); a row's
// last texel centre is its own, so the filter never mixes two rows).
vec4 preIntegratedSegment(int row, float vFront, float vBack) {
    vec2 t = vec2(vFront, vBack) * float(PRE_SIZE - 1) + 0.5;
    t.y += float(row * PRE_SIZE);
    return texture(uPreIntegrated, t / vec2(float(PRE_SIZE), float(PRE_SIZE * uPreRows)));
}
#ifdef TAGGED
// classifySlab's pre-integrated counterpart: the slab [x - front dir, x + back dir] cut at the
// faces of the tag cell around x, each piece pre-integrated with its own row between the data
// at its two ends (the tau-weighted mean colour and the mean optical depth per L0).
void preIntegrateSlab(vec3 x, vec3 dir, float front, float back, out vec3 color,
                      out float tauL0) {
    vec3 u0 = voxelCoord(x);
    vec3 cell = clamp(floor(u0), vec3(0.0), uVoxelCount - 1.0);
    vec2 inCell = slabInterval(u0, dir * uInvSpacing, cell, cell + 1.0);
    float cut[4] = float[4](-front, clamp(inCell.x, -front, back), 0.0, back);
    cut[2] = clamp(inCell.y, cut[1], back);
    vec3 emitted = vec3(0.0);
    float depthSum = 0.0;
    vec3 fallback = vec3(0.0);
    for (int i = 0; i < 3; ++i) {
        float length = cut[i + 1] - cut[i];
        if (!(length > 0.0) && i != 1) continue;
        int row = rowAt(x + dir * (0.5 * (cut[i] + cut[i + 1])));
        vec2 range = rangeOf(row);
        vec4 segment = preIntegratedSegment(row, normalised(dataAt(texCoord(x + dir * cut[i])), range),
                                            normalised(dataAt(texCoord(x + dir * cut[i + 1])), range));
        float tau = segment.a * max(length, 0.0);
        emitted += tau * segment.rgb;
        depthSum += tau;
        if (i == 1) fallback = segment.rgb;
    }
    float thickness = front + back;
    tauL0 = thickness > 0.0 ? depthSum / thickness : 0.0;
    color = depthSum > 0.0 ? emitted / depthSum : fallback;
}
#endif
#endif

float planeOpacityAt(float t) {
    float x = clamp(t, 0.0, 1.0) * float(PLANE_OPACITY_SIZE - 1);
    int i = min(int(x), PLANE_OPACITY_SIZE - 2);
    float f = x - float(i);
    return max(mix(texelFetch(uPlaneOpacity, i, 0).r, texelFetch(uPlaneOpacity, i + 1, 0).r, f),
               0.0);
}

#ifdef LIGHTING
// Inventor's Phong model with the transfer-function colour as ambient and diffuse colour and
// the normal from the gradient of v (central differences, one voxel either side).
vec3 shade(vec3 C, vec3 tc, vec2 range, vec3 local) {
    vec3 texel = 1.0 / uTexSize;
    vec3 g = vec3(dataAt(tc + vec3(texel.x, 0, 0)) - dataAt(tc - vec3(texel.x, 0, 0)),
                  dataAt(tc + vec3(0, texel.y, 0)) - dataAt(tc - vec3(0, texel.y, 0)),
                  dataAt(tc + vec3(0, 0, texel.z)) - dataAt(tc - vec3(0, 0, texel.z)));
    float width = range.y - range.x;
    g *= 0.5 * uInvSpacing / (width != 0.0 ? width : 1.0); // dv per local unit
    vec3 world = (uModel * vec4(local, 1.0)).xyz;
    vec3 V = normalize(uViewer.xyz - world * uViewer.w);
    vec3 gw = uNormalMatrix * g;
    // Homogeneous regions have no surface: they face the viewer.
    vec3 N = length(g) / uInvL0 > 1e-3 ? -normalize(gw) : V;
    if (dot(N, V) < 0.0) N = -N; // two-sided, as shapes are lit
    vec3 color = uAmbient * C;
    for (int i = 0; i < uLightCount; ++i) {
        vec3 L = normalize(uLightVector[i].xyz - world * uLightVector[i].w);
        float NdotL = dot(N, L);
        if (NdotL <= 0.0) continue;
        float NdotH = max(dot(N, normalize(L + V)), 0.0);
        float specular = uShininess > 0.0 ? pow(NdotH, uShininess) : 1.0;
        color += uLightColor[i] * (C * NdotL + uSpecular * specular);
    }
    return color;
}
#endif

#if MODE == 1 || MODE == 2
vec2 gRange; // untagged: the one row's dataRange, set once per fragment
// MIP / MINIP: the v of a sample and its row * 2 + region, or -1 when its region is removed.
float valueAt(vec3 x, out int info) {
    int rowHere = rowAt(x);
    int regionHere = 0;
    if (uHasBoxClip) {
        vec3 q = (uLocalToBox * vec4(x, 1.0)).xyz;
        regionHere = all(greaterThanEqual(q, uBoxMin)) && all(lessThanEqual(q, uBoxMax)) ? 1 : 0;
    }
    info = rowHere * 2 + regionHere;
    if ((regionHere == 1 ? uRegionOpacity.y : uRegionOpacity.x) <= 0.0) return -1.0;
#ifdef TAGGED
    return normalised(dataAt(texCoord(x)), rangeOf(rowHere));
#else
    return normalised(dataAt(texCoord(x)), gRange); // one row: its range, fetched once
#endif
}

// Whether a slab's end at x lies on the volume box's face, where a structure the face cuts has
// its extreme (between crossings, so no other sample finds it). Only there: ends elsewhere
// (half-way to a plane, a brick's seam) differ between bricked and whole volumes.
bool onVolumeFace(vec3 x) {
    return any(greaterThan(abs(x), uHalfExtent * (1.0 - 1e-4)));
}

// The voxel-centre planes u = i + 1/2 from u = ua to ub along one axis: the first, and in
// `count` how many. (The bound only guards loops: a slab lies in one brick, at most a
// texture's side, 16384 texels, across; a lower bound dropped crossings of thick slabs.)
float firstCrossing(float ua, float ub, out int count) {
    float first = ceil(min(ua, ub) - 0.5) + 0.5;
    count = clamp(int(floor(max(ua, ub) - first)) + 1, 0, 16384);
    return first;
}

// Keeps the extreme v of the samples it is given, with the row and BoxClip region of that
// sample; samples in a removed BoxClip region do not count.
void considerExtreme(vec3 x, inout float best, inout int bestInfo) {
    int info;
    float v = valueAt(x, info);
    if (v >= 0.0 && (MODE == 1 ? v > best : v < best)) {
        best = v;
        bestInfo = info;
    }
}

// Evenly spaced samples miss the part of a peak that lies between them (MIP always comes out
// low). Where the most extreme sample m has both neighbours (l, r), the extreme is taken from
// the parabola through the three: m + (p - q)^2 / (8 (p + q)), p = m - l, q = m - r. Exact for
// a smooth peak; never above a tent-shaped one (a trilinear kink); 0 when p = q. The samples
// next to a slab's ends, of the neighbouring slabs, serve as neighbours only (each slab finds
// its own top), so a peak at a slab boundary is refined too. Values are oriented so that
// larger is more extreme (MINIP passes -v); -1e30 is no sample.
struct PeakTracker {
    float top, left, right, prev;
    bool wantRight;
};
PeakTracker noPeak() { return PeakTracker(-1e30, -1e30, -1e30, -1e30, false); }
void track(inout PeakTracker k, float s) {
    if (k.wantRight) k.right = s;
    k.wantRight = s > k.top;
    if (k.wantRight) {
        k.left = k.prev;
        k.top = s;
        k.right = -1e30;
    }
    k.prev = s;
}
// Sample j of a slab of `parts`, where j = -1 and j = parts are the neighbouring slabs' nearest.
void trackSample(inout PeakTracker k, float s, int j, int parts) {
    if (j < 0) {
        k.prev = s;
    } else if (j >= parts) {
        if (k.wantRight) k.right = s;
    } else {
        track(k, s);
    }
}
float refinedTop(PeakTracker k) {
    // Not a peak of this slab when a neighbouring slab's sample is larger (it refines it).
    if (!uRefinePeaks || !(k.left > -1e29 && k.right > -1e29) || k.left > k.top ||
        k.right > k.top)
        return k.top;
    float p = k.top - k.left, q = k.top - k.right;
    return k.top + (p - q) * (p - q) / max(8.0 * (p + q), 1e-30);
}
#endif

#if defined(LEAN) && defined(PEAKS)
// Where the ray u0 + s along (voxel coordinates) first enters, from s0 on, a cell that may
// emit; past s1 when none does by then. The cells are walked face by face (not sampled), so
// no cell the ray crosses is stepped over; a hundredth of a voxel's margin covers rounding.
float firstEmitting(vec3 u0, vec3 along, float s0, float s1) {
    ivec3 lastCell = textureSize(uCells, 0) - 1;
    float cellSize = 1.0 / uCellScale;
    bvec3 still = equal(along, vec3(0.0));
    vec3 safe = mix(along, vec3(1.0), still);
    ivec3 cell = ivec3(floor((u0 + along * s0) * uCellScale));
    vec3 sNext = mix(((vec3(cell) + step(0.0, along)) * cellSize - u0) / safe, vec3(1e30), still);
    vec3 sDelta = mix(cellSize / abs(safe), vec3(0.0), still);
    ivec3 stepSign = ivec3(sign(along));
    float s = s0;
    for (int guard = 0; guard < 1024; ++guard) {
        if (texelFetch(uCells, clamp(cell, ivec3(0), lastCell), 0).r != 0u)
            return max(s0, s - 0.01 / length(along));
        s = min(min(sNext.x, sNext.y), sNext.z);
        if (s > s1) return s;
        if (sNext.x == s) {
            cell.x += stepSign.x;
            sNext.x += sDelta.x;
        } else if (sNext.y == s) {
            cell.y += stepSign.y;
            sNext.y += sDelta.y;
        } else {
            cell.z += stepSign.z;
            sNext.z += sDelta.z;
        }
    }
    return s0; // (a guard only: the whole stretch)
}
#endif

#ifdef LEAN
// The slab's samples when every one counts alike: untagged, no BoxClip, and for DVR no
// planeOpacity, lighting or pre-integration; several samples per plane (and the face pass).
// Each sample has row 0, its part's whole length and the transfer function's own colour, and
// the texture coordinate is linear along the ray. A program of its own: llvmpipe runs every
// branch of a SIMD block with its lanes masked, so general code left in the shader costs
// even where a uniform switches it off. Leading and trailing samples in cells that cannot emit
// are left out (emittingEnd); MIP keeps one such neighbour each side for the peak refinement,
// so the image is the general loop's. MIP/MINIP with peaks (PEAKS) take the general loop's
// samples too, each axis's voxel-centre crossings as one row of evenly spaced fetches.
void leanSlab(vec3 origin, vec3 dir, float front, float thickness, int parts, vec2 reach) {
    vec2 range = rangeOf(0);
    float partLength = thickness / float(parts);
    vec3 first = origin + dir * (-front + 0.5 * partLength);
    vec3 tc = texCoord(first);
    vec3 tcStep = dir * (partLength * uInvSpacing / uTexSize);
    int j0 = 0, j1 = parts - 1;
#ifndef PEAKS
    if (uSkipCells) {
        vec3 du = dir * (partLength * uInvSpacing);
        j0 = emittingEnd(voxelCoord(first), du, parts, false);
        if (j0 >= parts) discard; // nothing in this slab can emit
        j1 = emittingEnd(voxelCoord(first), du, parts, true);
    }
#endif
#if MODE == 0
    float lengthL0 = partLength * uInvL0;
    vec3 emitted = vec3(0.0);
    float depthSum = 0.0;
    float transmitted = 1.0; // e^-depthSum
    // The texel's v and its row-0 table coordinate as one multiply-add each (the general
    // loop's normalised() and classify(), with their per-sample constants taken out).
    vec2 size = vec2(textureSize(uTable, 0));
    float tableScale = float(ENTRIES - 1) / size.x, tableOffset = 0.5 / size.x;
    bool stepRange = range.x == range.y;
    float vScale = stepRange ? 0.0 : uDataScale / (range.y - range.x);
    float vOffset = stepRange ? 0.0 : (uDataOffset - range.x) / (range.y - range.x);
    for (int j = j0; j <= j1; ++j) {
        float texel = texture(uData, tc + float(j) * tcStep).r;
        float v = stepRange ? (texel * uDataScale + uDataOffset >= range.x ? 1.0 : 0.0)
                            : clamp(texel * vScale + vOffset, 0.0, 1.0);
        vec4 rgba = texture(uTableRow, v * tableScale + tableOffset);
        float D = rgba.a * lengthL0;
        float e = exp(-D);
        emitted += transmitted * (D < 0.01 ? opacityOf(D) : 1.0 - e) * rgba.rgb;
        transmitted *= e;
        depthSum += D;
    }
    float alpha = opacityOf(depthSum);
    if (!(alpha > 0.0)) discard;
    fragColor = vec4(emitted, alpha);
#else
    // v is a monotone function of the texel (rising, or falling for a reversed dataRange;
    // float rounding keeps the order), so the extreme texel gives the extreme v.
    float orient = ((MODE == 1) == (range.y >= range.x)) ? 1.0 : -1.0;
#ifdef PEAKS
    // The general loop's samples with peaks (see main), as texels: the texture coordinate is
    // linear along the ray, so each axis's crossings are a row of evenly spaced fetches.
    // Samples in cells that cannot emit are left out, as in the lean loop without peaks: the
    // slab's stretch from the first to the last cell it crosses that may.
    float top = -1e30;
    vec3 tcOrigin = texCoord(origin);
    vec3 tcPerT = dir * (uInvSpacing / uTexSize);
    vec3 u0 = voxelCoord(origin);
    vec3 du = dir * uInvSpacing;
    vec2 kept = vec2(-front, thickness - front);
    if (uSkipCells) {
        kept = vec2(firstEmitting(u0, du, kept.x, kept.y), -firstEmitting(u0, -du, -kept.y, -kept.x));
        if (kept.x > kept.y) discard;
    }
    vec3 ends[2] = vec3[2](origin - dir * front, origin + dir * (thickness - front));
    for (int e = 0; e < 2; ++e)
        if (onVolumeFace(ends[e]) && (e == 0 ? -front >= kept.x : thickness - front <= kept.y))
            top = max(top, orient * texture(uData, texCoord(ends[e])).r);
    if (parts == 1 && !uFacePass) { // a short slab: its plane point, and every crossing below
        if (0.0 >= kept.x && 0.0 <= kept.y) top = max(top, orient * texture(uData, tcOrigin).r);
    } else {
        // Part j's middle is at -front + (j + 0.5) partLength.
        int jA = max(int(ceil((kept.x + front) / partLength - 0.5)), 0);
        int jB = min(int(floor((kept.y + front) / partLength - 0.5)), parts - 1);
        for (int j = jA; j <= jB; ++j)
            top = max(top, orient * texture(uData, tc + float(j) * tcStep).r);
    }
    for (int axis = 0; axis < 3; ++axis) {
        float d = du[axis];
        if (d == 0.0) continue;
        int count;
        float first = firstCrossing(u0[axis] - d * front, u0[axis] + d * (thickness - front), count);
        // Crossing k is at t = (first + k - u0) / d; those in the kept stretch.
        float ka = u0[axis] + d * kept.x - first;
        float kb = u0[axis] + d * kept.y - first;
        int kA = max(int(ceil(min(ka, kb))), 0);
        int kB = min(int(floor(max(ka, kb))), count - 1);
        vec3 c = tcOrigin + tcPerT * ((first - u0[axis]) / d);
        vec3 cStep = tcPerT / d;
        for (int k = kA; k <= kB; ++k)
            top = max(top, orient * texture(uData, c + float(k) * cStep).r);
    }
    if (top < -1e29) discard;
    float best = normalised(orient * top * uDataScale + uDataOffset, range);
#else
    PeakTracker k = noPeak();
    for (int j = max(j0 - 1, -1); j <= min(j1 + 1, parts); ++j) {
        float t = -front + (float(j) + 0.5) * partLength;
        if (t < reach.x || t > reach.y) continue; // (only the neighbours can lie outside)
        trackSample(k, orient * texture(uData, tc + float(j) * tcStep).r, j, parts);
    }
    float texel = orient * (parts > 1 ? refinedTop(k) : k.top);
    float best = normalised(texel * uDataScale + uDataOffset, range);
#endif
    fragColor = vec4(uintBitsToFloat(floatBitsToUint(best + 1.0) & ~uInfoMask), 0.0, 0.0, 0.0);
#endif
}
#endif

void main() {
    if (!uFacePass) {
        // The polygons are cut from the brick's box grown by a margin, so that no pixel is
        // lost to rasterisation at the box's and the bricks' edges; what lies outside the
        // brick's part of the volume box is decided here, with the same arithmetic for every
        // brick and plane. (A point exactly on a seam would count for both bricks: a set of
        // measure zero.)
        if (any(lessThan(vLocal, uOwnMin)) || any(greaterThan(vLocal, uOwnMax))) discard;
        // One sample per plane, at this point: in an empty cell the fragment adds nothing
        // (DVR: no optical depth; MIP: below every value shown). Several samples are not
        // tested one by one: the geometry leaves out the rows of empty cells (up to two samples,
        // kMaxRowSamples), the lean loop trims a slab's empty ends (emittingEnd), and on llvmpipe
        // a per-sample test costs more than the masked-off samples it saves (chest CT, 8
        // samples a plane: DVR 188 -> 162 ms, MIP 16 samples 283 -> 219 ms, same image).
#if MODE == 0 && !defined(PREINTEGRATED)
        if (uSkipCells && uSlabSamples <= 1 && !cellMayEmit(vLocal)) discard;
#elif MODE == 1
        if (uSkipCells && uSlabSamples <= 1 && !uMipPeaks && !cellMayEmit(vLocal)) discard;
#endif
    }
    // The pixel's ray through this point: its direction, the path length between this plane
    // and the next along it (local units), and how fast eye depth grows along it.
    vec3 dir = uOrthographic ? uViewDirLocal : normalize(vLocal - uEyeLocal);
    float depth = dot(uDepthPlane.xyz, vLocal) + uDepthPlane.w;
    float depthRate = dot(uDepthPlane.xyz, dir); // > 0: the ray moves away from the eye
    float ds = uPlaneSpacing / depthRate;

    // The stretch of the ray around this point that may hold volume: inside the box (or the
    // brick's, whose neighbours' fragments stand for the ray beyond its faces), between the
    // near and far planes, on the kept side of every clip plane.
    vec2 inBox = slabInterval(vLocal, dir, uSlabMin, uSlabMax);
    float tEnter = inBox.x, tExit = inBox.y;
    tEnter = max(tEnter, (uNear - depth) / depthRate);
    tExit = min(tExit, (uFar - depth) / depthRate);
    // Opaque geometry ends the ray (the depth test rejects the planes behind it).
    float windowDepth = uHasOpaqueDepth ? texelFetch(uOpaqueDepth, ivec2(gl_FragCoord.xy), 0).r
                                        : 1.0;
    if (windowDepth < 1.0) {
        float ndc = 2.0 * windowDepth - 1.0;
        float opaqueDepth = uOrthographic
                                ? uNear + windowDepth * (uFar - uNear)
                                : 2.0 * uNear * uFar / ((uFar + uNear) - ndc * (uFar - uNear));
        tExit = min(tExit, (opaqueDepth - depth) / depthRate);
    }
    for (int i = 0; i < uClipPlaneCount; ++i) {
        float f = dot(uClipPlanes[i].xyz, vLocal) - uClipPlanes[i].w;
        if (f < 0.0) discard;
        float rate = dot(uClipPlanes[i].xyz, dir);
        if (rate > 0.0) tEnter = max(tEnter, -f / rate);
        else if (rate < 0.0) tExit = min(tExit, -f / rate);
    }
    float front, back;
    vec3 origin = vLocal; // the slab is [origin - front dir, origin + back dir]
    if (uFacePass) {
        // A front face of the box (or brick): it stands for the ray's whole stretch through
        // it when no plane crosses that stretch (a sliver near a silhouette, thinner than the
        // plane spacing), and for nothing otherwise, when plane fragments cover the ray.
        float t0 = max(tEnter, 0.0);
        if (!(tExit > t0)) discard;
        float d0 = depth + depthRate * t0;
        float k = ceil((d0 - uLayoutNear) / uPlaneSpacing - 0.5);
        if (uLayoutNear + (k + 0.5) * uPlaneSpacing < depth + depthRate * tExit) discard;
        front = 0.0;
        back = tExit - t0;
        origin = vLocal + dir * t0;
        depth += depthRate * t0;
    } else {
        // This plane stands for half the way to each neighbour; where a neighbour's point on
        // the ray is outside that stretch, no neighbour fragment exists there, so this one
        // stands for the whole way to the boundary. The slabs then tile each ray's part of
        // the volume exactly.
        front = -tEnter < ds ? max(-tEnter, 0.0) : 0.5 * ds;
        back = tExit < ds ? max(tExit, 0.0) : 0.5 * ds;
    }
    float thickness = front + back;
    if (thickness <= 0.0) discard;
    vec3 p = origin + dir * (0.5 * (back - front)); // the middle of the slab
    if (!uFacePass) p = vLocal; // (a plane's slab is sampled at the plane with one part)
    // Samples along the slab: uSlabSamples over a plane spacing. A slab cut shorter (at the
    // box's or a brick's faces) or a face's sliver takes as many at the same spacing (at least
    // one): slivers near the silhouette are sampled as densely as the rest, and a slab cut by
    // brick seams (slabsEndAtBricks) costs no more samples than the whole slab would.
    int parts = max(uSlabSamples, 1);
    parts = clamp(int(ceil(thickness * float(parts) / ds - 1e-3)), 1, parts);
    // The ray's stretch through the volume around origin (a face's sliver is all of it).
    vec2 reach = uFacePass ? vec2(0.0, back) : vec2(tEnter, tExit);
#ifdef LEAN
    leanSlab(origin, dir, front, thickness, parts, reach);
#else

    int row = rowAt(p);
    vec2 range = rangeOf(row);
#if MODE == 1 || MODE == 2
    gRange = range;
#endif
    // BoxClip: the sample's region, and how much of the slab lies inside the box, so that a
    // slab cut by a box face gets each region's opacity and colour for its own length.
    int region = 0;
    float insideLength = 0.0;
    vec2 inClip = vec2(0.0); // the ray's stretch inside the BoxClip box, from origin
    if (uHasBoxClip) {
        vec3 q = (uLocalToBox * vec4(p, 1.0)).xyz;
        region = all(greaterThanEqual(q, uBoxMin)) && all(lessThanEqual(q, uBoxMax)) ? 1 : 0;
        // The slab is measured from origin.
        inClip = slabInterval((uLocalToBox * vec4(origin, 1.0)).xyz,
                                   mat3(uLocalToBox) * dir, uBoxMin, uBoxMax);
        insideLength = max(0.0, min(back, inClip.y) - max(-front, inClip.x));
    }
    float outsideLength = max(thickness - insideLength, 0.0);

#if MODE == 0
    // The slab in `parts` equal parts, each sampled at its middle and composited front to back
    // here (one part: sampled at the plane point itself). A plane then stands for several
    // samples along its ray, which costs far less than as many planes where each fragment has
    // a large fixed cost (llvmpipe: rasterisation, the set-up above, the float blend).
    float partLength = thickness / float(parts);
    vec3 emitted = vec3(0.0);
    float depthSum = 0.0; // optical depth in front of the current part, within the slab
    for (int j = 0; j < parts; ++j) {
        float a = parts == 1 ? -front : -front + float(j) * partLength;
        float b = parts == 1 ? back : a + partLength;
        float middle = 0.5 * (a + b);
        vec3 x = parts == 1 ? p : origin + dir * middle;
        float inLength = insideLength;
        float outLength = outsideLength;
        if (parts > 1) {
            inLength = uHasBoxClip ? max(0.0, min(b, inClip.y) - max(a, inClip.x)) : 0.0;
            outLength = max((b - a) - inLength, 0.0);
        }
        float xDepth = parts == 1 && !uFacePass ? depth : depth + depthRate * middle;
        float m = uHasPlaneOpacity ? planeOpacityAt((xDepth - uBoxNear) / (uBoxFar - uBoxNear))
                                   : 1.0;
        float wIn = uRegionOpacity.y * inLength;
        float wOut = uRegionOpacity.x * outLength;
        float weighted = (wIn + wOut) * m; // local length, times the modifiers of tau
        if (!(weighted > 0.0)) continue;
#ifdef TAGGED
        int rowX = parts == 1 ? row : rowAt(x);
        vec2 rangeX = parts == 1 ? range : rangeOf(rowX);
#else
        int rowX = 0; // one row: its range is fetched once per fragment
        vec2 rangeX = range;
#endif
        vec3 tc = texCoord(x);
#ifdef PREINTEGRATED
#ifdef TAGGED
        vec3 C;
        float tauL0;
        float tX = parts == 1 && !uFacePass ? 0.0 : middle; // where x is on the ray
        preIntegrateSlab(x, dir, tX - a, b - tX, C, tauL0);
        float D = tauL0 * weighted * uInvL0;
#else
        float vFront = normalised(dataAt(texCoord(origin + dir * a)), rangeX);
        float vBack = normalised(dataAt(texCoord(origin + dir * b)), rangeX);
        vec4 segment = preIntegratedSegment(0, vFront, vBack);
        vec3 C = segment.rgb;
        float D = segment.a * weighted * uInvL0;
#endif
#else
        vec3 C;
        float tauL0;
#ifdef TAGGED
        if (!uFacePass) {
            if (parts == 1) classifySlab(vLocal, dir, front, back, C, tauL0);
            else classifySlab(x, dir, 0.5 * (b - a), 0.5 * (b - a), C, tauL0);
        } else
#endif
        {
            vec4 rgba = classify(normalised(dataAt(tc), rangeX), rowX);
            C = rgba.rgb;
            tauL0 = rgba.a;
        }
        float D = tauL0 * weighted * uInvL0;
#endif
        // Each region's share of the extinction emits its own blended colour.
        C = (wIn * mix(C, uRegionColor[1], uRegionWeight.y) +
             wOut * mix(C, uRegionColor[0], uRegionWeight.x)) / (wIn + wOut);
#ifdef LIGHTING
        C = shade(C, tc, rangeX, parts == 1 ? p : x);
#endif
        // exp(-0) is exactly 1: one part gives C alpha as before.
        emitted += exp(-depthSum) * opacityOf(D) * C;
        depthSum += D;
    }
    float alpha = opacityOf(depthSum);
    if (!(alpha > 0.0)) discard;
    fragColor = vec4(emitted, alpha);
#elif MODE == 3
    // The kept length of the slab weighs the sample.
    float kept = (uRegionOpacity.y > 0.0 ? insideLength : 0.0) +
                 (uRegionOpacity.x > 0.0 ? outsideLength : 0.0);
    if (!(kept > 0.0)) discard;
    float v = normalised(dataAt(texCoord(p)), range);
    fragColor = vec4(v * kept, kept, 0.0, 0.0);
#else
    // The extreme v over the slab. With peaks (the default), one part: at the sample point and
    // where the ray crosses the voxel-centre plane nearest to it along each axis (the trilinear
    // field's kinks, where peaks of thin structures sit); more parts: the middle of each part
    // and every crossing of a voxel-centre plane in the slab, so thick slabs still find them;
    // a face's sliver (as long as a plane spacing, with few planes) as several parts. Either
    // way the slab's ends where they lie on the volume box's face.
    float best = MODE == 1 ? -1.0 : 2.0;
    int bestInfo = 0;
    vec3 u0 = voxelCoord(origin);
    vec3 du = dir * uInvSpacing;
    if (!uMipPeaks) {
        // Evenly spaced samples only (the plane point, or each part's middle), like a ray
        // caster stepping at that spacing: a quarter of the fetches, thin peaks can be missed.
        // Several parts: the peak refined from the most extreme sample and its neighbours,
        // which may be the neighbouring slabs' nearest samples where the ray has them.
        float partLength = thickness / float(parts);
        PeakTracker k = noPeak();
        int outer = parts > 1 ? 1 : 0;
        for (int j = -outer; j < parts + outer; ++j) {
            float t = parts == 1 ? 0.5 * (back - front) : -front + (float(j) + 0.5) * partLength;
            if (t < reach.x || t > reach.y) continue; // (only the neighbours can lie outside)
            int info;
            float v = valueAt(parts == 1 ? p : origin + dir * t, info);
            float s = v < 0.0 ? -1e30 : (MODE == 1 ? v : -v);
            if (j >= 0 && j < parts && s > k.top) {
                best = v;
                bestInfo = info;
            }
            trackSample(k, s, j, parts);
        }
        if (parts > 1 && best >= 0.0 && best <= 1.0) {
            float refined = refinedTop(k);
            best = clamp(MODE == 1 ? refined : -refined, 0.0, 1.0);
        }
    } else if (uSlabSamples <= 1 && !uFacePass) {
        // Both ends of the slab too: where it ends at the box's face, a structure cut by the
        // face has its extreme there (chest CT: up to 90/255 missed along a silhouette).
        vec3 ends[2] = vec3[2](origin - dir * front, origin + dir * back);
        for (int e = 0; e < 2; ++e)
            if (onVolumeFace(ends[e])) considerExtreme(ends[e], best, bestInfo);
        vec3 tCentre = (floor(u0) + 0.5 - u0) / mix(du, vec3(1e-30), equal(du, vec3(0.0)));
        vec4 ts = vec4(uFacePass ? 0.5 * back : 0.0, tCentre);
        for (int i = 0; i < 4; ++i) {
            float t = ts[i];
            if (t < -front || t > back) continue;
            considerExtreme(origin + dir * t, best, bestInfo);
        }
    } else {
        // (Several samples a plane: every crossing even where a short slab has one part, so
        // that every layout takes all of a ray's crossings, as the error model assumes.)
        float partLength = thickness / float(parts);
        if (parts == 1 && !uFacePass)
            considerExtreme(p, best, bestInfo);
        else
            for (int j = 0; j < parts; ++j)
                considerExtreme(origin + dir * (-front + (float(j) + 0.5) * partLength), best,
                                bestInfo);
        vec3 ends[2] = vec3[2](origin - dir * front, origin + dir * back); // as with one part
        for (int e = 0; e < 2; ++e)
            if (onVolumeFace(ends[e])) considerExtreme(ends[e], best, bestInfo);
        for (int axis = 0; axis < 3; ++axis) {
            float d = du[axis];
            if (d == 0.0) continue;
            int count;
            float first = firstCrossing(u0[axis] - d * front, u0[axis] + d * back, count);
            for (int k = 0; k < count; ++k)
                considerExtreme(origin + dir * ((first + float(k) - u0[axis]) / d), best,
                                bestInfo);
        }
    }
    if (best < 0.0 || best > 1.0) discard; // every sample removed
    // v + 1 lies in [1, 2]: its bit pattern orders like v, and its lowest mantissa bits carry
    // the row and region of the sample, so the max (min) blend keeps them with the extreme v.
    fragColor = vec4(uintBitsToFloat((floatBitsToUint(best + 1.0) & ~uInfoMask) | uint(bestInfo)),
                     0.0, 0.0, 0.0);
#endif
#endif // LEAN
}
)GLSL";

/// A triangle that covers the viewport.
inline constexpr const char* compositeVertex = R"GLSL(
void main() {
    vec2 corner = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
    gl_Position = vec4(corner, 0.0, 1.0);
}
)GLSL";

/// MIP / MINIP / AVERAGE: the projected value at each pixel through the transfer function,
/// composited over what is drawn: C(v) A(v) + (1 - A(v)) behind.
inline constexpr const char* compositeFragment = R"GLSL(
uniform sampler2D uProjected;
uniform uint uInfoMask;
uniform vec3 uRegionColor[2];
uniform vec2 uRegionWeight;
out vec4 fragColor;

void main() {
    vec4 s = texelFetch(uProjected, ivec2(gl_FragCoord.xy), 0);
    float v;
    int row = 0;
    int region = 0;
    float weight = 0.0;
#if MODE == 3
    if (!(s.g > 0.0)) discard; // no unclipped volume on this ray
    v = clamp(s.r / s.g, 0.0, 1.0);
#else
#if MODE == 1
    if (s.r < 0.5) discard; // still the cleared 0
#else
    if (s.r > 3.0) discard; // still the cleared 4
#endif
    uint bits = floatBitsToUint(s.r);
    uint info = bits & uInfoMask;
    v = clamp(uintBitsToFloat(bits & ~uInfoMask) - 1.0, 0.0, 1.0);
    row = int(info >> 1u);
    region = int(info & 1u);
    weight = uRegionWeight[region];
#endif
    vec4 rgba = classify(v, row);
    float A = opacityOf(rgba.a); // A(v) = 1 - e^-(tau L0)
    vec3 C = mix(rgba.rgb, uRegionColor[region], weight);
    fragColor = vec4(C * A, A);
}
)GLSL";

} // namespace volsg::shaders
