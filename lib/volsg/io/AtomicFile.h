#pragma once
// Saving a file so that a failure never destroys the previous one: write a temporary file
// beside it, then rename it into place.

#include <functional>
#include <iosfwd>
#include <string>
#include <string_view>

namespace volsg {

/// Replaces the file at `path` with `bytes`, or throws volsg::Error naming `path` and leaves
/// whatever was there untouched. The bytes go to a new temporary file in the same folder
/// (`path.tmp.<pid>.<n>`, created exclusively, never an existing file), are flushed to the disk
/// (fsync) and only then renamed over `path`, so readers see the old file or the whole new one,
/// never half of it. A failure at any step (no folder, no permission, disk full, file size
/// limit, `path` naming a folder) removes the temporary file. The new file keeps the old one's
/// permissions (a new one gets 0666 less the umask); a symbolic link at `path` is followed and
/// its target replaced, the link kept.
void writeFileAtomically(const std::string& path, std::string_view bytes);

/// As above, with the content produced by `write` into a stream first; an exception from
/// `write` (a value that cannot be written) leaves the old file as it was and is passed on.
void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

} // namespace volsg
