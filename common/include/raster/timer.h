// Wall-clock stopwatch for reporting render times. Times are reported, never judged: a
// checkpoint's verdict must not depend on how busy the machine is.
#pragma once

#include <chrono>

namespace raster {

class Stopwatch {
public:
    Stopwatch() : start_(Clock::now()) {}
    void restart() { start_ = Clock::now(); }
    double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
    double milliseconds() const { return seconds() * 1e3; }

private:
    using Clock = std::chrono::steady_clock;
    Clock::time_point start_;
};

}  // namespace raster
