#pragma once
// The Volume slicer's state per volume (bricks, tables, buffers) and the functions on it.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/core/Object.h>
#include <volsg/gl/Buffer.h>
#include <volsg/gl/Texture.h>
#include <volsg/gl/VertexArray.h>
#include <volsg/paging/BrickKey.h>
#include <volsg/slicing/BrickLayout.h>
#include <volsg/slicing/CellRows.h>
#include <volsg/slicing/DataFormat.h>
#include <volsg/slicing/EmptyCells.h>
#include <volsg/slicing/PreIntegrationTable.h>
#include <volsg/slicing/ProxyPlaneCutter.h>
#include <volsg/slicing/SlabErrorModel.h>
#include <volsg/slicing/SlicingStats.h>
#include <volsg/slicing/TextureStaging.h>
#include <volsg/slicing/TransferTable.h>
#include <volsg/volume/PiecewiseLinear.h>
#include <volsg/volume/VolumeGrid.h>
#include <volsg/volume/VolumeModel.h>

namespace volsg {

class RenderCache;

namespace slicing {

struct SliceShared;

/// One brick's textures and what the CPU knows about its voxels.
struct BrickState {
    Texture data, tags;
    bool resident = false;
    std::uint64_t lastUse = 0;
    double dataMin = 0.0, dataMax = 0.0; ///< over the texture's voxels (non-finite replaced)
    int tagMin = 0, tagMax = 0;
    bool mayEmit = true; ///< under the current transfer functions
    GLint first = 0;     ///< this frame's slice vertices
    GLsizei count = 0;
    GLint faceFirst = 0; ///< this frame's front faces on the volume box (sliver rays)
    GLsizei faceCount = 0;
    /// This frame's rows of non-empty cells (CellRows), each drawn with its own box; empty:
    /// the whole brick is one draw.
    std::vector<CellRow> rows;
    std::vector<GLint> rowFirst;
    std::vector<GLsizei> rowCount;
    /// A paged brick's own empty-space cells (measured at upload, PagedBricks.cpp): its slices
    /// are cut to the box of the cells that may emit (emittingBox).
    std::shared_ptr<EmptyCells> cells;
    std::uint64_t cellsTableKey = ~std::uint64_t(0); ///< the table `cells` was classified for
    bool cellsMaximum = false;                       ///< classified for MIP
};

/// Per volume (node and grid): bricks, tables and geometry, kept across frames.
struct VolumeTextures {
    ref_ptr<const VolumeGrid> data, tags;
    DataFormat format;
    double finiteMin = 0.0, finiteMax = 0.0;
    glm::dvec2 naturalRange{0.0, 1.0};

    bool hasLayout = false;
    std::uint64_t layoutBudget = 0;
    int layoutGuard = 0;
    BrickLayout layout;
    std::vector<BrickState> bricks;
    std::size_t residentBytes = 0;
    std::uint64_t useCounter = 0;
    bool filterNearest = false;

    bool hasTable = false;
    std::uint64_t tableKey = 0;
    TransferTable table;
    Texture tableTexture, tagRowTexture;
    Texture tableRowTexture; ///< row 0 of tableTexture as a 1D texture (the lean DVR loop)

    EmptyCells cells;    ///< measured on first use
    Texture cellTexture; ///< EmptyCells::flags as R8UI, one texel per cell
    std::uint64_t cellTableKey = 0;
    int cellKind = -1; ///< prepareCells' kind of the flags in cellTexture; -1 none yet
    CellRows rows;     ///< the cell flags dilated by rowsReach
    int rowsReach = -1;
    std::uint64_t rowsTableKey = 0;
    int rowsKind = -1;

    /// A paged volume's bricks drawn in the last frame (their levels: LevelOfDetailError).
    std::vector<BrickKey> pagedDrawn;

    /// The error model of this grid under the current transfer functions and mode.
    std::unique_ptr<SlabErrorModel> errorModel;
    std::uint64_t errorModelKey = 0;
    int errorModelMode = -1;
    bool errorModelRegion = false; ///< made for a sort-last process's own part

