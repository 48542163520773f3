#pragma once
// Triangle meshes of Inventor's primitive shapes (SoCube, SoSphere, SoCone, SoCylinder), all
// centred on the origin, counter-clockwise seen from outside, with unit outward normals and
// Inventor's default texture coordinates. Negative sizes are taken by magnitude.

#include <cstdint>
#include <vector>

#include <volsg/geometry/Mesh.h>

namespace volsg {

/// Coin's tessellation of the round primitives at a complexity value c (SoSphere, SoCone,
/// SoCylinder and sogl_render_* in Coin 4): a sphere has (int)(30 c) slices and (int)(30 c)
/// rings pole to pole (c clamped to [0, 1]), so 15 x 14 bands at the default 0.5; cones and
/// cylinders (int)(40 c) sides (20 at 0.5; c not clamped). Slices are at least 4 and at most
/// 128, rings at least 3.
int sphereSlicesFor(float complexity);
/// Bands pole to pole (Coin's rings minus one): at least 2.
int sphereStacksFor(float complexity);
/// Sides of a cone or cylinder.
int roundSlicesFor(float complexity);

/// The largest distance of buildSphereMesh's surface from its sphere: at the middle of the
/// widest band's facets, |radius| (1 - cos(pi / slices) cos(pi / (2 stacks))).
double sphereMeshDeviation(float radius, int slices, int stacks);
/// The same for the round sides of a cone or cylinder with `slices` sides and their disks: the
/// sagitta |radius| (1 - cos(pi / slices)) of the base circle's chords.
double roundMeshDeviation(float radius, int slices);
/// The side counts of the coarser tessellations below `slices` (a detail chain), each about
/// 2/3 of the one before, finest first, down to `minimum` (Coin's least count for the shape).
std::vector<int> coarserSliceCounts(int slices, int minimum);

/// Where each part of a primitive starts among the mesh's vertices (for PER_PART materials):
/// parts appear in Inventor's part order and end where the next begins.
using PartStarts = std::vector<std::uint32_t>;

/// A box of `size` (width along X, height along Y, depth along Z): 6 faces of 4 vertices with
/// flat normals, 12 triangles, in Inventor's face order front (+Z), back, left (-X), right,
/// top, bottom; each face's texture covers the whole image, upright seen from outside (top and
/// bottom: seen with the front face below).
void buildBoxMesh(const glm::vec3& size, Mesh& out, PartStarts* faces = nullptr);

/// A UV sphere: `stacks` bands from +Y to -Y, `slices` around Y starting at the back (-Z) and
/// turning counter-clockwise seen from +Y (towards -X). Every vertex lies on the sphere and its
/// normal is the radial direction. Texture: s 0..1 around from the back, t 0..1 bottom to top;
/// at a pole s is the middle of its slice (as Coin's).
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
