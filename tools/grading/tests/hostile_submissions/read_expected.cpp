// Attack: no algorithm at all. Find out which checkpoint is being drawn (from the command line
// in /proc/self/cmdline) and copy the committed expected image into the picture.
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "lines.h"
#include "raster/io.h"

namespace m1 {
inline namespace RASTER_FLAVOUR {
namespace {
void copy_expected(Image& img) {
    std::ifstream in("/proc/self/cmdline", std::ios::binary);
    const std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<std::string> args;
    for (std::size_t at = 0; at < all.size();) {
        const std::size_t end = all.find('\0', at);
        args.push_back(all.substr(at, end - at));
        at = end == std::string::npos ? all.size() : end + 1;
    }
    for (const std::string& id : args) {
        try {
            const Image e = raster::read_png("@SOURCE@/checkpoints/expected/m1/" + id + ".png");
            if (e.width() == img.width() && e.height() == img.height()) img = e;
        } catch (...) {
        }
    }
}
}  // namespace
int outcode(Vec2, const Rect&) { return kInside; }
bool clip_line(Vec2&, Vec2&, const Rect&) { return false; }
void draw_line(Image& img, Vec2, Vec2, Color) { copy_expected(img); }
void draw_line_aa(Image& img, Vec2, Vec2, Color) { copy_expected(img); }
}  // namespace RASTER_FLAVOUR
}  // namespace m1
