// The Volume node's features against the reference ray caster: tags, bricking, empty-space
// skipping, clipping, plane opacity, polygons inside the volume, cameras inside it,
// pre-integration, lighting and several volumes.
#include "SlicingTestSupport.h"

#include <volsg/io/SceneReader.h>
#include <volsg/nodes/BoxClip.h>
#include <volsg/nodes/ClipPlane.h>
#include <volsg/nodes/Cube.h>
#include <volsg/nodes/Light.h>
#include <volsg/nodes/Material.h>
#include <volsg/nodes/Transform.h>
#include <volsg/nodes/Volume.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/volume/TestVolumes.h>
#include <volsg/volumescene/ReferenceScene.h>

using namespace volsg;
using namespace volsg::test;

namespace {

/// VolumeData (a generator), one TransferFunction and a Volume in a Separator.
struct NodeVolume {
    ref_ptr<Separator> root = Separator::create();
    ref_ptr<VolumeData> data = VolumeData::create();
    ref_ptr<TransferFunction> transfer = TransferFunction::create();
    ref_ptr<Volume> volume = Volume::create();

    NodeVolume(VolumeData::Generator generator, int n, const TransferFunction1D& function) {
        data->generator = generator;
        data->dimensions = glm::vec3(float(n));
        setNodeFields(*transfer, function);
        // The fixed rule (2 samples per voxel) these tests' tolerances were set for: they test
        // the features, not the choice from an error target (ErrorTargetTest does).
        volume->errorTarget = 0.0f;
        root->addChild(data);
        root->addChild(transfer);
        root->addChild(volume);
    }

    /// The volume as the reference sees it (default transfer function only).
    RayCastVolume description() const { return volumeOf(data->grid(), transfer->function()); }
};

Image renderScene(Renderer& renderer, Node& root, Camera& camera, int size,
                  const glm::vec3& background = glm::vec3(0.0f), bool interactive = false) {
    RenderOptions options;
    options.width = options.height = size;
    options.camera = ref_ptr<Camera>(&camera);
    options.background = background;
    options.interactive = interactive;
    return renderer.render(root, options);
}

} // namespace

TEST_CASE_FIXTURE(GlFixture, "tagged voxels use the transfer function of their tag") {
    const int n = 24;
    NodeVolume scene(VolumeData::LABELLED, n,
                     transferFunction({{0, 0}, {1, 0.3}}, {{0, 0.5}, {1, 0.5}}));
    const TransferFunction1D inner = transferFunction({{0, 0}, {1, 0.9}}, {{0, 1}, {1, 1}},
                                                      {{0, 0}, {1, 0.2}}, {{0, 0}, {1, 0}});
    const TransferFunction1D shell = transferFunction({{0, 0.1}, {1, 0.4}}, {{0, 0}, {1, 0}},
                                                      {{0, 0.3}, {1, 1}}, {{0, 0.2}, {1, 0.4}});
    TransferFunction1D corner = transferFunction({{0, 0.25}, {1, 0.25}}, {{0, 0}, {1, 0}},
                                                 {{0, 0}, {1, 0}}, {{0, 1}, {1, 1}});
    corner.setDataRange(0.0, 100.0);
    const std::pair<int, TransferFunction1D> tagged[] = {{1, inner}, {2, shell}, {3, corner}};
    for (const auto& [tag, function] : tagged) {
        auto node = TransferFunction::create();
        node->tag = tag;
        setNodeFields(*node, function);
        scene.root->insertChild(node, 2);
    }
    auto camera = framing(*scene.data->grid(), {0.3f, -0.6f, 1.0f});
    const Image gl = renderScene(renderer, *scene.root, *camera, 48);

    RayCastVolume v = scene.description();
    v.tags = scene.data->tagGrid();
    for (const auto& [tag, function] : tagged)
        v.transferFunctions[tag] = function;
    const Image ref = referenceImage(rayCamera(*camera, 48, 48), {v});
    keepImage(gl, "tagged-gl");
    keepImage(ref, "tagged-ref");
    // Tag boundaries are steps: each slab is split at its tag cell's faces (classifySlab), but
    // a slab that crosses two faces lumps the far parts together.
    checkDifference(difference(gl, ref), 0.5, 8.0);
    // The inner tag's yellow shows in the middle; the corner tag's blue at the bottom.
    CHECK(gl.at(24, 24).r > 2.0f * gl.at(24, 24).b);
}

