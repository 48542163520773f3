#include <volsg/sections/SliceSampler.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include <volsg/slicing/TransferTable.h>

namespace volsg {

SliceSampler::SliceSampler(const VolumeInScope& volume, SliceStyle style)
    : volume_(volume), style_(style), halfExtent_(volume.halfExtent()) {
    if (volume.data->type() == VoxelType::Float)
        std::tie(lowest_, highest_) = volume.data->minMax();
    // Once: for Float data the natural range is a pass over the grid.
    const auto [lo, hi] = volume.data->naturalRange();
    naturalRange_ = {lo, hi};
}

double SliceSampler::finiteValue(int i, int j, int k) const {
    const double d = volume_.data->value(i, j, k);
    if (std::isnan(d) || d == -INFINITY) return lowest_;
    if (d == INFINITY) return highest_;
    return d;
}

SliceSample SliceSampler::sample(const glm::dvec3& local) const {
    const VolumeGrid& grid = *volume_.data;
    const glm::ivec3 n = grid.dimensions();
    // Voxel coordinates: voxel i's cell is [i, i + 1), its centre at i + 0.5.
    const glm::dvec3 u = (local + halfExtent_) / grid.spacing();
    SliceSample out;
    for (int a = 0; a < 3; ++a)
        out.voxel[a] = std::clamp(int(std::floor(u[a])), 0, n[a] - 1);
    out.voxelValue = grid.value(out.voxel.x, out.voxel.y, out.voxel.z);
    if (style_.linear) {
        glm::ivec3 i0, i1;
        glm::dvec3 f;
        for (int a = 0; a < 3; ++a) {
            const double c = std::clamp(u[a] - 0.5, 0.0, double(n[a] - 1));
            i0[a] = std::min(int(std::floor(c)), n[a] - 1);
            i1[a] = std::min(i0[a] + 1, n[a] - 1);
            f[a] = c - i0[a];
        }
        auto at = [&](int x, int y, int z) { return finiteValue(x, y, z); };
        auto lerp = [](double a, double b, double t) { return a + (b - a) * t; };
        const double c00 = lerp(at(i0.x, i0.y, i0.z), at(i1.x, i0.y, i0.z), f.x);
        const double c10 = lerp(at(i0.x, i1.y, i0.z), at(i1.x, i1.y, i0.z), f.x);
        const double c01 = lerp(at(i0.x, i0.y, i1.z), at(i1.x, i0.y, i1.z), f.x);
        const double c11 = lerp(at(i0.x, i1.y, i1.z), at(i1.x, i1.y, i1.z), f.x);
        out.value = lerp(lerp(c00, c10, f.y), lerp(c01, c11, f.y), f.z);
    } else {
        out.value = finiteValue(out.voxel.x, out.voxel.y, out.voxel.z);
    }

    const TransferFunction1D* function = &identity_;
    const auto& functions = volume_.transferFunctions;
    if (auto it = functions.find(-1); it != functions.end()) function = &it->second;
    if (volume_.tags) {
        out.tag = int(volume_.tags->value(out.voxel.x, out.voxel.y, out.voxel.z));
        if (auto it = functions.find(out.tag); it != functions.end()) function = &it->second;
    }
    // TransferFunction1D::resolvedDataRange() without its pass over Float data.
    const glm::dvec2 range = function->dataRange().value_or(naturalRange_);
    out.rgba = function->evaluate(TransferFunction1D::normalise(out.value, range.x, range.y));
    switch (style_.alphaUse) {
    case SliceAlphaUse::AsIs:
        out.rgba.a = std::min(out.rgba.a, TransferTable::kMaxOpacity);
        break;
    case SliceAlphaUse::Opaque:
        out.rgba.a = 1.0;
        break;
    case SliceAlphaUse::Binary:
        out.rgba.a = out.rgba.a > 0.0 ? 1.0 : 0.0;
        break;
    }
    return out;
}

} // namespace volsg
