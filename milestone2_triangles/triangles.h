// Milestone 2: triangles. The functions you implement in triangles.cpp.
//
// Conventions. Each one below is a TESTED rule: a checkpoint draws a scene where breaking it
// changes pixels (or numbers) and fails, naming the convention. What is marked "Advice" is
// how the reference does it and what the lesson recommends; the checkpoints cannot see it,
// so another correct way passes too.
//
//  * Pixel grid: as in milestone 1. Pixel (x, y) covers [x, x+1) x [y, y+1), row 0 at the
//    top, y growing downward; its center is (x + 0.5, y + 0.5). Vertices are real points in
//    that plane, in pixels.
//
//  * Sampling. A pixel is covered when its CENTER is inside the triangle (anti-aliased fills
//    use several sample points per pixel instead, see fill_triangle_aa).
//
//  * Edge functions. For an edge from a to b, edge(a, b, p) = cross(b - a, p - a)
//    = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x). With y growing downward, it is
//    positive when p lies to the right of the edge as you walk from a to b on screen, and its
//    value at the third vertex is twice the triangle's signed area.
//
//  * Winding. Both windings are drawn and give identical pixels (a gradient pixel in the
//    half-level tie window described below may take either accepted level in each). A triangle whose signed area
//    is negative is first made positive by swapping two vertices; from then on p is inside
//    when all three edge functions are >= 0, with the fill rule deciding the zeros.
//
//  * Fill rule: top-left. A sample exactly on an edge is covered only if the edge is a TOP
//    edge (exactly horizontal, with the triangle below it) or a LEFT edge (the triangle to its
//    right). With positive area, edge a->b is top when b.y == a.y and b.x > a.x, and left when
//    b.y < a.y. Two triangles sharing an edge therefore never both cover, nor both miss, a
//    sample on it: a mesh is watertight.
//
//  * Precision. Vertices are snapped to 1/16 of a pixel (kSubpixelSteps) and edge functions
//    are evaluated exactly in 64-bit integers on that grid; see the lesson for why plain float
//    fails far from the origin. Tested: snap() and edge() return exactly the pinned numbers,
//    and triangles with vertices on the 1/16 grid cover exactly the pinned pixels. Where
//    scene vertices are not on the 1/16 grid, the checkpoints treat pixel centers within 1/16
//    pixel of an edge as ambiguous, so the exact snapping rule (nearest, ties away from zero)
//    never decides a pixel on its own. Advice: integers inside the loop (a double fill on
//    unsnapped vertices passes the checkpoints; the lesson says why it is still worse), and
//    any loop order, incremental stepping or helper structure you like.
//
//  * Range and bad input. Triangles with a NaN or infinite coordinate, with |coordinate| >
//    kMaxCoordinate, or with zero area (collinear or coincident vertices) draw nothing
//    (tested). Rejecting zero area before any division is advice: with the top-left rule, such
//    a triangle covers no center anyway, so no checkpoint sees the division by zero. Work is proportional to the pixels inside the image: the bounding
//    box is clamped to the image before any loop starts. Nothing extreme (1e300, subnormals,
//    vertices just past 2^24, n outside 1, 2, 4, 8) reaches undefined behaviour: the project
//    fuzzes the reference with such input under AddressSanitizer and UndefinedBehaviorSanitizer,
//    and `make fuzz-m2 FUZZ_STUDENT=1` in your build folder does the same to your code (clang).
//
//  * Barycentric coordinates. l0 = edge(v1, v2, p) / area2, l1 = edge(v2, v0, p) / area2,
//    l2 = edge(v0, v1, p) / area2, where area2 = edge(v0, v1, v2): each is 1 at its own vertex
//    and 0 on the opposite edge, and they sum to 1. A per-vertex color interpolates as
//    l0 * c0 + l1 * c1 + l2 * c2 per channel, rounded to the nearest level (not truncated).
//    Tested exactly: every gradient checkpoint has its vertices on the 1/16 grid, where the
//    judge knows each pixel's exact value as a ratio of integers; a channel must be that value
//    rounded to nearest, and only where the exact value is within 0.01 of a half level (x.5)
//    is either neighbour accepted, so float weights, stepped weights and exact integer
//    rounding all pass.
//
//  * Anti-aliasing by supersampling. fill_triangle_aa takes n*n samples per pixel on a
//    regular grid, at (x + (i + 0.5) / n, y + (j + 0.5) / n) for i, j in 0..n-1, applies the
//    same coverage test and fill rule to each, and blends the color over the pixel with
//    coverage = covered samples / (n * n). n is 1, 2, 4 or 8 (1, 4, 16 or 64 samples), so
//    every sample is a point of the 1/16 grid; n = 1 is the plain fill. Samples exactly on an
//    edge follow the top-left rule (tested with edges through samples). Every pixel with a
//    covered sample must be written, including pixels whose CENTER is outside the triangle's
//    box: bounding_box() is the wrong box here (the lesson, section 8, shows why).
#pragma once

#include <cstdint>

#include "raster/flavour.h"
#include "raster/image.h"
#include "raster/vec.h"

namespace m2 {
inline namespace RASTER_FLAVOUR {

using raster::Color;
using raster::Image;
using raster::Vec2;

inline constexpr int kSubpixelSteps = 16;           // snapping grid: 1/16 pixel
inline constexpr double kMaxCoordinate = 1 << 24;  // about 16.7 million pixels

// A vertex snapped to the 1/16-pixel grid: x = X / 16 pixels.
struct Fixed {
    std::int64_t x = 0, y = 0;
};

// TODO 1: snap p to the nearest point of the 1/16 grid, halves rounding away from zero (as
// std::llround does). Returns false (leaving `out` alone)
// when p is not finite or lies beyond +/-kMaxCoordinate.
bool snap(Vec2 p, Fixed& out);

// TODO 2: the edge function on the fixed grid, exactly, in units of (1/16 pixel)^2.
std::int64_t edge(Fixed a, Fixed b, Fixed p);

// Pixels [x0, x1) x [y0, y1); empty when x0 >= x1 or y0 >= y1.
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// TODO 3: the pixels whose centers can be inside the triangle, clamped to the image: exactly
// the pixels whose center lies within the vertices' range on both axes (borders included),
// intersected with the image. Tested number for number: not a superset (such as every pixel
// the range overlaps) and not a subset. An empty result may be any rectangle with
// x0 >= x1 or y0 >= y1. Must not overflow for coordinates up to kMaxCoordinate.
PixelRect bounding_box(Fixed v0, Fixed v1, Fixed v2, int width, int height);

// TODO 4: fills the triangle in one color: snap, orient, bounding box, then test every pixel
// center with the three edge functions and the top-left rule.
void fill_triangle(Image& img, Vec2 v0, Vec2 v1, Vec2 v2, Color c);

// TODO 5: like fill_triangle, but each covered pixel gets the barycentric interpolation of
// the three vertex colors.
void fill_triangle_gradient(Image& img, Vec2 v0, Vec2 v1, Vec2 v2, Color c0, Color c1, Color c2);

// TODO 6: supersampling anti-aliasing with n * n samples per pixel (n = 1, 2, 4 or 8; other
// values draw nothing). Visit every pixel the triangle's box overlaps, not only the pixels of
// bounding_box(): a sample off the center can be inside where the center is not.
void fill_triangle_aa(Image& img, Vec2 v0, Vec2 v1, Vec2 v2, Color c, int n);

}  // namespace RASTER_FLAVOUR
}  // namespace m2
