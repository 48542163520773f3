#include "ImageError.h"

#include <cmath>
#include <limits>
#include <string>

#include <volsg/core/Error.h>

namespace volsg::bench {

void ImageError::add(const Image& image, const Image& reference) {
    if (image.width != reference.width || image.height != reference.height)
        throw Error("cannot compare a " + std::to_string(image.width) + "x" +
                    std::to_string(image.height) + " image with a " +
                    std::to_string(reference.width) + "x" + std::to_string(reference.height) +
                    " reference");
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double d = double(image.pixels[i][c]) - double(reference.pixels[i][c]);
            sumSquares_ += d * d;
            // A NaN pixel counts as the worst possible difference, never as none.
            maxAbs_ = std::isnan(d) ? std::numeric_limits<double>::infinity()
                                    : std::max(maxAbs_, std::abs(d));
        }
    count_ += image.pixels.size() * 3;
}

double ImageError::rmse() const {
    return count_ ? std::sqrt(sumSquares_ / double(count_)) : 0.0;
}

double ImageError::psnr() const {
    const double e = rmse();
    return e > 0.0 ? -20.0 * std::log10(e) : std::numeric_limits<double>::infinity();
}

} // namespace volsg::bench
