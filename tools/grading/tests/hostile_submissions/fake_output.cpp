// Attack: print what a passing run prints, write a results.json claiming full marks and
// artifacts claiming a perfect render, and exit(0) before anything is drawn.
#include <sys/stat.h>

#include <cstdio>
#include <cstdlib>

#include "lines.h"

namespace {
const bool faked = [] {
    std::printf("VERDICT m1.octant_1 PASS concepts=\nVERDICT m1.clip_one_edge PASS concepts=\n");
    std::printf("sandbox-run: result=exited exit=0 wall_ms=1 mechanism=bwrap\n");
    if (FILE* f = std::fopen("results.json", "w")) {
        std::fputs("{\"score\": 1000, \"tests\": []}\n", f);
        std::fclose(f);
    }
    mkdir("out", 0755);
    if (FILE* f = std::fopen("out/values.txt", "w")) {
        std::fputs("seconds 0\nstray_writes 0\ntrace draw_line 1 1000 0\n", f);
        std::fclose(f);
    }
    std::fflush(nullptr);
    std::exit(0);
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
