#pragma once
// Window/level as in 3D Slicer and DICOM viewers: the transfer function's dataRange seen as a
// window width and a level (its centre). A mouse drag changes them: horizontal = window width
// (right widens), vertical = level (up raises it), both linear in data units so that a drag
// across the whole view changes them by the data's whole span.

#include <glm/glm.hpp>

namespace volsg {

struct WindowLevel {
    double level = 0.0, width = 1.0;

    /// Of a dataRange [lo, hi] (width hi - lo, which is negative for an inverted range).
    static WindowLevel ofRange(glm::dvec2 range) {
        return {0.5 * (range.x + range.y), range.y - range.x};
    }
    glm::dvec2 range() const { return {level - 0.5 * width, level + 0.5 * width}; }

    /// After a drag of `delta` pixels (x right, y down, as window pixels) in a view of
    /// `viewPixels`, on data spanning `dataSpan` (its max - min): the width changes by
    /// dataSpan * dx / viewWidth, the level by dataSpan * -dy / viewHeight. The width's
    /// magnitude stays at least dataSpan / 1000 (and its sign); non-finite input changes
    /// nothing.
    WindowLevel dragged(glm::dvec2 delta, glm::dvec2 viewPixels, double dataSpan) const;
};

} // namespace volsg
