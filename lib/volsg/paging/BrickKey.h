#pragma once
// Which brick of which pyramid level: the key of the host and texture brick caches.

#include <cstddef>
#include <functional>
#include <tuple>

#include <glm/glm.hpp>

namespace volsg {

/// Brick `index` of level `level` (0 the finest) in a PagedVolume's brick grid.
struct BrickKey {
    int level = 0;
    glm::ivec3 index{0};

    bool operator==(const BrickKey& o) const { return level == o.level && index == o.index; }
    bool operator<(const BrickKey& o) const {
        return std::tie(level, index.z, index.y, index.x) <
               std::tie(o.level, o.index.z, o.index.y, o.index.x);
    }
};

} // namespace volsg
