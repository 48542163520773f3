// A volume larger than GL_MAX_3D_TEXTURE_SIZE is bricked, never truncated. The GL here allows
// 2048, so the test lowers the limit through RenderDebug::max3DTextureSize to
// 8 texels and checks that the bricks obey it and the image still matches the reference ray
// caster (which samples the whole grid in double precision).
#include <doctest/doctest.h>

#include "slicing/SlicingTestSupport.h"

using namespace volsg;
using namespace volsg::test;

namespace {

double shell(const glm::dvec3& p) {
    const double r = glm::length(p);
    return std::clamp(1.0 - 4.0 * std::abs(r - 0.6), 0.0, 1.0) * (0.6 + 0.4 * p.x * p.x);
}

} // namespace

TEST_CASE("a volume beyond the 3D texture size limit is bricked and matches the reference") {
    OSMesaContext context;
    const RayCastVolume volume =
        volumeOf(makeGrid({30, 20, 12}, VoxelType::UByte, glm::dvec3(1.0), shell),
                 transferFunction({{0.1, 0}, {0.8, 0.8}}, {{0, 0.2}, {1, 1}}));
    auto camera = framing(*volume.data, {0.4f, 0.6f, 1.0f});

    Comparison whole, limited;
    {
        Renderer renderer;
        whole = compareGrid(renderer, volume, SlicingSettings{}, *camera, 64);
    }
    {
        RenderDebug debug;
        debug.max3DTextureSize = 8;
        Renderer renderer;
        limited = compareGrid(renderer, volume, SlicingSettings{}, *camera, 64, glm::vec3(0.0f),
                              false, debug);
    }
    MESSAGE("bricks " << limited.stats.brickGrid.x << "x" << limited.stats.brickGrid.y << "x"
                      << limited.stats.brickGrid.z << ", largest texture "
                      << limited.stats.brickTexels.x << "x" << limited.stats.brickTexels.y << "x"
                      << limited.stats.brickTexels.z << ", rmse to the reference "
                      << limited.difference.rmse * 255 << "/255");
    CHECK(whole.stats.bricksTotal == 1);
    // 30 voxels along x in textures of at most 8 texels (bricks share a seam layer): >= 5.
    CHECK(limited.stats.brickGrid.x >= 5);
    CHECK(limited.stats.brickGrid.y >= 3);
    CHECK(limited.stats.brickGrid.z >= 2);
    CHECK(limited.stats.brickTexels.x <= 8);
    CHECK(limited.stats.brickTexels.y <= 8);
    CHECK(limited.stats.brickTexels.z <= 8);
    // Nothing was cut off: the bricked image is as close to the reference as the whole one.
    CHECK(limited.difference.rmse < 0.5 * k8Bit);
    CHECK(limited.difference.rmse < whole.difference.rmse + 0.1 * k8Bit);
    CHECK(limited.difference.max < 8.0 * k8Bit);
}

TEST_CASE("slabs of many samples end at brick seams: bricked images match the whole volume's") {
    // Few planes far apart, each slab sampled 64 times: a slab reaches several voxels past its
    // plane. Before slabs ended at brick faces, the samples beyond a brick's guard voxel read
    // clamped texels: here 4.97/255 RMSE against the reference and up to 43/255 off the whole
    // volume's image (DVR), where the whole volume is within 0.013/255.
    OSMesaContext context;
    for (const VolumeRenderMode mode : {VolumeRenderMode::DVR, VolumeRenderMode::MIP}) {
        for (const bool preIntegration : {false, true}) {
            if (mode == VolumeRenderMode::MIP && preIntegration) continue;
            CAPTURE(int(mode));
            CAPTURE(preIntegration);
            const RayCastVolume volume =
                volumeOf(makeGrid({30, 20, 12}, VoxelType::UByte, glm::dvec3(1.0), shell),
                         transferFunction({{0.1, 0}, {0.8, 0.8}}, {{0, 0.2}, {1, 1}}), mode);
            auto camera = framing(*volume.data, {0.4f, 0.6f, 1.0f});
            SlicingSettings settings;
            settings.numPlanes = 5;
            settings.samplesPerPlane = 64;
            settings.preIntegrated = preIntegration;
            Comparison whole, limited;
            {
                Renderer renderer;
                whole = compareGrid(renderer, volume, settings, *camera, 64);
            }
            {
                RenderDebug debug;
                debug.max3DTextureSize = 8;
                Renderer renderer;
                limited = compareGrid(renderer, volume, settings, *camera, 64, glm::vec3(0.0f),
                                      false, debug);
            }
            MESSAGE("rmse to the reference: whole " << whole.difference.rmse * 255
                                                    << "/255, bricked "
                                                    << limited.difference.rmse * 255 << "/255");
            CHECK(limited.stats.bricksTotal >= 30);
            // MIP's samples sit elsewhere in slabs cut at seams: its maximum moves a little.
            CHECK(difference(whole.gl, limited.gl).max <
                  (mode == VolumeRenderMode::MIP ? 1.0 : 0.25) * k8Bit);
            CHECK(limited.difference.rmse < whole.difference.rmse + 0.02 * k8Bit);
        }
    }
}
