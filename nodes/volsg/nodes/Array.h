#pragma once
// Array: draws its children numElements1 x numElements2 x numElements3 times, copy (i, j, k)
// translated by i * separation1 + j * separation2 + k * separation3 (FIRST: the first copy at
// the origin; CENTER: the array centred on it; LAST: the last copy at it, the others at
// negative multiples). Each copy is separated: state changes stay in it (Inventor's SoArray).
#include <cstddef>

#include <volsg/fields/Fields.h>
#include <volsg/nodes/Group.h>

namespace volsg {

class Array : public Inherit<Group, Array> {
public:
    static constexpr const char* typeName = "Array";
    static constexpr bool inventorBuiltin() { return true; }
    enum Origin { FIRST, CENTER, LAST };
    static const EnumValues originNames;
    /// Most copies one Array draws (numElements1 x 2 x 3); more is an Error when traversed.
    static constexpr std::size_t maxCopies = std::size_t(1) << 20;

    SFEnum origin{this, "origin", originNames, FIRST};
    SFInt32 numElements1{this, "numElements1", 1}; ///< Inventor's SFShort; below 1: no copies
    SFInt32 numElements2{this, "numElements2", 1};
    SFInt32 numElements3{this, "numElements3", 1};
    SFVec3f separation1{this, "separation1", glm::vec3(1.0f, 0.0f, 0.0f)};
    SFVec3f separation2{this, "separation2", glm::vec3(0.0f, 1.0f, 0.0f)};
    SFVec3f separation3{this, "separation3", glm::vec3(0.0f, 0.0f, 1.0f)};

    /// The translation of copy (i, j, k), i counting along separation1.
    glm::dvec3 offset(int i, int j, int k) const;
    void doAction(Action& action) override;

protected:
    ~Array() override = default;
};

} // namespace volsg
