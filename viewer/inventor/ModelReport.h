#pragma once
// The rows of volsg-coin-compare: what happened to each model, the summary, and the text, TSV
// and Markdown they are printed as. No Coin and no GL here (tests/inventor/CoinCompareTest.cpp).

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ImageCompare.h"

namespace volsg::coincompare {

/// Longest message a row holds (longer ones are cut and end in "...").
inline constexpr std::size_t maxMessageLength = 240;

/// `text` on one line: control characters (newlines, tabs) become spaces, runs of spaces one,
/// no leading or trailing space, at most `maxLength` bytes (cut on a UTF-8 character boundary,
/// then "..." appended within the limit).
std::string oneLine(std::string_view text, std::size_t maxLength = maxMessageLength);

/// The kind of file its first line names: "V2.1 binary", "V2.0 binary", "V2.1 ascii",
/// "V1.0 ascii", "VRML V1.0 ascii"; "no Inventor header" otherwise, "unreadable" when the file
/// cannot be opened.
std::string headerKind(const std::string& path);
/// The same from the file's first bytes.
std::string headerKindOf(std::string_view firstBytes);

/// One model's row.
struct ModelRow {
    std::string model;  ///< the path as shown: relative to the folder it was found in
    std::string header; ///< headerKind()
    bool readOk = false;
    std::string readError; ///< volsg's error reading the original (one line), when !readOk
    bool coinRendered = false;
    bool volsgRendered = false;
    /// volsg's error reading or rendering the framed copy (one line), when Coin framed the model
    /// and volsg did not render it.
    std::string renderError;
    /// The node types of the framed copy that volsg's reader does not know, sorted, separated
    /// by spaces ("" when none or not framed).
    std::string missingTypes;
    bool compared = false; ///< both rendered: `comparison` holds the numbers
    Comparison comparison;
    Rgb8 coinBackground{}; ///< the colour Coin's clear left (compared against), when Coin rendered
    bool writeBackOk = false;
    std::string writeBackError; ///< why Coin did not read volsg's write-back cleanly
    std::string notes;          ///< render failures, Coin's own messages, timeouts (one line)

    /// Both rendered, Coin's image shows something (two empty images agree about nothing) and
    /// the comparison is within the thresholds.
    bool agree() const { return compared && comparison.pixelsA > 0 && agrees(comparison); }
};

/// A row as one line of tab-separated fields (every field is oneLine()'d, so no tab or newline
/// inside), and back: the worker processes hand rows to the main process this way.
std::string serialize(const ModelRow& row);
/// Throws volsg::Error when `line` is not a serialized row.
ModelRow deserialize(std::string_view line);

/// The printed table: a header line and one tab-separated line per row.
std::string tableHeader();
std::string tableLine(const ModelRow& row);

struct Summary {
    int models = 0;
    int read = 0;
    int coinRendered = 0;
    int volsgRendered = 0;
    int agree = 0;
    int writtenBack = 0;
};
Summary summarize(const std::vector<ModelRow>& rows);
/// "read 5/97, agree 3/97, written back ok 2/97 (rendered: Coin 97/97, volsg 10/97)".
std::string summaryLine(const Summary& s);

/// The node type names an Inventor ASCII text uses (each name written before a '{', outside
/// comments and strings), sorted, each once.
std::vector<std::string> nodeTypeNames(std::string_view text);
/// Those of `names` that volsg's reader does not know (volsg::nodeTypes()).
std::vector<std::string> typesVolsgLacks(const std::vector<std::string>& names);

/// What kind of error a message is: without its "file:line:column: " and anything from " ("
/// on, so that the same problem in many models counts once ("unknown node type 'Info'").
std::string errorKind(std::string_view message);
/// The kinds of the given messages, most frequent first (ties by name), with their counts.
std::vector<std::pair<std::string, int>> countKinds(const std::vector<std::string>& messages);
/// "12 x unknown node type 'Info'; 3 x ..." for the `limit` most frequent kinds.
std::string formatKinds(const std::vector<std::pair<std::string, int>>& kinds, std::size_t limit);

/// True when at least `fraction` of the models agree (a fraction in [0,1]; 0 always holds).
bool meetsAgreement(const Summary& s, double fraction);

/// The Markdown table: `intro` (already Markdown), then one row per model with an empty
/// "why it differs" column for people to fill in. Pipes in messages are escaped.
std::string markdownTable(const std::vector<ModelRow>& rows, const std::string& intro);

/// Named one-line values, as a child process hands them back: "key=value" lines.
using Fields = std::map<std::string, std::string>;
std::string encodeFields(const Fields& fields); ///< values oneLine()'d (bounded to 4096 bytes)
Fields decodeFields(std::string_view text);     ///< lines without '=' are ignored

/// "0.917" or "-" when not compared.
std::string formatIoU(const ModelRow& row);
std::string formatColourDifference(const ModelRow& row);

} // namespace volsg::coincompare
