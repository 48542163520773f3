#pragma once
// A typed 3D scalar grid: the voxels of one volume (or of its label volume) in memory.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <span>
#include <utility>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/core/Limits.h>
#include <volsg/core/Object.h>
#include <volsg/volume/VolumeGeometry.h>

namespace volsg {

/// The element types a volume file can hold (docs/SCENE-FORMAT.md section 3).
enum class VoxelType { UByte, UShort, Short, Float };

const char* voxelTypeName(VoxelType type); ///< "UBYTE", "USHORT", "SHORT", "FLOAT"
std::size_t voxelTypeSize(VoxelType type); ///< bytes per voxel

/// Voxels stored x fastest, then y, then z, in one contiguous typed array, with the size of a
/// voxel cell (`spacing`). The volume box is centred on the local origin with extent
/// `dimensions * spacing`; voxel (i,j,k) sits at the centre of its cell. A label (tag) grid is a
/// VolumeGrid of UByte or UShort.
///
/// ```
/// auto grid = VolumeGrid::create({64, 64, 32}, VoxelType::UShort, {1.0, 1.0, 2.5});
/// grid->setValue(1, 2, 3, 1200.0);
/// double d = grid->value(1, 2, 3);
/// ```
class VolumeGrid : public Object {
public:
    /// Largest storage create() allocates unless told otherwise: a bad header must give an
    /// Error, not an out-of-memory kill.
    /// 4 GiB (core/Limits.h); a grid is also refused when larger than the machine's memory or
    /// when a dimension exceeds limits::maxVolumeDimension.
    static constexpr std::uint64_t defaultByteLimit = limits::maxVolumeBytes;

    /// A zero-filled grid. Throws Error, before allocating anything, when a dimension is < 1,
    /// the voxel count or byte size overflows, the byte size exceeds `byteLimit`, or a spacing
    /// is not finite and > 0.
    static ref_ptr<VolumeGrid> create(glm::ivec3 dimensions, VoxelType type,
                                      glm::dvec3 spacing = glm::dvec3(1.0),
                                      std::uint64_t byteLimit = defaultByteLimit);

    /// Bytes needed for such a grid; throws Error as create() does (without allocating).
    static std::uint64_t checkedByteSize(glm::ivec3 dimensions, VoxelType type,
                                         std::uint64_t byteLimit = defaultByteLimit);

    VoxelType type() const { return type_; }
    const glm::ivec3& dimensions() const { return dimensions_; }
    const glm::dvec3& spacing() const { return spacing_; }
    void setSpacing(glm::dvec3 spacing); ///< throws Error unless each component is finite and > 0
    glm::dvec3 extent() const { return glm::dvec3(dimensions_) * spacing_; }
    double smallestSpacing() const;                    ///< L0 of docs/SCENE-FORMAT.md section 4
    glm::dvec3 voxelCenter(int i, int j, int k) const; ///< in local coordinates
    bool isLabelType() const { return type_ == VoxelType::UByte || type_ == VoxelType::UShort; }

    /// The file's placement in patient space (VolumeGeometry.h); unknown for raw and generated
    /// grids. Rendering uses the centred local box; a scene built for the file places it.
    const VolumeGeometry& geometry() const { return geometry_; }
    void setGeometry(const VolumeGeometry& geometry) { geometry_ = geometry; }

    std::size_t voxelCount() const { return voxelCount_; }
    std::size_t byteSize() const { return voxelCount_ * voxelTypeSize(type_); }
    std::size_t index(int i, int j, int k) const {
        return std::size_t(i) + std::size_t(dimensions_.x) *
                                    (std::size_t(j) + std::size_t(dimensions_.y) * std::size_t(k));
    }
    bool contains(int i, int j, int k) const {
        return i >= 0 && j >= 0 && k >= 0 && i < dimensions_.x && j < dimensions_.y &&
               k < dimensions_.z;
    }

    /// The voxel as a double (exact for every type). Indices are not checked.
    double value(std::size_t index) const;
    double value(int i, int j, int k) const { return value(index(i, j, k)); }
    /// Stores `v`: integer types round to nearest and saturate to the type's range (NaN throws
    /// Error); Float stores the nearest float (NaN and infinities as they are).
    void setValue(std::size_t index, double v);
    void setValue(int i, int j, int k, double v) { setValue(index(i, j, k), v); }

    /// Typed access; T must be the storage type (std::uint8_t, std::uint16_t, std::int16_t,
    /// float), else Error.
    template <class T> std::span<T> data() {
        rangeKnown_.store(false, std::memory_order_release); // the caller may write
        if (auto* v = std::get_if<std::vector<T>>(&storage_)) return {v->data(), v->size()};
        throwTypeMismatch();
    }
    template <class T> std::span<const T> data() const {
        if (auto* v = std::get_if<std::vector<T>>(&storage_)) return {v->data(), v->size()};
        throwTypeMismatch();
    }
    std::span<std::byte> bytes();
    std::span<const std::byte> bytes() const;

    /// Smallest and largest finite voxel value ({0, 0} when there is none). O(voxelCount) the
    /// first time, then kept until a non-const access (setValue, data(), bytes()) may have
    /// changed the voxels. A span from data() or bytes() written after this call leaves the
    /// kept range stale: call a non-const accessor again after such writes.
    std::pair<double, double> minMax() const;
    /// The range a transfer function without a dataRange maps to v = 0..1: UByte 0..255 (8-bit
    /// data spans its type, as windowed CT does, and Inventor's VolumeViz maps it so); UShort
    /// and Short the data's own minMax() (a 12-bit CT in SHORT spans a sliver of
    /// -32768..32767, which would render it flat grey), or the type's range for a constant
    /// grid, which has none of its own; Float minMax().
    std::pair<double, double> naturalRange() const;

protected:
    ~VolumeGrid() override = default;

private:
    VolumeGrid(glm::ivec3 dimensions, VoxelType type, glm::dvec3 spacing, std::size_t count);
    [[noreturn]] void throwTypeMismatch() const;

    using Storage = std::variant<std::vector<std::uint8_t>, std::vector<std::uint16_t>,
                                 std::vector<std::int16_t>, std::vector<float>>;
    VoxelType type_;
    glm::ivec3 dimensions_;
    glm::dvec3 spacing_;
    std::size_t voxelCount_;
    VolumeGeometry geometry_;
    Storage storage_;
    // minMax() kept between non-const accesses (several engines ask every frame).
    mutable std::atomic<bool> rangeKnown_{false};
    mutable std::mutex rangeMutex_;
    mutable std::pair<double, double> range_{0.0, 0.0};
    std::pair<double, double> computeMinMax() const;
};

} // namespace volsg
