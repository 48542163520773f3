#include "VolumeReport.h"

#include <cstdio>

#include <volsg/nodes/ShearWarpVolume.h>
#include <volsg/nodes/Volume.h>

namespace volsg::cli {

namespace {

template <class Visit> void forEachVolume(Node& node, Visit&& visit) {
    if (node.isA<Volume>() || node.isA<ShearWarpVolume>()) visit(node);
    if (auto* children = node.children())
        for (const auto& child : *children)
            if (child) forEachVolume(*child, visit);
}

std::string describe(const Volume& v) {
    const SlicingStats& s = v.slicingStats();
    char line[320];
    std::snprintf(line, sizeof line, "%d planes x %d samples (%.3g L0 apart)%s%s", s.planes,
                  s.samplesPerPlane, s.planeSpacingL0, s.preIntegrated ? ", pre-integrated" : "",
                  s.mipPeaks ? ", peaks" : "");
    std::string out = line;
    if (s.predictedRmse >= 0.0) {
        std::snprintf(line, sizeof line,
                      ", predicted RMSE %.3g/255 (target %.3g/255%s), %.0f%% of "
                      "the image covered, choice %.1f ms",
                      s.predictedRmse * 255.0, s.errorTarget * 255.0,
                      s.meetsTarget ? "" : ", not met", s.coverage * 100.0, s.qualityMilliseconds);
        out += line;
    } else {
        out += ", no prediction (no target, AVERAGE or NEAREST)";
    }
    return out;
}

std::string describe(const ShearWarpVolume& v) {
    const ShearWarpVolume::Quality q = v.lastQuality();
    char line[320];
    std::snprintf(line, sizeof line,
                  "slice step %d, predicted RMSE %.3g/255 (floor %.3g/255 at step 1; target "
                  "%.3g/255)",
                  q.sliceStep, q.predictedRmse * 255.0, q.floorRmse * 255.0, q.target * 255.0);
    return q.predicted ? std::string(line) : std::string("no prediction yet");
}

} // namespace

std::vector<std::string> volumeQualityLines(Node& root) {
    std::vector<std::string> out;
    int index = 0;
    forEachVolume(root, [&](Node& n) {
        ++index;
        const std::string name = n.getName().empty() ? "" : " (" + n.getName() + ")";
        const std::string what = n.isA<Volume>() ? describe(static_cast<const Volume&>(n))
                                                 : describe(static_cast<const ShearWarpVolume&>(n));
        out.push_back(std::string(n.isA<Volume>() ? "Volume" : "ShearWarpVolume") + " #" +
                      std::to_string(index) + name + ": " + what);
    });
    return out;
}

std::vector<double> predictedErrors(Node& root) {
    std::vector<double> out;
    forEachVolume(root, [&](Node& n) {
        if (n.isA<Volume>())
            out.push_back(static_cast<const Volume&>(n).slicingStats().predictedRmse);
        else {
            const ShearWarpVolume::Quality q = static_cast<const ShearWarpVolume&>(n).lastQuality();
            out.push_back(q.predicted ? q.predictedRmse : -1.0);
        }
    });
    return out;
}

} // namespace volsg::cli
