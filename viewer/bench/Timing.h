#pragma once
// Time sampling for the benchmark: wall-clock medians and minima, process CPU; never
// assertions.

#include <algorithm>
#include <chrono>
#include <ctime>
#include <vector>

namespace volsg::bench {

struct Samples {
    std::vector<double> ms;
    double median() const {
        if (ms.empty()) return 0.0;
        std::vector<double> s = ms;
        std::sort(s.begin(), s.end());
        const std::size_t n = s.size();
        return n % 2 ? s[n / 2] : 0.5 * (s[n / 2 - 1] + s[n / 2]);
    }
    double min() const { return ms.empty() ? 0.0 : *std::min_element(ms.begin(), ms.end()); }
};

/// Runs `f` and returns its duration in milliseconds.
template <class F> double timeMs(F&& f) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    const auto t1 = std::chrono::steady_clock::now();
    return std::chrono::duration<double, std::milli>(t1 - t0).count();
}

/// CPU time of the whole process (all its threads, llvmpipe's included), ms.
inline double processCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

} // namespace volsg::bench