TEST_CASE_FIXTURE(
    GlFixture, "a transfer function change rebuilds the table without uploading the volume again") {
    NodeVolume scene(VolumeData::SOFT_SPHERE, 20, transferFunction({{0, 0}, {1, 0.5}}));
    auto camera = framing(*scene.data->grid(), {0.0f, 0.0f, 1.0f});
    const Image first = renderScene(renderer, *scene.root, *camera, 32);
    const SlicingStats& stats = scene.volume->slicingStats();
    CHECK(stats.brickUploads == 1);
    CHECK(stats.transferTableBuilds == 1);

    renderScene(renderer, *scene.root, *camera, 32);
    CHECK(stats.brickUploads == 1);
    CHECK(stats.transferTableBuilds == 1); // nothing changed, nothing rebuilt

    scene.transfer->alpha = {glm::vec2(0, 0), glm::vec2(1, 0.9f)};
    scene.transfer->red = {glm::vec2(0, 1), glm::vec2(1, 1)};
    scene.transfer->green = {glm::vec2(0, 0), glm::vec2(1, 0)};
    const Image changed = renderScene(renderer, *scene.root, *camera, 32);
    CHECK(stats.brickUploads == 1);
    CHECK(stats.transferTableBuilds == 2);
    CHECK(std::abs(changed.at(16, 16).r - first.at(16, 16).r) > 0.1f);

    // A tagged function added later is a table change too, never a volume upload.
    auto tagged = TransferFunction::create();
    tagged->tag = 7;
    scene.root->insertChild(tagged, 2);
    renderScene(renderer, *scene.root, *camera, 32);
    CHECK(stats.brickUploads == 1);
    CHECK(stats.transferTableBuilds == 3);
}

TEST_CASE_FIXTURE(GlFixture, "a bricked volume renders the same image as an unbricked one") {
    const RayCastVolume plain =
        volumeOf(makeGrid({30, 26, 22}, VoxelType::UByte, glm::dvec3(1.0, 1.2, 1.0), blob),
                 transferFunction({{0.1, 0}, {0.7, 0.7}}, {{0, 0.3}, {1, 1}}));
    const RayCastVolume tagged =
        labelledVolume(26, {{-1, plain.transferFunctions.at(-1)},
                            {1, transferFunction({{0, 0}, {1, 0.9}}, {{0, 1}, {1, 1}})},
                            {3, transferFunction({{0, 0.3}, {1, 0.3}}, {{0, 0}, {1, 0}})}});
    RayCastVolume mip = plain;
    mip.mode = VolumeRenderMode::MIP;
    struct Case {
        const char* name;
        const RayCastVolume* volume;
        bool lighting, preIntegrated;
    };
    for (const Case c : {Case{"unlit", &plain, false, false}, Case{"lit", &plain, true, false},
                         Case{"pre-integrated", &plain, false, true},
                         Case{"tagged", &tagged, false, false}, Case{"MIP", &mip, false, false}}) {
        auto camera = framing(*c.volume->data, {0.6f, 0.5f, 1.0f});
        SlicingSettings whole;
        whole.lighting = c.lighting;
        whole.preIntegrated = c.preIntegrated;
        SlicingSettings bricked = whole;
        bricked.textureBudget = 6000; // bytes: R16 texels (+ R8UI tags), about 14^3 voxels
        const Comparison a = compareGrid(renderer, *c.volume, whole, *camera, 64);
        const Comparison b = compareGrid(renderer, *c.volume, bricked, *camera, 64);
        keepImage(b.gl, std::string("bricked-") + c.name);
        const ImageDifference d = difference(a.gl, b.gl);
        MESSAGE(std::string(c.name)
                << ": " << b.stats.bricksTotal << " bricks (" << b.stats.brickGrid.x << "x"
                << b.stats.brickGrid.y << "x" << b.stats.brickGrid.z << "), max difference "
                << d.max * 255 << "/255, resident " << b.stats.textureBytes << " bytes");
        CHECK(a.stats.bricksTotal == 1);
        CHECK(b.stats.bricksTotal >= 8);
        const glm::ivec3 t = b.stats.brickTexels;
        CHECK(std::size_t(t.x) * t.y * t.z * (c.volume->tags ? 3 : 2) <= 6000);
        CHECK(b.stats.textureBytes <= 6000);
        CHECK(d.max < 1.0 * k8Bit);
        CHECK(d.rmse < 0.05 * k8Bit);
        // And both near the reference (which does not shade: lit images have no reference).
        if (!c.lighting) CHECK(b.difference.rmse < 0.5 * k8Bit);
    }
}

