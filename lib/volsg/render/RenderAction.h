#pragma once
// The traversal that draws: one per pass, with the camera, the target and the per-node caches.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/actions/Action.h>
#include <volsg/render/NodeCache.h>

namespace volsg {

class RenderTarget;
class ShapeRenderer;

/// The passes of one frame, in order (DESIGN.md "Rendering is passes"). The Renderer sets this
/// GL state before each, and a node that changes it restores it:
/// - Opaque: depth test GL_LESS, depth writes on, blending off. Opaque shapes draw here.
/// - Volume: depth test GL_LESS against the opaque depth, depth writes off, blending on with
///   premultiplied colour (GL_ONE, GL_ONE_MINUS_SRC_ALPHA). Volume nodes draw here.
/// - Transparent: depth test GL_LESS, depth writes off, blending GL_SRC_ALPHA,
///   GL_ONE_MINUS_SRC_ALPHA. Shapes with a Material transparency > 0 queue themselves and are
///   drawn back to front (by the view depth of their centre) at the end of the pass.
/// Face culling is off in every pass (lighting is two-sided).
enum class RenderPass { Opaque, Volume, Transparent };

/// The camera of a frame, in world coordinates.
struct RenderView {
    glm::dmat4 view{1.0};       ///< world to eye
    glm::dmat4 projection{1.0}; ///< eye to clip
    int width = 1, height = 1;  ///< viewport in pixels
    /// Where the viewer is: the eye position (w = 1, perspective) or the direction towards
    /// the viewer (w = 0, orthographic).
    glm::dvec4 viewer{0.0, 0.0, 1.0, 0.0};
    bool orthographic = false;
    /// No light is on anywhere in the scene: shapes are lit by a headlight, a directional
    /// light of intensity 1 along the view direction (as Inventor's viewers do).
    bool headlight = false;
};

/// A light as shaders use it, in world coordinates.
struct SceneLight {
    glm::vec4 vector{0.0f, 0.0f, 1.0f,
                     0.0f}; ///< position (w = 1) or direction to the light (w = 0)
    glm::vec3 color{1.0f};  ///< intensity * colour
};

class RenderAction : public Action {
public:
    RenderAction(NodeCache& cache, ShapeRenderer& shapes, RenderTarget& target,
                 const RenderView& view, bool interactive);

    RenderPass pass() const { return pass_; }
    void setPass(RenderPass pass) { pass_ = pass; }
    /// The user is moving the view: volumes use their fast settings.
    bool isInteractive() const { return interactive_; }
    /// While interactive: the factor on the volumes' interactive plane count
    /// (RenderOptions::interactivePlaneScale).
    double interactivePlaneScale() const { return interactivePlaneScale_; }
    void setInteractivePlaneScale(double scale) { interactivePlaneScale_ = scale; }

    const RenderView& view() const { return view_; }
    const glm::dmat4& viewMatrix() const { return view_.view; }
    const glm::dmat4& projectionMatrix() const { return view_.projection; }
    glm::ivec2 viewportSize() const { return {view_.width, view_.height}; }

    /// GPU data a node keeps across frames, per (node, T, key): see NodeCache. A Volume node
    /// keeps its bricks with `action.cache<VolumeTextures>(*this)`.
    template <class T> T& cache(const Node& node, std::uint64_t key = 0) {
        return cache_.get<T>(node, key);
    }
    ShapeRenderer& shapeRenderer() { return shapes_; }
    /// The float colour + depth target being drawn into (bound during the passes).
    RenderTarget& target() { return target_; }

    /// The lights in scope at the current node (plus the headlight when the scene has no
    /// light), in world coordinates. Fills `out` (cleared first) to reuse its memory.
    void lightsInScope(std::vector<SceneLight>& out) const;
    /// The ClipPlanes in scope as world planes (a, b, c, d), keeping a*x + b*y + c*z >= d.
    void clipPlanesInScope(std::vector<glm::dvec4>& out) const;

protected:
    void dispatch(Node& node) override;

private:
    NodeCache& cache_;
    ShapeRenderer& shapes_;
    RenderTarget& target_;
    RenderView view_;
    bool interactive_;
    double interactivePlaneScale_ = 1.0;
    RenderPass pass_ = RenderPass::Opaque;
};

} // namespace volsg
