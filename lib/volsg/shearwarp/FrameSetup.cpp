// Stages 1-5 of a shear-warp frame (FrameStages.h): output buffers, factorisation, objects,
// paths and intermediate buffers.
#include <volsg/shearwarp/FrameStages.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include <volsg/core/Error.h>
#include <volsg/core/Limits.h>

namespace volsg::shearwarp {

namespace {

bool isOrthographic(const glm::dmat4& p) {
    return p[0][3] == 0.0 && p[1][3] == 0.0 && p[2][3] == 0.0 && p[3][3] == 1.0;
}

/// Index-space point of intermediate position (u, v) on slice k.
glm::dvec3 indexPoint(const Factorisation& f, double u, double v, double k) {
    glm::dvec3 g;
    g[f.a] = u - f.ua0 + f.sa * k;
    g[f.b] = v - f.vb0 + f.sb * k;
    g[f.c] = k;
    return g;
}

glm::dvec3 eyeOf(const glm::dmat4& indexToEye, const glm::dvec3& g) {
    return glm::dvec3(indexToEye * glm::dvec4(g, 1.0));
}

/// Output pixel (x, y) of an eye point, pixel centres at integers, row 0 at the top.
glm::dvec2 pixelOf(const ShearWarpView& view, const glm::dvec3& eye) {
    const glm::dvec4 clip = view.projection * glm::dvec4(eye, 1.0);
    return glm::dvec2((clip.x * 0.5 + 0.5) * view.width - 0.5,
                      (0.5 - clip.y * 0.5) * view.height - 0.5);
}

/// The principal axis and the shear of the view (index space, spacing folded in).
void chooseAxes(Factorisation& f, const glm::dmat4& indexToEye, const glm::ivec3& n) {
    const glm::dvec3 D = glm::inverse(glm::dmat3(indexToEye)) * glm::dvec3(0.0, 0.0, -1.0);
    int c = 0;
    for (int axis = 1; axis < 3; ++axis)
        if (std::abs(D[axis]) > std::abs(D[c])) c = axis;
    f.c = c;
    f.a = (c + 1) % 3;
    f.b = (c + 2) % 3;
    f.na = n[f.a];
    f.nb = n[f.b];
    f.nc = n[c];
    f.sa = D[f.a] / D[c];
    f.sb = D[f.b] / D[c];
    f.ua0 = std::max(0.0, f.sa * (f.nc - 1)) + 1.0;
    f.vb0 = std::max(0.0, f.sb * (f.nc - 1)) + 1.0;
    f.W = f.na + int(std::ceil(std::abs(f.sa) * (f.nc - 1))) + 3;
    f.H = f.nb + int(std::ceil(std::abs(f.sb) * (f.nc - 1))) + 3;
    f.ascending = D[c] < 0.0; // back to front: the far end of c first
}

/// The MIP table of an object: value (4096) -> premultiplied TF colour.
std::vector<glm::vec4> mipTableOf(const ShearWarpObject& o) {
    std::vector<glm::vec4> table(4096);
    for (int m = 0; m < 4096; ++m) {
        const double v = double(m) / 4095.0;
        const float alpha = float(std::clamp(
            o.transferFunction.evaluate(TransferFunction1D::Alpha, v) * double(o.unclipped.opacity),
            0.0, 1.0));
        const glm::vec3 colour(o.transferFunction.evaluate(TransferFunction1D::Red, v),
                               o.transferFunction.evaluate(TransferFunction1D::Green, v),
                               o.transferFunction.evaluate(TransferFunction1D::Blue, v));
        table[std::size_t(m)] = glm::vec4(colour * alpha, alpha);
    }
    return table;
}

/// Per slice k (and nc) the first entry of the slice: entries are sorted by slice.
std::vector<std::uint32_t> sliceStarts(const RenderList& list, int nc) {
    std::vector<std::uint32_t> start(std::size_t(nc) + 1, 0);
    const auto& entries = list.entries;
    std::size_t e = 0;
    for (int k = 0; k <= nc; ++k) {
        while (e < entries.size() && entries[e].slice() < k)
            ++e;
        start[std::size_t(k)] = std::uint32_t(e);
    }
    return start;
}

template <class Buffer> void ensureSize(Buffer& buffer, std::size_t size) {
    if (buffer.size() < size) buffer.resize(size);
}

} // namespace

void checkView(const ShearWarpView& view) {
    if (!isOrthographic(view.projection))
        throw Error("ShearWarpVolume renders parallel projections only: use an "
                    "OrthographicCamera (a perspective camera is not supported)");
    if (view.width <= 0 || view.height <= 0) throw Error("shear-warp: empty output size");
}

ShearWarpFrame takeOutputBuffers(ShearWarpFrame& spare, const ShearWarpView& view,
                                 StaleOutput& stale) {
    // The buffers of a recycled frame: its image is 0 and its depth 1 outside the rectangle it
    // drew, and that is cleared only where the new frame does not write it (no allocation, no
    // page faults, no full clear, no second pass over the pixels the warp writes anyway).
    ShearWarpFrame frame;
    stale = StaleOutput{};
    const std::size_t outPixels = std::size_t(view.width) * std::size_t(view.height);
    if (spare.image.width == view.width && spare.image.height == view.height &&
        spare.image.pixels.size() == outPixels && spare.windowDepth.size() == outPixels) {
        frame.image = std::move(spare.image);
        frame.windowDepth = std::move(spare.windowDepth);
        if (spare.drawn.x < spare.drawn.z && spare.drawn.y < spare.drawn.w)
            stale = StaleOutput{spare.drawn, spare.wroteDepth};
    } else {
        frame.image = Image(view.width, view.height);
        frame.windowDepth.assign(outPixels, 1.0f);
    }
    frame.pickObject = std::move(spare.pickObject); // refilled by sizeBuffers (capacity kept)
    frame.pickSlice = std::move(spare.pickSlice);
    spare = ShearWarpFrame();
    return frame;
}

void clearStaleRows(const StaleOutput& stale, ShearWarpFrame& frame, int y0, int y1) {
    const glm::ivec4 r = stale.rect;
    const std::size_t width = std::size_t(frame.image.width);
    for (int y = std::max(y0, r.y); y < std::min(y1, r.w); ++y) {
        const std::size_t row = std::size_t(y) * width;
        std::fill(frame.image.pixels.begin() + std::ptrdiff_t(row + std::size_t(r.x)),
                  frame.image.pixels.begin() + std::ptrdiff_t(row + std::size_t(r.z)),
                  glm::vec4(0.0f));
        if (stale.depth)
            std::fill(frame.windowDepth.begin() + std::ptrdiff_t(row + std::size_t(r.x)),
                      frame.windowDepth.begin() + std::ptrdiff_t(row + std::size_t(r.z)), 1.0f);
    }
}

void checkObjects(const std::vector<ShearWarpObject>& objects) {
    for (const auto& o : objects)
        if (!o.object) throw Error("shear-warp: object without voxels");
    const VoxelObject& first = *objects.front().object;
    for (const auto& o : objects)
        if (o.object->dimensions() != first.dimensions())
            throw Error("shear-warp: the objects of one frame must come from one volume");
}

glm::dmat4 indexToLocalMatrix(const VoxelObject& object) {
    const glm::dvec3 s = object.spacing();
    const glm::dvec3 origin = -0.5 * glm::dvec3(object.dimensions()) * s + 0.5 * s;
    glm::dmat4 m(1.0);
    m[0][0] = s.x;
    m[1][1] = s.y;
    m[2][2] = s.z;
    m[3] = glm::dvec4(origin, 1.0);
    return m;
}

bool isFinite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

bool isFinite(const glm::dmat3& m) {
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

Factorisation factorise(const VoxelObject& first, const ShearWarpView& view) {
    Factorisation f;
    f.indexToLocal = indexToLocalMatrix(first);
    const glm::dmat4 E = view.modelView * f.indexToLocal; // index -> eye
    // A singular or non-finite transform has no factorisation: refused, as the reference ray
    // caster refuses it, before any size or index is computed from it.
    const double det = glm::determinant(glm::dmat3(E));
    if (!isFinite(E) || !isFinite(view.projection) || !std::isfinite(det) || det == 0.0 ||
        !isFinite(glm::inverse(glm::dmat3(E))))
        throw Error("ShearWarpVolume: the transform to the view is singular or not finite "
                    "(a zero or extreme scale, or an extreme translation)");
    chooseAxes(f, E, first.dimensions());
    f.projection = view.projection;
    f.width = view.width;
    f.height = view.height;
    // The warp: where intermediate (0, 0), (1, 0) and (0, 1) of slice 0 land.
    const glm::dvec2 p00 = pixelOf(view, eyeOf(E, indexPoint(f, 0, 0, 0)));
    const glm::dvec2 p10 = pixelOf(view, eyeOf(E, indexPoint(f, 1, 0, 0)));
    const glm::dvec2 p01 = pixelOf(view, eyeOf(E, indexPoint(f, 0, 1, 0)));
    f.warp[0] = glm::dvec3(p10 - p00, 0.0);
    f.warp[1] = glm::dvec3(p01 - p00, 0.0);
    f.warp[2] = glm::dvec3(p00, 1.0);
    f.unwarp = glm::inverse(f.warp);
    // A volume far outside the view, or seen as a point, may give a warp that cannot be
    // inverted in double precision: then it shows nothing (every pixel misses it).
    f.warpValid = isFinite(f.warp) && isFinite(f.unwarp) && glm::determinant(f.warp) != 0.0;
    f.z0 = eyeOf(E, indexPoint(f, 0, 0, 0)).z;
    f.zu = eyeOf(E, indexPoint(f, 1, 0, 0)).z - f.z0;
    f.zv = eyeOf(E, indexPoint(f, 0, 1, 0)).z - f.z0;
    f.zk = eyeOf(E, indexPoint(f, 0, 0, 1)).z - f.z0;
    glm::dvec3 step(0.0);
    step[f.a] = f.sa;
    step[f.b] = f.sb;
    step[f.c] = 1.0;
    const glm::dvec3 spacing = first.spacing();
    const double ds = glm::length(step * spacing);
    f.stepRatio = ds / (std::min({spacing.x, spacing.y, spacing.z}));
    return f;
}

void describeFactorisation(const Factorisation& f, ShearWarpFrame& frame) {
    frame.outputToIntermediate = f.unwarp;
    frame.indexToLocal = f.indexToLocal;
    frame.axisA = f.a;
    frame.axisB = f.b;
    frame.axisC = f.c;
    frame.shearA = f.sa;
    frame.shearB = f.sb;
    frame.originA = f.ua0;
    frame.originB = f.vb0;
    frame.stats.principalAxis = f.c;
    frame.stats.intermediateSize = {f.W, f.H};
}

std::vector<FrameObject> frameObjects(std::vector<ShearWarpObject>& objects, int axis) {
    std::vector<FrameObject> fo(objects.size());
    std::set<RenderList*> lists;
    for (std::size_t i = 0; i < objects.size(); ++i) {
        fo[i].source = &objects[i];
        fo[i].list = &objects[i].object->renderList(axis);
        if (!lists.insert(fo[i].list).second)
            throw Error("shear-warp: two objects of a frame share one voxel list");
    }
    return fo;
}

std::vector<std::unique_lock<std::mutex>> lockLists(const std::vector<FrameObject>& objects) {
    std::set<RenderList*> lists;
    for (const FrameObject& f : objects)
        lists.insert(f.list);
    std::vector<std::unique_lock<std::mutex>> locks;
    for (RenderList* list : lists)
        locks.emplace_back(list->mutex);
    return locks;
}

void prepareObjects(std::vector<FrameObject>& objects, const Factorisation& fac,
                    const ShearWarpView& view, int sliceStep) {
    const glm::dmat3 localToEye(view.modelView);
    for (FrameObject& f : objects) {
        ShearWarpObject& o = *f.source;
        ShearWarpRenderer::prepare(o, *f.list);
        // Skipped slices: the kept ones sit in the middle of their group of sliceStep (so the
        // pattern is symmetric in the volume) and each stands for sliceStep slices.
        f.sliceStep = o.thinLayer ? 1 : sliceStep;
        f.slicePhase = ((fac.nc - 1) % f.sliceStep) / 2;
        const VoxelLook looks[2] = {o.unclipped, o.clipped};
        for (int part = 0; part < 2; ++part) {
            f.parts[part].draw = looks[part].opacity > 0.0f;
            if (f.parts[part].draw)
                f.parts[part].tables = VoxelTables::build(
                    o, looks[part], fac.stepRatio * f.sliceStep, localToEye, view.lightDirection);
        }
        if (o.compositing == ObjectCompositing::MIP) f.mipTable = mipTableOf(o);
        f.sliceStart = sliceStarts(*f.list, fac.nc);
    }
}

FramePaths choosePaths(const std::vector<FrameObject>& objects, const ShearWarpView& view) {
    FramePaths p;
    p.pureDvr = view.interObject == InterObjectCompositing::DVR;
    for (const FrameObject& f : objects)
        if (f.source->compositing != ObjectCompositing::DVR) p.pureDvr = false;
    // Pure MIP: every object MIP (and MIP between them), no clipped voxels (they would need
    // their own look), no opaque geometry to test against; the value-sorted voxels exist.
    bool pureMip = view.interObject == InterObjectCompositing::MIP || objects.size() == 1;
    for (const FrameObject& f : objects) {
        if (!pureMip) break;
        pureMip = f.source->compositing == ObjectCompositing::MIP && f.parts[0].draw;
        for (const RenderListEntry& e : f.list->entries)
            pureMip = pureMip && e.firstClipped == e.lastInSlice;
    }
    pureMip = pureMip && view.valueSortedMip && view.opaqueWindowDepth.empty();
    for (const FrameObject& f : objects)
        if (pureMip) {
            p.sorted.push_back(f.source->object->valueSorted());
            pureMip = p.sorted.back() != nullptr;
        }
    p.pureMip = pureMip;
    p.twoLevel = !p.pureDvr && !p.pureMip; // the value-sorted MIP has its own buffers
    for (const FrameObject& f : objects)
        p.anySurface = p.anySurface || f.source->compositing == ObjectCompositing::Surface;
    p.hasLimit = !view.opaqueWindowDepth.empty();
    if (p.hasLimit &&
        view.opaqueWindowDepth.size() != std::size_t(view.width) * std::size_t(view.height))
        throw Error("shear-warp: opaque depth buffer of the wrong size");
    return p;
}

FrameBuffers sizeBuffers(FrameScratch& s, ShearWarpFrame& frame, const Factorisation& f,
                         const FramePaths& paths) {
    const std::size_t pixels = std::size_t(f.W) * std::size_t(f.H);
    // One intermediate pixel per voxel across the principal slices, whatever the output size:
    // a total checked before anything is allocated.
    if (pixels > limits::maxShearWarpIntermediatePixels)
        throw Error("ShearWarpVolume: the intermediate image of " + std::to_string(f.W) + " x " +
                    std::to_string(f.H) + " pixels for this view is larger than the limit of " +
                    std::to_string(limits::maxShearWarpIntermediatePixels) +
                    " (one pixel per voxel of a slice)");
    ensureSize(s.global, pixels);
    if (paths.twoLevel) {
        ensureSize(s.local, pixels);
        ensureSize(s.localValue, pixels);
        ensureSize(s.localDepth, pixels);
        ensureSize(s.localObject, pixels);
    }
    if (paths.anySurface) ensureSize(s.hitDepth, pixels);
    if (paths.pureDvr) {
        ensureSize(s.nextOpen, pixels);
        s.opaqueCount.assign(std::size_t(f.H), 0);
    }
    if (paths.hasLimit) ensureSize(s.limit, pixels);
    frame.pickObject.resize(pixels);
    frame.pickSlice.resize(pixels);
    return FrameBuffers{s.global.data(),         s.local.data(),        s.localValue.data(),
                        s.localDepth.data(),     s.localObject.data(),  s.hitDepth.data(),
                        s.limit.data(),          s.nextOpen.data(),     s.opaqueCount.data(),
                        frame.pickObject.data(), frame.pickSlice.data()};
}

} // namespace volsg::shearwarp
