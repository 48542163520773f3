#pragma once
// The histogram of a grid's voxel values over its actual range, and the first transfer
// function chosen from it for a volume opened without one.

#include <cstdint>
#include <vector>

#include <volsg/volume/TransferFunction1D.h>

namespace volsg {

class VolumeGrid;

/// Voxel counts in equal bins over [lo, hi]: the smallest and largest finite voxel values, or,
/// for integer data with no more distinct values than `maxBins`, those +- 0.5 with one bin per
/// value (so a value is never split between bins).
struct DataHistogram {
    double minimum = 0.0, maximum = 0.0; ///< of the finite voxels: the data range to use
    double lo = 0.0, hi = 0.0;           ///< the bins' outer edges
    std::vector<std::uint64_t> counts;
    std::uint64_t total = 0;

    double binWidth() const { return counts.empty() ? 0.0 : (hi - lo) / double(counts.size()); }
    double binCentre(std::size_t bin) const { return lo + (double(bin) + 0.5) * binWidth(); }
};

DataHistogram histogramOf(const VolumeGrid& grid, std::size_t maxBins = 256);

/// A first transfer function for data nobody has looked at: dataRange is the data's
/// minimum..maximum; the dominant peak (the background: air in CT, the empty field in MR) and the
/// values on its far side are transparent; opacity rises from the end of that peak through the
/// 50th (faint), 85th and 97th (dense) percentiles of the remaining voxels, so that the large
/// classes (soft tissue) stay see-through and the rare dense ones (bone, contrast) stand out.
/// The colours run from dark red through orange to near white with the value.
/// When the background peak is the brightest class, the ramp runs the other way.
TransferFunction1D transferFunctionFromHistogram(const DataHistogram& histogram);

} // namespace volsg
