#pragma once
// Triangle meshes of Inventor's primitive shapes (SoCube, SoSphere, SoCone, SoCylinder), all
// centred on the origin, counter-clockwise seen from outside, with unit outward normals.
// Negative sizes are taken by magnitude.

#include <volsg/geometry/Mesh.h>

namespace volsg {

/// Tessellation used by the shape nodes: fine enough that smooth shading shows no facets at
/// ordinary sizes. The sphere's largest distance from the true surface is
/// r * (1 - cos(pi/slices) * cos(pi/(2*stacks))), about 0.0024 r for 64 x 32.
inline constexpr int kRoundSlices = 64;  ///< around the Y axis (sphere, cone, cylinder)
inline constexpr int kSphereStacks = 32; ///< pole to pole

/// A box of `size` (width along X, height along Y, depth along Z): 6 faces of 4 vertices with
/// flat normals, 12 triangles.
void buildBoxMesh(const glm::vec3& size, Mesh& out);

/// A UV sphere: `stacks` rings from +Y to -Y, `slices` around Y starting at +Z towards +X.
/// Every vertex lies on the sphere and its normal is the radial direction.
void buildSphereMesh(float radius, int slices, int stacks, Mesh& out);

/// A cone along +Y: apex at +height/2, base circle of `bottomRadius` at -height/2. The sides
/// have smooth normals (one apex vertex per slice carries the normal of the slice's middle);
/// the bottom disk faces -Y.
void buildConeMesh(float bottomRadius, float height, bool sides, bool bottom, int slices,
                   Mesh& out);

/// A cylinder along +Y from -height/2 to +height/2: smooth radial normals on the sides, flat
/// disks facing +Y (top) and -Y (bottom).
void buildCylinderMesh(float radius, float height, bool sides, bool top, bool bottom, int slices,
                       Mesh& out);

} // namespace volsg
