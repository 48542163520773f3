#include <volsg/core/Error.h>
#include <volsg/core/Limits.h>
#include <volsg/io/BinaryInput.h>

#include <bit>
#include <cmath>
#include <cstring>

namespace volsg {

BinaryInput::BinaryInput(std::string_view data, std::string fileName, std::size_t baseOffset,
                         float version)
    : data_(data), fileName_(std::move(fileName)), baseOffset_(baseOffset), version_(version) {}

void BinaryInput::failAt(std::size_t offset, const std::string& message) const {
    lastErrorOffset_ = offset;
    lastErrorMessage_ = message;
    throw Error("byte " + std::to_string(offset) + ": " + message, fileName_);
}

void BinaryInput::require(std::size_t n, const char* what) {
    if (n > remaining())
        fail(std::string("unexpected end of file: ") + what + " needs " + std::to_string(n) +
             " bytes, " + std::to_string(remaining()) + " left");
}

void BinaryInput::requireItems(std::uint64_t count, std::size_t bytesEach, const char* what,
                               std::size_t countAt) {
    if (bytesEach != 0 && count > remaining() / bytesEach)
        failAt(countAt, std::string(what) + ": " + std::to_string(count) + " values of at least " +
                            std::to_string(bytesEach) + " bytes each do not fit in the " +
                            std::to_string(remaining()) + " bytes left in the file");
}

std::uint32_t BinaryInput::readUInt32(const char* what) {
    require(4, what);
    const auto* p = reinterpret_cast<const unsigned char*>(data_.data() + pos_);
    pos_ += 4;
    return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) |
           std::uint32_t(p[3]);
}

std::int32_t BinaryInput::readInt32(const char* what) {
    return static_cast<std::int32_t>(readUInt32(what));
}

float BinaryInput::readFloat(const char* what) {
    const std::size_t at = offset();
    const float v = std::bit_cast<float>(readUInt32(what));
    if (!std::isfinite(v)) failAt(at, std::string(what) + " is not a finite number");
    return v;
}

double BinaryInput::readDouble(const char* what) {
    const std::size_t at = offset();
    const std::uint64_t high = readUInt32(what);
    const std::uint64_t low = readUInt32(what);
    const double v = std::bit_cast<double>((high << 32) | low);
    if (!std::isfinite(v)) failAt(at, std::string(what) + " is not a finite number");
    return v;
}

std::string BinaryInput::readString(const char* what) {
    const std::size_t at = offset();
    const std::uint32_t length = readUInt32(what);
    if (length > limits::maxStringLength)
        failAt(at, std::string(what) + ": a string of " + std::to_string(length) +
                       " bytes, more than the limit of " + std::to_string(limits::maxStringLength));
    const std::size_t padded = (std::size_t(length) + 3) / 4 * 4;
    if (padded > remaining())
        failAt(at, std::string("unexpected end of file: ") + what + " is a string of " +
                       std::to_string(length) + " bytes, " + std::to_string(remaining()) + " left");
    std::string s(data_.substr(pos_, length));
    pos_ += padded;
    return s;
}

std::string BinaryInput::readBytes(std::size_t n, const char* what) {
    require(n, what);
    std::string s(data_.substr(pos_, n));
    pos_ += n;
    return s;
}

void BinaryInput::skip(std::size_t n, const char* what) {
    require(n, what);
    pos_ += n;
}

} // namespace volsg
