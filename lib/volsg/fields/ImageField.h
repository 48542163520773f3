#pragma once
// SFImage: an inline image (Inventor's SoSFImage), as Texture2 holds its texels.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/fields/Field.h>

namespace volsg {

/// Width, height, components (1 grey, 2 grey + alpha, 3 RGB, 4 RGBA) and width*height*components
/// bytes, rows bottom up as Inventor stores them. In files: `width height components` then one
/// number per pixel with its components packed high byte first (`0xRRGGBB`).
struct InlineImage {
    glm::ivec2 size{0};
    int components = 0;
    std::vector<std::uint8_t> bytes;
    bool empty() const { return size.x <= 0 || size.y <= 0 || components <= 0; }
    bool operator==(const InlineImage&) const = default;
};

class SFImage final : public Field {
public:
    SFImage(Node* owner, const char* name) : Field(owner, name) {}
    const InlineImage& getValue() const { return value_; }
    const InlineImage& operator()() const { return value_; }
    /// Throws Error for a size or component count out of range, or bytes that do not match.
    void setValue(InlineImage image);

    const char* typeName() const override { return "SFImage"; }
    void read(FieldInput& in) override;
    void write(FieldOutput& out) const override;
    bool equals(const Field& other) const override;
    void copyFrom(const Field& other) override;

private:
    InlineImage value_;
};

} // namespace volsg
