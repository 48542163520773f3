#include "TargetSweep.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>

#include "ImageError.h"
#include "PrintfFormat.h"
#include "Timing.h"
#include <volsg/core/Error.h>

namespace volsg::bench {

namespace {

/// A fixed setting of the grid: planes per L0 (over the box diagonal, so every view has at
/// least that many along the view), samples per plane, pre-integration (DVR) or peaks (MIP).
struct FixedSetting {
    double planesPerL0;
    int samples;
    bool method; ///< DVR: preIntegrated; MIP, MINIP: mipPeaks
};

bool extremeMode(const Volume& v) {
    return v.renderMode() == Volume::MIP || v.renderMode() == Volume::MINIP;
}

std::string fixedText(const FixedSetting& s, bool extreme) {
    std::string t = printfFormat("%g planes/L0 x %g", s.planesPerL0, double(s.samples));
    if (extreme)
        t += s.method ? ", peaks" : ", no peaks";
    else if (s.method)
        t += ", pre-int";
    return t;
}

std::vector<FixedSetting> gridOf(bool quick) {
    std::vector<FixedSetting> out;
    const std::vector<int> samples =
        quick ? std::vector<int>{4, 16} : std::vector<int>{1, 4, 16, 64};
    for (const bool method : {false, true})
        for (int e = quick ? 1 : 2; e >= -5; --e) { // samples per L0: 4 (quick: 2) .. 1/32
            const double sigma = std::pow(2.0, e);
            for (const int k : samples) {
                const double p = sigma / k;
                if (p > 2.0 || p < 1.0 / 256.0) continue;
                out.push_back({p, k, method});
            }
        }
    return out;
}

/// Back to the node's automatic settings (fields never set), at error target `target`.
void setAutomatic(Volume& v, double target) {
    v.numPlanes = 0;
    v.numPlanes.setDefault(true);
    v.interactivePlanes = 0;
    v.interactivePlanes.setDefault(true);
    v.samplesPerPlane = 1;
    v.samplesPerPlane.setDefault(true);
    v.preIntegrated = false;
    v.preIntegrated.setDefault(true);
    v.mipPeaks = true;
    v.mipPeaks.setDefault(true);
    v.errorTarget = float(target);
}

void setFixed(Volume& v, const FixedSetting& s, double diagonalL0, double target) {
    v.numPlanes = std::max(1, int(std::ceil(s.planesPerL0 * diagonalL0)));
    v.samplesPerPlane = s.samples;
    if (extremeMode(v)) {
        v.mipPeaks = s.method;
        v.preIntegrated = false;
    } else {
        v.preIntegrated = s.method;
        v.mipPeaks = true;
    }
    v.errorTarget = float(target); // only for the prediction: every field above is set
}

/// Times each view (the median of repeated renders of a short frame) after a warm-up pass over all
/// of them (uploads, shader builds and the error model's rays along each view direction are made
/// once, not per frame), keeps the error views' images and the model's predictions there.
struct Measured {
    double ms = 0.0, rmse = 0.0, predicted = 0.0;
    std::string chosen;
    std::vector<double> viewRmse;   ///< 1/255, per compared view
    std::vector<SweepFrame> frames; ///< per compared view: what was drawn, predicted, measured
};

/// Fills the line's counts of compared views within the target and within twice it.
void countViews(SweepLine& line, const Measured& m) {
    line.viewsCompared = int(m.viewRmse.size());
    for (const double e : m.viewRmse) {
        line.viewsWithin += e <= line.target ? 1 : 0;
        line.viewsWithinTwice += e <= 2.0 * line.target ? 1 : 0;
    }
}
/// Renders every view once (uploads, shader builds and the error model's rays are made once,
/// not per frame).
void warmUp(Renderer& renderer, SweepCase& c, RenderOptions& options) {
    for (const auto& camera : c.views.cameras) {
        options.camera = camera;
        renderer.render(*c.root, options);
    }
}

/// The median time of `render`, run again until it has taken 100 ms (at most 9 times): a
/// single 2-30 ms frame on a 2-core machine is mostly noise.
template <class Render> double repeatedMs(Render&& render) {
    Samples view;
    do {
        view.ms.push_back(timeMs(render));
    } while (view.ms.size() < 9 && std::accumulate(view.ms.begin(), view.ms.end(), 0.0) < 100.0);
    return view.median();
}

Measured measure(SweepCase& c) {
    Renderer renderer;
    RenderOptions options = c.options;
    warmUp(renderer, c, options);
    Samples samples;
    std::vector<Image> images;
    double predictedSquares = 0.0;
    std::size_t next = 0;
    Measured m;
    for (std::size_t i = 0; i < c.views.cameras.size(); ++i) {
        options.camera = c.views.cameras[i];
        Image image;
        samples.ms.push_back(repeatedMs([&] { image = renderer.render(*c.root, options); }));
        if (i == 0) m.chosen = chosenSettingText(*c.volume);
        if (next < c.views.errorIndices.size() && c.views.errorIndices[next] == int(i)) {
            const double p = std::max(c.volume->slicingStats().predictedRmse, 0.0);
            predictedSquares += p * p;
            m.frames.push_back({int(i), chosenSettingText(*c.volume), p * 255.0, 0.0});
            images.push_back(std::move(image));
            ++next;
        }
    }
    ImageError error;
    for (std::size_t i = 0; i < images.size(); ++i) {
        error.add(images[i], c.reference[i]);
        ImageError view;
        view.add(images[i], c.reference[i]);
        m.viewRmse.push_back(view.rmse() * 255.0);
        m.frames[i].measured = view.rmse() * 255.0;
    }
    m.ms = samples.median();
    m.rmse = error.rmse() * 255.0;
    m.predicted = images.empty() ? 0.0 : std::sqrt(predictedSquares / images.size()) * 255.0;
    return m;
}

/// The median over views of each view's median frame time, after a warm-up pass: measure()'s
/// timing alone, for the alternating rounds of a default and its best fixed setting.
double timeViews(SweepCase& c) {
    Renderer renderer;
    RenderOptions options = c.options;
    warmUp(renderer, c, options);
    Samples samples;
    for (const auto& camera : c.views.cameras) {
        options.camera = camera;
        samples.ms.push_back(repeatedMs([&] { renderer.render(*c.root, options); }));
    }
    return samples.median();
}

/// Rounds of the default against its best fixed setting, alternating: the two were first
/// timed minutes apart, and frames of 1-3 ms drift by more than the bar's margin over that.
constexpr int kAlternatingRounds = 5;

BenchRow rowOf(const SweepCase& c, const std::string& setting, const Measured& m,
               const std::string& series) {
    BenchRow row;
    row.scene = c.name;
    row.path = "slicing";
    row.setting = setting;
    row.ms = m.ms;
    row.frames = int(c.views.cameras.size());
    row.hasError = true;
    row.rmse = m.rmse / 255.0;
    row.psnr = m.rmse > 0.0 ? 20.0 * std::log10(255.0 / m.rmse) : 0.0;
    row.errorFrames = int(c.views.errorIndices.size());
    row.note = printfFormat("predicted %.3g/255", m.predicted);
    row.series = series;
    return row;
}

} // namespace

std::string chosenSettingText(const Volume& volume) {
    const SlicingStats& s = volume.slicingStats();
    std::string t = printfFormat("%g planes x %g (%.3g L0 apart)", double(s.planes),
                                 double(s.samplesPerPlane), s.planeSpacingL0);
    if (s.preIntegrated) t += ", pre-int";
    if (s.mipPeaks) t += ", peaks";
    if (s.predictedRmse >= 0.0)
        t += printfFormat(", predicted %.3g/255 (target %.3g)", s.predictedRmse * 255.0,
                          s.errorTarget * 255.0) +
             (s.meetsTarget ? "" : " NOT MET");
    return t;
}

std::vector<BenchRow> runTargetSweep(SweepCase& c, const SweepSettings& st,
                                     std::vector<SweepLine>& lines,
                                     std::vector<ValidationLine>& validation) {
    if (!c.volume) throw Error("sweep case " + c.name + " has no Volume");
    std::vector<BenchRow> rows;
    const bool extreme = extremeMode(*c.volume);
    setAutomatic(*c.volume, st.targets.front());
    Measured first = measure(c);
    const double depthL0 = c.diagonalL0;

    struct FixedRow {
        FixedSetting setting;
        Measured m;
    };
    std::vector<FixedRow> fixedRows;
    if (st.beforeAfter) {
        // The fixed rule the node had before error targets: errorTarget 0.
        setAutomatic(*c.volume, 0.0);
        const Measured before = measure(c);
        BenchRow row = rowOf(c, "before: errorTarget 0 (2 samples per voxel): " + before.chosen,
                             before, "before");
        printRow(row);
        rows.push_back(row);
        SweepLine line;
        line.scene = c.name;
        line.target = 0.0;
        line.defaultSetting = "before (fixed rule): " + before.chosen;
        line.defaultMs = before.ms;
        line.defaultRmse = before.rmse;
        lines.push_back(line);
    }
    for (const FixedSetting& f : st.beforeAfter ? std::vector<FixedSetting>{} : gridOf(st.quick)) {
        setFixed(*c.volume, f, depthL0, st.targets.front());
        Measured m;
        try {
            m = measure(c);
        } catch (const Error& e) {
            std::printf("%s %s: %s\n", c.name.c_str(), fixedText(f, extreme).c_str(), e.what());
            continue;
        }
        BenchRow row = rowOf(c, fixedText(f, extreme), m,
                             extreme ? (f.method ? "fixed peaks" : "fixed")
                                     : (f.method ? "fixed pre-int" : "fixed"));
        printRow(row);
        rows.push_back(row);
        validation.push_back({c.name, fixedText(f, extreme), m.predicted, m.rmse});
        fixedRows.push_back({f, m});
    }
    for (std::size_t t = 0; t < st.targets.size(); ++t) {
        const double target = st.targets[t];
        setAutomatic(*c.volume, target);
        const Measured m = t == 0 ? first : measure(c);
        BenchRow row =
            rowOf(c, printfFormat("default, errorTarget %g: ", target) + m.chosen, m, "default");
        printRow(row);
        rows.push_back(row);
        SweepLine line;
        line.scene = c.name;
        line.target = target;
        line.defaultSetting = m.chosen;
        line.defaultMs = m.ms;
        line.defaultRmse = m.rmse;
        line.defaultPredicted = m.predicted;
        countViews(line, m);
        line.frames = m.frames;
        double bestMs = std::numeric_limits<double>::infinity();
        const FixedRow* best = nullptr;
        for (const FixedRow& f : fixedRows)
            if (f.m.rmse <= target && f.m.ms < bestMs) {
                bestMs = f.m.ms;
                best = &f;
                line.bestSetting = fixedText(f.setting, extreme);
                line.bestMs = f.m.ms;
                line.bestRmse = f.m.rmse;
            }
        if (best) {
            Samples defaultRounds, bestRounds;
            for (int round = 0; round < kAlternatingRounds; ++round) {
                setAutomatic(*c.volume, target);
                defaultRounds.ms.push_back(timeViews(c));
                setFixed(*c.volume, best->setting, depthL0, target);
                bestRounds.ms.push_back(timeViews(c));
            }
            line.defaultMs = defaultRounds.median();
            line.bestMs = bestRounds.median();
        }
        lines.push_back(line);
    }
    setAutomatic(*c.volume, st.targets.front());
    return rows;
}

void printSweepTables(const std::vector<SweepLine>& lines,
                      const std::vector<ValidationLine>& validation) {
    std::printf("\nError targets: the default against the fastest fixed setting that meets the "
                "target (RMSE in 1/255, measured against the reference; ms: medians of %d "
                "rounds alternating the two)\n\n",
                kAlternatingRounds);
    std::printf("| case | target | default (chosen at view 0) | ms | RMSE | predicted | best fixed "
                "| ms | RMSE | default/best ms | meets | views within target, 2x |\n");
    std::printf(
        "| --- | ---: | --- | ---: | ---: | ---: | --- | ---: | ---: | ---: | --- | ---: |\n");
    for (const SweepLine& l : lines) {
        if (l.target <= 0.0) { // the fixed rule before error targets
            std::printf("| %s | (none) | %s | %.1f | %.3g | | | | | | | |\n", l.scene.c_str(),
                        l.defaultSetting.c_str(), l.defaultMs, l.defaultRmse);
            continue;
        }
        const bool meets = l.defaultRmse <= l.target;
        std::printf(
            "| %s | %g | %s | %.1f | %.3g | %.3g | %s | %s | %s | %s | %s | %d, %d of %d |\n",
            l.scene.c_str(), l.target, l.defaultSetting.c_str(), l.defaultMs, l.defaultRmse,
            l.defaultPredicted, l.bestSetting.empty() ? "(none meets it)" : l.bestSetting.c_str(),
            l.bestSetting.empty() ? "" : printfFormat("%.1f", l.bestMs).c_str(),
            l.bestSetting.empty() ? "" : printfFormat("%.3g", l.bestRmse).c_str(),
            l.bestSetting.empty() ? "" : printfFormat("%.2f", l.defaultMs / l.bestMs).c_str(),
            meets ? "yes" : (l.defaultRmse <= 2.0 * l.target ? "within 2x" : "NO"), l.viewsWithin,
            l.viewsWithinTwice, l.viewsCompared);
    }
    std::printf(
        "\nThe default's frames: per compared view, what the node drew and its error (1/255)"
        "\n\n| case | target | view | drawn | predicted | measured | measured / target "
        "|\n| --- | ---: | ---: | --- | ---: | ---: | ---: |\n");
    for (const SweepLine& l : lines)
        for (const SweepFrame& f : l.frames)
            std::printf("| %s | %g | %d | %s | %.3g | %.3g | %.2f |\n", l.scene.c_str(), l.target,
                        f.view, f.setting.substr(0, f.setting.find(", predicted")).c_str(),
                        f.predicted, f.measured, l.target > 0.0 ? f.measured / l.target : 0.0);
    if (validation.empty()) return;
    std::printf("\nThe error model: predicted against measured RMSE (1/255) of the fixed "
                "settings\n\n| case | setting | predicted | measured | ratio |\n| --- | --- | "
                "---: | ---: | ---: |\n");
    std::vector<double> logRatios;
    for (const ValidationLine& v : validation) {
        const double ratio = v.measured > 0.0 ? v.predicted / v.measured : 0.0;
        if (v.measured > 0.01 && v.predicted > 0.0) logRatios.push_back(std::log(ratio));
        std::printf("| %s | %s | %.3g | %.3g | %.2f |\n", v.scene.c_str(), v.setting.c_str(),
                    v.predicted, v.measured, ratio);
    }
    if (!logRatios.empty()) {
        std::sort(logRatios.begin(), logRatios.end());
        const auto at = [&](double q) {
            return std::exp(logRatios[std::size_t(q * double(logRatios.size() - 1))]);
        };
        std::printf("\npredicted/measured over %zu settings with measured RMSE > 0.01/255: "
                    "min %.2f, 10%% %.2f, median %.2f, 90%% %.2f, max %.2f\n",
                    logRatios.size(), at(0.0), at(0.1), at(0.5), at(0.9), at(1.0));
    }
}

} // namespace volsg::bench
