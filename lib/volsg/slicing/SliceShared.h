#pragma once
// The Volume slicer's GL resources per context: programs, texture units, projection target.

#include <map>

#include <glm/glm.hpp>

#include <volsg/gl/Framebuffer.h>
#include <volsg/gl/Program.h>
#include <volsg/gl/Texture.h>
#include <volsg/gl/VertexArray.h>
#include <volsg/volume/VolumeModel.h>

namespace volsg {

struct FrameContext;
class RenderTarget;

namespace slicing {

// Limits the shaders are compiled with.
constexpr int kMaxClipPlanes = 32;
constexpr int kMaxLights = 8;
constexpr int kPlaneOpacitySize = 1024;

enum TextureUnit : GLuint {
    kDataUnit = 0,
    kTagUnit = 1,
    kTagRowUnit = 2,
    kTableUnit = 3,
    kPreIntegratedUnit = 4,
    kPlaneOpacityUnit = 5,
    kProjectedUnit = 6,
    kOpaqueDepthUnit = 7,
    kCellsUnit = 8,
    kTableRowUnit = 9,
    /// Active while textures are created or uploaded (Texture binds them to the active unit),
    /// so that no upload replaces a texture bound for drawing.
    kUploadUnit = 15
};

inline void activateUploadUnit() {
    glActiveTexture(GL_TEXTURE0 + kUploadUnit);
}

/// The render mode as the shaders' MODE takes it.
enum Mode { kDvr = 0, kMip = 1, kMinip = 2, kAverage = 3 };

Mode modeOf(VolumeRenderMode m);

/// Per GL context: the program variants and the projection target of MIP/MINIP/AVERAGE.
struct SliceShared {
    std::map<int, Program> slicePrograms;
    std::map<int, Program> compositePrograms;
    VertexArray emptyVertexArray;
    Framebuffer projectionFramebuffer;
    Texture projected[2]; ///< [0] R32F keys (MIP, MINIP), [1] RG32F sums (AVERAGE)
    glm::ivec2 projectedSize[2]{glm::ivec2(0), glm::ivec2(0)};
    GLuint attachedDepth = 0;
    Framebuffer opaqueDepthFramebuffer;
    Texture opaqueDepth;
    glm::ivec2 opaqueDepthSize{0};
    int driverMax3DTextureSize = 0; ///< GL_MAX_3D_TEXTURE_SIZE
    int max3DTextureSize = 0;       ///< what bricks use (RenderDebug may lower it)

    /// `lean`: the variant with only the slab loop of samples that all count alike (see
    /// LEAN in SliceShaders.h), `peaks` its MIP/MINIP loop with the voxel-centre crossings;
    /// the caller decides when that holds.
    const Program& sliceProgram(int mode, bool tagged, bool lighting, bool preIntegrated, bool lean,
                                bool peaks);
    const Program& compositeProgram(int mode);

    /// Copies the opaque pass's depth into a texture the slices may read: sampling the depth
    /// attached to the framebuffer being drawn would be a feedback loop.
    void copyOpaqueDepth(RenderTarget& target);

    /// Binds the projection target (sharing the render target's opaque depth) and clears it.
    void beginProjection(RenderTarget& target, int which, float clearValue);
};

/// The frame's SliceShared, with max3DTextureSize set for this frame (the driver's limit, or
/// lower when RenderDebug asks); leaves the upload unit active.
SliceShared& sliceSharedOf(FrameContext& frame);

} // namespace slicing
} // namespace volsg
