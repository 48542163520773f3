#pragma once
// Writes node graphs as Inventor ASCII scene files (docs/SCENE-FORMAT.md section 1).

#include <iosfwd>
#include <string>

#include <volsg/core/Node.h>

namespace volsg {

/// Writes `#Inventor V2.1 ascii` and the graph under `root`, two spaces per level: each node
/// with its non-default fields (Field::isDefault()), then its children.
///
/// - Sharing is kept with DEF/USE: a node reached more than once is written `DEF name` the
///   first time and `USE name` after. Named nodes keep their names (written `DEF name` even
///   when used once). Unnamed shared nodes get `+N`, and a name that would hide a node still
///   to be USEd gets `name+N`; readers (ours and Coin) drop the suffix, so names round-trip.
///   Characters a name cannot hold in a file are written as '_'.
/// - Types that are not standard Inventor (NodeType::isInventorBuiltin() false) and
///   UnknownNodes are written with their `fields [ SFFloat a, ... ]` description, so other
///   Inventor readers (Coin3D) load the file.
///
/// Throws volsg::Error when a value cannot be written (a NaN or infinite float).
void writeScene(std::ostream& out, const Node& root);

/// Writes through a temporary file and a rename (io/AtomicFile.h): a failure leaves the old file
/// as it was.
void writeSceneToFile(const std::string& path, const Node& root);

std::string writeSceneToString(const Node& root);

} // namespace volsg
