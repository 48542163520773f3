#pragma once
// Draws a scene graph into the current GL context: passes for opaque geometry, volumes and
// transparent geometry, into a floating-point target, read back as an Image.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/core/Node.h>
#include <volsg/image/Image.h>
#include <volsg/nodes/Camera.h> // RenderOptions holds a ref_ptr<Camera>
#include <volsg/render/FrameContext.h>

namespace volsg {

struct RenderOptions {
    int width = 512;
    int height = 512;
    glm::vec3 background{0.0f};
    bool interactive = false; ///< the user is moving the view: volumes use their fast settings
    /// While interactive, volumes multiply their interactive plane count by this (in (0, 1]):
    /// the viewer lowers it when interactive frames are still too slow.
    double interactivePlaneScale = 1.0;
    ref_ptr<Camera> camera;  ///< overrides the scene's camera when set (model matrix = identity)
    bool opaqueOnly = false; ///< only the Opaque pass: no volumes, no transparent shapes
    /// Multisample antialiasing of the opaque pass: with samples > 1 it is drawn into a
    /// multisampled float target (at most GL_MAX_SAMPLES, 4 on llvmpipe) whose colour and depth
    /// are resolved into the frame's target before the volumes, which then composite against
    /// the resolved depth; the transparent pass is drawn single-sampled. 0 or 1: off.
    int samples = 0;
    /// The caller keeps 8 bits per channel of the frame (a window, a PNG): a frame without
    /// volumes or sections then draws into an 8-bit target, as Coin's window does, which
    /// loses nothing the output keeps and is cheaper to clear, shade and blend on a software
    /// rasteriser (the colour of each blend is rounded to 1/255 then, as in Coin's). Set by
    /// renderToBoundFramebuffer when the bound framebuffer has 8 bits or fewer per channel.
    bool eightBitOutput = false;
    /// Optimisations switched off, to measure them (volsg-bench) or test fallbacks.
    RenderDebug debug;
    /// Sort-last rendering (lib/volsg/sortlast/README.md): the partial image of this process,
    /// its part of the volumes (`partition`) premultiplied over transparent black. The opaque
    /// pass still draws, so its depth stops the volumes; its colour is cleared to (0, 0, 0, 0)
    /// before the Volume pass; no transparent pass. Always the float target.
    bool volumePartial = false;
    VolumePartition partition{};
    /// Sort-last: this process draws the opaque shapes of its share only
    /// (ShapeRenderer::setShare: the k-th opaque shape when k % count == index).
    int shapeShareIndex = 0, shapeShareCount = 1;
    /// Sort-last, with volumePartial: the window depth of every process's opaque shapes
    /// composited (width * height values, row 0 at the top, 1 where nothing; empty when no
    /// process drew any). The Opaque pass is not drawn; this depth is written instead (and
    /// counted as a draw, as the shapes were) and stops the volumes as the shapes would.
    const std::vector<float>* opaqueDepth = nullptr;
};

/// What a Renderer has done, for tests and the benchmark: a frame where nothing changed
/// uploads no mesh and builds no program.
struct RenderStats {
    std::uint64_t frames = 0;
    std::uint64_t meshUploads = 0;   ///< meshes sent to the GPU since the Renderer was made
    std::uint64_t programBuilds = 0; ///< shader programs compiled and linked since then
    std::size_t cachedEntries = 0;   ///< per-node GPU caches alive after the last frame
    /// The last frame was composited on the CPU (RenderDebug::cpuFrames), not drawn by GL.
    bool cpuFrame = false;
    std::size_t shapeDraws = 0;       ///< shape draw calls in the last frame
    std::size_t opaqueShapes = 0;     ///< opaque shapes (and glTF primitives) of the last frame
    std::size_t sharedOutShapes = 0;  ///< of those, left to other processes (sort-last)
    std::size_t batches = 0;          ///< instanced draws of batched opaque shapes, last frame
    std::size_t batchedShapes = 0;    ///< the shapes those draws drew
    std::size_t replayedShapes = 0;   ///< shapes drawn from Separators' render caches, last frame
    std::size_t culledSeparators = 0; ///< Separators outside the view, not drawn, last frame
    std::size_t coarserShapes = 0;    ///< drawn from a coarser tessellation (ShapeDetail.h)
    std::size_t litShapes = 0;        ///< shapes drawn lit in the last frame
    std::size_t vertexLitShapes = 0;  ///< of those, lit per vertex (VertexLighting.h)
    std::size_t meshBytes = 0;        ///< GPU bytes of the (shared) shape meshes alive
    std::size_t instanceBytes = 0;    ///< GPU bytes of the per-instance buffer
    /// The last frame's shapes' vertex data as if each had its own mesh (what meshBytes and
    /// instanceBytes stand in for).
    std::size_t drawnMeshBytes = 0;
};

/// Holds the GL resources (programs, meshes, targets) of one context across frames. Create
/// and use it with that context current, and destroy it before the context.
///
/// A frame: the camera (RenderOptions::camera, else findOrMakeCamera), a clear to the
/// background (alpha 1), then the passes of RenderPass (opaque shapes, volumes, transparent
/// shapes back to front) into a float RGBA target. Lighting follows Inventor: the lights in
/// scope of each shape, plus 0.2 white ambient; **a scene with no light on at all is lit by a
/// headlight**, a directional light of intensity 1 along the view direction, as Inventor's
/// viewers do. Values are linear (no gamma). GL errors during a frame throw Error.
class Renderer {
public:
    Renderer();
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    /// Renders offscreen and reads the linear float result back (renderFrame, then readImage).
    /// A frame whose only drawing is images rendered on the CPU (ShearWarpVolume) is
    /// composited on the CPU instead, with the same pixels and no GL frame
    /// (RenderDebug::cpuFrames, RenderStats::cpuFrame).
    Image render(Node& root, const RenderOptions& options);
    /// The same into `into`, whose storage is reused when it has the size already (a caller
    /// rendering frame after frame pays no allocation and no page faults for the image).
    void render(Node& root, const RenderOptions& options, Image& into);
    /// Renders offscreen and reads nothing back: the frame stays in the Renderer's target
    /// (readImage, readWindowDepth) until the next one. GL may still be drawing on return.
    void renderFrame(Node& root, const RenderOptions& options);
    /// The last frame's colour as linear floats, row 0 at the top (empty before the first).
    /// After a CPU frame, its image.
    /// From an 8-bit target (RenderTarget) the values are multiples of 1/255.
    Image readImage() const;
    /// The same into `into` (storage reused when it has the size already).
    void readImage(Image& into) const;
    /// Renders into the framebuffer bound now (a window's back buffer), same image; with
    /// RenderOptions::eightBitOutput when that framebuffer keeps at most 8 bits per channel.
    void renderToBoundFramebuffer(Node& root, const RenderOptions& options);

    /// The depth buffer of the last frame in window coordinates ([0,1], 1 where nothing was
    /// drawn), width*height values with row 0 at the top, like the Image. The context must
    /// still be current. Empty before the first frame; all 1 after a CPU frame.
    std::vector<float> readWindowDepth() const;

    /// Several renders that make one displayed frame (the viewer's section views, a stereo
    /// pair): from beginViewGroup() to endViewGroup() the per-node GPU caches keep every entry
    /// any of the renders used, so views that share nodes share their GL resources instead of
    /// freeing them after one view and rebuilding them for the next.
    void beginViewGroup();
    void endViewGroup();

    const RenderStats& stats() const;

    struct Impl;

private:
    std::unique_ptr<Impl> impl_;
};

/// The camera a render of this scene uses: the first Camera in traversal order with the model
/// matrix above it, or, without one, a new camera in its default orientation that views the
/// whole bounding box from +Z (viewAll; model matrix identity): a PerspectiveCamera, or an
/// OrthographicCamera when the scene draws a ShearWarpVolume (parallel projections only).
struct SceneCamera {
    ref_ptr<Camera> camera;
    glm::dmat4 model{1.0};
};
SceneCamera findOrMakeCamera(Node& root, double viewportAspect);

} // namespace volsg
