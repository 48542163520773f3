#include <volsg/series/FilePattern.h>

#include <volsg/core/Error.h>

namespace volsg {

namespace {

constexpr int kMaxWidth = 9; // wider fields only make absurd names (and huge allocations)

[[noreturn]] void refuse(const std::string& pattern, const std::string& why) {
    throw Error("series file pattern \"" + pattern + "\": " + why);
}

} // namespace

FilePattern::FilePattern(std::string pattern) : pattern_(std::move(pattern)) {
    bool converted = false;
    std::string* out = &prefix_;
    for (std::size_t i = 0; i < pattern_.size(); ++i) {
        const char c = pattern_[i];
        if (c != '%') {
            out->push_back(c);
            continue;
        }
        if (++i == pattern_.size()) refuse(pattern_, "ends with a lone '%'");
        if (pattern_[i] == '%') {
            out->push_back('%');
            continue;
        }
        if (converted) refuse(pattern_, "has more than one conversion (write %% for a '%')");
        if (pattern_[i] == '0') {
            zeroPad_ = true;
            ++i;
        }
        int digits = 0;
        while (i < pattern_.size() && pattern_[i] >= '0' && pattern_[i] <= '9') {
            if (++digits > 1 && width_ == 0) refuse(pattern_, "has a malformed width");
            width_ = width_ * 10 + (pattern_[i] - '0');
            if (width_ > kMaxWidth)
                refuse(pattern_, "has a width above " + std::to_string(kMaxWidth));
            ++i;
        }
        if (i == pattern_.size()) refuse(pattern_, "ends inside a conversion");
        if (pattern_[i] != 'd' && pattern_[i] != 'i')
            refuse(pattern_, std::string("has the conversion '%") + pattern_[i] +
                                 "': only %d or %i (with an optional 0 flag and width) is allowed");
        converted = true;
        out = &suffix_;
    }
    if (!converted) refuse(pattern_, "has no %d conversion for the step number");
}

std::string FilePattern::format(int number) const {
    const long long value = number; // no overflow negating INT_MIN
    std::string digits = std::to_string(value < 0 ? -value : value);
    const std::size_t sign = value < 0 ? 1 : 0;
    std::string field;
    if (digits.size() + sign < std::size_t(width_)) {
        const std::size_t pad = std::size_t(width_) - digits.size() - sign;
        if (zeroPad_)
            field = std::string(sign ? "-" : "") + std::string(pad, '0') + digits;
        else
            field = std::string(pad, ' ') + (sign ? "-" : "") + digits;
    } else {
        field = (sign ? "-" : "") + digits;
    }
    return prefix_ + field + suffix_;
}

} // namespace volsg
