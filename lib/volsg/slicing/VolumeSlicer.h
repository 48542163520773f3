#pragma once
// The GL renderer of the Volume node: 3D-texture slicing (Cabral et al. 1994; the seed's
// Inventor Volume node) measured against docs/SCENE-FORMAT.md section 4.

#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include <volsg/render/FrameContext.h>
#include <volsg/slicing/SlicingStats.h>
#include <volsg/volume/VolumeModel.h>

namespace volsg {

/// How the slicer renders, not what (they choose speed and method, not the image the
/// rendering model defines). The Volume node sets them from its fields of the same names,
/// which document them (nodes/volsg/nodes/Volume.h); 0 counts mean automatic.
struct SlicingSettings {
    int numPlanes = 0;
    int interactivePlanes = 0;
    int samplesPerPlane = 1;
    bool mipPeaks = true;
    bool refinePeaks = true;
    bool nearest = false; ///< interpolation NEAREST
    bool preIntegrated = false;
    bool lighting = false;
    std::uint64_t textureBudget = 0;
    /// Skip the cells of 8^3 voxels that cannot emit (RenderDebug::skipEmptyCells).
    bool skipEmptyCells = true;
    /// Error targets (RMSE per channel of the image, 0..1 units) for still and interactive
    /// frames; 0: no target, the automatic settings are the fixed rules of numPlanes etc. With
    /// a target, the settings not marked fixed below are chosen per frame as the cheapest whose
    /// predicted error meets it (SlicingQuality.h); numPlanes > 0 and interactivePlanes > 0 fix
    /// the plane counts.
    double errorTarget = 0.0;
    double interactiveErrorTarget = 0.0;
    bool fixedSamplesPerPlane = false;
    bool fixedPreIntegrated = false;
    bool fixedMipPeaks = false;
    /// Plane spacing along the view in L0 (set by the slicer from the target): replaces the
    /// automatic plane count when numPlanes is 0; for this frame, interactive or not.
    double planeSpacingL0 = 0.0;
    /// A paged volume (RayCastVolume::paged): a brick's level is fine enough when one of its
    /// voxels projects to at most this many pixels (the Volume's lodPixels).
    double lodPixels = 1.0;
    glm::vec3 specular{0.0f}; ///< lighting: the Material's specular colour
    float shininess = 0.2f;   ///< lighting: the Material's shininess (Inventor, 0..1)
};

/// Draws one volume in the Volume pass of a frame: view-aligned proxy planes cut from
/// each brick with one shared PlaneLayout, back to front, into the float target over what the
/// opaque pass drew, with its depth test. lib/volsg/slicing/README.md has the measurements.
///
/// What a slice fragment does (DVR), at the point p of plane k on a pixel's ray:
/// - data d = scale * texel + offset from the brick's 3D texture (trilinear, or nearest), the
///   row of its tag from the tag texture (texelFetch, nearest) and the tag -> row map, then
///   v = normalise(d, the row's dataRange) in float, then (C, tau L0) from the row
///   (TransferTable: tau L0 = -ln(1 - min(A, 1 - 1e-6)) baked in double);
/// - the slab it stands for: half the way to the neighbouring planes along the ray, in LOCAL
///   units (plane spacing / |cos| of the ray to the view axis, through the inverse model-view),
///   extended to the boundary where the neighbour's point lies outside the box, in front of
///   the near plane, behind opaque geometry or on the removed side of a clip plane, so the
///   slabs tile every ray's visible part of the volume exactly; front faces of the box and
///   entered clip planes stand for the rays no plane crosses (silhouette slivers);
/// - tagged: the slab split at its tag cell's faces, each part with its own tag; BoxClip: the
///   slab split at the box faces, each part with its region's opacity and colour blend;
///   planeOpacity m(t) multiplies tau; alpha = 1 - e^-(tau ds) (a series for small values);
///   shaded when lighting; output (C alpha, alpha), blended (ONE, ONE_MINUS_SRC_ALPHA) in float.
/// - ClipPlanes (all of them, up to 32) discard exactly where n.p < d.
///
/// MIP / MINIP: the extreme v over the slab (at p and where the ray crosses the nearest
/// voxel-centre planes), as v + 1 with the sample's row and BoxClip region in its lowest
/// mantissa bits, max (min) blended into an R32F target sharing the opaque depth; then one
/// composite pass draws C(v) A(v) + (1 - A(v)) behind. The bits hold row * 2 + region; with R
/// rows (1 + tagged transfer functions) and a BoxClip they cost ceil(log2(2R)) bits, so v is
/// truncated to 2^-(23 - bits) (exact without tags or BoxClip; 2^-19 with 4 tagged functions).
/// Equal values after truncation keep the larger (MIP) / smaller (MINIP) row. AVERAGE:
/// (v ds, ds) added into an RG32F target, then the mean through the default function.
///
/// Lighting: central differences of v on the fly (6 extra fetches per fragment, no extra
/// texture memory and nothing to rebuild when the data changes; bricks then carry one guard
/// voxel so differences are exact across seams). The reference does not shade: lit images are
/// compared only for sanity. Pre-integration: see PreIntegrationTable; used for DVR of
/// volumes without tagged transfer functions (tagged ones fall back to post-classification:
/// the table would need one 2D slice per pair of rows).
///
/// Several Volume nodes are drawn one after the other in traversal order: correct where they
/// do not overlap along a ray; where they overlap, the later one is composited over the
/// earlier one as a whole (not merged per sample as the reference does).
class VolumeSlicer {
public:
    /// Draws `volume` (its data, tags, model, transfer functions, mode, planeOpacity, BoxClip,
    /// and world clip planes, as the reference ray caster takes them) if this is the Volume
    /// pass, lit by `lights` when settings.lighting. `owner` keys the GPU cache (textures,
    /// tables) in the frame's RenderCache; `volume.transferKey` must change whenever the
    /// transfer functions change: the tables are rebuilt only then, and the volume textures
    /// never are. Throws Error for invalid input (mismatched tag grid, too many rows, lights or
    /// clip planes).
    static void draw(FrameContext& frame, const Object& owner, const RayCastVolume& volume,
                     std::span<const SceneLight> lights, const SlicingSettings& settings,
                     SlicingStats& stats);

    /// Stages the textures of the grid `owner` will show next (a VolumeSeries' next step that
    /// is in memory already) in a pixel unpack buffer, laid out as the last frame's bricks, so
    /// that the frame showing it uploads from the ready buffer (SlicingStats::stagedUploads).
    /// Call in the Volume pass after draw(); nothing to do when that grid is staged already.
    static void stage(FrameContext& frame, const Object& owner,
                      const ref_ptr<const VolumeGrid>& data, const ref_ptr<const VolumeGrid>& tags);
};

} // namespace volsg
