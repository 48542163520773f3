#pragma once
// A k-d split of a volume into boxes, one per process of a sort-last render, and the boxes'
// visibility order for a view. Plain geometry: no GL, no MPI.

#include <vector>

#include <glm/glm.hpp>

namespace volsg {

/// Splits a volume of `dimensions` voxels (`spacing` apart; local coordinates centred on the
/// box, as the slicer's) into `parts` boxes. Voxel i's centre is at voxel coordinate u = i +
/// 0.5; cuts lie on the planes u = c + 0.5 between cells, as brick seams do, so a part is
/// voxels first..last drawing u in [first + 0.5, last + 0.5] (from the face u = 0 for the first
/// and to u = N for the last). The box with the longest extent along an axis is cut there, into
/// two with cells in proportion to the parts each side gets (half, rounded down, on the low
/// side), recursively. A volume with fewer cells than parts leaves the last parts empty.
///
/// Why a split of the box rather than of the bricks: each part draws the fragments whose plane
/// point lies in its box, each computed as the single process computes it (same bricks, same
/// samples), so composited in visibility order the parts give the single-process blend
/// sequence, whatever the plane layout and samples per plane.
class KdVolumeSplit {
public:
    struct Part {
        bool empty = true;
        glm::ivec3 firstVoxel{0}; ///< the voxels whose centres the part spans (inclusive)
        glm::ivec3 lastVoxel{0};
        glm::dvec3 boxMin{0.0}; ///< the region it draws, local coordinates
        glm::dvec3 boxMax{0.0};
    };

    KdVolumeSplit(glm::ivec3 dimensions, glm::dvec3 spacing, int parts);

    int parts() const { return int(parts_.size()); }
    const Part& part(int p) const { return parts_[std::size_t(p)]; }

    /// The voxels part p's fragments may sample: its own and `ghost` more on each side (within
    /// the volume), as first voxel and count. An empty part: count 0.
    void voxelsWithGhost(int p, int ghost, glm::ivec3& first, glm::ivec3& count) const;

    /// The parts front to back for a viewer at `eyeOrDirection` (local coordinates: the eye,
    /// or the viewing direction when orthographic). At every cut the side holding the eye
    /// (orthographic: the side the view comes from) is in front: the leaves of a k-d tree in
    /// that order are a visibility order for any viewer, as a ray crosses each cut plane at
    /// most once. Empty parts come last.
    std::vector<int> frontToBack(const glm::dvec3& eyeOrDirection, bool orthographic) const;

private:
    struct Cut {
        int axis = -1;      ///< -1: a leaf
        double plane = 0.0; ///< local coordinate of the cut along `axis`
        int low = -1, high = -1;
        int part = -1; ///< a leaf's part
    };
    glm::ivec3 dims_{1};
    glm::dvec3 spacing_{1.0};
    std::vector<Part> parts_;
    std::vector<Cut> cuts_;

    double localOf(int axis, int voxel, bool upper) const;
    int split(glm::ivec3 first, glm::ivec3 last, int firstPart, int count);
};

} // namespace volsg
