#include <volsg/volumeio/HeaderLineReader.h>

#include <charconv>
#include <cmath>
#include <limits>

#include <volsg/volumeio/InputFile.h>

namespace volsg {

bool HeaderLineReader::next(std::string& line) {
    line.clear();
    int c = file_.getByte();
    if (c < 0) return false;
    ++lineNumber_;
    for (; c >= 0 && c != '\n'; c = file_.getByte()) {
        if (c == 0) fail("binary data in the header (a header line holds a NUL byte)");
        if (line.size() >= maxLineLength)
            fail("header line longer than " + std::to_string(maxLineLength) + " bytes");
        if (++headerBytes_ > maxHeaderLength)
            fail("header longer than " + std::to_string(maxHeaderLength) + " bytes");
        line.push_back(char(c));
    }
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return true;
}

const std::string& HeaderLineReader::path() const {
    return file_.path();
}

void HeaderLineReader::fail(const std::string& message) const {
    file_.fail(message, lineNumber_);
}

std::int64_t HeaderLineReader::parseInteger(std::string_view text, std::string_view what) const {
    text = trim(text);
    std::int64_t value = 0;
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec == std::errc::result_out_of_range)
        fail(std::string(what) + " '" + std::string(text) + "' is out of range");
    if (ec != std::errc() || ptr != end || text.empty())
        fail("malformed " + std::string(what) + ": expected an integer, got '" + std::string(text) +
             "'");
    return value;
}

double HeaderLineReader::parseNumber(std::string_view text, std::string_view what) const {
    text = trim(text);
    if (!text.empty() && text.front() == '+') text.remove_prefix(1); // from_chars refuses '+'
    double value = 0.0;
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || ptr != end || text.empty())
        fail("malformed " + std::string(what) + ": expected a number, got '" + std::string(text) +
             "'");
    if (!std::isfinite(value))
        fail(std::string(what) + " must be a finite number, got '" + std::string(text) + "'");
    return value;
}

int HeaderLineReader::parseDimension(std::string_view text, std::string_view what) const {
    const std::int64_t n = parseInteger(text, what);
    if (n < 1 || n > std::numeric_limits<int>::max())
        fail(std::string(what) + " " + std::to_string(n) + " is out of range (1 .. " +
             std::to_string(std::numeric_limits<int>::max()) + ")");
    return int(n);
}

double HeaderLineReader::parseSpacing(std::string_view text, std::string_view what) const {
    text = trim(text);
    // Checked here rather than by parseNumber so that "nan" reads as an absurd spacing.
    if (lowercase(text).find("nan") != std::string::npos)
        fail(std::string(what) + " must be finite and > 0, got '" + std::string(text) + "'");
    const double s = parseNumber(text, what);
    if (!(s > 0.0))
        fail(std::string(what) + " must be finite and > 0, got '" + std::string(text) + "'");
    return s;
}

bool HeaderLineReader::parseBool(std::string_view text, std::string_view what) const {
    const std::string v = lowercase(trim(text));
    if (v == "true" || v == "1") return true;
    if (v == "false" || v == "0") return false;
    fail("malformed " + std::string(what) + ": expected True or False, got '" + std::string(text) +
         "'");
}

std::string_view HeaderLineReader::trim(std::string_view text) {
    const auto space = [](char c) {
        return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
    };
    while (!text.empty() && space(text.front()))
        text.remove_prefix(1);
    while (!text.empty() && space(text.back()))
        text.remove_suffix(1);
    return text;
}

std::vector<std::string_view> HeaderLineReader::splitWords(std::string_view text) {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && (text[i] == ' ' || text[i] == '\t'))
            ++i;
        const std::size_t start = i;
        while (i < text.size() && text[i] != ' ' && text[i] != '\t')
            ++i;
        if (i > start) words.push_back(text.substr(start, i - start));
    }
    return words;
}

std::string HeaderLineReader::lowercase(std::string_view text) {
    std::string out(text);
    for (char& c : out)
        if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
    return out;
}

} // namespace volsg
