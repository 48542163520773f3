#include <volsg/editors/ValueAxis.h>

#include <algorithm>
#include <cmath>

namespace volsg {

double niceStep(double rough) {
    if (!std::isfinite(rough) || rough <= 0.0) return 0.0;
    const double decade = std::pow(10.0, std::floor(std::log10(rough)));
    for (const double m : {1.0, 2.0, 5.0, 10.0})
        if (m * decade >= rough * (1.0 - 1e-12)) return m * decade;
    return 10.0 * decade;
}

double niceFloor(double limit) {
    if (!std::isfinite(limit) || limit <= 0.0) return 0.0;
    const double decade = std::pow(10.0, std::floor(std::log10(limit)));
    for (const double m : {5.0, 2.0, 1.0})
        if (m * decade <= limit * (1.0 + 1e-12)) return m * decade;
    return decade;
}

std::vector<double> niceTicks(double a, double b, int maxTicks) {
    std::vector<double> ticks;
    const double lo = std::min(a, b), hi = std::max(a, b);
    if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo)) return ticks;
    maxTicks = std::max(maxTicks, 2);
    // The finest nice step that may fit; a coarser one when it gives too many ticks.
    double step = niceStep((hi - lo) / double(maxTicks));
    for (int attempt = 0; attempt < 4; ++attempt) {
        ticks.clear();
        const double first = std::ceil(lo / step - 1e-9) * step;
        for (int i = 0; i <= maxTicks + 1; ++i) {
            const double t = first + double(i) * step;
            if (t > hi + 1e-9 * step) break;
            ticks.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
        }
        if (int(ticks.size()) <= maxTicks) break;
        step = niceStep(step * 1.01);
    }
    if (ticks.size() < 2) ticks = {lo, hi}; // a narrow interval between two multiples
    return ticks;
}

} // namespace volsg
