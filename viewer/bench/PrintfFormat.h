#pragma once
// printf-style formatting of up to four numbers into a string, for the benchmark's tables.

#include <cstdio>
#include <string>

namespace volsg::bench {

/// `pattern` (printf conversions for doubles) filled with a, b, c, d; the numbers the pattern
/// does not name are ignored.
inline std::string printfFormat(const char* pattern, double a, double b = 0.0, double c = 0.0,
                                double d = 0.0) {
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, pattern, a, b, c, d);
    return buffer;
}

} // namespace volsg::bench
