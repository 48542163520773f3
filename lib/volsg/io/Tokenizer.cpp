#include <volsg/core/Error.h>
#include <volsg/io/Tokenizer.h>

#include <charconv>
#include <cstdio>
#include <limits>
#include <system_error>

namespace volsg {

namespace {

bool isSpace(unsigned char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}
bool isPunct(unsigned char c) {
    return c == '{' || c == '}' || c == '[' || c == ']' || c == '(' || c == ')' || c == ',' ||
           c == '|';
}
bool isControl(unsigned char c) {
    return (c < 0x20 && !isSpace(c)) || c == 0x7f;
}
bool isWordChar(unsigned char c) {
    return !isSpace(c) && !isPunct(c) && !isControl(c) && c != '"' && c != '#';
}
bool isDigit(char c) {
    return c >= '0' && c <= '9';
}
bool isHexDigit(char c) {
    return isDigit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}
char lower(char c) {
    return (c >= 'A' && c <= 'Z') ? char(c - 'A' + 'a') : c;
}

// A printable excerpt of token text for messages: bounded, control bytes shown as '?'.
std::string excerpt(std::string_view text) {
    constexpr std::size_t maxShown = 40;
    std::string out;
    for (std::size_t i = 0; i < text.size() && i < maxShown; ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        out += (c < 0x20 || c == 0x7f) ? '?' : char(c);
    }
    if (text.size() > maxShown) out += "...";
    return out;
}

std::string_view withoutSign(std::string_view s, bool& negative) {
    negative = false;
    if (!s.empty() && (s[0] == '+' || s[0] == '-')) {
        negative = s[0] == '-';
        s.remove_prefix(1);
    }
    return s;
}

bool looksNonFinite(std::string_view s) {
    bool negative;
    s = withoutSign(s, negative);
    if (s.size() < 3) return false;
    const char a = lower(s[0]), b = lower(s[1]), c = lower(s[2]);
    return (a == 'n' && b == 'a' && c == 'n') || (a == 'i' && b == 'n' && c == 'f');
}

// Checks the decimal grammar [+-]? (d+ (. d*)? | . d+) ([eE] [+-]? d+)? and returns, in
// `magnitude`, the power of ten just above the leading significant digit (roughly log10 of
// the value + 1), which tells an overflow from an underflow when the conversion fails.
bool isDecimalNumber(std::string_view s, long& magnitude) {
    bool negative;
    s = withoutSign(s, negative);
    std::size_t i = 0;
    long intDigits = 0, leadingZerosAfterPoint = 0;
    bool significant = false, anyDigit = false;
    while (i < s.size() && isDigit(s[i])) {
        anyDigit = true;
        if (s[i] != '0') significant = true;
        if (significant) ++intDigits;
        ++i;
    }
    if (i < s.size() && s[i] == '.') {
        ++i;
        while (i < s.size() && isDigit(s[i])) {
            anyDigit = true;
            if (s[i] != '0') significant = true;
            if (!significant) ++leadingZerosAfterPoint;
            ++i;
        }
    }
    if (!anyDigit) return false;
    long exponent = 0;
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
        ++i;
        bool expNegative = false;
        if (i < s.size() && (s[i] == '+' || s[i] == '-')) expNegative = s[i++] == '-';
        if (i >= s.size() || !isDigit(s[i])) return false;
        while (i < s.size() && isDigit(s[i])) {
            if (exponent < 100000000) exponent = exponent * 10 + (s[i] - '0');
            ++i;
        }
        if (expNegative) exponent = -exponent;
    }
    if (i != s.size()) return false;
    magnitude = (intDigits > 0 ? intDigits : -leadingZerosAfterPoint) + exponent;
    return true;
}

} // namespace

Tokenizer::Tokenizer(std::string_view text, std::string fileName)
    : text_(text), fileName_(std::move(fileName)) {}

void Tokenizer::fail(const std::string& message) const {
    throw Error(message, fileName_, lastLine_, lastColumn_);
}

void Tokenizer::failAt(const Token& t, const std::string& message) const {
    throw Error(message, fileName_, t.line, t.column);
}

std::string Tokenizer::describe(const Token& t) {
    switch (t.kind) {
    case Token::Kind::End:
        return "end of file";
    case Token::Kind::Punct:
        return "'" + t.text + "'";
    case Token::Kind::Word:
        return "'" + excerpt(t.text) + "'";
    case Token::Kind::String:
        return "string \"" + excerpt(t.text) + "\"";
    }
    return "?";
}

