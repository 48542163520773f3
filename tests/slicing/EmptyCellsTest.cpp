// Empty-space skipping inside a brick (lib/volsg/slicing/EmptyCells): which 8^3 cells may emit,
// and that skipping them changes no image (DVR with one and several samples per plane, plain
// and pre-integrated, MIP with and without peaks), follows transfer-function edits, and still
// matches the reference.
#include "SlicingTestSupport.h"

#include <cmath>
#include <limits>

#include <volsg/slicing/EmptyCells.h>
#include <volsg/slicing/SlicePlan.h>
#include <volsg/slicing/TransferTable.h>

using namespace volsg;
using namespace volsg::test;

namespace {

/// A ball of radius 0.45 (of the half extent) in a 40^3 box, its value falling from 1 at the
/// centre to 0 at the surface, and 0 outside: most cells hold nothing but zeros.
ref_ptr<VolumeGrid> ball() {
    return makeGrid({40, 40, 40}, VoxelType::UByte, glm::dvec3(1.0),
                    [](const glm::dvec3& p) { return std::max(0.0, 1.0 - glm::length(p) / 0.45); });
}

/// A slab of value 1 from voxel 16 on (a cell face) along x, 0 before it: samples between
/// voxels 15 and 16 read both, so cell 1 (voxels 8..15) must not count as empty.
ref_ptr<VolumeGrid> stepAtCellFace() {
    return makeGrid({40, 40, 40}, VoxelType::UByte, glm::dvec3(1.0),
                    [](const glm::dvec3& p) { return p.x > -0.2 ? 1.0 : 0.0; });
}

RayCastVolume ballVolume(const TransferFunction1D& tf, VolumeRenderMode mode,
                         ref_ptr<VolumeGrid> grid = ball()) {
    RayCastVolume v;
    v.data = grid;
    v.transferFunctions[-1] = tf;
    v.mode = mode;
    return v;
}

/// The images of one volume with and without skipping, through one Renderer per image.
struct SkipPair {
    Comparison skipping, plain;
};

SkipPair renderBoth(const RayCastVolume& v, SlicingSettings settings, Camera& camera) {
    Renderer a, b;
    SkipPair out;
    settings.skipEmptyCells = true;
    out.skipping = compareGrid(a, v, settings, camera, 48);
    settings.skipEmptyCells = false;
    out.plain = compareGrid(b, v, settings, camera, 48);
    return out;
}

} // namespace

TEST_CASE("cells record what trilinear samples in them can read") {
    const ref_ptr<VolumeGrid> grid = ball();
    EmptyCells cells;
    cells.measure(*grid, nullptr, 0.0, 255.0);
    REQUIRE(cells.measured());
    CHECK(cells.cells() == glm::ivec3(5)); // 40 / 8

    TransferTable table;
    table.build({{-1, transferFunction({{0.0, 0.0}, {0.05, 0.0}, {1.0, 0.6}})}}, {0.0, 255.0});
    cells.classify(table, false);
    const auto at = [&](int x, int y, int z) {
        return cells.flags()[std::size_t(x + 5 * (y + 5 * z))];
    };
    CHECK(at(0, 0, 0) == 0); // a corner: zeros only
    CHECK(at(2, 2, 2) == 1); // the centre
    // The ball reaches 0.45 * 20 = 9 voxels from the centre (20, 20, 20): cell 1 spans voxels
    // 8..15 and, with the layer around it, reads voxel 16, whose centre is inside the ball.
    CHECK(at(1, 2, 2) == 1);
    CHECK(cells.emptyFraction() > 0.5);

    // A band-pass function (visible only for v in [0.2, 0.4]) on a ball with a bright plateau
    // (v = 1 within 10 voxels of the centre): DVR skips the plateau's cells, whose values are
    // above the band, but MIP may not: a skipped bright sample would be the maximum, and a
    // darker visible one would be shown instead of nothing.
    const ref_ptr<VolumeGrid> plateau =
        makeGrid({40, 40, 40}, VoxelType::UByte, glm::dvec3(1.0), [](const glm::dvec3& p) {
            return std::clamp(3.0 * (1.0 - glm::length(p) / 0.8), 0.0, 1.0);
        });
    table.build({{-1, transferFunction({{0.0, 0.0}, {0.2, 0.0}, {0.3, 0.8}, {0.4, 0.0}})}},
                {0.0, 255.0});
    EmptyCells band;
    band.measure(*plateau, nullptr, 0.0, 255.0);
    band.classify(table, false, false);
    const double dvrEmpty = band.emptyFraction();
    CHECK(band.flags()[std::size_t(2 + 5 * (2 + 5 * 2))] == 0); // the plateau: above the band
    band.classify(table, false, true);
    const double mipEmpty = band.emptyFraction();
    CHECK(band.flags()[std::size_t(2 + 5 * (2 + 5 * 2))] == 1);
    CHECK(mipEmpty < dvrEmpty);
    CHECK(mipEmpty > 0.2); // the zeros around the ball are below the band either way

    // Pre-integrated lookups read up to one table entry (1/255 in v) beyond a value: data
    // ending just below the band is empty for point samples, not for them.
    CHECK_FALSE(table.mayEmit(0.0, 0.199 * 255.0, false, 0, 0));
    CHECK(table.mayEmit(0.0, 0.199 * 255.0, false, 0, 0, 1.0 / 255.0));
    CHECK_FALSE(table.mayEmit(0.0, 0.19 * 255.0, false, 0, 0, 1.0 / 255.0));
}

