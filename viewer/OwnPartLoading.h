#pragma once
// A sort-last process reading only its own part of the volume (and a ghost layer) from an
// OME-Zarr image, chunk by chunk. lib/volsg/sortlast/README.md, "Loading only a process's own
// data".

#include <string>

#include <glm/glm.hpp>

#include <volsg/core/Node.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg::cli {

/// What loading the process's own part did.
struct OwnPartLoad {
    bool loaded = false; ///< only the part and its ghost were read
    /// The volume is paged from its pyramid: each process's frames load only the bricks
    /// meeting its part (PagedBricks.cpp, keepToPart), so nothing is read here.
    bool paged = false;
    std::string whyNot; ///< when not, why (the whole volume is read as usual)
    double milliseconds = 0.0;
    double voxelsRead = 0.0; ///< voxels of the box read (the chunks hold some more)
    /// 16-bit and float data take the data's own range where a transfer function gives none:
    /// the processes must agree on the whole volume's (agreeOnRange).
    bool needsRange = false;
    glm::dvec2 ownRange{0.0}; ///< smallest and largest finite value of the box read
    VoxelType type = VoxelType::UByte;
};

/// Voxels beyond its box a part's fragments sample when the process holds only its part: one
/// for trilinear interpolation and one for lighting's central differences beyond the part's
/// faces, where slabs end (VolumePartition::ownDataOnly); where planes lie at most a voxel
/// apart or a fragment samples only its point, slabs reach at most half a voxel further.
constexpr int kOwnPartGhost = 4;

/// When the scene's one VolumeData pages an OME-Zarr pyramid, reads nothing and says so (paged).
/// Otherwise, when it reads an OME-Zarr image (no labels), reads part `part` of `parts`
/// (KdVolumeSplit) with kOwnPartGhost voxels around it into the node
/// (VolumeData::adoptLoaded); the rest of the grid holds the fill value. The render must then
/// set VolumePartition::ownDataOnly. Otherwise reads nothing and says why. Relative file names
/// resolve against `sceneFile`'s folder. A Volume drawn to an error target reads the whole
/// image unless `underTarget`: its quadrature may lay slabs deeper than the ghost, which a
/// process holding its part must end at the part's faces, so the frame would meet the target
/// but not be one process's within 1/255 (lib/volsg/sortlast/README.md).
OwnPartLoad loadOwnPart(Node& root, const std::string& sceneFile, int part, int parts,
                        bool underTarget = false);

/// Gives the transfer functions that take the data's own range `range` (the whole volume's,
/// agreed by the processes) as their dataRange, as one process reading it all would use.
void useDataRange(Node& root, glm::dvec2 range);

} // namespace volsg::cli
