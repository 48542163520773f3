#pragma once
// The rotating views of a benchmark run and the reference images of some of them, so that any
// renderer's frames can be compared with the reference on the same views.

#include <vector>

#include "Timing.h"
#include <volsg/image/Image.h>
#include <volsg/reference/ReferenceRayCaster.h>
#include <volsg/render/Renderer.h>

namespace volsg::bench {

/// The RenderOptions of a suite's frames: its size (`st.width`, `st.height`) and volsg-bench's
/// debug switches (`st.debug`).
template <class SuiteSettings> RenderOptions suiteOptions(const SuiteSettings& st) {
    RenderOptions options;
    options.width = st.width;
    options.height = st.height;
    options.debug = st.debug;
    return options;
}

/// `frames` cameras orbiting the scene's centre (the scene's camera turned about the vertical
/// axis by 2 pi i / frames), and which of them are compared with the reference: `errorFrames`
/// indices spread evenly (0, frames/K, 2 frames/K, ...; all of them when K >= frames).
struct OrbitViews {
    std::vector<ref_ptr<Camera>> cameras;
    std::vector<int> errorIndices;
};
OrbitViews makeOrbitViews(Node& root, const RenderOptions& options, int frames, int errorFrames);

/// Reference images (renderReference) of the error views, with their times.
struct ReferenceImages {
    std::vector<Image> images; ///< one per OrbitViews::errorIndices entry
    Samples ms;                ///< milliseconds per reference frame
    double errorBound = 0.0;   ///< the largest RayCastResult::errorBound of them
    bool converged = true;     ///< every view reached the tolerance
    std::size_t rssDelta = 0;  ///< resident memory grown while rendering them (bytes)
};
/// Needs a current GL context (the opaque geometry is drawn by GL).
ReferenceImages renderReferenceViews(Node& root, const RenderOptions& options,
                                     const OrbitViews& views, const RayCastOptions& rayOptions);

} // namespace volsg::bench
