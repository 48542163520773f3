#pragma once
// Draws planar sections (OrthoSlice, ObliqueSlice) as textured polygons into a frame.

#include <volsg/sections/SlicePlane.h>
#include <volsg/sections/SliceSampler.h>
#include <volsg/volume/VolumeModel.h>

namespace volsg {

struct FrameContext;

/// The pass a slice draws in: Opaque for ALPHA_OPAQUE and ALPHA_BINARY (its pixels are
/// opaque or discarded, and it writes depth, so Volume nodes composite with it as with any
/// opaque shape), Transparent for ALPHA_AS_IS (blended over what is drawn; over a Volume as a
/// whole, like transparent shapes).
///
/// Per fragment: the data from a 3D texture of the whole volume (trilinear by the texture
/// filter, or texelFetch of the nearest voxel), the tag's row from the same tag map and
/// transfer table as the Volume slicer (TransferTable, shaders::sliceCommon), then alpha by
/// SliceAlphaUse; fully transparent fragments are discarded; ClipPlanes in scope discard
/// their removed side. The data texture is kept per data owner (the VolumeData node) and grid
/// in the frame's RenderCache, so every slice of one volume shares one copy; the tables per
/// data owner and transfer functions.
class SliceRenderer {
public:
    static constexpr int kMaxClipPlanes = 32;

    /// Draws the slice if this pass is its pass, clipped by the volume's clip planes. Throws
    /// Error for more clip planes than kMaxClipPlanes or more tagged transfer functions than a
    /// table holds.
    static void draw(FrameContext& frame, const VolumeInScope& volume, const SlicePlane& plane,
                     const SliceStyle& style);
};

} // namespace volsg
