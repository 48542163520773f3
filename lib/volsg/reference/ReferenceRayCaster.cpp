#include <volsg/reference/ReferenceRayCaster.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <mutex>
#include <string>
#include <thread>
#include <tuple>
#include <type_traits>

#include <volsg/core/Error.h>

namespace volsg {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
/// docs/SCENE-FORMAT.md section 4: A is clamped so that tau stays finite.
constexpr double kMaxOpacity = 1.0 - 1e-6;
/// Early ray termination: what is left behind changes the pixel by less than this.
constexpr double kStopTransmittance = 1e-7;

// ---------------------------------------------------------------------------------------------
// Camera

struct CameraFrame {
    glm::dmat4 inverseViewProjection{1.0};
    glm::dvec3 eye{0.0};
    glm::dvec3 forward{0.0, 0.0, -1.0};
    bool perspective = false;
    int width = 0;
    int height = 0;
    bool clipToNearFar = false;
};

/// A pixel's ray: unit direction, and the stretch [start, end] of it that counts.
struct PixelRay {
    glm::dvec3 origin{0.0};
    glm::dvec3 dir{0.0, 0.0, -1.0};
    double start = 0.0;
    double end = kInfinity;
    glm::dvec3 nearPoint{0.0}; // unprojected at NDC z = -1
};

bool isFinite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

glm::dmat4 checkedInverse(const glm::dmat4& m, const char* what) {
    const double det = glm::determinant(m);
    if (!std::isfinite(det) || det == 0.0 || !isFinite(m))
        throw Error(std::string(what) + " is singular or not finite");
    return glm::inverse(m);
}

CameraFrame makeFrame(const RayCastCamera& camera) {
    if (camera.width < 1 || camera.height < 1)
        throw Error("ray caster viewport must be at least 1x1, got " +
                    std::to_string(camera.width) + "x" + std::to_string(camera.height));
    CameraFrame f;
    f.inverseViewProjection =
        checkedInverse(camera.projection * camera.view, "camera projection * view");
    const glm::dmat4 cameraToWorld = checkedInverse(camera.view, "camera view matrix");
    f.eye = glm::dvec3(cameraToWorld * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    f.forward = glm::normalize(glm::dvec3(cameraToWorld * glm::dvec4(0.0, 0.0, -1.0, 0.0)));
    // glm is column-major: m[2][3] is the w row's z entry, -1 for a perspective frustum.
    f.perspective = camera.projection[2][3] != 0.0;
    f.width = camera.width;
    f.height = camera.height;
    f.clipToNearFar = camera.clipToNearFar;
    return f;
}

glm::dvec3 unproject(const CameraFrame& f, double ndcX, double ndcY, double ndcZ) {
    const glm::dvec4 p = f.inverseViewProjection * glm::dvec4(ndcX, ndcY, ndcZ, 1.0);
    return glm::dvec3(p) / p.w;
}

glm::dvec2 pixelCentreNdc(const CameraFrame& f, int x, int y) {
    return {(x + 0.5) / f.width * 2.0 - 1.0, 1.0 - (y + 0.5) / f.height * 2.0};
}

PixelRay makePixelRay(const CameraFrame& f, int x, int y) {
    const glm::dvec2 ndc = pixelCentreNdc(f, x, y);
    const glm::dvec3 nearPoint = unproject(f, ndc.x, ndc.y, -1.0);
    const glm::dvec3 farPoint = unproject(f, ndc.x, ndc.y, 1.0);
    PixelRay ray;
    ray.dir = glm::normalize(farPoint - nearPoint);
    ray.nearPoint = nearPoint;
    if (f.perspective) {
        ray.origin = f.eye;
    } else { // back along the ray to the eye plane
        ray.origin = nearPoint - ray.dir * (glm::dot(nearPoint - f.eye, f.forward) /
                                            glm::dot(ray.dir, f.forward));
    }
    if (f.clipToNearFar) {
        ray.start = glm::dot(nearPoint - ray.origin, ray.dir);
        ray.end = glm::dot(farPoint - ray.origin, ray.dir);
    }
    return ray;
}

/// The parameter interval where origin + s*dir lies in the axis-aligned box [lo, hi]; empty
/// (first > second) when it misses.
std::pair<double, double> slabInterval(const glm::dvec3& origin, const glm::dvec3& dir,
                                       const glm::dvec3& lo, const glm::dvec3& hi) {
    double enter = -kInfinity, exit = kInfinity;
    for (int a = 0; a < 3; ++a) {
        if (dir[a] == 0.0) {
            if (origin[a] < lo[a] || origin[a] > hi[a]) return {kInfinity, -kInfinity};
            continue;
        }
        double t0 = (lo[a] - origin[a]) / dir[a];
        double t1 = (hi[a] - origin[a]) / dir[a];
        if (t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0);
        exit = std::min(exit, t1);
    }
    return {enter, exit};
}

// ---------------------------------------------------------------------------------------------
// Volumes prepared for sampling: plain arrays, resolved transfer functions.

struct PreparedTransferFunction {
    double lo = 0.0, hi = 1.0;
    PiecewiseLinear red, green, blue, alpha;
    /// Data values where tau or C of this TF may kink or jump: the control points of every
    /// channel, the clamp ends lo and hi, and where A reaches the 1 - 1e-6 clamp. DVR steps are
    /// split where the data crosses one, so each sub-step sees one linear piece of each.
    std::vector<double> breaks;

    double normalise(double d) const { return TransferFunction1D::normalise(d, lo, hi); }
    glm::dvec3 color(double v) const { return {red(v), green(v), blue(v)}; }
};

struct PreparedVolume {
    VolumeRenderMode mode = VolumeRenderMode::DVR;
    glm::ivec3 dims{1};
    glm::dvec3 spacing{1.0};
    glm::dvec3 halfExtent{0.5};
    std::size_t strideY = 1, strideZ = 1;
    std::vector<float> values;              ///< non-finite voxels already replaced
    std::vector<std::uint16_t> slotOfVoxel; ///< transfer function per voxel; empty: slot 0
    std::vector<PreparedTransferFunction> transferFunctions; ///< slot 0: the default
    double L0 = 1.0;
    double localStep = 0.5;
    glm::dmat4 worldToLocal{1.0};
    std::vector<glm::dvec4> clipPlanes;
    bool hasPlaneOpacity = false;
    PiecewiseLinear planeOpacity;
    double depthNear = 0.0, depthFar = 1.0; ///< of the box's corners, along the camera's forward
    bool hasBoxClip = false;
    glm::dmat4 worldToBox{1.0};
    glm::dvec3 boxMin{0.0}, boxMax{0.0};
    double opacity[2] = {1.0, 1.0}; ///< [0] outside, [1] inside the BoxClip box
    glm::dvec3 blendColor[2] = {glm::dvec3(1.0), glm::dvec3(1.0)};
    double blendWeight[2] = {0.0, 0.0};
    int brickSize = 8;
    glm::ivec3 bricks{1};
    std::vector<std::uint8_t> brickMayEmit; ///< DVR only: 0 where no TF gives opacity

    std::size_t voxelIndex(const glm::ivec3& c) const {
        return std::size_t(c.x) + std::size_t(c.y) * strideY + std::size_t(c.z) * strideZ;
    }
    /// The voxel whose cell holds local point p (nearest neighbour, clamped to the grid).
    glm::ivec3 cellOf(const glm::dvec3& p) const {
        glm::ivec3 c;
        for (int a = 0; a < 3; ++a)
            c[a] = std::clamp(int(std::floor((p[a] + halfExtent[a]) / spacing[a])), 0, dims[a] - 1);
        return c;
    }
    int slotAt(const glm::dvec3& p) const {
        return slotOfVoxel.empty() ? 0 : slotOfVoxel[voxelIndex(cellOf(p))];
    }
    bool mayEmitAt(const glm::dvec3& p) const {
        const glm::ivec3 b = cellOf(p) / brickSize;
        return brickMayEmit[std::size_t(b.x) +
                            std::size_t(bricks.x) *
                                (std::size_t(b.y) + std::size_t(bricks.y) * std::size_t(b.z))] != 0;
    }

    /// Trilinear between voxel centres, clamped to the edge beyond the outermost ones.
    double sample(const glm::dvec3& p) const {
        const std::size_t stride[3] = {1, strideY, strideZ};
        std::size_t base = 0, next[3];
        double f[3];
        for (int a = 0; a < 3; ++a) {
            const int n = dims[a];
            const double u =
                std::clamp((p[a] + halfExtent[a]) / spacing[a] - 0.5, 0.0, double(n - 1));
            const int i = std::min(int(u), std::max(n - 2, 0));
            f[a] = u - i;
            base += std::size_t(i) * stride[a];
            next[a] = n > 1 ? stride[a] : 0;
        }
        const float* c = values.data() + base;
        auto lerp = [](double a, double b, double t) { return a + (b - a) * t; };
        const double c00 = lerp(c[0], c[next[0]], f[0]);
        const double c10 = lerp(c[next[1]], c[next[1] + next[0]], f[0]);
        const double c01 = lerp(c[next[2]], c[next[2] + next[0]], f[0]);
        const double c11 = lerp(c[next[2] + next[1]], c[next[2] + next[1] + next[0]], f[0]);
        return lerp(lerp(c00, c10, f[1]), lerp(c01, c11, f[1]), f[2]);
    }
};

template <class T>
void copyValues(const VolumeGrid& grid, std::vector<float>& out, double lowest, double highest) {
    const auto src = grid.data<T>();
    out.resize(src.size());
    for (std::size_t i = 0; i < src.size(); ++i) {
        if constexpr (std::is_same_v<T, float>) {
            const float x = src[i];
            if (std::isnan(x) || x == -std::numeric_limits<float>::infinity())
                out[i] = float(lowest);
            else if (x == std::numeric_limits<float>::infinity())
                out[i] = float(highest);
            else
                out[i] = x;
        } else {
            out[i] = float(src[i]); // every UByte/UShort/Short value is exact in float
        }
    }
}

std::vector<float> floatValues(const VolumeGrid& grid) {
    std::vector<float> out;
    const auto [lowest, highest] = grid.minMax(); // finite values only
    switch (grid.type()) {
    case VoxelType::UByte:
        copyValues<std::uint8_t>(grid, out, lowest, highest);
        break;
    case VoxelType::UShort:
        copyValues<std::uint16_t>(grid, out, lowest, highest);
        break;
    case VoxelType::Short:
        copyValues<std::int16_t>(grid, out, lowest, highest);
        break;
    case VoxelType::Float:
        copyValues<float>(grid, out, lowest, highest);
        break;
    }
    return out;
}

PreparedTransferFunction prepareTransferFunction(const TransferFunction1D& tf,
                                                 glm::dvec2 naturalRange) {
    PreparedTransferFunction p;
    const glm::dvec2 range = tf.dataRange() ? *tf.dataRange() : naturalRange;
    p.lo = range.x;
    p.hi = range.y;
    p.red = tf.channel(TransferFunction1D::Red);
    p.green = tf.channel(TransferFunction1D::Green);
    p.blue = tf.channel(TransferFunction1D::Blue);
    p.alpha = tf.channel(TransferFunction1D::Alpha);

    std::vector<double> v = {0.0, 1.0};
    for (const PiecewiseLinear* c : {&p.red, &p.green, &p.blue, &p.alpha})
        for (const auto& point : c->points())
            if (point.x > 0.0 && point.x < 1.0) v.push_back(point.x);
    const auto& a = p.alpha.points();
    for (std::size_t i = 0; i + 1 < a.size(); ++i)
        if ((a[i].y < kMaxOpacity) != (a[i + 1].y < kMaxOpacity) && a[i].x < a[i + 1].x) {
            const double x =
                a[i].x + (kMaxOpacity - a[i].y) * (a[i + 1].x - a[i].x) / (a[i + 1].y - a[i].y);
            if (x > 0.0 && x < 1.0) v.push_back(x);
        }
    if (p.hi == p.lo) {
        p.breaks = {p.lo}; // a step: v is 0 or 1
    } else {
        for (double x : v)
            p.breaks.push_back(p.lo + x * (p.hi - p.lo));
        std::sort(p.breaks.begin(), p.breaks.end());
        p.breaks.erase(std::unique(p.breaks.begin(), p.breaks.end()), p.breaks.end());
    }
    return p;
}

void prepareTransferFunctions(const RayCastVolume& in, PreparedVolume& out) {
    const auto [natLo, natHi] = in.data->naturalRange();
    const glm::dvec2 natural(natLo, natHi);
    const auto defaultTf = in.transferFunctions.find(-1);
    out.transferFunctions.push_back(prepareTransferFunction(
        defaultTf != in.transferFunctions.end() ? defaultTf->second : TransferFunction1D(),
        natural));

    std::vector<std::uint16_t> slotOfTag; // tag value -> slot; 0 = the default
    for (const auto& [tag, tf] : in.transferFunctions) {
        if (tag < -1 || tag > 65535)
            throw Error("transfer function tag must be -1 or 0..65535, got " + std::to_string(tag));
        if (tag == -1) continue;
        if (slotOfTag.size() <= std::size_t(tag)) slotOfTag.resize(std::size_t(tag) + 1, 0);
        slotOfTag[std::size_t(tag)] = std::uint16_t(out.transferFunctions.size());
        out.transferFunctions.push_back(prepareTransferFunction(tf, natural));
    }
    if (!in.tags || slotOfTag.empty()) return; // every voxel uses the default

    const VolumeGrid& tags = *in.tags;
    out.slotOfVoxel.resize(tags.voxelCount());
    for (std::size_t v = 0; v < tags.voxelCount(); ++v) {
        const auto tag = std::size_t(tags.value(v));
        out.slotOfVoxel[v] = tag < slotOfTag.size() ? slotOfTag[tag] : 0;
    }
}

// A brick may emit when, for some transfer function, its data range maps to a non-zero
// opacity somewhere. Trilinear values inside the brick are convex combinations of the voxels
// from one before its first cell to one after its last, so their min..max bounds them all.
void prepareBricks(PreparedVolume& out, int brickSize) {
    out.brickSize = brickSize;
    out.bricks = (out.dims + (brickSize - 1)) / brickSize;
    out.brickMayEmit.assign(std::size_t(out.bricks.x) * out.bricks.y * out.bricks.z, 0);
    std::size_t at = 0;
    for (int bz = 0; bz < out.bricks.z; ++bz)
        for (int by = 0; by < out.bricks.y; ++by)
            for (int bx = 0; bx < out.bricks.x; ++bx, ++at) {
                const glm::ivec3 b(bx, by, bz);
                const glm::ivec3 lo = glm::max(b * brickSize - 1, glm::ivec3(0));
                const glm::ivec3 hi = glm::min((b + 1) * brickSize, out.dims - 1);
                double dMin = kInfinity, dMax = -kInfinity;
                for (int k = lo.z; k <= hi.z; ++k)
                    for (int j = lo.y; j <= hi.y; ++j)
                        for (int i = lo.x; i <= hi.x; ++i) {
                            const double d = out.values[out.voxelIndex({i, j, k})];
                            dMin = std::min(dMin, d);
                            dMax = std::max(dMax, d);
                        }
                for (const auto& tf : out.transferFunctions)
                    if (tf.alpha.maxOver(tf.normalise(dMin), tf.normalise(dMax)) > 0.0)
                        out.brickMayEmit[at] = 1;
            }
}

PreparedVolume prepareVolume(const RayCastVolume& in, const CameraFrame& frame,
                             const RayCastOptions& options, std::size_t number,
                             bool withBricks = true) {
    const std::string which = "volume " + std::to_string(number) + ": ";
    if (!in.data) throw Error(which + "no data grid");
    const VolumeGrid& grid = *in.data;
    if (in.tags) {
        if (in.tags->dimensions() != grid.dimensions())
            throw Error(which + "the tag grid's dimensions differ from the data's");
        if (!in.tags->isLabelType()) throw Error(which + "the tag grid must be UByte or UShort");
    }

    PreparedVolume out;
    out.mode = in.mode;
    out.dims = grid.dimensions();
    out.spacing = grid.spacing();
    out.halfExtent = 0.5 * grid.extent();
    out.strideY = std::size_t(out.dims.x);
    out.strideZ = std::size_t(out.dims.x) * std::size_t(out.dims.y);
    out.values = floatValues(grid);
    out.L0 = grid.smallestSpacing();
    out.localStep = options.step > 0.0 ? options.step : out.L0;
    out.worldToLocal = checkedInverse(in.model, (which + "model matrix").c_str());
    out.clipPlanes = in.clipPlanes;
    prepareTransferFunctions(in, out);

    if (!in.planeOpacity.empty()) {
        out.hasPlaneOpacity = true;
        out.planeOpacity = PiecewiseLinear(in.planeOpacity);
    }
    out.depthNear = kInfinity;
    out.depthFar = -kInfinity;
    for (int c = 0; c < 8; ++c) {
        const glm::dvec3 corner((c & 1) ? out.halfExtent.x : -out.halfExtent.x,
                                (c & 2) ? out.halfExtent.y : -out.halfExtent.y,
                                (c & 4) ? out.halfExtent.z : -out.halfExtent.z);
        const glm::dvec3 world(in.model * glm::dvec4(corner, 1.0));
        const double depth = glm::dot(world - frame.eye, frame.forward);
        out.depthNear = std::min(out.depthNear, depth);
        out.depthFar = std::max(out.depthFar, depth);
    }

    if (in.boxClip) {
        const RayCastBoxClip& b = *in.boxClip;
        out.hasBoxClip = true;
        out.worldToBox = b.model ? checkedInverse(*b.model, (which + "BoxClip model").c_str())
                                 : out.worldToLocal;
        out.boxMin = glm::min(b.origin, b.origin + b.extent);
        out.boxMax = glm::max(b.origin, b.origin + b.extent);
        out.opacity[0] = std::max(0.0, b.outsideOpacity);
        out.opacity[1] = std::max(0.0, b.insideOpacity);
        out.blendColor[0] = b.outsideColor;
        out.blendColor[1] = b.insideColor;
        out.blendWeight[0] = std::clamp(b.outsideColorWeight, 0.0, 1.0);
        out.blendWeight[1] = std::clamp(b.insideColorWeight, 0.0, 1.0);
    }
    if (out.mode == VolumeRenderMode::DVR && withBricks) prepareBricks(out, options.brickSize);
    return out;
}

// ---------------------------------------------------------------------------------------------
// Tracing

/// One volume along one pixel ray. Distances s are world units along the unit world direction;
/// the local ray has the same parameter, its direction `scale` local units long.
struct VolumeOnRay {
    bool hit = false;
    glm::dvec3 origin{0.0}, dir{0.0}; ///< local
    double scale = 1.0;
    double enter = 0.0, exit = 0.0;                      ///< unclipped part inside the box
    double clipEnter = kInfinity, clipExit = -kInfinity; ///< inside the BoxClip box
    double depth0 = 0.0, depthRate = 0.0; ///< camera depth at s: depth0 + s * depthRate
    double step = 1.0;                    ///< world length of the volume's local step

    glm::dvec3 localAt(double s) const { return origin + s * dir; }
    int region(double s) const { return s >= clipEnter && s <= clipExit ? 1 : 0; }
    /// planeOpacity's t at s: 0 at the volume box's nearest corner depth, 1 at its farthest.
    double depthFraction(const PreparedVolume& V, double s) const {
        return (depth0 + s * depthRate - V.depthNear) / (V.depthFar - V.depthNear);
    }
};

/// A MIP/MINIP/AVERAGE volume's result: a thin layer where its unclipped part starts.
struct Layer {
    double at = 0.0;
    glm::dvec3 premultiplied{0.0};
    double alpha = 0.0;
};

/// A DVR volume active over one piece of the ray, with what is constant over the piece.
struct ActiveVolume {
    std::size_t index;
    int slot;
    int region;
    PiecewiseLinear::Line planeOpacity; ///< m(t) on this piece (its control points are cuts)
};

/// `mu(D) = 1/D - 1/(e^D - 1)`: where, as a fraction of the step, the light of a homogeneous
/// step of optical depth D comes from on average (1/2 when thin, -> 0 when opaque).
double meanEmissionFraction(double D) {
    if (D < 1e-3) return 0.5 - D / 12.0 + D * D * D / 720.0;
    return 1.0 / D - 1.0 / std::expm1(D);
}

/// Equal steps no longer than `step` over `length`, times 2^level (so the grids of successive
/// levels nest). Capped only to keep the count representable.
long stepCount(double length, double step, int level) {
    const double n = std::max(1.0, std::ceil(length / step)) * std::ldexp(1.0, level);
    return long(std::min(n, 0x1p40));
}

struct TraceResult {
    glm::dvec3 rgb{0.0};
    double transmittance = 1.0;
};

/// Traces pixel rays; owns the scratch space, so nothing is allocated per pixel once warm.
class RayTracer {
public:
    RayTracer(const std::vector<PreparedVolume>& volumes, const CameraFrame& frame)
        : volumes_(volumes), frame_(frame), rays_(volumes.size()) {}

    /// Sets up the volumes along this ray; false when no volume has anything on it.
    bool setup(const PixelRay& ray, double opaqueDistance) {
        bool any = false;
        const double end = std::min(ray.end, opaqueDistance);
        for (std::size_t i = 0; i < volumes_.size(); ++i) {
            const PreparedVolume& V = volumes_[i];
            VolumeOnRay& R = rays_[i];
            R = VolumeOnRay{};
            R.origin = glm::dvec3(V.worldToLocal * glm::dvec4(ray.origin, 1.0));
            R.dir = glm::dvec3(V.worldToLocal * glm::dvec4(ray.dir, 0.0));
            R.scale = glm::length(R.dir);
            auto [enter, exit] = slabInterval(R.origin, R.dir, -V.halfExtent, V.halfExtent);
            enter = std::max(enter, ray.start);
            exit = std::min(exit, end);
            for (const glm::dvec4& plane : V.clipPlanes) { // keep n.p >= d
                const glm::dvec3 n(plane);
                const double rate = glm::dot(n, ray.dir);
                const double atOrigin = glm::dot(n, ray.origin) - plane.w;
                if (rate == 0.0) {
                    if (atOrigin < 0.0) exit = -kInfinity;
                } else if (rate > 0.0) {
                    enter = std::max(enter, -atOrigin / rate);
                } else {
                    exit = std::min(exit, -atOrigin / rate);
                }
            }
            R.enter = enter;
            R.exit = exit;
            R.hit = enter < exit && R.scale > 0.0;
            if (!R.hit) continue;
            any = true;
            if (V.hasBoxClip) {
                const glm::dvec3 o(V.worldToBox * glm::dvec4(ray.origin, 1.0));
                const glm::dvec3 d(V.worldToBox * glm::dvec4(ray.dir, 0.0));
                std::tie(R.clipEnter, R.clipExit) = slabInterval(o, d, V.boxMin, V.boxMax);
            }
            R.depth0 = glm::dot(ray.origin - frame_.eye, frame_.forward);
            R.depthRate = glm::dot(ray.dir, frame_.forward);
            R.step = V.localStep / R.scale;
        }
        return any;
    }

    /// The pixel with steps of the volumes' local step / 2^level.
    TraceResult trace(const glm::dvec3& behind, int level) {
        layers_.clear();
        for (std::size_t i = 0; i < volumes_.size(); ++i)
            if (rays_[i].hit && volumes_[i].mode != VolumeRenderMode::DVR)
                projectionLayer(i, level);
        std::sort(layers_.begin(), layers_.end(),
                  [](const Layer& a, const Layer& b) { return a.at < b.at; });

        events_.clear();
        for (std::size_t i = 0; i < volumes_.size(); ++i)
            if (rays_[i].hit && volumes_[i].mode == VolumeRenderMode::DVR) dvrEvents(i);
        for (const Layer& layer : layers_)
            events_.push_back(layer.at);
        std::sort(events_.begin(), events_.end());

        glm::dvec3 light(0.0);
        double T = 1.0;
        std::size_t nextLayer = 0;
        auto applyLayersUpTo = [&](double s) {
            for (; nextLayer < layers_.size() && layers_[nextLayer].at <= s; ++nextLayer) {
                light += T * layers_[nextLayer].premultiplied;
                T *= 1.0 - layers_[nextLayer].alpha;
            }
        };
        for (std::size_t e = 0; e + 1 < events_.size() && T >= kStopTransmittance; ++e) {
            const double s0 = events_[e], s1 = events_[e + 1];
            applyLayersUpTo(s0);
            if (!(s1 > s0)) continue;
            integratePiece(s0, s1, level, light, T);
        }
        applyLayersUpTo(kInfinity);
        return {light + T * behind, T};
    }

    /// Volume i's first point on the ray whose opacity per L0, 1 - (1 - A)^m, reaches
    /// `threshold` (ReferenceRayCaster::firstVisibleDistance).
    std::optional<double> firstVisible(std::size_t i, double threshold) {
        const PreparedVolume& V = volumes_[i];
        const VolumeOnRay& R = rays_[i];
        if (!R.hit) return std::nullopt;
        // Pieces on which the data is one smooth cubic of s, with one tag and one region.
        events_.clear();
        events_.push_back(R.enter);
        events_.push_back(R.exit);
        for (int a = 0; a < 3; ++a) {
            if (!V.slotOfVoxel.empty())
                for (int c = 1; c < V.dims[a]; ++c)
                    addPlane(R, a, -V.halfExtent[a] + c * V.spacing[a]);
            for (int c = 0; c < V.dims[a]; ++c)
                addPlane(R, a, -V.halfExtent[a] + (c + 0.5) * V.spacing[a]);
        }
        addInside(R, R.clipEnter);
        addInside(R, R.clipExit);
        std::sort(events_.begin(), events_.end());
        for (std::size_t e = 0; e + 1 < events_.size(); ++e) {
            const double s0 = events_[e], s1 = events_[e + 1];
            if (!(s1 > s0)) continue;
            const double mid = 0.5 * (s0 + s1);
            const double m = V.opacity[R.region(mid)];
            if (m == 0.0) continue;
            const PreparedTransferFunction& tf =
                V.transferFunctions[std::size_t(V.slotAt(R.localAt(mid)))];
            auto visible = [&](double s) {
                const double v = tf.normalise(V.sample(R.localAt(s)));
                const double A = std::clamp(tf.alpha(v), 0.0, kMaxOpacity);
                return 1.0 - std::pow(1.0 - A, m) >= threshold;
            };
            if (visible(s0)) return s0;
            const long n = stepCount(s1 - s0, R.step / 8.0, 0);
            double a = s0;
            for (long j = 1; j <= n; ++j) {
                double b = j == n ? s1 : s0 + (s1 - s0) * double(j) / double(n);
                if (!visible(b)) {
                    a = b;
                    continue;
                }
                const double tolerance = 1e-9 * R.step;
                while (b - a > tolerance) {
                    const double c = 0.5 * (a + b);
                    (visible(c) ? b : a) = c;
                }
                return b;
            }
        }
        return std::nullopt;
    }

private:
    // Where the DVR integrand may jump or kink: the ray is cut there so that each piece is
    // smooth and has one transfer function, BoxClip region and brick per volume.
    void dvrEvents(std::size_t i) {
        const PreparedVolume& V = volumes_[i];
        const VolumeOnRay& R = rays_[i];
        events_.push_back(R.enter);
        events_.push_back(R.exit);
        for (int a = 0; a < 3; ++a) {
            for (int b = 1; b < V.bricks[a]; ++b) // empty-space bricks
                addPlane(R, a, -V.halfExtent[a] + double(b * V.brickSize) * V.spacing[a]);
            if (!V.slotOfVoxel.empty()) // tag cells
                for (int c = 1; c < V.dims[a]; ++c)
                    addPlane(R, a, -V.halfExtent[a] + c * V.spacing[a]);
            for (int c = 0; c < V.dims[a]; ++c) // trilinear kinks: the field is cubic between
                addPlane(R, a, -V.halfExtent[a] + (c + 0.5) * V.spacing[a]);
        }
        addInside(R, R.clipEnter);
        addInside(R, R.clipExit);
        if (V.hasPlaneOpacity && R.depthRate != 0.0)
            for (const auto& p : V.planeOpacity.points()) {
                const double depth = V.depthNear + p.x * (V.depthFar - V.depthNear);
                addInside(R, (depth - R.depth0) / R.depthRate);
            }
    }

    void addPlane(const VolumeOnRay& R, int axis, double local) {
        if (R.dir[axis] != 0.0) addInside(R, (local - R.origin[axis]) / R.dir[axis]);
    }
    void addInside(const VolumeOnRay& R, double s) {
        if (s > R.enter && s < R.exit) events_.push_back(s);
    }

    void integratePiece(double s0, double s1, int level, glm::dvec3& light, double& T) {
        const double mid = 0.5 * (s0 + s1);
        active_.clear();
        double step = kInfinity;
        for (std::size_t i = 0; i < volumes_.size(); ++i) {
            const PreparedVolume& V = volumes_[i];
            const VolumeOnRay& R = rays_[i];
            if (!R.hit || V.mode != VolumeRenderMode::DVR || mid < R.enter || mid > R.exit)
                continue;
            const glm::dvec3 p = R.localAt(mid);
            const int region = R.region(mid);
            if (!V.mayEmitAt(p) || V.opacity[region] == 0.0) continue; // tau == 0 exactly
            const PiecewiseLinear::Line m = V.hasPlaneOpacity
                                                ? V.planeOpacity.lineAt(R.depthFraction(V, mid))
                                                : PiecewiseLinear::Line{1.0, 0.0};
            active_.push_back({i, V.slotAt(p), region, m});
            step = std::min(step, R.step);
        }
        if (active_.empty()) return;

        const long n = stepCount(s1 - s0, step, level);
        const double ds = (s1 - s0) / double(n);
        dataAt(s0, dataA_);
        double a = s0;
        for (long j = 1; j <= n; ++j) {
            const double b = j == n ? s1 : s0 + double(j) * ds;
            dataAt(b, dataB_);
            integrateStep(a, b, light, T);
            if (T < kStopTransmittance) return;
            std::swap(dataA_, dataB_);
            a = b;
        }
    }

    /// The interpolated data value of every active volume at s.
    void dataAt(double s, std::vector<double>& out) const {
        out.resize(active_.size());
        for (std::size_t k = 0; k < active_.size(); ++k)
            out[k] = volumes_[active_[k].index].sample(rays_[active_[k].index].localAt(s));
    }

    /// One step from a (data in dataA_) to b (dataB_). Where an active volume's data crosses a
    /// breakpoint of its TF inside the step, the step is split there first, so that every
    /// sub-step is smooth. dataA_ is overwritten.
    void integrateStep(double a, double b, glm::dvec3& light, double& T) {
        for (int split = 0; split < 64; ++split) {
            double cut = b, cutValue = 0.0;
            std::size_t cutVolume = active_.size();
            for (std::size_t k = 0; k < active_.size(); ++k) {
                const double d0 = dataA_[k], d1 = dataB_[k];
                if (d0 == d1) continue;
                const auto& breaks = transferFunction(k).breaks;
                for (double c : breaks) {
                    if (!((c > d0 && c < d1) || (c < d0 && c > d1))) continue;
                    const double s = crossing(k, a, b, d0 - c, d1 - c, c);
                    if (s < cut) {
                        cut = s;
                        cutValue = c;
                        cutVolume = k;
                    }
                }
            }
            if (cutVolume == active_.size()) break;
            dataAt(cut, dataCut_);
            dataCut_[cutVolume] = cutValue; // exactly on the breakpoint: no crossing left there
            homogeneousStep(a, cut, dataA_, dataCut_, light, T);
            a = cut;
            std::swap(dataA_, dataCut_);
        }
        homogeneousStep(a, b, dataA_, dataB_, light, T);
    }

    /// Where active volume k's data equals c between a and b (f = data - c changes sign):
    /// regula falsi with the Illinois modification, on the smooth cubic of one cell.
    double crossing(std::size_t k, double a, double b, double fa, double fb, double c) const {
        const PreparedVolume& V = volumes_[active_[k].index];
        const VolumeOnRay& R = rays_[active_[k].index];
        const double width = b - a;
        int kept = 0; // which end stayed twice in a row: halve its value (Illinois)
        for (int it = 0; it < 100 && b - a > 1e-12 * width; ++it) {
            double s = (a * fb - b * fa) / (fb - fa);
            if (!(s > a && s < b)) s = 0.5 * (a + b);
            const double f = V.sample(R.localAt(s)) - c;
            if (f == 0.0) return s;
            if ((f < 0.0) == (fa < 0.0)) {
                a = s;
                fa = f;
                if (kept == -1) fb *= 0.5;
                kept = -1;
            } else {
                b = s;
                fb = f;
                if (kept == 1) fa *= 0.5;
                kept = 1;
            }
        }
        return 0.5 * (a + b);
    }

    const PreparedTransferFunction& transferFunction(std::size_t k) const {
        return volumes_[active_[k].index].transferFunctions[std::size_t(active_[k].slot)];
    }

    /// tau = -ln(1 - min(A, 1 - 1e-6)) / L0 times the modifiers, per world length, and the
    /// emitted colour, of active volume k at s with data d, on the TF pieces `lines` holds.
    struct Optics {
        double tau;
        glm::dvec3 color;
    };
    Optics optics(std::size_t k, double s, double v, const PiecewiseLinear::Line lines[4]) const {
        const ActiveVolume& act = active_[k];
        const PreparedVolume& V = volumes_[act.index];
        const VolumeOnRay& R = rays_[act.index];
        const double A = std::clamp(lines[3](v), 0.0, kMaxOpacity);
        double tau = A > 0.0 ? -std::log1p(-A) / V.L0 : 0.0;
        tau *= V.opacity[act.region];
        if (V.hasPlaneOpacity) tau *= std::max(0.0, act.planeOpacity(R.depthFraction(V, s)));
        tau *= R.scale; // per local length -> per world length
        const glm::dvec3 C =
            glm::clamp(glm::dvec3(lines[0](v), lines[1](v), lines[2](v)), 0.0, 1.0);
        const double w = V.blendWeight[act.region];
        return {tau, C * (1.0 - w) + V.blendColor[act.region] * w};
    }

    /// A step with no breakpoint inside: each TF channel is one straight line over it, taken
    /// where the step's middle data value lies (so a step's end on a jump takes this side).
    /// Volumes add their extinctions; the colour is weighted by each one's share of it.
    void homogeneousStep(double a, double b, const std::vector<double>& d0,
                         const std::vector<double>& d1, glm::dvec3& light, double& T) const {
        const double ds = b - a;
        if (!(ds > 0.0)) return;
        double tauA = 0.0, tauB = 0.0;
        glm::dvec3 weightedA(0.0), weightedB(0.0), plainA(0.0), plainB(0.0);
        for (std::size_t k = 0; k < active_.size(); ++k) {
            const PreparedTransferFunction& tf = transferFunction(k);
            const double vMid = tf.normalise(0.5 * (d0[k] + d1[k]));
            const PiecewiseLinear::Line lines[4] = {tf.red.lineAt(vMid), tf.green.lineAt(vMid),
                                                    tf.blue.lineAt(vMid), tf.alpha.lineAt(vMid)};
            // An empty data range is a step at lo: v is constant on each side of it.
            const bool step = tf.hi == tf.lo;
            const Optics oa = optics(k, a, step ? vMid : tf.normalise(d0[k]), lines);
            const Optics ob = optics(k, b, step ? vMid : tf.normalise(d1[k]), lines);
            tauA += oa.tau;
            tauB += ob.tau;
            weightedA += oa.tau * oa.color;
            weightedB += ob.tau * ob.color;
            plainA += oa.color;
            plainB += ob.color;
        }
        // Where nothing absorbs, the colour still matters to the step's interpolation.
        const double count = double(active_.size());
        const glm::dvec3 CA = tauA > 0.0 ? weightedA / tauA : plainA / count;
        const glm::dvec3 CB = tauB > 0.0 ? weightedB / tauB : plainB / count;
        // Trapezoidal optical depth; emission of a homogeneous step with linear colour.
        const double D = 0.5 * (tauA + tauB) * ds;
        if (D > 0.0) {
            const double absorbed = -std::expm1(-D); // 1 - e^-D
            light += T * absorbed * (CA + (CB - CA) * meanEmissionFraction(D));
            T *= 1.0 - absorbed;
        }
    }

    // MIP/MINIP/AVERAGE of volume i: v is sampled on every voxel-centre plane (where the
    // trilinear field has its kinks, so axis-aligned extremes are hit exactly) and in steps.
    void projectionLayer(std::size_t i, int level) {
        const PreparedVolume& V = volumes_[i];
        const VolumeOnRay& R = rays_[i];
        events_.clear(); // reused: the DVR events are collected after all layers
        events_.push_back(R.enter);
        events_.push_back(R.exit);
        for (int a = 0; a < 3; ++a) {
            for (int c = 0; c < V.dims[a]; ++c)
                addPlane(R, a, -V.halfExtent[a] + (c + 0.5) * V.spacing[a]);
            if (!V.slotOfVoxel.empty())
                for (int c = 1; c < V.dims[a]; ++c)
                    addPlane(R, a, -V.halfExtent[a] + c * V.spacing[a]);
        }
        addInside(R, R.clipEnter);
        addInside(R, R.clipExit);
        std::sort(events_.begin(), events_.end());

        const bool wantMax = V.mode == VolumeRenderMode::MIP;
        double best = wantMax ? -kInfinity : kInfinity;
        int bestSlot = 0, bestRegion = 0;
        double first = kInfinity, sum = 0.0, length = 0.0;
        for (std::size_t e = 0; e + 1 < events_.size(); ++e) {
            const double s0 = events_[e], s1 = events_[e + 1];
            if (!(s1 > s0)) continue;
            const double mid = 0.5 * (s0 + s1);
            const int region = R.region(mid);
            if (V.opacity[region] == 0.0) continue; // BoxClip removes this part
            first = std::min(first, s0);
            const int slot = V.slotAt(R.localAt(mid));
            const PreparedTransferFunction& tf = V.transferFunctions[std::size_t(slot)];
            const long n = stepCount(s1 - s0, R.step, level);
            const double ds = (s1 - s0) / double(n);
            double previous = 0.0;
            for (long j = 0; j <= n; ++j) {
                const double s = j == n ? s1 : s0 + double(j) * ds;
                const double v = tf.normalise(V.sample(R.localAt(s)));
                if (V.mode == VolumeRenderMode::AVERAGE) {
                    if (j > 0) sum += 0.5 * (previous + v) * ds;
                    previous = v;
                } else if (wantMax ? v > best : v < best) {
                    best = v;
                    bestSlot = slot;
                    bestRegion = region;
                }
            }
            length += s1 - s0;
        }
        if (first == kInfinity) return; // all of it removed

        double v = best;
        int slot = bestSlot;
        double weight = V.blendWeight[bestRegion];
        if (V.mode == VolumeRenderMode::AVERAGE) {
            v = sum / length;
            slot = 0; // the mean is mapped through the default transfer function
            weight = 0.0;
        }
        const PreparedTransferFunction& tf = V.transferFunctions[std::size_t(slot)];
        const double A = tf.alpha(v);
        const glm::dvec3 C = tf.color(v) * (1.0 - weight) + V.blendColor[bestRegion] * weight;
        layers_.push_back({first, C * A, A});
    }

    const std::vector<PreparedVolume>& volumes_;
    const CameraFrame& frame_;
    std::vector<VolumeOnRay> rays_;
    std::vector<double> events_;
    std::vector<Layer> layers_;
    std::vector<ActiveVolume> active_;
    std::vector<double> dataA_, dataB_, dataCut_;
};

double maxDifference(const TraceResult& a, const TraceResult& b) {
    const glm::dvec3 d = glm::abs(a.rgb - b.rgb);
    return std::max({d.x, d.y, d.z, std::abs(a.transmittance - b.transmittance)});
}

void checkOptions(const RayCastOptions& o) {
    if (!std::isfinite(o.step) || o.step < 0.0) throw Error("ray caster step must be >= 0");
    if (!(o.tolerance > 0.0)) throw Error("ray caster tolerance must be > 0");
    if (o.maxHalvings < 1 || o.maxHalvings > 30)
        throw Error("ray caster maxHalvings must be in 1..30");
    if (o.brickSize < 1) throw Error("ray caster brickSize must be >= 1");
    if (o.threads < 0) throw Error("ray caster threads must be >= 0");
}

void checkPerPixel(std::size_t size, std::size_t pixels, const char* what) {
    if (size != 0 && size != pixels)
        throw Error(std::string(what) + " has " + std::to_string(size) +
                    " entries; expected 0 or width*height = " + std::to_string(pixels));
}

} // namespace

ReferenceRayCaster::ReferenceRayCaster(RayCastOptions options) : options_(options) {
    checkOptions(options_);
}

Ray ReferenceRayCaster::pixelRay(const RayCastCamera& camera, int x, int y) {
    const PixelRay r = makePixelRay(makeFrame(camera), x, y);
    return {r.origin, r.dir};
}

double ReferenceRayCaster::rayDistanceFromWindowDepth(const RayCastCamera& camera, int x, int y,
                                                      double windowDepth) {
    if (!(windowDepth < 1.0)) return kInfinity;
    const CameraFrame frame = makeFrame(camera);
    const PixelRay ray = makePixelRay(frame, x, y);
    const glm::dvec2 ndc = pixelCentreNdc(frame, x, y);
    const glm::dvec3 p = unproject(frame, ndc.x, ndc.y, 2.0 * windowDepth - 1.0);
    return glm::dot(p - ray.origin, ray.dir);
}

std::optional<double> ReferenceRayCaster::firstVisibleDistance(const RayCastVolume& volume,
                                                               const Ray& ray, double nearDistance,
                                                               double farDistance,
                                                               double threshold) {
    const double length = glm::length(ray.direction);
    if (!(length > 0.0) || !std::isfinite(length)) return std::nullopt;
    CameraFrame frame; // only planeOpacity's depths use it, and picking leaves them out
    frame.eye = ray.origin;
    frame.forward = ray.direction / length;
    const std::vector<PreparedVolume> volumes = {
        prepareVolume(volume, frame, RayCastOptions{}, 0, false)};
    PixelRay pixel;
    pixel.origin = ray.origin;
    pixel.dir = frame.forward;
    pixel.start = std::max(nearDistance, 0.0);
    pixel.end = farDistance;
    RayTracer tracer(volumes, frame);
    if (!tracer.setup(pixel, kInfinity)) return std::nullopt;
    return tracer.firstVisible(0, threshold);
}

RayCastResult ReferenceRayCaster::render(const RayCastScene& scene) const {
    const CameraFrame frame = makeFrame(scene.camera);
    const std::size_t pixels = std::size_t(frame.width) * std::size_t(frame.height);
    checkPerPixel(scene.behind.backgroundPixels.size(), pixels, "backgroundPixels");
    checkPerPixel(scene.behind.opaqueDistance.size(), pixels, "opaqueDistance");

    std::vector<PreparedVolume> volumes;
    volumes.reserve(scene.volumes.size());
    for (std::size_t i = 0; i < scene.volumes.size(); ++i)
        volumes.push_back(prepareVolume(scene.volumes[i], frame, options_, i));

    RayCastResult result;
    result.image = Image(frame.width, frame.height);
    result.errorBound = options_.adaptive ? 0.0 : kInfinity;

    std::atomic<int> nextRow{0};
    std::mutex merge;
    std::exception_ptr failure;
    auto work = [&]() {
        try {
            RayTracer tracer(volumes, frame);
            double worstDifference = 0.0;
            int finest = 0;
            bool converged = true;
            for (int y = nextRow++; y < frame.height; y = nextRow++) {
                for (int x = 0; x < frame.width; ++x) {
                    const std::size_t p = std::size_t(y) * std::size_t(frame.width) + x;
                    const glm::dvec3 behind = scene.behind.backgroundPixels.empty()
                                                  ? scene.behind.background
                                                  : scene.behind.backgroundPixels[p];
                    const double opaque = scene.behind.opaqueDistance.empty()
                                              ? kInfinity
                                              : scene.behind.opaqueDistance[p];
                    TraceResult pixel{behind, 1.0};
                    if (tracer.setup(makePixelRay(frame, x, y), opaque)) {
                        pixel = tracer.trace(behind, 0);
                        if (options_.adaptive) {
                            // Halve the step until two successive results agree to the
                            // tolerance AND the comparison before agreed to 4x it, as second-order
                            // convergence predicts: one accidental agreement of two coarse
                            // results is not enough to stop.
                            int level = 1;
                            TraceResult finer = tracer.trace(behind, level);
                            double before = kInfinity;
                            double difference = maxDifference(pixel, finer);
                            auto settled = [&] {
                                return difference <= options_.tolerance &&
                                       before <= 4.0 * options_.tolerance;
                            };
                            while (!settled() && level < options_.maxHalvings) {
                                pixel = finer;
                                finer = tracer.trace(behind, ++level);
                                before = difference;
                                difference = maxDifference(pixel, finer);
                            }
                            pixel = finer;
                            worstDifference = std::max(worstDifference, difference);
                            finest = std::max(finest, level);
                            converged = converged && settled();
                        }
                    }
                    result.image.at(x, y) =
                        glm::vec4(glm::vec3(pixel.rgb), float(1.0 - pixel.transmittance));
                }
            }
            std::lock_guard lock(merge);
            if (options_.adaptive) {
                result.errorBound = std::max(result.errorBound, worstDifference);
                result.maxHalvingsUsed = std::max(result.maxHalvingsUsed, finest);
                result.converged = result.converged && converged;
            }
        } catch (...) {
            std::lock_guard lock(merge);
            if (!failure) failure = std::current_exception();
            nextRow = frame.height; // the others stop too
        }
    };

    int threads = options_.threads > 0 ? options_.threads
                                       : int(std::max(1u, std::thread::hardware_concurrency()));
    threads = std::min(threads, frame.height);
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t)
        pool.emplace_back(work);
    work();
    for (auto& t : pool)
        t.join();
    if (failure) std::rethrow_exception(failure);
    return result;
}

} // namespace volsg
