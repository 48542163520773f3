#include <volsg/volume/TestVolumes.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <volsg/core/Error.h>

namespace volsg {

namespace {

// The value stored for a signal in [0, 1]: the type's positive range, or the value itself.
double scaleUnit(double unit, VoxelType type) {
    switch (type) {
    case VoxelType::UByte:
        return std::nearbyint(unit * 255.0);
    case VoxelType::UShort:
        return std::nearbyint(unit * 65535.0);
    case VoxelType::Short:
        return std::nearbyint(unit * 32767.0);
    case VoxelType::Float:
        return unit;
    }
    return unit;
}

void requireSize(int n, int minimum, const char* what) {
    if (n < minimum)
        throw Error(std::string(what) + " needs at least " + std::to_string(minimum) +
                    " voxels a side, got " + std::to_string(n));
}

// Distance of voxel (i,j,k)'s centre from the grid centre, in voxel units.
double radiusInVoxels(int n, int i, int j, int k) {
    const double c = 0.5 * (n - 1);
    return std::sqrt((i - c) * (i - c) + (j - c) * (j - c) + (k - c) * (k - c));
}

} // namespace

double marschnerLobb(double x, double y, double z, double fM, double alpha) {
    using std::numbers::pi;
    const double r = std::sqrt(x * x + y * y);
    const double rhoR = std::cos(2.0 * pi * fM * std::cos(pi * r / 2.0));
    return (1.0 - std::sin(pi * z / 2.0) + alpha * (1.0 + rhoR)) / (2.0 * (1.0 + alpha));
}

ref_ptr<VolumeGrid> makeMarschnerLobb(int n, VoxelType type) {
    requireSize(n, 2, "the Marschner-Lobb volume");
    const double h = 2.0 / (n - 1);
    auto grid = VolumeGrid::create({n, n, n}, type, glm::dvec3(h));
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const double rho = marschnerLobb(-1.0 + i * h, -1.0 + j * h, -1.0 + k * h);
                grid->setValue(i, j, k, scaleUnit(std::clamp(rho, 0.0, 1.0), type));
            }
    return grid;
}

ref_ptr<VolumeGrid> makeSoftSphere(int n, VoxelType type) {
    requireSize(n, 1, "the soft sphere volume");
    auto grid = VolumeGrid::create({n, n, n}, type);
    const double radius = 0.45 * n;
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const double unit = std::max(0.0, 1.0 - radiusInVoxels(n, i, j, k) / radius);
                grid->setValue(i, j, k, scaleUnit(unit, type));
            }
    return grid;
}

ref_ptr<VolumeGrid> makeThinShell(int n, double radius, double thickness) {
    requireSize(n, 1, "the thin shell volume");
    if (!(thickness > 0.0) || !(radius >= 0.0))
        throw Error("the thin shell volume needs a radius >= 0 and a thickness > 0");
    auto grid = VolumeGrid::create({n, n, n}, VoxelType::UByte);
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                if (std::abs(radiusInVoxels(n, i, j, k) - radius) <= 0.5 * thickness)
                    grid->setValue(i, j, k, 255.0);
    return grid;
}

ref_ptr<VolumeGrid> makeFullRange16(int n) {
    requireSize(n, 2, "the 16-bit full-range volume");
    const double sigma = 0.25 * n;
    std::vector<double> g(std::size_t(n) * n * n);
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    std::size_t at = 0;
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i, ++at) {
                const double r = radiusInVoxels(n, i, j, k);
                g[at] = std::exp(-r * r / (2.0 * sigma * sigma));
                lo = std::min(lo, g[at]);
                hi = std::max(hi, g[at]);
            }
    auto grid = VolumeGrid::create({n, n, n}, VoxelType::UShort);
    auto data = grid->data<std::uint16_t>();
    for (std::size_t v = 0; v < g.size(); ++v)
        data[v] = std::uint16_t(std::nearbyint((g[v] - lo) / (hi - lo) * 65535.0));
    return grid;
}

LabelledVolume makeLabelledVolume(int n) {
    requireSize(n, 1, "the labelled volume");
    LabelledVolume out{makeSoftSphere(n, VoxelType::UByte),
                       VolumeGrid::create({n, n, n}, VoxelType::UByte)};
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const double r = radiusInVoxels(n, i, j, k);
                int tag = 0;
                if (r < 0.25 * n)
                    tag = 1;
                else if (r < 0.4 * n)
                    tag = 2;
                else if (k < n / 4)
                    tag = 3;
                out.tags->setValue(i, j, k, tag);
            }
    return out;
}

ref_ptr<VolumeGrid> makeConstant(glm::ivec3 dimensions, VoxelType type, double value,
                                 glm::dvec3 spacing) {
    auto grid = VolumeGrid::create(dimensions, type, spacing);
    for (std::size_t v = 0; v < grid->voxelCount(); ++v)
        grid->setValue(v, value);
    return grid;
}

ref_ptr<VolumeGrid> makeRamp(glm::ivec3 dimensions, VoxelType type, int axis, double first,
                             double last, glm::dvec3 spacing) {
    if (axis < 0 || axis > 2) throw Error("the ramp volume's axis must be 0, 1 or 2");
    auto grid = VolumeGrid::create(dimensions, type, spacing);
    const int n = dimensions[axis];
    for (int k = 0; k < dimensions.z; ++k)
        for (int j = 0; j < dimensions.y; ++j)
            for (int i = 0; i < dimensions.x; ++i) {
                const int along = glm::ivec3(i, j, k)[axis];
                const double f = n > 1 ? double(along) / double(n - 1) : 0.0;
                grid->setValue(i, j, k, first + (last - first) * f);
            }
    return grid;
}

} // namespace volsg
