#pragma once
// Draws a GltfAsset's instanced primitives in the render passes, PBR-shaded with the scene's
// Inventor lights.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/gl/Program.h>
#include <volsg/render/FrameContext.h>
#include <volsg/render/ShapeRenderer.h>

namespace volsg {

struct GltfAsset;
struct GltfMaterial;
class GltfGpuAsset;
struct GltfGpuPrimitive;
class Texture;

/// A BoxClip as a glTF model sees it: the box [min, max] in coordinates that `boxFromWorld`
/// maps world points to, and the opacity multipliers inside and outside it.
struct GltfBoxClip {
    glm::mat4 boxFromWorld{1.0f};
    glm::vec3 min{0.0f}, max{0.0f};
    float insideOpacity = 1.0f, outsideOpacity = 1.0f;
};

/// What a glTF model's surroundings do to it, gathered by the traversal from the state.
struct GltfLook {
    glm::dmat4 model{1.0};
    glm::vec3 extraEmissive{0.0f}; ///< an Inventor Material's emissiveColor
    float transparency = 0.0f;     ///< an Inventor Material's transparency
    std::optional<GltfBoxClip> boxClip;
    std::span<const SceneLight> lights;     ///< in scope (with the headlight), world
    std::span<const glm::dvec4> clipPlanes; ///< world (a, b, c, d) keeping ax+by+cz >= d
};

/// One per GL context (RenderCache::shared): the glTF program and its draws.
///
/// Passes: OPAQUE and MASK primitives draw in the Opaque pass with depth writes, so volumes
/// drawn later stop at them per pixel; BLEND primitives (and every primitive when the Inventor
/// Material in scope has a transparency > 0, or a BoxClip in scope has an opacity strictly
/// between 0 and 1) queue with the transparent shapes and are drawn back to front by the eye
/// depth of each primitive's box centre, after the volumes. So a BLEND mesh inside a volume
/// is composited over the whole volume, not at its depth within it, and two intersecting BLEND
/// primitives are sorted as wholes, not per pixel: the limits of one sorted pass without
/// per-pixel lists.
///
/// Shading (linear values; base colour and emissive textures are sRGB and decoded to linear):
///   base     = baseColorFactor * baseColorTexture * COLOR_0
///   metallic = metallicFactor * texture.b, roughness = roughnessFactor * texture.g, a = r^2
///   N        = the normal map in glTF's tangent frame (TANGENT, else one from the derivatives
///              of position and UV); flat normals without NORMAL; flipped on back faces
///   colour   = emissive + 0.2 * base * occlusion
///            + sum over lights of pi * BRDF * max(N.L, 0) * intensity * colour
///   BRDF     = (1 - F) * base * (1 - metallic) / pi + F * D * Vis, with GGX D,
///              height-correlated Smith Vis, Schlick F from F0 = mix(0.04, base, metallic).
/// The approximation where Inventor and glTF differ: Inventor lights have no physical units,
/// so a light's intensity * colour is taken as the radiance scale of a punctual light, times pi
/// so that a light facing a rough white dielectric gives about its base colour, as
/// Inventor's Lambert term does; point lights do not fall off with distance (Inventor's
/// default); there is no image-based lighting, only Inventor's constant 0.2 ambient (times
/// the base colour and the occlusion texture); with no light on in the scene, the headlight.
/// KHR_materials_unlit, points and lines show the base colour alone. An Inventor Material
/// in scope adds its emissiveColor and multiplies alpha by 1 - transparency; its other
/// colours do not apply (the glTF material is the surface). ClipPlanes in scope clip as for
/// shapes; a BoxClip in scope removes the parts where its opacity is 0 and scales alpha
/// elsewhere. Single-sided primitives have their back faces culled (mirroring transforms
/// keep the right front face).
class GltfRenderer {
public:
    GltfRenderer(); ///< compiles the program; the context must be current
    GltfRenderer(const GltfRenderer&) = delete;
    GltfRenderer& operator=(const GltfRenderer&) = delete;

    /// The renderer of the frame's context (created on first use).
    static GltfRenderer& of(FrameContext& frame);

    /// Draws (Opaque pass) or queues (Transparent pass) the asset's primitives that belong to
    /// the current pass, as `look` says. Throws Error for more lights or clip planes than it
    /// can draw.
    void submit(const FrameContext& frame, const GltfAsset& asset, const GltfGpuAsset& gpu,
                const GltfLook& look);

private:
    static constexpr int kMaxClipPlanes = ShapeRenderer::kMaxClipPlanes;

    /// What every primitive of one node's render shares: state gathered once.
    struct NodeState {
        SurfaceScope scope;
        glm::vec3 extraEmissive{0.0f};
        float alphaScale = 1.0f;
        bool boxClip = false;
        glm::mat4 boxFromWorld{1.0f};
        glm::vec3 boxMin{0.0f}, boxMax{0.0f};
        float boxInside = 1.0f, boxOutside = 1.0f;
        bool forceBlend = false; ///< Inventor transparency or a partial BoxClip opacity
    };
    struct DrawItem {
        const GltfGpuPrimitive* gpu = nullptr;
        const GltfMaterial* material = nullptr;
        std::array<const Texture*, 5> textures{}; ///< base, metal-rough, normal, occl., emissive
        glm::mat4 model{1.0f};
        glm::mat3 normalMatrix{1.0f};
        bool mirrored = false; ///< negative determinant: the front face winds clockwise
        bool blend = false;
    };

    void draw(ShapeRenderer& shapes, const NodeState& node, const DrawItem& item);

    Program program_;
    SurfaceScope::Locations scopeLocations_{};
    int maxClipPlanes_ = 8;
    RenderView view_;
};

} // namespace volsg