TEST_CASE_FIXTURE(GlFixture, "bricks beyond the budget are streamed: uploaded again each frame") {
    auto root = Separator::create();
    auto node = GridVolume::create();
    node->description.data = makeSoftSphere(24, VoxelType::UByte);
    node->settings.textureBudget = 2 * 13 * 13 * 13; // one 13^3 brick of R16 at a time
    root->addChild(node);
    auto camera = framing(*node->description.data, {0.1f, 0.2f, 1.0f});
    renderScene(renderer, *root, *camera, 32);
    const SlicingStats first = node->stats;
    renderScene(renderer, *root, *camera, 32);
    const SlicingStats second = node->stats;
    MESSAGE(first.bricksDrawn << " bricks drawn, " << second.bricksResident << " resident, "
                              << second.brickUploads << " uploads after two frames");
    CHECK(first.bricksDrawn == first.bricksTotal);
    CHECK(second.textureBytes <= node->settings.textureBudget);
    CHECK(second.bricksResident < second.bricksTotal);
    // The least recently used brick is evicted; with room for one brick, every drawn brick
    // is uploaded again in the next frame.
    CHECK(second.brickUploads == 2 * std::uint64_t(first.bricksDrawn));

    // Without a budget the volume is one brick, uploaded once and then kept.
    node->settings.textureBudget = 0;
    renderScene(renderer, *root, *camera, 32);
    CHECK(node->stats.bricksTotal == 1);
    CHECK(node->stats.brickUploads == second.brickUploads + 1);
    renderScene(renderer, *root, *camera, 32);
    CHECK(node->stats.brickUploads == second.brickUploads + 1);
}

TEST_CASE_FIXTURE(GlFixture,
                  "bricks empty under the transfer function are neither uploaded nor drawn") {
    // Data only where x < 0: the bricks of the other half hold zeros, transparent under a
    // function whose alpha is 0 at v = 0.
    const auto halfBlob = [](const glm::dvec3& p) {
        return p.x < -0.1 ? std::clamp(0.8 - 0.6 * glm::length(p + glm::dvec3(0.5, 0, 0)), 0.0, 1.0)
                          : 0.0;
    };
    RayCastVolume v = volumeOf(makeGrid({32, 16, 16}, VoxelType::UByte, glm::dvec3(1.0), halfBlob),
                               transferFunction({{0, 0}, {1, 0.8}}));
    auto camera = framing(*v.data, {0.2f, 0.3f, 1.0f});
    SlicingSettings whole, bricked;
    bricked.textureBudget = 2 * 9 * 9 * 9; // bricks of at most 9^3 texels
    const Comparison a = compareGrid(renderer, v, whole, *camera, 48);
    const Comparison b = compareGrid(renderer, v, bricked, *camera, 48);
    MESSAGE(b.stats.bricksTotal << " bricks: " << b.stats.bricksDrawn << " drawn, "
                                << b.stats.bricksSkipped << " skipped, " << b.stats.brickUploads
                                << " uploaded");
    CHECK(b.stats.bricksSkipped >= b.stats.bricksTotal / 3);
    CHECK(b.stats.bricksDrawn + b.stats.bricksSkipped == b.stats.bricksTotal);
    CHECK(b.stats.brickUploads == std::uint64_t(b.stats.bricksDrawn));
    CHECK(difference(a.gl, b.gl).max < 1.0 * k8Bit);
    CHECK(b.difference.rmse < 0.25 * k8Bit);

    // Opaque at v = 0: no brick is empty any more.
    v.transferFunctions[-1] = transferFunction({{0, 0.05}, {1, 0.8}});
    const Comparison c = compareGrid(renderer, v, bricked, *camera, 48);
    CHECK(c.stats.bricksSkipped == 0);
    CHECK(c.stats.bricksDrawn == c.stats.bricksTotal);
    CHECK(c.difference.rmse < 0.25 * k8Bit);
}

