// The parts of the harness that need no test framework (used by the demos and tools too).
#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "harness/checkpoint.h"
#include "raster/timer.h"

namespace fs = std::filesystem;

namespace cp {

double time_best_of(const std::function<void()>& fn) {
    // One run is enough for anything slow; tiny scenes are repeated (up to 5 runs or about
    // 50 ms) and the fastest run is kept, which is the figure least disturbed by the machine.
    double best = 0, total = 0;
    for (int run = 0; run < 5; ++run) {
        raster::Stopwatch sw;
        fn();
        const double t = sw.seconds();
        best = run == 0 ? t : std::min(best, t);
        total += t;
        if (total > 0.05) break;
    }
    return best;
}

std::string expected_png_path(const std::string& milestone, const std::string& id) {
    const fs::path dir = [] {
        const char* v = std::getenv("RASTER_EXPECTED_DIR");
        return v && *v ? std::string(v) : std::string(RASTER_DEFAULT_EXPECTED_DIR);
    }();
    return (dir / milestone / (id + ".png")).string();
}

}  // namespace cp
