#pragma once
// How far a rendered image is from the reference: RMSE, PSNR and the largest difference.

#include <cstddef>

#include <volsg/image/Image.h>

namespace volsg::bench {

/// Accumulates the per-channel differences (red, green, blue; alpha is left out: paths store
/// different things there) of image/reference pairs, so several views give one figure.
class ImageError {
public:
    /// Adds one pair. Throws Error when the sizes differ.
    void add(const Image& image, const Image& reference);

    std::size_t samples() const { return count_; }
    /// Root of the mean squared difference over every channel of every pixel added.
    double rmse() const;
    /// 20 log10(1 / rmse): the peak signal is 1 (linear values); +infinity for rmse 0.
    double psnr() const;
    /// The largest absolute difference of any channel.
    double maxAbs() const { return maxAbs_; }

private:
    double sumSquares_ = 0.0;
    std::size_t count_ = 0;
    double maxAbs_ = 0.0;
};

} // namespace volsg::bench