TEST_CASE_FIXTURE(GlFixture, "ClipPlanes remove exactly the clipped side") {
    NodeVolume scene(VolumeData::SOFT_SPHERE, 24,
                     transferFunction({{0, 0.05}, {1, 0.8}}, {{0, 1}, {1, 0.3}}));
    // Two planes, one of them under a transform: both apply to the volume after them.
    auto transform = Transform::create();
    transform->rotation = Rotation{glm::vec3(0, 0, 1), 0.5f};
    auto first = ClipPlane::create();
    first->plane = Plane{glm::vec3(1, 0, 0.3f), -2.0f};
    auto second = ClipPlane::create();
    second->plane = Plane{glm::vec3(0, -1, 0), -4.0f};
    scene.root->insertChild(first, 0);
    scene.root->insertChild(transform, 1);
    scene.root->insertChild(second, 2);
    auto camera = framing(*scene.data->grid(), {0.4f, 0.5f, 1.0f});
    const Image gl = renderScene(renderer, *scene.root, *camera, 48);

    RayCastVolume v = scene.description();
    const glm::dmat4 rotated = Rotation{glm::vec3(0, 0, 1), 0.5f}.matrix();
    v.model = rotated; // the Volume is after the Transform
    v.clipPlanes = {ClipPlane::worldPlane(first->plane(), glm::dmat4(1.0)),
                    ClipPlane::worldPlane(second->plane(), rotated)};
    const Image ref = referenceImage(rayCamera(*camera, 48, 48), {v});
    keepImage(gl, "clip-planes");
    // Where a clip plane cuts a ray between two planes the slab is cut exactly.
    checkDifference(difference(gl, ref), 0.2, 2.0);
    // Unclipped, the image differs a lot: the planes do remove part of the sphere.
    RayCastVolume whole = v;
    whole.clipPlanes.clear();
    CHECK(difference(gl, referenceImage(rayCamera(*camera, 48, 48), {whole})).max > 0.2);
}

TEST_CASE_FIXTURE(GlFixture, "BoxClip inside and outside opacity and colour match the reference") {
    NodeVolume scene(VolumeData::SOFT_SPHERE, 24,
                     transferFunction({{0, 0.1}, {1, 0.7}}, {{0, 1}, {1, 0.2}}));
    auto box = BoxClip::create();
    box->origin = glm::vec3(-6, -9, -4);
    box->extent = glm::vec3(14, 12, 16);
    auto camera = framing(*scene.data->grid(), {0.7f, 0.4f, 1.0f});
    const auto settingsOf = [](const BoxClip& b) {
        RayCastBoxClip c;
        c.origin = glm::dvec3(b.origin());
        c.extent = glm::dvec3(b.extent());
        c.model = glm::dmat4(1.0);
        c.insideOpacity = b.insideOpacity();
        c.outsideOpacity = b.outsideOpacity();
        c.insideColor = glm::dvec3(b.insideColor());
        c.insideColorWeight = b.insideColorWeight();
        c.outsideColor = glm::dvec3(b.outsideColor());
        c.outsideColorWeight = b.outsideColorWeight();
        return c;
    };
    scene.root->insertChild(box, 0);
    struct Case {
        float insideOpacity, outsideOpacity, insideWeight, outsideWeight;
    };
    for (const Case c :
         {Case{1, 0, 0, 0}, Case{0, 1, 0, 0}, Case{2, 0.3f, 0, 0}, Case{1, 1, 0.8f, 0.5f}}) {
        box->insideOpacity = c.insideOpacity;
        box->outsideOpacity = c.outsideOpacity;
        box->insideColor = glm::vec3(0, 1, 0);
        box->insideColorWeight = c.insideWeight;
        box->outsideColor = glm::vec3(0, 0, 1);
        box->outsideColorWeight = c.outsideWeight;
        const Image gl = renderScene(renderer, *scene.root, *camera, 48);
        RayCastVolume v = scene.description();
        v.boxClip = settingsOf(*box);
        const Image ref = referenceImage(rayCamera(*camera, 48, 48), {v});
        keepImage(gl, "boxclip-" + std::to_string(int(10 * c.outsideOpacity)));
        MESSAGE("inside " << c.insideOpacity << " outside " << c.outsideOpacity << " weights "
                          << c.insideWeight << "/" << c.outsideWeight);
        // A slab cut by a box face gets each region's opacity and colour for its length.
        checkDifference(difference(gl, ref), 0.2, 1.5);
    }
}

