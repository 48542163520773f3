#pragma once
// The rendering model's description of a volume (docs/SCENE-FORMAT.md section 4): what every
// volume path reads, the reference ray caster, the Volume slicer, shear-warp and the slices.

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/core/Object.h>
#include <volsg/volume/PiecewiseLinear.h>
#include <volsg/volume/TransferFunction1D.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

class PagedVolume; // lib/volsg/paging/PagedVolume.h

enum class VolumeRenderMode { DVR, MIP, MINIP, AVERAGE };

/// docs/SCENE-FORMAT.md section 3 BoxClip. The box [origin, origin + extent] is in the volume's
/// local coordinates, or, when `model` is set, in coordinates that `model` maps to world.
/// Inside the box tau is multiplied by insideOpacity and the colour is blended
/// `mix(C, insideColor, insideColorWeight)`; outside likewise with the outside values. A
/// multiplier of 0 removes that region (also for MIP, MINIP and AVERAGE).
struct RayCastBoxClip {
    glm::dvec3 origin{-0.5};
    glm::dvec3 extent{1.0};
    std::optional<glm::dmat4> model;
    double insideOpacity = 1.0;
    double outsideOpacity = 0.0;
    glm::dvec3 insideColor{1.0};
    double insideColorWeight = 0.0;
    glm::dvec3 outsideColor{1.0};
    double outsideColorWeight = 0.0;
};

/// The volume in scope at a node: its data and everything around it that changes what it
/// shows. Built once per node visit by one gatherer from the traversal's state
/// (gatherVolumeInScope, nodes/volsg/volumescene/VolumeInScope.h) and read by every volume
/// path, so they all see the same scene by construction.
/// - data, tags: the nearest VolumeData; `dataOwner` is that node, which keys the GPU copies
///   of its data that all its users share; model: the model matrix at the node drawing it.
/// - transferFunctions: the nearest TransferFunction of each tag (-1: the default for voxels
///   without their own), `transferKeys` a key per tag and `transferKey` one for them all,
///   which change exactly when the set or one of the functions changes.
/// - boxClip: the nearest BoxClip, in its own coordinates (RayCastBoxClip::model).
/// - clipPlanes: every ClipPlane in scope that is on, world (a, b, c, d) keeping
///   a*x + b*y + c*z >= d.
struct VolumeInScope {
    const Object* dataOwner = nullptr;
    ref_ptr<const VolumeGrid> data;
    ref_ptr<const VolumeGrid> tags; ///< optional, UByte or UShort, same dimensions as data
    glm::dmat4 model{1.0};          ///< local to world (affine, invertible)
    std::map<int, TransferFunction1D> transferFunctions;
    std::map<int, std::uint64_t> transferKeys;
    std::uint64_t transferKey = 0;
    std::optional<RayCastBoxClip> boxClip;
    std::vector<glm::dvec4> clipPlanes;
    /// A volume paged from its pyramid (VolumeData's paging): `data` is then its stand-in, a
    /// coarse level whole with level 0's box, which the whole-grid consumers use; the slicer
    /// draws bricks of every level from here.
    std::shared_ptr<PagedVolume> paged;

    /// Half the volume box: it is centred on the local origin (VolumeGrid::extent()).
    glm::dvec3 halfExtent() const { return 0.5 * data->extent(); }
};

/// One volume in the scene.
///
/// - The volume box is centred on the local origin with extent dimensions*spacing; voxel
///   (i,j,k)'s centre is at -extent/2 + (i+0.5, j+0.5, k+0.5)*spacing. The data is trilinear
///   between centres and clamped to the edge between the outermost centres and the box faces.
///   Tags are nearest-neighbour (constant over each voxel's cell).
/// - Non-finite voxels (Float data): before interpolation NaN and -Inf are replaced by the
///   smallest finite value of the grid and +Inf by the largest (VolumeGrid::minMax()). With the
///   default dataRange (the type's range, which for Float is that min..max) a NaN or -Inf voxel
///   thus has v = 0 and a +Inf voxel v = 1, and interpolation near them stays finite.
/// - `transferFunctions`: key -1 is the default for voxels without their own; key N >= 0
///   applies to voxels tagged N. Without key -1 the default is the identity ramp. AVERAGE maps
///   its mean v through the default one.
/// - `planeOpacity`: (t, m) points, m multiplies tau; t = 0 at the nearest and t = 1 at the
///   farthest point of the volume box along the camera's forward axis (the depths of the box's
///   8 corners). Empty means m = 1. DVR only: the projection modes have no extinction.
/// - `clipPlanes`: world (a, b, c, d) keeping a*x + b*y + c*z >= d; tau = 0 on the removed side,
///   and MIP/MINIP/AVERAGE ignore the removed part.
struct RayCastVolume : VolumeInScope {
    VolumeRenderMode mode = VolumeRenderMode::DVR;
    std::vector<PiecewiseLinear::Point> planeOpacity;
};

} // namespace volsg
