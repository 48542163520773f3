#pragma once
// The one rule for files that a data file names (a detached NRRD or MetaImage data file, a
// glTF buffer or image): they lie inside the naming file's folder. A scene file is the
// user's own and may name files anywhere (docs/SCENE-FORMAT.md 1.6); a data file comes from
// elsewhere, so it must not reach out of its folder with `..`, an absolute name or a symbolic
// link leading out.

#include <filesystem>
#include <string>

namespace volsg {

/// Whether the existing file `path` is inside `canonicalFolder` (itself canonical) once its
/// symbolic links and `..` are resolved. False when `path` cannot be resolved.
bool isInsideFolder(const std::filesystem::path& canonicalFolder, const std::string& path);

/// The path of `name`, as written in the data file `namingFile`, resolved against that
/// file's folder. Throws Error naming `namingFile` when `name` is absolute, or escapes the
/// folder (by `..` or, for an existing file, a symbolic link).
std::string containedFile(const std::string& namingFile, const std::string& name);

} // namespace volsg
