// The Volume slicer's frame as a list of stages, and the staging of a series' next grid.
#include <volsg/slicing/VolumeSlicer.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include <volsg/core/Error.h>
#include <volsg/render/RenderTarget.h>
#include <volsg/render/ShapeRenderer.h>
#include <volsg/slicing/BrickLayout.h>
#include <volsg/slicing/SliceGeometry.h>
#include <volsg/slicing/SlicePlan.h>
#include <volsg/slicing/SliceShared.h>
#include <volsg/slicing/TextureStaging.h>
#include <volsg/slicing/VolumeTextures.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

using namespace slicing;

namespace {

/// Inventor's default environment: white ambient light of intensity 0.2 (as shapes use).
constexpr float kAmbientIntensity = 0.2f;

void checkVolume(const RayCastVolume& volume) {
    if (!volume.data) throw Error("Volume: no data to render");
    if (volume.tags) {
        if (volume.tags->dimensions() != volume.data->dimensions())
            throw Error("Volume: the tag grid's dimensions differ from the data's");
        if (!volume.tags->isLabelType())
            throw Error("Volume: the tag grid must be UByte or UShort");
    }
}

/// Decides how this frame draws the volume and brings the volume's bricks and tables up to
/// date for that; records the layout in `staging` for a grid staged next.
SliceMethod prepareVolume(VolumeTextures& v, const SliceShared& shared, TextureStaging& staging,
                          const RayCastVolume& volume, const SlicingSettings& settings) {
    SliceMethod m;
    m.mode = modeOf(volume.mode);
    m.lighting = settings.lighting && m.mode == kDvr;
    // Lighting, pre-integration and tag-cell splitting sample up to a voxel (or half a slab)
    // beyond the point drawn: bricks then carry a guard voxel, so seams stay invisible.
    const bool sampleAround = m.lighting || settings.preIntegrated || volume.tags;
    prepareLayout(v, shared, settings.textureBudget, sampleAround ? 1 : 0);
    prepareTable(v, volume, volume.transferKey);
    m.tagged = v.tags && v.table.rows() > 1;
    staging.hasFrame = true; // a grid staged next is laid out as this one
    staging.textureBudget = settings.textureBudget;
    staging.guard = sampleAround ? 1 : 0;
    staging.tagged = m.tagged;
    m.preIntegrated = settings.preIntegrated && m.mode == kDvr && !m.tagged;
    if (m.preIntegrated) preparePreIntegration(v);
    // Empty cells are skipped (rows left out of the geometry, one-sample fragments discarded)
    // where that is exact: DVR samples each part at one point (not pre-integrated, not split at
    // tag cells); MIP of one row (tags would let a skipped sample's row matter). MINIP and
    // AVERAGE see every sample.
    m.skipCells = settings.skipEmptyCells && ((m.mode == kDvr && !m.tagged && !m.preIntegrated) ||
                                              (m.mode == kMip && !m.tagged));
    if (m.skipCells) prepareCells(v, m.mode == kMip ? 1 : 0);
    m.hasPlaneOpacity = m.mode == kDvr && planeOpacityMatters(volume.planeOpacity);
    if (m.hasPlaneOpacity) preparePlaneOpacity(v, volume.planeOpacity);
    prepareFilter(v, settings.nearest);
    m.slabSamples = m.mode != kAverage ? std::clamp(settings.samplesPerPlane, 1, 256) : 1;
    // The lean program when every sample of a slab counts alike (several of them, no tags, no
    // BoxClip; DVR without planeOpacity, lighting or pre-integration; MIP/MINIP without the
    // voxel-centre crossings).
    m.lean = m.slabSamples > 1 && !m.tagged && !volume.boxClip &&
             (m.mode == kDvr ? !m.lighting && !m.preIntegrated && !m.hasPlaneOpacity
                             : (m.mode == kMip || m.mode == kMinip) && !settings.mipPeaks);
    return m;
}

/// The last-frame counters known before anything is cut.
SlicingStats layoutStats(const VolumeTextures& v, const SlicePlan& plan) {
    SlicingStats drawn;
    drawn.bricksTotal = int(v.bricks.size());
    drawn.brickGrid = v.layout.grid();
    drawn.brickTexels = v.layout.largestTexture();
    drawn.planes = plan.layout.count;
    drawn.planeSpacing = plan.layout.spacing;
    drawn.emptyCells = plan.method.skipCells ? v.cells.emptyFraction() : 0.0;
    return drawn;
}

/// After the draws: drops what only this grid's first frame needed, and counts.
void finishFrame(VolumeTextures& v, SlicingStats& drawn) {
    v.staged.reset(); // its bricks are uploaded; skipped (empty) ones upload directly later
    v.spareTextures.clear();
    for (const BrickState& s : v.bricks)
        if (s.resident) ++drawn.bricksResident;
    drawn.textureBytes = v.residentBytes;
    ++v.totals.frames;
    drawn.frames = v.totals.frames;
    drawn.brickUploads = v.totals.brickUploads;
    drawn.uploadedBytes = v.totals.uploadedBytes;
    drawn.transferTableBuilds = v.totals.transferTableBuilds;
    drawn.preIntegrationBuilds = v.totals.preIntegrationBuilds;
    drawn.stagedUploads = v.totals.stagedUploads;
    drawn.refilledTextures = v.totals.refilledTextures;
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

} // namespace

void VolumeSlicer::draw(FrameContext& frame, const Object& owner, const RayCastVolume& volume,
                        std::span<const SceneLight> lights, const SlicingSettings& settings,
                        SlicingStats& stats) {
    if (frame.pass != RenderPass::Volume) return;
    const auto started = std::chrono::steady_clock::now();
    checkVolume(volume);
    SliceShared& shared = sliceSharedOf(frame);
    const std::uint64_t key = textureKeyOf(volume);
    VolumeTextures& v = frame.cache.get<VolumeTextures>(owner, key);
    TextureStaging& staging = frame.cache.get<TextureStaging>(owner);
    adoptGrid(frame.cache, owner, key, v, staging, volume);
    prepareGrid(v, volume);

    SlicePlan plan;
    plan.method = prepareVolume(v, shared, staging, volume, settings);
    plan.local = localView(frame.view, volume.model, *volume.data);
    plan.layout = planeLayout(plan.local, settings, plan.method.slabSamples, frame);
    SlicingStats drawn = layoutStats(v, plan);
    plan.clipPlanes = localClipPlanes(volume);
    plan.rows = planRows(v, plan, settings);
    cutBricks(v, *volume.data, plan, drawn);

    const auto prepared = std::chrono::steady_clock::now();
    drawn.cpuMilliseconds = std::chrono::duration<double, std::milli>(prepared - started).count();
    // The names the draw below takes (until it is split into stages too).
    const Mode mode = plan.method.mode;
    const bool tagged = plan.method.tagged, lighting = plan.method.lighting;
    const bool preIntegrated = plan.method.preIntegrated, skipCells = plan.method.skipCells;
    const bool hasPlaneOpacity = plan.method.hasPlaneOpacity;
    const int slabSamples = plan.method.slabSamples;
    const VolumeGrid& grid = *volume.data;
    const RenderView& view = frame.view;
    const glm::dmat4 model = volume.model;
    const glm::dmat4& modelView = plan.local.modelView;
    const glm::dmat4& eyeToLocal = plan.local.eyeToLocal;
    const glm::dmat3& eyeToLocal3 = plan.local.eyeToLocal3;
    const glm::dvec3& halfExtent = plan.local.halfExtent;
    const glm::dvec2& boxDepth = plan.local.boxDepth;
    const glm::dvec2& clipDepth = plan.local.clipDepth;
    const double L0 = plan.local.L0;
    const PlaneLayout& layout = plan.layout;
    const std::vector<glm::dvec4>& localPlanes = plan.clipPlanes;
    if (!v.vertices.empty()) {
        if (!v.vertexBuffer) {
            v.vertexBuffer = Buffer(GL_ARRAY_BUFFER);
            v.vertexArray = VertexArray::create();
            v.vertexArray.setAttribute(0, v.vertexBuffer, 3);
        }
        v.vertexBuffer.setData(v.vertices, GL_STREAM_DRAW);

        // Uniforms of this volume and frame.
        const Program& program =
            shared.sliceProgram(mode, tagged, lighting, preIntegrated, plan.method.lean);
        program.use();
        program.set("uModelView", glm::mat4(modelView));
        program.set("uProjection", glm::mat4(view.projection));
        program.set("uHalfExtent", glm::vec3(halfExtent));
        program.set("uInvSpacing", glm::vec3(1.0 / grid.spacing()));
        program.set("uVoxelCount", glm::vec3(grid.dimensions()));
        program.set("uDataScale", v.format.scale);
        program.set("uDataOffset", v.format.offset);
        program.set("uEyeLocal", glm::vec3(eyeToLocal * glm::dvec4(0.0, 0.0, 0.0, 1.0)));
        program.set("uViewDirLocal",
                    glm::vec3(glm::normalize(eyeToLocal3 * glm::dvec3(0.0, 0.0, -1.0))));
        // Eye depth is -z in eye coordinates: an affine function of the local point.
        program.set("uDepthPlane", glm::vec4(-modelView[0][2], -modelView[1][2], -modelView[2][2],
                                             -modelView[3][2]));
        program.set("uOrthographic", view.orthographic ? 1 : 0);
        program.set("uPlaneSpacing", float(layout.spacing));
        program.set("uSlabSamples", slabSamples);
        program.set("uMipPeaks", settings.mipPeaks ? 1 : 0);
        program.set("uRefinePeaks", settings.refinePeaks ? 1 : 0);
        program.set("uSkipCells", skipCells ? 1 : 0);
        if (skipCells) {
            program.set("uCellScale", 1.0f / float(EmptyCells::kCellSize));
            v.cellTexture.bind(kCellsUnit);
        }
        program.set("uLayoutNear", float(layout.nearDepth));
        program.set("uFacePass", 0);
        program.set("uInvL0", float(1.0 / L0));
        program.set("uNear", float(clipDepth.x));
        program.set("uFar", float(clipDepth.y));
        program.set("uHasPlaneOpacity", hasPlaneOpacity ? 1 : 0);
        program.set("uBoxNear", float(boxDepth.x));
        program.set("uBoxFar", float(std::max(boxDepth.y, boxDepth.x + 1e-12)));

        program.set("uClipPlaneCount", int(localPlanes.size()));
        if (!localPlanes.empty()) {
            std::vector<glm::vec4> planes(localPlanes.begin(), localPlanes.end());
            program.set("uClipPlanes", planes.data(), int(planes.size()));
        }

        glm::vec2 regionOpacity(1.0f), regionWeight(0.0f);
        glm::vec3 regionColor[2] = {glm::vec3(1.0f), glm::vec3(1.0f)};
        program.set("uHasBoxClip", volume.boxClip ? 1 : 0);
        if (volume.boxClip) {
            const RayCastBoxClip& b = *volume.boxClip;
            const glm::dmat4 localToBox =
                b.model ? glm::inverse(*b.model) * model : glm::dmat4(1.0);
            program.set("uLocalToBox", glm::mat4(localToBox));
            program.set("uBoxMin", glm::vec3(glm::min(b.origin, b.origin + b.extent)));
            program.set("uBoxMax", glm::vec3(glm::max(b.origin, b.origin + b.extent)));
            regionOpacity = {float(std::max(0.0, b.outsideOpacity)),
                             float(std::max(0.0, b.insideOpacity))};
            regionWeight = {float(std::clamp(b.outsideColorWeight, 0.0, 1.0)),
                            float(std::clamp(b.insideColorWeight, 0.0, 1.0))};
            regionColor[0] = glm::vec3(b.outsideColor);
            regionColor[1] = glm::vec3(b.insideColor);
        }
        program.set("uRegionOpacity", regionOpacity);
        program.set("uRegionWeight", regionWeight);
        program.set("uRegionColor", regionColor, 2);

        // MIP/MINIP: the key's low bits carry row * 2 + region.
        int infoBits = 0;
        if (tagged || volume.boxClip)
            while ((1 << infoBits) < 2 * v.table.rows())
                ++infoBits;
        const GLuint infoMask = (1u << infoBits) - 1u;
        glUniform1ui(program.uniformLocation("uInfoMask"), infoMask);

        if (lighting) {
            if (lights.size() > std::size_t(kMaxLights))
                throw Error(std::to_string(lights.size()) +
                            " lights are in scope of a Volume; at most " +
                            std::to_string(kMaxLights) + " light it");
            std::vector<glm::vec4> vectors;
            std::vector<glm::vec3> colors;
            for (const SceneLight& l : lights) {
                vectors.push_back(l.vector);
                colors.push_back(l.color);
            }
            program.set("uModel", glm::mat4(model));
            program.set("uNormalMatrix",
                        glm::mat3(glm::transpose(glm::inverse(glm::dmat3(model)))));
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

        // Opaque geometry (drawn by the shape renderer in the opaque pass) ends rays: the
        // slices read a copy of its depth. Without any, the copy and the reads are skipped.
        const bool hasOpaque = frame.shapes.drawsLastFrame() > 0;
        program.set("uHasOpaqueDepth", hasOpaque ? 1 : 0);
        if (hasOpaque) {
            shared.copyOpaqueDepth(frame.target);
            shared.opaqueDepth.bind(kOpaqueDepthUnit);
        }
        v.tableTexture.bind(kTableUnit);
        if (tagged) v.tagRowTexture.bind(kTagRowUnit);
        if (preIntegrated) v.preIntegrationTexture.bind(kPreIntegratedUnit);
        if (hasPlaneOpacity) v.planeOpacityTexture.bind(kPlaneOpacityUnit);

        // Projection modes gather into their own target, then composite once.
        if (mode == kMip || mode == kMinip) {
            shared.beginProjection(frame.target, 0, mode == kMip ? 0.0f : 4.0f);
            glBlendEquation(mode == kMip ? GL_MAX : GL_MIN);
        } else if (mode == kAverage) {
            shared.beginProjection(frame.target, 1, 0.0f);
            glBlendFunc(GL_ONE, GL_ONE);
        }

        v.vertexArray.bind();
        for (const int i : v.order) {
            BrickState& s = v.bricks[std::size_t(i)];
            if (s.count == 0 && s.faceCount == 0) continue;
            makeResident(v, std::size_t(i), settings.textureBudget, tagged);
            const Brick& b = v.layout.bricks()[std::size_t(i)];
            s.data.bind(kDataUnit);
            if (tagged) s.tags.bind(kTagUnit);
            program.set("uTexOrigin", glm::vec3(b.firstVoxel));
            program.set("uTexSize", glm::vec3(b.voxelCount));
            if (s.rows.empty()) {
                program.set("uOwnMin", glm::vec3(b.boxMin));
                program.set("uOwnMax", glm::vec3(b.boxMax));
                glDrawArrays(GL_TRIANGLES, s.first, s.count);
            } else {
                for (std::size_t r = 0; r < s.rows.size(); ++r) {
                    if (s.rowCount[r] == 0) continue;
                    program.set("uOwnMin", glm::vec3(s.rows[r].boxMin));
                    program.set("uOwnMax", glm::vec3(s.rows[r].boxMax));
                    glDrawArrays(GL_TRIANGLES, s.rowFirst[r], s.rowCount[r]);
                }
                program.set("uOwnMin", glm::vec3(b.boxMin)); // the faces: the whole brick
                program.set("uOwnMax", glm::vec3(b.boxMax));
            }
            if (s.faceCount > 0) {
                // No ray has both plane and face fragments, so this order is as good as any.
                program.set("uFacePass", 1);
                glDrawArrays(GL_TRIANGLES, s.faceFirst, s.faceCount);
                program.set("uFacePass", 0);
            }
            ++drawn.bricksDrawn;
        }

        if (mode != kDvr) {
            frame.target.bind();
            glBlendEquation(GL_FUNC_ADD);
            glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
            const Program& composite = shared.compositeProgram(mode);
            composite.use();
            glUniform1ui(composite.uniformLocation("uInfoMask"), infoMask);
            composite.set("uRegionColor", regionColor, 2);
            composite.set("uRegionWeight", regionWeight);
            shared.projected[mode == kAverage ? 1 : 0].bind(kProjectedUnit);
            if (!shared.emptyVertexArray) shared.emptyVertexArray = VertexArray::create();
            shared.emptyVertexArray.bind();
            glDisable(GL_DEPTH_TEST);
            glDrawArrays(GL_TRIANGLES, 0, 3);
            glEnable(GL_DEPTH_TEST);
        }
        VertexArray::unbind();
        glActiveTexture(GL_TEXTURE0);
    }

    finishFrame(v, drawn);
    drawn.submitMilliseconds = millisecondsSince(prepared);
    stats = drawn;
}

void VolumeSlicer::stage(FrameContext& frame, const Object& owner,
                         const ref_ptr<const VolumeGrid>& data,
                         const ref_ptr<const VolumeGrid>& tags) {
    if (frame.pass != RenderPass::Volume || !data) return;
    if (!frame.debug.textureStaging) return; // the direct upload of every step (volsg-bench)
    TextureStaging& staging = frame.cache.get<TextureStaging>(owner);
    if (!staging.hasFrame) return; // no frame drawn yet: how to lay the grid out is unknown
    const ref_ptr<const VolumeGrid> labels = staging.tagged ? tags : nullptr;
    if (staging.next && staging.next->data() == data.get() && staging.next->tags() == labels.get())
        return;                                                   // staged already
    if (tags && tags->dimensions() != data->dimensions()) return; // drawing it will say why
    if (labels && !labels->isLabelType()) return;
    const SliceShared& shared = frame.cache.shared<SliceShared>();
    const BrickLayout layout(
        data->dimensions(), data->spacing(),
        layoutLimits(*data, tags.get(), shared, staging.textureBudget, staging.guard));
    staging.next.reset(); // one staged grid at a time: its memory before the new one's
    staging.next = std::make_unique<StagedGrid>(data, labels, layout);
    ++staging.stagedGrids;
}

} // namespace volsg
