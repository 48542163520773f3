#include <volsg/io/ContainedFile.h>

#include <system_error>

#include <volsg/core/Error.h>

namespace volsg {

bool isInsideFolder(const std::filesystem::path& canonicalFolder, const std::string& path) {
    std::error_code ec;
    const std::filesystem::path canonical = std::filesystem::canonical(path, ec);
    if (ec) return false;
    const std::filesystem::path relative = canonical.lexically_relative(canonicalFolder);
    return !relative.empty() && *relative.begin() != ".." && relative.is_relative();
}

std::string containedFile(const std::string& namingFile, const std::string& name) {
    namespace fs = std::filesystem;
    const fs::path file(name);
    const auto refuse = [&](const std::string& why) {
        throw Error("refused to read '" + name + "': " + why +
                        " (a data file may name files only inside its own folder)",
                    namingFile);
    };
    if (file.is_absolute() || file.has_root_name()) refuse("an absolute name");
    // Lexically first: a name that climbs out is refused whether or not it exists.
    const fs::path normal = file.lexically_normal();
    if (!normal.empty() && *normal.begin() == "..") refuse("outside the folder");
    const fs::path folder = fs::path(namingFile).parent_path();
    const std::string resolved = (folder / file).string();
    std::error_code ec;
    if (fs::exists(resolved, ec)) {
        const fs::path canonicalFolder = fs::canonical(folder.empty() ? "." : folder, ec);
        if (ec || !isInsideFolder(canonicalFolder, resolved))
            refuse("a symbolic link leading outside the folder");
    }
    return resolved;
}

} // namespace volsg
