#pragma once
// The first check of every reader that takes a path: is it a regular file of bounded size?

#include <cstdint>
#include <string>

namespace volsg {

/// The size of the regular file at `path`, or an Error naming `path` that starts with `what`
/// ("cannot read scene file: ..."): "No such file or directory", "Too many levels of symbolic
/// links", "not a regular file" (a folder, a FIFO, which would block the open, or a device,
/// which could stream forever) or "N bytes, more than the limit of M" when over `maxBytes`.
std::uintmax_t regularFileSize(const std::string& path, const std::string& what,
                               std::uintmax_t maxBytes);

} // namespace volsg
