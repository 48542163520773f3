#pragma once
// Generated scene files for the benchmark suites. They are plain Inventor 2.1 files, so the same
// files can be timed in Coin3D (write them with `volsg-bench --suite NAME --keep DIR`).

#include <string>

namespace volsg::bench {

/// About `nodeCount` nodes: Separators each holding Transform, Material and a shape, cycling
/// through Cube, Sphere, Cone and Cylinder, with varied field values (deterministic).
std::string generateParseScene(int nodeCount);

/// A `side` x `side` grid of Separator { Transform Material shape } in the XY plane, with an
/// orthographic camera and a directional light that see all of it.
std::string generateGridScene(int side);

} // namespace volsg::bench
