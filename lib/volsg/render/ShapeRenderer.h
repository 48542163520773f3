#pragma once
// Draws shapes' meshes with Inventor's Phong lighting, textures, draw styles, clip planes,
// environment and transparency.

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/gl/Buffer.h>
#include <volsg/gl/Program.h>
#include <volsg/gl/Texture.h>
#include <volsg/render/FrameContext.h>
#include <volsg/render/ShaderPrelude.h>

namespace volsg {

struct GpuMesh;
struct ImageValue;
struct Mesh;

/// Inventor's SoMaterial values for one shape (its defaults without a Material in scope).
struct SurfaceMaterial {
    glm::vec3 ambient{0.2f}, diffuse{0.8f}, specular{0.0f}, emissive{0.0f};
    float shininess = 0.2f;    ///< 0..1 (times 128 for the exponent)
    float transparency = 0.0f; ///< 0..1
};

/// A texture image on the GPU (per Texture2 node and version, in the RenderCache).
struct ShapeTexture {
    Texture texture;
    bool uploaded = false;
    /// Uploads the texels (1 to 4 components; grey becomes (L, L, L, 1), grey-alpha
    /// (L, L, L, A)) with mipmaps and the wrap modes (true: repeat, false: clamp).
    void upload(const ImageValue& image, bool repeatS, bool repeatT);
};

/// How a shape's texture applies (Inventor's SoTexture2 models), with its coordinates.
struct ShapeTexturing {
    enum class Model { Modulate, Decal, Blend, Replace };
    const ShapeTexture* texture = nullptr; ///< null: untextured
    Model model = Model::Modulate;
    glm::vec3 blendColor{0.0f};
    glm::mat4 matrix{1.0f}; ///< the Texture2Transforms in scope
    bool sphereMap = false; ///< TextureCoordinateEnvironment
};

/// Inventor's SoEnvironment: ambient light, point-light attenuation, fog.
struct ShapeEnvironment {
    glm::vec3 ambient{0.2f};                 ///< ambientIntensity * ambientColor
    glm::vec3 attenuation{0.0f, 0.0f, 1.0f}; ///< squared, linear, constant
    int fogType = 0;                         ///< 0 none, 1 haze, 2 fog, 3 smoke
    glm::vec3 fogColor{1.0f};
    float fogVisibility = 0.0f; ///< 0: the far plane
};

/// What a shape looks like where it is drawn, gathered by the traversal from the state.
struct ShapeLook {
    enum class Style { Filled, Lines, Points, Invisible }; ///< SoDrawStyle
    glm::dmat4 model{1.0};
    SurfaceMaterial material;
    /// Inventor's LightModel BASE_COLOR: unlit, the diffuse (or vertex) colour alone.
    bool baseColorOnly = false;
    Style style = Style::Filled;
    float lineWidth = 1.0f, pointSize = 1.0f; ///< pixels
    /// SoShapeHints with a known vertex ordering and SOLID: back faces are not drawn.
    bool cullBackFaces = false;
    bool clockwise = false; ///< the front faces wind clockwise (SoShapeHints CLOCKWISE)
    /// Coin's rule (SoShapeHintsElement): two-sided lighting only for a known vertex ordering
    /// and an unknown shape type; otherwise a face seen from behind keeps its normal (dark).
    bool twoSidedLighting = false;
    ShapeTexturing texturing;
    ShapeEnvironment environment;
    std::span<const SceneLight> lights;     ///< in scope (with the headlight), world
    std::span<const glm::dvec4> clipPlanes; ///< world (a, b, c, d) keeping ax+by+cz >= d
};

/// One per Renderer (so per GL context): the shape program and the queue of transparent
/// shapes. Shading (linear values, no gamma), per fragment or, where that matches within
/// kVertexLightingTolerance, per vertex (setLighting, VertexLighting.h):
///   colour = emissive + ambient * environment ambient
///          + sum over lights of strength * intensity * colour * (diffuse * max(N.L, 0)
///                                                    + specular * max(N.H, 0)^(shininess*128))
///   alpha  = 1 - transparency
/// then the texture by its model, then fog; strength is 1 for directional lights, the
/// environment's attenuation and the cone for point and spot lights. Vertex colours replace
/// the diffuse colour, N is flipped towards the viewer under two-sided lighting, and H is the half
/// vector to the viewer. Lines and points without normals are unlit, as Coin draws them (its
/// BASE_COLOR light model): the diffuse (or vertex) colour alone.
class ShapeRenderer {
public:
    static constexpr int kMaxLights = kMaxSurfaceLights;
    /// Clip planes are limited by GL_MAX_CLIP_DISTANCES (8 here), and by this.
    static constexpr int kMaxClipPlanes = kMaxSurfaceClipPlanes;

