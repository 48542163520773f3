#pragma once
// VolPack 1.0b3 (Lacroute's shear-warp library) driven with volsg's volume, classification and
// cameras, so its frames can be timed and compared pixel for pixel with ours. A benchmark
// baseline only: nothing in the volsg library depends on it.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/image/Image.h>
#include <volsg/nodes/Camera.h>
#include <volsg/volume/VolumeGrid.h>

struct _vp_context; // VolPack's context (volpack.h: typedef struct _vp_context vpContext)

namespace volsg::volpack {

/// What VolPack is told per 8-bit data value d: the opacity of a slab one voxel thick (the
/// classifier table) and the colour (the shading table when unshaded), both of the scene's
/// TransferFunction at v(d).
struct Classification {
    std::array<double, 256> opacity{};
    std::array<glm::dvec3, 256> color{};
};

/// VolPack's own Phong shading (vpShadeTable) from its encoded normals, one material, one
/// directional light given in eye coordinates (x right, y up, z towards the viewer). The colour
/// then comes from the material, not from the transfer function.
struct Shading {
    bool enabled = false;
    glm::dvec3 lightDirection{0.3, 0.3, 1.0};
    glm::dvec3 materialColor{1.0, 0.9, 0.8};
    double ambient = 0.15, diffuse = 0.7, specular = 0.3, shininess = 20.0;
};

/// One classified (run-length encoded, pre-classified) VolPack volume and its context.
///
/// How volsg's model is set up in VolPack:
/// - Geometry: VolPack puts voxel i at object coordinate (i - N/2) / maxdim; volsg at
///   (i + 0.5 - N/2) * spacing. The model matrix maps one onto the other (scale
///   maxdim * spacing, then half a voxel), so both place every voxel at the same point.
/// - Camera: VolPack's view matrix is the identity and the camera's view matrix is folded into
///   its model matrix, because vpShadeTable takes the viewer to be on +z of VolPack's world;
///   the projection is the camera's own (glm::ortho); perspective is refused.
/// - Pixels: VolPack samples output pixel (x, y) at image coordinate (x, y); GL and the
///   reference at (x + 0.5, y + 0.5). `pixelCenterShift` moves the image by half a pixel so
///   they sample the same points (measured: see VolPackBenchMain's --no-pixel-shift).
/// - Opacity: VolPack stores each voxel's opacity in 8 bits, truncating. The classifier table
///   holds (round(255 A) + 0.25) / 255 so that the stored byte is round(255 A), the nearest
///   level. VolPack then corrects it per view for the path through one slice,
///   1 - (1 - a)^sqrt(1 + shear_i^2 + shear_j^2), which for voxels of the smallest spacing is
///   exactly docs/SCENE-FORMAT.md section 4's 1 - (1 - A)^(ds / L0).
/// - Voxels whose opacity rounds to 0 are left out (VP_MIN_VOXEL_OPACITY = 0.5/255).
/// Differences that remain: VolPack classifies voxels, then interpolates colour and opacity
/// bilinearly in each slice (the model interpolates data, then classifies); it samples once per
/// slice; opacities are 8-bit; the output is 8-bit.
class Renderer {
public:
    /// `grid` must be UByte (VolPack's scalars are 8-bit); throws Error otherwise.
    Renderer(const VolumeGrid& grid, const Classification& classification, const Shading& shading);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    void setMaxRayOpacity(double threshold); ///< VolPack's early ray termination; default 1
    void setPixelCenterShift(bool on) { pixelShift_ = on; }

    /// Renders the volume (centred at the origin, as in the volsg scene) seen by `camera` (its
    /// model matrix the identity, as the orbit cameras have) into a width x height image,
    /// linear values (8-bit levels / 255), row 0 at the top, alpha = VolPack's pixel opacity.
    /// Throws Error for a perspective camera or a VolPack error.
    Image render(const Camera& camera, int width, int height);
    /// The same into `into` (its storage reused when it has the size already).
    void render(const Camera& camera, int width, int height, Image& into);

    /// Voxels kept in VolPack's classified volume (opacity >= 1/255 after rounding).
    std::size_t classifiedVoxels() const { return classifiedVoxels_; }
    int colorChannels() const { return channels_; }

private:
    /// A raw VolPack voxel: the shading field (the data byte when unshaded, VolPack's 13-bit
    /// encoded normal when shaded), then the data byte VolPack classifies (dropped from the
    /// classified volume).
    struct RawVoxel {
        std::uint16_t shade;
        std::uint8_t density;
        std::uint8_t pad;
    };
    _vp_context* vpc_ = nullptr;
    std::vector<RawVoxel> rawVoxels_;
    glm::ivec3 dimensions_;
    glm::dvec3 spacing_;
    int channels_ = 1;
    bool shaded_ = false;
    bool pixelShift_ = true;
    std::size_t classifiedVoxels_ = 0;
    std::vector<float> shadeTable_;
    std::vector<float> classifierTable_;
    std::vector<unsigned char> pixels_;
    int imageWidth_ = 0, imageHeight_ = 0;
    void check(int result, const char* what) const;
};

} // namespace volsg::volpack
