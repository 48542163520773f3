#pragma once
// The binary Inventor format (docs/SCENE-FORMAT.md section 1.9). Internal to nodes/volsg/io:
// readScene() sends files with a binary header here.

#include <cstddef>
#include <string_view>

#include <volsg/core/Node.h>
#include <volsg/io/ReaderSupport.h>

namespace volsg {

/// Reads the nodes of a binary file; `data` is what follows the header line, which took
/// `headerBytes` bytes of the file (error offsets count from the start of the file).
ref_ptr<Node> readBinaryScene(std::string_view data, std::size_t headerBytes,
                              reader::FileState& file);

} // namespace volsg
