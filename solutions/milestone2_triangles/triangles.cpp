// BEGIN SOLUTION
// Milestone 2 reference solution. The student's skeleton, milestone2_triangles/triangles.cpp,
// is generated from this file by `make skeletons`.
// SKELETON: // Milestone 2: triangles. Fill in the numbered TODOs; triangles.h says exactly what
// SKELETON: // each function must do, and README.md walks through them in the same order.
// SKELETON: // Run `make check-m2` in your build folder to see which checkpoints pass.
// END SOLUTION
#include "triangles.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>

namespace m2 {
inline namespace RASTER_FLAVOUR {

bool snap(Vec2 p, Fixed& out) {
    // TODO 1: reject non-finite points and points beyond kMaxCoordinate, then round each
    // coordinate times kSubpixelSteps to the nearest integer (std::llround).
    // BEGIN SOLUTION
    if (!raster::is_finite(p) || std::abs(p.x) > kMaxCoordinate || std::abs(p.y) > kMaxCoordinate) {
        return false;
    }
    out = {std::llround(p.x * kSubpixelSteps), std::llround(p.y * kSubpixelSteps)};
    return true;
    // SKELETON: return false;
    // END SOLUTION
}

std::int64_t edge(Fixed a, Fixed b, Fixed p) {
    // TODO 2: cross(b - a, p - a). With |coordinates| <= 2^28 sixteenths, every product fits
    // in 64 bits, so the result is exact: no rounding can put a sample on the wrong side.
    // BEGIN SOLUTION
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    // SKELETON: return 0;
    // END SOLUTION
}

// BEGIN SOLUTION
namespace {

// Division rounding toward minus infinity and plus infinity (C++'s / rounds toward zero,
// which is wrong for negative coordinates).
std::int64_t floor_div(std::int64_t a, std::int64_t b) { return a / b - ((a % b != 0) && ((a < 0) != (b < 0))); }
std::int64_t ceil_div(std::int64_t a, std::int64_t b) { return -floor_div(-a, b); }

// A pixel's center, on the 1/16 grid.
Fixed center(int x, int y) {
    return {std::int64_t(x) * kSubpixelSteps + kSubpixelSteps / 2, std::int64_t(y) * kSubpixelSteps + kSubpixelSteps / 2};
}

}  // namespace

// END SOLUTION
PixelRect bounding_box(Fixed v0, Fixed v1, Fixed v2, int width, int height) {
    // TODO 3: pixel x is a candidate when its center 16x + 8 (in sixteenths) lies between the
    // smallest and largest vertex x. Round with floor/ceil division (careful: negative
    // numbers), then clamp to the image.
    // BEGIN SOLUTION
    const std::int64_t min_x = std::min({v0.x, v1.x, v2.x}), max_x = std::max({v0.x, v1.x, v2.x});
    const std::int64_t min_y = std::min({v0.y, v1.y, v2.y}), max_y = std::max({v0.y, v1.y, v2.y});
    const std::int64_t half = kSubpixelSteps / 2;
    auto clamp = [](std::int64_t v, int hi) { return static_cast<int>(std::clamp<std::int64_t>(v, 0, hi)); };
    return {clamp(ceil_div(min_x - half, kSubpixelSteps), width), clamp(ceil_div(min_y - half, kSubpixelSteps), height),
            clamp(floor_div(max_x - half, kSubpixelSteps) + 1, width),
            clamp(floor_div(max_y - half, kSubpixelSteps) + 1, height)};
    // SKELETON: return {};
    // END SOLUTION
}

namespace {

// A triangle ready for rasterizing: snapped, with positive area.
struct Setup {
    Fixed v[3];
    std::int64_t area2 = 0;     // twice the area, in (1/16 pixel)^2; > 0
    bool top_left[3] = {};      // edge i runs from v[i] to v[(i + 1) % 3]
    // BEGIN SOLUTION
    std::int64_t bias[3] = {};  // 0 on a top or left edge, -1 on the others (see inside())
    // END SOLUTION
    bool swapped = false;       // v[1] and v[2] were exchanged to make the area positive
};

// TODO 4a: snap the three vertices, compute the signed area, reject zero area, swap two
// vertices when it is negative, and mark which edges are top or left edges.
[[maybe_unused]] bool set_up(Vec2 v0, Vec2 v1, Vec2 v2, Setup& t) {
    // BEGIN SOLUTION
    if (!snap(v0, t.v[0]) || !snap(v1, t.v[1]) || !snap(v2, t.v[2])) return false;
    t.area2 = edge(t.v[0], t.v[1], t.v[2]);
    if (t.area2 == 0) return false;  // degenerate: collinear or coincident vertices
    if (t.area2 < 0) {
        std::swap(t.v[1], t.v[2]);
        t.area2 = -t.area2;
        t.swapped = true;
    }
    for (int i = 0; i < 3; ++i) {
        const Fixed a = t.v[i], b = t.v[(i + 1) % 3];
        t.top_left[i] = (b.y == a.y && b.x > a.x) || b.y < a.y;
        t.bias[i] = t.top_left[i] ? 0 : -1;
    }
    return true;
    // SKELETON: return false;
    // END SOLUTION
}

// BEGIN SOLUTION
// The three edge values at one sample (e0 for the edge from v[0] to v[1], and so on), and
// adding a step to all three.
struct Edges {
    std::int64_t e0 = 0, e1 = 0, e2 = 0;
    Edges& operator+=(const Edges& d) {
        e0 += d.e0;
        e1 += d.e1;
        e2 += d.e2;
        return *this;
    }
    Edges times(std::int64_t k) const { return {e0 * k, e1 * k, e2 * k}; }
};

// Covered: all three positive, or zero on a top or left edge (the fill rule). On integers,
// "e > 0" is "e - 1 >= 0", so with bias 0 on a top or left edge and -1 on the others the rule
// is: every e + bias >= 0, i.e. no sign bit in their OR. One test with no branch per edge,
// which matters in the pixel loops.
bool inside(const Setup& t, const Edges& e) {
    return ((e.e0 + t.bias[0]) | (e.e1 + t.bias[1]) | (e.e2 + t.bias[2])) >= 0;
}

// The edge values at point p, and how much they grow per sixteenth to the right and down.
// edge(a, b, p) is linear in p: moving p by dx sixteenths adds -(b.y - a.y) * dx, moving it by
// dy adds (b.x - a.x) * dy. So the pixel loops add constants instead of multiplying, and the
// values stay the exact integers that covers() computes.
struct Stepper {
    Edges start, per_x, per_y;
};

Stepper stepper(const Setup& t, Fixed p) {
    const Fixed* v = t.v;
    return {{edge(v[0], v[1], p), edge(v[1], v[2], p), edge(v[2], v[0], p)},
            {v[0].y - v[1].y, v[1].y - v[2].y, v[2].y - v[0].y},
            {v[1].x - v[0].x, v[2].x - v[1].x, v[0].x - v[2].x}};
}

// END SOLUTION
// TODO 4b: is sample p covered? Fill e[] with the three edge values (e[i] for the edge
// from v[i] to v[i+1], which is 0 on that edge), then apply the top-left rule to zeros.
[[maybe_unused]] bool covers(const Setup& t, Fixed p, std::int64_t e[3]) {
    // BEGIN SOLUTION
    for (int i = 0; i < 3; ++i) {
        e[i] = edge(t.v[i], t.v[(i + 1) % 3], p);
        if (e[i] < 0 || (e[i] == 0 && !t.top_left[i])) return false;
    }
    return true;
    // SKELETON: return false;
    // END SOLUTION
}

}  // namespace

void fill_triangle(Image& img, Vec2 v0, Vec2 v1, Vec2 v2, Color c) {
    // TODO 4c: set up the triangle, then test the center of every pixel in its bounding box.
    // BEGIN SOLUTION
    Setup t;
    if (!set_up(v0, v1, v2, t)) return;
    const PixelRect box = bounding_box(t.v[0], t.v[1], t.v[2], img.width(), img.height());
    // covers(t, center(x, y), e) at every pixel would be correct; stepping the same exact
    // values by constants (one addition per edge and pixel) is what makes it fast.
    const Stepper s = stepper(t, center(box.x0, box.y0));
    const Edges step_x = s.per_x.times(kSubpixelSteps), step_y = s.per_y.times(kSubpixelSteps);
    Edges row = s.start;
    for (int y = box.y0; y < box.y1; ++y) {
        Edges e = row;
        for (int x = box.x0; x < box.x1; ++x) {
            if (inside(t, e)) img.set(x, y, c);
            e += step_x;
        }
        row += step_y;
    }
    // END SOLUTION
}

void fill_triangle_gradient(Image& img, Vec2 v0, Vec2 v1, Vec2 v2, Color c0, Color c1, Color c2) {
    // TODO 5: as fill_triangle; for a covered pixel, the weight of vertex k is the edge value
    // of the edge opposite it divided by area2 (in floating point: integer division gives 0).
    // Remember which vertices set_up swapped. Round each channel to nearest (raster::to_channel).
    // BEGIN SOLUTION
    Setup t;
    if (!set_up(v0, v1, v2, t)) return;
    if (t.swapped) std::swap(c1, c2);
    const Color colors[3] = {c0, c1, c2};
    const PixelRect box = bounding_box(t.v[0], t.v[1], t.v[2], img.width(), img.height());
    std::int64_t e[3];
    for (int y = box.y0; y < box.y1; ++y) {
        for (int x = box.x0; x < box.x1; ++x) {
            if (!covers(t, center(x, y), e)) continue;
            // e[1] is 0 on the edge v1-v2, opposite v0; e[2] is opposite v1; e[0] opposite v2.
            const double w[3] = {double(e[1]) / double(t.area2), double(e[2]) / double(t.area2),
                                 double(e[0]) / double(t.area2)};
            double r = 0, g = 0, b = 0;
            for (int k = 0; k < 3; ++k) {
                r += w[k] * colors[k].r;
                g += w[k] * colors[k].g;
                b += w[k] * colors[k].b;
            }
            img.set(x, y, {raster::to_channel(r), raster::to_channel(g), raster::to_channel(b)});
        }
    }
    // END SOLUTION
}

void fill_triangle_aa(Image& img, Vec2 v0, Vec2 v1, Vec2 v2, Color c, int n) {
    // TODO 6: n * n samples per pixel at (x + (i + 0.5) / n, y + (j + 0.5) / n), which are
    // exact points of the 1/16 grid for n = 1, 2, 4, 8. Count the covered samples (same test,
    // same fill rule) and blend. Loop over every pixel the vertices' box overlaps, not over
    // bounding_box(): that one holds only the pixels whose CENTERS can be inside.
    // BEGIN SOLUTION
    if (n != 1 && n != 2 && n != 4 && n != 8) return;
    Setup t;
    if (!set_up(v0, v1, v2, t)) return;
    // Every pixel that a sample of the triangle can fall in: the pixels the box overlaps.
    const std::int64_t min_x = std::min({t.v[0].x, t.v[1].x, t.v[2].x}), max_x = std::max({t.v[0].x, t.v[1].x, t.v[2].x});
    const std::int64_t min_y = std::min({t.v[0].y, t.v[1].y, t.v[2].y}), max_y = std::max({t.v[0].y, t.v[1].y, t.v[2].y});
    auto clamp = [](std::int64_t v, int hi) { return static_cast<int>(std::clamp<std::int64_t>(v, 0, hi)); };
    const int x0 = clamp(floor_div(min_x, kSubpixelSteps), img.width()), x1 = clamp(ceil_div(max_x, kSubpixelSteps), img.width());
    const int y0 = clamp(floor_div(min_y, kSubpixelSteps), img.height()), y1 = clamp(ceil_div(max_y, kSubpixelSteps), img.height());
    if (x0 >= x1 || y0 >= y1) return;
    const int step = kSubpixelSteps / n;  // sample spacing in sixteenths
    // The edge values at the first sample (i = j = 0) of pixel (x0, y0), stepped by constants
    // from sample to sample and from pixel to pixel, as in fill_triangle.
    const Stepper s = stepper(t, {std::int64_t(x0) * kSubpixelSteps + step / 2, std::int64_t(y0) * kSubpixelSteps + step / 2});
    const Edges sample_x = s.per_x.times(step), sample_y = s.per_y.times(step);
    const Edges pixel_x = s.per_x.times(kSubpixelSteps), pixel_y = s.per_y.times(kSubpixelSteps);
    Edges row = s.start;
    for (int y = y0; y < y1; ++y) {
        Edges pixel = row;
        for (int x = x0; x < x1; ++x) {
            int covered = 0;
            Edges sample_row = pixel;
            for (int j = 0; j < n; ++j) {
                Edges e = sample_row;
                for (int i = 0; i < n; ++i) {
                    covered += inside(t, e);
                    e += sample_x;
                }
                sample_row += sample_y;
            }
            if (covered > 0) img.blend(x, y, c, double(covered) / (n * n));
            pixel += pixel_x;
        }
        row += pixel_y;
    }
    // END SOLUTION
}

}  // namespace RASTER_FLAVOUR
}  // namespace m2