    ShapeRenderer(); ///< compiles the program; the context must be current
    ShapeRenderer(const ShapeRenderer&) = delete;
    ShapeRenderer& operator=(const ShapeRenderer&) = delete;

    /// How many ClipPlanes a shape may have in scope (GL_MAX_CLIP_DISTANCES, at most 16).
    int maxClipPlanes() const { return maxClipPlanes_; }

    /// Puts `mesh` on the GPU into `gpu` (counted in meshUploads()).
    void upload(GpuMesh& gpu, const Mesh& mesh);
    /// Draws `gpu` as `look` says: if it is opaque and this is the Opaque pass, batched (below)
    /// or at once; queued if it is transparent and this is the Transparent pass; not at all
    /// otherwise (nor when its style is INVISIBLE). Throws Error for more clip planes or lights
    /// than it can draw.
    void submit(const FrameContext& frame, const GpuMesh& gpu, const ShapeLook& look);

    /// Batching of opaque shapes (on by default): submit() keeps them, and flushOpaque() draws
    /// them grouped by everything but their model matrix and material (mesh, lights, clip
    /// planes, texture, draw style, ...), one instanced draw per group with the matrices and
    /// materials in a per-instance buffer, each group's shapes front to back. Off: each shape
    /// is drawn when it is submitted (Annotations, whose shapes draw in scene order).
    void setBatching(bool on) { batching_ = on; }
    /// Sort-last (lib/volsg/sortlast/README.md): this process draws only its share of the
    /// opaque shapes, the k-th submitted in a frame's Opaque pass when k % count == index.
    /// Every process traverses the same scene in the same order, so the shares are disjoint
    /// and together the whole; (0, 1), the default, draws all.
    void setShare(int index, int count) {
        shareIndex_ = index;
        shareCount_ = count > 0 ? count : 1;
    }
    /// Counts the next opaque shape (or glTF primitive) and says whether this process draws it.
    bool ownsNextOpaque() {
        const bool mine = opaqueOrdinal_ % std::uint64_t(shareCount_) == std::uint64_t(shareIndex_);
        ++opaqueOrdinal_;
        if (!mine) ++sharedOutLastFrame_;
        return mine;
    }
    /// Opaque shapes submitted in this frame, drawn here or left to other processes.
    std::size_t opaqueShapesLastFrame() const { return std::size_t(opaqueOrdinal_); }
    /// Opaque shapes left to other processes in this frame (setShare).
    std::size_t sharedOutLastFrame() const { return sharedOutLastFrame_; }
    /// Where lights are summed (RenderDebug::shapeLighting; Automatic by default).
    void setLighting(RenderDebug::Lighting lighting) { lighting_ = lighting; }
    /// Draws the opaque shapes batched since the last flush (the Renderer calls it at the end
    /// of the opaque pass).
    void flushOpaque();

    /// Queues a draw that is not a shape's mesh (a glTF BLEND primitive) with the transparent
    /// shapes, sorted with them by `eyeDepth` (eye-space z, more negative = farther). It runs in
    /// drawQueuedTransparent() and may bind any program, VAO and texture; it sets the clip
    /// distances it uses through setClipDistances().
    void queueTransparent(double eyeDepth, std::function<void()> draw);
    /// Enables GL_CLIP_DISTANCE0 .. count-1 and disables the rest, keeping track of them, so
    /// other renderers drawing between shapes (glTF models) leave the state shapes expect.
    void setClipDistances(int count);
    /// Counts a draw made by another renderer (a glTF primitive) in drawsLastFrame(), which
    /// volumes read to know whether opaque geometry is in the depth buffer.
    void countDraw() { ++drawsLastFrame_; }