TEST_CASE("cell ranges equal a brute-force walk over each cell and its layer") {
    // Dimensions that are no multiple of 8 (partial last cells); float data with non-finite
    // voxels, which count as the finite extremes as the textures hold them, and 16-bit data
    // (compared in its own type).
    const glm::ivec3 d(21, 13, 10);
    for (const VoxelType type : {VoxelType::Float, VoxelType::UShort}) {
        INFO((type == VoxelType::Float ? "float" : "ushort"));
        const ref_ptr<VolumeGrid> grid = VolumeGrid::create(d, type);
        std::uint32_t state = 12345u;
        for (std::size_t i = 0; i < grid->voxelCount(); ++i) {
            state = state * 1664525u + 1013904223u;
            const double unit = double(state >> 8) / double(1u << 24);
            grid->setValue(i, type == VoxelType::Float ? unit * 100.0 - 50.0
                                                       : std::floor(unit * 65535.0));
        }
        const bool isFloat = type == VoxelType::Float;
        if (isFloat) {
            grid->setValue(grid->index(8, 7, 8), std::numeric_limits<double>::quiet_NaN());
            grid->setValue(grid->index(20, 0, 0), std::numeric_limits<double>::infinity());
        }
        const double lowest = isFloat ? -60.0 : 0.0, highest = isFloat ? 60.0 : 65535.0;
        EmptyCells cells;
        cells.measure(*grid, nullptr, lowest, highest);
        REQUIRE(cells.cells() == glm::ivec3(3, 2, 2));
        std::size_t c = 0;
        for (int cz = 0; cz < 2; ++cz)
            for (int cy = 0; cy < 2; ++cy)
                for (int cx = 0; cx < 3; ++cx, ++c) {
                    double lo = 1e300, hi = -1e300;
                    for (int z = std::max(8 * cz - 1, 0); z < std::min(8 * cz + 9, d.z); ++z)
                        for (int y = std::max(8 * cy - 1, 0); y < std::min(8 * cy + 9, d.y); ++y)
                            for (int x = std::max(8 * cx - 1, 0); x < std::min(8 * cx + 9, d.x);
                                 ++x) {
                                double v = grid->value(x, y, z);
                                if (std::isnan(v)) v = lowest;
                                if (std::isinf(v)) v = v > 0 ? highest : lowest;
                                lo = std::min(lo, v);
                                hi = std::max(hi, v);
                            }
                    INFO("cell " << cx << " " << cy << " " << cz);
                    CHECK(cells.dataRange(c).x == lo);
                    CHECK(cells.dataRange(c).y == hi);
                }
        if (isFloat) {
            CHECK(cells.dataRange(1 + 3 * (0 + 2 * 1)).x == lowest); // the NaN at (8, 7, 8)
            CHECK(cells.dataRange(2).y == highest);                  // the +Inf at (20, 0, 0)
        }
    }
}

