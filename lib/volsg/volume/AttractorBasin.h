#pragma once
// The "attractor and basin" scene of the RTVR paper (Mroz & Hauser, table 1, row 3; its
// section 5 application to dynamical systems), generated: a chaotic attractor as a volumetric
// density inside a closed surface around it, as a labelled volume.

#include <cstddef>

#include <volsg/core/Object.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

/// What makeAttractorBasin() returns. Tags: 0 empty space, attractorTag the attractor's
/// voxels, basinSurfaceTag the one-voxel layer that bounds the basin region around it.
struct AttractorBasinVolume {
    static constexpr int attractorTag = 1;
    static constexpr int basinSurfaceTag = 2;

    ref_ptr<VolumeGrid> data; ///< UByte, spacing 1
    ref_ptr<VolumeGrid> tags; ///< UByte, same dimensions
    std::size_t attractorVoxels = 0;
    std::size_t surfaceVoxels = 0;
};

/// An n^3 labelled volume (16 <= n <= 512) of the Lorenz system (sigma 10, rho 28, beta 8/3), the
/// best-known chaotic flow, integrated with fixed-step RK4 from a fixed start (deterministic:
/// no random numbers, the same bytes on every run and thread count).
///
/// - Attractor (tag 1): the time the trajectory spends in each voxel (its invariant measure),
///   smoothed by a tent filter of radius 4% of n so the thin sheets become a volumetric,
///   fuzzy object; the voxels above a density threshold (0.5% of a thin sheet's mean density).
///   Data 128..255: the log of the density normalised over the attractor.
/// - Basin (tag 2): the Lorenz attractor attracts almost all of phase space, so the closed
///   surface is the boundary of the attractor's neighbourhood: the region where a wide blur
///   (a tent of radius 6% of n) of the attractor's indicator exceeds 0.08, joined with the
///   attractor and its 6-neighbours, so the attractor lies strictly inside. Tag 2 marks the
///   region's voxels that have a 6-neighbour outside it. Data 0..127 outside the attractor: the
///   wide field, scaled so that the surface's level is at 64, so gradients of the data are the
///   surface's normals (for shading).
/// - Phase space is mapped per axis so the attractor fills the middle of the cube, with a margin
///   (9% of n, more for small n) wider than both filters reach: no tagged voxel on a face.
///
/// At n = 256: 910549 attractor and 94327 surface voxels, 1.005M in all (the paper's scene has
/// 1M). Release build, this 2-core machine kind: 1.3 s wall at load 4, about 1.2 s of CPU.
AttractorBasinVolume makeAttractorBasin(int n);

} // namespace volsg
