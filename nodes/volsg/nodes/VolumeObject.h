#pragma once
// VolumeObject: one object of a ShearWarpVolume (RTVR's VolumeObject): which voxels it takes
// from the VolumeData in scope, and how they are drawn. Fields: lib/volsg/shearwarp/README.md.
#include <cstdint>
#include <list>

#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>
#include <volsg/shearwarp/VoxelObject.h>

namespace volsg {

class VolumeObject : public Inherit<Node, VolumeObject> {
public:
    static constexpr const char* typeName = "VolumeObject";
    enum Source { WHOLE, TAG, THRESHOLD };
    enum Voxels { VISIBLE, SURFACE, GRADIENT };
    enum RenderMode { TF, SHADED, GRADIENT_OPACITY, CONTOUR, COLORED_CONTOUR };
    enum Compositing { DVR, MIP, SURFACE_HIT };
    static const EnumValues sourceNames, voxelsNames, renderModeNames, compositingNames;

    SFEnum source{this, "source", sourceNames, WHOLE};
    SFInt32 tag{this, "tag", 0}; ///< source TAG
    SFVec2f threshold{this, "threshold",
                      glm::vec2(128.0f, 255.0f)}; ///< source THRESHOLD, data units
    SFEnum voxels{this, "voxels", voxelsNames, VISIBLE};
    SFFloat gradientThreshold{this, "gradientThreshold", 0.05f}; ///< voxels GRADIENT: |grad v| L0
    SFEnum renderMode{this, "renderMode", renderModeNames, TF};
    SFEnum compositing{this, "compositing", compositingNames, DVR};
    SFFloat opacity{this, "opacity", 1.0f};
    SFFloat clippedOpacity{this, "clippedOpacity", 0.0f};
    SFEnum clippedRenderMode{this, "clippedRenderMode", renderModeNames, TF};
    SFColor contourColor{this, "contourColor", glm::vec3(1.0f, 1.0f, 0.0f)};
    SFFloat contourSharpness{this, "contourSharpness", 4.0f};
    SFFloat shininess{this, "shininess", 20.0f};

    /// The extracted voxels for this grid and transfer function, cached per grid (so a Switch
    /// browsing time steps keeps each step's lists, up to 8) and shared by every view.
    /// `transferKey` identifies the transfer function's content; it keys the extraction only
    /// where the function selects voxels (VISIBLE, or a WHOLE region), else its data range does.
    ref_ptr<VoxelObject> voxelObject(const VolumeGrid& grid, const VolumeGrid* tags,
                                     const TransferFunction1D& transferFunction,
                                     std::uint64_t transferKey);
    /// The extraction spec of the current field values.
    ExtractionSpec extractionSpec(const TransferFunction1D& transferFunction) const;

protected:
    ~VolumeObject() override = default;

private:
    struct CacheEntry {
        ref_ptr<const VolumeGrid> grid, tags;
        std::uint64_t key = 0;
        ref_ptr<VoxelObject> voxels;
    };
    std::list<CacheEntry> cache_; ///< most recently used first
};

} // namespace volsg
