#pragma once
// Round numbers for an axis or a scale bar: ticks at multiples of 1, 2 or 5 x 10^k.

#include <vector>

namespace volsg {

/// The smallest step of 1, 2 or 5 x 10^k that is at least `rough` (> 0); 0 for non-finite or
/// non-positive input.
double niceStep(double rough);

/// The largest number 1, 2 or 5 x 10^k not above `limit` (> 0); 0 for non-finite or
/// non-positive input. (A scale bar's length.)
double niceFloor(double limit);

/// Ticks at multiples of one nice step inside [min(a, b), max(a, b)], at most `maxTicks`
/// (>= 2) of them and at least two where the interval is not empty; empty for a non-finite or
/// empty interval.
std::vector<double> niceTicks(double a, double b, int maxTicks);

} // namespace volsg
