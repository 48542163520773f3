#pragma once
// What a node learns from the scene reader about the file it was read from.

#include <filesystem>
#include <string>

namespace volsg {

/// Given to Node::readDone() by the scene reader: relative file names in a scene (VolumeData,
/// GltfModel, ...) resolve against the folder of the scene file that names them.
struct ReadContext {
    std::string fileName;  ///< the scene file as named to the reader ("<string>" for text)
    std::string directory; ///< its folder; empty for text without a file (working directory)

    /// `name` itself when it is empty or absolute, else `directory/name`.
    std::string resolve(const std::string& name) const {
        const std::filesystem::path p(name);
        if (name.empty() || p.is_absolute() || directory.empty()) return name;
        return (std::filesystem::path(directory) / p).string();
    }
};

} // namespace volsg
