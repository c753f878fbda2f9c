#include "m2/scenes.h"

#include "harness/checkpoint.h"
#include "variant_random.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace m2cp {

namespace {

using namespace raster::colors;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMaxCoordinate = 1 << 24;  // as pinned in triangles.h
// m2.edge_and_box's last boxes, which no variation moves (see make_scenes).
constexpr std::size_t kFixedBoxes = 3;

Tri solid(Vec2 a, Vec2 b, Vec2 c, Color color) { return {{a, b, c}, {color, color, color}, false, 0}; }
Tri gradient(Vec2 a, Vec2 b, Vec2 c, Color ca, Color cb, Color cc) { return {{a, b, c}, {ca, cb, cc}, true, 0}; }
Tri aa(Vec2 a, Vec2 b, Vec2 c, Color color, int n) { return {{a, b, c}, {color, color, color}, false, n}; }

const Color kPalette[] = {{230, 80, 60}, {60, 170, 90}, {70, 110, 230}, {230, 200, 60},
                          {170, 80, 200}, {60, 190, 200}, {240, 140, 40}, {200, 200, 200}};

// A triangle fan around c with n triangles whose outer vertices lie on a circle.
std::vector<Tri> fan(Vec2 c, double r, int n, double phase) {
    std::vector<Tri> out;
    auto at = [&](int k) {
        const double a = phase + 2 * std::numbers::pi * k / n;
        return Vec2{c.x + r * std::cos(a), c.y + r * std::sin(a)};
    };
    for (int k = 0; k < n; ++k) out.push_back(solid(c, at(k), at(k + 1), kPalette[k % 8]));
    return out;
}

// The flat-shaded faces of a cube turned towards the viewer and seen in perspective, as the
// spinning-cube renderer this course grew from draws it. Only the faces that face the viewer
// are listed: this milestone has no depth buffer, and a convex object needs none.
std::vector<Tri> cube(Vec2 center, double size, double yaw, double pitch, int aa_samples) {
    const double v[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                            {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    const int faces[6][4] = {{0, 1, 2, 3}, {5, 4, 7, 6}, {4, 0, 3, 7}, {1, 5, 6, 2}, {4, 5, 1, 0}, {3, 2, 6, 7}};
    double p[8][3];
    Vec2 s[8];
    for (int i = 0; i < 8; ++i) {
        const double x1 = v[i][0] * std::cos(yaw) + v[i][2] * std::sin(yaw);
        const double z1 = -v[i][0] * std::sin(yaw) + v[i][2] * std::cos(yaw);
        const double y2 = v[i][1] * std::cos(pitch) - z1 * std::sin(pitch);
        const double z2 = v[i][1] * std::sin(pitch) + z1 * std::cos(pitch);
        p[i][0] = x1;
        p[i][1] = y2;
        p[i][2] = z2 + 5;  // camera 5 units in front of the cube's center
        s[i] = {center.x + size * p[i][0] / p[i][2], center.y + size * p[i][1] / p[i][2]};
    }
    std::vector<Tri> out;
    for (int f = 0; f < 6; ++f) {
        const int* q = faces[f];
        // Facing the viewer: the face's outward normal points towards the camera at the origin.
        const double e1[3] = {p[q[1]][0] - p[q[0]][0], p[q[1]][1] - p[q[0]][1], p[q[1]][2] - p[q[0]][2]};
        const double e2[3] = {p[q[2]][0] - p[q[0]][0], p[q[2]][1] - p[q[0]][1], p[q[2]][2] - p[q[0]][2]};
        const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        const double to_face = n[0] * p[q[0]][0] + n[1] * p[q[0]][1] + n[2] * p[q[0]][2];
        if (to_face <= 0) continue;
        for (const auto& t : {std::array<int, 3>{q[0], q[1], q[2]}, std::array<int, 3>{q[0], q[2], q[3]}}) {
            out.push_back(aa_samples > 0 ? aa(s[t[0]], s[t[1]], s[t[2]], kPalette[f], aa_samples)
                                         : solid(s[t[0]], s[t[1]], s[t[2]], kPalette[f]));
        }
    }
    return out;
}

Scene make(std::string id, std::string title, std::string hint, std::vector<Tri> tris) {
    Scene s;
    s.id = std::move(id);
    s.title = std::move(title);
    s.hint = std::move(hint);
    s.tris = std::move(tris);
    return s;
}

std::vector<Scene> make_scenes() {
    std::vector<Scene> all;
    {
        Scene s = make("m2.solid", "solid triangles of several shapes",
                       "Test every pixel center of the bounding box against all three edge functions; "
                       "a pixel is in when none of them is negative.",
                       {solid({4.3, 3.1}, {30.2, 8.7}, {9.6, 27.9}, kPalette[0]),
                        solid({36.1, 2.2}, {60.8, 3.9}, {59.3, 29.4}, kPalette[1]),   // right-angled-ish
                        solid({3.2, 33.3}, {61.7, 36.1}, {20.4, 42.6}, kPalette[2]),  // wide and obtuse
                        solid({40.6875, 44.125}, {44.1875, 62.8125}, {30.875, 61.3125}, kPalette[3]),  // on the 1/16 grid
                        solid({5.5, 47.25}, {22.75, 62.5}, {5.5, 62.5}, kPalette[4]),
                        // Legs through pixel centers at opposite corners to the one before: mirrored
                        // or turned, one of the two keeps a bottom or a right leg, whose centers
                        // the top-left rule leaves out (every variant tests the rule).
                        solid({48.5, 45.5}, {61.5, 45.5}, {61.5, 58.5}, kPalette[5])});
        s.check_winding = true;
        all.push_back(s);
    }
    {
        // The same triangles as in m2.solid, half of them listed clockwise and half
        // counter-clockwise on screen. The gradient lies on a gray backdrop (two triangles
        // drawn first), so a pixel it paints black is told apart from one it skips.
        const Color gray{60, 60, 60};
        Scene s = make("m2.windings", "both windings give the same pixels",
                       "If the signed area is negative, swap two vertices (and their colors) "
                       "before testing: do not skip the triangle, and do not flip the fill rule.",
                       {solid({4.3, 3.1}, {9.6, 27.9}, {30.2, 8.7}, kPalette[0]),
                        solid({36.1, 2.2}, {60.8, 3.9}, {59.3, 29.4}, kPalette[1]),
                        solid({3.2, 33.3}, {20.4, 42.6}, {61.7, 36.1}, kPalette[2]),
                        solid({29, 43}, {47, 43}, {47, 64}, gray), solid({29, 43}, {47, 64}, {29, 64}, gray),
                        gradient({40.6875, 44.125}, {30.875, 61.3125}, {44.1875, 62.8125}, red, green, blue)});
        s.check_winding = true;
        all.push_back(s);
    }
    {
        // Edges through pixel centers: horizontal and vertical, and slanted ones with
        // rational slopes. Every center on an edge is decided by the fill rule alone.
        Scene s = make("m2.top_left", "fill rule: centers on top and left edges are in, on bottom and right edges out",
                       "A center exactly on an edge (edge value 0) is covered only for a top edge "
                       "(horizontal, triangle below) or a left edge (going up, once the area is positive).",
                       {solid({4.5, 4.5}, {20.5, 4.5}, {4.5, 20.5}, kPalette[0]),     // top and left edges
                        solid({40.5, 4.5}, {40.5, 20.5}, {24.5, 20.5}, kPalette[1]),  // bottom and right edges
                        solid({44.5, 4.5}, {60.5, 12.5}, {44.5, 20.5}, kPalette[2]),
                        solid({20.5, 26.5}, {36.5, 58.5}, {4.5, 58.5}, kPalette[3]),   // slanted sides, flat bottom
                        solid({42.5, 26.5}, {58.5, 26.5}, {50.5, 58.5}, kPalette[4])}); // flat top
        s.check_winding = true;
        all.push_back(s);
    }
    {
        Scene s = make("m2.shared_edges", "triangles sharing an edge cover each center on it exactly once",
                       "Two triangles on either side of an edge see the edge with opposite direction: "
                       "the top-left rule gives each center on it to exactly one of them.",
                       {solid({4.5, 4.5}, {28.5, 4.5}, {4.5, 28.5}, kPalette[0]),
                        solid({28.5, 4.5}, {28.5, 28.5}, {4.5, 28.5}, kPalette[1]),  // diagonal shared
                        solid({36.5, 4.5}, {60.5, 16.5}, {36.5, 28.5}, kPalette[2]),
                        solid({60.5, 16.5}, {60.5, 28.5}, {36.5, 28.5}, kPalette[3]),
                        solid({36.5, 4.5}, {60.5, 4.5}, {60.5, 16.5}, kPalette[4]),
                        solid({4.5, 36.5}, {32.5, 36.5}, {18.5, 60.5}, kPalette[5]),  // horizontal and slanted shared
                        solid({32.5, 36.5}, {60.5, 60.5}, {18.5, 60.5}, kPalette[6]),
                        solid({32.5, 36.5}, {60.5, 36.5}, {60.5, 60.5}, kPalette[7])});
        s.watertight = true;
        all.push_back(s);
    }
    {
        // Vertices on the 1/16 grid, so every pixel's color is known exactly: l0 * c0 + l1 * c1 +
        // l2 * c2 rounded to the nearest level. The gradient lies over a gray backdrop, so a
        // pixel it paints black (integer division in the weights) differs from one it skips.
        const Color gray{60, 60, 60};
        Scene s = make("m2.gradient", "per-vertex colors interpolated with barycentric coordinates, rounded to nearest",
                       "The weight of a vertex is the edge function of the OPPOSITE edge divided by the "
                       "doubled area (in floating point, not integer division): 1 at that vertex, 0 on the far "
                       "edge. Round each channel to the nearest level; do not truncate.",
                       {solid({0, 0}, {64, 0}, {0, 64}, gray), solid({64, 0}, {64, 64}, {0, 64}, gray),
                        gradient({32.25, 3.75}, {60.625, 58.125}, {3.375, 52.875}, red, green, blue)});
        s.check_winding = true;
        s.demo = true;
        all.push_back(s);
    }
    {
        Scene s = make("m2.fan", "a fan of 16 triangles is watertight (demo)",
                       "Neighbouring triangles share an edge: each center near it must be covered by "
                       "exactly one of them. Double coverage or gaps mean the fill rule is off.",
                       fan({32.3, 31.7}, 29.4, 16, 0.1));
        s.watertight = true;
        s.demo = true;
        all.push_back(s);
    }
    {
        std::vector<Tri> tris;
        for (int j = 0; j < 6; ++j) {
            for (int i = 0; i < 6; ++i) {
                // Every x on a pixel center, so vertical edges run through centers; every other
                // column of corners a quarter pixel lower, so some edges are slightly slanted.
                auto p = [](int a, int b) { return Vec2{2.5 + 10.0 * a, 1.5 + 10.0 * b + 0.25 * (a % 2)}; };
                const Color c1 = kPalette[(i + j) % 8], c2 = kPalette[(i + j + 3) % 8];
                if ((i + j) % 2 == 0) {
                    tris.push_back(solid(p(i, j), p(i + 1, j), p(i + 1, j + 1), c1));
                    tris.push_back(solid(p(i, j), p(i + 1, j + 1), p(i, j + 1), c2));
                } else {
                    tris.push_back(solid(p(i, j), p(i + 1, j), p(i, j + 1), c1));
                    tris.push_back(solid(p(i + 1, j), p(i + 1, j + 1), p(i, j + 1), c2));
                }
            }
        }
        Scene s = make("m2.grid", "a grid of 72 triangles is watertight",
                       "Every interior edge is shared by two triangles and every center must be covered "
                       "exactly once: check the top-left rule and that the bounding box includes its last row and column.",
                       tris);
        s.watertight = true;
        all.push_back(s);
    }
    {
        Scene s = make("m2.slivers", "a disc of 96 slivers is watertight",
                       "Slivers put many centers very close to shared edges. Exact integer edge functions "
                       "on snapped vertices decide them consistently; floats do not.",
                       fan({31.7, 32.2}, 30.3, 96, 0.05));
        s.watertight = true;
        all.push_back(s);
    }
    all.push_back(make("m2.needles", "needle triangles thinner than a pixel",
                       "A triangle thinner than a pixel covers only the centers it really contains: "
                       "often one per column, sometimes none. Do not widen it.",
                       {solid({2.5, 3.5}, {61.5, 5.0}, {61.5, 5.25}, kPalette[0]),
                        solid({3.0, 20.5}, {60.0, 21.0}, {3.0, 20.6875}, kPalette[1]),
                        solid({10.5, 30.0}, {10.75, 30.0}, {12.5, 62.0}, kPalette[2]),
                        solid({30.0, 40.0}, {60.4375, 61.5}, {60.5, 61.5}, kPalette[3]),
                        solid({40.5, 8.5}, {55.5, 8.5}, {55.5, 8.5625}, kPalette[4])}));
    all.push_back(make("m2.subpixel", "triangles smaller than a pixel",
                       "A tiny triangle covers a pixel only if it contains the pixel's center; the bounding "
                       "box may be empty, and must then draw nothing.",
                       {solid({5.25, 5.25}, {5.75, 5.25}, {5.5, 5.75}, kPalette[0]),      // contains (5.5, 5.5)
                        solid({10.0, 10.0}, {10.4, 10.0}, {10.0, 10.4}, kPalette[1]),     // misses (10.5, 10.5)
                        solid({20.5, 20.5}, {21.0, 20.5}, {20.5, 21.0}, kPalette[2]),     // center on top-left corner
                        solid({30.0, 30.0}, {30.5, 30.5}, {30.0, 30.5}, kPalette[3]),     // center on right/bottom
                        solid({40.1875, 40.3125}, {40.9375, 40.5}, {40.25, 40.6875}, kPalette[4]),
                        solid({8.5, 50.5}, {40.5, 50.5}, {24.5, 54.5}, kPalette[5])}));   // an ordinary one
    all.push_back(make("m2.degenerate", "degenerate triangles draw nothing",
                       "Zero area (collinear or coincident vertices) means nothing to draw: return before "
                       "dividing by the area.",
                       {solid({4.5, 4.5}, {30.5, 30.5}, {56.5, 56.5}, red),   // collinear
                        solid({10, 50}, {10, 50}, {10, 50}, red),             // one point
                        solid({40, 10}, {40, 10}, {60, 20}, red),             // two coincident vertices
                        solid({2.5, 60.5}, {62.5, 60.5}, {32.5, 60.5}, red),  // flat, on centers
                        gradient({50, 40}, {55, 45}, {60, 50}, red, green, blue),
                        solid({6.3, 8.1}, {26.9, 12.2}, {14.4, 30.7}, kPalette[1])}));
    all.push_back(make("m2.nonfinite", "NaN, infinite and out-of-range vertices, and unsupported sample counts, draw nothing",
                       "Check std::isfinite and the coordinate range when snapping; a NaN compares false "
                       "with everything, so range checks alone let it through. fill_triangle_aa draws nothing "
                       "unless n is 1, 2, 4 or 8.",
                       {solid({kNaN, 5}, {30, 30}, {5, 30}, red), solid({5, 5}, {kInf, 5}, {5, 30}, red),
                        solid({-kInf, -kInf}, {kInf, 5}, {5, kInf}, red),
                        gradient({5, 5}, {30, kNaN}, {5, 30}, red, green, blue),
                        aa({5, 5}, {30, 5}, {kNaN, 30}, red, 4),
                        solid({1e300, 0}, {2e300, 10}, {1e300, 50}, red),  // beyond kMaxCoordinate, off to the right
                        aa({4.5, 36.5}, {28.5, 40.5}, {8.5, 60.5}, red, 3),      // n = 3 and n = 16: not supported
                        aa({12.5, 34.5}, {30.5, 50.5}, {4.5, 62.5}, red, 16),
                        solid({34.2, 36.6}, {61.1, 40.3}, {45.7, 60.8}, kPalette[2])}));
    {
        Scene s = make("m2.huge", "vertices at +/-1e7 in all three fills: clamp the bounding box, keep exact edges",
                       "Clamp the bounding box to the image before looping (in fill_triangle, "
                       "fill_triangle_gradient and fill_triangle_aa alike), and evaluate edge functions "
                       "exactly: in float, 1e7 has no fractional digits left and edges move by pixels.",
                       {solid({-1e7, 10.25}, {1e7, 30.75}, {0.5, 1e7}, kPalette[0]),
                        solid({-1e7, -1e7}, {40.5, 2.0}, {1e7, -1e7}, kPalette[1]),
                        solid({55.25, -1e7}, {62.0, 1e7}, {1e7, 0}, kPalette[2]),
                        // Wedges inside the first triangle, each with one vertex in the image and
                        // two far away: a gradient (one color: its box is what is tested, not its
                        // weights at 1e7) and 16 samples per pixel.
                        gradient({44.6, 36.2}, {0.5e7, 1e7}, {44.9, 1e7}, kPalette[3], kPalette[3], kPalette[3]),
                        aa({20.3, 40.7}, {-1e7, 47.9}, {-1e7, 1e7}, white, 4)});
        s.check_winding = true;
        all.push_back(s);
    }

    // Anti-aliasing: the same white triangles on black with 1, 4 and 16 samples per pixel.
    for (int n : {1, 2, 4}) {
        Scene s = make("m2.aa_" + std::to_string(n * n), std::to_string(n * n) + " sample(s) per pixel",
                       "Samples sit at (x + (i + 0.5) / n, y + (j + 0.5) / n); coverage is the share of "
                       "covered samples, blended over the pixel with Image::blend.",
                       {aa({4.3, 3.7}, {60.2, 14.9}, {18.8, 40.1}, white, n),
                        aa({40.6, 30.3}, {61.4, 61.2}, {22.7, 58.6}, white, n),
                        aa({3.1, 50.2}, {14.6, 47.9}, {9.2, 62.4}, white, n)});
        all.push_back(s);
    }
    {
        // Every vertex on the 4 x 4 sample grid (x + 1/8 + i/4), so edges run exactly through
        // samples: horizontal, vertical and slanted ones, shared and outer. The top-left rule
        // decides each of those samples, as it decides pixel centers.
        auto q = [](double a, double b) { return Vec2{a + 0.125, b + 0.125}; };
        const Vec2 hub = q(32, 46);
        Scene s = make("m2.aa_edges", "16 samples per pixel with edges exactly through samples: the fill rule per sample",
                       "A sample exactly on an edge counts only for a top or left edge, exactly as a pixel center "
                       "does in fill_triangle: use the same coverage test for samples.",
                       {aa(q(4, 4), q(28, 4), q(4, 28), kPalette[0], 4), aa(q(28, 4), q(28, 28), q(4, 28), kPalette[1], 4),
                        aa(q(36, 4), q(60, 16), q(36, 28), kPalette[2], 4),
                        aa(q(60, 16), q(60, 28), q(36, 28), kPalette[3], 4),
                        aa(hub, q(16, 46), q(32, 34), kPalette[4], 4), aa(hub, q(32, 34), q(48, 46), kPalette[5], 4),
                        aa(hub, q(48, 46), q(32, 60), kPalette[6], 4), aa(hub, q(32, 60), q(16, 46), kPalette[7], 4),
                        // Top edge at y = 4.625 and left edge at x = 66.625: row 4 and column 66
                        // hold no center of the triangle (bounding_box() leaves them out), but
                        // half of their samples are inside.
                        aa(q(66.5, 4.5), q(90.25, 4.5), q(66.5, 28.25), white, 4)});
        s.width = 96;
        all.push_back(s);
    }
    {
        Scene s = make("m2.edge_and_box", "snap(), edge() and bounding_box() on chosen inputs",
                       "snap rounds to the nearest 1/16; edge is cross(b - a, p - a) in sixteenths; the box "
                       "holds every pixel whose center is inside the vertices' range, clamped to the image.",
                       {});
        s.numbers.snaps = {{1.03, 2.97}, {-1.03, -2.97}, {0.03125, -0.03125}, {1e7, -1e7}, {3e7, 0}, {kNaN, 1},
                           {kMaxCoordinate, -kMaxCoordinate}};  // the range's end is in it
        s.numbers.boxes = {{{4.5, 4.5}, {20.5, 4.5}, {4.5, 20.5}},     // box edges on centers
                           {{4.4, 4.6}, {20.6, 4.4}, {4.6, 20.6}},     // just outside / inside
                           {{-10.2, -3.3}, {12.7, 70.1}, {80.0, 8.8}},  // clamped on all sides
                           {{30.2, 30.2}, {30.4, 30.7}, {30.3, 30.3}},  // no center inside: empty
                           {{44.7, 44.8}, {60.3, 44.9}, {44.9, 60.2}},  // the overlapped pixels are a superset
                           {{-1e7, 5.5}, {1e7, 5.6}, {0, 1e7}},
                           // The largest x (then y) in [-0.5, 0.5): floor((5 - 8) / 16) + 1 = 0, an
                           // empty box; a division that truncates toward zero gives 1. Kept as
                           // they are in every variation (kFixedBoxes): mirrored, they test nothing.
                           {{-3, 5}, {0.3, 5}, {-1, 8}},
                           {{5, -3}, {8, 0.3}, {6, -1}},
                           // An edge of -51200007680000132 sixteenths squared: exact in 64-bit
                           // integers; with its products rounded to double (53 bits) it is 4 off,
                           // with or without a fused multiply-add.
                           {{-9999999.9375, 1.0625}, {9999999.9375, 2.6875}, {0.4375, -9999999.6875}}};
        for (const auto& b : s.numbers.boxes) s.tris.push_back(solid(b[0], b[1], b[2], kPalette[s.tris.size() % 8]));
        all.push_back(s);
    }
    {
        Scene s = make("m2.cube", "flat-colored faces of a cube (demo)",
                       "Each face is two triangles sharing a diagonal; neighbouring faces share edges.",
                       cube({64, 64}, 170, 0.6, 0.45, 0));
        s.width = s.height = 128;
        s.watertight = true;
        s.demo = true;
        all.push_back(s);
    }
    {
        std::vector<Tri> tris = cube({48, 64}, 120, 0.6, 0.45, 0);
        for (const Tri& t : cube({144, 64}, 120, 0.6, 0.45, 4)) tris.push_back(t);
        Scene s = make("m2.aa_compare", "the cube without and with 16x anti-aliasing (demo)",
                       "Left: one sample per pixel. Right: 16 samples per pixel; edges shade smoothly.",
                       tris);
        s.width = 192;
        s.height = 128;
        s.demo = true;
        all.push_back(s);
    }
    return all;
}

// ---- scene variants (grading): see "Scene variants (grading)" in checkpoints/README.md ----

using Rng = cp::VariantRng;

using Symmetry = cp::ImageSymmetry;  // see variant_random.h

bool near_image(Vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::abs(p.x) < 1e4 && std::abs(p.y) < 1e4; }

// The scene's colors from kPalette permuted among themselves, and each gradient's three vertex
// colors permuted: distinct colors stay distinct, and the gray backdrops, white and red stay.
void recolor(Scene& s, Rng& rng) {
    std::vector<int> perm{0, 1, 2, 3, 4, 5, 6, 7};
    rng.shuffle(perm);
    for (Tri& t : s.tris) {
        for (Color& c : t.c) {
            for (int k = 0; k < 8; ++k) {
                if (c == kPalette[k]) {
                    c = kPalette[perm[std::size_t(k)]];
                    break;
                }
            }
        }
        if (t.gradient) {
            std::vector<Color> cs{t.c[0], t.c[1], t.c[2]};
            rng.shuffle(cs);
            for (int i = 0; i < 3; ++i) t.c[i] = cs[std::size_t(i)];
        }
    }
}

Scene vary(const Scene& pub, Rng& rng) {
    Scene s = pub;
    const std::string& id = s.id;
    if (id == "m2.edge_and_box") {
        // Move the snapped points by whole units (their fractions, which decide the rounding, stay).
        for (Vec2& p : s.numbers.snaps) {
            if (near_image(p)) p = {p.x + rng.uniform(-40, 40), p.y + rng.uniform(-40, 40)};
        }
    }
    Symmetry sym;
    sym.w = s.width;
    sym.h = s.height;
    sym.transpose = s.width == s.height && rng.coin();
    sym.mirror_x = rng.coin();
    sym.mirror_y = rng.coin();
    if (id == "m2.huge") {
        // Without its box clamped, the first triangle's loop must run into the stray-write
        // budget (a "runaway loop"); in some mirror images it walks empty rows first and the
        // watchdog stops it instead, naming another concept: only the colors vary.
        sym.transpose = sym.mirror_x = sym.mirror_y = false;
    }
    if (id != "m2.huge" && id != "m2.edge_and_box") {
        // Up to 3 whole pixels, keeping every vertex near the image inside it.
        double x0 = s.width, y0 = s.height, x1 = 0, y1 = 0;
        for (const Tri& t : s.tris) {
            for (const Vec2& v : t.v) {
                if (!near_image(v)) continue;
                const Vec2 p = sym(v);
                x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
            }
        }
        sym.tx = rng.uniform(std::max(-3, -int(std::floor(x0))), std::min(3, s.width - int(std::ceil(x1))));
        sym.ty = rng.uniform(std::max(-3, -int(std::floor(y0))), std::min(3, s.height - int(std::ceil(y1))));
    }
    for (Tri& t : s.tris) {
        for (Vec2& v : t.v) v = sym(v);
    }
    for (Vec2& p : s.numbers.snaps) p = sym(p);
    // Moved and mirrored, the public scene's negative half may have become a positive one: keep
    // one negative half on each axis (-0.5 and -16.5 sixteenths, which std::llround sends away
    // from zero and floor(x + 0.5) toward it).
    // And the range's end, which a mirror image moves.
    if (id == "m2.edge_and_box") {
        s.numbers.snaps.push_back({-0.03125, -1.03125});
        s.numbers.snaps.push_back({-kMaxCoordinate, kMaxCoordinate});
    }
    const std::size_t fixed_boxes = id == "m2.edge_and_box" ? kFixedBoxes : 0;
    for (std::size_t i = 0; i + fixed_boxes < s.numbers.boxes.size(); ++i) {
        for (Vec2& v : s.numbers.boxes[i]) v = sym(v);
    }
    recolor(s, rng);
    return s;
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

void use_variant(std::uint64_t seed) { variants().use(seed); }

}  // namespace m2cp
