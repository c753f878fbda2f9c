#include "m1/scenes.h"

#include "harness/checkpoint.h"
#include "variant_random.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <set>
#include <utility>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace m1cp {

namespace {

using namespace raster::colors;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// The center of pixel (i, j): scenes use it so that endpoints are unambiguous.
constexpr Vec2 px(double i, double j) { return {i + 0.5, j + 0.5}; }

Segment line(Vec2 a, Vec2 b, Color c = white) { return {a, b, c, false}; }
Segment aa_line(Vec2 a, Vec2 b, Color c = white) { return {a, b, c, true}; }

// The eight octants, numbered as in the lesson (y grows downward):
//   1 shallow right-down   2 steep down-right   3 steep down-left   4 shallow left-down
//   5 shallow left-up      6 steep up-left      7 steep up-right    8 shallow right-up
// Each octant scene is the octant-1 scene mapped by the symmetry of the 48x48 square that
// carries octant 1 onto that octant, so all eight test the same slopes.
struct Ij {
    int i, j;
};
// Octant-1 lines with slopes 1/4 (every other step a tie), 17/28, 1/4 from an odd start,
// 11/12 (nearly diagonal) and 5/43 (long and flat), placed so no two share a pixel and
// each can be checked on its own.
constexpr Ij kOctantBase[5][2] = {{{4, 1}, {40, 10}}, {{18, 13}, {46, 30}}, {{9, 33}, {29, 38}},
                                  {{2, 12}, {14, 23}}, {{2, 41}, {45, 46}}};

Scene octant_scene(int octant, const Ij (&base)[5][2] = kOctantBase) {
    constexpr int n = 47;  // last pixel index of a 48x48 image
    auto map = [octant](Ij p) -> Ij {
        switch (octant) {
            case 1: return p;
            case 2: return {p.j, p.i};
            case 3: return {n - p.j, p.i};
            case 4: return {n - p.i, p.j};
            case 5: return {n - p.i, n - p.j};
            case 6: return {n - p.j, n - p.i};
            case 7: return {p.j, n - p.i};
            default: return {p.i, n - p.j};
        }
    };
    const Color palette[] = {white, yellow, cyan, magenta, green};
    const char* words[] = {"",
                           "shallow, going right and down",
                           "steep, going down and right",
                           "steep, going down and left",
                           "shallow, going left and down",
                           "shallow, going left and up",
                           "steep, going up and left",
                           "steep, going up and right",
                           "shallow, going right and up"};
    Scene s;
    s.id = "m1.octant_" + std::to_string(octant);
    s.title = std::string("octant ") + std::to_string(octant) + ": " + words[octant];
    s.hint = "Lines in this octant are wrong. Check the step signs (sx, sy) and which axis is "
             "the major one (|dx| >= |dy|): one loop with signed steps covers all eight octants.";
    s.width = s.height = 48;
    s.disjoint = true;
    for (int k = 0; k < 5; ++k) {
        const Ij a = map(base[k][0]), b = map(base[k][1]);
        s.lines.push_back(line(px(a.i, a.j), px(b.i, b.j), palette[k]));
    }
    return s;
}

std::vector<Scene> make_scenes() {
    std::vector<Scene> all;  // in the order of the lesson's TODOs
    {
        Scene s;
        s.id = "m1.outcodes";
        s.title = "Cohen-Sutherland outcodes of every pixel center";
        s.hint = "TOP is y < ymin (the top of the screen, since y grows downward); the border "
                 "itself is inside; a point can be both LEFT and TOP.";
        s.width = s.height = 48;
        s.kind = Kind::kOutcodes;
        s.viewport = {12.5, 16.5, 35.5, 31.5};  // borders through pixel centers
        all.push_back(s);
    }

    for (int octant = 1; octant <= 8; ++octant) all.push_back(octant_scene(octant));

    {
        Scene s;
        s.id = "m1.axis_aligned";
        s.title = "horizontal and vertical lines, both directions";
        s.hint = "When dy = 0 or dx = 0 the error term must never make the minor axis step.";
        s.width = s.height = 48;
        s.disjoint = true;
        s.lines = {line(px(4, 4), px(43, 4)), line(px(43, 8), px(4, 8), yellow),
                   line(px(6, 14), px(6, 43), cyan), line(px(12, 43), px(12, 14), magenta),
                   line(px(20, 20), px(21, 20), green), line(px(30, 30), px(30, 31), red)};
        all.push_back(s);
    }
    {
        Scene s;
        s.id = "m1.diagonals";
        s.title = "45-degree lines in the four diagonal directions";
        s.hint = "At |dx| = |dy| both axes step every time; check the comparison that picks "
                 "the major axis and the error update.";
        s.width = s.height = 48;
        s.disjoint = true;
        s.lines = {line(px(3, 3), px(20, 20)), line(px(44, 3), px(27, 20), yellow),
                   line(px(3, 44), px(20, 27), cyan), line(px(44, 44), px(27, 27), magenta)};
        all.push_back(s);
    }
    {
        Scene s;
        s.id = "m1.endpoints";
        s.title = "endpoints are inclusive, and a real endpoint means the pixel containing it";
        s.hint = "Both endpoint pixels belong to the line: loop while the major coordinate has "
                 "not passed the last pixel (<=, not <). Endpoints snap with floor(), not round().";
        s.width = s.height = 40;
        s.disjoint = true;
        // Two- and three-pixel lines in every direction.
        const int d[][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
        for (int k = 0; k < 8; ++k) {
            const int cx = 4 + 4 * k;
            s.lines.push_back(line(px(cx, 4), px(cx + d[k][0], 4 + d[k][1])));
            s.lines.push_back(line(px(cx, 12), px(cx + 2 * d[k][0], 12 + 2 * d[k][1]), yellow));
        }
        // Endpoints that are not pixel centers: each still selects the pixel containing it.
        s.lines.push_back(line({3.0, 20.0}, {20.99, 24.99}, cyan));       // (3,20)-(20,24)
        s.lines.push_back(line({36.999, 20.2}, {24.01, 22.7}, magenta));  // (36,20)-(24,22)
        s.lines.push_back(line({5.6, 30.4}, {30.3, 35.8}, green));        // (5,30)-(30,35)
        all.push_back(s);
    }
    {
        Scene s;
        s.id = "m1.symmetry";
        s.title = "a->b draws the same pixels as b->a, ties included";
        s.hint = "Where the ideal line passes exactly between two pixels the choice is yours, "
                 "but it must not depend on the drawing direction: put the endpoints in a "
                 "fixed order before drawing.";
        s.width = s.height = 48;
        s.disjoint = true;
        s.check_reversed = true;
        // dx = 2 * dy with dy odd: every other step is an exact tie.
        s.lines = {line(px(2, 2), px(16, 9)),           line(px(44, 4), px(30, 11), yellow),
                   line(px(4, 16), px(11, 30), cyan),   line(px(40, 16), px(33, 30), magenta),
                   line(px(2, 36), px(28, 45), green),  line(px(44, 44), px(30, 35), red)};
        all.push_back(s);
    }
    {
        Scene s;
        s.id = "m1.star";
        s.title = "eight-octant star (demo)";
        s.hint = "Each ray of the star is one octant or axis; the failing pixels show which.";
        s.width = s.height = 128;
        s.demo = true;
        const Color palette[] = {white, yellow, cyan, magenta, green, red, blue, gray};
        for (int k = 0; k < 16; ++k) {
            const double angle = k * std::numbers::pi / 8 + 0.2;
            const Vec2 tip{64 + 58 * std::cos(angle), 64 + 58 * std::sin(angle)};
            s.lines.push_back(line({64.5, 64.5}, tip, palette[k % 8]));
        }
        all.push_back(s);
    }
    {
        Scene s;
        s.id = "m1.clock";
        s.title = "clock face: radial lines every 15 degrees (demo)";
        s.hint = "Radial lines cover every octant; snap each real endpoint with floor().";
        s.width = s.height = 128;
        s.demo = true;
        for (int k = 0; k < 24; ++k) {
            const double angle = k * std::numbers::pi / 12;
            const double r0 = k % 2 == 0 ? 30 : 44;  // hour marks are longer
            const Vec2 dir{std::cos(angle), std::sin(angle)};
            s.lines.push_back(line({64 + r0 * dir.x, 64 + r0 * dir.y},
                                   {64 + 60 * dir.x, 64 + 60 * dir.y}, k % 2 == 0 ? white : gray));
        }
        s.lines.push_back(line({64, 64}, {64 + 24 * std::cos(-1.2), 64 + 24 * std::sin(-1.2)}, yellow));
        s.lines.push_back(line({64, 64}, {64 + 40 * std::cos(0.65), 64 + 40 * std::sin(0.65)}, cyan));
        all.push_back(s);
    }
    // Clipping against a viewport smaller than the image. The viewport's sides are not on
    // pixel centers, so an off-by-one in the clip shows up as a wrong coordinate.
    const Box vp{10.25, 12.75, 53.5, 50.0};
    auto clip_scene = [&](std::string id, std::string title, std::string hint,
                          std::vector<Segment> lines) {
        Scene s;
        s.id = std::move(id);
        s.title = std::move(title);
        s.hint = std::move(hint);
        s.kind = Kind::kClip;
        s.viewport = vp;
        s.lines = std::move(lines);
        all.push_back(s);
    };
    clip_scene("m1.clip_inside", "segments inside the viewport are kept unchanged",
               "If both outcodes are 0, accept at once and leave the points alone.",
               {line({15, 20}, {50, 45}, yellow), line({48.7, 14.1}, {12.2, 40.9}, cyan),
                line({10.25, 30}, {53.5, 30}, green),    // on the left and right borders
                line({30, 12.75}, {30, 50}, magenta)});  // on the top and bottom borders
    clip_scene("m1.clip_outside", "segments outside the viewport are rejected",
               "Reject when the outcodes share a bit. A segment can also miss the viewport "
               "with no shared bit (it cuts a corner region): clip and test again.",
               {line({1, 5}, {8, 60}), line({2, 4}, {60, 9}), line({56, 2}, {62, 63}),
                line({3, 55}, {63, 60}),
                // From the LEFT region to the TOP region, missing the corner (10.25, 12.75):
                // no shared bit, and only a second pass on the moved endpoint shows it misses.
                line({2, 14}, {11, 3}), line({60, 16}, {50, 4}),  // and one past the top-right corner
                line({20, 25}, {40, 35}, yellow)});      // inside, so doing nothing fails
    clip_scene("m1.clip_one_edge", "one endpoint inside, one beyond one edge",
               "Move the outside endpoint onto the edge its outcode names: for the left edge "
               "x = xmin and y = a.y + t * (b.y - a.y) with t = (xmin - a.x) / (b.x - a.x).",
               {line({30, 30}, {2, 20}, yellow), line({30, 30}, {62, 37}, cyan),
                line({30, 30}, {24, 3}, magenta), line({30, 30}, {40, 62}, green)});
    clip_scene("m1.clip_two_edges", "both endpoints outside, the segment crosses the viewport",
               "Both endpoints need moving; after moving one, recompute its outcode and loop.",
               {line({2, 20}, {62, 40}, yellow), line({25, 2}, {45, 62}, cyan),
                line({1, 3}, {63, 61}, magenta), line({3, 44}, {36, 63}, green),
                line({60, 3}, {55, 62}, red)});
    {
        Scene s;
        s.id = "m1.viewport";
        s.title = "lines clipped against a viewport (demo)";
        s.hint = "Gray is each whole line, color is what clip_line kept: color must stay inside "
                 "the blue viewport and cover the gray everywhere inside it.";
        s.width = s.height = 96;
        s.kind = Kind::kClip;
        s.viewport = {20.5, 24.5, 75.5, 71.5};
        s.demo = true;
        const Color palette[] = {white, yellow, cyan, magenta, green, red};
        for (int k = 0; k < 12; ++k) {
            const double a0 = k * 0.53, a1 = a0 + 2.2 + 0.15 * k;
            s.lines.push_back(line({48 + 46 * std::cos(a0), 48 + 46 * std::sin(a0)},
                                   {48 + 46 * std::cos(a1), 48 + 46 * std::sin(a1)},
                                   palette[k % 6]));
        }
        all.push_back(s);
    }
    {
        Scene s;
        s.id = "m1.aa_shallow";
        s.title = "Wu anti-aliased shallow lines";
        s.hint = "In each column the pixel whose center is nearer the line gets the larger "
                 "coverage (1 - f), the other gets f; the two add up to full intensity.";
        s.disjoint = true;
        s.lines = {aa_line({2.5, 4.2}, {61.5, 12.9}), aa_line({60.2, 21.3}, {3.1, 20.6}),
                   aa_line({2.0, 30.0}, {61.0, 52.0})};
        all.push_back(s);
    }
    {
        Scene s;
        s.id = "m1.aa_steep";
        s.title = "Wu anti-aliased steep lines";
        s.hint = "For steep lines swap the roles of x and y: step along y and split coverage "
                 "between two horizontally adjacent pixels.";
        s.disjoint = true;
        // The last one goes right while it goes up: x and y disagree, so ordering a steep
        // line's endpoints by x (not y) runs its y loop backwards.
        s.lines = {aa_line({4.2, 2.5}, {12.9, 61.5}), aa_line({21.3, 60.2}, {20.6, 3.1}),
                   aa_line({30.0, 2.0}, {52.0, 61.0}), aa_line({57.5, 61.0}, {61.2, 3.4})};
        all.push_back(s);
    }

    {
        Scene s;
        s.id = "m1.aa_diagonal";
        s.title = "Wu anti-aliased lines at exactly 45 degrees";
        s.hint = "At |dx| == |dy| the line is neither steeper nor shallower: lines.h makes x the "
                 "major axis whenever |dx| >= |dy|, so test steepness with > on one side and "
                 "let the other branch take the tie.";
        s.width = s.height = 48;
        s.disjoint = true;
        // Endpoints a quarter pixel off the centers (exact in binary, so |dx| == |dy| exactly):
        // every column splits its coverage 3:1 between two pixels.
        s.lines = {aa_line({2.5, 4.25}, {20.5, 22.25}), aa_line({45.5, 3.75}, {27.5, 21.75}, yellow),
                   aa_line({3.5, 44.25}, {21.5, 26.25}, cyan), aa_line({44.5, 43.75}, {26.5, 25.75}, magenta)};
        all.push_back(s);
    }
    {
        Scene s;
        s.id = "m1.aa_leaving";
        s.title = "Wu anti-aliased lines that leave the image through every side";
        s.hint = "Where a line leaves the image, one or both of a column's two pixels are outside "
                 "it: test the row (0 <= row < height; for steep lines the x) before each blend, "
                 "and convert it to int only after that test.";
        // Wider than tall: a steep line's rows end at the height and its columns at the width,
        // so limits taken from the wrong side of the image show (a square image hides them).
        s.width = 80;
        s.height = 56;
        s.lines = {aa_line({30.3, 12.6}, {75.5, -9.4}),             // out through the top
                   aa_line({-10.5, 40.3}, {40.5, 63.9}, yellow),    // out through the bottom
                   aa_line({12.3, 20.5}, {-9.4, 75.5}, cyan),       // steep, out through the left
                   aa_line({65.7, -8.5}, {88.2, 40.5}, magenta),    // steep, out through the top and right
                   aa_line({66.4, 20.3}, {74.9, 70.5}, white),      // steep, beyond x = 56, out through the bottom
                   aa_line({8.5, 40.2}, {40.5, 28.7}, green)};      // inside, so doing nothing fails
        all.push_back(s);
    }

    // ---- extreme inputs: each is paired with ordinary lines, so doing nothing fails ----
    {
        Scene s;
        s.id = "m1.extreme_huge";
        s.title = "endpoints at +/-1e9 and +/-1e300";
        s.hint = "Clip in double before converting anything to int: 1e9 fits an int but "
                 "2 * dx does not, and 1e300 fits nothing. Loop over visible pixels only. Put "
                 "a clipped coordinate exactly on the edge, and interpolate the other from the "
                 "endpoint nearer the image.";
        s.lines = {line({-1e9, 20.5}, {1e9, 20.5}), line({-1e9, -1e9}, {1e9, 1e9}, yellow),
                   line({1e300, 40.5}, {-1e300, 44.5}, cyan),
                   line({-1e9, -5}, {1e9, -5}, red),  // entirely above the image
                   aa_line({-1e9, 52.25}, {1e9, 52.25}, magenta),
                   aa_line({-1e300, 58.7}, {1e300, 58.7}, green),
                   line(px(30, 2), px(60, 12), white),
                   // One endpoint 1e300 away in both coordinates, the other inside: the line
                   // y = x - 46 (slope 1 in double) enters the image at (46.5, 0.5).
                   line({-1e300, -1e300}, {62.5, 16.5}, gray),
                   aa_line({-1e300, 5e299}, {40.25, 30.5}, blue)};  // y = 30.5 - (x - 40.25) / 2
        all.push_back(s);
    }
    {
        Scene s;
        s.id = "m1.extreme_far";
        s.title = "far lines (both endpoints far away in both coordinates) are judged for safety only; the two short lines beside them, to the pixel";
        s.hint = "Such a line must not crash, hang or write outside the image: check that the "
                 "numbers you compute are finite (1.5e308 - -1.5e308 overflows to infinity, and "
                 "0 * infinity is NaN) and clip before converting to int. Where it is drawn is "
                 "not judged: a double cannot place it to the pixel.";
        s.lines = {line({-1e300, -1e300}, {1e300, 1e300}),                // y = x
                   line({1e300, 5e299}, {-1e300, -5e299}, yellow),       // y = x / 2
                   line({-5e299, -1e300}, {5e299, 1e300}, cyan),         // y = 2 x
                   line({-1.5e308, -1.5e308}, {1.5e308, 1.5e308}, magenta),  // b - a overflows
                   aa_line({-1e300, -1e300}, {1e300, 1e300}, green),
                   aa_line({-1.5e308, -1.5e308}, {1.5e308, 1.5e308}, red),
                   line(px(2, 40), px(14, 60), white), line(px(40, 4), px(62, 20), yellow)};
        all.push_back(s);
    }
    {
        Scene s;
        s.id = "m1.extreme_zero_length";
        s.title = "zero-length lines: one pixel, and Wu's rule with no length";
        s.hint = "When a and b are in the same pixel, dx = dy = 0: draw that pixel once and "
                 "stop; no division by the length. For Wu, the slope 0/0 is NaN: use 0.";
        s.width = s.height = 32;
        s.disjoint = true;
        s.lines = {line(px(5, 5), px(5, 5)),          line({0.2, 0.7}, {0.9, 0.1}, yellow),
                   line({31.9, 31.9}, {31.1, 31.2}, cyan), line({16, 16}, {16, 16}, magenta),
                   line({-3, -3}, {-3, -3}, red),     // outside: nothing
                   // Anti-aliased: the rule is unchanged, so a zero-length line covers the
                   // column whose center is its x, if any (x is the major axis: |dx| >= |dy|).
                   aa_line(px(10, 24), px(10, 24), green),         // a pixel center: that pixel
                   aa_line({20.5, 24.75}, {20.5, 24.75}, green),   // column 20: 0.75 and 0.25
                   aa_line({26.25, 12.5}, {26.25, 12.5}, green)};  // on no column center: nothing
        all.push_back(s);
    }
    {
        Scene s;
        s.id = "m1.extreme_nonfinite";
        s.title = "NaN and infinite endpoints draw nothing";
        s.hint = "Test std::isfinite on both endpoints first: NaN compares false with "
                 "everything, so it slips through range checks, and int(NaN) is undefined.";
        s.width = s.height = 32;
        s.lines = {line({kNaN, 5}, {20, 20}, red),        line({5, 5}, {kInf, 5}, red),
                   line({-kInf, -kInf}, {kInf, kInf}, red), line({kNaN, kNaN}, {kNaN, kNaN}, red),
                   aa_line({3, 3}, {kNaN, 30}, red),        aa_line({-kInf, 9}, {kInf, 9}, red),
                   line(px(2, 28), px(29, 16), white),      aa_line({2.5, 20.3}, {29.5, 24.8}, yellow)};
        s.clip_nonfinite = true;
        all.push_back(s);
    }
    {
        Scene s;
        s.id = "m1.image_border";
        s.title = "lines along the image border";
        s.hint = "The first and last rows and columns are inside the image: clip to "
                 "0 <= x <= width - 1, not width - 2, and keep lines that lie on the border.";
        s.width = 48;
        s.height = 32;
        s.lines = {line(px(0, 0), px(47, 0)), line(px(47, 31), px(0, 31), yellow),
                   line({0.5, -10}, {0.5, 40}, cyan), line({47.9, 40}, {47.2, -3}, magenta),
                   line(px(10, 10), px(30, 20), green)};
        all.push_back(s);
    }
    {
        Scene s;
        s.id = "m1.extreme_long_shallow";
        s.title = "very long, nearly horizontal lines";
        s.hint = "Keep the error term in integers: a float slope added 1000 times drifts. "
                 "Lines a billion pixels long must be clipped first, not walked.";
        s.width = 1024;
        s.height = 48;
        s.disjoint = true;
        s.lines = {line(px(0, 4), px(1023, 5)), line(px(1023, 10), px(0, 13), yellow),
                   line(px(0, 18), px(1023, 25), cyan), line({-1e9, 33.5}, {1e9, 34.5}, magenta),
                   aa_line({0.5, 40.3}, {1023.5, 42.7}, green)};
        all.push_back(s);
    }
    return all;
}

// ---- scene variants (grading): see "Scene variants" in checkpoints/README.md ----

using Rng = cp::VariantRng;

using Symmetry = cp::ImageSymmetry;  // see variant_random.h

Box map_box(const Box& b, const std::function<Vec2(Vec2)>& f) {
    const Vec2 p = f({b.xmin, b.ymin}), q = f({b.xmax, b.ymax});
    return {std::min(p.x, q.x), std::min(p.y, q.y), std::max(p.x, q.x), std::max(p.y, q.y)};
}

void map_points(Scene& s, const std::function<Vec2(Vec2)>& f) {
    for (Segment& g : s.lines) {
        g.a = f(g.a);
        g.b = f(g.b);
    }
    s.viewport = map_box(s.viewport, f);
}

// Bright colors, distinct from the black background, from each other and from the clip
// pictures' kUnclippedColor and kViewportColor.
constexpr Color kVariantPalette[] = {white,          yellow,          cyan,           magenta,
                                     green,          red,             {255, 150, 40}, {255, 120, 200},
                                     {120, 170, 255}, {170, 255, 90}, {200, 130, 255}};

// Gives the scene's distinct line colors new distinct colors (the same old color, the same new).
void recolor(Scene& s, Rng& rng) {
    std::vector<Color> pool(std::begin(kVariantPalette), std::end(kVariantPalette));
    rng.shuffle(pool);
    std::vector<std::pair<Color, Color>> given;
    for (Segment& g : s.lines) {
        auto it = std::find_if(given.begin(), given.end(), [&](const auto& p) { return p.first == g.color; });
        if (it == given.end()) {
            if (given.size() == pool.size()) return;  // more colors than the palette: keep them
            given.push_back({g.color, pool[given.size()]});
            it = given.end() - 1;
        }
        g.color = it->second;
    }
}

// The pixels a line may draw (Bresenham's, both pixels at a tie; Wu's, a wide band), for
// checking that the lines of a `disjoint` scene still share no pixel after a variation.
std::set<std::pair<int, int>> may_draw(const Segment& g) {
    std::set<std::pair<int, int>> out;
    Vec2 a = g.a, b = g.b;
    if (!g.aa) {
        a = {std::floor(a.x) + 0.5, std::floor(a.y) + 0.5};
        b = {std::floor(b.x) + 0.5, std::floor(b.y) + 0.5};
    }
    const bool steep = std::abs(b.y - a.y) > std::abs(b.x - a.x);
    if (steep) {
        std::swap(a.x, a.y);
        std::swap(b.x, b.y);
    }
    if (a.x > b.x) std::swap(a, b);
    const double slope = b.x > a.x ? (b.y - a.y) / (b.x - a.x) : 0.0;
    const double reach = g.aa ? 1.5 : 0.5;  // a tie is exactly 0.5 away
    for (double c = std::floor(a.x) - 1; c <= std::floor(b.x) + 1; ++c) {
        if (!g.aa && (c + 0.5 < a.x || c + 0.5 > b.x)) continue;
        const double y = a.y + slope * (c + 0.5 - a.x);
        for (double r = std::floor(y - reach) - 1; r <= std::floor(y + reach) + 1; ++r) {
            if (std::abs(r + 0.5 - y) <= reach) out.insert(steep ? std::pair{int(r), int(c)} : std::pair{int(c), int(r)});
        }
    }
    return out;
}

bool lines_disjoint(const Scene& s) {
    std::set<std::pair<int, int>> taken;
    for (const Segment& g : s.lines) {
        auto near_image = [&](Vec2 p) { return p.x > -2 && p.y > -2 && p.x < s.width + 2 && p.y < s.height + 2; };
        if (!near_image(g.a) || !near_image(g.b)) continue;  // clipped lines and non-finite ones
        for (const auto& p : may_draw(g)) {
            if (!taken.insert(p).second) return false;
        }
    }
    return true;
}

// The octant scenes keep their structure (octant k is octant 1 mapped by the symmetry that
// carries it there) with new octant-1 lines: each endpoint moved by up to 2 pixels, every
// line still strictly shallow and going right and down, no two sharing a pixel, and at least
// one line with exact ties.
Scene octant_variant(int octant, Rng& rng) {
    for (int attempt = 0; attempt < 200; ++attempt) {
        Ij base[5][2];
        bool ok = true, ties = false;
        for (int k = 0; k < 5 && ok; ++k) {
            for (int e = 0; e < 2; ++e) {
                base[k][e] = {kOctantBase[k][e].i + rng.uniform(-2, 2), kOctantBase[k][e].j + rng.uniform(-2, 2)};
                ok &= base[k][e].i >= 0 && base[k][e].i <= 47 && base[k][e].j >= 0 && base[k][e].j <= 47;
            }
            const int dx = base[k][1].i - base[k][0].i, dy = base[k][1].j - base[k][0].j;
            ok &= dx > dy && dy > 0;
            for (int i = 1; i < dx; ++i) ties |= 2 * ((dy * i) % dx) == dx;
        }
        if (!ok || !ties) continue;
        Scene s = octant_scene(1, base);
        if (lines_disjoint(s)) return octant_scene(octant, base);
    }
    return octant_scene(octant);
}

Scene vary(const Scene& pub, Rng& rng) {
    const std::string& id = pub.id;
    auto is = [&](std::initializer_list<const char*> names) {
        return std::any_of(names.begin(), names.end(), [&](const char* n) { return id == n; });
    };
    Scene s = pub;
    if (id.rfind("m1.octant_", 0) == 0) {
        s = octant_variant(id.back() - '0', rng);
        recolor(s, rng);
        return s;
    }
    if (id == "m1.outcodes") {  // sides move by whole pixels, so they still pass through centers
        s.viewport = {s.viewport.xmin + rng.uniform(-6, 6), s.viewport.ymin + rng.uniform(-6, 6),
                      s.viewport.xmax + rng.uniform(-6, 6), s.viewport.ymax + rng.uniform(-6, 6)};
    }
    if (s.kind == Kind::kClip) {
        // Each axis scaled by 13/16..1 and shifted within the image: an affine map keeps
        // every segment's relation to the viewport (inside, outside, missing a corner,
        // crossing one or two edges) while moving and resizing the viewport and the slopes.
        const double sx = 1 - rng.uniform(0, 6) / 32.0, sy = 1 - rng.uniform(0, 6) / 32.0;
        const double bx = rng.uniform(0, int(s.width * (1 - sx) * 4)) / 4.0;
        const double by = rng.uniform(0, int(s.height * (1 - sy) * 4)) / 4.0;
        map_points(s, [&](Vec2 p) { return Vec2{sx * p.x + bx, sy * p.y + by}; });
    }
    Symmetry sym;
    sym.w = s.width;
    sym.h = s.height;
    // Shallow and steep Wu scenes stay shallow and steep.
    sym.transpose = s.width == s.height && !is({"m1.aa_shallow", "m1.aa_steep"}) && rng.coin();
    sym.mirror_x = rng.coin();
    sym.mirror_y = rng.coin();
    if (id == "m1.extreme_huge") {
        // Its far lines test computing from the endpoint nearer the image. An implementation
        // that always computes from a (or from the left end) passes some mirror images of a
        // line from 1e300 by luck, and in others its misplaced line crosses the ordinary
        // lines, which hides the precision diagnosis: only the colors vary.
        sym.transpose = sym.mirror_x = sym.mirror_y = false;
    }
    if (is({"m1.axis_aligned", "m1.diagonals", "m1.endpoints", "m1.symmetry", "m1.aa_shallow", "m1.aa_steep",
            "m1.aa_diagonal"})) {
        // Nothing here touches the image border: move by up to 3 pixels, staying 1 pixel inside.
        double x0 = s.width, y0 = s.height, x1 = 0, y1 = 0;
        for (const Segment& g : s.lines) {
            for (const Vec2 p : {sym(g.a), sym(g.b)}) {
                x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
            }
        }
        sym.tx = rng.uniform(std::max(-3, 1 - int(std::floor(x0))), std::min(3, s.width - 1 - int(std::ceil(x1))));
        sym.ty = rng.uniform(std::max(-3, 1 - int(std::floor(y0))), std::min(3, s.height - 1 - int(std::ceil(y1))));
    }
    Scene mapped = s;
    map_points(mapped, sym);
    recolor(mapped, rng);
    // A mirrored endpoint on a pixel's edge lands in the neighbouring pixel: if that makes two
    // lines of a disjoint scene touch, keep the scene unmirrored (still recolored).
    if (mapped.disjoint && !lines_disjoint(mapped)) {
        recolor(s, rng);
        return s;
    }
    return mapped;
}

const std::vector<Scene>& public_scenes() {
    static const std::vector<Scene> all = make_scenes();
    return all;
}

// Made on first use: the checkpoints register (and list the scenes) during static initialization.
cp::SceneVariants<Scene>& variants() {
    static cp::SceneVariants<Scene> all(public_scenes, vary);
    return all;
}

}  // namespace

const std::vector<Scene>& scenes() { return variants().scenes(); }

const Scene& scene(const std::string& id) { return cp::find_scene(scenes(), id); }

std::vector<Vec2> border_probes(const Box& r) {
    const double mx = (r.xmin + r.xmax) / 2, my = (r.ymin + r.ymax) / 2;
    return {{r.xmin, r.ymin}, {mx, r.ymin}, {r.xmax, r.ymin}, {r.xmax, my},
            {r.xmax, r.ymax}, {mx, r.ymax}, {r.xmin, r.ymax}, {r.xmin, my}};
}

Color outcode_color(int code) {
    // Inside is white; each side has a hue and the corners mix their two sides.
    switch (code) {
        case 0: return white;
        case 1: return {200, 40, 40};    // left
        case 2: return {40, 160, 40};    // right
        case 4: return {40, 80, 220};    // top
        case 8: return {220, 180, 30};   // bottom
        case 5: return {150, 50, 170};   // left + top
        case 9: return {230, 110, 30};   // left + bottom
        case 6: return {30, 150, 170};   // right + top
        case 10: return {120, 170, 40};  // right + bottom
        default: return black;
    }
}

void use_variant(std::uint64_t seed) { variants().use(seed); }

}  // namespace m1cp
