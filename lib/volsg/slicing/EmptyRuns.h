#pragma once
// The stretches of a ray that lie in cells no DVR sample can make emit (EmptyCells, classified
// with a pad that covers the tables' filtering). The error model integrates its rays many times
// (the truth once, then every quadrature the search tries), and on a body in air most of a
// ray's length is such cells: there a segment's optical depth is exactly 0, so skipping it
// leaves every composite as it was.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace volsg {

class EmptyCells;

/// The cells as a trilinear sampler meets them: a point's voxel coordinate
/// u = clamp((p + half) / spacing - 1/2, 0, dims - 1) lies in cell floor(u / kCellSize), whose
/// measured range holds every voxel that sample reads.
struct EmptyCellMap {
    glm::dvec3 half{0.0}, spacing{1.0};
    glm::ivec3 dims{1};
    const EmptyCells* cells = nullptr; ///< classified; its flag 0 = cannot emit
};

/// [start, end] in t of ray origin + t dir within [t0, t1], ascending and disjoint, each inside
/// cells that cannot emit and shrunk by a hair at both ends (so rounding in a sample's position
/// cannot put it in the neighbouring cell).
std::vector<glm::dvec2> emptyRunsAlong(const EmptyCellMap& map, const glm::dvec3& origin,
                                       const glm::dvec3& dir, double t0, double t1);

/// Queries in ascending t over one ray's runs.
class EmptyRunCursor {
public:
    explicit EmptyRunCursor(const std::vector<glm::dvec2>* runs) : runs_(runs) {}
    /// The run holding all of [a, b], or null. Calls must not decrease a.
    const glm::dvec2* covering(double a, double b) {
        if (!runs_) return nullptr;
        while (next_ < runs_->size() && (*runs_)[next_].y < a)
            ++next_;
        if (next_ == runs_->size()) return nullptr;
        const glm::dvec2& r = (*runs_)[next_];
        return r.x <= a && b <= r.y ? &r : nullptr;
    }

private:
    const std::vector<glm::dvec2>* runs_;
    std::size_t next_ = 0;
};

} // namespace volsg
