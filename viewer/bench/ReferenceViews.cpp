#include "ReferenceViews.h"

#include <algorithm>
#include <numbers>

#include "BenchRow.h"
#include "OrbitCamera.h"
#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/volumescene/ReferenceScene.h>

namespace volsg::bench {

OrbitViews makeOrbitViews(Node& root, const RenderOptions& options, int frames, int errorFrames) {
    const double aspect = double(options.width) / double(options.height);
    const SceneCamera sceneCamera = options.camera ? SceneCamera{options.camera, glm::dmat4(1.0)}
                                                   : findOrMakeCamera(root, aspect);
    const Box3 box = computeBoundingBox(root);
    const glm::dvec3 center = box.isEmpty() ? glm::dvec3(0.0) : box.center();
    OrbitViews views;
    for (int i = 0; i < frames; ++i)
        views.cameras.push_back(
            orbitCamera(sceneCamera, center, 2.0 * std::numbers::pi * i / frames));
    const int k = std::clamp(errorFrames, 0, frames);
    for (int i = 0; i < k; ++i)
        views.errorIndices.push_back(int(std::int64_t(i) * frames / k));
    return views;
}

ReferenceImages renderReferenceViews(Node& root, const RenderOptions& options,
                                     const OrbitViews& views, const RayCastOptions& rayOptions) {
    ReferenceImages out;
    const std::size_t before = residentBytes();
    RenderOptions viewOptions = options;
    for (int index : views.errorIndices) {
        viewOptions.camera = views.cameras[std::size_t(index)];
        RayCastResult details;
        out.ms.ms.push_back(
            timeMs([&] { renderReference(root, viewOptions, &details, rayOptions); }));
        out.errorBound = std::max(out.errorBound, details.errorBound);
        out.converged = out.converged && details.converged;
        out.images.push_back(std::move(details.image));
    }
    const std::size_t after = residentBytes();
    out.rssDelta = after > before ? after - before : 0;
    return out;
}

} // namespace volsg::bench
