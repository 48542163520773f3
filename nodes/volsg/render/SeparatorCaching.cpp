// Separators keep render caches (RenderCaching.h): in the opaque pass a Separator whose
// dependencies and state above are unchanged replays its shapes into the batches; otherwise it
// traverses its children while recording them, and keeps the recording when everything under
// it can be cached. Its other passes follow what the opaque pass found.
#include <algorithm>
#include <mutex>
#include <unordered_map>

#include <volsg/geometry/MeshKey.h>
#include <volsg/nodes/ClipPlane.h>
#include <volsg/nodes/Light.h>
#include <volsg/nodes/ResetTransform.h>
#include <volsg/nodes/Separator.h>
#include <volsg/render/BuiltinRendering.h>
#include <volsg/render/RenderAction.h>
#include <volsg/render/RenderCaching.h>

namespace volsg {

namespace {

/// Renders in a row that find a cache changed before it stops recording for a while, and the
/// longest while (renders): a Separator edited every frame costs no recording.
constexpr int kInvalidRunsBeforeBackOff = 2;
constexpr int kLongestBackOff = 64;

bool cacheableType(const NodeType& type);

/// Records the Separator's subgraph as it is traversed; on destruction (also by an exception)
/// the recording is unlinked from the frame.
class RecordingScope {
public:
    explicit RecordingScope(FrameContext& frame) : frame_(frame) {
        recording_.outer = frame.recording;
        frame.recording = &recording_;
    }
    ~RecordingScope() { frame_.recording = recording_.outer; }
    RecordingScope(const RecordingScope&) = delete;
    RecordingScope& operator=(const RecordingScope&) = delete;
    RenderRecording& recording() { return recording_; }

private:
    FrameContext& frame_;
    RenderRecording recording_;
};

bool unchanged(const SeparatorCache& cache) {
    // In traversal order: a removed child changes its group's version, which comes before it.
    return std::all_of(cache.dependencies.begin(), cache.dependencies.end(),
                       [](const CacheDependency& d) { return d.node->version() == d.version; });
}

/// Hands what a cache drew (models relative to `entry`) to the recording of an outer Separator.
void passOutward(RenderRecording& outer, const SeparatorCache& cache, const glm::dmat4& entry) {
    outer.dependencies.insert(outer.dependencies.end(), cache.dependencies.begin(),
                              cache.dependencies.end());
    for (const ShapeRecord& r : cache.shapes) {
        ShapeRecord& copy = outer.shapes.emplace_back(r);
        copy.look.model = entry * r.look.model;
    }
}

/// Submits the cache's shapes of this pass with the model, lights and clip planes in scope.
void replay(RenderAction& action, const SeparatorCache& cache, bool transparent) {
    thread_local std::vector<SceneLight> lights;
    thread_local std::vector<glm::dvec4> clipPlanes;
    action.lightsInScope(lights);
    action.clipPlanesInScope(clipPlanes);
    FrameContext& frame = action.frame();
    const glm::dmat4& entry = action.state().modelMatrix();
    for (const ShapeRecord& r : cache.shapes) {
        if (r.transparent != transparent) continue;
        ShapeLook look = r.look;
        look.model = entry * r.look.model;
        look.lights = lights;
        look.clipPlanes = clipPlanes;
        const GpuMesh& mesh = r.detail ? r.detail->chooseFor(frame, look.model, *r.mesh) : *r.mesh;
        frame.shapes.submit(frame, mesh, look);
        ++frame.replayedShapes;
    }
}

/// View-frustum culling (Inventor's renderCulling AUTO, as Coin: with a valid cache's box): the
/// box relative to the Separator, whose corners are all beyond one side of the view volume.
bool outsideView(const RenderAction& action, const Box3& box) {
    if (box.isEmpty()) return true; // draws nothing
    const glm::dmat4 toClip =
        action.projectionMatrix() * action.viewMatrix() * action.state().modelMatrix();
    glm::dvec4 c[8];
    for (int i = 0; i < 8; ++i)
        c[i] = toClip * glm::dvec4((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                                   (i & 4) ? box.max.z : box.min.z, 1.0);
    for (int axis = 0; axis < 3; ++axis)
        for (double side : {-1.0, 1.0}) {
            // Beyond the plane side * x = w (x the clip coordinate of this axis).
            bool allBeyond = true;
            for (const glm::dvec4& p : c)
                allBeyond = allBeyond && side * p[axis] > p.w;
            if (allBeyond) return true;
        }
    return false;
}

/// Traverses the Separator while recording it, and keeps the recording in `cache`.
void record(RenderAction& action, Separator& node, SeparatorCache& cache, std::uint64_t above) {
    FrameContext& frame = action.frame();
    RenderRecording* outer = frame.recording;
    const glm::dmat4 entry = action.state().modelMatrix();
    RecordingScope scope(frame);
    RenderRecording& rec = scope.recording();
    rec.dependencies.push_back({ref_ptr<const Node>(&node), node.version()});
    node.doAction(action);

    cache.recorded = true;
    cache.cacheable = rec.cacheable;
    cache.aboveKey = above;
    cache.validIn = rec.cacheable ? frame.renderSerial : 0;
    if (outer) {
        // The outer recording gets this one as it is (world models).
        outer->cacheable = outer->cacheable && rec.cacheable;
        outer->dependencies.insert(outer->dependencies.end(), rec.dependencies.begin() + 1,
                                   rec.dependencies.end());
        outer->shapes.insert(outer->shapes.end(), rec.shapes.begin(), rec.shapes.end());
    }
    const glm::dmat4 toLocal = glm::inverse(entry);
    for (ShapeRecord& r : rec.shapes)
        r.look.model = toLocal * r.look.model;
    cache.dependencies = std::move(rec.dependencies);
    cache.shapes = rec.cacheable ? std::move(rec.shapes) : std::vector<ShapeRecord>{};
    cache.bounds = Box3{};
    for (const ShapeRecord& r : cache.shapes)
        if (!r.mesh->bounds.isEmpty()) cache.bounds.extendBy(r.mesh->bounds, r.look.model);
}

void renderSeparator(RenderAction& action, Separator& node) {
    FrameContext& frame = action.frame();
    const bool caching = frame.debug.renderCaching && frame.renderSerial != 0 &&
                         node.renderCaching() != Separator::OFF &&
                         &node.type() == &Separator::classType();
    if (!caching) {
        node.doAction(action);
        return;
    }
    SeparatorCache& cache = frame.cache.get<SeparatorCache>(node);
    if (action.pass() != RenderPass::Opaque) {
        // The opaque pass of this render decided: replay (nothing under a cache is a volume),
        // or traverse.
        if (cache.validIn != frame.renderSerial) {
            node.doAction(action);
        } else if (action.pass() == RenderPass::Transparent && !cache.culled) {
            replay(action, cache, true);
        }
        return;
    }
    const std::uint64_t above = stateAboveKey(action.state());
    const bool valid = cache.recorded && cache.aboveKey == above && unchanged(cache);
    if (valid && cache.cacheable) {
        cache.invalidRuns = 0;
        cache.validIn = frame.renderSerial;
        if (frame.recording) passOutward(*frame.recording, cache, action.state().modelMatrix());
        cache.culled = node.renderCulling() != Separator::OFF && frame.debug.renderCulling &&
                       outsideView(action, cache.bounds);
        if (cache.culled)
            ++frame.culledSeparators;
        else
            replay(action, cache, false);
        return;
    }
    cache.validIn = 0;
    if (valid || (cache.recorded && cache.skipRecording > 0)) {
        // Not cacheable and unchanged, or changing every render: traverse without recording
        // (an outer recording still records what is under it).
        if (cache.skipRecording > 0) --cache.skipRecording;
        node.doAction(action);
        return;
    }
    if (cache.recorded && ++cache.invalidRuns >= kInvalidRunsBeforeBackOff)
        cache.skipRecording = std::min(kLongestBackOff, 1 << std::min(cache.invalidRuns, 6));
    record(action, node, cache, above);
}

bool cacheableType(const NodeType& type) {
    const ActionMethods& methods = RenderAction::methods();
    if (methods.hasMethod(type))
        return rendersAsShape(type) || methods.runs(type, &renderSeparator);
    // State work only: all but what lights or clips in world space, or resets the model.
    return !type.isDerivedFrom(Light::classType()) && !type.isDerivedFrom(ClipPlane::classType()) &&
           !type.isDerivedFrom(ResetTransform::classType());
}

} // namespace

void noteForCache(RenderRecording& recording, const Node& node) {
    recording.dependencies.push_back({ref_ptr<const Node>(&node), node.version()});
    if (!recording.cacheable) return;
    static std::mutex mutex;
    static std::unordered_map<const NodeType*, bool> known;
    const NodeType& type = node.type();
    std::lock_guard lock(mutex);
    auto [it, inserted] = known.try_emplace(&type, false);
    if (inserted) it->second = cacheableType(type);
    recording.cacheable = it->second;
}

std::uint64_t stateAboveKey(const State& state) {
    std::uint64_t key = 0x9e3779b97f4a7c15ULL;
    for (const StateEntry& e : state.entries()) {
        key = combineMeshKey(key, reinterpret_cast<std::uintptr_t>(e.node));
        key = combineMeshKey(key, e.node->version());
    }
    return key;
}

void addSeparatorRenderMethods(ActionMethods& methods) {
    methods.add(&renderSeparator);
}

} // namespace volsg
