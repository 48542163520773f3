#include <volsg/slicing/BrickLayout.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace volsg {

namespace {

constexpr int kMaxBricksPerAxis = 16;

int bricksAlong(int voxels, int cells) {
    return voxels <= 1 ? 1 : (voxels - 1 + cells - 1) / cells;
}

/// First and last voxel of brick k's texture along one axis.
glm::ivec2 voxelRange(int voxels, int cells, int k, int guard) {
    return {std::max(k * cells - guard, 0), std::min((k + 1) * cells + guard, voxels - 1)};
}

int largestTextureAlong(int voxels, int cells, int guard) {
    int largest = 1;
    const int count = bricksAlong(voxels, cells);
    for (int k = 0; k < count; ++k) {
        const glm::ivec2 r = voxelRange(voxels, cells, k, guard);
        largest = std::max(largest, r.y - r.x + 1);
    }
    return largest;
}

} // namespace

BrickLayout::BrickLayout(glm::ivec3 dimensions, glm::dvec3 spacing, const Limits& limits)
    : dims_(glm::max(dimensions, glm::ivec3(1))), spacing_(spacing),
      bytesPerVoxel_(std::max<std::size_t>(limits.bytesPerVoxel, 1)) {
    const int maxSize = std::max(limits.maxTextureSize, 2);
    const int guard = std::max(limits.guard, 0);
    cells_ = glm::max(dims_ - 1, glm::ivec3(1));
    // At most kMaxBricksPerAxis bricks along an axis (unless the texture size limit needs
    // more): a tiny budget gets bricks of 1/16 of the axis instead of voxel-sized bricks
    // (n^3 of them, each drawn per plane), and says it does not fit.
    glm::ivec3 minCells;
    for (int a = 0; a < 3; ++a)
        minCells[a] = (cells_[a] + kMaxBricksPerAxis - 1) / kMaxBricksPerAxis;
    for (;;) {
        glm::ivec3 texels;
        for (int a = 0; a < 3; ++a)
            texels[a] = largestTextureAlong(dims_[a], cells_[a], guard);
        const double bytes = double(texels.x) * texels.y * texels.z * double(bytesPerVoxel_);
        const bool withinBudget = limits.budgetBytes == 0 || bytes <= double(limits.budgetBytes);
        const bool withinSize = texels.x <= maxSize && texels.y <= maxSize && texels.z <= maxSize;
        largest_ = texels;
        if (withinBudget && withinSize) break;
        // Halve the axis with the largest texture that can still be split.
        int axis = -1;
        // The texture size limit always holds; the minimum brick only bounds what the budget
        // may ask for.
        for (int a = 0; a < 3; ++a)
            if (cells_[a] > 1 && (!withinSize || (cells_[a] + 1) / 2 >= minCells[a]) &&
                (axis < 0 || texels[a] > texels[axis]))
                axis = a;
        if (axis < 0) {
            fitsBudget_ = withinBudget;
            break;
        }
        cells_[axis] = (cells_[axis] + 1) / 2;
    }

    for (int a = 0; a < 3; ++a)
        grid_[a] = bricksAlong(dims_[a], cells_[a]);
    const glm::dvec3 halfExtent = 0.5 * glm::dvec3(dims_) * spacing_;
    bricks_.reserve(std::size_t(grid_.x) * grid_.y * grid_.z);
    for (int kz = 0; kz < grid_.z; ++kz)
        for (int ky = 0; ky < grid_.y; ++ky)
            for (int kx = 0; kx < grid_.x; ++kx) {
                Brick b;
                b.index = {kx, ky, kz};
                for (int a = 0; a < 3; ++a) {
                    const int k = b.index[a];
                    const glm::ivec2 r = voxelRange(dims_[a], cells_[a], k, guard);
                    b.firstVoxel[a] = r.x;
                    b.voxelCount[a] = r.y - r.x + 1;
                    const double u0 = k == 0 ? 0.0 : k * cells_[a] + 0.5;
                    const double u1 =
                        k == grid_[a] - 1 ? double(dims_[a]) : (k + 1) * cells_[a] + 0.5;
                    b.boxMin[a] = u0 * spacing_[a] - halfExtent[a];
                    b.boxMax[a] = u1 * spacing_[a] - halfExtent[a];
                }
                bricks_.push_back(b);
            }
}

BrickLayout BrickLayout::fromBricks(std::vector<Brick> bricks, glm::ivec3 dimensions,
                                    glm::dvec3 spacing, std::size_t bytesPerVoxel) {
    BrickLayout layout;
    layout.dims_ = dimensions;
    layout.spacing_ = spacing;
    layout.grid_ = glm::ivec3(0);
    layout.bytesPerVoxel_ = bytesPerVoxel;
    for (const Brick& b : bricks)
        layout.largest_ = glm::max(layout.largest_, b.voxelCount);
    layout.bricks_ = std::move(bricks);
    layout.explicit_ = true;
    return layout;
}

void BrickLayout::backToFront(const glm::dvec3& eyeOrDirection, bool orthographic,
                              std::vector<int>& order) const {
    const glm::dvec3 halfExtent = 0.5 * glm::dvec3(dims_) * spacing_;
    glm::ivec3 viewerBrick(0);
    if (!orthographic)
        for (int a = 0; a < 3; ++a) {
            const double u = (eyeOrDirection[a] + halfExtent[a]) / spacing_[a];
            const double k = std::floor((u - 0.5) / cells_[a]);
            viewerBrick[a] = int(std::clamp(k, 0.0, double(grid_[a] - 1)));
        }
    sortScratch_.clear();
    for (std::size_t i = 0; i < bricks_.size(); ++i) {
        const glm::ivec3& k = bricks_[i].index;
        int distance = 0;
        for (int a = 0; a < 3; ++a) {
            if (!orthographic)
                distance += std::abs(k[a] - viewerBrick[a]);
            else if (eyeOrDirection[a] > 0.0)
                distance += k[a];
            else if (eyeOrDirection[a] < 0.0)
                distance += grid_[a] - 1 - k[a];
        }
        sortScratch_.emplace_back(-distance, int(i));
    }
    std::sort(sortScratch_.begin(), sortScratch_.end());
    order.clear();
    for (const auto& entry : sortScratch_)
        order.push_back(entry.second);
}

} // namespace volsg
