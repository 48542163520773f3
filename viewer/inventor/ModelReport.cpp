#include "ModelReport.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include <volsg/core/Error.h>
#include <volsg/fields/Fields.h>
#include <volsg/io/ReaderSupport.h>
#include <volsg/nodes/BuiltinNodes.h>

namespace volsg::coincompare {

std::string oneLine(std::string_view text, std::size_t maxLength) {
    std::string out;
    out.reserve(std::min(text.size(), maxLength + 8));
    bool pendingSpace = false;
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u == 0x7f || c == ' ') {
            pendingSpace = !out.empty();
            continue;
        }
        if (pendingSpace) out += ' ';
        pendingSpace = false;
        out += c;
        if (out.size() > maxLength + 4) break; // enough to know it must be cut
    }
    if (out.size() <= maxLength) return out;
    const std::string_view ellipsis = "...";
    std::size_t cut = maxLength > ellipsis.size() ? maxLength - ellipsis.size() : 0;
    // Do not cut a UTF-8 character: back off over continuation bytes (10xxxxxx).
    while (cut > 0 && (static_cast<unsigned char>(out[cut]) & 0xc0) == 0x80)
        --cut;
    out.resize(cut);
    while (!out.empty() && out.back() == ' ')
        out.pop_back();
    out += ellipsis.substr(0, std::min(ellipsis.size(), maxLength - out.size()));
    return out;
}

std::string headerKindOf(std::string_view firstBytes) {
    const std::size_t end = firstBytes.find_first_of("\r\n");
    std::string_view line = firstBytes.substr(0, end);
    while (!line.empty() && (line.back() == ' ' || line.back() == '\t' || line.back() == '\0'))
        line.remove_suffix(1);
    const std::string_view inventor = "#Inventor ";
    const std::string_view vrml = "#VRML ";
    if (line.substr(0, inventor.size()) == inventor) {
        const std::string_view kind = line.substr(inventor.size());
        if (kind.size() >= 4 && kind[0] == 'V') return oneLine(kind, 40);
    } else if (line.substr(0, vrml.size()) == vrml) {
        return oneLine(line.substr(1), 40);
    }
    return "no Inventor header";
}

std::string headerKind(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return "unreadable";
    char buffer[80] = {};
    in.read(buffer, sizeof buffer);
    return headerKindOf(std::string_view(buffer, std::size_t(in.gcount())));
}

namespace {

std::string number(double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

std::vector<std::string_view> splitTabs(std::string_view line) {
    std::vector<std::string_view> fields;
    std::size_t start = 0;
    while (true) {
        const std::size_t tab = line.find('\t', start);
        fields.push_back(line.substr(start, tab == std::string_view::npos ? tab : tab - start));
        if (tab == std::string_view::npos) break;
        start = tab + 1;
    }
    return fields;
}

double parseNumber(std::string_view text) {
    const std::string s(text);
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || *end != '\0') throw volsg::Error("bad number '" + oneLine(s, 40) + "'");
    return v;
}

bool parseFlag(std::string_view text) {
    if (text == "1") return true;
    if (text == "0") return false;
    throw volsg::Error("bad flag '" + oneLine(text, 40) + "'");
}

const char* serialTag = "row1";
constexpr std::size_t serialFields = 20;

} // namespace

std::string serialize(const ModelRow& row) {
    const Comparison& c = row.comparison;
    const std::string fields[] = {serialTag,
                                  oneLine(row.model, 4096),
                                  oneLine(row.header),
                                  row.readOk ? "1" : "0",
                                  oneLine(row.readError),
                                  row.coinRendered ? "1" : "0",
                                  row.volsgRendered ? "1" : "0",
                                  oneLine(row.renderError),
                                  oneLine(row.missingTypes, 4096),
                                  row.compared ? "1" : "0",
                                  number(double(c.pixelsA)),
                                  number(double(c.pixelsB)),
                                  number(double(c.intersection)),
                                  number(double(c.unionCount)),
                                  number(c.iou),
                                  number(c.colourDifference),
                                  std::to_string(row.coinBackground[0]) + "," +
                                      std::to_string(row.coinBackground[1]) + "," +
                                      std::to_string(row.coinBackground[2]),
                                  row.writeBackOk ? "1" : "0",
                                  oneLine(row.writeBackError),
                                  oneLine(row.notes, 2 * maxMessageLength)};
    static_assert(std::size(fields) == serialFields);
    std::string line;
    for (const std::string& f : fields) {
        if (!line.empty()) line += '\t';
        line += f;
    }
    return line;
}