    bool hasPreIntegration = false;
    std::vector<PreIntegrationTable> preIntegration; ///< one per transfer-table row
    Texture preIntegrationTexture;

    std::vector<PiecewiseLinear::Point> planeOpacity;
    Texture planeOpacityTexture;

    Buffer vertexBuffer;
    VertexArray vertexArray;
    std::vector<glm::vec3> vertices;
    ProxySlices slices;
    std::vector<int> order;
    std::vector<std::uint32_t> scratch; ///< converted texels of a brick (4-byte aligned)
    /// The grid's bricks staged before it was shown (TextureStaging.h); dropped after the
    /// first frame's uploads.
    std::unique_ptr<StagedGrid> staged;
    /// The previous grid's brick textures (a series' last step), refilled in place when a
    /// brick of this grid has their size and format: on llvmpipe a new 256^3 R16 texture
    /// costs 28 ms against 10 ms to overwrite one (its pages are fresh). Freed after the frame.
    std::vector<Texture> spareTextures;

    SlicingStats totals;
};

// VolumeTextures.cpp: the per-frame preparation, each step doing nothing when up to date.

/// The cache key of a volume's textures: its grids (new data starts a fresh cache, and the old
/// one is dropped after the frame), and a paged volume's guard (PagedVolume::wideGuard).
std::uint64_t textureKeyOf(const RayCastVolume& volume);
/// Takes over what was made for this grid before its first frame: the bricks staged while the
/// previous step showed (waited for), and that step's textures to refill.
void adoptGrid(RenderCache& cache, const Object& owner, std::uint64_t key, VolumeTextures& v,
               TextureStaging& staging, const RayCastVolume& volume);
/// Records the grid's format and ranges, once per cache.
void prepareGrid(VolumeTextures& v, const RayCastVolume& volume);
/// How a grid is split into bricks (prepareLayout, and the staging of the next grid).
BrickLayout::Limits layoutLimits(const VolumeGrid& data, const VolumeGrid* tags,
                                 const SliceShared& shared, std::uint64_t budget, int guard);
void prepareLayout(VolumeTextures& v, const SliceShared& shared, std::uint64_t budget, int guard);
void prepareTable(VolumeTextures& v, const RayCastVolume& volume, std::uint64_t key);
/// The empty-cell flags for this table and kind (0 DVR: may emit; 1 MIP: may be a shown
/// maximum; 2 pre-integrated DVR: may emit with the pre-integration table's filter, whose
/// lookups read up to one of its entries beyond a value), measured on first use and uploaded
/// when the table or the kind changes.
void prepareCells(VolumeTextures& v, int kind);
/// The cells' data ranges (once per grid; the staging thread's when it took them).
void measureCells(VolumeTextures& v);
void preparePreIntegration(VolumeTextures& v);
/// Whether planeOpacity changes anything: m = 1 everywhere needs no lookup.
bool planeOpacityMatters(const std::vector<PiecewiseLinear::Point>& points);
void preparePlaneOpacity(VolumeTextures& v, const std::vector<PiecewiseLinear::Point>& points);
/// Sets the data textures' filter (interpolation NEAREST or LINEAR) when it changed.
void prepareFilter(VolumeTextures& v, bool nearest);

// BrickResidency.cpp: bricks' ranges, uploads and eviction under the texture budget.

/// The staged grid's measures, when they are of this grid with its labels (a grid staged
/// without them, for an untagged table, has no tag ranges a later tagged table would need).
const GridMeasures* stagedMeasures(const VolumeTextures& v);
/// Brick ranges of the layout: from the staged grid's measures when they are of this layout.
void measureBricks(VolumeTextures& v);
void release(VolumeTextures& v, std::size_t i);
/// Makes brick i resident, first evicting the least recently used others while the budget
/// would be exceeded (bricks drawn earlier in this frame may go: their draws are issued). So
/// a volume whose visible bricks exceed the budget streams them, as the seed's bricking does.
void makeResident(VolumeTextures& v, std::size_t i, std::uint64_t budget, bool withTags);

} // namespace slicing
} // namespace volsg
