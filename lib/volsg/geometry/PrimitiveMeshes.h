#pragma once
// Triangle meshes of Inventor's primitive shapes (SoCube, SoSphere, SoCone, SoCylinder), all
// centred on the origin, counter-clockwise seen from outside, with unit outward normals and
// Inventor's default texture coordinates. Negative sizes are taken by magnitude.

#include <cstdint>
#include <vector>

#include <volsg/geometry/Mesh.h>

namespace volsg {

/// Tessellation at Complexity 0.5 (the default): fine enough that smooth shading shows no
/// facets at ordinary sizes. The sphere's largest distance from the true surface is
/// r * (1 - cos(pi/slices) * cos(pi/(2*stacks))), about 0.0024 r for 64 x 32.
inline constexpr int kRoundSlices = 64;  ///< around the Y axis (sphere, cone, cylinder)
inline constexpr int kSphereStacks = 32; ///< pole to pole

/// Slices around Y for a Complexity value in [0, 1]: kRoundSlices at 0.5, proportional to it,
/// at least 6 (so even a complexity of 0 keeps a round outline, as Inventor's does).
int roundSlicesFor(float complexity);

/// Where each part of a primitive starts among the mesh's vertices (for PER_PART materials):
/// parts appear in Inventor's part order and end where the next begins.
using PartStarts = std::vector<std::uint32_t>;

/// A box of `size` (width along X, height along Y, depth along Z): 6 faces of 4 vertices with
/// flat normals, 12 triangles, in Inventor's face order front (+Z), back, left (-X), right,
/// top, bottom; each face's texture covers the whole image, upright seen from outside (top and
/// bottom: seen with the front face below).
void buildBoxMesh(const glm::vec3& size, Mesh& out, PartStarts* faces = nullptr);

/// A UV sphere: `stacks` rings from +Y to -Y, `slices` around Y starting at the back (-Z) and
/// turning counter-clockwise seen from +Y (towards -X). Every vertex lies on the sphere and its
/// normal is the radial direction. Texture: s 0..1 around from the back, t 0..1 bottom to top.
void buildSphereMesh(float radius, int slices, int stacks, Mesh& out);

/// A cone along +Y: apex at +height/2, base circle of `bottomRadius` at -height/2. The sides
/// have smooth normals (one apex vertex per slice carries the normal of the slice's middle);
/// the bottom disk faces -Y. Parts: sides, bottom. Texture: sides as a cylinder's, the bottom
/// a disk cut from the image as seen from below.
void buildConeMesh(float bottomRadius, float height, bool sides, bool bottom, int slices, Mesh& out,
                   PartStarts* parts = nullptr);

/// A cylinder along +Y from -height/2 to +height/2: smooth radial normals on the sides, flat
/// disks facing +Y (top) and -Y (bottom). Parts: sides, top, bottom. Texture: sides s around
/// from the back, t bottom to top; the disks cut from the image as seen from outside.
void buildCylinderMesh(float radius, float height, bool sides, bool top, bool bottom, int slices,
                       Mesh& out, PartStarts* parts = nullptr);

} // namespace volsg
