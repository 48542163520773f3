#include <volsg/volumeio/DicomLengths.h>

#include <cstdio>
#include <string_view>
#include <vector>

namespace volsg {

namespace {

constexpr std::uint32_t kUndefinedLength = 0xffffffffu;

struct Syntax {
    bool implicitVr = false;
    bool bigEndian = false;
};

std::uint16_t read16(const std::uint8_t* p, bool bigEndian) {
    return bigEndian ? std::uint16_t(p[0] << 8 | p[1]) : std::uint16_t(p[1] << 8 | p[0]);
}

std::uint32_t read32(const std::uint8_t* p, bool bigEndian) {
    return bigEndian ? std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 |
                           std::uint32_t(p[2]) << 8 | p[3]
                     : std::uint32_t(p[3]) << 24 | std::uint32_t(p[2]) << 16 |
                           std::uint32_t(p[1]) << 8 | p[0];
}

bool isVrLetter(std::uint8_t c) {
    return c >= 'A' && c <= 'Z';
}

/// The value representations of PS3.5 6.2 (GDCM reads a length of 4 bytes after any other).
bool isKnownVr(std::string_view vr) {
    static constexpr std::string_view known[] = {
        "AE", "AS", "AT", "CS", "DA", "DS", "DT", "FL", "FD", "IS", "LO", "LT",
        "OB", "OD", "OF", "OL", "OV", "OW", "PN", "SH", "SL", "SQ", "SS", "ST",
        "SV", "TM", "UC", "UI", "UL", "UN", "UR", "US", "UT", "UV"};
    for (std::string_view k : known)
        if (vr == k) return true;
    return false;
}

/// The VRs whose length is a 4-byte field after two reserved bytes (PS3.5 7.1.2).
bool hasLongLength(std::string_view vr) {
    for (const char* v :
         {"OB", "OD", "OF", "OL", "OV", "OW", "SQ", "UC", "UN", "UR", "UT", "SV", "UV"})
        if (vr == v) return true;
    return false;
}

std::string tagText(std::uint16_t group, std::uint16_t element) {
    char text[16];
    std::snprintf(text, sizeof text, "(%04x,%04x)", group, element);
    return text;
}

std::string tooLong(std::size_t at, std::uint16_t group, std::uint16_t element,
                    std::uint32_t length, std::size_t left) {
    return "byte " + std::to_string(at) + ": element " + tagText(group, element) + " declares " +
           std::to_string(length) + " bytes, " + std::to_string(left) + " are left in the file";
}

/// The transfer syntax a UID names, or false for a deflated data set (not walked).
bool syntaxOf(std::string uid, Syntax& out) {
    while (!uid.empty() && (uid.back() == '\0' || uid.back() == ' '))
        uid.pop_back();
    if (uid == "1.2.840.10008.1.2.1.99") return false;
    out.implicitVr = uid == "1.2.840.10008.1.2";
    out.bigEndian = uid == "1.2.840.10008.1.2.2";
    return true;
}

} // namespace

std::string dicomLengthProblem(std::span<const std::uint8_t> bytes, DicomPixelData* pixels) {
    const std::size_t size = bytes.size();
    const std::uint8_t* data = bytes.data();
    std::size_t pos = 0;
    if (size >= 132 && std::string_view(reinterpret_cast<const char*>(data) + 128, 4) == "DICM")
        pos = 132;
    // Without a meta group the data set's VR form is guessed as GDCM does: explicit when the
    // first element's VR bytes are letters.
    Syntax dataSet;
    dataSet.implicitVr =
        !(size >= pos + 6 && isVrLetter(data[pos + 4]) && isVrLetter(data[pos + 5]));
    bool inMeta = true, deflated = false;
    std::vector<Syntax> undefinedNesting; // the syntax outside each undefined-length SQ or UN
    Syntax current{false, false};
    bool fragments = false; // inside encapsulated pixel data: items are skipped whole

    while (size - pos >= 8) {
        const std::size_t at = pos;
        // The meta group (0002) is explicit VR little endian whatever the data set uses.
        const std::uint16_t metaGroup = read16(data + pos, false);
        if (inMeta && metaGroup != 0x0002) {
            inMeta = false;
            if (deflated) return {};
            current = dataSet;
        }
        const Syntax s = inMeta ? Syntax{false, false} : current;
        const std::uint16_t group = read16(data + pos, s.bigEndian);
        const std::uint16_t element = read16(data + pos + 2, s.bigEndian);
        pos += 4;

        if (group == 0xfffe) { // items and delimiters: a 4-byte length, no VR
            const std::uint32_t length = read32(data + pos, s.bigEndian);
            pos += 4;
            if (element == 0xe0dd) { // the end of a sequence of undefined length
                if (fragments) {
                    fragments = false;
                } else if (!undefinedNesting.empty()) {
                    current = undefinedNesting.back();
                    undefinedNesting.pop_back();
                }
                continue;
            }
            if (element == 0xe00d) continue;
            if (element != 0xe000)
                return "byte " + std::to_string(at) + ": unknown item tag " +
                       tagText(group, element);
            if (length == kUndefinedLength) continue; // its elements follow, up to E00D
            if (length > size - pos) return tooLong(at, group, element, length, size - pos);
            if (fragments) pos += length; // a fragment of compressed pixels
            continue;                     // else: an item's elements follow
        }
        if (fragments)
            return "byte " + std::to_string(at) + ": " + tagText(group, element) +
                   " inside encapsulated pixel data, where only items may be";

        std::uint32_t length = 0;
        std::string_view vr;
        if (s.implicitVr) {
            length = read32(data + pos, s.bigEndian);
            pos += 4;
        } else {
            if (!isVrLetter(data[pos]) || !isVrLetter(data[pos + 1]))
                return "byte " + std::to_string(at) + ": element " + tagText(group, element) +
                       " has no value representation (two capital letters expected)";
            vr = std::string_view(reinterpret_cast<const char*>(data) + pos, 2);
            if (!isKnownVr(vr))
                return "byte " + std::to_string(at) + ": element " + tagText(group, element) +
                       " has an unknown value representation '" + std::string(vr) + "'";
            if (hasLongLength(vr)) {
                if (size - pos < 8)
                    return "byte " + std::to_string(at) + ": element " + tagText(group, element) +
                           " is cut short";
                length = read32(data + pos + 4, s.bigEndian);
                pos += 8;
            } else {
                length = read16(data + pos + 2, s.bigEndian);
                pos += 4;
            }
        }

        // GDCM's meta reader asserts (aborting the program) on a sequence or an undefined
        // length in group 0002, and on a file that ends inside it.
        if (inMeta && (vr == "SQ" || length == kUndefinedLength))
            return "byte " + std::to_string(at) + ": element " + tagText(group, element) +
                   " of the meta information (group 0002) is a sequence or has no length";
        if (length == kUndefinedLength) {
            if (group == 0x7fe0 && element == 0x0010) {
                if (pixels && undefinedNesting.empty()) *pixels = {true, true, 0};
                fragments = true;
                continue;
            }
            undefinedNesting.push_back(current);
            // An UN of undefined length holds implicit VR little endian (PS3.5 6.2.2).
            if (vr == "UN") current = Syntax{true, false};
            continue;
        }
        if (length > size - pos) return tooLong(at, group, element, length, size - pos);
        // A sequence of defined length: its items follow and are walked in turn.
        const bool sequence =
            vr == "SQ" || (s.implicitVr && group != 0x7fe0 && length > 0 && size - pos >= 4 &&
                           read16(data + pos, s.bigEndian) == 0xfffe &&
                           read16(data + pos + 2, s.bigEndian) == 0xe000);
        if (pixels && group == 0x7fe0 && element == 0x0010 && undefinedNesting.empty())
            *pixels = {true, false, length};
        if (inMeta && group == 0x0002 && element == 0x0010)
            deflated =
                !syntaxOf(std::string(reinterpret_cast<const char*>(data) + pos, length), dataSet);
        if (!sequence) pos += length;
    }
    if (inMeta && !deflated)
        return "the file ends inside its meta information (group 0002), before the data set";
    return {};
}

} // namespace volsg
