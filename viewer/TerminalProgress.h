#pragma once
// A one-line progress bar on stderr for the command-line tools, drawn only when stderr is a
// terminal: a log file or a pipe never gets carriage returns and escape codes.

#include <cstdio>
#include <string>

namespace volsg::cli {

/// "\r<task> [########............]  40%  <stage>" followed by an erase-to-end-of-line code:
/// the text one update writes (`width` characters of bar; `fraction` clamped to [0, 1]).
std::string progressLine(const std::string& task, double fraction, const std::string& stage,
                         int width = 24);

/// The bar of one run of a tool. Each stage() redraws it; the destructor (or finish()) erases
/// the line, so the tool's own output starts on a clean line.
class TerminalProgress {
public:
    /// Draws on `out` (stderr by default) only when it is a terminal, or when `force` is set
    /// (for tests).
    explicit TerminalProgress(std::string task, std::FILE* out = stderr, bool force = false);
    ~TerminalProgress();
    TerminalProgress(const TerminalProgress&) = delete;
    TerminalProgress& operator=(const TerminalProgress&) = delete;

    bool shown() const { return enabled_; }
    /// `fraction` of the work done, now at `stage` ("reading", "rendering", ...).
    void stage(double fraction, const std::string& stage);
    void finish(); ///< erases the line; later calls draw nothing

private:
    std::string task_;
    std::FILE* out_;
    bool enabled_;
};

} // namespace volsg::cli