    /// Per frame: the camera; clears the transparent queue.
    void beginFrame(const RenderView& view);
    /// Per pass: resets the clip-distance switches this class keeps track of.
    void beginPass();
    /// Draws the queued transparent shapes, farthest centre first, and empties the queue.
    void drawQueuedTransparent();
    /// Leaves GL with no program, no VAO and no clip distances enabled.
    void endFrame();

    std::uint64_t meshUploads() const { return meshUploads_; }
    /// Instanced draws made by flushOpaque() in this frame, and the shapes they drew.
    std::size_t batchesLastFrame() const { return batchesLastFrame_; }
    std::size_t batchedShapesLastFrame() const { return batchedShapesLastFrame_; }
    /// Bytes of the per-instance buffer (model matrix and material per batched shape).
    std::size_t instanceBytes() const { return instanceBuffer_.size(); }
    std::uint64_t programBuilds() const { return programBuilds_; }
    std::size_t drawsLastFrame() const { return drawsLastFrame_; }
    /// Shapes lit per vertex in this frame (of all lit shapes submitted).
    std::size_t vertexLitLastFrame() const { return vertexLitLastFrame_; }
    std::size_t litLastFrame() const { return litLastFrame_; }
    /// The bytes the shapes submitted in this frame would take as meshes of their own (the
    /// scene's vertex data, without sharing or instancing).
    std::size_t submittedMeshBytesLastFrame() const { return submittedMeshBytes_; }

private:
    /// Everything one draw needs, captured during traversal (transparent draws happen after).
    struct DrawItem {
        const GpuMesh* mesh = nullptr;
        glm::mat4 model{1.0f};
        glm::mat3 normalMatrix{1.0f};
        glm::vec3 emissive{0.0f}, ambient{0.0f}, diffuse{0.8f}, specular{0.0f};
        float shininess = 0.0f, alpha = 1.0f;
        bool lit = true;
        bool vertexLighting = false; ///< the lights summed per vertex
        bool specularOn = false;     ///< the specular colour is not black (all of a batch's)
        ShapeLook::Style style = ShapeLook::Style::Filled;
        float lineWidth = 1.0f, pointSize = 1.0f;
        bool cull = false, frontClockwise = false, twoSided = false;
        int textureModel = -1; ///< -1: none
        const ShapeTexture* texture = nullptr;
        glm::vec3 blendColor{0.0f};
        glm::mat4 textureMatrix{1.0f};
        bool sphereMap = false;
        ShapeEnvironment environment;
        SurfaceScope scope; ///< no lights when unlit
        std::array<glm::vec4, kMaxLights> spots{};
        std::array<float, kMaxLights> spotExponents{};
        double eyeDepth = 0.0; ///< eye-space z of the bounds' centre (more negative = farther)
        std::function<void()> external; ///< set: a queueTransparent() draw, not a mesh
    };
    struct Locations {
        GLint model, normalMatrix, viewProjection, view, textureMatrix, emissive, ambient, diffuse,
            specular, shininess, alpha, viewer, spot, spotExponent, attenuation, textureModel,
            blendColor, fogType, fogColor, fogVisibility;
        SurfaceScope::Locations scope;
    };
    /// The shape program specialised for one kind of draw (ShapeShaders.h), compiled when
    /// first needed.
    struct Variant {
        Program program;
        Locations at{};
        std::uint64_t frame = 0; ///< the frame whose view uniforms it holds
    };

