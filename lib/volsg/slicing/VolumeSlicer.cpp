#include <volsg/slicing/VolumeSlicer.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include <volsg/core/Error.h>
#include <volsg/gl/Buffer.h>
#include <volsg/gl/Framebuffer.h>
#include <volsg/gl/Program.h>
#include <volsg/gl/Texture.h>
#include <volsg/gl/VertexArray.h>
#include <volsg/render/FrameContext.h>
#include <volsg/render/RenderTarget.h>
#include <volsg/render/ShapeRenderer.h>
#include <volsg/slicing/BrickLayout.h>
#include <volsg/slicing/CellRows.h>
#include <volsg/slicing/DataFormat.h>
#include <volsg/slicing/EmptyCells.h>
#include <volsg/slicing/PreIntegrationTable.h>
#include <volsg/slicing/ProxyPlaneCutter.h>
#include <volsg/slicing/SliceShared.h>
#include <volsg/slicing/TextureStaging.h>
#include <volsg/slicing/TransferTable.h>
#include <volsg/slicing/VolumeTextures.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

using namespace slicing;

namespace {

constexpr int kMaxPlanes = 100000;
/// Planes x rows of empty-space cells above which the rows grow (see rowGroup in render).
constexpr double kRowCutBudget = 20000.0;
/// The fewest planes the viewer's interactive plane scale may leave (unless fewer were asked).
constexpr long kMinScaledPlanes = 8;
/// Inventor's default environment: white ambient light of intensity 0.2 (as shapes use).
constexpr float kAmbientIntensity = 0.2f;

/// Eye depths of the camera's near and far planes, from the projection matrix.
glm::dvec2 nearFar(const glm::dmat4& p, bool orthographic) {
    if (orthographic) return {(p[3][2] + 1.0) / p[2][2], (p[3][2] - 1.0) / p[2][2]};
    return {p[3][2] / (p[2][2] - 1.0), p[3][2] / (p[2][2] + 1.0)};
}

/// The faces of brick b that lie on the volume box and face the viewer (at `viewer`, or
/// looking along it when orthographic; local coordinates), as triangles.
void appendFrontFaces(const Brick& b, const glm::ivec3& grid, const glm::dvec3& viewer,
                      bool orthographic, std::vector<glm::vec3>& out) {
    for (int a = 0; a < 3; ++a)
        for (int side = 0; side < 2; ++side) {
            const bool onBoundary = side == 0 ? b.index[a] == 0 : b.index[a] == grid[a] - 1;
            if (!onBoundary) continue;
            const double c = side == 0 ? b.boxMin[a] : b.boxMax[a];
            const bool facing = orthographic ? (side == 0 ? viewer[a] > 0.0 : viewer[a] < 0.0)
                                             : (side == 0 ? viewer[a] < c : viewer[a] > c);
            if (!facing) continue;
            const int u = (a + 1) % 3, w = (a + 2) % 3;
            glm::vec3 corner[4];
            for (int k = 0; k < 4; ++k) {
                glm::dvec3 p;
                p[a] = c;
                p[u] = (k == 1 || k == 2) ? b.boxMax[u] : b.boxMin[u];
                p[w] = k >= 2 ? b.boxMax[w] : b.boxMin[w];
                corner[k] = glm::vec3(p);
            }
            for (const int k : {0, 1, 2, 0, 2, 3})
                out.push_back(corner[k]);
        }
}

void checkVolume(const RayCastVolume& volume) {
    if (!volume.data) throw Error("Volume: no data to render");
    if (volume.tags) {
        if (volume.tags->dimensions() != volume.data->dimensions())
            throw Error("Volume: the tag grid's dimensions differ from the data's");
        if (!volume.tags->isLabelType())
            throw Error("Volume: the tag grid must be UByte or UShort");
    }
}

} // namespace

