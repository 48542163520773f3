#pragma once
// Lexer for Inventor ASCII: words, numbers, quoted strings and punctuation, with positions.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include <volsg/core/Limits.h>

namespace volsg {

/// One token of an Inventor ASCII file.
struct Token {
    enum class Kind { End, Word, String, Punct };
    Kind kind = Kind::End;
    std::string text; ///< word text, unescaped string contents, or the punctuation character
    int line = 0;
    int column = 0;

    bool isPunct(char c) const { return kind == Kind::Punct && text.size() == 1 && text[0] == c; }
    bool isWord(std::string_view w) const { return kind == Kind::Word && text == w; }
};

/// Splits Inventor ASCII text into tokens. Words are runs of characters that are not white
/// space, quotes or one of `{ } [ ] ( ) , |`; `#` starts a comment to the end of the line.
/// Every error it raises is a volsg::Error naming the file, line and column.
///
/// Input is untrusted: a token longer than its limit is an error, never an unbounded
/// allocation, and control characters outside strings are refused at once (random bytes fail
/// on the first one instead of being read as megabytes of one word).
class Tokenizer {
public:
    /// Longest word (names and numbers); anything longer is not Inventor text.
    static constexpr std::size_t maxWordLength = limits::maxWordLength;
    /// Longest quoted string, after unescaping.
    static constexpr std::size_t maxStringLength = limits::maxStringLength;

    /// `text` must outlive the tokenizer; `fileName` is used in error messages only.
    Tokenizer(std::string_view text, std::string fileName);

    const Token& peek();                      ///< the next token, not consumed
    const Token& peekSecond();                ///< the token after peek(), not consumed
    Token next();                             ///< consumes the next token
    bool atEnd();                             ///< no tokens left
    bool acceptPunct(char c);                 ///< consumes `c` if it is next
    void expectPunct(char c);                 ///< consumes `c` or throws
    bool acceptWord(std::string_view word);   ///< consumes the word if it is next
    std::string expectWord(const char* what); ///< a word, else throws "expected <what>"
    std::string expectString(); ///< a quoted string (or a bare word, as Inventor allows)

    double readDouble();      ///< a finite number in double range; throws on NaN, Inf, overflow
    float readFloat();        ///< as readDouble(), checked against float range
    std::int32_t readInt32(); ///< decimal, or hex with 0x (a 32-bit pattern); range checked
    std::uint32_t readUInt32();
    bool readBool(); ///< TRUE FALSE 0 1

    [[noreturn]] void fail(const std::string& message) const; ///< throws at the last token position
    [[noreturn]] void failAt(const Token& t, const std::string& message) const;
    const std::string& fileName() const { return fileName_; }

    /// How a token reads in an error message: `'{'`, `'Cube'`, `string "abc"`, `end of file`.
    static std::string describe(const Token& t);

private:
    Token lex();
    Token lexString(int line, int column);
    const Token& consumeNumberWord(const char* expected);
    template <class Real> Real readReal(const char* rangeMessage);
    std::string_view text_;
    std::string fileName_;
    std::size_t pos_ = 0;
    int line_ = 1;
    int column_ = 1;
    Token peeked_;
    bool hasPeeked_ = false;
    Token second_;
    bool hasSecond_ = false;
    Token last_; ///< the token consumed last (numbers are parsed from here)
    int lastLine_ = 1;
    int lastColumn_ = 1;
};

} // namespace volsg
