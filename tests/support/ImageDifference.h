#pragma once
// The largest difference between two images of one size, for tests that compare renders.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <volsg/image/Image.h>

namespace volsg::test {

/// The largest difference of any channel (RGBA) of any pixel.
inline float maxDifference(const Image& a, const Image& b) {
    REQUIRE(a.pixels.size() == b.pixels.size());
    float most = 0.0f;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 4; ++c)
            most = std::max(most, std::abs(a.pixels[i][c] - b.pixels[i][c]));
    return most;
}

} // namespace volsg::test
