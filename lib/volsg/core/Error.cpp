#include <volsg/core/Error.h>

namespace volsg {

namespace {
std::string format(const std::string& message, const std::string& file, int line, int column) {
    std::string where = file;
    if (line > 0) {
        where += (where.empty() ? "" : ":") + std::to_string(line);
        if (column > 0) where += ":" + std::to_string(column);
    }
    return where.empty() ? message : where + ": " + message;
}
} // namespace

Error::Error(std::string message, std::string file, int line, int column)
    : std::runtime_error(format(message, file, line, column)), message_(std::move(message)),
      file_(std::move(file)), line_(line), column_(column) {}

} // namespace volsg
