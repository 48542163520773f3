#include <volsg/actions/Action.h>
#include <volsg/nodes/Bindings.h>

namespace volsg {

EnumValues bindingNames(int defaultValue) {
    return EnumValues{{"OVERALL", OVERALL},
                      {"PER_PART", PER_PART},
                      {"PER_PART_INDEXED", PER_PART_INDEXED},
                      {"PER_FACE", PER_FACE},
                      {"PER_FACE_INDEXED", PER_FACE_INDEXED},
                      {"PER_VERTEX", PER_VERTEX},
                      {"PER_VERTEX_INDEXED", PER_VERTEX_INDEXED},
                      {"DEFAULT", defaultValue},
                      {"NONE", defaultValue}};
}

Binding toBinding(int value) {
    switch (value) {
    case PER_PART:
        return Binding::PerPart;
    case PER_PART_INDEXED:
        return Binding::PerPartIndexed;
    case PER_FACE:
        return Binding::PerFace;
    case PER_FACE_INDEXED:
        return Binding::PerFaceIndexed;
    case PER_VERTEX:
        return Binding::PerVertex;
    case PER_VERTEX_INDEXED:
        return Binding::PerVertexIndexed;
    default:
        return Binding::Overall;
    }
}

const EnumValues MaterialBinding::valueNames = bindingNames(OVERALL);
const EnumValues NormalBinding::valueNames = bindingNames(PER_VERTEX_INDEXED);
const EnumValues TextureCoordinateBinding::valueNames{{"PER_VERTEX", PER_VERTEX},
                                                      {"PER_VERTEX_INDEXED", PER_VERTEX_INDEXED},
                                                      {"DEFAULT", PER_VERTEX_INDEXED}};

void MaterialBinding::doAction(Action& action) {
    action.state().add(*this);
}
void NormalBinding::doAction(Action& action) {
    action.state().add(*this);
}
void TextureCoordinateBinding::doAction(Action& action) {
    action.state().add(*this);
}

} // namespace volsg
