#pragma once
// Meshes of Inventor's indexed shapes (SoIndexedFaceSet, SoIndexedLineSet) from plain arrays,
// so the rules can be tested without a scene graph.

#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include <volsg/geometry/Mesh.h>

namespace volsg {

/// Triangles from polygons. `coordIndex` lists point indices, each polygon ended by -1 (a
/// final polygon without -1 counts too); convex polygons are fanned from their first corner,
/// keeping their winding. Every corner becomes its own vertex, so flat and smooth normals mix.
///
/// Normals, the first rule that applies:
/// 1. `normalIndex` is in use (not empty and not the default [-1]) and `normals` is not empty:
///    corner k takes normals[normalIndex[k]] (normalIndex runs parallel to coordIndex,
///    -1 separators included; Inventor's PER_VERTEX_INDEXED binding).
/// 2. `normals` has an entry for every point index that coordIndex uses: corner k takes
///    normals[coordIndex[k]] (Inventor's default binding with normalIndex [-1]).
/// 3. Otherwise each polygon gets its flat normal by Newell's method, which is robust for
///    any planar polygon; polygons of zero area are left out (they cover nothing).
/// Given normals are normalized; a zero one is replaced by the polygon's Newell normal.
///
/// Bad input never crashes and is not an error: a polygon with an index below -1, a point or
/// normal index out of range, or fewer than 3 corners is skipped, silently and without a
/// count, and the rest of the shape is built.
void buildFaceSetMesh(std::span<const glm::vec3> points, std::span<const std::int32_t> coordIndex,
                      std::span<const glm::vec3> normals, std::span<const std::int32_t> normalIndex,
                      Mesh& out);

/// Line segments from polylines: `coordIndex` as above, each polyline of n points gives n-1
/// segments. No normals (lines are unlit). A polyline with a bad index or fewer than 2 points
/// is skipped, silently.
void buildLineSetMesh(std::span<const glm::vec3> points, std::span<const std::int32_t> coordIndex,
                      Mesh& out);

} // namespace volsg
