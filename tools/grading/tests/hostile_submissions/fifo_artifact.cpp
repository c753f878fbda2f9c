// Attack: the main image is a FIFO. A reader that simply opens it waits for a writer forever.
#include <sys/stat.h>

#include <cstdio>
#include <cstdlib>

#include "lines.h"

namespace {
const bool planted = [] {
    mkdir("out", 0755);
    if (FILE* f = std::fopen("out/values.txt", "w")) {
        std::fputs("seconds 0\nstray_writes 0\n", f);
        std::fclose(f);
    }
    mkfifo("out/main.png", 0644);
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