TEST_CASE_FIXTURE(GlFixture,
                  "planeOpacity scales extinction over view depth as the reference does") {
    NodeVolume scene(VolumeData::SOFT_SPHERE, 24,
                     transferFunction({{0, 0.1}, {1, 0.8}}, {{0, 1}, {1, 0}}, {{0, 0}, {1, 1}}));
    scene.volume->planeOpacity = {glm::vec2(0, 0), glm::vec2(0.4f, 1), glm::vec2(0.7f, 0.2f),
                                  glm::vec2(1, 1)};
    auto camera = framing(*scene.data->grid(), {-0.5f, 0.3f, 1.0f});
    const Image gl = renderScene(renderer, *scene.root, *camera, 48);
    RayCastVolume v = scene.description();
    v.planeOpacity = {{0, 0}, {0.4, 1}, {0.7, 0.2}, {1, 1}};
    checkDifference(difference(gl, referenceImage(rayCamera(*camera, 48, 48), {v})), 0.25, 2.0);
    v.planeOpacity.clear();
    CHECK(difference(gl, referenceImage(rayCamera(*camera, 48, 48), {v})).max > 0.1);
}

TEST_CASE_FIXTURE(
    GlFixture, "an opaque cube inside the volume hides what is behind it and is dimmed in front") {
    NodeVolume scene(VolumeData::SOFT_SPHERE, 24,
                     transferFunction({{0, 0.05}, {1, 0.5}}, {{0, 0.2}, {1, 0.2}},
                                      {{0, 0.4}, {1, 1}}, {{0, 1}, {1, 0.3}}));
    auto material = Material::create();
    material->diffuseColor = {glm::vec3(1.0f, 0.1f, 0.1f)};
    auto cube = Cube::create();
    cube->width = 8.0f;
    cube->height = 8.0f;
    cube->depth = 8.0f;
    auto opaque = Separator::create();
    opaque->addChild(material);
    opaque->addChild(cube);
    auto camera = framing(*scene.data->grid(), {0.5f, 0.4f, 1.0f});
    const int size = 48;
    const Image cubeAlone = renderScene(renderer, *opaque, *camera, size);
    const Image volumeAlone = renderScene(renderer, *scene.root, *camera, size);
    scene.root->insertChild(opaque, 0);
    const Image gl = renderScene(renderer, *scene.root, *camera, size);

    // The reference: the volume over the GL image of the cube, with rays ending at the cube.
    const RayCastCamera rays = rayCamera(*camera, size, size);
    RayCastBehind behind;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            behind.backgroundPixels.push_back(glm::dvec3(cubeAlone.at(x, y)));
            const Ray r = ReferenceRayCaster::pixelRay(rays, x, y);
            double enter = -1e300, exit = 1e300;
            for (int a = 0; a < 3; ++a) {
                const double t0 = (-4.0 - r.origin[a]) / r.direction[a];
                const double t1 = (4.0 - r.origin[a]) / r.direction[a];
                enter = std::max(enter, std::min(t0, t1));
                exit = std::min(exit, std::max(t0, t1));
            }
            behind.opaqueDistance.push_back(
                enter <= exit && enter > 0.0 ? enter : std::numeric_limits<double>::infinity());
        }
    const Image ref = referenceImage(rays, {scene.description()}, glm::dvec3(0.0), &behind);
    keepImage(gl, "cube-in-volume-gl");
    keepImage(ref, "cube-in-volume-ref");
    checkDifference(difference(gl, ref), 0.2, 1.5);
    // At the centre the red cube shows through the part of the volume in front of it,
    // dimmed: redder than the volume alone, darker than the bare cube.
    const glm::vec4 centre = gl.at(size / 2, size / 2);
    CHECK(centre.r > volumeAlone.at(size / 2, size / 2).r + 0.1f);
    CHECK(centre.r < cubeAlone.at(size / 2, size / 2).r - 0.1f);
}

