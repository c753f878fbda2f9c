// BEGIN SOLUTION
// Milestone 1 reference solution. The student's skeleton, milestone1_lines/lines.cpp, is
// generated from this file by `make skeletons`: each region between BEGIN SOLUTION and
// END SOLUTION is replaced by its SKELETON lines.
// SKELETON: // Milestone 1: lines. Fill in the numbered TODOs; lines.h says exactly what each
// SKELETON: // function must do, and README.md walks through them in the same order.
// SKELETON: // Run `make check-m1` in your build folder to see which checkpoints pass.
// END SOLUTION
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
    // BEGIN SOLUTION
    int code = kInside;
    if (p.x < r.xmin) {
        code |= kLeft;
    } else if (p.x > r.xmax) {
        code |= kRight;
    }
    if (p.y < r.ymin) {
        code |= kTop;
    } else if (p.y > r.ymax) {
        code |= kBottom;
    }
    return code;
    // SKELETON: return kInside;
    // END SOLUTION
}

bool clip_line(Vec2& a, Vec2& b, const Rect& r) {
    // TODO 2: Cohen-Sutherland. Accept when both outcodes are 0, reject when they share a
    // bit, otherwise move one outside endpoint onto the edge its outcode names and repeat.
    // Check for NaN or infinity first: comparisons with NaN are always false, so a NaN point
    // looks "inside" to outcode(). Put a moved coordinate exactly on its edge, and interpolate
    // the other one from the endpoint nearer the rectangle (1e300 + 0.5 == 1e300 in double).
    // BEGIN SOLUTION
    if (!raster::is_finite(a) || !raster::is_finite(b)) return false;
    int code_a = outcode(a, r);
    int code_b = outcode(b, r);
    // Each pass puts one endpoint exactly on an edge line, so two passes per endpoint are
    // enough; the bound only guards against rounding making a corner case bounce.
    for (int pass = 0; pass < 8; ++pass) {
        if ((code_a | code_b) == 0) return true;  // both inside
        if ((code_a & code_b) != 0) return false;  // both beyond the same edge
        const int out = code_a != 0 ? code_a : code_b;
        // The point p where the segment meets the edge. Its coordinate across the edge is
        // the edge itself, exactly. The other coordinate is interpolated from the endpoint n
        // that is nearer the rectangle in that coordinate, with t the fraction of the way
        // from n to the far endpoint f: measured from a point 1e300 away, t could not resolve
        // a pixel (1e300 + 0.5 == 1e300 in double). Computing t first keeps every
        // intermediate value near the input's size, so nothing overflows up to about 1e300.
        auto outside_by = [](double v, double lo, double hi) { return v < lo ? lo - v : v > hi ? v - hi : 0.0; };
        Vec2 p;
        if (out & (kTop | kBottom)) {
            const double y = (out & kTop) ? r.ymin : r.ymax;
            const bool from_a = outside_by(a.x, r.xmin, r.xmax) <= outside_by(b.x, r.xmin, r.xmax);
            const Vec2 n = from_a ? a : b, f = from_a ? b : a;
            const double t = (y - n.y) / (f.y - n.y);
            p = {n.x + t * (f.x - n.x), y};
        } else {
            const double x = (out & kLeft) ? r.xmin : r.xmax;
            const bool from_a = outside_by(a.y, r.ymin, r.ymax) <= outside_by(b.y, r.ymin, r.ymax);
            const Vec2 n = from_a ? a : b, f = from_a ? b : a;
            const double t = (x - n.x) / (f.x - n.x);
            p = {x, n.y + t * (f.y - n.y)};
        }
        if (!raster::is_finite(p)) return false;  // the difference b - a overflowed
        if (out == code_a) {
            a = p;
            code_a = outcode(a, r);
        } else {
            b = p;
            code_b = outcode(b, r);
        }
    }
    return (code_a | code_b) == 0;
    // SKELETON: return false;
    // END SOLUTION
}

namespace {

// BEGIN SOLUTION
// Center of the pixel that contains p.
Vec2 pixel_center(Vec2 p) { return {std::floor(p.x) + 0.5, std::floor(p.y) + 0.5}; }

// END SOLUTION
// Bresenham's algorithm from pixel (x0, y0) to pixel (x1, y1), both inside the image.
[[maybe_unused]] void bresenham(Image& img, int x0, int y0, int x1, int y1, Color c) {
    // TODO 3: step one pixel at a time along the major axis (x if dx >= dy, else y) and keep
    // an integer error term that says when the minor coordinate must step too. Handle all
    // eight octants with the step signs sx, sy instead of eight copies of the loop.
    // BEGIN SOLUTION
    const int dx = std::abs(x1 - x0);
    const int dy = std::abs(y1 - y0);
    const int sx = x0 <= x1 ? 1 : -1;
    const int sy = y0 <= y1 ? 1 : -1;
    if (dx >= dy) {
        // err is 2*dx times (distance from the line to the midpoint between the two candidate
        // rows); err > 0 means the line passes beyond the midpoint, so the minor axis steps.
        int err = 2 * dy - dx;
        for (int x = x0, y = y0;; x += sx) {
            img.set(x, y, c);
            if (x == x1) break;
            if (err > 0) {
                y += sy;
                err -= 2 * dx;
            }
            err += 2 * dy;
        }
    } else {
        int err = 2 * dx - dy;
        for (int y = y0, x = x0;; y += sy) {
            img.set(x, y, c);
            if (y == y1) break;
            if (err > 0) {
                x += sx;
                err -= 2 * dy;
            }
            err += 2 * dx;
        }
    }
    // END SOLUTION
}

}  // namespace

