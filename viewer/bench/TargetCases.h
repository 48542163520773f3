#pragma once
// The cases of the error-target sweep in volsg-bench --suite volumes --sweep: transfer-function
// families (smooth ramp, steep step, narrow spike, several spikes, a feature in 1% of a 16-bit
// range, tagged), data (smooth, noisy, 8 and 16 bit, anisotropic spacing 1 x 1.5 x 2.5), views
// (orthographic, perspective, camera inside), sizes 32^3 to 256^3; and the two cases.

#include <string>
#include <vector>

#include "TargetSweep.h"
#include <volsg/render/FrameContext.h>

namespace volsg::bench {

struct TargetCaseSpec {
    std::string name;
    std::string text; ///< a scene with one Volume named SUITE_VOLUME
    int width = 128, height = 128;
    int frames = 4, errorFrames = 4; // every view compared: the bar is per frame
};

/// The specs; raw volumes the scenes read are written into `dataDir`. `large`: also the
/// 128^3 and 256^3 cases (the 256^3 reference at 512 x 512 takes minutes per view).
std::vector<TargetCaseSpec> targetCaseSpecs(const std::string& dataDir, bool large);

/// Loads a case: its scene, views, and reference images (rendered, or read from
/// `referenceDir` when kept there by an earlier run). Needs a current GL context.
SweepCase loadTargetCase(const TargetCaseSpec& spec, const RenderDebug& debug,
                         const std::string& referenceDir);

} // namespace volsg::bench
