// Binary Inventor files cut at every byte, and with every byte changed, read or give one
// volsg::Error `file: byte N: message` with N inside the file: never a crash, hang, other
// exception or allocation the file merely asks for (tests/BAD-INPUT.md, binary scene files).
// The files are the seeds of fuzz-binaryscene (real models, tests/fuzz/corpus/binaryscene/).
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <volsg/core/Error.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/SceneWriter.h>

using namespace volsg;
namespace fs = std::filesystem;

namespace {

/// The seeds as whole files: the header their first byte picks, then the rest.
std::vector<std::pair<std::string, std::string>> seeds() {
    std::vector<std::pair<std::string, std::string>> out;
    const fs::path dir = fs::path(VOLSG_SOURCE_DIR) / "tests/fuzz/corpus/binaryscene";
    for (const auto& e : fs::directory_iterator(dir)) {
        if (e.path().extension() != ".bin") continue;
        std::ifstream in(e.path(), std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (bytes.empty()) continue;
        std::string file =
            (bytes[0] & 1) ? "#Inventor V2.1 binary  \n" : "#Inventor V2.0 binary  \n";
        file += bytes.substr(1);
        out.emplace_back(e.path().filename().string(), std::move(file));
    }
    std::sort(out.begin(), out.end());
    return out;
}

/// Reads `bytes`; on an error checks it is `name: byte N: ...` with N < size.
bool readsOrFailsCleanly(const std::string& bytes, const std::string& name, std::string& message) {
    try {
        ref_ptr<Node> root = readSceneFromString(bytes, name);
        (void)writeSceneToString(*root);
        return true;
    } catch (const Error& e) {
        message = e.what();
        const std::string prefix = name + ": byte ";
        if (message.rfind(prefix, 0) != 0) return false;
        const std::size_t offset = std::stoul(message.substr(prefix.size()));
        return offset <= bytes.size() && message.find('\n') == std::string::npos;
    }
}

} // namespace

TEST_CASE("a binary file cut at every byte reads or is refused at a byte offset") {
    const auto files = seeds();
    REQUIRE(files.size() >= 5);
    for (const auto& seed : files) { // not a structured binding: CAPTURE's lambda captures it
        const std::string& name = seed.first;
        const std::string& file = seed.second;
        CAPTURE(name);
        int refused = 0;
        for (std::size_t cut = 24; cut < file.size(); ++cut) {
            std::string message;
            const bool ok = readsOrFailsCleanly(file.substr(0, cut), name, message);
            CHECK_MESSAGE(ok, "cut at ", cut, ": ", message);
            refused += !message.empty();
        }
        // A cut file is short of something, except where it ends between top-level nodes.
        CHECK(refused >= int(file.size() - 24) - 8);
        std::string message;
        CHECK(readsOrFailsCleanly(file, name, message));
        CHECK_MESSAGE(message.empty(), message); // the whole file reads
    }
}

TEST_CASE("a binary file with any one byte changed reads or is refused at a byte offset") {
    for (const auto& seed : seeds()) { // not a structured binding: CAPTURE captures it
        const std::string& name = seed.first;
        const std::string& file = seed.second;
        CAPTURE(name);
        for (std::size_t i = 24; i < file.size(); ++i) {
            for (unsigned char change : {0xFF, 0x80, 0x01}) {
                std::string bad = file;
                bad[i] = char(bad[i] ^ change);
                std::string message;
                CHECK_MESSAGE(readsOrFailsCleanly(bad, name, message), "byte ", i, " ^ ",
                              int(change), ": ", message);
            }
        }
    }
}

TEST_CASE("every input fuzz-binaryscene found reads or is refused at a byte offset") {
    // tests/robustness/inputs/fuzz-binaryscene-*.iv: each was a finding (a crash, a sanitizer
    // report, a leak under the sanitizer build) and is a regression test from then on.
    const fs::path dir = fs::path(VOLSG_SOURCE_DIR) / "tests/robustness/inputs";
    int found = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
        const std::string name = e.path().filename().string();
        if (name.rfind("fuzz-binaryscene-", 0) != 0 || e.path().extension() != ".iv") continue;
        ++found;
        CAPTURE(name);
        std::ifstream in(e.path(), std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::string message;
        CHECK_MESSAGE(readsOrFailsCleanly(bytes, name, message), message);
    }
    CHECK(found >= 1);
}