TEST_CASE_FIXTURE(GlFixture,
                  "a camera inside the volume sees only what is in front of its near plane") {
    const RayCastVolume v =
        volumeOf(makeGrid({24, 24, 24}, VoxelType::UByte, glm::dvec3(1.0), blob),
                 transferFunction({{0, 0.02}, {1, 0.3}}, {{0, 0.2}, {1, 1}}));
    for (const glm::vec3 eye : {glm::vec3(0, 0, 6), glm::vec3(3, -2, 4)}) {
        auto camera = perspectiveAt(eye, 1.2f, 0.5f, 100.0f);
        const Comparison c = compareGrid(renderer, v, {}, *camera, 48);
        keepImage(c.gl, "inside-" + std::to_string(int(eye.x)));
        checkSliced(c, 0.5, 2.0, "eye " + text(eye) + ": ");
    }
}

TEST_CASE_FIXTURE(GlFixture, "pre-integration cuts the error of a spiky transfer function") {
    // A thin opaque shell where the soft sphere crosses v = 0.5.
    const RayCastVolume v = volumeOf(makeSoftSphere(24, VoxelType::UShort),
                                     transferFunction(spike(0.47, 0.5, 0.53), {{0, 1}, {1, 1}},
                                                      {{0, 0.8}, {1, 0.8}}, {{0, 0.2}, {1, 0.2}}));
    auto camera = framing(*v.data, {0.3f, 0.2f, 1.0f});
    SlicingSettings post;
    post.numPlanes = 40; // under one plane per voxel along the view
    const auto [a, b] = compareSettings(renderer, v, post, preIntegrated(post), *camera, 48);
    keepImage(a.gl, "spiky-post");
    keepImage(b.gl, "spiky-pre");
    keepImage(a.reference, "spiky-ref");
    MESSAGE("40 planes: post-classified rmse "
            << a.difference.rmse * 255 << "/255 max " << a.difference.max * 255
            << "/255; pre-integrated rmse " << b.difference.rmse * 255 << "/255 max "
            << b.difference.max * 255 << "/255");
    CHECK(b.stats.preIntegrationBuilds == 1);
    CHECK(b.difference.rmse < a.difference.rmse / 4.0);
    CHECK(b.difference.max < a.difference.max / 2.0);
    CHECK(b.difference.rmse < 2.0 * k8Bit);
}

TEST_CASE_FIXTURE(GlFixture, "lighting shades the side of the volume that faces the light") {
    NodeVolume scene(VolumeData::SOFT_SPHERE, 24,
                     transferFunction({{0, 0}, {0.3, 0}, {0.35, 0.9}, {1, 0.9}}, {{0, 1}, {1, 1}},
                                      {{0, 1}, {1, 1}}, {{0, 1}, {1, 1}}));
    auto camera = framing(*scene.data->grid(), {0.0f, 0.0f, 1.0f});
    const Image unlit = renderScene(renderer, *scene.root, *camera, 48);
    auto light = DirectionalLight::create();
    light->direction = glm::vec3(-1, 0, -0.3f); // shines from +x
    scene.root->insertChild(light, 0);
    scene.volume->lighting = true;
    const Image lit = renderScene(renderer, *scene.root, *camera, 48);
    keepImage(lit, "lit");
    CHECK(allFinite(lit));
    double left = 0.0, right = 0.0;
    for (int y = 16; y < 32; ++y)
        for (int x = 0; x < 24; ++x) {
            left += lit.at(x, y).r;
            right += lit.at(47 - x, y).r;
        }
    MESSAGE("lit left half " << left << ", right half " << right);
    CHECK(right > 1.5 * left);
    // The ambient term alone (0.2) lights the far side: dim but not black, and the lit image
    // differs from the unlit one (which shows the plain colour).
    CHECK(left > 0.0);
    CHECK(difference(lit, unlit).max > 0.2);
}

