#pragma once
// An object extracted from a volume: the voxels that can contribute to its image, with their
// attributes, and its three RenderLists built lazily (RTVR sections 3 and 3.1).

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/core/Object.h>
#include <volsg/shearwarp/RenderList.h>
#include <volsg/volume/TransferFunction1D.h>

namespace volsg {

class VolumeGrid;

/// Which voxels belong to the object's region.
struct ObjectSource {
    enum Kind { Whole, Tag, Threshold };
    Kind kind = Whole;
    int tag = 0;                  ///< Tag: voxels whose label is `tag`
    double low = 0.0, high = 0.0; ///< Threshold: data values low <= d <= high
};

/// Which voxels of the region are kept.
/// - Visible: opacity alpha(v) > 0 under the object's transfer function;
/// - Surface: the boundary layer of the region (a 6-neighbour outside it or outside the grid);
///   for a Whole source the region is the visible voxels;
/// - Gradient: gradient magnitude |grad v| * L0 >= gradientThreshold (v normalised by the
///   transfer function's data range; so the threshold is "change of v across one voxel").
enum class VoxelSelection { Visible, Surface, Gradient };

/// An object's voxels ordered by value for pure MIP (RTVR 3.4, after Mroz et al. 2000): drawn
/// from the lowest value to the highest, each voxel simply overwrites its pixel, so no maximum
/// is searched and the values no transfer function shows at the low end are never read. One
/// copy serves every viewing axis.
struct ValueSortedVoxels {
    static constexpr int kBitsI = 11, kBitsJ = 11, kBitsK = 10; ///< dimensions up to 2048^2 x 1024
    /// Index-space position i | j << 11 | k << 22, ascending value, then (k, j, i).
    std::vector<std::uint32_t> position;
    /// Voxels of value12 v: [start[v], start[v + 1]).
    std::array<std::uint32_t, 4097> start{};
    static constexpr std::uint32_t pack(unsigned i, unsigned j, unsigned k) {
        return i | (j << kBitsI) | (k << (kBitsI + kBitsJ));
    }
    /// Whether a grid of these dimensions fits the packing.
    static bool fits(const glm::ivec3& d) {
        return d.x <= (1 << kBitsI) && d.y <= (1 << kBitsJ) && d.z <= (1 << kBitsK);
    }
};

struct ExtractionSpec {
    ObjectSource source;
    VoxelSelection selection = VoxelSelection::Visible;
    double gradientThreshold = 0.05;
    TransferFunction1D transferFunction; ///< its data range normalises v; Visible uses alpha
};

/// Extraction scans the grid once, keeps the selected voxels in (k, j, i) order and computes
/// their attributes: v quantised to 12 bits over the transfer function's data range (the
/// paper's "sub-range remapping"), the gradient by central differences of v in local units
/// (one-sided at the grid border), its direction as a 12-bit GradientCode of the surface
/// normal -grad v, its magnitude log-remapped to 8 bits (of which the 4-bit channel takes
/// the top 4: log keeps the weak gradients of soft tissue apart, RTVR 3.1).
class VoxelObject : public Object {
public:
    /// Throws Error when `tags` is needed (Tag source) but missing or of other dimensions.
    static ref_ptr<VoxelObject> extract(const VolumeGrid& data, const VolumeGrid* tags,
                                        const ExtractionSpec& spec);

    const glm::ivec3& dimensions() const { return dimensions_; }
    const glm::dvec3& spacing() const { return spacing_; }
    std::size_t voxelCount() const { return i_.size(); }
    /// Largest gradient magnitude (v per L0) and the 8-bit code's inverse.
    double maxMagnitude() const { return maxMagnitude_; }
    double magnitudeOf(std::uint8_t code) const;
    std::uint8_t magnitudeCode(double magnitude) const;

    /// The RenderList for principal axis 0, 1 or 2, built on first use (thread-safe).
    RenderList& renderList(int axis);
    bool hasRenderList(int axis) const;
    /// The voxels ordered by value, built on first use (thread-safe); nullptr when the grid
    /// is too large for its packing (ValueSortedVoxels::fits).
    const ValueSortedVoxels* valueSorted();
    /// Takes a RenderList kept outside the object (the series' disk cache) for its axis
    /// instead of sorting one; an existing list of that axis stays. Throws Error when the list
    /// does not fit the object (RenderList::checkConsistent).
    void adoptRenderList(std::unique_ptr<RenderList> list);
    /// RenderLists this object sorted itself (adopted ones do not count).
    unsigned renderListBuilds() const;
    /// RenderLists sorted by all objects of the process so far (benchmarks).
    static std::uint64_t processRenderListBuilds();
    /// Extracted voxels plus every RenderList built so far.
    std::size_t memoryBytes() const;

    /// The extracted arrays without RenderLists: what it takes to store an object outside the
    /// process (the series' disk cache) and rebuild it bit for bit with fromArrays().
    struct Arrays {
        glm::ivec3 dimensions{0};
        glm::dvec3 spacing{1.0};
        double maxMagnitude = 0.0;
        std::vector<std::uint16_t> i, j, k, value12, gradientCode;
        std::vector<std::uint8_t> magnitude8;
    };
    Arrays arrays() const;
    /// Throws Error when the arrays differ in length or a position lies outside dimensions.
    static ref_ptr<VoxelObject> fromArrays(Arrays arrays);

protected:
    ~VoxelObject() override = default;

private:
    VoxelObject() = default;
    glm::ivec3 dimensions_{0};
    glm::dvec3 spacing_{1.0};
    double maxMagnitude_ = 0.0;
    std::vector<std::uint16_t> i_, j_, k_;
    std::vector<std::uint16_t> value12_, gradientCode_;
    std::vector<std::uint8_t> magnitude8_;
    mutable std::mutex buildMutex_;
    std::array<std::unique_ptr<RenderList>, 3> lists_;
    std::unique_ptr<ValueSortedVoxels> valueSorted_;
    unsigned builds_ = 0; // guarded by buildMutex_
    void build(RenderList& list, int axis) const;
};

} // namespace volsg
