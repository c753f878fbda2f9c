// Attack: start children that leave the session, ignore SIGTERM and SIGHUP, and wait for the
// verdict to be written, to rewrite it afterwards. Their command line carries a marker the test
// looks for (@MARKER@, one per test: tests running side by side must not see each other's
// children): none may be left when grading ends.
#include <sys/prctl.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>

#include "lines.h"

namespace {
const bool spawned = [] {
    for (int i = 0; i < 3; ++i) {
        if (fork() == 0) {
            setsid();
            if (fork() != 0) _exit(0);  // double fork: re-parented away from the render
            std::signal(SIGTERM, SIG_IGN);
            std::signal(SIGHUP, SIG_IGN);
            execl("/bin/sh", "sh", "-c", "exec -a @MARKER@ sleep 600", static_cast<char*>(nullptr));
            _exit(0);
        }
    }
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
