// Attack: before main() (so before the checkpoint's watchdog exists), ignore SIGTERM and spin
// forever. Only the sandbox's SIGKILL deadline ends it.
#include <csignal>

#include "lines.h"

namespace {
volatile unsigned long long spins = 0;
const bool stuck = [] {
    std::signal(SIGTERM, SIG_IGN);
    std::signal(SIGHUP, SIG_IGN);
    for (;;) spins = spins + 1;
    return true;
}();
}  // namespace

namespace m1 {
inline namespace RASTER_FLAVOUR {
int outcode(Vec2, const Rect&) { return kInside; }
bool clip_line(Vec2&, Vec2&, const Rect&) { return false; }
void draw_line(Image&, Vec2, Vec2, Color) {}
void draw_line_aa(Image&, Vec2, Vec2, Color) {}
}  // namespace RASTER_FLAVOUR
}  // namespace m1
