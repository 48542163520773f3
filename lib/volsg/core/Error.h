#pragma once
// The one error type: where (file, line, column) and what.

#include <stdexcept>
#include <string>

namespace volsg {

/// Thrown for bad input and failed operations. `what()` is one line:
/// "file:line:column: message" (parts that are unknown are left out).
class Error : public std::runtime_error {
public:
    explicit Error(std::string message, std::string file = {}, int line = 0, int column = 0);

    const std::string& message() const noexcept { return message_; }
    const std::string& file() const noexcept { return file_; }
    int line() const noexcept { return line_; }
    int column() const noexcept { return column_; }

private:
    std::string message_;
    std::string file_;
    int line_ = 0;
    int column_ = 0;
};

} // namespace volsg
