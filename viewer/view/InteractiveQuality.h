#pragma once
// The viewer's frame-rate rule: while the user interacts, a frame slower than the budget
// (100 ms) lowers the cost of the next interactive frame; fast frames win it back slowly. The
// cost goes first into the 3D view's resolution (down to a quarter of its width and height,
// drawn into a smaller target and scaled up), and only then into the volumes' interactive
// plane count: a coarser image keeps the still frame's look (the same transfer function and
// brightness, blurred), while far fewer planes show slicing bands. Full quality returns as
// soon as the interaction stops, because a still frame is not interactive at all.

namespace volsg {

class InteractiveQuality {
public:
    static constexpr double budgetMs = 100.0;
    /// The smallest cost: 1/16 of the pixels (a quarter of the width and height) times a
    /// quarter of the interactive planes.
    static constexpr double minimumScale = 1.0 / 64.0;
    static constexpr double minimumPixelFraction = 1.0 / 16.0;

    /// The cost factor for the next interactive frame, in [minimumScale, 1]: the product of
    /// the pixel fraction and the plane scale.
    double scale() const { return scale_; }
    /// The 3D view's width and height factor (in [1/4, 1], a multiple of 1/16): the square root
    /// of the pixel fraction, which takes the cost down to minimumPixelFraction first.
    double resolutionScale() const;
    /// The factor on the volumes' interactive plane count (RenderOptions::
    /// interactivePlaneScale): what the resolution could not take, in [1/4, 1].
    double planeScale() const;
    /// Reports a finished frame. Interactive frames over the budget cut the scale in proportion
    /// (aiming at 80% of the budget, at most a quarter per frame); those under half the budget
    /// raise it by a quarter. Still frames leave it alone, so the next interaction starts at
    /// the scale the last one needed.
    void frameDone(bool interactive, double frameMs);

private:
    double scale_ = 1.0;
};

} // namespace volsg
