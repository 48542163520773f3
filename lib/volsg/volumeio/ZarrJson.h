#pragma once
// The Zarr metadata files (.zarray, .zattrs, .zgroup) as JSON, for the volumeio sources only.

#include <string>

#include <nlohmann/json.hpp>

namespace volsg {

/// The JSON in `path`, at most limits::maxHeaderLength bytes; an Error naming the file for a
/// missing, oversized or malformed one ("malformed JSON: ... at line 3, column 7").
nlohmann::json readZarrJson(const std::string& path);

} // namespace volsg