ModelRow deserialize(std::string_view line) {
    const std::vector<std::string_view> f = splitTabs(line);
    if (f.size() != serialFields || f[0] != serialTag)
        throw volsg::Error("not a model row: '" + oneLine(line, 80) + "'");
    ModelRow row;
    row.model = f[1];
    row.header = f[2];
    row.readOk = parseFlag(f[3]);
    row.readError = f[4];
    row.coinRendered = parseFlag(f[5]);
    row.volsgRendered = parseFlag(f[6]);
    row.renderError = f[7];
    row.missingTypes = f[8];
    row.compared = parseFlag(f[9]);
    row.comparison.pixelsA = static_cast<long long>(parseNumber(f[10]));
    row.comparison.pixelsB = static_cast<long long>(parseNumber(f[11]));
    row.comparison.intersection = static_cast<long long>(parseNumber(f[12]));
    row.comparison.unionCount = static_cast<long long>(parseNumber(f[13]));
    row.comparison.iou = parseNumber(f[14]);
    row.comparison.colourDifference = parseNumber(f[15]);
    int rgb[3] = {0, 0, 0};
    const std::string background(f[16]);
    if (std::sscanf(background.c_str(), "%d,%d,%d", &rgb[0], &rgb[1], &rgb[2]) != 3)
        throw volsg::Error("bad colour '" + oneLine(background, 40) + "'");
    for (int k = 0; k < 3; ++k)
        row.coinBackground[k] = static_cast<std::uint8_t>(std::clamp(rgb[k], 0, 255));
    row.writeBackOk = parseFlag(f[17]);
    row.writeBackError = f[18];
    row.notes = f[19];
    return row;
}

std::string encodeFields(const Fields& fields) {
    std::string text;
    for (const auto& [key, value] : fields)
        text += key + '=' + oneLine(value, 4096) + '\n';
    return text;
}

Fields decodeFields(std::string_view text) {
    Fields fields;
    while (!text.empty()) {
        const std::size_t end = text.find('\n');
        const std::string_view line = text.substr(0, end);
        const std::size_t eq = line.find('=');
        if (eq != std::string_view::npos)
            fields[std::string(line.substr(0, eq))] = std::string(line.substr(eq + 1));
        if (end == std::string_view::npos) break;
        text.remove_prefix(end + 1);
    }
    return fields;
}

std::string formatIoU(const ModelRow& row) {
    if (!row.compared) return "-";
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", row.comparison.iou);
    return text;
}

std::string formatColourDifference(const ModelRow& row) {
    if (!row.compared) return "-";
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", row.comparison.colourDifference);
    return text;
}

namespace {

std::string readCell(const ModelRow& row) {
    return row.readOk ? "ok" : "error: " + row.readError;
}

std::string renderCell(const ModelRow& row) {
    if (row.volsgRendered) return "ok";
    return row.renderError.empty() ? "-" : "error: " + row.renderError;
}

std::string writeBackCell(const ModelRow& row) {
    return row.writeBackOk ? "ok" : "error: " + row.writeBackError;
}

} // namespace

std::string tableHeader() {
    return "model\theader\tvolsg read\tvolsg render (framed copy)\tnode types volsg lacks\tIoU\t"
           "colour diff\tagree\twrite-back read by Coin\tnotes";
}

std::string tableLine(const ModelRow& row) {
    return row.model + '\t' + row.header + '\t' + readCell(row) + '\t' + renderCell(row) + '\t' +
           (row.missingTypes.empty() ? "-" : row.missingTypes) + '\t' + formatIoU(row) + '\t' +
           formatColourDifference(row) + '\t' + (row.agree() ? "yes" : "no") + '\t' +
           writeBackCell(row) + '\t' + (row.notes.empty() ? "-" : row.notes);
}

Summary summarize(const std::vector<ModelRow>& rows) {
    Summary s;
    s.models = int(rows.size());
    for (const ModelRow& r : rows) {
        s.read += r.readOk;
        s.coinRendered += r.coinRendered;
        s.volsgRendered += r.volsgRendered;
        s.agree += r.agree();
        s.writtenBack += r.writeBackOk;
    }
    return s;
}

std::string summaryLine(const Summary& s) {
    const std::string n = "/" + std::to_string(s.models);
    return "read " + std::to_string(s.read) + n + ", agree " + std::to_string(s.agree) + n +
           ", written back ok " + std::to_string(s.writtenBack) + n + " (rendered: Coin " +
           std::to_string(s.coinRendered) + n + ", volsg " + std::to_string(s.volsgRendered) + n +
           ")";
}

