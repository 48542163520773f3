#include "TerminalProgress.h"

#include <algorithm>
#include <cmath>

#include <unistd.h>

namespace volsg::cli {

std::string progressLine(const std::string& task, double fraction, const std::string& stage,
                         int width) {
    const double f = std::isfinite(fraction) ? std::clamp(fraction, 0.0, 1.0) : 0.0;
    const int filled = int(std::lround(f * width));
    std::string line = "\r" + task + " [";
    line.append(std::size_t(filled), '#');
    line.append(std::size_t(width - filled), '.');
    char percent[16];
    std::snprintf(percent, sizeof percent, "] %3d%%  ", int(std::lround(f * 100.0)));
    return line + percent + stage + "\x1b[K";
}

TerminalProgress::TerminalProgress(std::string task, std::FILE* out, bool force)
    : task_(std::move(task)), out_(out), enabled_(force || (out && isatty(fileno(out)) == 1)) {}

TerminalProgress::~TerminalProgress() {
    finish();
}

void TerminalProgress::stage(double fraction, const std::string& stage) {
    if (!enabled_) return;
    std::fputs(progressLine(task_, fraction, stage).c_str(), out_);
    std::fflush(out_);
}

void TerminalProgress::finish() {
    if (!enabled_) return;
    std::fputs("\r\x1b[K", out_);
    std::fflush(out_);
    enabled_ = false;
}

} // namespace volsg::cli
