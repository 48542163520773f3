#pragma once
// A walk over a DICOM file's data elements that checks every declared value length against the
// bytes left, before GDCM sees the file: GDCM sizes a value's buffer from its declared length
// (a 4-byte field), so a 12-byte file declaring a 4 GB element would make it allocate 4 GB.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace volsg {

/// Why the DICOM bytes cannot be what they declare (an element or item longer than the bytes
/// left after it, with its byte offset and tag), or an empty string when every declared length
/// fits. Knows the file meta group, explicit and implicit VR, little and big endian, sequences
/// and items of defined and undefined length, and encapsulated pixel data. A deflated data set
/// is checked up to its meta group (GDCM inflates the rest with lengths of its own).
/// Where the walk found the top-level pixel data (7fe0,0010), when `pixels` is given.
struct DicomPixelData {
    bool found = false;
    bool encapsulated = false; ///< compressed fragments (undefined length)
    std::size_t length = 0;    ///< the declared length of native pixel data
};
std::string dicomLengthProblem(std::span<const std::uint8_t> bytes,
                               DicomPixelData* pixels = nullptr);

} // namespace volsg
