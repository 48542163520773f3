#pragma once
// The family of volumes volsg-volpack-bench renders with VolPack and the ShearWarpVolume: each
// case a volsg scene (one Volume, its transfer function, an orthographic camera) and, for the
// node, the transfer function it reads in SHADED mode. Generated volumes are written as raw
// 8-bit files next to the scenes.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace volsg::volpackbench {

/// A user's raw 8-bit volume (`--raw FILE --dims X Y Z [--spacing ...] [--tf LO HI ALPHA]`):
/// grey colour and alpha ramps from 0 at data value LO to 1 and ALPHA at HI.
struct RawInput {
    std::filesystem::path file;
    glm::ivec3 dimensions{0};
    glm::dvec3 spacing{1.0};
    double tfLow = 40.0, tfHigh = 255.0, tfAlpha = 0.6;
};

struct Case {
    std::string name;
    std::string description;
    std::string sceneText; ///< the Volume scene VolPack's classification comes from
    bool shaded = false;
    /// The ShearWarpVolume's transfer function when it differs from the scene's (shaded: the
    /// colour ramp over the shading intensity that gives VolPack's material colour).
    std::string shearWarpTransferFunction;
};

/// Where the cases' inputs are: `out` gets the generated volumes (and the scenes), `data` is
/// examples/data (the CT volumes), `side` the generated volumes' size.
struct CaseInputs {
    std::filesystem::path out;
    std::filesystem::path data;
    int side = 256;
    std::optional<RawInput> raw;
};

/// Every case name, in the order `all` runs them.
std::vector<std::string> caseNames(const CaseInputs& inputs);
/// The case `name`, writing the volume it reads when it is generated (or converted, the head
/// CT to 8 bits). Throws Error for an unknown name.
Case makeCase(const std::string& name, const CaseInputs& inputs);

} // namespace volsg::volpackbench