std::vector<std::string> nodeTypeNames(std::string_view text) {
    std::vector<std::string> names;
    std::string last; // the identifier just before, if nothing but space came after it
    auto isStart = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; };
    auto isPart = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    for (std::size_t i = 0; i < text.size();) {
        const char c = text[i];
        if (c == '#') { // a comment to the end of the line
            while (i < text.size() && text[i] != '\n')
                ++i;
            last.clear();
        } else if (c == '"') { // a string, with backslash escapes
            for (++i; i < text.size() && text[i] != '"'; ++i)
                if (text[i] == '\\') ++i;
            ++i;
            last.clear();
        } else if (isStart(c)) {
            const std::size_t start = i;
            while (i < text.size() && isPart(text[i]))
                ++i;
            last = std::string(text.substr(start, i - start));
        } else if (c == '{') {
            if (!last.empty()) names.push_back(last);
            last.clear();
            ++i;
        } else {
            if (!std::isspace(static_cast<unsigned char>(c))) last.clear();
            ++i;
        }
    }
    std::sort(names.begin(), names.end());
    names.erase(std::unique(names.begin(), names.end()), names.end());
    return names;
}

std::vector<std::string> typesVolsgLacks(const std::vector<std::string>& names) {
    std::vector<std::string> lacking;
    for (const std::string& name : names)
        if (!volsg::reader::registry().find(name)) lacking.push_back(name);
    return lacking;
}

std::string errorKind(std::string_view message) {
    // "file:line:column: " (the file may hold spaces but not ": ").
    const std::size_t colonSpace = message.find(": ");
    if (colonSpace != std::string_view::npos) {
        const std::string_view head = message.substr(0, colonSpace);
        const std::size_t c2 = head.rfind(':');
        const std::size_t c1 = c2 == std::string_view::npos ? c2 : head.rfind(':', c2 - 1);
        auto digits = [](std::string_view t) {
            return !t.empty() && t.find_first_not_of("0123456789") == std::string_view::npos;
        };
        if (c1 != std::string_view::npos && digits(head.substr(c1 + 1, c2 - c1 - 1)) &&
            digits(head.substr(c2 + 1)))
            message.remove_prefix(colonSpace + 2);
    }
    const std::size_t paren = message.find(" (");
    return oneLine(message.substr(0, paren));
}

std::vector<std::pair<std::string, int>> countKinds(const std::vector<std::string>& messages) {
    std::map<std::string, int> counts;
    for (const std::string& m : messages)
        ++counts[errorKind(m)];
    std::vector<std::pair<std::string, int>> kinds(counts.begin(), counts.end());
    std::stable_sort(kinds.begin(), kinds.end(),
                     [](const auto& a, const auto& b) { return a.second > b.second; });
    return kinds;
}

std::string formatKinds(const std::vector<std::pair<std::string, int>>& kinds, std::size_t limit) {
    std::string text;
    for (std::size_t i = 0; i < kinds.size() && i < limit; ++i)
        text +=
            (text.empty() ? "" : "; ") + std::to_string(kinds[i].second) + " x " + kinds[i].first;
    if (kinds.size() > limit) text += "; " + std::to_string(kinds.size() - limit) + " more kinds";
    return text.empty() ? "none" : text;
}

bool meetsAgreement(const Summary& s, double fraction) {
    if (fraction <= 0.0) return true;
    // agree/models >= fraction, without dividing (no rounding at exactly the threshold).
    return double(s.agree) >= fraction * double(s.models) - 1e-9;
}

namespace {

std::string markdownCell(const std::string& text) {
    std::string out;
    for (const char c : text) {
        if (c == '|') out += '\\';
        out += c;
    }
    return out.empty() ? " " : out;
}

} // namespace

std::string markdownTable(const std::vector<ModelRow>& rows, const std::string& intro) {
    std::string md = intro;
    if (!md.empty() && md.back() != '\n') md += '\n';
    md += "\n| model | header | volsg read | volsg render (framed copy) | node types volsg lacks | "
          "IoU | colour diff | agree | write-back read by Coin | notes | why it differs |\n";
    md += "| --- | --- | --- | --- | --- | ---: | ---: | --- | --- | --- | --- |\n";
    for (const ModelRow& r : rows) {
        md += "| " + markdownCell(r.model) + " | " + markdownCell(r.header) + " | " +
              markdownCell(readCell(r)) + " | " + markdownCell(renderCell(r)) + " | " +
              markdownCell(r.missingTypes) + " | " + formatIoU(r) + " | " +
              formatColourDifference(r) + " | " + (r.agree() ? "yes" : "no") + " | " +
              markdownCell(writeBackCell(r)) + " | " + markdownCell(r.notes) + " |   |\n";
    }
    return md;
}

} // namespace volsg::coincompare
