#pragma once
// A bounds-checked cursor over the bytes of a binary Inventor file (docs/SCENE-FORMAT.md
// section 1.9): big-endian 32-bit words, 64-bit doubles and length-prefixed strings padded to
// four bytes, each checked against the bytes left before anything is read or allocated.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace volsg {

/// Errors are one volsg::Error, `file: byte N: message`, N the offset in the file of the item
/// at fault (the header counts: the first item after `#Inventor V2.1 binary  \n` is byte 24).
class BinaryInput {
public:
    /// `data` is the file after its header line, which started `baseOffset` bytes earlier in
    /// the file; `version` is 2.0 or 2.1 (the layouts differ a little, section 1.9).
    BinaryInput(std::string_view data, std::string fileName, std::size_t baseOffset, float version);

    float version() const { return version_; }
    const std::string& fileName() const { return fileName_; }
    /// The offset in the file of the next byte.
    std::size_t offset() const { return baseOffset_ + pos_; }
    std::size_t remaining() const { return data_.size() - pos_; }
    bool atEnd() const { return pos_ >= data_.size(); }

    std::uint32_t readUInt32(const char* what);
    std::int32_t readInt32(const char* what);
    float readFloat(const char* what);   ///< finite only
    double readDouble(const char* what); ///< finite only
    /// A string: its byte count as a 32-bit word, then the bytes, padded to a multiple of 4.
    std::string readString(const char* what);
    /// `n` raw bytes (then `pad` more that are skipped).
    std::string readBytes(std::size_t n, const char* what);
    void skip(std::size_t n, const char* what);
    /// Throws unless `count` items of at least `bytesEach` bytes fit in what is left: a count
    /// read from the file is checked here before anything is allocated for it. The error is
    /// placed at `countAt`, the offset of the count.
    void requireItems(std::uint64_t count, std::size_t bytesEach, const char* what,
                      std::size_t countAt);

    /// Throws `file: byte <offset>: message`.
    [[noreturn]] void failAt(std::size_t offset, const std::string& message) const;
    [[noreturn]] void fail(const std::string& message) const { failAt(offset(), message); }

    /// Where the last error of this input was and what it said without the position, so a
    /// caller can add context ("field 'x' of Cube expects SFFloat: ...") at the same offset.
    std::size_t lastErrorOffset() const { return lastErrorOffset_; }
    const std::string& lastErrorMessage() const { return lastErrorMessage_; }

private:
    void require(std::size_t n, const char* what);
    std::string_view data_;
    std::string fileName_;
    std::size_t baseOffset_;
    float version_;
    std::size_t pos_ = 0;
    mutable std::size_t lastErrorOffset_ = 0;
    mutable std::string lastErrorMessage_;
};

} // namespace volsg
