#pragma once
// Reads Inventor scene files, text and binary (docs/SCENE-FORMAT.md section 1), into node
// graphs.

#include <cstdint>
#include <string>
#include <string_view>

#include <volsg/core/Limits.h>
#include <volsg/core/Node.h>

namespace volsg {

/// Deepest nesting of nodes the reader accepts (children and SFNode/MFNode values each count
/// one level); deeper input is an error, never a stack overflow.
inline constexpr int maxSceneNestingDepth = limits::maxSceneNestingDepth;
/// Largest scene file readScene() loads.
inline constexpr std::uintmax_t maxSceneFileSize = limits::maxSceneFileSize;

/// How the reader treats what it has no class for.
struct ReadOptions {
    /// Text files: keep a node of a type the reader has no class for and that does not
    /// describe its fields as an UnknownNode instead of refusing the file. A standard Inventor
    /// type (Texture2, ShapeHints, ...) gets its fields from the reader's table of them
    /// (io/InventorTypes.h) and reads as such; any other type keeps each value as the text it
    /// was written in (io/UnknownNode.h, Description::Raw). Binary files always keep standard
    /// Inventor types (every node there names its fields), whatever this says.
    bool keepUnknownTypes = false;
};

/// Reads a scene file. One top-level node is returned as it is; several (or none) are wrapped
/// in a Separator, as Coin does. Every node gets Node::readDone() with the file's folder, so
/// relative file names in it resolve against that folder (io/ReadContext.h).
///
/// - Header `#Inventor V2.1 ascii` (also V2.0, V1.0, upgraded as Coin does, and
///   `#VRML V1.0 ascii`), or `#Inventor V2.1 binary` / `#Inventor V2.0 binary`; files without
///   a header are refused. Errors in binary files give the byte offset: `file: byte N: ...`.
/// - Field values may carry Inventor's ignore flag (`value ~`) and a connection
///   (`field = Engine { ... } . output`, `field = USE name . field`): kept, evaluated by
///   nodes/volsg/engines/Evaluator.h and written back.
/// - `DEF name` names a node, `USE name` shares it (the same node). A DEF name written as
///   `name+N` (Coin's suffix for shared nodes) names the node `name`; `+N` alone leaves it
///   unnamed. A name is bound when its node is complete, so a graph read is never cyclic.
/// - A type the reader does not know must describe its fields
///   (`Foo { fields [ SFFloat a ] a 1 }`) and becomes an UnknownNode; our own node types may
///   carry the same description, which must match their fields.
///
/// Errors throw volsg::Error with file, line and column and what was expected. Any input,
/// however malformed, gives such an error (never a crash, hang or unbounded allocation).
ref_ptr<Node> readScene(const std::string& path, const ReadOptions& options = {});

/// Reads scene text; `fileName` is used in error messages, and its folder (unless it is a
/// placeholder like "<string>") is where relative file names resolve.
ref_ptr<Node> readSceneFromString(std::string_view text, const std::string& fileName = "<string>",
                                  const ReadOptions& options = {});

} // namespace volsg
