#pragma once
// Lexer for Inventor ASCII: words, numbers, quoted strings and punctuation, with positions.

#include <cstdint>
#include <string>
#include <string_view>

namespace volsg {

/// One token of an Inventor ASCII file.
struct Token {
    enum class Kind { End, Word, String, Punct };
    Kind kind = Kind::End;
    std::string text; ///< word text, unescaped string contents, or the punctuation character
    int line = 0;
    int column = 0;
};

/// Splits Inventor ASCII text into tokens. Words are runs of characters that are not white
/// space, quotes or one of `{ } [ ] ( ) , |`; `#` starts a comment to the end of the line.
/// Every error it raises is a volsg::Error naming the file, line and column.
class Tokenizer {
public:
    /// `text` must outlive the tokenizer; `fileName` is used in error messages only.
    Tokenizer(std::string_view text, std::string fileName);

    const Token& peek();                  ///< the next token, not consumed
    Token next();                         ///< consumes the next token
    bool atEnd();                         ///< no tokens left
    bool acceptPunct(char c);             ///< consumes `c` if it is next
    void expectPunct(char c);             ///< consumes `c` or throws
    std::string expectWord(const char* what); ///< a word, else throws "expected <what>"
    std::string expectString();           ///< a quoted string (or a bare word, as Inventor allows)

    double readDouble();  ///< a finite number; throws on NaN, Inf, out of float range
    float readFloat();    ///< readDouble() checked against float range
    std::int32_t readInt32(); ///< decimal, or hex with 0x; range checked
    std::uint32_t readUInt32();
    bool readBool();      ///< TRUE FALSE 0 1

    [[noreturn]] void fail(const std::string& message) const; ///< throws at the last token position
    [[noreturn]] void failAt(const Token& t, const std::string& message) const;
    const std::string& fileName() const { return fileName_; }

private:
    Token lex();
    std::string_view text_;
    std::string fileName_;
    std::size_t pos_ = 0;
    int line_ = 1;
    int column_ = 1;
    Token peeked_;
    bool hasPeeked_ = false;
    int lastLine_ = 1;
    int lastColumn_ = 1;
};

} // namespace volsg
