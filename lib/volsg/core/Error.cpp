#include <volsg/core/Error.h>

#include <string_view>

namespace volsg {

namespace {

/// Length of the valid UTF-8 sequence at `s[i]`, or 0 if there is none.
std::size_t utf8SequenceLength(const std::string& s, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char c = byte(i);
    std::size_t n = c < 0x80           ? 1
                    : (c >> 5) == 0x6  ? 2
                    : (c >> 4) == 0xE  ? 3
                    : (c >> 3) == 0x1E ? 4
                                       : 0;
    if (n == 0 || i + n > s.size() || (n == 2 && c < 0xC2)) return 0;
    for (std::size_t k = 1; k < n; ++k)
        if ((byte(i + k) >> 6) != 0x2) return 0;
    if (n == 3 && ((c == 0xE0 && byte(i + 1) < 0xA0) || (c == 0xED && byte(i + 1) >= 0xA0)))
        return 0; // overlong or a surrogate
    if (n == 4 &&
        ((c == 0xF0 && byte(i + 1) < 0x90) || c > 0xF4 || (c == 0xF4 && byte(i + 1) >= 0x90)))
        return 0;
    return n;
}

/// The text with control characters and bytes that are not UTF-8 written as \xNN: bad input
/// quoted in a message must not garble a terminal or a log (what() is one printable line).
std::string printable(const std::string& text) {
    static constexpr char hex[] = "0123456789ABCDEF";
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        const std::size_t n = utf8SequenceLength(text, i);
        if (n == 0 || c < 0x20 || c == 0x7F) {
            out += "\\x";
            out += hex[c >> 4];
            out += hex[c & 0xF];
            ++i;
        } else {
            out.append(text, i, n);
            i += n;
        }
    }
    return out;
}

/// At most Error::kMaxMessageLength characters: the start and the end of a longer text, so a
/// message quoting a huge value (a 3 MB data: URI) stays one readable line.
std::string bounded(std::string text) {
    constexpr std::size_t max = Error::kMaxMessageLength;
    if (text.size() <= max) return text;
    constexpr std::string_view cut = " [...] ";
    const std::size_t head = (max - cut.size()) * 2 / 3, tail = max - cut.size() - head;
    return text.substr(0, head) + std::string(cut) + text.substr(text.size() - tail);
}

std::string format(const std::string& message, const std::string& file, int line, int column) {
    std::string where = file;
    if (line > 0) {
        where += (where.empty() ? "" : ":") + std::to_string(line);
        if (column > 0) where += ":" + std::to_string(column);
    }
    return bounded(printable(where.empty() ? message : where + ": " + message));
}
} // namespace

Error::Error(std::string message, std::string file, int line, int column)
    : std::runtime_error(format(message, file, line, column)), message_(std::move(message)),
      file_(std::move(file)), line_(line), column_(column) {}

Error Error::atSceneNode(const std::exception& inner, const std::string& node,
                         const std::string& file, int line, int column) {
    // A message that starts by naming its node ("Array 'N4' has ...") is not prefixed again.
    const std::string_view what = inner.what();
    const bool named = what.starts_with(node) && what.size() > node.size() &&
                       (what[node.size()] == ' ' || what[node.size()] == ':');
    Error e(named ? std::string(what) : node + ": " + std::string(what), file, line, column);
    e.namesSceneNode_ = true;
    return e;
}

} // namespace volsg
