#pragma once
// Texture2: the texture of the shapes after it (Inventor's SoTexture2): an image file (SGI
// .rgb, PNG, JPEG and the other formats libsimage reads), resolved against the scene file's
// folder, or an inline image; how it wraps and how it combines with the lit colour.
#include <memory>
#include <string>

#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class Texture2 : public Inherit<Node, Texture2> {
public:
    static constexpr const char* typeName = "Texture2";
    static constexpr bool inventorBuiltin() { return true; }
    enum Wrap { REPEAT, CLAMP };
    enum Model { MODULATE, DECAL, BLEND, REPLACE };
    static const EnumValues wrapNames, modelNames;

    SFString filename{this, "filename", ""};
    SFImage image{this, "image"};
    SFEnum wrapS{this, "wrapS", wrapNames, REPEAT};
    SFEnum wrapT{this, "wrapT", wrapNames, REPEAT};
    SFEnum model{this, "model", modelNames, MODULATE};
    SFColor blendColor{this, "blendColor", glm::vec3(0.0f)};

    /// The texels: the file when filename is set, else the inline image (empty: no texture).
    /// Read on first use and again after a field changes. Throws Error naming the file.
    const ImageValue& texels() const;
    /// filename resolved against the scene file's folder.
    std::string path() const;

    void readDone(const ReadContext& context) override;
    void doAction(Action& action) override;

protected:
    ~Texture2() override = default;

private:
    std::string directory_;
    mutable ImageValue loaded_;
    mutable std::uint64_t loadedVersion_ = 0;
};

} // namespace volsg
