// The Volume slicer's GL work of a frame: program, uniforms, textures, brick draws, composite.
#include <volsg/slicing/SliceDraw.h>

#include <algorithm>
#include <string>
#include <vector>

#include <volsg/core/Error.h>
#include <volsg/render/RenderTarget.h>
#include <volsg/render/ShapeRenderer.h>

namespace volsg::slicing {

namespace {

/// Inventor's default environment: white ambient light of intensity 0.2 (as shapes use).
constexpr float kAmbientIntensity = 0.2f;

/// BoxClip's opacity multipliers and colour blends per region ([0] outside, [1] inside), which
/// the composite of the projection modes applies too; nothing changes without a BoxClip.
struct RegionLook {
    glm::vec2 opacity{1.0f};
    glm::vec2 weight{0.0f};
    glm::vec3 color[2] = {glm::vec3(1.0f), glm::vec3(1.0f)};
};

void uploadVertices(VolumeTextures& v) {
    if (!v.vertexBuffer) {
        v.vertexBuffer = Buffer(GL_ARRAY_BUFFER);
        v.vertexArray = VertexArray::create();
        v.vertexArray.setAttribute(0, v.vertexBuffer, 3);
    }
    v.vertexBuffer.setData(v.vertices, GL_STREAM_DRAW);
}

/// The uniforms of this volume and frame: view, grid, data format, planes and sampling (and
/// binds the empty-cell flags when they are read).
void setFrameUniforms(const Program& program, const VolumeTextures& v, const VolumeGrid& grid,
                      const RenderView& view, const SlicingSettings& settings,
                      const SlicePlan& plan) {
    const LocalView& local = plan.local;
    const glm::dmat4& modelView = local.modelView;
    const PlaneLayout& layout = plan.layout;
    program.set("uModelView", glm::mat4(modelView));
    program.set("uProjection", glm::mat4(view.projection));
    program.set("uHalfExtent", glm::vec3(local.halfExtent));
    program.set("uInvSpacing", glm::vec3(1.0 / grid.spacing()));
    program.set("uVoxelCount", glm::vec3(grid.dimensions()));
    program.set("uDataScale", v.format.scale);
    program.set("uDataOffset", v.format.offset);
    program.set("uEyeLocal", glm::vec3(local.eyeToLocal * glm::dvec4(0.0, 0.0, 0.0, 1.0)));
    program.set("uViewDirLocal",
                glm::vec3(glm::normalize(local.eyeToLocal3 * glm::dvec3(0.0, 0.0, -1.0))));
    // Eye depth is -z in eye coordinates: an affine function of the local point.
    program.set("uDepthPlane",
                glm::vec4(-modelView[0][2], -modelView[1][2], -modelView[2][2], -modelView[3][2]));
    program.set("uOrthographic", view.orthographic ? 1 : 0);
    program.set("uPlaneSpacing", float(layout.spacing));
    program.set("uSlabSamples", plan.method.slabSamples);
    program.set("uMipPeaks", settings.mipPeaks ? 1 : 0);
    program.set("uRefinePeaks", settings.refinePeaks ? 1 : 0);
    program.set("uSkipCells", plan.method.skipCells ? 1 : 0);
    if (plan.method.skipCells) {
        program.set("uCellScale", 1.0f / float(EmptyCells::kCellSize));
        v.cellTexture.bind(kCellsUnit);
    }
    program.set("uLayoutNear", float(layout.nearDepth));
    program.set("uFacePass", 0);
    program.set("uInvL0", float(1.0 / local.L0));
    program.set("uNear", float(local.clipDepth.x));
    program.set("uFar", float(local.clipDepth.y));
    program.set("uHasPlaneOpacity", plan.method.hasPlaneOpacity ? 1 : 0);
    program.set("uBoxNear", float(local.boxDepth.x));
    program.set("uBoxFar", float(std::max(local.boxDepth.y, local.boxDepth.x + 1e-12)));

    program.set("uClipPlaneCount", int(plan.clipPlanes.size()));
    if (!plan.clipPlanes.empty()) {
        std::vector<glm::vec4> planes(plan.clipPlanes.begin(), plan.clipPlanes.end());
        program.set("uClipPlanes", planes.data(), int(planes.size()));
    }
}

/// The BoxClip's uniforms (in the volume's local coordinates) and its look per region.
RegionLook setBoxClipUniforms(const Program& program, const RayCastVolume& volume) {
    RegionLook look;
    program.set("uHasBoxClip", volume.boxClip ? 1 : 0);
    if (volume.boxClip) {
        const RayCastBoxClip& b = *volume.boxClip;
        const glm::dmat4 localToBox =
            b.model ? glm::inverse(*b.model) * volume.model : glm::dmat4(1.0);
        program.set("uLocalToBox", glm::mat4(localToBox));
        program.set("uBoxMin", glm::vec3(glm::min(b.origin, b.origin + b.extent)));
        program.set("uBoxMax", glm::vec3(glm::max(b.origin, b.origin + b.extent)));
        look.opacity = {float(std::max(0.0, b.outsideOpacity)),
                        float(std::max(0.0, b.insideOpacity))};
        look.weight = {float(std::clamp(b.outsideColorWeight, 0.0, 1.0)),
                       float(std::clamp(b.insideColorWeight, 0.0, 1.0))};
        look.color[0] = glm::vec3(b.outsideColor);
        look.color[1] = glm::vec3(b.insideColor);
    }
    program.set("uRegionOpacity", look.opacity);
    program.set("uRegionWeight", look.weight);
    program.set("uRegionColor", look.color, 2);
    return look;
}

/// MIP/MINIP: the mask of the key's low bits that carry row * 2 + region (none without tags
/// or BoxClip).
GLuint infoMaskOf(int tableRows, bool tagsOrBoxClip) {
    int infoBits = 0;
    if (tagsOrBoxClip)
        while ((1 << infoBits) < 2 * tableRows)
            ++infoBits;
    return (1u << infoBits) - 1u;
}

/// Lighting: the lights (at most kMaxLights, else Error), the model's normal matrix and the
/// Material's specular terms.
void setLightUniforms(const Program& program, std::span<const SceneLight> lights,
                      const SlicingSettings& settings, const glm::dmat4& model,
                      const RenderView& view) {
    if (lights.size() > std::size_t(kMaxLights))
        throw Error(std::to_string(lights.size()) + " lights are in scope of a Volume; at most " +
                    std::to_string(kMaxLights) + " light it");
    std::vector<glm::vec4> vectors;
    std::vector<glm::vec3> colors;
    for (const SceneLight& l : lights) {
        vectors.push_back(l.vector);
        colors.push_back(l.color);
    }
    program.set("uModel", glm::mat4(model));
    program.set("uNormalMatrix", glm::mat3(glm::transpose(glm::inverse(glm::dmat3(model)))));
    program.set("uViewer", glm::vec4(view.viewer));
    program.set("uLightCount", int(lights.size()));
    if (!lights.empty()) {
        program.set("uLightVector", vectors.data(), int(vectors.size()));
        program.set("uLightColor", colors.data(), int(colors.size()));
    }
    program.set("uAmbient", kAmbientIntensity);
    program.set("uSpecular", settings.specular);
    program.set("uShininess", settings.shininess * 128.0f);
}

/// Binds the tables the program samples, and the copy of the opaque depth: opaque geometry
/// (drawn by the shape renderer in the opaque pass) ends rays. Without any, the copy and the
/// reads are skipped.
void bindTables(FrameContext& frame, SliceShared& shared, const VolumeTextures& v,
                const SliceMethod& method, const Program& program) {
    const bool hasOpaque = frame.shapes.drawsLastFrame() > 0;
    program.set("uHasOpaqueDepth", hasOpaque ? 1 : 0);
    if (hasOpaque) {
        shared.copyOpaqueDepth(frame.target);
        shared.opaqueDepth.bind(kOpaqueDepthUnit);
    }
    v.tableTexture.bind(kTableUnit);
    if (method.lean) v.tableRowTexture.bind(kTableRowUnit);
    if (method.tagged) v.tagRowTexture.bind(kTagRowUnit);
    if (method.preIntegrated) {
        v.preIntegrationTexture.bind(kPreIntegratedUnit);
        program.set("uPreRows", int(v.preIntegration.size()));
    }
    if (method.hasPlaneOpacity) v.planeOpacityTexture.bind(kPlaneOpacityUnit);
}

/// Projection modes gather into their own target (cleared, with its blending), then
/// composite once; DVR blends straight into the frame's target.
void beginProjection(FrameContext& frame, SliceShared& shared, Mode mode) {
    if (mode == kMip || mode == kMinip) {
        shared.beginProjection(frame.target, 0, mode == kMip ? 0.0f : 4.0f);
        glBlendEquation(mode == kMip ? GL_MAX : GL_MIN);
    } else if (mode == kAverage) {
        shared.beginProjection(frame.target, 1, 0.0f);
        glBlendFunc(GL_ONE, GL_ONE);
    }
}

/// One brick's draws: its slices (whole, or row by row, each row with its own box), then
/// its bounding faces.
/// The box whose plane points a draw keeps: `lo`..`hi` within this process's part (sort-last;
/// the whole box otherwise). Neighbouring parts clamp to the same double, so they share it.
void setOwnBox(const Program& program, const glm::dvec3& lo, const glm::dvec3& hi,
               const SlicePlan& plan) {
    program.set("uOwnMin", glm::vec3(glm::max(lo, plan.partMin)));
    program.set("uOwnMax", glm::vec3(glm::min(hi, plan.partMax)));
}

void drawBrick(const BrickState& s, const Brick& b, const Program& program, const SlicePlan& plan) {
    program.set("uTexOrigin", glm::vec3(b.firstVoxel));
    program.set("uTexSize", glm::vec3(b.voxelCount));
    // The whole brick (b is), also under sort-last: every process's fragments are the ones a
    // single process draws; unless the process holds only its part (slabsEndAtPart).
    const glm::dvec3 half = plan.local.halfExtent;
    glm::dvec3 slabMin = plan.slabsEndAtBricks ? b.boxMin : -half;
    glm::dvec3 slabMax = plan.slabsEndAtBricks ? b.boxMax : half;
    if (plan.slabsEndAtBricks && plan.slabsEndAtPart) { // the part's faces too
        slabMin = glm::max(slabMin, plan.partMin);
        slabMax = glm::min(slabMax, plan.partMax);
    }
    program.set("uSlabMin", glm::vec3(slabMin));
    program.set("uSlabMax", glm::vec3(slabMax));
    if (b.levelSpacing.x > 0.0) { // a paged brick: its level's voxels
        program.set("uInvSpacing", glm::vec3(1.0 / b.levelSpacing));
        program.set("uVoxelCount", glm::vec3(b.levelDimensions));
    }
    if (s.rows.empty()) {
        setOwnBox(program, b.boxMin, b.boxMax, plan);
        glDrawArrays(GL_TRIANGLES, s.first, s.count);
    } else {
        for (std::size_t r = 0; r < s.rows.size(); ++r) {
            if (s.rowCount[r] == 0) continue;
            setOwnBox(program, s.rows[r].boxMin, s.rows[r].boxMax, plan);
            glDrawArrays(GL_TRIANGLES, s.rowFirst[r], s.rowCount[r]);
        }
        setOwnBox(program, b.boxMin, b.boxMax, plan); // the faces: the whole brick
    }
    if (s.faceCount > 0) {
        // No ray has both plane and face fragments, so this order is as good as any.
        program.set("uFacePass", 1);
        glDrawArrays(GL_TRIANGLES, s.faceFirst, s.faceCount);
        program.set("uFacePass", 0);
    }
}

/// The bricks with geometry, back to front, each made resident (uploaded, perhaps evicting
/// others) just before its draws.
void drawBricks(VolumeTextures& v, const Program& program, std::uint64_t budget, bool tagged,
                const SlicePlan& plan, SlicingStats& drawn) {
    v.vertexArray.bind();
    for (const int i : v.order) {
        BrickState& s = v.bricks[std::size_t(i)];
        if (s.count == 0 && s.faceCount == 0) continue;
        makeResident(v, std::size_t(i), budget, tagged);
        s.data.bind(kDataUnit);
        if (tagged) s.tags.bind(kTagUnit);
        drawBrick(s, v.layout.bricks()[std::size_t(i)], program, plan);
        ++drawn.bricksDrawn;
    }
}

/// MIP, MINIP, AVERAGE: the projection target over the frame's target, in one pass.
void composite(FrameContext& frame, SliceShared& shared, Mode mode, const RegionLook& regions,
               GLuint infoMask) {
    frame.target.bind();
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    const Program& program = shared.compositeProgram(mode);
    program.use();
    glUniform1ui(program.uniformLocation("uInfoMask"), infoMask);
    program.set("uRegionColor", regions.color, 2);
    program.set("uRegionWeight", regions.weight);
    shared.projected[mode == kAverage ? 1 : 0].bind(kProjectedUnit);
    if (!shared.emptyVertexArray) shared.emptyVertexArray = VertexArray::create();
    shared.emptyVertexArray.bind();
    glDisable(GL_DEPTH_TEST);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEnable(GL_DEPTH_TEST);
}

} // namespace

void drawSlices(FrameContext& frame, SliceShared& shared, VolumeTextures& v,
                const RayCastVolume& volume, std::span<const SceneLight> lights,
                const SlicingSettings& settings, const SlicePlan& plan, SlicingStats& drawn) {
    const SliceMethod& m = plan.method;
    uploadVertices(v);
    const Program& program =
        shared.sliceProgram(m.mode, m.tagged, m.lighting, m.preIntegrated, m.lean, m.leanPeaks);
    program.use();
    setFrameUniforms(program, v, *volume.data, frame.view, settings, plan);
    const RegionLook regions = setBoxClipUniforms(program, volume);
    const GLuint infoMask = infoMaskOf(v.table.rows(), m.tagged || volume.boxClip);
    glUniform1ui(program.uniformLocation("uInfoMask"), infoMask);
    if (m.lighting) setLightUniforms(program, lights, settings, volume.model, frame.view);
    bindTables(frame, shared, v, m, program);
    beginProjection(frame, shared, m.mode);
    drawBricks(v, program, settings.textureBudget, m.tagged, plan, drawn);
    if (m.mode != kDvr) composite(frame, shared, m.mode, regions, infoMask);
    VertexArray::unbind();
    glActiveTexture(GL_TEXTURE0);
}

} // namespace volsg::slicing