Token Tokenizer::lex() {
    const std::size_t size = text_.size();
    // Skip white space and comments.
    while (pos_ < size) {
        const unsigned char c = static_cast<unsigned char>(text_[pos_]);
        if (c == '\n') {
            ++pos_;
            ++line_;
            column_ = 1;
        } else if (isSpace(c)) {
            ++pos_;
            ++column_;
        } else if (c == '#') {
            while (pos_ < size && text_[pos_] != '\n') {
                ++pos_;
                ++column_;
            }
        } else {
            break;
        }
    }
    Token t;
    t.line = line_;
    t.column = column_;
    if (pos_ >= size) return t;

    const unsigned char c = static_cast<unsigned char>(text_[pos_]);
    if (isPunct(c)) {
        t.kind = Token::Kind::Punct;
        t.text.assign(1, char(c));
        ++pos_;
        ++column_;
        return t;
    }
    if (c == '"') return lexString(t.line, t.column);
    if (isControl(c)) {
        char hex[8];
        std::snprintf(hex, sizeof hex, "0x%02X", unsigned(c));
        throw Error(std::string("unexpected control character ") + hex + " (not Inventor text)",
                    fileName_, line_, column_);
    }
    const std::size_t start = pos_;
    while (pos_ < size && isWordChar(static_cast<unsigned char>(text_[pos_]))) {
        if (pos_ - start >= maxWordLength)
            throw Error("word longer than " + std::to_string(maxWordLength) +
                            " bytes (not Inventor text)",
                        fileName_, t.line, t.column);
        ++pos_;
    }
    t.kind = Token::Kind::Word;
    t.text.assign(text_.substr(start, pos_ - start));
    column_ += int(pos_ - start);
    return t;
}

Token Tokenizer::lexString(int line, int column) {
    const std::size_t size = text_.size();
    Token t;
    t.kind = Token::Kind::String;
    t.line = line;
    t.column = column;
    ++pos_; // the opening quote
    ++column_;
    while (true) {
        if (pos_ >= size)
            throw Error("unterminated string: the string started at " + std::to_string(line) + ":" +
                            std::to_string(column) + " has no closing '\"'",
                        fileName_, line_, column_);
        if (t.text.size() >= maxStringLength)
            throw Error("string longer than " + std::to_string(maxStringLength) + " bytes",
                        fileName_, line, column);
        const char c = text_[pos_];
        if (c == '"') {
            ++pos_;
            ++column_;
            return t;
        }
        if (c == '\\' && pos_ + 1 < size && (text_[pos_ + 1] == '"' || text_[pos_ + 1] == '\\')) {
            // Inventor escapes only these two; any other backslash is kept as written.
            t.text += text_[pos_ + 1];
            pos_ += 2;
            column_ += 2;
            continue;
        }
        t.text += c;
        ++pos_;
        if (c == '\n') {
            ++line_;
            column_ = 1;
        } else {
            ++column_;
        }
    }
}

const Token& Tokenizer::peek() {
    if (!hasPeeked_) {
        peeked_ = lex();
        hasPeeked_ = true;
    }
    return peeked_;
}

const Token& Tokenizer::peekSecond() {
    peek();
    if (!hasSecond_) {
        second_ = lex();
        hasSecond_ = true;
    }
    return second_;
}

Token Tokenizer::next() {
    peek();
    lastLine_ = peeked_.line;
    lastColumn_ = peeked_.column;
    Token t = std::move(peeked_);
    if (hasSecond_) {
        peeked_ = std::move(second_);
        hasSecond_ = false;
    } else {
        hasPeeked_ = false;
    }
    return t;
}

bool Tokenizer::atEnd() {
    return peek().kind == Token::Kind::End;
}

bool Tokenizer::acceptPunct(char c) {
    if (!peek().isPunct(c)) return false;
    next();
    return true;
}

void Tokenizer::expectPunct(char c) {
    if (acceptPunct(c)) return;
    failAt(peek(), std::string("expected '") + c + "', found " + describe(peek()));
}

bool Tokenizer::acceptWord(std::string_view word) {
    if (!peek().isWord(word)) return false;
    next();
    return true;
}

