#include "InteractiveQuality.h"

#include <algorithm>
#include <cmath>

namespace volsg {

double InteractiveQuality::resolutionScale() const {
    const double linear = std::sqrt(std::max(scale_, minimumPixelFraction));
    // Whole sixteenths, rounded up: the view's target is not remade for tiny changes.
    return std::min(1.0, std::ceil(linear * 16.0 - 1e-9) / 16.0);
}

double InteractiveQuality::planeScale() const {
    const double pixels = resolutionScale() * resolutionScale();
    return std::clamp(scale_ / pixels, 0.25, 1.0);
}

void InteractiveQuality::frameDone(bool interactive, double frameMs) {
    if (!interactive || !(frameMs > 0.0)) return;
    if (frameMs > budgetMs) {
        // Pixels and planes both scale a volume frame's time about linearly.
        const double cut = std::max(0.25, 0.8 * budgetMs / frameMs);
        scale_ = std::max(minimumScale, scale_ * cut);
    } else if (frameMs < 0.5 * budgetMs) {
        scale_ = std::min(1.0, scale_ * 1.25);
    }
}

} // namespace volsg
