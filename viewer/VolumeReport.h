#pragma once
// One line per volume node of a scene after a render: the quality settings it drew with and the
// error it predicts against the rendering model (volsg-render --verbose, volsg-bench).

#include <string>
#include <vector>

#include <volsg/core/Node.h>

namespace volsg::cli {

/// "Volume #1 (name): 12 planes x 16 samples (2.1 L0 apart), predicted 0.31/255 (target 0.5)"
/// for every Volume and ShearWarpVolume under `root`, in traversal order.
/// `predictNewViews` false: a ShearWarpVolume whose view direction is new to its error model
/// reports no prediction rather than casting the model's rays now (ShearWarpVolume::lastQuality;
/// the viewer while the user drags).
std::vector<std::string> volumeQualityLines(Node& root, bool predictNewViews = true);

/// Whether a paged Volume's last frame still waited for bricks (PagingStats::converged false):
/// the next frame will show more.
bool volumesRefining(Node& root);

/// The first brick read error of each paged Volume that had one (its bricks stay coarse).
std::vector<std::string> pagingErrors(Node& root);

/// The predicted RMSE (0..1 units) of every Volume and ShearWarpVolume under `root` that
/// predicts one, in the same order as volumeQualityLines (-1 where none is predicted).
std::vector<double> predictedErrors(Node& root);

} // namespace volsg::cli
