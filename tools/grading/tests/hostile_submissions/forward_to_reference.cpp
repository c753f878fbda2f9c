// Attack: call the reference solution, which `make check` links into every checkpoint program.
// The grader's render program has no reference: this must not link.
#include "lines.h"

namespace m1 {
inline namespace reference {
int outcode(Vec2 p, const Rect& r);
bool clip_line(Vec2& a, Vec2& b, const Rect& r);
void draw_line(Image& img, Vec2 a, Vec2 b, Color c);
void draw_line_aa(Image& img, Vec2 a, Vec2 b, Color c);
}  // namespace reference
namespace student {
int outcode(Vec2 p, const Rect& r) { return reference::outcode(p, r); }
bool clip_line(Vec2& a, Vec2& b, const Rect& r) { return reference::clip_line(a, b, r); }
void draw_line(Image& img, Vec2 a, Vec2 b, Color c) { reference::draw_line(img, a, b, c); }
void draw_line_aa(Image& img, Vec2 a, Vec2 b, Color c) { reference::draw_line_aa(img, a, b, c); }
}  // namespace student
}  // namespace m1
