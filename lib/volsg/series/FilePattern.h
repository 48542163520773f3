#pragma once
// A printf-style file-name pattern for the steps of a volume series ("step_%04d.nrrd").
#include <string>

namespace volsg {

/// Exactly one integer conversion `%d` or `%i` with an optional `0` flag and a width of at most
/// 9 digits, plus any number of literal `%%`. Everything else is refused with an Error that
/// quotes the pattern: other conversions (`%s`, `%n`, `%x`, ...), flags, precisions, length
/// modifiers, a second conversion, a `%` at the end. Formatting never calls printf, so a
/// pattern from a file cannot read or write memory.
class FilePattern {
public:
    /// Throws Error for a malformed pattern (see the class comment) or one without conversion.
    explicit FilePattern(std::string pattern);

    /// The file name of step number `number` (any int, negative numbers get a '-').
    std::string format(int number) const;
    const std::string& pattern() const { return pattern_; }

private:
    std::string pattern_;
    std::string prefix_, suffix_; ///< literal text around the conversion, `%%` already undone
    int width_ = 0;
    bool zeroPad_ = false;
};

} // namespace volsg
