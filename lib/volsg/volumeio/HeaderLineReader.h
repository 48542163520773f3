#pragma once
// Bounded line-by-line reading of a text header (NRRD, MetaImage) with number parsing.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <volsg/core/Limits.h>

namespace volsg {

class InputFile;

/// Reads the text lines at the start of a volume file, counting them for error messages.
/// A header is untrusted: a line longer than maxLineLength, a header longer than
/// maxHeaderLength or a NUL byte is an Error, never an unbounded allocation. After the last
/// header line the file is positioned at the first byte that follows it (attached data).
class HeaderLineReader {
public:
    static constexpr std::size_t maxLineLength = limits::maxHeaderLineLength;
    static constexpr std::size_t maxHeaderLength = limits::maxHeaderLength;

    explicit HeaderLineReader(InputFile& file) : file_(file) {}

    /// The next line without its "\n" or "\r\n"; false at the end of the file.
    bool next(std::string& line);
    int lineNumber() const { return lineNumber_; } ///< of the line last returned (1-based)
    const std::string& path() const;

    [[noreturn]] void fail(const std::string& message) const; ///< at the current line

    // Parsers for header values; each throws at the current line, naming `what`.
    std::int64_t parseInteger(std::string_view text, std::string_view what) const;
    double parseNumber(std::string_view text, std::string_view what) const;  ///< finite
    int parseDimension(std::string_view text, std::string_view what) const;  ///< 1 .. INT_MAX
    double parseSpacing(std::string_view text, std::string_view what) const; ///< finite, > 0
    bool parseBool(std::string_view text, std::string_view what) const;      ///< True/False/1/0

    static std::string_view trim(std::string_view text);
    static std::vector<std::string_view> splitWords(std::string_view text);
    static std::string lowercase(std::string_view text);

private:
    InputFile& file_;
    int lineNumber_ = 0;
    std::size_t headerBytes_ = 0;
};

} // namespace volsg
