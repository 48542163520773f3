// Property nodes that only put themselves in scope; renderers read them from the State.
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include <volsg/actions/Action.h>
#include <volsg/nodes/BaseColor.h>
#include <volsg/nodes/ClipPlane.h>
#include <volsg/nodes/Complexity.h>
#include <volsg/nodes/Coordinate3.h>
#include <volsg/nodes/Coordinate4.h>
#include <volsg/nodes/DrawStyle.h>
#include <volsg/nodes/Environment.h>
#include <volsg/nodes/Light.h>
#include <volsg/nodes/Material.h>
#include <volsg/nodes/Normal.h>
#include <volsg/nodes/ShapeHints.h>
#include <volsg/nodes/Texture2Transform.h>
#include <volsg/nodes/TextureCoordinate2.h>
#include <volsg/nodes/TextureCoordinateDefault.h>
#include <volsg/nodes/TextureCoordinateEnvironment.h>
#include <volsg/nodes/TextureCoordinatePlane.h>
#include <volsg/nodes/VertexProperty.h>

namespace volsg {

void Material::doAction(Action& action) {
    action.state().add(*this);
}
void Coordinate3::doAction(Action& action) {
    action.state().add(*this);
}
void Normal::doAction(Action& action) {
    action.state().add(*this);
}
void Light::doAction(Action& action) {
    if (on()) action.state().add(*this);
}
void ClipPlane::doAction(Action& action) {
    if (on()) action.state().add(*this);
}

#define VOLSG_IN_SCOPE(Type)                                                                       \
    void Type::doAction(Action& action) {                                                          \
        action.state().add(*this);                                                                 \
    }
VOLSG_IN_SCOPE(BaseColor)
VOLSG_IN_SCOPE(Complexity)
VOLSG_IN_SCOPE(Coordinate4)
VOLSG_IN_SCOPE(DrawStyle)
VOLSG_IN_SCOPE(Environment)
VOLSG_IN_SCOPE(ShapeHints)
VOLSG_IN_SCOPE(Texture2Transform)
VOLSG_IN_SCOPE(TextureCoordinate2)
VOLSG_IN_SCOPE(TextureCoordinateDefault)
VOLSG_IN_SCOPE(TextureCoordinateEnvironment)
VOLSG_IN_SCOPE(TextureCoordinatePlane)
VOLSG_IN_SCOPE(VertexProperty)
#undef VOLSG_IN_SCOPE

const EnumValues ShapeHints::vertexOrderingNames{{"UNKNOWN_ORDERING", UNKNOWN_ORDERING},
                                                 {"CLOCKWISE", CLOCKWISE},
                                                 {"COUNTERCLOCKWISE", COUNTERCLOCKWISE}};
const EnumValues ShapeHints::shapeTypeNames{{"UNKNOWN_SHAPE_TYPE", UNKNOWN_SHAPE_TYPE},
                                            {"SOLID", SOLID}};
const EnumValues ShapeHints::faceTypeNames{{"UNKNOWN_FACE_TYPE", UNKNOWN_FACE_TYPE},
                                           {"CONVEX", CONVEX}};
const EnumValues DrawStyle::styleNames{
    {"FILLED", FILLED}, {"LINES", LINES}, {"POINTS", POINTS}, {"INVISIBLE", INVISIBLE}};
const EnumValues Complexity::typeNames{
    {"OBJECT_SPACE", OBJECT_SPACE}, {"SCREEN_SPACE", SCREEN_SPACE}, {"BOUNDING_BOX", BOUNDING_BOX}};
const EnumValues Environment::fogTypeNames{
    {"NONE", NONE}, {"HAZE", HAZE}, {"FOG", FOG}, {"SMOKE", SMOKE}};
const EnumValues VertexProperty::normalBindingNames = bindingNames(PER_VERTEX_INDEXED);
const EnumValues VertexProperty::materialBindingNames = bindingNames(OVERALL);

glm::mat4 Texture2Transform::matrix() const {
    const glm::vec3 c(center(), 0.0f);
    glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(translation(), 0.0f) + c);
    m = glm::rotate(m, rotation(), glm::vec3(0.0f, 0.0f, 1.0f));
    m = glm::scale(m, glm::vec3(scaleFactor(), 1.0f));
    return glm::translate(m, -c);
}

glm::vec4 unpackRGBA(std::uint32_t packed) {
    return glm::vec4(float((packed >> 24) & 0xFF), float((packed >> 16) & 0xFF),
                     float((packed >> 8) & 0xFF), float(packed & 0xFF)) /
           255.0f;
}

glm::dvec4 ClipPlane::worldPlane(const Plane& local, const glm::dmat4& model) {
    // A plane as a covector transforms by the inverse transpose: (n, -d) * M^-1.
    const glm::dvec4 p(glm::dvec3(local.normal), -double(local.distance));
    const glm::dvec4 w = glm::transpose(glm::inverse(model)) * p;
    return {w.x, w.y, w.z, -w.w};
}

} // namespace volsg