TEST_CASE_FIXTURE(GlFixture, "two volumes side by side match the reference") {
    RayCastVolume a = volumeOf(makeSoftSphere(16, VoxelType::UByte),
                               transferFunction({{0, 0}, {1, 0.8}}, {{0, 1}, {1, 1}}));
    a.model = glm::translate(glm::dmat4(1.0), glm::dvec3(-10, 0, 0));
    RayCastVolume b = volumeOf(makeGrid({12, 16, 10}, VoxelType::Float, glm::dvec3(1.0), blob),
                               transferFunction({{0.2, 0}, {1, 0.6}}, {{0, 0}, {1, 0}}));
    b.model = glm::translate(glm::dmat4(1.0), glm::dvec3(10, 2, -3)) *
              glm::rotate(glm::dmat4(1.0), 0.4, glm::dvec3(0, 1, 0));
    auto root = Separator::create();
    for (const RayCastVolume* v : {&a, &b}) {
        auto node = GridVolume::create();
        node->description = *v;
        root->addChild(node);
    }
    auto camera = perspectiveAt({0, 10, 60}, 0.6f, 20.0f, 120.0f);
    const Image gl = renderScene(renderer, *root, *camera, 64);
    const Image ref = referenceImage(rayCamera(*camera, 64, 64), {a, b});
    keepImage(gl, "two-volumes");
    checkDifference(difference(gl, ref), 0.25, 2.0);
}

TEST_CASE_FIXTURE(GlFixture,
                  "tagged MIP carries each maximum's tag and BoxClip region to the composite") {
    RayCastVolume v =
        labelledVolume(20,
                       {{-1, transferFunction({{0, 0}, {1, 1}}, {{0, 0.5}, {1, 0.5}})},
                        {1, transferFunction({{0, 0.5}, {1, 1}}, {{0, 1}, {1, 1}}, {{0, 0}, {1, 0}},
                                             {{0, 0}, {1, 0}})},
                        {2, transferFunction({{0, 0.2}, {1, 0.9}}, {{0, 0}, {1, 0}},
                                             {{0, 1}, {1, 1}}, {{0, 0}, {1, 0}})}},
                       VolumeRenderMode::MIP);
    RayCastBoxClip clip;
    clip.origin = glm::dvec3(-10, -10, -10);
    clip.extent = glm::dvec3(10, 20, 20);
    clip.outsideOpacity = 1.0;
    clip.insideColor = glm::dvec3(0, 0, 1);
    clip.insideColorWeight = 0.6;
    v.boxClip = clip;
    auto camera = framing(*v.data, {0.2f, 0.1f, 1.0f});
    const Comparison c = compareGrid(renderer, v, {}, *camera, 48);
    keepImage(c.gl, "tagged-mip");
    const double close = fractionWithin(c.gl, c.reference, 3.0 * k8Bit);
    MESSAGE("rmse " << c.difference.rmse * 255 << "/255, max " << c.difference.max * 255
                    << "/255, within 3/255: " << close * 100 << "% of the pixels");
    // Where the maximum lies on a tag boundary, which side's function applies depends on
    // where the samples fall: a few pixels take the other tag's colour. All others agree.
    CHECK(close > 0.97);
    // Left of x = 0 (inside the box) the maxima are blended toward blue.
    CHECK(c.gl.at(18, 24).b > c.gl.at(30, 24).b + 0.2f);
}

