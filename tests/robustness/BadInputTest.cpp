// Every file in tests/robustness/inputs/ (one per class of bad input and format, and each
// input a fuzzer found) must give a volsg::Error whose message contains the text of its
// `.error` file and names the file: never a crash, hang, other exception or huge allocation.
// tests/BAD-INPUT.md lists them with what the user sees.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "robustness/RobustnessSupport.h"

using namespace volsg;
using namespace volsg::test;
namespace fs = std::filesystem;

namespace {

const fs::path inputs = fs::path(VOLSG_SOURCE_DIR) / "tests/robustness/inputs";

std::vector<fs::path> inputFiles(const std::string& prefix) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(inputs)) {
        const std::string name = entry.path().filename().string();
        const bool isFuzz = name.rfind("fuzz-", 0) == 0;
        if (entry.path().extension() == ".error") continue;
        if (name.rfind(prefix, 0) == 0 || (isFuzz && name.find("-" + prefix) != std::string::npos))
            files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::string expectedError(const fs::path& input) {
    std::ifstream in(input.string() + ".error");
    std::string line;
    std::getline(in, line);
    return line;
}

void checkEveryInput(const std::string& prefix) {
    const std::vector<fs::path> files = inputFiles(prefix);
    REQUIRE(!files.empty());
    for (const fs::path& file : files) {
        CAPTURE(file.filename().string());
        REQUIRE(fs::exists(file.string() + ".error"));
        const std::string expected = expectedError(file);
        const std::string message = loadError(file); // anything but volsg::Error escapes
        CAPTURE(message);
        // VOLSG_PRINT_BAD_INPUT=1 lists what the user sees (tests/BAD-INPUT.md is made from it).
        if (std::getenv("VOLSG_PRINT_BAD_INPUT"))
            std::printf("| `%s` | `%s` |\n", file.filename().string().c_str(), message.c_str());
        CHECK(!message.empty());
        CHECK(message.find(expected) != std::string::npos);
        // The user learns which file: the input itself, or for a refused companion file the
        // message names that one (and the header's own name for volume files).
        const bool namesFile = message.find(file.filename().string()) != std::string::npos;
        CHECK(namesFile);
    }
}

} // namespace

TEST_CASE("every bad scene file gives an error naming the file and the problem") {
    checkEveryInput("scene-");
}

TEST_CASE("every bad NRRD file gives an error naming the file and the problem") {
    checkEveryInput("nrrd-");
}

TEST_CASE("every bad MetaImage file gives an error naming the file and the problem") {
    checkEveryInput("metaimage-");
}

TEST_CASE("every bad glTF file gives an error naming the file and the problem") {
    checkEveryInput("gltf-");
}

TEST_CASE("every bad PNG or PFM image gives an error naming the file and the problem") {
    checkEveryInput("image-");
}
