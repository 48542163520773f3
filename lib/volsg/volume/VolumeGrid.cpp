#include <volsg/volume/VolumeGrid.h>

#include <cstdio>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>

#include <volsg/core/Error.h>
#include <volsg/core/Limits.h>

namespace volsg {

const char* voxelTypeName(VoxelType type) {
    switch (type) {
    case VoxelType::UByte:
        return "UBYTE";
    case VoxelType::UShort:
        return "USHORT";
    case VoxelType::Short:
        return "SHORT";
    case VoxelType::Float:
        return "FLOAT";
    }
    return "?";
}

std::size_t voxelTypeSize(VoxelType type) {
    switch (type) {
    case VoxelType::UByte:
        return 1;
    case VoxelType::UShort:
        return 2;
    case VoxelType::Short:
        return 2;
    case VoxelType::Float:
        return 4;
    }
    return 0;
}

namespace {

std::string shortNumber(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

void checkSpacing(const glm::dvec3& s) {
    // Bounded, not only positive: the GL paths work in single precision, where a box of
    // 1e18-unit voxels (or 1e-18) loses every digit and shows nothing while the reference in
    // double precision would show it. Every path refuses such a volume alike.
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(s[a]) || !(s[a] >= limits::minVolumeSpacing) ||
            !(s[a] <= limits::maxVolumeSpacing))
            throw Error("volume spacing must be in [" + shortNumber(limits::minVolumeSpacing) +
                        ", " + shortNumber(limits::maxVolumeSpacing) + "], got " +
                        shortNumber(s.x) + " " + shortNumber(s.y) + " " + shortNumber(s.z));
}

std::string dimensionsText(glm::ivec3 d) {
    return std::to_string(d.x) + " x " + std::to_string(d.y) + " x " + std::to_string(d.z);
}

// Round to nearest and saturate: what a file writer would store for `v`.
template <class T> T saturate(double v) {
    if (std::isnan(v)) throw Error("NaN cannot be stored in an integer voxel");
    const double lo = double(std::numeric_limits<T>::min());
    const double hi = double(std::numeric_limits<T>::max());
    return T(std::clamp(std::nearbyint(v), lo, hi));
}

} // namespace

std::uint64_t VolumeGrid::checkedByteSize(glm::ivec3 d, VoxelType type, std::uint64_t byteLimit) {
    if (d.x < 1 || d.y < 1 || d.z < 1)
        throw Error("volume dimensions must be >= 1 each, got " + dimensionsText(d));
    if (d.x > limits::maxVolumeDimension || d.y > limits::maxVolumeDimension ||
        d.z > limits::maxVolumeDimension)
        throw Error("volume dimensions " + dimensionsText(d) + " exceed the limit of " +
                    std::to_string(limits::maxVolumeDimension) + " voxels per axis");
    // Multiply step by step, checking each product against the limit, so nothing overflows.
    const std::uint64_t size = voxelTypeSize(type);
    std::uint64_t bytes = size;
    for (int a = 0; a < 3; ++a) {
        const std::uint64_t n = std::uint64_t(d[a]);
        if (bytes > byteLimit / n)
            throw Error("volume of " + dimensionsText(d) + " " + voxelTypeName(type) +
                        " voxels exceeds the allocation limit of " + std::to_string(byteLimit) +
                        " bytes");
        bytes *= n;
    }
    if (bytes > std::uint64_t(std::numeric_limits<std::size_t>::max()))
        throw Error("volume of " + dimensionsText(d) + " does not fit in memory addresses");
    // Whatever the caller allows, more than the machine has could only end in the OOM killer.
    const std::uint64_t memory = limits::physicalMemoryBytes();
    if (memory != 0 && bytes > memory)
        throw Error("volume of " + dimensionsText(d) + " " + voxelTypeName(type) +
                    " voxels needs " + std::to_string(bytes) +
                    " bytes, more than this machine's memory (" + std::to_string(memory) +
                    " bytes)");
    return bytes;
}

ref_ptr<VolumeGrid> VolumeGrid::create(glm::ivec3 dimensions, VoxelType type, glm::dvec3 spacing,
                                       std::uint64_t byteLimit) {
    checkSpacing(spacing);
    const std::uint64_t bytes = checkedByteSize(dimensions, type, byteLimit);
    return ref_ptr<VolumeGrid>(
        new VolumeGrid(dimensions, type, spacing, std::size_t(bytes / voxelTypeSize(type))));
}

VolumeGrid::VolumeGrid(glm::ivec3 dimensions, VoxelType type, glm::dvec3 spacing, std::size_t count)
    : type_(type), dimensions_(dimensions), spacing_(spacing), voxelCount_(count) {
    switch (type) {
    case VoxelType::UByte:
        storage_ = std::vector<std::uint8_t>(count);
        break;
    case VoxelType::UShort:
        storage_ = std::vector<std::uint16_t>(count);
        break;
    case VoxelType::Short:
        storage_ = std::vector<std::int16_t>(count);
        break;
    case VoxelType::Float:
        storage_ = std::vector<float>(count);
        break;
    }
}

void VolumeGrid::setSpacing(glm::dvec3 spacing) {
    checkSpacing(spacing);
    spacing_ = spacing;
}

double VolumeGrid::smallestSpacing() const {
    return std::min({spacing_.x, spacing_.y, spacing_.z});
}

glm::dvec3 VolumeGrid::voxelCenter(int i, int j, int k) const {
    return -0.5 * extent() + (glm::dvec3(i, j, k) + 0.5) * spacing_;
}

double VolumeGrid::value(std::size_t index) const {
    return std::visit([index](const auto& v) { return double(v[index]); }, storage_);
}

void VolumeGrid::setValue(std::size_t index, double v) {
    rangeKnown_.store(false, std::memory_order_relaxed);
    std::visit(
        [index, v](auto& data) {
            using T = typename std::decay_t<decltype(data)>::value_type;
            if constexpr (std::is_same_v<T, float>)
                data[index] = float(v);
            else
                data[index] = saturate<T>(v);
        },
        storage_);
}

std::span<std::byte> VolumeGrid::bytes() {
    rangeKnown_.store(false, std::memory_order_release); // the caller may write
    return std::visit([](auto& v) { return std::as_writable_bytes(std::span(v.data(), v.size())); },
                      storage_);
}

std::span<const std::byte> VolumeGrid::bytes() const {
    return std::visit([](const auto& v) { return std::as_bytes(std::span(v.data(), v.size())); },
                      storage_);
}

void VolumeGrid::throwTypeMismatch() const {
    throw Error(std::string("volume data accessed with the wrong element type (the grid holds ") +
                voxelTypeName(type_) + ")");
}

std::pair<double, double> VolumeGrid::minMax() const {
    if (rangeKnown_.load(std::memory_order_acquire)) return range_;
    std::lock_guard<std::mutex> lock(rangeMutex_);
    if (!rangeKnown_.load(std::memory_order_acquire)) {
        range_ = computeMinMax();
        rangeKnown_.store(true, std::memory_order_release);
    }
    return range_;
}

std::pair<double, double> VolumeGrid::computeMinMax() const {
    return std::visit(
        [](const auto& data) {
            using T = std::decay_t<decltype(data[0])>;
            if constexpr (std::is_integral_v<T>) { // all finite: compared in their own type
                if (data.empty()) return std::pair(0.0, 0.0);
                T a = data[0], b = data[0];
                for (const T x : data) {
                    a = x < a ? x : a;
                    b = x > b ? x : b;
                }
                return std::pair(double(a), double(b));
            }
            double lo = std::numeric_limits<double>::infinity();
            double hi = -lo;
            for (const auto x : data) {
                const double d = double(x);
                if (!std::isfinite(d)) continue;
                lo = std::min(lo, d);
                hi = std::max(hi, d);
            }
            return lo <= hi ? std::pair(lo, hi) : std::pair(0.0, 0.0);
        },
        storage_);
}

std::pair<double, double> VolumeGrid::naturalRange() const {
    switch (type_) {
    case VoxelType::UByte:
        return {0.0, 255.0};
    case VoxelType::UShort:
    case VoxelType::Short: {
        // 16-bit data rarely spans its type: 12-bit CT in SHORT uses a sliver of -32768..32767.
        const auto range = minMax();
        if (range.first < range.second) return range;
        return type_ == VoxelType::UShort ? std::pair(0.0, 65535.0) : std::pair(-32768.0, 32767.0);
    }
    case VoxelType::Float:
        return minMax();
    }
    return {0.0, 0.0};
}

} // namespace volsg
