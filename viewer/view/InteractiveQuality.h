#pragma once
// The viewer's frame-rate rule: while the user interacts, a frame slower than the budget
// (100 ms) lowers the volumes' interactive plane count further (RenderOptions::
// interactivePlaneScale); fast frames win it back slowly. Full quality returns as soon as the
// interaction stops, because a still frame is not interactive at all.

namespace volsg {

class InteractiveQuality {
public:
    static constexpr double budgetMs = 100.0;
    static constexpr double minimumScale = 1.0 / 32.0;

    /// The plane-count factor for the next interactive frame, in [minimumScale, 1].
    double scale() const { return scale_; }
    /// Reports a finished frame. Interactive frames over the budget cut the scale in proportion
    /// (aiming at 80% of the budget, at most a quarter per frame); those under half the budget
    /// raise it by a quarter. Still frames leave it alone, so the next interaction starts at
    /// the scale the last one needed.
    void frameDone(bool interactive, double frameMs);

private:
    double scale_ = 1.0;
};

} // namespace volsg
