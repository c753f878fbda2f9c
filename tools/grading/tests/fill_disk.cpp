// A submission for grade_test.sh's full_disk case (graded without the code check): its render
// writes 16 MB files into its working folder until the file system is full, then draws nothing.
// With a size-limited folder per submission, only its own checkpoints suffer.
#include <cstdio>
#include <string>
#include <vector>

#include "lines.h"

namespace {
const bool filled = [] {
    const std::vector<char> block(1 << 20, 'x');
    for (int i = 0; i < 1000; ++i) {
        FILE* f = std::fopen(("fill-" + std::to_string(i)).c_str(), "w");
        if (!f) break;
        bool full = false;
        for (int mb = 0; mb < 16 && !full; ++mb) full = std::fwrite(block.data(), 1, block.size(), f) != block.size();
        full = std::fclose(f) != 0 || full;
        if (full) break;
    }
    return true;
}();
}  // namespace

namespace m1 {
inline namespace RASTER_FLAVOUR {
int outcode(Vec2, const Rect&) { return kInside; }
bool clip_line(Vec2&, Vec2&, const Rect&) { return filled; }
void draw_line(Image&, Vec2, Vec2, Color) {}
void draw_line_aa(Image&, Vec2, Vec2, Color) {}
}  // namespace RASTER_FLAVOUR
}  // namespace m1
