#pragma once
// What a GL engine needs to draw into the frame being rendered: the pass, the camera, the
// target, the per-context caches and the shape renderer. Traversals (RenderAction, above the
// node types) fill it; engines in lib/ read it and know nothing of nodes.

#include <cstddef>
#include <cstdint>
#include <functional>

#include <glm/glm.hpp>

#include <volsg/render/RenderCache.h>

namespace volsg {

class RenderTarget;
class ShapeRenderer;
struct Image;
struct RenderRecording;

/// The passes of one frame, in order (docs/SCENE-FORMAT.md section 4.8). The Renderer sets
/// this GL state before each, and whatever changes it restores it:
/// - Opaque: depth test GL_LESS, depth writes on, blending off. Opaque shapes draw here.
/// - Volume: depth test GL_LESS against the opaque depth, depth writes off, blending on with
///   premultiplied colour (GL_ONE, GL_ONE_MINUS_SRC_ALPHA). Volumes draw here.
/// - Transparent: depth test GL_LESS, depth writes off, blending GL_SRC_ALPHA,
///   GL_ONE_MINUS_SRC_ALPHA. Shapes with a Material transparency > 0 queue themselves and are
///   drawn back to front (by the view depth of their centre) at the end of the pass.
/// Face culling is off in every pass (shapes under SOLID ShapeHints turn it on for their draw).
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
    /// A spot light (positions only): the direction it points, the cosine of its cut-off
    /// angle (below -1 for lights without a cone) and the exponent of its fall-off.
    glm::vec3 spotDirection{0.0f, 0.0f, -1.0f};
    float spotCosCutOff = -2.0f;
    float spotExponent = 0.0f;
};

/// Switches that turn an optimisation off, to measure what it saves (volsg-bench) or to
/// exercise a fallback in tests. The defaults are what users get.
struct RenderDebug {
    /// Volume: skip the 8^3 cells the transfer function shows nothing of (EmptyCells).
    bool skipEmptyCells = true;
    /// Volume: stage a VolumeSeries' next step in a pixel unpack buffer while this one shows.
    bool textureStaging = true;
    /// Volume: bricks no larger than this per side (0: the driver's GL_MAX_3D_TEXTURE_SIZE);
    /// only ever lowers the driver's limit, to test bricking at small sizes.
    int max3DTextureSize = 0;
    /// ShearWarpVolume: the widest vector kernels this CPU runs (false: the scalar ones).
    bool vectorKernels = true;
    /// Frames without volumes or sections draw into an 8-bit target even when the caller
    /// reads float pixels (by default only where the output keeps 8 bits: RenderOptions).
    bool byteTarget = false;
    /// Separators whose subgraph does not change replay what they drew (render caches).
    bool renderCaching = true;
    /// Separators with a valid render cache whose box lies outside the view are not drawn.
    bool renderCulling = true;
    /// Opaque shapes are drawn batched: instanced draws grouped by state (ShapeRenderer).
    bool batchShapes = true;
    /// Spheres, cones and cylinders a few pixels wide are drawn from coarser tessellations
    /// within kShapeDetailPixels of their surface (ShapeDetail.h).
    bool shapeDetail = true;
    /// Where shapes sum their lights: per vertex where that matches per fragment within
    /// kVertexLightingTolerance (Automatic, VertexLighting.h), or always in one of the two.
    enum class Lighting { Automatic, PerFragment, PerVertex };
    Lighting shapeLighting = Lighting::Automatic;
    /// A frame the caller reads back whose only drawing is images rendered on the CPU
    /// (ShearWarpVolume) is composited on the CPU: no GL clear, composite and read-back.
    bool cpuFrames = true;
};

/// Sort-last rendering across processes (lib/volsg/sortlast/README.md): this process draws
/// part `part` of `parts` of every Volume (a k-d split of its bricks) and the parts are
/// composited afterwards. parts == 1: the whole volume, as always.
struct VolumePartition {
    int part = 0;
    int parts = 1;
    /// The process holds only its part's voxels and a ghost layer (viewer/OwnPartLoading):
    /// its slabs end at the part's faces as at brick seams, and an error target's choice is
    /// made on its part and agreed with the others (fromSmallest).
    bool ownDataOnly = false;
    /// A collective (each process calls it the same number of times in a frame): every
    /// process passes a key and `count` values and receives the values of the process with
    /// the smallest key (the lowest rank among equals). For what the processes must agree on
    /// but decide from their own parts: a paged volume's finest drawn level, an error
    /// target's costliest choice. Unset: the process's own values stand.
    std::function<void(double key, double* values, int count)> fromSmallest;
    double smallest(double value) const {
        if (fromSmallest) fromSmallest(value, &value, 1);
        return value;
    }
};

/// The frame being drawn, as engines see it.
struct FrameContext {
    RenderCache& cache;
    ShapeRenderer& shapes;
    RenderTarget& target;
    RenderView view;
    RenderPass pass = RenderPass::Opaque;
    /// The user is moving the view: volumes use their fast settings.
    bool interactive = false;
    /// While interactive: the factor on the volumes' interactive plane count, in (0, 1].
    double interactivePlaneScale = 1.0;
    RenderDebug debug;
    /// Volume nodes drawn so far in this frame, every USE counted (limits::maxVolumeInstances).
    std::uint64_t volumeInstances = 0;
    /// Set by the render methods of volumes and sections (in every pass) when they find one:
    /// the frame needs the float target (an 8-bit one would quantise their compositing).
    bool floatTargetNeeded = false;
    /// Which render this is (from 1, per process; 0: render caches are not used, as in an
    /// Annotation's own traversal): a Separator's cache checked in this render's opaque pass
    /// serves its other passes.
    std::uint64_t renderSerial = 0;
    /// The render caches being recorded (innermost), or null (nodes/volsg/render/RenderCaching.h).
    RenderRecording* recording = nullptr;
    /// Shapes replayed from render caches in this render (all passes).
    std::size_t replayedShapes = 0;
    /// Separators left out in this render because their cached bounds lie outside the view.
    std::size_t culledSeparators = 0;
    /// Shapes drawn from a coarser tessellation in this render (ShapeDetail.h).
    std::size_t coarserShapes = 0;
    /// Screen-text characters laid out so far in this frame (limits::maxFrameTextGlyphs).
    std::uint64_t textGlyphs = 0;
    /// Which part of the volumes this process draws (sort-last; parts 1: all of them).
    VolumePartition partition{};
    /// A frame drawn on the CPU (RenderDebug::cpuFrames): no GL target; images rendered on the
    /// CPU are composited into this one, which holds the background. A node that would draw
    /// with GL sets `needsGl` instead, and the frame is drawn again on GL.
    Image* cpuImage = nullptr;
    bool needsGl = false;
};

} // namespace volsg
