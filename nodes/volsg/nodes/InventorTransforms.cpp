// The transform nodes of Inventor besides Transform and MatrixTransform: Translation,
// Rotation, RotationXYZ, Scale, TransformSeparator and Units.
#include <volsg/actions/Action.h>
#include <volsg/nodes/Rotation.h>
#include <volsg/nodes/RotationXYZ.h>
#include <volsg/nodes/Scale.h>
#include <volsg/nodes/TransformSeparator.h>
#include <volsg/nodes/Translation.h>
#include <volsg/nodes/Units.h>

#include <glm/gtc/matrix_transform.hpp>

namespace volsg {

void Translation::doAction(Action& action) {
    action.state().multModelMatrix(glm::translate(glm::dmat4(1.0), glm::dvec3(translation())));
}

void RotationNode::doAction(Action& action) {
    action.state().multModelMatrix(rotation().matrix());
}

const EnumValues RotationXYZ::axisNames{{"X", X}, {"Y", Y}, {"Z", Z}};

glm::dmat4 RotationXYZ::matrix() const {
    glm::dvec3 unit(0.0);
    const int a = axis();
    if (a < X || a > Z) return glm::dmat4(1.0); // an integer outside the enum: no rotation
    unit[a] = 1.0;
    return glm::rotate(glm::dmat4(1.0), double(angle()), unit);
}

void RotationXYZ::doAction(Action& action) {
    action.state().multModelMatrix(matrix());
}

void Scale::doAction(Action& action) {
    action.state().multModelMatrix(glm::scale(glm::dmat4(1.0), glm::dvec3(scaleFactor())));
}

void TransformSeparator::doAction(Action& action) {
    const glm::dmat4 saved = action.state().modelMatrix();
    Group::doAction(action);
    action.state().setModelMatrix(saved);
}

const EnumValues Units::unitNames{{"METERS", METERS},
                                  {"CENTIMETERS", CENTIMETERS},
                                  {"MILLIMETERS", MILLIMETERS},
                                  {"MICROMETERS", MICROMETERS},
                                  {"MICRONS", MICRONS},
                                  {"NANOMETERS", NANOMETERS},
                                  {"ANGSTROMS", ANGSTROMS},
                                  {"KILOMETERS", KILOMETERS},
                                  {"FEET", FEET},
                                  {"INCHES", INCHES},
                                  {"POINTS", POINTS},
                                  {"YARDS", YARDS},
                                  {"MILES", MILES},
                                  {"NAUTICAL_MILES", NAUTICAL_MILES}};

double Units::metersPer(int unit) {
    // Coin's SoUnits table (src/nodes/SoUnits.cpp), as decimal numbers.
    static constexpr double meters[] = {1.0,           0.01,   0.001,  1e-6,   1e-6,
                                        1e-9,          1e-10,  1000.0, 0.3048, 0.0254,
                                        3.52777737e-4, 0.9144, 1609.3, 1852.0};
    if (unit < 0 || unit >= int(std::size(meters))) return 1.0;
    return meters[unit];
}

int Units::inScope(const State& state) {
    const Units* units = state.nearestNode<Units>();
    return units ? units->units() : METERS;
}

void Units::doAction(Action& action) {
    State& state = action.state();
    const int current = inScope(state);
    if (current == units()) return; // as Coin: the same unit again changes nothing
    const double ratio = metersPer(units()) / metersPer(current);
    state.add(*this);
    state.multModelMatrix(glm::scale(glm::dmat4(1.0), glm::dvec3(ratio)));
}

} // namespace volsg
