#pragma once
// Units: the unit of length of what follows it. The model matrix is scaled by the ratio of
// this unit to the one in scope before it (meters at the top), so CENTIMETERS under METERS
// scales by 0.01 (Inventor's SoUnits, with Coin's factors).
#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class State;

class Units : public Inherit<Node, Units> {
public:
    static constexpr const char* typeName = "Units";
    static constexpr bool inventorBuiltin() { return true; }
    enum Unit {
        METERS,
        CENTIMETERS,
        MILLIMETERS,
        MICROMETERS,
        MICRONS,
        NANOMETERS,
        ANGSTROMS,
        KILOMETERS,
        FEET,
        INCHES,
        POINTS,
        YARDS,
        MILES,
        NAUTICAL_MILES
    };
    static const EnumValues unitNames;

    SFEnum units{this, "units", unitNames, METERS};

    /// Meters per unit (Coin's table); 1 for a value outside the enum.
    static double metersPer(int unit);
    /// The unit in scope at the current node (METERS when no Units node is).
    static int inScope(const State& state);
    void doAction(Action& action) override;

protected:
    ~Units() override = default;
};

} // namespace volsg
