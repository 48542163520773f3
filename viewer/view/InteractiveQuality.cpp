#include "InteractiveQuality.h"

#include <algorithm>

namespace volsg {

void InteractiveQuality::frameDone(bool interactive, double frameMs) {
    if (!interactive || !(frameMs > 0.0)) return;
    if (frameMs > budgetMs) {
        // Plane work dominates a slow volume frame, so time scales about with the plane count.
        const double cut = std::max(0.25, 0.8 * budgetMs / frameMs);
        scale_ = std::max(minimumScale, scale_ * cut);
    } else if (frameMs < 0.5 * budgetMs) {
        scale_ = std::min(1.0, scale_ * 1.25);
    }
}

} // namespace volsg
