#pragma once
// VolumeData: the voxels (and optional labels) that the Volume and ShearWarpVolume nodes after
// it in scope render. Read from a file (docs/SCENE-FORMAT.md section 3) or generated (test
// volumes).
#include <memory>
#include <string>

#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>
#include <volsg/math/Box3.h>
#include <volsg/volume/VolumeGrid.h> // complete: the node holds ref_ptrs to grids

namespace volsg {

class PagedVolume; // lib/volsg/paging/PagedVolume.h

class VolumeData : public Inherit<Node, VolumeData> {
public:
    static constexpr const char* typeName = "VolumeData";
    enum DataType { UBYTE, USHORT, SHORT, FLOAT };
    enum ByteOrder { LITTLE_ENDIAN_ORDER, BIG_ENDIAN_ORDER };
    /// Generated test volumes (lib/volsg/volume/TestVolumes.h); NONE reads fileName. Their size
    /// is `dimensions` (0 0 0: 64^3; all but RAMP16 are cubic). MARSCHNER_LOBB and SOFT_SPHERE
    /// store `dataType`; THIN_SHELL is UBYTE (radius 0.35 n, 1.5 voxels thick); RAMP16 is
    /// USHORT 0..65535 along x; LABELLED is a UBYTE soft sphere with four tags. Each has its
    /// own spacing (Marschner-Lobb 2/(n-1), others 1) unless `spacing` is set.
    /// ATTRACTOR_BASIN is the UBYTE Lorenz attractor (tag 1) inside its basin surface (tag 2)
    /// of lib/volsg/volume/AttractorBasin.h.
    enum Generator {
        NONE,
        MARSCHNER_LOBB,
        SOFT_SPHERE,
        THIN_SHELL,
        RAMP16,
        LABELLED,
        ATTRACTOR_BASIN
    };
    /// OME-Zarr pyramids (fileName a *.zarr folder): AUTO pages the volume from its pyramid
    /// (out-of-core, lib/volsg/paging) when level 0 exceeds memoryBudget, ON always, OFF never
    /// (level 0 is read whole, as for every other file).
    enum Paging { AUTO, ON, OFF };
    static const EnumValues dataTypeNames, tagDataTypeNames, byteOrderNames, generatorNames,
        pagingNames;

    SFString fileName{this, "fileName", ""};
    SFVec3f dimensions{this, "dimensions", glm::vec3(0.0f)}; ///< raw files and generators
    SFEnum dataType{this, "dataType", dataTypeNames, UBYTE};
    SFEnum byteOrder{this, "byteOrder", byteOrderNames, LITTLE_ENDIAN_ORDER};
    SFUInt32 headerSkip{this, "headerSkip", 0u};
    /// Raw files: the voxel size. NRRD/MetaImage headers and generators give their own unless
    /// this field is set in the scene (Field::isDefault() false).
    SFVec3f spacing{this, "spacing", glm::vec3(1.0f)};
    /// Labels: raw files take tagDataType, the data's dimensions and byteOrder, no headerSkip.
    SFString tagFileName{this, "tagFileName", ""};
    SFEnum tagDataType{this, "tagDataType", tagDataTypeNames, UBYTE};
    SFEnum generator{this, "generator", generatorNames, NONE};
    SFEnum paging{this, "paging", pagingNames, AUTO};
    /// MiB of host memory a paged volume's voxels may take: bricks, decoded chunks and the
    /// coarse levels kept whole (its GPU textures follow the Volume's textureBudget).
    SFUInt32 memoryBudget{this, "memoryBudget", 1024u};

    /// The voxels, loaded on first use and again after a field changes (relative file names
    /// resolve against the folder of the scene file, see readDone). Throws Error naming the
    /// file and the problem. Not thread-safe: call from one thread at a time.
    /// Virtual: a VolumeSeries (a VolumeData) answers with its current time step.
    virtual ref_ptr<const VolumeGrid> grid() const;
    /// The volume box in local coordinates (centred on the local origin, dimensions *
    /// spacing; empty without data); loads the data as grid() does.
    virtual Box3 localBounds() const;
    /// The label volume, or null without tagFileName (or a generator without labels).
    virtual ref_ptr<const VolumeGrid> tagGrid() const;
    /// The pyramid this volume is paged from, or null when it is in memory whole. When paged,
    /// grid() is the stand-in: the finest level of at most 16 MiB (and 1/16 of memoryBudget),
    /// whole, with level 0's box
    /// (PagedVolume::standIn), which whatever needs a whole grid uses (histogram, picking,
    /// the reference ray caster, shear-warp, slices); the Volume node draws every level.
    virtual std::shared_ptr<PagedVolume> pagedVolume() const;
    /// Whether the fields ask for the data to be paged (as pagedVolume() will be), decided
    /// from the pyramid's metadata without reading voxels. Throws Error for an unreadable one.
    bool pagesFromPyramid() const;

    /// Takes `data`, read already from what the fields name, as this node's voxels (the scene
    /// built for a data file reads it once: volumescene/SceneForFile.h); `directory` is where
    /// a relative fileName resolves, as readDone() gives it. A later field change reloads.
    void adoptLoaded(ref_ptr<const VolumeGrid> data, const std::string& directory);

    void readDone(const ReadContext& context) override;
    void doAction(Action& action) override;

protected:
    ~VolumeData() override;

private:
    std::string directory_; ///< of the scene file that named fileName
    mutable ref_ptr<const VolumeGrid> grid_, tags_;
    mutable std::shared_ptr<PagedVolume> paged_;
    mutable std::uint64_t loadedVersion_ = 0;
    void load() const;
    void loadIfChanged() const; ///< load() once per version, errors said of this node
};

} // namespace volsg
