#include <volsg/nodes/Texture2.h>

#include <volsg/actions/Action.h>
#include <volsg/image/TextureFile.h>
#include <volsg/io/ReadContext.h>

namespace volsg {

const EnumValues Texture2::wrapNames{{"REPEAT", REPEAT}, {"CLAMP", CLAMP}};
const EnumValues Texture2::modelNames{
    {"MODULATE", MODULATE}, {"DECAL", DECAL}, {"BLEND", BLEND}, {"REPLACE", REPLACE}};

void Texture2::readDone(const ReadContext& context) {
    directory_ = context.directory;
}

std::string Texture2::path() const {
    return ReadContext{{}, directory_}.resolve(filename());
}

const ImageValue& Texture2::texels() const {
    if (loadedVersion_ != version()) {
        loaded_ = ImageValue{}; // a failed read leaves nothing stale behind
        loaded_ = filename().empty() ? image() : readTextureFile(path());
        loadedVersion_ = version();
    }
    return loaded_;
}

void Texture2::doAction(Action& action) {
    action.state().add(*this);
}

} // namespace volsg