TEST_CASE_FIXTURE(GlFixture, "NEAREST interpolation shows each voxel's value unblended") {
    // Opaque at the front face, 8 voxels along x: an orthographic view straight on shows
    // exactly 8 distinct reds with NEAREST and a smooth ramp with LINEAR.
    const RayCastVolume v = volumeOf(
        makeRamp({8, 4, 4}, VoxelType::UByte, 0, 0.0, 255.0),
        transferFunction({{0, 1}, {1, 1}}, {{0, 0}, {1, 1}}, {{0, 0}, {1, 0}}, {{0, 0}, {1, 0}}));
    auto camera = orthographicAt({0, 0, 20}, 8.5f, 1.0f, 50.0f);
    SlicingSettings nearest;
    nearest.nearest = true;
    const glm::vec3 blue(0.0f, 0.0f, 1.0f);
    const Comparison n = compareGrid(renderer, v, nearest, *camera, 64, blue);
    const Comparison l = compareGrid(renderer, v, {}, *camera, 64, blue);
    std::vector<float> reds;
    int columns = 0;
    for (int x = 0; x < 64; ++x) {
        if (n.gl.at(x, 32).b > 0.5f) continue; // background
        ++columns;
        const float r = n.gl.at(x, 32).r;
        if (reds.empty() || std::abs(reds.back() - r) > 1e-4f) reds.push_back(r);
    }
    CHECK(columns > 56);
    REQUIRE(reds.size() == 8);
    for (std::size_t i = 0; i < reds.size(); ++i) // voxel i holds round(255 i / 7)
        CHECK(std::abs(reds[i] - std::nearbyint(255.0 * double(i) / 7.0) / 255.0) < 1e-5);
    CHECK(l.difference.max < 1.0 * k8Bit); // LINEAR is the reference's trilinear field
}

TEST_CASE_FIXTURE(
    GlFixture, "a scene file with clipping and a shape inside the volume matches renderReference") {
    // The Volume's state gathered by the node and by collectVolumes() must agree: a Transform
    // between the BoxClip and the Volume, a ClipPlane under a Separator that ends before the
    // Volume (so it does not apply), a tagged function, an opaque cone inside.
    const ref_ptr<Node> root = readSceneFromString(R"(#Inventor V2.1 ascii
Separator {
  PerspectiveCamera { position 0.3 0.45 2.2 orientation 1 0 0 -0.18 heightAngle 0.7
                      nearDistance 0.5 farDistance 5 }
  Separator { Material { diffuseColor 0.9 0.8 0.3 } Cone { bottomRadius 0.25 height 0.9 } }
  Separator { ClipPlane { plane 0 1 0 0.2 } }
  VolumeData { generator LABELLED dimensions 24 24 24 spacing 0.05 0.05 0.05 }
  TransferFunction { red [ 0 0.2, 1 1 ] green [ 0 0.5, 1 0.4 ] blue [ 0 1, 1 0.3 ]
                     alpha [ 0 0, 1 0.5 ] }
  TransferFunction { tag 2 red [ 0 0 ] green [ 0 1 ] blue [ 0 0 ] alpha [ 0 0.05, 1 0.3 ] }
  ClipPlane { plane -1 0 -1 -0.3 }
  BoxClip { origin -0.4 -0.4 -0.4 extent 0.8 0.8 0.8 insideOpacity 1 outsideOpacity 0.3
            outsideColor 1 1 1 outsideColorWeight 0.5 }
  Transform { rotation 0 1 0 0.3 }
  Volume { errorTarget 0 }
}
)");
    RenderOptions options;
    options.width = options.height = 48;
    options.background = glm::vec3(0.05f, 0.05f, 0.1f);
    checkDifference(compareScene(renderer, *root, options, "scene-file"), 0.3, 4.0);
    const std::vector<RayCastVolume> volumes = collectVolumes(*root);
    REQUIRE(volumes.size() == 1);
    CHECK(volumes[0].clipPlanes.size() == 1);
    CHECK(volumes[0].transferFunctions.size() == 2);
}