TEST_CASE("skipping empty cells changes no image and matches the reference") {
    OSMesaContext context;
    const TransferFunction1D rampFromZero = transferFunction(
        {{0.0, 0.0}, {0.05, 0.02}, {1.0, 0.6}}, {{0, 0.2}, {1, 1}}, {{0, 0.9}, {1, 0.3}});
    const TransferFunction1D bandAboveZero =
        transferFunction({{0.0, 0.0}, {0.02, 0.0}, {0.05, 0.3}, {0.3, 0.0}, {1.0, 0.6}},
                         {{0, 0.2}, {1, 1}}, {{0, 0.9}, {1, 0.3}});
    const TransferFunction1D& tf = rampFromZero;
    auto camera = framing(*ball(), {0.4f, 0.3f, 1.0f});
    auto stepCamera = framing(*ball(), {0.0f, 0.2f, 1.0f}); // the step's face seen edge-on
    struct Case {
        const char* name;
        VolumeRenderMode mode;
        int samples;
        bool peaks;
        int planes = 0; // automatic
        bool preIntegrated = false;
    };
    // With peaks and several samples (the lean loop), the cells a slab crosses are walked
    // face by face; 3 planes make slabs that cross several cells of air and of the ball.
    for (const Case c :
         {Case{"DVR, 1 sample per plane", VolumeRenderMode::DVR, 1, true},
          Case{"DVR, 4 samples per plane", VolumeRenderMode::DVR, 4, true},
          Case{"MIP with peaks", VolumeRenderMode::MIP, 1, true},
          Case{"MIP without peaks, 4 samples", VolumeRenderMode::MIP, 4, false},
          Case{"MIP with peaks, 4 samples", VolumeRenderMode::MIP, 4, true},
          Case{"MIP with peaks, 3 planes x 16", VolumeRenderMode::MIP, 16, true, 3},
          // Pre-integrated parts span their slab: rows reach over it, no point discards.
          Case{"DVR pre-integrated, 1 sample per plane", VolumeRenderMode::DVR, 1, true, 0, true},
          Case{"DVR pre-integrated, 6 planes x 16", VolumeRenderMode::DVR, 16, true, 6, true}}) {
        INFO(c.name);
        SlicingSettings settings;
        settings.samplesPerPlane = c.samples;
        settings.mipPeaks = c.peaks;
        settings.numPlanes = c.planes;
        settings.preIntegrated = c.preIntegrated;
        // Pre-integration's lookups read a table entry (1/255 in v) beyond a value: its cells
        // are empty under a function transparent a little above the zeros.
        const TransferFunction1D& tf = c.preIntegrated ? bandAboveZero : rampFromZero;
        const SkipPair step =
            renderBoth(ballVolume(tf, c.mode, stepAtCellFace()), settings, *stepCamera);
        CHECK(step.skipping.stats.emptyCells > 0.15); // cells x = 0 (voxels 0..8): a fifth
        CHECK(difference(step.skipping.gl, step.plain.gl).max < 0.01 * k8Bit);
        const SkipPair pair = renderBoth(ballVolume(tf, c.mode), settings, *camera);
        const ImageDifference skipped = difference(pair.skipping.gl, pair.plain.gl);
        MESSAGE(std::string(c.name)
                << ": " << 100.0 * pair.skipping.stats.emptyCells
                << "% of cells empty; skipping vs not: max " << skipped.max / k8Bit
                << "/255; vs reference rmse " << pair.skipping.difference.rmse / k8Bit << "/255");
        CHECK(pair.skipping.stats.emptyCells > 0.5);
        CHECK(pair.plain.stats.emptyCells == 0.0);
        // The geometry left the air out, where a fragment takes few samples (kMaxRowSamples);
        // a slab of more trims its own ends.
        CHECK((pair.skipping.stats.cellRows > 0) == (c.samples <= slicing::kMaxRowSamples));
        CHECK(pair.plain.stats.cellRows == 0);
        // Exact up to the transfer table's linear filter next to the first visible entry.
        CHECK(skipped.max < 0.01 * k8Bit);
        CHECK(pair.skipping.difference.rmse < 1.0 * k8Bit);
    }

    // MINIP sees every sample: nothing is skipped.
    SlicingSettings settings;
    const SkipPair minip = renderBoth(ballVolume(tf, VolumeRenderMode::MINIP), settings, *camera);
    CHECK(minip.skipping.stats.emptyCells == 0.0);
    CHECK(minip.skipping.gl.pixels == minip.plain.gl.pixels);
}

