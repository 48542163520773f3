#pragma once
// Node types for the reader and writer tests: one field of every type, a group of our own, and
// a node that records what the reader told it about its file. None is standard Inventor, so
// all are written with their `fields [...]` description.

#include <string>

#include <volsg/core/Node.h>
#include <volsg/core/NodeType.h>
#include <volsg/fields/Fields.h>
#include <volsg/io/ReadContext.h>
#include <volsg/nodes/Group.h>

namespace volsg::test {

class AllFieldsNode : public Inherit<Node, AllFieldsNode> {
public:
    static constexpr const char* typeName = "AllFieldsNode";
    enum Mode { FIRST = 0, SECOND = 1, THIRD = 7 };
    enum Bits { A = 1, B = 2, C = 4, AB = 3 };
    static inline const EnumValues modeNames{
        {"FIRST", FIRST}, {"SECOND", SECOND}, {"THIRD", THIRD}};
    static inline const EnumValues bitNames{{"A", A}, {"B", B}, {"C", C}, {"AB", AB}};

    SFFloat sfFloat{this, "sfFloat"};
    SFInt32 sfInt32{this, "sfInt32"};
    SFUInt32 sfUInt32{this, "sfUInt32"};
    SFBool sfBool{this, "sfBool"};
    SFString sfString{this, "sfString"};
    SFVec2f sfVec2f{this, "sfVec2f"};
    SFVec3f sfVec3f{this, "sfVec3f"};
    SFVec4f sfVec4f{this, "sfVec4f"};
    SFColor sfColor{this, "sfColor"};
    SFRotation sfRotation{this, "sfRotation"};
    SFPlane sfPlane{this, "sfPlane"};
    SFMatrix sfMatrix{this, "sfMatrix", glm::mat4(1.0f)};
    SFEnum sfEnum{this, "sfEnum", modeNames, FIRST};
    SFBitMask sfBitMask{this, "sfBitMask", bitNames, 0};
    SFNode sfNode{this, "sfNode"};
    MFFloat mfFloat{this, "mfFloat"};
    MFInt32 mfInt32{this, "mfInt32"};
    MFUInt32 mfUInt32{this, "mfUInt32"};
    MFBool mfBool{this, "mfBool"};
    MFString mfString{this, "mfString"};
    MFVec2f mfVec2f{this, "mfVec2f"};
    MFVec3f mfVec3f{this, "mfVec3f"};
    MFVec4f mfVec4f{this, "mfVec4f"};
    MFColor mfColor{this, "mfColor"};
    MFRotation mfRotation{this, "mfRotation"};
    MFPlane mfPlane{this, "mfPlane"};
    MFMatrix mfMatrix{this, "mfMatrix"};
    MFNode mfNode{this, "mfNode"};

protected:
    ~AllFieldsNode() override = default;
};

/// A group type of our own: fields, then children.
class TestGroup : public Inherit<Group, TestGroup> {
public:
    static constexpr const char* typeName = "TestGroup";
    SFFloat weight{this, "weight", 1.0f};

protected:
    ~TestGroup() override = default;
};

/// Resolves its file name at read time, as VolumeData does.
class FileUser : public Inherit<Node, FileUser> {
public:
    static constexpr const char* typeName = "FileUser";
    SFString fileName{this, "fileName"};
    std::string resolved;
    std::string sceneFile;
    int readDoneCalls = 0;

    void readDone(const ReadContext& context) override {
        resolved = context.resolve(fileName());
        sceneFile = context.fileName;
        ++readDoneCalls;
    }

protected:
    ~FileUser() override = default;
};

/// Makes the test types known to the reader (idempotent).
inline void registerTestNodeTypes() {
    NodeRegistry& registry = NodeRegistry::instance();
    registry.add(AllFieldsNode::classType());
    registry.add(TestGroup::classType());
    registry.add(FileUser::classType());
}

} // namespace volsg::test
