#pragma once
// The complexity value the round primitives (Sphere, Cone, Cylinder) are tessellated at, as
// Coin's SoShape::getComplexityValue computes it: OBJECT_SPACE the Complexity's value (0.5
// without one), BOUNDING_BOX 0.5, SCREEN_SPACE sqrt(the larger side in pixels of the shape's
// projected bounding box) * 0.4 * value, when the state has a projected view (rendering, a
// pick through a pixel); without one, the value.
#include <volsg/math/Box3.h>

namespace volsg {

class State;

/// Not clamped (SCREEN_SPACE exceeds 1 for shapes larger than about 6 pixels); a value that is
/// not finite counts as 0.5. `objectBox` is the shape's bounding box in its own coordinates.
float primitiveComplexity(const State& state, const Box3& objectBox);

/// The tessellation follows the view (SCREEN_SPACE): render caches cannot keep the shape.
bool tessellationFollowsView(const State& state);

} // namespace volsg