std::string Tokenizer::expectWord(const char* what) {
    if (peek().kind != Token::Kind::Word)
        failAt(peek(), std::string("expected ") + what + ", found " + describe(peek()));
    return next().text;
}

std::string Tokenizer::expectString() {
    const Token& t = peek();
    if (t.kind != Token::Kind::String && t.kind != Token::Kind::Word)
        failAt(t, "expected a string, found " + describe(t));
    return next().text;
}

const Token& Tokenizer::consumeNumberWord(const char* expected) {
    if (peek().kind != Token::Kind::Word)
        failAt(peek(), std::string("expected ") + expected + ", found " + describe(peek()));
    last_ = next();
    return last_;
}

template <class Real> Real Tokenizer::readReal(const char* rangeMessage) {
    const Token& t = consumeNumberWord("a number");
    if (looksNonFinite(t.text)) failAt(t, "value '" + excerpt(t.text) + "' is not a finite number");
    long magnitude = 0;
    if (!isDecimalNumber(t.text, magnitude)) failAt(t, "expected a number, found " + describe(t));
    std::string_view s = t.text;
    if (s[0] == '+') s.remove_prefix(1);
    // Parsed straight as Real (a float not via double) so the result is correctly rounded.
    Real value = 0;
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    if (ec == std::errc::result_out_of_range) {
        if (magnitude > 0)
            failAt(t, "value " + excerpt(t.text) + " is out of range for " + rangeMessage);
        value = s[0] == '-' ? -Real(0) : Real(0); // underflow: as close as the type gets
    } else if (ec != std::errc() || ptr != s.data() + s.size()) {
        failAt(t, "expected a number, found " + describe(t));
    }
    return value;
}

double Tokenizer::readDouble() {
    return readReal<double>("a 64-bit float");
}

float Tokenizer::readFloat() {
    return readReal<float>("a 32-bit float (largest 3.4028235e38)");
}

namespace {

struct IntegerText {
    bool negative = false;
    bool hex = false;
    bool tooLong = false; ///< more digits than 64 bits hold
    std::uint64_t magnitude = 0;
};

bool parseInteger(std::string_view s, IntegerText& out) {
    s = withoutSign(s, out.negative);
    int base = 10;
    if (s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
        s.remove_prefix(2);
        base = 16;
        out.hex = true;
    }
    if (s.empty()) return false;
    for (char c : s)
        if (base == 16 ? !isHexDigit(c) : !isDigit(c)) return false;
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out.magnitude, base);
    if (ec == std::errc::result_out_of_range)
        out.tooLong = true;
    else if (ec != std::errc() || ptr != s.data() + s.size())
        return false;
    return true;
}

} // namespace

std::int32_t Tokenizer::readInt32() {
    const Token& t = consumeNumberWord("an integer");
    IntegerText n;
    if (!parseInteger(t.text, n)) failAt(t, "expected an integer, found " + describe(t));
    const std::uint64_t limit =
        n.negative ? 0x80000000ull : (n.hex ? 0xFFFFFFFFull : 0x7FFFFFFFull);
    if (n.tooLong || n.magnitude > limit)
        failAt(t, "value " + excerpt(t.text) + " is out of range for a 32-bit integer");
    if (n.negative) return static_cast<std::int32_t>(-static_cast<std::int64_t>(n.magnitude));
    // Hex is a bit pattern: 0xFFFFFFFF is -1, as in Inventor's packed values.
    return static_cast<std::int32_t>(static_cast<std::uint32_t>(n.magnitude));
}

std::uint32_t Tokenizer::readUInt32() {
    const Token& t = consumeNumberWord("an unsigned integer");
    IntegerText n;
    if (!parseInteger(t.text, n)) failAt(t, "expected an unsigned integer, found " + describe(t));
    if (n.tooLong || n.magnitude > 0xFFFFFFFFull || (n.negative && n.magnitude != 0))
        failAt(t, "value " + excerpt(t.text) + " is out of range for an unsigned 32-bit integer");
    return static_cast<std::uint32_t>(n.magnitude);
}

bool Tokenizer::readBool() {
    const Token& t = peek();
    if (t.kind == Token::Kind::Word) {
        const bool isTrue = t.text == "TRUE" || t.text == "1";
        if (isTrue || t.text == "FALSE" || t.text == "0") {
            next();
            return isTrue;
        }
    }
    failAt(t, "expected TRUE, FALSE, 0 or 1, found " + describe(t));
}

} // namespace volsg
