#pragma once
// The field lists of standard Inventor node types, for the ones the reader has no class for.

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace volsg {

/// A standard Inventor node type as files use it (docs/SCENE-FORMAT.md section 1.4).
struct InventorType {
    std::string name;
    std::string parent;
    bool isGroup = false; ///< has children in a file (SoGroup and below)
    bool isKit = false;   ///< a node kit (its parts are SFNode fields)
    std::vector<std::pair<std::string, std::string>> fields; ///< name, field type
};

/// The type of that name (Texture2, ShapeHints, ...), or null for a name standard Inventor
/// does not have.
const InventorType* findInventorType(std::string_view name);

} // namespace volsg