TEST_CASE("a transfer-function edit reclassifies the cells") {
    // First everything below 0.5 is transparent (the outer shell of the ball and the zeros
    // around it are skipped), then the whole range is visible: the same node and Renderer must
    // show the zeros' colour now, exactly as a fresh renderer does.
    OSMesaContext context;
    auto camera = framing(*ball(), {0.3f, 0.2f, 1.0f});
    auto root = Separator::create();
    auto node = GridVolume::create();
    node->description =
        ballVolume(transferFunction({{0.0, 0.0}, {0.5, 0.0}, {1.0, 0.7}}), VolumeRenderMode::DVR);
    root->addChild(node);
    RenderOptions options;
    options.width = options.height = 40;
    options.camera = camera;
    Renderer renderer;
    renderer.render(*root, options);
    const double emptyBefore = node->stats.emptyCells;

    node->description.transferFunctions[-1] = transferFunction({{0.0, 0.3}, {1.0, 0.7}});
    ++node->transferKey;
    const Image edited = renderer.render(*root, options);
    CHECK(node->stats.emptyCells == 0.0); // alpha 0.3 even at v = 0
    CHECK(emptyBefore > 0.5);

    auto freshRoot = Separator::create();
    auto fresh = GridVolume::create();
    fresh->description = node->description;
    freshRoot->addChild(fresh);
    Renderer other;
    CHECK(other.render(*freshRoot, options).pixels == edited.pixels);
}

TEST_CASE("rows grow with the plane count, and a brick whose cells all count is one box") {
    // Each row costs a plane cut per plane and a draw: with many planes the rows are several
    // cells across (fewer, larger boxes), which leaves less air out but changes no image.
    OSMesaContext context;
    const TransferFunction1D tf = transferFunction({{0.0, 0.0}, {0.05, 0.02}, {1.0, 0.6}},
                                                   {{0, 0.2}, {1, 1}}, {{0, 0.9}, {1, 0.3}});
    auto camera = framing(*ball(), {0.4f, 0.3f, 1.0f});
    SlicingSettings few;
    few.numPlanes = 64;
    SlicingSettings many;
    many.numPlanes = 2000; // 2000 planes x 25 rows of single cells: over the cut budget
    const SkipPair coarse = renderBoth(ballVolume(tf, VolumeRenderMode::DVR), few, *camera);
    const SkipPair fine = renderBoth(ballVolume(tf, VolumeRenderMode::DVR), many, *camera);
    MESSAGE("64 planes: " << coarse.skipping.stats.cellRows << " rows of "
                          << coarse.skipping.stats.cellRowGroup
                          << " cells; 2000 planes: " << fine.skipping.stats.cellRows << " rows of "
                          << fine.skipping.stats.cellRowGroup << " cells");
    CHECK(coarse.skipping.stats.cellRowGroup == 1);
    CHECK(fine.skipping.stats.cellRowGroup > 1);
    CHECK(fine.skipping.stats.cellRows > 0);
    CHECK(fine.skipping.stats.cellRows < coarse.skipping.stats.cellRows);
    CHECK(difference(fine.skipping.gl, fine.plain.gl).max < 0.01 * k8Bit);
    CHECK(difference(coarse.skipping.gl, coarse.plain.gl).max < 0.01 * k8Bit);

    // Opaque from the lowest value up: no cell is empty, and the rows are the brick itself.
    const TransferFunction1D everywhere = transferFunction({{0.0, 0.3}, {1.0, 0.6}});
    const SkipPair full = renderBoth(ballVolume(everywhere, VolumeRenderMode::DVR), few, *camera);
    CHECK(full.skipping.stats.emptyCells == 0.0);
    CHECK(full.skipping.stats.cellRows == 1);
    CHECK(full.skipping.gl.pixels == full.plain.gl.pixels);
}
