// The Volume slicer's geometry of a frame: local view, plane layout, clip planes, brick slices.
#include <volsg/slicing/SliceGeometry.h>

#include <volsg/core/Limits.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <volsg/core/Error.h>

namespace volsg::slicing {

namespace {

constexpr int kMaxPlanes = 100000;
/// Most samples a ray takes per voxel along the view (planes x samplesPerPlane): finer slabs
/// resolve nothing more of trilinear data (1000 planes through 16 voxels already agree with
/// the reference within 1/255), and without this bound numPlanes 16777216 on a 3-voxel volume
/// drew 65536 full-screen planes (half a minute a frame on llvmpipe).
constexpr double kMaxSamplesPerVoxel = 64.0;
/// Planes x rows of empty-space cells above which the rows grow (see rowGroupFor).
constexpr double kRowCutBudget = 20000.0;
/// The fewest planes the viewer's interactive plane scale may leave (unless fewer were asked).
constexpr long kMinScaledPlanes = 8;

/// Eye depths of the camera's near and far planes, from the projection matrix.
glm::dvec2 nearFar(const glm::dmat4& p, bool orthographic) {
    if (orthographic) return {(p[3][2] + 1.0) / p[2][2], (p[3][2] - 1.0) / p[2][2]};
    return {p[3][2] / (p[2][2] - 1.0), p[3][2] / (p[2][2] + 1.0)};
}

/// How far from a fragment's point its samples reach, in cells: none with one sample at the
/// point; half a slab, along the longest ray of the view, with several parts or MIP's
/// crossings. -1 when that is too far for rows to leave anything out (a wide view from close
/// by).
/// How far (local units) a fragment's samples reach beyond its point: 0 for one sample at the
/// point, -1 where slabs reach too far to be worth bounding (a wide view from close by).
double sampleReachLocal(const SlicePlan& plan, bool mipPeaks) {
    const LocalView& local = plan.local;
    const Mode mode = plan.method.mode;
    // (A pre-integrated part spans its slab, one sample a plane or many.)
    const bool onePoint =
        plan.method.slabSamples == 1 && (mode == kDvr ? !plan.method.preIntegrated : !mipPeaks);
    if (onePoint) return 0.0;
    double cosMin = 1.0; // of the angle between the view axis and the longest ray
    if (!local.orthographic)
        for (int c = 0; c < 8; ++c) {
            const glm::dvec3 corner((c & 1) ? local.halfExtent.x : -local.halfExtent.x,
                                    (c & 2) ? local.halfExtent.y : -local.halfExtent.y,
                                    (c & 4) ? local.halfExtent.z : -local.halfExtent.z);
            const glm::dvec3 eye = glm::dvec3(local.modelView * glm::dvec4(corner, 1.0));
            cosMin = std::min(cosMin, -eye.z / std::max(glm::length(eye), 1e-300));
        }
    if (cosMin <= 0.25) return -1.0; // a wide view from close by: slabs reach too far
    double localPerEye = 0.0;
    for (int a = 0; a < 3; ++a)
        localPerEye = std::max(localPerEye, glm::length(local.eyeToLocal3[a]));
    return 0.5 * plan.layout.spacing / cosMin * localPerEye;
}

int rowReachOf(const SlicePlan& plan, bool mipPeaks) {
    const double reach = sampleReachLocal(plan, mipPeaks);
    if (reach <= 0.0) return int(reach);
    return int(std::ceil(reach / plan.local.L0 / EmptyCells::kCellSize));
}

/// A paged brick's slices cut to the box of its cells that may emit (its own EmptyCells,
/// classified for this frame's table), grown by the samples' reach: the air it holds makes
/// no fragments. Slabs and faces keep the brick's box (what lies between is transparent).
/// False when no cell may emit.
bool emittingBox(BrickState& s, const Brick& b, const VolumeTextures& v, const SlicePlan& plan,
                 glm::dvec3& lo, glm::dvec3& hi) {
    const bool maximum = plan.method.mode == kMip;
    if (s.cellsTableKey != v.tableKey || s.cellsMaximum != maximum) {
        s.cells->classify(v.table, false, maximum);
        s.cellsTableKey = v.tableKey;
        s.cellsMaximum = maximum;
    }
    const glm::ivec3 n = s.cells->cells();
    const std::vector<std::uint8_t>& flags = s.cells->flags();
    glm::ivec3 first(n), last(-1);
    for (int z = 0; z < n.z; ++z)
        for (int y = 0; y < n.y; ++y)
            for (int x = 0; x < n.x; ++x)
                if (flags[std::size_t(x) +
                          std::size_t(n.x) *
                              (std::size_t(y) + std::size_t(n.y) * std::size_t(z))]) {
                    first = glm::min(first, glm::ivec3(x, y, z));
                    last = glm::max(last, glm::ivec3(x, y, z));
                }
    if (last.x < 0) return false;
    // Cell c spans the brick's voxel coordinates [8c, 8c + 8] (its voxels and the layer
    // around them that trilinear samples read); voxel coordinate u of the brick's texture is
    // at local (firstVoxel + u) levelSpacing - halfExtent.
    constexpr double C = EmptyCells::kCellSize;
    const glm::dvec3 origin = glm::dvec3(b.firstVoxel) * b.levelSpacing - plan.local.halfExtent;
    lo = origin + glm::dvec3(first) * C * b.levelSpacing - plan.rows.pagedReach;
    hi = origin + glm::dvec3(last + 1) * C * b.levelSpacing + plan.rows.pagedReach;
    lo = glm::max(lo, b.boxMin);
    hi = glm::min(hi, b.boxMax);
    return glm::all(glm::lessThan(lo, hi));
}

/// Each row costs a plane cut per plane and a draw: with many planes the rows grow (group x
/// group cells across) until planes x rows is at most kRowCutBudget, which keeps the frame's
/// CPU work under about a millisecond.
int rowGroupFor(const glm::ivec3& cells, int axis, int planes) {
    const int ns = cells[(axis + 1) % 3], nt = cells[(axis + 2) % 3];
    auto rowsAcross = [&](int g) { return double((ns + g - 1) / g) * double((nt + g - 1) / g); };
    int group = 1;
    while (double(planes) * rowsAcross(group) > kRowCutBudget && group < 64)
        group *= 2;
    return group;
}

/// Brick b's slices, the whole brick or row by row, appended to v.vertices.
void cutSlices(VolumeTextures& v, const Brick& b, BrickState& s, const VolumeGrid& grid,
               const SlicePlan& plan, SlicingStats& drawn) {
    const LocalView& local = plan.local;
    const glm::dvec3 margin(0.5 * local.L0); // see uOwnMin in the shader
    s.first = GLint(v.vertices.size());
    if (plan.rows.reach >= 0) {
        v.rows.rowsOf(b, plan.rows.axis, grid.spacing(), local.halfExtent, local.viewer,
                      local.orthographic, plan.rows.group, s.rows);
        for (const CellRow& row : s.rows) {
            ProxyPlaneCutter::cutInto(row.boxMin - margin, row.boxMax + margin, local.modelView,
                                      plan.layout, local.clipDepth.x, v.slices);
            s.rowFirst.push_back(GLint(v.vertices.size()));
            s.rowCount.push_back(GLsizei(v.slices.vertices.size()));
            v.vertices.insert(v.vertices.end(), v.slices.vertices.begin(), v.slices.vertices.end());
        }
        drawn.cellRows += int(s.rows.size());
    } else {
        ProxyPlaneCutter::cutInto(b.boxMin - margin, b.boxMax + margin, local.modelView,
                                  plan.layout, local.clipDepth.x, v.slices);
        v.vertices.insert(v.vertices.end(), v.slices.vertices.begin(), v.slices.vertices.end());
    }
    s.count = GLsizei(v.vertices.size()) - s.first;
    drawn.sliceTriangles += std::size_t(s.count) / 3;
}

/// The faces of brick b that face the viewer (at `viewer`, or looking along it when
/// orthographic; local coordinates), as triangles: those on the volume box (a paged brick, of
/// any level, where its region reaches the box's face), and with `seamsToo`
/// (SlicePlan::slabsEndAtBricks) those between bricks. They stand for the rays no plane
/// crosses within the box (or the brick). Sort-last: b is the part of brick `whole` in this
/// process's part; the faces the part cuts through are not the brick's, unless `partSeams`
/// (SlicePlan::slabsEndAtPart).
void appendFrontFaces(const Brick& b, const Brick& whole, const glm::ivec3& grid,
                      const glm::dvec3& halfExtent, bool seamsToo, bool partSeams,
                      const glm::dvec3& viewer, bool orthographic, std::vector<glm::vec3>& out) {
    for (int a = 0; a < 3; ++a)
        for (int side = 0; side < 2; ++side) {
            const bool wholeFace =
                side == 0 ? b.boxMin[a] == whole.boxMin[a] : b.boxMax[a] == whole.boxMax[a];
            const bool onBox =
                b.levelSpacing.x > 0.0
                    ? (side == 0 ? b.boxMin[a] <= -halfExtent[a] : b.boxMax[a] >= halfExtent[a])
                    : (side == 0 ? b.index[a] == 0 : b.index[a] == grid[a] - 1);
            // A face the part cuts through is a seam when slabs end at the part's faces.
            if (wholeFace ? !(onBox || seamsToo) : !(seamsToo && partSeams)) continue;
            const double c = side == 0 ? b.boxMin[a] : b.boxMax[a];
            const bool facing = orthographic ? (side == 0 ? viewer[a] > 0.0 : viewer[a] < 0.0)
                                             : (side == 0 ? viewer[a] < c : viewer[a] > c);
            if (!facing) continue;
            const int u = (a + 1) % 3, w = (a + 2) % 3;
            glm::vec3 corner[4];
            for (int k = 0; k < 4; ++k) {
                glm::dvec3 p;
                p[a] = c;
                p[u] = (k == 1 || k == 2) ? b.boxMax[u] : b.boxMin[u];
                p[w] = k >= 2 ? b.boxMax[w] : b.boxMin[w];
                corner[k] = glm::vec3(p);
            }
            for (const int k : {0, 1, 2, 0, 2, 3})
                out.push_back(corner[k]);
        }
}

/// Brick b's faces that bound the visible part, appended to v.vertices: its front faces (on the
/// volume box, or at seams too), and the clip planes that rays cross into the kept side.
void appendBoundingFaces(VolumeTextures& v, const Brick& b, const Brick& whole, BrickState& s,
                         const SlicePlan& plan) {
    const LocalView& local = plan.local;
    s.faceFirst = GLint(v.vertices.size());
    appendFrontFaces(b, whole, v.layout.grid(), local.halfExtent, plan.slabsEndAtBricks,
                     plan.slabsEndAtPart, local.viewer, local.orthographic, v.vertices);
    for (const glm::dvec4& plane : plan.clipPlanes) {
        const glm::dvec3 n(plane);
        const bool entering = local.orthographic ? glm::dot(n, local.viewer) > 0.0
                                                 : glm::dot(n, local.viewer) < plane.w;
        if (entering)
            ProxyPlaneCutter::appendPlanePolygon(b.boxMin, b.boxMax, n, plane.w, v.vertices);
    }
    // The camera in the box: rays enter the volume at the near plane, so its cut through the
    // brick is a face like the box's. Without it a ray that leaves the box before it meets a
    // plane had no fragment (from inside, with a few planes, whole regions of the image
    // stayed empty). A hair beyond the near plane, so that clipping keeps it.
    if (local.clipDepth.x > local.boxDepth.x) {
        const glm::dmat4& m = local.modelView;
        const glm::dvec3 n(-m[0][2], -m[1][2], -m[2][2]); // eye depth = n . p - m[3][2]
        const double depth =
            local.clipDepth.x + 1e-5 * std::max(local.boxDepth.y - local.clipDepth.x, 0.0);
        ProxyPlaneCutter::appendPlanePolygon(b.boxMin, b.boxMax, n, depth + m[3][2], v.vertices);
    }
    s.faceCount = GLsizei(v.vertices.size()) - s.faceFirst;
}

} // namespace

LocalView localView(const RenderView& view, const glm::dmat4& model, const VolumeGrid& grid) {
    LocalView local;
    local.model = model;
    local.modelView = view.view * model;
    local.eyeToLocal = glm::inverse(local.modelView);
    local.eyeToLocal3 = glm::dmat3(local.eyeToLocal);
    local.halfExtent = 0.5 * grid.extent();
    local.boxDepth =
        ProxyPlaneCutter::depthRange(-local.halfExtent, local.halfExtent, local.modelView);
    local.clipDepth = nearFar(view.projection, view.orthographic);
    local.L0 = grid.smallestSpacing();
    local.viewer = view.orthographic
                       ? local.eyeToLocal3 * glm::dvec3(0.0, 0.0, -1.0)
                       : glm::dvec3(local.eyeToLocal * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    local.orthographic = view.orthographic;
    return local;
}

QualityView qualityView(const LocalView& local, const RenderView& view) {
    return qualityViewOf(local.modelView, view.projection, local.halfExtent, local.L0);
}

PlaneLayout planeLayout(const LocalView& local, const SlicingSettings& settings, int slabSamples,
                        const FrameContext& frame) {
    // Plane count: numPlanes, or 2 per voxel (spacing L0 / 2 in local units along the view
    // axis); a quarter while interacting. Opacity correction makes both the same image.
    const double localPerEyeAxis = glm::length(local.eyeToLocal3 * glm::dvec3(0.0, 0.0, -1.0));
    const double depthExtent = local.boxDepth.y - local.boxDepth.x;
    const double autoSpacing = 0.5 * local.L0 / localPerEyeAxis;
    const bool chosen = settings.numPlanes <= 0 && settings.planeSpacingL0 > 0.0;
    const double wanted = chosen ? settings.planeSpacingL0 * local.L0 / localPerEyeAxis
                                 : autoSpacing * double(slabSamples);
    const double count =
        settings.numPlanes > 0 ? double(settings.numPlanes) : std::ceil(depthExtent / wanted);
    long still = long(std::clamp(count, 1.0, double(kMaxPlanes)));
    long planes = still;
    if (frame.interactive) {
        // A spacing chosen for this frame is the interactive target's already.
        planes = settings.interactivePlanes > 0 ? long(settings.interactivePlanes)
                 : chosen                       ? still
                                                : std::max(1L, (still + 3) / 4);
        // The viewer lowers this further when interactive frames are too slow, but not below
        // kMinScaledPlanes: with two or three planes the slab boundaries show as seams.
        planes = std::max(long(std::ceil(double(planes) * frame.interactivePlaneScale)),
                          std::min(planes, kMinScaledPlanes));
    }
    planes = std::clamp(planes, 1L, long(kMaxPlanes));
    // The quality fields multiply: planes x samples per plane is what each ray takes, bounded
    // as a total (numPlanes 100000 with samplesPerPlane 256 would take 25.6M samples a ray).
    planes = std::min(planes, std::max(1L, long(limits::maxSamplesPerRay) / long(slabSamples)));
    // And as a density: at most kMaxSamplesPerVoxel samples per voxel along the view.
    const double finest = std::ceil(depthExtent * localPerEyeAxis / local.L0 * kMaxSamplesPerVoxel /
                                    double(slabSamples));
    if (finest >= 1.0 && finest < double(planes)) planes = long(finest);
    return PlaneLayout::over(local.boxDepth,
                             std::max(depthExtent, 1e-12) / double(planes) * (1.0 + 1e-9));
}

std::vector<glm::dvec4> localClipPlanes(const RayCastVolume& volume) {
    if (volume.clipPlanes.size() > std::size_t(kMaxClipPlanes))
        throw Error(std::to_string(volume.clipPlanes.size()) +
                    " ClipPlanes are in scope of a Volume; it clips with at most " +
                    std::to_string(kMaxClipPlanes));
    const glm::dmat4& model = volume.model;
    std::vector<glm::dvec4> localPlanes;
    localPlanes.reserve(volume.clipPlanes.size());
    for (const glm::dvec4& w : volume.clipPlanes) {
        // n_w . (M p) >= d_w  <=>  (M^T n_w) . p >= d_w - n_w . t
        const glm::dvec3 n(w);
        const glm::dvec3 local = glm::transpose(glm::dmat3(model)) * n;
        localPlanes.emplace_back(local, w.w - glm::dot(n, glm::dvec3(model[3])));
    }
    return localPlanes;
}

RowPlan planRows(VolumeTextures& v, const SlicePlan& plan, const SlicingSettings& settings) {
    RowPlan rows;
    if (plan.method.skipCells && settings.skipEmptyCells &&
        plan.method.slabSamples <= kMaxRowSamples) {
        rows.reach = rowReachOf(plan, settings.mipPeaks);
        if (rows.reach >= 0 && (v.rowsReach != rows.reach || v.rowsKind != v.cellKind ||
                                v.rowsTableKey != v.cellTableKey)) {
            v.rows.dilate(v.cells, rows.reach);
            v.rowsReach = rows.reach;
            v.rowsKind = v.cellKind;
            v.rowsTableKey = v.cellTableKey;
        }
    }
    // A paged volume's bricks cut their slices to their own emitting cells, where the
    // in-memory slicer's rows are exact (the same modes; see prepareVolume's skipCells).
    const Mode mode = plan.method.mode;
    if (v.layout.explicitBricks() && settings.skipEmptyCells && !plan.method.tagged &&
        ((mode == kDvr && !plan.method.preIntegrated) || mode == kMip))
        rows.pagedReach = sampleReachLocal(plan, settings.mipPeaks);
    const LocalView& local = plan.local;
    const glm::dvec3 towardsVolume = local.orthographic ? local.viewer : -local.viewer; // centred
    rows.axis = CellRows::axisFor(towardsVolume);
    if (rows.reach >= 0) rows.group = rowGroupFor(v.cells.cells(), rows.axis, plan.layout.count);
    return rows;
}

void cutBricks(VolumeTextures& v, const VolumeGrid& grid, const SlicePlan& plan,
               SlicingStats& drawn) {
    // A paged volume's bricks come ordered by their chooser (PagedBricks.h).
    if (!v.layout.explicitBricks())
        v.layout.backToFront(plan.local.viewer, plan.local.orthographic, v.order);
    drawn.cellRowGroup = plan.rows.group;
    v.vertices.clear();
    for (const int i : v.order) {
        BrickState& s = v.bricks[std::size_t(i)];
        s.count = 0;
        s.faceCount = 0;
        s.rows.clear();
        s.rowFirst.clear();
        s.rowCount.clear();
        // Sort-last: only where the brick meets this process's part (all of it otherwise).
        const Brick& whole = v.layout.bricks()[std::size_t(i)];
        Brick b = whole;
        b.boxMin = glm::max(whole.boxMin, plan.partMin);
        b.boxMax = glm::min(whole.boxMax, plan.partMax);
        if (glm::any(glm::greaterThanEqual(b.boxMin, b.boxMax))) continue;
        if (plan.method.mode == kDvr && !s.mayEmit) {
            ++drawn.bricksSkipped;
            continue;
        }
        if (plan.rows.pagedReach >= 0.0 && s.cells && b.levelSpacing.x > 0.0) {
            Brick emitting = b;
            if (!emittingBox(s, b, v, plan, emitting.boxMin, emitting.boxMax)) {
                ++drawn.bricksSkipped;
                continue;
            }
            if (emitting.boxMin != b.boxMin || emitting.boxMax != b.boxMax) ++drawn.bricksTrimmed;
            cutSlices(v, emitting, s, grid, plan, drawn);
        } else {
            cutSlices(v, b, s, grid, plan, drawn);
        }
        appendBoundingFaces(v, b, whole, s, plan);
    }
}

} // namespace volsg::slicing