void VolumeSlicer::draw(FrameContext& frame, const Object& owner, const RayCastVolume& volume,
                        std::span<const SceneLight> lights, const SlicingSettings& settings,
                        SlicingStats& stats) {
    if (frame.pass != RenderPass::Volume) return;
    const std::uint64_t transferKey = volume.transferKey;
    const auto started = std::chrono::steady_clock::now();
    checkVolume(volume);
    const VolumeGrid& grid = *volume.data;
    const Mode mode = modeOf(volume.mode);

    SliceShared& shared = sliceSharedOf(frame);
    const std::uint64_t key = textureKeyOf(volume);
    VolumeTextures& v = frame.cache.get<VolumeTextures>(owner, key);
    TextureStaging& staging = frame.cache.get<TextureStaging>(owner);
    adoptGrid(frame.cache, owner, key, v, staging, volume);
    prepareGrid(v, volume);

    const bool lighting = settings.lighting && mode == kDvr;
    // Lighting, pre-integration and tag-cell splitting sample up to a voxel (or half a slab)
    // beyond the point drawn: bricks then carry a guard voxel, so seams stay invisible.
    const bool sampleAround = lighting || settings.preIntegrated || volume.tags;
    prepareLayout(v, shared, settings.textureBudget, sampleAround ? 1 : 0);
    prepareTable(v, volume, transferKey);
    const bool tagged = v.tags && v.table.rows() > 1;
    staging.hasFrame = true; // a grid staged next is laid out as this one
    staging.textureBudget = settings.textureBudget;
    staging.guard = sampleAround ? 1 : 0;
    staging.tagged = tagged;
    const bool preIntegrated = settings.preIntegrated && mode == kDvr && !tagged;
    if (preIntegrated) preparePreIntegration(v);
    // Empty cells are skipped (rows left out of the geometry, one-sample fragments discarded)
    // where that is exact: DVR samples each part at one point (not pre-integrated, not split at
    // tag cells); MIP of one row (tags would let a skipped sample's row matter). MINIP and
    // AVERAGE see every sample.
    const bool skipCells =
        settings.skipEmptyCells &&
        ((mode == kDvr && !tagged && !preIntegrated) || (mode == kMip && !tagged));
    if (skipCells) prepareCells(v, mode == kMip ? 1 : 0);
    const bool hasPlaneOpacity = mode == kDvr && planeOpacityMatters(volume.planeOpacity);
    if (hasPlaneOpacity) preparePlaneOpacity(v, volume.planeOpacity);
    prepareFilter(v, settings.nearest);

    // The view in the volume's local coordinates.
    const RenderView& view = frame.view;
    const glm::dmat4 model = volume.model;
    const glm::dmat4 modelView = view.view * model;
    const glm::dmat4 eyeToLocal = glm::inverse(modelView);
    const glm::dmat3 eyeToLocal3(eyeToLocal);
    const glm::dvec3 halfExtent = 0.5 * grid.extent();
    const glm::dvec2 boxDepth = ProxyPlaneCutter::depthRange(-halfExtent, halfExtent, modelView);
    const glm::dvec2 clipDepth = nearFar(view.projection, view.orthographic);
    const double L0 = grid.smallestSpacing();

    // Plane count: numPlanes, or 2 per voxel (spacing L0 / 2 in local units along the view
    // axis); a quarter while interacting. Opacity correction makes both the same image.
    const double localPerEyeAxis = glm::length(eyeToLocal3 * glm::dvec3(0.0, 0.0, -1.0));
    const double depthExtent = boxDepth.y - boxDepth.x;
    const double autoSpacing = 0.5 * L0 / localPerEyeAxis;
    const int slabSamples = mode != kAverage ? std::clamp(settings.samplesPerPlane, 1, 256) : 1;
    long still = settings.numPlanes > 0
                     ? long(settings.numPlanes)
                     : long(std::ceil(depthExtent / (autoSpacing * double(slabSamples))));
    still = std::clamp(still, 1L, long(kMaxPlanes));
    long planes = still;
    if (frame.interactive) {
        planes = settings.interactivePlanes > 0 ? long(settings.interactivePlanes)
                                                : std::max(1L, (still + 3) / 4);
        // The viewer lowers this further when interactive frames are too slow, but not below
        // kMinScaledPlanes: with two or three planes the slab boundaries show as seams.
        planes = std::max(long(std::ceil(double(planes) * frame.interactivePlaneScale)),
                          std::min(planes, kMinScaledPlanes));
    }
    planes = std::clamp(planes, 1L, long(kMaxPlanes));
    const PlaneLayout layout =
        PlaneLayout::over(boxDepth, std::max(depthExtent, 1e-12) / double(planes) * (1.0 + 1e-9));

    SlicingStats drawn;
    drawn.bricksTotal = int(v.bricks.size());
    drawn.brickGrid = v.layout.grid();
    drawn.brickTexels = v.layout.largestTexture();
    drawn.planes = layout.count;
    drawn.planeSpacing = layout.spacing;
    drawn.emptyCells = skipCells ? v.cells.emptyFraction() : 0.0;

    // The clip planes in local coordinates.
    if (volume.clipPlanes.size() > std::size_t(kMaxClipPlanes))
        throw Error(std::to_string(volume.clipPlanes.size()) +
                    " ClipPlanes are in scope of a Volume; it clips with at most " +
                    std::to_string(kMaxClipPlanes));
    std::vector<glm::dvec4> localPlanes;
    localPlanes.reserve(volume.clipPlanes.size());
    for (const glm::dvec4& w : volume.clipPlanes) {
        // n_w . (M p) >= d_w  <=>  (M^T n_w) . p >= d_w - n_w . t
        const glm::dvec3 n(w);
        const glm::dvec3 local = glm::transpose(glm::dmat3(model)) * n;
        localPlanes.emplace_back(local, w.w - glm::dot(n, glm::dvec3(model[3])));
    }

    // Cut the bricks that can contribute, back to front.
    const glm::dvec3 viewer = view.orthographic
                                  ? eyeToLocal3 * glm::dvec3(0.0, 0.0, -1.0)
                                  : glm::dvec3(eyeToLocal * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    v.layout.backToFront(viewer, view.orthographic, v.order);
    const glm::dvec3 margin(0.5 * L0); // see uOwnMin in the shader
    // Empty space out of the geometry: rows of cells that may emit, grown by how far from a
    // fragment's point its samples reach (none with one sample at the point; half a slab,
    // along the longest ray of the view, with several parts or MIP's crossings).
    int rowReach = -1; // -1: whole bricks
    if (skipCells && settings.skipEmptyCells) {
        const bool onePoint = slabSamples == 1 && (mode == kDvr || !settings.mipPeaks);
        double cosMin = 1.0;
        if (!onePoint && !view.orthographic)
            for (int c = 0; c < 8; ++c) {
                const glm::dvec3 corner((c & 1) ? halfExtent.x : -halfExtent.x,
                                        (c & 2) ? halfExtent.y : -halfExtent.y,
                                        (c & 4) ? halfExtent.z : -halfExtent.z);
                const glm::dvec3 eye = glm::dvec3(modelView * glm::dvec4(corner, 1.0));
                cosMin = std::min(cosMin, -eye.z / std::max(glm::length(eye), 1e-300));
            }
        if (onePoint) {
            rowReach = 0;
        } else if (cosMin > 0.25) { // else (a wide view from close by) slabs reach too far
            double localPerEye = 0.0;
            for (int a = 0; a < 3; ++a)
                localPerEye = std::max(localPerEye, glm::length(eyeToLocal3[a]));
            const double halfSlabVoxels = 0.5 * layout.spacing / cosMin * localPerEye / L0;
            rowReach = int(std::ceil(halfSlabVoxels / EmptyCells::kCellSize));
        }
        if (rowReach >= 0 && (v.rowsReach != rowReach || v.rowsKind != v.cellKind ||
                              v.rowsTableKey != v.cellTableKey)) {
            v.rows.dilate(v.cells, rowReach);
            v.rowsReach = rowReach;
            v.rowsKind = v.cellKind;
            v.rowsTableKey = v.cellTableKey;
        }
    }
    const glm::dvec3 towardsVolume = view.orthographic ? viewer : -viewer; // the box is centred
    const int rowAxis = CellRows::axisFor(towardsVolume);
    // Each row costs a plane cut per plane and a draw: with many planes the rows grow (group x
    // group cells across) until planes x rows is at most kRowCutBudget, which keeps the
    // frame's CPU work under about a millisecond.
    int rowGroup = 1;
    if (rowReach >= 0) {
        const glm::ivec3 n = v.cells.cells();
        const int ns = n[(rowAxis + 1) % 3], nt = n[(rowAxis + 2) % 3];
        auto rowsAcross = [&](int g) {
            return double((ns + g - 1) / g) * double((nt + g - 1) / g);
        };
        while (double(layout.count) * rowsAcross(rowGroup) > kRowCutBudget && rowGroup < 64)
            rowGroup *= 2;
    }
    drawn.cellRowGroup = rowGroup;
    v.vertices.clear();
    for (const int i : v.order) {
        BrickState& s = v.bricks[std::size_t(i)];
        s.count = 0;
        s.faceCount = 0;
        s.rows.clear();
        s.rowFirst.clear();
        s.rowCount.clear();
        if (mode == kDvr && !s.mayEmit) {
            ++drawn.bricksSkipped;
            continue;
        }
        const Brick& b = v.layout.bricks()[std::size_t(i)];
        s.first = GLint(v.vertices.size());
        if (rowReach >= 0) {
            v.rows.rowsOf(b, rowAxis, grid.spacing(), halfExtent, viewer, view.orthographic,
                          rowGroup, s.rows);
            for (const CellRow& row : s.rows) {
                ProxyPlaneCutter::cutInto(row.boxMin - margin, row.boxMax + margin, modelView,
                                          layout, clipDepth.x, v.slices);
                s.rowFirst.push_back(GLint(v.vertices.size()));
                s.rowCount.push_back(GLsizei(v.slices.vertices.size()));
                v.vertices.insert(v.vertices.end(), v.slices.vertices.begin(),
                                  v.slices.vertices.end());
            }
            drawn.cellRows += int(s.rows.size());
        } else {
            ProxyPlaneCutter::cutInto(b.boxMin - margin, b.boxMax + margin, modelView, layout,
                                      clipDepth.x, v.slices);
            v.vertices.insert(v.vertices.end(), v.slices.vertices.begin(), v.slices.vertices.end());
        }
        s.count = GLsizei(v.vertices.size()) - s.first;
        drawn.sliceTriangles += std::size_t(s.count) / 3;
        s.faceFirst = GLint(v.vertices.size());
        appendFrontFaces(b, v.layout.grid(), viewer, view.orthographic, v.vertices);
        // Clip planes that rays cross into the kept side bound the visible part too.
        for (const glm::dvec4& plane : localPlanes) {
            const glm::dvec3 n(plane);
            const bool entering =
                view.orthographic ? glm::dot(n, viewer) > 0.0 : glm::dot(n, viewer) < plane.w;
            if (entering)
                ProxyPlaneCutter::appendPlanePolygon(b.boxMin, b.boxMax, n, plane.w, v.vertices);
        }
        s.faceCount = GLsizei(v.vertices.size()) - s.faceFirst;
    }

    const auto prepared = std::chrono::steady_clock::now();
    drawn.cpuMilliseconds = std::chrono::duration<double, std::milli>(prepared - started).count();
    if (!v.vertices.empty()) {
        if (!v.vertexBuffer) {
            v.vertexBuffer = Buffer(GL_ARRAY_BUFFER);
            v.vertexArray = VertexArray::create();
            v.vertexArray.setAttribute(0, v.vertexBuffer, 3);
        }
        v.vertexBuffer.setData(v.vertices, GL_STREAM_DRAW);

        // Uniforms of this volume and frame.
        // The lean program when every sample of a slab counts alike (several of them, no
        // tags, no BoxClip; DVR without planeOpacity, lighting or pre-integration; MIP/MINIP
        // without the voxel-centre crossings).
        const bool lean = slabSamples > 1 && !tagged && !volume.boxClip &&
                          (mode == kDvr ? !lighting && !preIntegrated && !hasPlaneOpacity
                                        : (mode == kMip || mode == kMinip) && !settings.mipPeaks);
        const Program& program = shared.sliceProgram(mode, tagged, lighting, preIntegrated, lean);
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
    drawn.submitMilliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - prepared)
            .count();
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
