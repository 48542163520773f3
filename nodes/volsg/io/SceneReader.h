#pragma once
// Reads Inventor ASCII scene files (docs/SCENE-FORMAT.md section 1) into node graphs.

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

/// Reads a scene file. One top-level node is returned as it is; several (or none) are wrapped
/// in a Separator, as Coin does. Every node gets Node::readDone() with the file's folder, so
/// relative file names in it resolve against that folder (io/ReadContext.h).
///
/// - Header `#Inventor V2.1 ascii` (also V2.0 and `#VRML V1.0 ascii`); binary files and
///   files without a header are refused.
/// - `DEF name` names a node, `USE name` shares it (the same node). A DEF name written as
///   `name+N` (Coin's suffix for shared nodes) names the node `name`; `+N` alone leaves it
///   unnamed. A name is bound when its node is complete, so a graph read is never cyclic.
/// - A type the reader does not know must describe its fields
///   (`Foo { fields [ SFFloat a ] a 1 }`) and becomes an UnknownNode; our own node types may
///   carry the same description, which must match their fields.
///
/// Errors throw volsg::Error with file, line and column and what was expected. Any input,
/// however malformed, gives such an error (never a crash, hang or unbounded allocation).
ref_ptr<Node> readScene(const std::string& path);

/// Reads scene text; `fileName` is used in error messages, and its folder (unless it is a
/// placeholder like "<string>") is where relative file names resolve.
ref_ptr<Node> readSceneFromString(std::string_view text, const std::string& fileName = "<string>");

} // namespace volsg
