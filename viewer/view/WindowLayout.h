#pragma once
// Where the viewer's parts go in its window: the editor panels dock in one column at the right
// edge, and the views (the 3D view alone, or the four-view layout) share the rest. Nothing
// overlaps, so a click always lands on what is drawn under the mouse.

#include <array>

#include <glm/glm.hpp>

#include "ViewModes.h"

namespace volsg {

/// A rectangle of window pixels, origin top-left; empty when width or height is 0.
struct PixelRect {
    int x = 0, y = 0, width = 0, height = 0;
    bool empty() const { return width <= 0 || height <= 0; }
    bool contains(const glm::dvec2& p) const {
        return !empty() && p.x >= x && p.y >= y && p.x < x + width && p.y < y + height;
    }
    bool overlaps(const PixelRect& o) const {
        return !empty() && !o.empty() && x < o.x + o.width && o.x < x + width &&
               y < o.y + o.height && o.y < y + height;
    }
    bool operator==(const PixelRect&) const = default;
};

struct WindowLayout {
    PixelRect panels; ///< the panel column (empty when the panels are hidden)
    /// Views: 0 the 3D view, then 1 + SectionViews::Section (sagittal, coronal, axial).
    std::array<PixelRect, 4> views{};
    int viewCount = 1; ///< 1, or 4 in the four-view layout
};

/// The panel column's width in a window `windowWidth` wide: about 30% (260 to 420 pixels),
/// always leaving the views at least 200 pixels (or half of a very narrow window).
int panelColumnWidth(int windowWidth);

/// The layout of a window of `size` pixels. In the four-view layout the view area is split
/// 2x2: 3D top left, axial top right, coronal bottom left, sagittal bottom right; odd pixels go
/// to the right and bottom views, so the views tile the area exactly.
WindowLayout layoutWindow(glm::ivec2 size, bool panels, ViewLayout layout);

} // namespace volsg
