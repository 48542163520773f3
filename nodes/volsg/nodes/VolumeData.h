#pragma once
// VolumeData: the voxels (and optional labels) that the Volume and ShearWarpVolume nodes after
// it in scope render. Read from a file (SCENE-FORMAT.md section 3) or generated (test volumes).
#include <string>

#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class VolumeGrid;

class VolumeData : public Inherit<Node, VolumeData> {
public:
    static constexpr const char* typeName = "VolumeData";
    enum DataType { UBYTE, USHORT, SHORT, FLOAT };
    enum ByteOrder { LITTLE_ENDIAN_ORDER, BIG_ENDIAN_ORDER };
    /// Generated test volumes (lib/volsg/volume/TestVolumes.h); NONE reads fileName.
    enum Generator { NONE, MARSCHNER_LOBB, SOFT_SPHERE, THIN_SHELL, RAMP16, LABELLED };
    static const EnumValues dataTypeNames, tagDataTypeNames, byteOrderNames, generatorNames;

    SFString fileName{this, "fileName", ""};
    SFVec3f dimensions{this, "dimensions", glm::vec3(0.0f)}; ///< raw files and generators
    SFEnum dataType{this, "dataType", dataTypeNames, UBYTE};
    SFEnum byteOrder{this, "byteOrder", byteOrderNames, LITTLE_ENDIAN_ORDER};
    SFUInt32 headerSkip{this, "headerSkip", 0u};
    SFVec3f spacing{this, "spacing", glm::vec3(1.0f)}; ///< from the header where it has one
    SFString tagFileName{this, "tagFileName", ""};
    SFEnum tagDataType{this, "tagDataType", tagDataTypeNames, UBYTE};
    SFEnum generator{this, "generator", generatorNames, NONE};

    /// The voxels, loaded on first use and again after a field changes. Throws Error naming
    /// the file and the problem.
    ref_ptr<const VolumeGrid> grid() const;
    /// The label volume, or null without tagFileName (or a generator without labels).
    ref_ptr<const VolumeGrid> tagGrid() const;

    void readDone(const ReadContext& context) override;
    void doAction(Action& action) override;

protected:
    ~VolumeData() override;

private:
    std::string directory_; ///< of the scene file that named fileName
    mutable ref_ptr<const VolumeGrid> grid_, tags_;
    mutable std::uint64_t loadedVersion_ = 0;
    void load() const;
};

} // namespace volsg
