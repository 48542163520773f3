#include "VolumeReport.h"

#include <cstdio>
#include <string>

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

double mebibytes(std::uint64_t bytes) {
    return double(bytes) / double(1 << 20);
}

/// A paged volume's level of detail (the error the quadrature prediction leaves out),
/// residency and I/O.
std::string describePaging(const PagingStats& p) {
    char line[480];
    std::snprintf(line, sizeof line,
                  "paged: %s, %d bricks of levels %d..%d (of %d), voxels up to %.2f px (budget "
                  "%.2f px)%s%s; host %.0f/%.0f MiB (%d bricks), textures %.0f/%.0f MiB (%d); "
                  "loading %d, queued %d; loaded %llu bricks, %.0f MiB in %.0f ms",
                  p.converged ? "converged" : "refining", p.bricksDrawn, p.finestLevel,
                  p.coarsestLevel, p.levels, p.worstVoxelPixels, p.pixelBudget,
                  p.coarserBricks > 0
                      ? (", " + std::to_string(p.coarserBricks) + " coarser than that").c_str()
                      : "",
                  p.budgetLimited ? " (texture budget)" : "", mebibytes(p.hostBytes),
                  mebibytes(p.hostBudget), p.hostBricks, mebibytes(p.textureBytes),
                  mebibytes(p.textureBudget), p.textureBricks, p.loading, p.queued,
                  static_cast<unsigned long long>(p.bricksLoaded), mebibytes(p.bytesLoaded),
                  p.loadMilliseconds);
    std::string out = line;
    if (!p.firstError.empty())
        out += "; " + std::to_string(p.loadFailures) + " bricks unreadable: " + p.firstError;
    return out;
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
        if (s.paging.paged && s.paging.lodRmse >= 0.0) {
            std::snprintf(line, sizeof line,
                          " = quadrature %.3g/255 and level of detail %.3g/255%s",
                          s.quadratureRmse * 255.0, s.paging.lodRmse * 255.0,
                          s.paging.measuredFrom == 0
                              ? ""
                              : " (the levels from the stand-in up: finer detail not seen)");
            out += line;
        }
    } else {
        out += s.paging.paged ? ", no prediction (paged without a target: 2 planes per voxel of "
                                "the finest level drawn)"
                              : ", no prediction (no target, AVERAGE or NEAREST)";
    }
    if (s.paging.paged) out += "; " + describePaging(s.paging);
    return out;
}

std::string describe(const ShearWarpVolume& v, bool predictNewViews) {
    const ShearWarpVolume::Quality q = predictNewViews ? v.lastQuality() : v.lastQualityKnown();
    char line[320];
    std::snprintf(line, sizeof line,
                  "slice step %d, predicted RMSE %.3g/255 (floor %.3g/255 at step 1; target "
                  "%.3g/255)",
                  q.sliceStep, q.predictedRmse * 255.0, q.floorRmse * 255.0, q.target * 255.0);
    std::string out = q.predicted ? std::string(line)
                      : v.predictionPending()
                          ? std::string("a new view direction: predicted when the view rests")
                          : std::string("no prediction yet");
    if (q.pagedLevel >= 0) {
        std::snprintf(line, sizeof line, "; paged: level %d read whole (the view asks for %d)%s",
                      q.pagedLevel, q.wantedLevel, q.refining ? ", a finer level loading" : "");
        out += line;
    }
    return out;
}

} // namespace

std::vector<std::string> volumeQualityLines(Node& root, bool predictNewViews) {
    std::vector<std::string> out;
    int index = 0;
    forEachVolume(root, [&](Node& n) {
        ++index;
        const std::string name = n.getName().empty() ? "" : " (" + n.getName() + ")";
        const std::string what =
            n.isA<Volume>() ? describe(static_cast<const Volume&>(n))
                            : describe(static_cast<const ShearWarpVolume&>(n), predictNewViews);
        out.push_back(std::string(n.isA<Volume>() ? "Volume" : "ShearWarpVolume") + " #" +
                      std::to_string(index) + name + ": " + what);
    });
    return out;
}

bool volumesRefining(Node& root) {
    bool refining = false;
    forEachVolume(root, [&](Node& n) {
        if (n.isA<ShearWarpVolume>()) { // a paged volume's finer level read whole
            refining = refining || static_cast<const ShearWarpVolume&>(n).lastQuality().refining;
            return;
        }
        const PagingStats& p = static_cast<const Volume&>(n).slicingStats().paging;
        refining = refining || (p.paged && !p.converged);
    });
    return refining;
}

std::vector<std::string> pagingErrors(Node& root) {
    std::vector<std::string> out;
    forEachVolume(root, [&](Node& n) {
        if (n.isA<ShearWarpVolume>()) {
            const std::string& e = static_cast<const ShearWarpVolume&>(n).lastQuality().levelError;
            if (!e.empty()) out.push_back("a level unreadable, drawn coarser: " + e);
            return;
        }
        const PagingStats& p = static_cast<const Volume&>(n).slicingStats().paging;
        if (p.paged && !p.firstError.empty())
            out.push_back(std::to_string(p.loadFailures) +
                          " bricks unreadable, drawn coarser: " + p.firstError);
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
