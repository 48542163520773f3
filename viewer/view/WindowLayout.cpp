#include "WindowLayout.h"

#include <algorithm>

namespace volsg {

int panelColumnWidth(int windowWidth) {
    const int wanted = std::clamp(int(0.3 * windowWidth), 260, 420);
    const int leave = std::max(1, std::min(200, windowWidth / 2)); // the views keep this much
    return std::max(0, std::min(wanted, windowWidth - leave));
}

WindowLayout layoutWindow(glm::ivec2 size, bool panels, ViewLayout layout) {
    size = glm::max(size, glm::ivec2(1));
    WindowLayout out;
    const int column = panels ? panelColumnWidth(size.x) : 0;
    if (column > 0) out.panels = {size.x - column, 0, column, size.y};
    const PixelRect area{0, 0, std::max(size.x - column, 1), size.y};
    if (layout == ViewLayout::Single) {
        out.views[0] = area;
        return out;
    }
    out.viewCount = 4;
    const int left = std::max(area.width / 2, 1), top = std::max(area.height / 2, 1);
    const int right = std::max(area.width - left, 1), bottom = std::max(area.height - top, 1);
    // Index 1 + SectionViews::Section: 1 sagittal, 2 coronal, 3 axial.
    out.views[0] = {0, 0, left, top};
    out.views[3] = {left, 0, right, top};
    out.views[2] = {0, top, left, bottom};
    out.views[1] = {left, top, right, bottom};
    return out;
}

} // namespace volsg
