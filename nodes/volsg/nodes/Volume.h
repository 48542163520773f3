#pragma once
// Volume: renders the VolumeData in scope by slicing a 3D texture back to front (the seed's
// Inventor Volume node), with the TransferFunctions, ClipPlanes and BoxClip in scope
// (nodes/volsg/render/VolumeRendering.cpp draws it).
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>
#include <volsg/slicing/SlicingStats.h>

namespace volsg {

enum class VolumeRenderMode; // lib/volsg/volume/VolumeModel.h

class Volume : public Inherit<Node, Volume> {
public:
    static constexpr const char* typeName = "Volume";
    enum RenderMode { DVR, MIP, MINIP, AVERAGE };
    enum Interpolation { LINEAR, NEAREST };
    static const EnumValues renderModeNames, interpolationNames;

    SFEnum renderMode{this, "renderMode", renderModeNames, DVR};
    /// RMSE per channel, in 1/255, that a still frame may have against the rendering model:
    /// the fields below that are not set (numPlanes 0, samplesPerPlane, preIntegrated,
    /// mipPeaks never written) are chosen per frame as the cheapest whose predicted error
    /// meets it (lib/volsg/slicing/SlicingQuality.h). <= 0 or NaN: no target (2 samples per
    /// voxel, one per plane, as before).
    SFFloat errorTarget{this, "errorTarget", 0.5f};
    /// The same for interactive frames (interactivePlanes 0).
    SFFloat interactiveErrorTarget{this, "interactiveErrorTarget", 2.0f};
    SFInt32 numPlanes{this, "numPlanes", 0};                 ///< 0: from errorTarget
    SFInt32 interactivePlanes{this, "interactivePlanes", 0}; ///< 0: from interactiveErrorTarget
    /// DVR, MIP, MINIP: samples per plane, taken along each pixel's ray inside the plane's slab
    /// (fewer planes for the same sampling). Not set: from errorTarget.
    SFInt32 samplesPerPlane{this, "samplesPerPlane", 1};
    /// MIP, MINIP: also sample where each ray crosses a voxel-centre plane, so thin peaks are
    /// found at any plane count. FALSE: only samplesPerPlane evenly spaced samples per plane
    /// (about a quarter of the texture fetches; the error of a ray caster at that step).
    SFBool mipPeaks{this, "mipPeaks", true};
    /// MIP, MINIP without mipPeaks, several samples per plane: the extreme from the parabola
    /// through the most extreme sample and its neighbours (evenly spaced samples always miss
    /// part of a peak). FALSE: the most extreme sample itself.
    SFBool refinePeaks{this, "refinePeaks", true};
    SFEnum interpolation{this, "interpolation", interpolationNames, LINEAR};
    SFBool preIntegrated{this, "preIntegrated", false};
    SFBool lighting{this, "lighting", false};
    /// (t, m): extinction multiplier over view depth, t = 0 nearest, 1 farthest box point.
    MFVec2f planeOpacity{this, "planeOpacity", {glm::vec2(0, 1), glm::vec2(1, 1)}};
    SFUInt32 textureBudget{this, "textureBudget", 0u}; ///< bytes; 0 = the driver's limit
    /// A paged volume (VolumeData paging): a brick's level is fine enough when one of its
    /// voxels projects to at most this many pixels; coarser bricks are drawn until finer ones
    /// arrive (slicingStats().paging reports the difference). textureBudget 0: 512 MiB.
    SFFloat lodPixels{this, "lodPixels", 1.0f};

    /// renderMode as the engines name it.
    VolumeRenderMode mode() const;

    /// What the last render of this node did (bricks drawn and skipped, uploads, planes).
    const SlicingStats& slicingStats() const { return slicingStats_; }
    void setSlicingStats(const SlicingStats& stats) { slicingStats_ = stats; }

protected:
    ~Volume() override = default;

private:
    SlicingStats slicingStats_;
};

} // namespace volsg
