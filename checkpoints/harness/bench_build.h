// What every `make bench` program shares: the build it was compiled with, printed beside its
// numbers (the ratios depend on the optimisation level), and the timing helpers. CMake defines
// RASTER_BUILD_TYPE and RASTER_BUILD_FLAGS (checkpoints/CMakeLists.txt); a compile without them
// says "unknown".
#pragma once

#include <algorithm>
#include <cstdlib>
#include <vector>

#include <time.h>

#include "raster/image.h"

#ifndef RASTER_BUILD_TYPE
#define RASTER_BUILD_TYPE "unknown"
#endif
#ifndef RASTER_BUILD_FLAGS
#define RASTER_BUILD_FLAGS ""
#endif

namespace bench {

// This thread's CPU time in seconds: on a shared machine, wall time would also count the time
// other processes held the core.
inline double cpu_now() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// The best of `runs` runs of fn, in CPU seconds. The benchmarks time their renderers in
// alternating rounds of one run each and report medians and the spread of the ratios.
template <class F>
double best_cpu_seconds(F&& fn, int runs = 1) {
    double best = 0;
    for (int run = 0; run < runs; ++run) {
        const double start = cpu_now();
        fn();
        const double t = cpu_now() - start;
        best = run == 0 ? t : std::min(best, t);
    }
    return best;
}

inline double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

// Pixels where two images of one size differ by more than `levels` in some channel.
inline long long differing_pixels(const raster::Image& a, const raster::Image& b, int levels = 1) {
    long long n = 0;
    for (std::size_t i = 0; i + 2 < a.size_bytes() && i + 2 < b.size_bytes(); i += 3) {
        bool differ = false;
        for (int k = 0; k < 3; ++k) differ |= std::abs(int(a.data()[i + k]) - int(b.data()[i + k])) > levels;
        n += differ;
    }
    return n;
}

}  // namespace bench
