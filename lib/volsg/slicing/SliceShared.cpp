// The Volume slicer's GL resources per context: program variants, projection target, depth copy.
#include <volsg/slicing/SliceShared.h>

#include <algorithm>
#include <string>
#include <utility>

#include <volsg/gl/Shader.h>
#include <volsg/render/FrameContext.h>
#include <volsg/render/RenderTarget.h>
#include <volsg/slicing/PreIntegrationTable.h>
#include <volsg/slicing/SliceShaders.h>
#include <volsg/slicing/TransferTable.h>

namespace volsg::slicing {

namespace {

std::string prelude(int mode, bool tagged, bool lighting, bool preIntegrated, bool lean = false,
                    bool peaks = false) {
    std::string s = "#version 330 core\n#define MODE " + std::to_string(mode) + "\n";
    if (lean) s += "#define LEAN\n";
    if (peaks) s += "#define PEAKS\n";
    if (tagged) s += "#define TAGGED\n";
    if (lighting) s += "#define LIGHTING\n";
    if (preIntegrated) s += "#define PREINTEGRATED\n";
    s += "#define ENTRIES " + std::to_string(TransferTable::kEntries) + "\n";
    s += "#define PRE_SIZE " + std::to_string(PreIntegrationTable::kSize) + "\n";
    s += "#define PLANE_OPACITY_SIZE " + std::to_string(kPlaneOpacitySize) + "\n";
    s += "#define MAX_CLIP_PLANES " + std::to_string(kMaxClipPlanes) + "\n";
    s += "#define MAX_LIGHTS " + std::to_string(kMaxLights) + "\n";
    return s;
}

void setSamplers(const Program& p) {
    p.use();
    p.set("uData", int(kDataUnit));
    p.set("uTags", int(kTagUnit));
    p.set("uTagRows", int(kTagRowUnit));
    p.set("uTable", int(kTableUnit));
    p.set("uPreIntegrated", int(kPreIntegratedUnit));
    p.set("uPlaneOpacity", int(kPlaneOpacityUnit));
    p.set("uProjected", int(kProjectedUnit));
    p.set("uOpaqueDepth", int(kOpaqueDepthUnit));
    p.set("uCells", int(kCellsUnit));
    p.set("uTableRow", int(kTableRowUnit));
}

} // namespace

Mode modeOf(VolumeRenderMode m) {
    switch (m) {
    case VolumeRenderMode::MIP:
        return kMip;
    case VolumeRenderMode::MINIP:
        return kMinip;
    case VolumeRenderMode::AVERAGE:
        return kAverage;
    case VolumeRenderMode::DVR:
        break;
    }
    return kDvr;
}

const Program& SliceShared::sliceProgram(int mode, bool tagged, bool lighting, bool preIntegrated,
                                         bool lean, bool peaks) {
    const int key = mode | (tagged ? 4 : 0) | (lighting ? 8 : 0) | (preIntegrated ? 16 : 0) |
                    (lean ? 32 : 0) | (peaks ? 64 : 0);
    auto it = slicePrograms.find(key);
    if (it != slicePrograms.end()) return it->second;
    const std::string head = prelude(mode, tagged, lighting, preIntegrated, lean, peaks);
    const Shader vertex(GL_VERTEX_SHADER, head + shaders::sliceVertex, "volume slice");
    const Shader fragment(GL_FRAGMENT_SHADER, head + shaders::sliceCommon + shaders::sliceFragment,
                          "volume slice");
    Program p({&vertex, &fragment}, "volume slice");
    setSamplers(p);
    return slicePrograms.emplace(key, std::move(p)).first->second;
}

const Program& SliceShared::compositeProgram(int mode) {
    auto it = compositePrograms.find(mode);
    if (it != compositePrograms.end()) return it->second;
    const std::string head = prelude(mode, false, false, false);
    const Shader vertex(GL_VERTEX_SHADER, head + shaders::compositeVertex, "volume composite");
    const Shader fragment(GL_FRAGMENT_SHADER,
                          head + shaders::sliceCommon + shaders::compositeFragment,
                          "volume composite");
    Program p({&vertex, &fragment}, "volume composite");
    setSamplers(p);
    return compositePrograms.emplace(mode, std::move(p)).first->second;
}

void SliceShared::copyOpaqueDepth(RenderTarget& target) {
    activateUploadUnit();
    const glm::ivec2 size(target.width(), target.height());
    if (!opaqueDepthFramebuffer) {
        opaqueDepthFramebuffer = Framebuffer::create();
        opaqueDepth = Texture(GL_TEXTURE_2D);
        opaqueDepth.setFilter(GL_NEAREST, GL_NEAREST);
    }
    if (opaqueDepthSize != size) {
        opaqueDepth.image2D(GL_DEPTH_COMPONENT32F, size.x, size.y, GL_DEPTH_COMPONENT, GL_FLOAT,
                            nullptr);
        opaqueDepthFramebuffer.attach(GL_DEPTH_ATTACHMENT, opaqueDepth);
        glDrawBuffer(GL_NONE);
        glReadBuffer(GL_NONE);
        opaqueDepthFramebuffer.requireComplete("volume opaque-depth copy");
        opaqueDepthSize = size;
    }
    target.framebuffer().bind(GL_READ_FRAMEBUFFER);
    opaqueDepthFramebuffer.bind(GL_DRAW_FRAMEBUFFER);
    glBlitFramebuffer(0, 0, size.x, size.y, 0, 0, size.x, size.y, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    target.bind();
}

void SliceShared::beginProjection(RenderTarget& target, int which, float clearValue) {
    activateUploadUnit();
    const glm::ivec2 size(target.width(), target.height());
    bool reattach = false;
    if (!projectionFramebuffer) projectionFramebuffer = Framebuffer::create();
    if (!projected[which]) {
        projected[which] = Texture(GL_TEXTURE_2D);
        projected[which].setFilter(GL_NEAREST, GL_NEAREST);
    }
    if (projectedSize[which] != size) {
        projected[which].image2D(which == 0 ? GL_R32F : GL_RG32F, size.x, size.y,
                                 which == 0 ? GL_RED : GL_RG, GL_FLOAT, nullptr);
        projectedSize[which] = size;
        reattach = true;
    }
    projectionFramebuffer.attach(GL_COLOR_ATTACHMENT0, projected[which]);
    if (reattach || attachedDepth != target.depthTexture().id()) {
        projectionFramebuffer.attach(GL_DEPTH_ATTACHMENT, target.depthTexture());
        attachedDepth = target.depthTexture().id();
    }
    projectionFramebuffer.requireComplete("volume projection target");
    projectionFramebuffer.bind();
    glClearColor(clearValue, clearValue, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
}

SliceShared& sliceSharedOf(FrameContext& frame) {
    activateUploadUnit();
    SliceShared& shared = frame.cache.shared<SliceShared>();
    if (shared.driverMax3DTextureSize == 0)
        glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &shared.driverMax3DTextureSize);
    // RenderDebug can lower the limit, to test bricking as a smaller GL would need it.
    shared.max3DTextureSize = shared.driverMax3DTextureSize;
    if (frame.debug.max3DTextureSize > 0)
        shared.max3DTextureSize = std::min(shared.max3DTextureSize, frame.debug.max3DTextureSize);
    shared.max3DTextureSize = std::max(shared.max3DTextureSize, 2);
    return shared;
}

} // namespace volsg::slicing
