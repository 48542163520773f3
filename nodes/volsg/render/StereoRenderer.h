#pragma once
// Stereo pairs of a camera (Inventor's stereo mode): red-cyan anaglyph and side-by-side images,
// with the eye separation and the zero-parallax distance taken from the camera.
//
// ```
// StereoOptions stereo;
// stereo.mode = StereoMode::Anaglyph;            // red = left eye, green and blue = right eye
// Image image = renderStereo(renderer, *root, options, stereo);
// ```

#include <string>

#include <volsg/render/Renderer.h>

namespace volsg {

enum class StereoMode { Off, Anaglyph, SideBySide };

/// "off", "anaglyph" or "side-by-side"; anything else throws Error.
StereoMode parseStereoMode(const std::string& text);
const char* stereoModeName(StereoMode mode);

enum class Eye { Left, Right };

struct StereoOptions {
    /// The eye separation as a fraction of the camera's focalDistance. 1/30 is the stereo
    /// photographers' rule: comfortable depth for a scene around the focal distance.
    static constexpr double kDefaultSeparationFraction = 1.0 / 30.0;

    StereoMode mode = StereoMode::Anaglyph;
    double separationFraction = kDefaultSeparationFraction;
};

/// The camera of one eye, in world coordinates (model matrix identity, as RenderOptions::camera
/// takes it). The eyes sit at -+ separation/2 along the camera's x axis, where separation =
/// separationFraction * focalDistance.
/// - Perspective: parallel view axes with off-axis frusta whose windows coincide at the focal
///   distance, so a point there projects to the same pixel in both eyes (zero parallax); a
///   nearer point has crossed parallax (right-eye image left of the left-eye image) of
///   separation * P00 * (1/focal - 1/depth) * width/2 pixels, P00 the projection's x scale.
/// - Orthographic: parallel rays have no parallax from a sideways shift, so each eye turns
///   about the focal point by atan(separation/2 / focal) instead (the same zero-parallax
///   distance and sign of depth).
ref_ptr<Camera> stereoEyeCamera(const Camera& center, double separationFraction, Eye eye);

/// The scene camera (SceneCamera) as a world-space camera: position and orientation through
/// its model matrix (rigid part only), so it can be given as RenderOptions::camera.
ref_ptr<Camera> worldSpaceCamera(const SceneCamera& scene);

/// Renders both eyes with `renderer` (the same GL resources for both) and combines them:
/// anaglyph: (left.r, right.g, right.b) at options' size; side-by-side: the left eye in the
/// left half and the right eye in the right half, each half of options.width wide (the right
/// half takes the odd column). The camera is options.camera, else the scene's
/// (findOrMakeCamera). StereoMode::Off renders the camera itself.
Image renderStereo(Renderer& renderer, Node& root, const RenderOptions& options,
                   const StereoOptions& stereo);

} // namespace volsg
