#pragma once
// Transfer-function presets: generic ramps (in the normalised value v) and CT and MR presets
// defined in data units: Hounsfield units for CT, fractions of the data's actual range for MR
// (MR intensities have no absolute scale). A preset's points are mapped into v through the
// transfer function's dataRange when it is applied, so a CT bone preset lands on bone whatever
// the range is, and clipped to v in [0, 1] by interpolating the curve at the ends.

#include <array>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace volsg {

struct TransferFunctionPreset {
    enum class Units {
        V,            ///< x is the normalised value v itself
        Hounsfield,   ///< x is a data value in Hounsfield units (CT stored in HU)
        DataFraction, ///< x is a fraction of the data's actual range [min, max] (MR)
    };
    std::string name;
    std::string modality; ///< "", "CT" or "MR"
    Units units = Units::V;
    /// Red, green, blue, alpha: (x, output) points in x order, x in `units`.
    std::array<std::vector<glm::vec2>, 4> channels;
};

/// Every preset: the generic ones first, then CT (bone, soft tissue, lung, angiography) and MR
/// (T1 brain).
const std::vector<TransferFunctionPreset>& transferFunctionPresets();

/// Which channels applying a preset replaces: its colour (red, green, blue), its opacity
/// (alpha), or both.
enum class PresetApply { Colour, Opacity, Both };
const char* presetApplyName(PresetApply apply);

/// The data value of a preset x: x + hounsfieldZero (Hounsfield; hounsfieldZero is the data
/// value of 0 HU: 0 for data in HU, 1024 for CT stored unsigned with DICOM's usual rescale
/// intercept of -1024), min + x (max - min) (DataFraction); for Units::V the value at v = x
/// under `functionRange`.
double presetDataValue(const TransferFunctionPreset& preset, float x, glm::dvec2 functionRange,
                       glm::dvec2 dataMinMax, double hounsfieldZero = 0.0);

/// Channel `channel` (0 red .. 3 alpha) of `preset` as (v, output) points for a transfer
/// function whose dataRange is `functionRange` on data whose actual range is `dataMinMax`:
/// v = (value - lo) / (hi - lo), the curve cut at v = 0 and v = 1 (points outside dropped, the
/// ends interpolated; a curve wholly outside becomes its constant value there).
std::vector<glm::vec2> presetChannelInV(const TransferFunctionPreset& preset, int channel,
                                        glm::dvec2 functionRange, glm::dvec2 dataMinMax,
                                        double hounsfieldZero = 0.0);

} // namespace volsg