    /// One batched shape's own values, as the instanced program reads them (locations 4-11).
    struct Instance {
        glm::mat4 model;
        glm::vec4 emissiveShininess, ambient, diffuseAlpha, specular;
    };
    /// What a batch's shapes share, compared bytewise (made with makeBatchKey, which zeroes the
    /// padding): everything a DrawItem has but the model matrix and the material.
    struct BatchKey {
        const GpuMesh* mesh;
        const ShapeTexture* texture;
        int scope; ///< index into scopes_
        int textureModel, style;
        float lineWidth, pointSize;
        std::uint8_t lit, vertexLighting, specularOn, cull, frontClockwise, sphereMap, twoSided;
        glm::vec3 blendColor;
        glm::mat4 textureMatrix;
        glm::vec3 attenuation, fogColor;
        int fogType;
        float fogVisibility;
    };
    struct Batch {
        BatchKey key;
        DrawItem item;                    ///< the first shape's, for the shared uniforms
        std::vector<std::size_t> members; ///< into batched_
    };
    struct Batched {
        Instance instance;
        float depth; ///< eye-space z of the bounds' centre (front first)
    };
    /// Lights and clip planes, interned per frame (shapes mostly share them).
    struct Scope {
        std::vector<SceneLight> lights;
        std::vector<glm::dvec4> clipPlanes;
    };

    void fill(const GpuMesh& gpu, const ShapeLook& look, DrawItem& item);
    void countLighting(const DrawItem& item) {
        litLastFrame_ += item.lit;
        vertexLitLastFrame_ += item.vertexLighting;
    }
    void draw(const DrawItem& item);
    /// Sets the uniforms and GL state of `item` but the model matrix and material (which
    /// `withMaterial` adds) in the program in use, whose uniforms are at `at`.
    void applyState(const Locations& at, const DrawItem& item, bool withMaterial);
    /// Undoes what applyState changed beyond uniforms (culling, polygon mode, widths).
    void restoreState(const DrawItem& item);
    /// Draws the item's mesh (`instances` of it): its primitives, or its polygon outlines
    /// under the LINES draw style when the mesh has them (Mesh::outline).
    static void drawElements(const DrawItem& item, GLsizei instances);
    static bool drawsOutline(const DrawItem& item);
    static bool cullsBackFaces(const GpuMesh& gpu, const ShapeLook& look);
    void batch(const GpuMesh& gpu, const ShapeLook& look);
    int internScope(const ShapeLook& look, bool lit);
    Locations locate(const Program& program) const;
    /// Whether `gpu` drawn as `look` (lit) sums its lights per vertex.
    bool lightsPerVertex(const GpuMesh& gpu, const ShapeLook& look) const;
    /// Puts the program specialised for `item` in use, with this frame's view uniforms, and
    /// says where its uniforms are.
    const Locations& useVariant(const DrawItem& item, bool instanced);

    std::unordered_map<unsigned, Variant> variants_; ///< by their specialisation bits
    std::uint64_t frameSerial_ = 0;
    glm::mat4 viewProjection_{1.0f}, eye_{1.0f};
    glm::vec4 viewer_{0.0f, 0.0f, 1.0f, 0.0f};
    bool batching_ = true;
    RenderDebug::Lighting lighting_ = RenderDebug::Lighting::Automatic;
    std::size_t vertexLitLastFrame_ = 0, litLastFrame_ = 0, submittedMeshBytes_ = 0;
    int shareIndex_ = 0, shareCount_ = 1;
    std::uint64_t opaqueOrdinal_ = 0;
    std::size_t sharedOutLastFrame_ = 0;
    std::uint64_t submittedIndices_ = 0; ///< this frame's, against limits::maxFrameShapeIndices
    std::vector<Scope> scopes_;
    std::vector<Batch> batches_;
    std::unordered_map<std::uint64_t, std::size_t> batchIndex_; ///< key hash -> batches_
    std::vector<Batched> batched_;
    std::vector<Instance> instances_; ///< flushOpaque's upload, kept for its memory
    Buffer instanceBuffer_;
    std::size_t batchesLastFrame_ = 0, batchedShapesLastFrame_ = 0;
    int maxClipPlanes_ = 8;
    int enabledClipPlanes_ = 0;
    RenderView view_;
    std::vector<DrawItem> transparentQueue_;
    std::uint64_t meshUploads_ = 0;
    std::uint64_t programBuilds_ = 0;
    std::size_t drawsLastFrame_ = 0;
};

} // namespace volsg
