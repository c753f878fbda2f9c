// Attack: find another submission's compiled render program (graded at the same time, without
// bubblewrap) and run it on this checkpoint, copying its artifacts as this one's. Then draw
// nothing of its own.
#include <glob.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

#include "lines.h"

namespace {
const bool attacked = [] {
    // Next to its own folder first (the render runs in <tmp>/raster-grade.XXXXXX/run/<checkpoint>),
    // then where the grader puts them by default.
    char cwd[4096] = "";
    std::string near = getcwd(cwd, sizeof cwd) ? cwd : "";
    for (int i = 0; i < 3; ++i) near = near.substr(0, near.rfind('/'));
    near += "/raster-grade.*/bin/m1/render";
    glob_t g{};
    if (glob(near.c_str(), 0, nullptr, &g) == 0 || glob("/tmp/*/raster-grade.*/bin/m1/render", 0, nullptr, &g) == 0 ||
        glob("/tmp/raster-grade.*/bin/m1/render", 0, nullptr, &g) == 0) {
        for (size_t i = 0; i < g.gl_pathc; ++i) {
            const std::string cmd = std::string(g.gl_pathv[i]) + " m1.octant_1 0 out";
            if (std::system(cmd.c_str()) == 0) std::_Exit(0);
        }
    }
    return true;
}();
}  // namespace

namespace m1 {
inline namespace RASTER_FLAVOUR {
int outcode(Vec2, const Rect&) { return kInside; }
bool clip_line(Vec2&, Vec2&, const Rect&) { return attacked; }
void draw_line(Image&, Vec2, Vec2, Color) {}
void draw_line_aa(Image&, Vec2, Vec2, Color) {}
}  // namespace RASTER_FLAVOUR
}  // namespace m1
