#include <volsg/editors/TransferFunctionPresets.h>

#include <algorithm>
#include <cmath>

namespace volsg {

namespace {

using P = std::vector<glm::vec2>;
using Units = TransferFunctionPreset::Units;

TransferFunctionPreset generic(const char* name, P r, P g, P b, P a) {
    return {name, "", Units::V, {std::move(r), std::move(g), std::move(b), std::move(a)}};
}

std::vector<TransferFunctionPreset> makePresets() {
    const P ramp{{0, 0}, {1, 1}};
    std::vector<TransferFunctionPreset> out;
    out.push_back(generic("grey ramp", ramp, ramp, ramp, ramp));
    out.push_back(generic("hot metal", {{0, 0}, {0.4f, 1}, {1, 1}},
                          {{0, 0}, {0.3f, 0}, {0.8f, 1}, {1, 1}}, {{0, 0}, {0.6f, 0}, {1, 1}},
                          ramp));
    out.push_back(generic("cool to warm", {{0, 0.23f}, {0.5f, 0.87f}, {1, 0.71f}},
                          {{0, 0.3f}, {0.5f, 0.86f}, {1, 0.02f}},
                          {{0, 0.75f}, {0.5f, 0.86f}, {1, 0.15f}}, ramp));
    out.push_back(generic("alpha tent", ramp, ramp, ramp,
                          {{0, 0}, {0.3f, 0}, {0.5f, 0.8f}, {0.7f, 0}, {1, 0}}));
    out.push_back(
        generic("alpha step", ramp, ramp, ramp, {{0, 0}, {0.49f, 0}, {0.51f, 1}, {1, 1}}));

    // CT in Hounsfield units: air -1000, lung -900 to -500, fat -100, water 0, soft tissue and
    // blood 20 to 80, contrast-filled vessels 150 to 500, bone 300 to 2000.
    out.push_back({"CT bone",
                   "CT",
                   Units::Hounsfield,
                   {P{{-1024, 0}, {150, 0.55f}, {400, 0.9f}, {1200, 1}},
                    P{{-1024, 0}, {150, 0.35f}, {400, 0.82f}, {1200, 1}},
                    P{{-1024, 0}, {150, 0.25f}, {400, 0.62f}, {1200, 0.95f}},
                    P{{-1024, 0}, {150, 0}, {300, 0.35f}, {700, 0.8f}, {3071, 0.85f}}}});
    out.push_back({"CT soft tissue",
                   "CT",
                   Units::Hounsfield,
                   {P{{-1024, 0}, {-120, 0.85f}, {20, 0.75f}, {80, 0.9f}, {300, 1}},
                    P{{-1024, 0}, {-120, 0.7f}, {20, 0.3f}, {80, 0.45f}, {300, 0.95f}},
                    P{{-1024, 0}, {-120, 0.45f}, {20, 0.25f}, {80, 0.35f}, {300, 0.9f}},
                    P{{-1024, 0},
                      {-300, 0},
                      {-120, 0.04f},
                      {0, 0.02f},
                      {40, 0.2f},
                      {120, 0.35f},
                      {400, 0.6f},
                      {3071, 0.7f}}}});
    out.push_back({"CT lung",
                   "CT",
                   Units::Hounsfield,
                   {P{{-1024, 0.3f}, {-700, 0.85f}, {-300, 1}, {200, 1}},
                    P{{-1024, 0.3f}, {-700, 0.55f}, {-300, 0.75f}, {200, 0.9f}},
                    P{{-1024, 0.45f}, {-700, 0.55f}, {-300, 0.7f}, {200, 0.85f}},
                    P{{-1024, 0},
                      {-950, 0},
                      {-800, 0.06f},
                      {-600, 0.1f},
                      {-400, 0},
                      {-100, 0},
                      {0, 0.02f},
                      {3071, 0.02f}}}});
    out.push_back({"CT angiography (MIP)",
                   "CT",
                   Units::Hounsfield,
                   {P{{-1024, 0}, {150, 0.7f}, {300, 0.95f}, {700, 1}},
                    P{{-1024, 0}, {150, 0.05f}, {300, 0.25f}, {700, 1}},
                    P{{-1024, 0}, {150, 0.05f}, {300, 0.2f}, {700, 1}},
                    P{{-1024, 0}, {120, 0}, {200, 0.45f}, {500, 0.85f}, {3071, 0.9f}}}});
    // MR T1 (brain): CSF dark, grey matter below white matter, fat and contrast brightest.
    out.push_back(
        {"MR T1 brain",
         "MR",
         Units::DataFraction,
         {P{{0, 0}, {0.2f, 0.45f}, {0.45f, 0.85f}, {0.7f, 1}, {1, 1}},
          P{{0, 0}, {0.2f, 0.3f}, {0.45f, 0.7f}, {0.7f, 0.95f}, {1, 1}},
          P{{0, 0}, {0.2f, 0.25f}, {0.45f, 0.6f}, {0.7f, 0.9f}, {1, 1}},
          P{{0, 0}, {0.12f, 0}, {0.25f, 0.08f}, {0.45f, 0.3f}, {0.7f, 0.55f}, {1, 0.6f}}}});
    return out;
}

} // namespace

const std::vector<TransferFunctionPreset>& transferFunctionPresets() {
    static const std::vector<TransferFunctionPreset> presets = makePresets();
    return presets;
}

const char* presetApplyName(PresetApply apply) {
    switch (apply) {
    case PresetApply::Colour:
        return "colour";
    case PresetApply::Opacity:
        return "opacity";
    case PresetApply::Both:
        return "both";
    }
    return "?";
}

double presetDataValue(const TransferFunctionPreset& preset, float x, glm::dvec2 functionRange,
                       glm::dvec2 dataMinMax, double hounsfieldZero) {
    switch (preset.units) {
    case Units::Hounsfield:
        return double(x) + (std::isfinite(hounsfieldZero) ? hounsfieldZero : 0.0);
    case Units::DataFraction:
        return dataMinMax.x + double(x) * (dataMinMax.y - dataMinMax.x);
    case Units::V:
        break;
    }
    return functionRange.x + double(x) * (functionRange.y - functionRange.x);
}

std::vector<glm::vec2> presetChannelInV(const TransferFunctionPreset& preset, int channel,
                                        glm::dvec2 functionRange, glm::dvec2 dataMinMax,
                                        double hounsfieldZero) {
    const std::vector<glm::vec2>& points = preset.channels[std::size_t(std::clamp(channel, 0, 3))];
    if (preset.units == Units::V || points.empty()) return points;
    const double span = functionRange.y - functionRange.x;
    std::vector<glm::dvec2> inV;
    for (const glm::vec2& p : points) {
        const double value =
            presetDataValue(preset, p.x, functionRange, dataMinMax, hounsfieldZero);
        inV.emplace_back(span != 0.0 ? (value - functionRange.x) / span : 0.0, double(p.y));
    }
    if (span < 0.0) std::reverse(inV.begin(), inV.end()); // an inverted range
    // The curve (constant beyond its ends) at v.
    auto at = [&](double v) {
        if (v <= inV.front().x) return inV.front().y;
        if (v >= inV.back().x) return inV.back().y;
        for (std::size_t i = 1; i < inV.size(); ++i)
            if (v <= inV[i].x) {
                const double t = (v - inV[i - 1].x) / std::max(inV[i].x - inV[i - 1].x, 1e-300);
                return inV[i - 1].y + t * (inV[i].y - inV[i - 1].y);
            }
        return inV.back().y;
    };
    std::vector<glm::vec2> out;
    out.emplace_back(0.0f, float(at(0.0)));
    for (const glm::dvec2& p : inV)
        if (p.x > 0.0 && p.x < 1.0) out.emplace_back(float(p.x), float(p.y));
    out.emplace_back(1.0f, float(at(1.0)));
    return out;
}

} // namespace volsg
