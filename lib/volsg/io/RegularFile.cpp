#include <volsg/core/Error.h>
#include <volsg/io/RegularFile.h>

#include <filesystem>

namespace volsg {

std::uintmax_t regularFileSize(const std::string& path, const std::string& what,
                               std::uintmax_t maxBytes) {
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status))
        throw Error(what + ": " + (ec ? ec.message() : std::string("No such file or directory")),
                    path);
    if (!std::filesystem::is_regular_file(status)) throw Error(what + ": not a regular file", path);
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throw Error(what + ": " + ec.message(), path);
    if (size > maxBytes)
        throw Error(what + ": " + std::to_string(size) + " bytes, more than the limit of " +
                        std::to_string(maxBytes),
                    path);
    return size;
}

} // namespace volsg
