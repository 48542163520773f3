// The Inventor sample models of Debian's inventor-data package (SGI's, 97 files: 72 binary
// V2.1, 6 binary V2.0, 18 ASCII V2.1, one ASCII V1.0) read, with the node types this library
// has no class for kept as unknown nodes, and write back to text that reads to the same graph.
// Skipped where the package is not installed (`apt-get install inventor-data`).
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <volsg/core/Error.h>
#include <volsg/fields/Fields.h>
#include <volsg/io/GraphCompare.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/SceneWriter.h>
#include <volsg/io/UnknownNode.h>

using namespace volsg;

namespace {

const std::filesystem::path modelsDir = "/usr/share/inventor/data/models";

std::vector<std::filesystem::path> models() {
    std::vector<std::filesystem::path> out;
    std::error_code ec;
    if (!std::filesystem::is_directory(modelsDir, ec)) return out;
    for (const auto& e : std::filesystem::recursive_directory_iterator(modelsDir))
        if (e.is_regular_file() && e.path().extension() == ".iv") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

std::string header(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::string line;
    std::getline(in, line);
    while (!line.empty() && (line.back() == ' ' || line.back() == '\r'))
        line.pop_back();
    return line;
}

void countUnknown(const Node* node, std::map<std::string, int>& types,
                  std::map<const Node*, bool>& seen) {
    if (!node || seen[node]) return;
    seen[node] = true;
    if (const auto* u = dynamic_cast<const UnknownNode*>(node)) ++types[u->fileTypeName()];
    for (std::size_t i = 0; i < node->fieldCount(); ++i) {
        const Field* f = node->fieldAt(i);
        if (const auto* sf = dynamic_cast<const SFNode*>(f))
            countUnknown(sf->getValue(), types, seen);
        if (const auto* mf = dynamic_cast<const MFNode*>(f))
            for (const auto& v : mf->getValues())
                countUnknown(v.get(), types, seen);
        if (f && f->connection()) countUnknown(f->connection()->source.get(), types, seen);
    }
    if (const auto* c = node->children())
        for (const auto& child : *c)
            countUnknown(child.get(), types, seen);
}

} // namespace

TEST_CASE("every inventor-data model reads, with unknown types kept, and round-trips as text") {
    const auto files = models();
    if (files.empty()) {
        MESSAGE("inventor-data is not installed: skipped");
        return;
    }
    ReadOptions keep;
    keep.keepUnknownTypes = true;
    std::map<std::string, int> byHeader, unknownTypes, filesNeeding;
    int read = 0, withoutUnknown = 0;
    for (const auto& path : files) {
        CAPTURE(path.string());
        ++byHeader[header(path)];
        ref_ptr<Node> root;
        try {
            root = readScene(path.string(), keep);
        } catch (const Error& e) {
            FAIL_CHECK(std::string(e.what()));
            continue;
        }
        ++read;
        std::map<std::string, int> types;
        std::map<const Node*, bool> seen;
        countUnknown(root.get(), types, seen);
        if (types.empty()) ++withoutUnknown;
        for (const auto& [type, count] : types) {
            unknownTypes[type] += count;
            ++filesNeeding[type];
        }
        // Written as text and read again: the same graph, and the same text again.
        const std::string text = writeSceneToString(*root);
        ref_ptr<Node> back;
        try {
            back = readSceneFromString(text, path.string() + ".written.iv", keep);
        } catch (const Error& e) {
            FAIL_CHECK(std::string(e.what()));
            continue;
        }
        std::string why;
        CHECK_MESSAGE(graphsEqual(*root, *back, &why), why);
        CHECK(writeSceneToString(*back) == text);
    }
    CHECK(read == int(files.size()));
    std::ostringstream report;
    report << read << " of " << files.size() << " models read; " << withoutUnknown
           << " without unknown node types. Headers:";
    for (const auto& [h, n] : byHeader)
        report << " [" << h << "] " << n;
    report << "\nnode types kept as unknown nodes (nodes, files):";
    std::vector<std::pair<std::string, int>> sorted(unknownTypes.begin(), unknownTypes.end());
    std::sort(sorted.begin(), sorted.end(), [&](const auto& a, const auto& b) {
        return filesNeeding[a.first] > filesNeeding[b.first];
    });
    for (const auto& [type, count] : sorted)
        report << " " << type << " (" << count << ", " << filesNeeding[type] << ")";
    MESSAGE(report.str());
}
