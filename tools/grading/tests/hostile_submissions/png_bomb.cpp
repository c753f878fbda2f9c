// Attack: the main image is a PNG whose header claims 60000 x 60000 pixels (10 GB decoded).
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
    if (FILE* f = std::fopen("out/main.png", "wb")) {
        const unsigned char header[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R',
                                        0, 0, 0xea, 0x60, 0, 0, 0xea, 0x60, 8, 2, 0, 0, 0};
        std::fwrite(header, 1, sizeof header, f);
        std::fclose(f);
    }
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
