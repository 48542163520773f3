#pragma once
// Render caches of Separators (Inventor's renderCaching AUTO): what a Separator's subgraph drew,
// kept while nothing under it or in the state above it changes, and replayed instead of
// traversing it. The shapes replay into the ShapeRenderer's batches, so caches and uncached
// shapes share instanced draws.

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/actions/ActionMethods.h>
#include <volsg/core/Node.h>
#include <volsg/math/Box3.h>
#include <volsg/render/GpuMesh.h>
#include <volsg/render/ShapeDetail.h>
#include <volsg/render/ShapeRenderer.h>

namespace volsg {

class RenderAction;
class State;

/// One shape as a cache keeps it: its mesh and look, without the lights and clip planes (those
/// in scope where the cache replays, as no Light or ClipPlane is under a cached Separator).
struct ShapeRecord {
    std::shared_ptr<const GpuMesh> mesh;
    std::shared_ptr<const ShapeTexture> texture; ///< keeps look.texturing.texture alive
    ShapeLook look; ///< model: world while recording, relative to the Separator in a cache
    bool transparent = false;
    std::shared_ptr<const ShapeDetail> detail; ///< coarser meshes drawn when small, or null
};

/// A node the cache depends on and its version when recorded. Held, so a node removed from
/// the graph is not freed while a cache still compares its version.
struct CacheDependency {
    ref_ptr<const Node> node;
    std::uint64_t version;
};

/// What the Separators being recorded collect (FrameContext::recording, innermost first).
struct RenderRecording {
    RenderRecording* outer = nullptr;
    std::vector<CacheDependency> dependencies; ///< every node traversed, in traversal order
    std::vector<ShapeRecord> shapes;           ///< models in world coordinates
    bool cacheable = true; ///< nothing under it draws other than shapes, or reads the view
};

/// A Separator's cache (in the RenderCache, per Separator).
struct SeparatorCache {
    bool recorded = false;  ///< dependencies and aboveKey hold a recording
    bool cacheable = false; ///< the recording can replay (else the Separator traverses)
    std::uint64_t aboveKey = 0;
    std::vector<CacheDependency> dependencies;
    std::vector<ShapeRecord> shapes; ///< models relative to the Separator
    Box3 bounds;                     ///< of the shapes' meshes, relative to the Separator
    bool culled = false;             ///< this render's opaque pass found it outside the view
    std::uint64_t validIn = 0;       ///< the render whose opaque pass found it valid
    int invalidRuns = 0;             ///< renders in a row that found it changed
    int skipRecording = 0;           ///< renders left before recording it again (AUTO)
};

/// Notes `node` in the recording being made: its version, and whether its type can be cached.
void noteForCache(RenderRecording& recording, const Node& node);

/// The key of what a cache reads from the state above it: every property node in scope and its
/// version (the model matrix is applied when the cache replays).
std::uint64_t stateAboveKey(const State& state);

} // namespace volsg
