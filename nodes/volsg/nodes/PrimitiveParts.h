#pragma once
// Materials of the primitive shapes' parts (Cube faces, Cone and Cylinder parts): under a
// PER_PART or PER_FACE material binding (and their _INDEXED forms, which index in order) each
// part takes its own material, in Inventor's part order.
#include <volsg/geometry/PrimitiveMeshes.h>

namespace volsg {

class State;

/// Gives the mesh per-vertex colours by part when the material binding in scope asks for
/// them; `allParts` is the index of each built part among all the shape's parts (a Cylinder
/// without its top still takes the bottom's material from the third).
void colorPrimitiveParts(const State& state, const PartStarts& starts,
                         const std::vector<int>& allParts, Mesh& mesh);

} // namespace volsg
