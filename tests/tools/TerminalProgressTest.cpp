// The command-line tools' progress bar: its text, and that it stays silent unless stderr is a
// terminal (a pipe or a file gets nothing).

#include <doctest/doctest.h>

#include <cstdio>
#include <string>

#include "../../viewer/TerminalProgress.h"

using volsg::cli::progressLine;
using volsg::cli::TerminalProgress;

namespace {

std::string contents(std::FILE* f) {
    std::rewind(f);
    std::string out;
    for (int c; (c = std::fgetc(f)) != EOF;)
        out += char(c);
    return out;
}

} // namespace

TEST_CASE("the progress line: a bar of # and ., the percentage, the stage, erase to the end") {
    CHECK(progressLine("volsg-render", 0.5, "rendering", 10) ==
          "\rvolsg-render [#####.....]  50%  rendering\x1b[K");
    CHECK(progressLine("t", 0.0, "", 4) == "\rt [....]   0%  \x1b[K");
    CHECK(progressLine("t", 7.0, "", 4) == "\rt [####] 100%  \x1b[K");       // clamped
    CHECK(progressLine("t", 0.0 / 0.0, "", 4) == "\rt [....]   0%  \x1b[K"); // NaN: nothing done
}

TEST_CASE("a file is not a terminal: nothing is written, forced, the line is drawn and erased") {
    std::FILE* file = std::tmpfile();
    REQUIRE(file);
    {
        TerminalProgress quiet("tool", file);
        CHECK_FALSE(quiet.shown());
        quiet.stage(0.5, "working");
    }
    CHECK(contents(file).empty());
    {
        TerminalProgress shown("tool", file, true);
        shown.stage(0.25, "reading");
    }
    CHECK(contents(file) == progressLine("tool", 0.25, "reading") + "\r\x1b[K");
    std::fclose(file);
}
