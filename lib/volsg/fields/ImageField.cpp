#include <volsg/fields/ImageField.h>

#include <ostream>
#include <string>

#include <volsg/core/Error.h>
#include <volsg/core/Limits.h>
#include <volsg/io/Tokenizer.h>

namespace volsg {

namespace {

void checkShape(const InlineImage& image) {
    if (image.size.x < 0 || image.size.y < 0 || image.components < 0 || image.components > 4)
        throw Error("an image needs a size of at least 0 x 0 and 0 to 4 components");
    if (std::uint32_t(image.size.x) > limits::maxImageSide ||
        std::uint32_t(image.size.y) > limits::maxImageSide ||
        std::uint64_t(image.size.x) * std::uint64_t(image.size.y) > limits::maxImagePixels)
        throw Error("an image of " + std::to_string(image.size.x) + " x " +
                    std::to_string(image.size.y) + " pixels is larger than the limit");
}

} // namespace

void SFImage::setValue(InlineImage image) {
    checkShape(image);
    const std::size_t expected =
        std::size_t(image.size.x) * std::size_t(image.size.y) * std::size_t(image.components);
    if (image.bytes.size() != expected)
        throw Error("an image of " + std::to_string(image.size.x) + " x " +
                    std::to_string(image.size.y) + " x " + std::to_string(image.components) +
                    " needs " + std::to_string(expected) + " bytes, got " +
                    std::to_string(image.bytes.size()));
    value_ = std::move(image);
    changed();
}

void SFImage::read(FieldInput& in) {
    Tokenizer& tokens = in.tokens();
    const Token first = tokens.peek();
    InlineImage image;
    image.size.x = tokens.readInt32();
    image.size.y = tokens.readInt32();
    image.components = tokens.readInt32();
    try {
        checkShape(image);
    } catch (const Error& e) {
        tokens.failAt(first, e.message());
    }
    if (image.empty()) image = InlineImage{};
    const std::size_t pixels = std::size_t(image.size.x) * std::size_t(image.size.y);
    // Each pixel is at least one token of the file, so the tokens left bound the allocation.
    image.bytes.reserve(std::min<std::size_t>(pixels, limits::maxFieldValues) *
                        std::size_t(image.components));
    for (std::size_t p = 0; p < pixels; ++p) {
        const Token& at = tokens.peek();
        if (at.kind == Token::Kind::End)
            tokens.failAt(at, "unexpected end of file: the image needs " + std::to_string(pixels) +
                                  " pixels, found " + std::to_string(p));
        const std::uint32_t packed = tokens.readUInt32();
        for (int c = image.components - 1; c >= 0; --c)
            image.bytes.push_back(std::uint8_t(packed >> (8 * c)));
    }
    value_ = std::move(image);
    changed();
}

void SFImage::write(FieldOutput& out) const {
    std::ostream& os = out.stream();
    os << value_.size.x << ' ' << value_.size.y << ' ' << value_.components;
    const std::size_t pixels = value_.empty() ? 0 : std::size_t(value_.size.x) * value_.size.y;
    static constexpr char hex[] = "0123456789abcdef";
    for (std::size_t p = 0; p < pixels; ++p) {
        if (p % 8 == 0)
            out.newline();
        else
            os << ' ';
        os << "0x";
        for (int c = 0; c < value_.components; ++c) {
            const std::uint8_t b =
                value_.bytes[p * std::size_t(value_.components) + std::size_t(c)];
            os << hex[b >> 4] << hex[b & 15];
        }
    }
}

bool SFImage::equals(const Field& other) const {
    const auto* o = dynamic_cast<const SFImage*>(&other);
    return o && o->value_ == value_;
}

void SFImage::copyFrom(const Field& other) {
    value_ = dynamic_cast<const SFImage&>(other).value_;
    changed();
}

} // namespace volsg
