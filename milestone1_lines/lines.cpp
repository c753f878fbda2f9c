// GENERATED from solutions/milestone1_lines/lines.cpp by `make skeletons`. Fill in the TODOs; do not edit the rest.
// Milestone 1: lines. Fill in the numbered TODOs; lines.h says exactly what each
// function must do, and README.md walks through them in the same order.
// Run `make check-m1` in your build folder to see which checkpoints pass.
#include "lines.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>

namespace m1 {
inline namespace RASTER_FLAVOUR {

int outcode(Vec2 p, const Rect& r) {
    // TODO 1: set kLeft/kRight from p.x and kTop/kBottom from p.y. Remember that y grows
    // downward, so "top" means y < ymin. Points on the border are inside.
    return kInside;
}

bool clip_line(Vec2& a, Vec2& b, const Rect& r) {
    // TODO 2: Cohen-Sutherland. Accept when both outcodes are 0, reject when they share a
    // bit, otherwise move one outside endpoint onto the edge its outcode names and repeat.
    // Check for NaN or infinity first: comparisons with NaN are always false, so a NaN point
    // looks "inside" to outcode(). Put a moved coordinate exactly on its edge, and interpolate
    // the other one from the endpoint nearer the rectangle (1e300 + 0.5 == 1e300 in double).
    return false;
}

namespace {

// Bresenham's algorithm from pixel (x0, y0) to pixel (x1, y1), both inside the image.
[[maybe_unused]] void bresenham(Image& img, int x0, int y0, int x1, int y1, Color c) {
    // TODO 3: step one pixel at a time along the major axis (x if dx >= dy, else y) and keep
    // an integer error term that says when the minor coordinate must step too. Handle all
    // eight octants with the step signs sx, sy instead of eight copies of the loop.
}

}  // namespace

void draw_line(Image& img, Vec2 a, Vec2 b, Color c) {
    // TODO 4: reject NaN and infinite endpoints; snap each endpoint to the center of its
    // pixel; put the two in a fixed order so a->b and b->a draw the same pixels; clip the
    // segment to the rectangle of pixel centers BEFORE converting anything to int (an int
    // cannot hold 1e10, and 2 * dx overflows long before that); then call bresenham().
}

void draw_line_aa(Image& img, Vec2 a, Vec2 b, Color c) {
    // TODO 5: Xiaolin Wu. Swap x and y for steep lines (|dy| > |dx|: at exactly 45 degrees x
    // stays the major axis), order the endpoints by x, and for every column whose center lies
    // between them (and inside the image) split the coverage between the two pixels whose
    // centers straddle the line. A zero-length line has slope 0, not 0 / 0. Compute each
    // column's y from the endpoint whose y is nearer the image, and check rows before
    // converting them to int: far from the image they can be as large as 1e300.
}

}  // namespace RASTER_FLAVOUR
}  // namespace m1