void draw_line(Image& img, Vec2 a, Vec2 b, Color c) {
    // TODO 4: reject NaN and infinite endpoints; snap each endpoint to the center of its
    // pixel; put the two in a fixed order so a->b and b->a draw the same pixels; clip the
    // segment to the rectangle of pixel centers BEFORE converting anything to int (an int
    // cannot hold 1e10, and 2 * dx overflows long before that); then call bresenham().
    // BEGIN SOLUTION
    if (!raster::is_finite(a) || !raster::is_finite(b)) return;
    Vec2 pa = pixel_center(a);
    Vec2 pb = pixel_center(b);
    if (pb.x < pa.x || (pb.x == pa.x && pb.y < pa.y)) std::swap(pa, pb);
    const Rect centers{0.5, 0.5, img.width() - 0.5, img.height() - 0.5};
    if (!clip_line(pa, pb, centers)) return;
    // Both points now lie inside the image, so these conversions are exact and safe.
    bresenham(img, static_cast<int>(std::floor(pa.x)), static_cast<int>(std::floor(pa.y)),
              static_cast<int>(std::floor(pb.x)), static_cast<int>(std::floor(pb.y)), c);
    // END SOLUTION
}

void draw_line_aa(Image& img, Vec2 a, Vec2 b, Color c) {
    // TODO 5: Xiaolin Wu. Swap x and y for steep lines (|dy| > |dx|: at exactly 45 degrees x
    // stays the major axis), order the endpoints by x, and for every column whose center lies
    // between them (and inside the image) split the coverage between the two pixels whose
    // centers straddle the line. A zero-length line has slope 0, not 0 / 0. Compute each
    // column's y from the endpoint whose y is nearer the image, and check rows before
    // converting them to int: far from the image they can be as large as 1e300.
    // BEGIN SOLUTION
    if (!raster::is_finite(a) || !raster::is_finite(b)) return;
    const bool steep = std::abs(b.y - a.y) > std::abs(b.x - a.x);
    if (steep) {
        std::swap(a.x, a.y);
        std::swap(b.x, b.y);
    }
    if (a.x > b.x) std::swap(a, b);
    const int columns = steep ? img.height() : img.width();
    const int rows = steep ? img.width() : img.height();
    const double gradient = b.x > a.x ? (b.y - a.y) / (b.x - a.x) : 0.0;
    if (!std::isfinite(gradient)) return;  // b - a overflowed

    // Columns whose centers lie in [a.x, b.x], limited to the image: work is bounded by the
    // image size however long the line is.
    const double first = std::max(std::ceil(a.x - 0.5), 0.0);
    const double last = std::min(std::floor(b.x - 0.5), columns - 1.0);
    if (first > last) return;

    auto plot = [&](int column, int row, double coverage) {
        if (row < 0 || row >= rows) return;
        if (steep) {
            img.blend(row, column, c, coverage);
        } else {
            img.blend(column, row, c, coverage);
        }
    };
    // Each column's y is computed from the endpoint whose y is nearer the image, so that a
    // line from 1e300 far away still lands on the right rows near the other endpoint.
    auto outside_by = [](double v, double hi) { return v < 0 ? -v : v > hi ? v - hi : 0.0; };
    const Vec2 n = outside_by(a.y, rows) <= outside_by(b.y, rows) ? a : b;
    for (int x = static_cast<int>(first); x <= static_cast<int>(last); ++x) {
        const double t = n.y + gradient * (x + 0.5 - n.x) - 0.5;
        if (!(t > -1.0 && t < rows)) continue;  // both candidate rows are off the image
        // floor(t) without a library call: t is in (-1, rows), so the int conversion (which
        // truncates toward zero) is safe and only needs correcting below zero.
        int row = static_cast<int>(t);
        if (row > t) --row;
        const double f = t - row;
        plot(x, row, 1.0 - f);
        plot(x, row + 1, f);
    }
    // END SOLUTION
}

}  // namespace RASTER_FLAVOUR
}  // namespace m1
