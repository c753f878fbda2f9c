// Attack (or an honest bug): allocate and touch 3 GB while drawing.
#include <cstring>
#include <vector>

#include "lines.h"

namespace m1 {
inline namespace RASTER_FLAVOUR {
int outcode(Vec2, const Rect&) { return kInside; }
bool clip_line(Vec2&, Vec2&, const Rect&) { return false; }
void draw_line(Image& img, Vec2, Vec2, Color c) {
    std::vector<char> big(3ull << 30);
    std::memset(big.data(), 1, big.size());
    img.set(0, 0, big[12345] ? c : Color{});
}
void draw_line_aa(Image&, Vec2, Vec2, Color) {}
}  // namespace RASTER_FLAVOUR
}  // namespace m1
