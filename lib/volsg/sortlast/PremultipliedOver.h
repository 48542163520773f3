#pragma once
// The "over" operator on premultiplied RGBA float pixels: how sort-last partial images combine.

#include <cstddef>

namespace volsg {

/// back = front over back, pixel by pixel, for `pixels` RGBA pixels of premultiplied float
/// colour: back = front + (1 - front.alpha) back, exactly the blend (ONE, ONE_MINUS_SRC_ALPHA)
/// the slicer uses within one image. Associative, not commutative: partial images combine in
/// visibility order, in any grouping.
void compositeOver(const float* front, float* back, std::size_t pixels);

} // namespace volsg
