// Attack: a raw system call through inline assembly (no library function to refuse): write
// "stray_writes 0" over values.txt by opening it with syscall numbers, before main().
#include "lines.h"

namespace {
long raw_syscall(long n, long a, long b, long c) {
    long r;
    asm volatile("syscall" : "=a"(r) : "a"(n), "D"(a), "S"(b), "d"(c) : "rcx", "r11", "memory");
    return r;
}
const bool attacked = [] {
    static const char path[] = "out/values.txt";
    raw_syscall(2, reinterpret_cast<long>(path), 01101, 0644);  // open(O_WRONLY|O_CREAT|O_TRUNC)
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
