// Milestone 1: lines. The functions you implement in lines.cpp.
//
// Conventions. Every rule below is tested by the checkpoints; what is only advice (a way to
// get there that the checkpoints cannot observe) is marked "Advice".
//
//  * Pixel grid. Pixel (x, y) is column x, row y; row 0 is the top row and y grows downward.
//    The pixel covers the square [x, x+1) x [y, y+1), so its center is (x + 0.5, y + 0.5).
//
//  * Endpoints. A line's endpoints are real points. Each endpoint selects the pixel that
//    contains it: (floor(p.x), floor(p.y)). The drawn line joins the CENTERS of those two
//    pixels. So (10.5, 20.5), (10.0, 20.0) and (10.99, 20.99) all mean pixel (10, 20).
//
//  * Aliased lines (draw_line). Both endpoint pixels are drawn. Along the major axis (x when
//    |dx| >= |dy|, else y) exactly one pixel is drawn per step: the one whose center is
//    nearest to the ideal line in the minor axis. When the ideal line passes exactly halfway
//    between two pixels (a tie), either may be chosen, but drawing from a to b must give the
//    same pixels as drawing from b to a. A zero-length line draws its single pixel.
//
//  * Clipping. Lines may start and end anywhere, up to about +/-1e300. Only pixels inside the
//    image are ever written (Image::stray_writes() stays 0), and the work done is proportional
//    to the number of visible pixels, never to the line's full length. Where a line is
//    clipped, snapping the clipped endpoints may shift it: its pixels must stay within
//    1 + |slope| / 2 pixels of the ideal line (measured along the minor axis), with no gaps.
//    Precision: that band is promised when at least one endpoint lies within 1e12 of the image
//    along the minor axis (y for a shallow line, x for a steep one), as in (1e300, 40.5) to
//    (-1e300, 44.5) or (-1e300, -1e300) to (62.5, 16.5). A parameter t measured from 1e300
//    away cannot resolve a pixel (1e300 + 0.5 == 1e300 in double). Advice (the way to meet
//    the rule): put each clipped coordinate exactly on its edge (x = xmin, never
//    a.x + t (b.x - a.x)) and interpolate the other one from the endpoint nearer the image;
//    in draw_line_aa, compute each column's y from the endpoint whose y is nearer the image.
//    When both endpoints are farther than that, as in (-1e300, -1e300) to (1e300, 1e300), no
//    double arithmetic can place the line to the pixel: only safety is tested (no crash, no
//    hang, no write outside the image, bounded work), not which pixels it lights.
//
//  * Bad input. An endpoint that is NaN or infinite draws nothing (no crash, no hang).
//    Nothing else extreme (1e300, DBL_MAX, subnormals, any rectangle given to clip_line)
//    reaches undefined behaviour (such as a double converted to an int it does not fit) or
//    writes outside the image. The project fuzzes the reference with
//    such input under AddressSanitizer and UndefinedBehaviorSanitizer; `make fuzz-m1
//    FUZZ_STUDENT=1` in your build folder does the same to your code (it needs clang).
//
//  * Anti-aliased lines (draw_line_aa), Xiaolin Wu's algorithm without endpoint weighting.
//    Endpoints are used as given (no snapping). Let the major axis be x (swap the roles of x
//    and y for steep lines). The line covers every column whose center x + 0.5 lies in
//    [min(a.x, b.x), max(a.x, b.x)]. In such a column, let yc be the ideal line's y at
//    x + 0.5, and t = yc - 0.5. The two pixels whose centers straddle yc, rows floor(t) and
//    floor(t) + 1, receive coverage 1 - f and f, where f = t - floor(t). Coverage is applied
//    with Image::blend, so the nearer pixel is the brighter one. Only pixels inside the image
//    are blended: where the line leaves the image through the top or bottom (left or right,
//    for steep lines), test each row before converting it to int and writing.
//    The major axis is x when |dx| >= |dy|, as for draw_line: an exact 45-degree line steps
//    along x, and a zero-length line (a == b) is an x-major line of slope 0 (not 0 / 0). So a
//    zero-length line covers the column whose center is exactly a.x, if there is one: at
//    (20.5, 24.75) pixels (20, 24) and (20, 25) get 0.75 and 0.25, at a pixel center it lights
//    that pixel, and anywhere else it draws nothing.
//    Tested: every pixel of the interior columns, within 3 of 255 levels. The first and last
//    column, and one beyond each, are judged leniently (only "near the line"), so Wu's
//    textbook endpoint weighting (each end column dimmed by its endpoint's gap,
//    1 - frac(x + 0.5)) is accepted too. A weighting that gives an end column no light at all
//    is not: a zero-length line on a column center must still light the nearer of its two
//    pixels (how brightly is judged leniently, as for every end column); the textbook's gap
//    is 1 there. At exactly 45 degrees, stepping along y gives the
//    same interior pixels as stepping along x, so there only the end columns differ, and they
//    are lenient. No write outside the image, ever (Image::stray_writes() stays 0).
//
//  * Cohen-Sutherland outcodes. Bit LEFT: x < xmin; RIGHT: x > xmax; TOP: y < ymin (top of
//    the screen, since y grows downward); BOTTOM: y > ymax. The rectangle is closed: points on
//    its border are inside.
#pragma once

#include "raster/flavour.h"
#include "raster/image.h"
#include "raster/vec.h"

namespace m1 {
inline namespace RASTER_FLAVOUR {

using raster::Color;
using raster::Image;
using raster::Vec2;

// An axis-aligned clipping rectangle, border included: xmin <= x <= xmax, ymin <= y <= ymax.
struct Rect {
    double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
};

enum Outcode : int {
    kInside = 0,
    kLeft = 1,
    kRight = 2,
    kTop = 4,
    kBottom = 8,
};

// TODO 1: the Cohen-Sutherland region code of p with respect to r (an OR of Outcode bits).
int outcode(Vec2 p, const Rect& r);

// TODO 2: clips the segment a-b to r in place. Returns false, leaving a and b unspecified,
// when no part of the segment lies in r; otherwise true, with a and b moved along the segment
// onto r's border where they were outside (each moved coordinate exactly on its edge; see
// "Precision" above). Non-finite input returns false.
bool clip_line(Vec2& a, Vec2& b, const Rect& r);

// TODO 3 and 4: Bresenham's line from the pixel containing a to the pixel containing b,
// in all eight octants. Clipped to the image. Advice, not tested: keep the loop in integer
// arithmetic (Bresenham's error term); it is exact and never drifts. The checkpoints judge
// only the pixels, so a floating-point DDA that picks the same pixels passes.
void draw_line(Image& img, Vec2 a, Vec2 b, Color c);

// TODO 5: Xiaolin Wu's anti-aliased line, as pinned above. Clipped to the image.
void draw_line_aa(Image& img, Vec2 a, Vec2 b, Color c);

}  // namespace RASTER_FLAVOUR
}  // namespace m1
