// Benchmarks of the reference solutions of milestones 1 and 2 (`make bench`). Speed is
// measured here, never in the checkpoints, in this thread's CPU time (another process on the
// machine does not count).
//
// Part 1: each reference function against the naive method a student writes first, on the
// same input in the same run (lines: a floating-point DDA rounding per pixel; Wu: the same
// columns and blend computed per pixel in floating point with the library's floor and round;
// triangles: the bounding box with the barycentric coordinates solved by a cross product in
// double at every pixel, and for supersampling at every sample). The two are timed in
// alternating rounds and the median of the per-round ratios is reported, with its spread, so
// a busy machine slows both alike. `bench_reference --lesson1 FILE --lesson2 FILE` writes the
// tables between the m1-bench-<build type> and m2-bench-<build type> markers of the lessons
// (RelWithDebInfo, the default, and Release have their own tables).
//
// Part 2: what the numbers should show about clipping first: the work is proportional to the
// visible pixels (a line or triangle reaching a billion pixels away costs what its visible
// part costs), and supersampling costs about n * n times the plain fill.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "harness/bench_build.h"
#include "harness/checkpoint.h"
#include "lines.h"
#include "raster/image.h"
#include "triangles.h"

namespace {

using raster::Color;
using raster::Image;
using raster::Vec2;

constexpr int kSize = 800;

struct Segment {
    Vec2 a, b;
};

std::vector<Segment> random_segments(int count, double lo, double hi, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> d(lo, hi);
    std::vector<Segment> out;
    for (int i = 0; i < count; ++i) out.push_back({{d(rng), d(rng)}, {d(rng), d(rng)}});
    return out;
}

long long lit_pixels(const Image& img) {
    long long n = 0;
    for (int y = 0; y < img.height(); ++y) {
        for (int x = 0; x < img.width(); ++x) n += img.at(x, y) != raster::colors::black;
    }
    return n;
}

void report(const char* what, double seconds, long long items, const char* unit) {
    std::printf("%-58s %9.3f ms %10.1f ns per %s\n", what, seconds * 1e3, seconds * 1e9 / double(items), unit);
}

// ---- the naive methods ----

// A DDA in floating point: step x and y by their share of the longer axis and round both
// at every pixel (the endpoints snapped to pixel centers as draw_line does; no clipping, so
// the input must lie inside the image).
void naive_dda(Image& img, Vec2 a, Vec2 b, Color c) {
    const double x0 = std::floor(a.x), y0 = std::floor(a.y), x1 = std::floor(b.x), y1 = std::floor(b.y);
    const double steps = std::max(std::abs(x1 - x0), std::abs(y1 - y0));
    const double sx = steps > 0 ? (x1 - x0) / steps : 0, sy = steps > 0 ? (y1 - y0) / steps : 0;
    double x = x0, y = y0;
    for (int i = 0; i <= int(steps); ++i) {
        img.set(int(std::lround(x)), int(std::lround(y)), c);
        x += sx;
        y += sy;
    }
}

// Wu's line as first written: for each column, the line's y in floating point, its integer
// and fractional parts with std::floor, the steep case decided per pixel, and each pixel
// blended in floating point, the channels rounded with std::round.
void blend_float(Image& img, int x, int y, Color c, double coverage) {
    if (!img.in_bounds(x, y)) return;
    std::uint8_t* p = img.data() + 3 * (std::size_t(y) * std::size_t(img.width()) + std::size_t(x));
    const double to[3] = {double(c.r), double(c.g), double(c.b)};
    for (int k = 0; k < 3; ++k) {
        const double v = std::clamp(p[k] + coverage * (to[k] - p[k]), 0.0, 255.0);
        p[k] = std::uint8_t(std::round(v));
    }
}

void naive_wu(Image& img, Vec2 a, Vec2 b, Color c) {
    const bool steep = std::abs(b.y - a.y) > std::abs(b.x - a.x);
    if (steep) {
        std::swap(a.x, a.y);
        std::swap(b.x, b.y);
    }
    if (a.x > b.x) std::swap(a, b);
    const double gradient = b.x > a.x ? (b.y - a.y) / (b.x - a.x) : 0.0;
    auto plot = [&](int x, int y, double coverage) {
        if (steep) {
            blend_float(img, y, x, c, coverage);
        } else {
            blend_float(img, x, y, c, coverage);
        }
    };
    for (int x = int(std::ceil(a.x - 0.5)); x <= int(std::floor(b.x - 0.5)); ++x) {
        const double y = a.y + gradient * (x + 0.5 - a.x) - 0.5;
        const double fraction = y - std::floor(y);
        plot(x, int(std::floor(y)), 1 - fraction);
        plot(x, int(std::floor(y)) + 1, fraction);
    }
}

// The triangle as first written: the bounding box of the vertices, and at every pixel center
// (or every sample, for supersampling) the barycentric coordinates solved by a cross product
// in double; covered where all three are >= 0.
struct Barycentric {
    double u, v, w;  // weights of a, b, c
    bool ok;
};
Barycentric barycentric(Vec2 a, Vec2 b, Vec2 c, Vec2 p) {
    const double ux = c.x - a.x, vx = b.x - a.x, wx = a.x - p.x;
    const double uy = c.y - a.y, vy = b.y - a.y, wy = a.y - p.y;
    const double cx = vx * wy - wx * vy, cy = wx * uy - ux * wy, cz = ux * vy - vx * uy;
    if (std::abs(cz) < 1e-12) return {0, 0, 0, false};
    return {1 - (cx + cy) / cz, cy / cz, cx / cz, true};
}

void naive_triangle(Image& img, Vec2 a, Vec2 b, Vec2 c, Color color) {
    const int x0 = std::max(0, int(std::floor(std::min({a.x, b.x, c.x}))));
    const int x1 = std::min(img.width() - 1, int(std::ceil(std::max({a.x, b.x, c.x}))));
    const int y0 = std::max(0, int(std::floor(std::min({a.y, b.y, c.y}))));
    const int y1 = std::min(img.height() - 1, int(std::ceil(std::max({a.y, b.y, c.y}))));
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            const Barycentric l = barycentric(a, b, c, {x + 0.5, y + 0.5});
            if (l.ok && l.u >= 0 && l.v >= 0 && l.w >= 0) img.set(x, y, color);
        }
    }
}

void naive_triangle_aa(Image& img, Vec2 a, Vec2 b, Vec2 c, Color color, int n) {
    const int x0 = std::max(0, int(std::floor(std::min({a.x, b.x, c.x}))));
    const int x1 = std::min(img.width() - 1, int(std::ceil(std::max({a.x, b.x, c.x}))));
    const int y0 = std::max(0, int(std::floor(std::min({a.y, b.y, c.y}))));
    const int y1 = std::min(img.height() - 1, int(std::ceil(std::max({a.y, b.y, c.y}))));
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            int covered = 0;
            for (int j = 0; j < n; ++j) {
                for (int i = 0; i < n; ++i) {
                    const Barycentric l = barycentric(a, b, c, {x + (i + 0.5) / n, y + (j + 0.5) / n});
                    covered += l.ok && l.u >= 0 && l.v >= 0 && l.w >= 0;
                }
            }
            if (covered > 0) img.blend(x, y, color, double(covered) / (n * n));
        }
    }
}

// ---- reference against naive, alternating rounds ----

struct Comparison {
    std::string what;
    long long items = 0;
    const char* unit = "";
    double reference = 0, naive = 0;  // median seconds per run
    double ratio = 0, ratio_lo = 0, ratio_hi = 0;  // median, smallest and largest per-round ratio
    long long differing = 0;  // pixels where the two images differ by more than 1 level
};

// Each round clears an image and draws the whole input with the reference, then with the
// naive method (the order alternates between rounds).
Comparison compare(const std::string& what, long long items, const char* unit, const std::function<void(Image&)>& reference,
                   const std::function<void(Image&)>& naive, int rounds) {
    Comparison c;
    // (BENCH_ONLY=text: only the comparisons whose name contains it, e.g. for profiling)
    if (const char* only = std::getenv("BENCH_ONLY"); only && what.find(only) == std::string::npos) return c;
    Image ref_img(kSize, kSize), naive_img(kSize, kSize);
    std::vector<double> tr, tn, ratio;
    auto timed = [](Image& img, const std::function<void(Image&)>& fn) {
        img.fill(raster::colors::black);
        const double start = bench::cpu_now();
        fn(img);
        return bench::cpu_now() - start;
    };
    for (int r = 0; r < rounds; ++r) {
        double a, b;
        if (r % 2 == 0) {
            a = timed(ref_img, reference);
            b = timed(naive_img, naive);
        } else {
            b = timed(naive_img, naive);
            a = timed(ref_img, reference);
        }
        tr.push_back(a);
        tn.push_back(b);
        ratio.push_back(b / a);
    }
    c.what = what;
    c.items = items;
    c.unit = unit;
    c.reference = bench::median(tr);
    c.naive = bench::median(tn);
    c.ratio = bench::median(ratio);
    c.ratio_lo = *std::min_element(ratio.begin(), ratio.end());
    c.ratio_hi = *std::max_element(ratio.begin(), ratio.end());
    c.differing = bench::differing_pixels(ref_img, naive_img);
    std::printf("%-52s reference %8.1f ns, naive %8.1f ns per %s: %5.2fx (rounds %.2f to %.2f)%s\n", what.c_str(),
                c.reference * 1e9 / double(items), c.naive * 1e9 / double(items), unit, c.ratio, c.ratio_lo, c.ratio_hi,
                c.ratio >= 2 ? "" : "  below 2x");
    if (c.differing > 0) std::printf("%-52s (the two pictures differ in %lld pixels)\n", "", c.differing);
    return c;
}

std::string table_of(const std::vector<Comparison>& rows) {
    std::ostringstream out;
    out << "Build: " << RASTER_BUILD_TYPE << " (`" << RASTER_BUILD_FLAGS << "`), one thread, CPU time, median of the rounds.\n\n"
        << "| what | reference | naive method | speedup (median) | speedup, slowest to fastest round |\n"
        << "|---|---|---|---|---|\n";
    for (const Comparison& c : rows) {
        if (c.items == 0) continue;
        char row[400];
        std::snprintf(row, sizeof row, "| %s | %.1f ns per %s | %.1f ns per %s | %.2fx | %.2fx to %.2fx |\n", c.what.c_str(),
                      c.reference * 1e9 / double(c.items), c.unit, c.naive * 1e9 / double(c.items), c.unit, c.ratio,
                      c.ratio_lo, c.ratio_hi);
        out << row;
    }
    return out.str();
}

bool write_between_markers(const std::string& lesson, const std::string& name, const std::string& table) {
    std::ifstream in(lesson);
    std::stringstream ss;
    ss << in.rdbuf();
    std::string text = ss.str();
    const std::string begin = "<!-- " + name, end = "<!-- /" + name + " -->";
    const auto b = text.find(begin), e = text.find(end);
    if (!in || b == std::string::npos || e == std::string::npos || e < b) {
        std::cerr << lesson << ": no " << name << " markers; the table was not written\n";
        return false;
    }
    const auto body = text.find('\n', b) + 1;
    text.replace(body, e - body, table);
    std::ofstream(lesson) << text;
    std::printf("wrote the table into %s\n", lesson.c_str());
    return true;
}

// Small triangles tiling a disc: a fan of rings, about 18 pixels each (as in a mesh).
std::vector<std::array<Vec2, 3>> disc_triangles() {
    std::vector<std::array<Vec2, 3>> out;
    const Vec2 center{400.3, 400.7};
    const int rings = 25;
    const double r_step = 4.8;  // a disc of radius 120: about 18 pixels per triangle
    for (int ring = 0; ring < rings; ++ring) {
        const int segments = 4 * ring + 4;
        const double r0 = ring * r_step, r1 = (ring + 1) * r_step;
        const int inner = std::max(1, 4 * ring);
        for (int s = 0; s < segments; ++s) {
            auto at = [&](double r, int k, int count) {
                const double angle = 2 * M_PI * k / count;
                return Vec2{center.x + r * std::cos(angle), center.y + r * std::sin(angle)};
            };
            // the ring between r0 and r1, as triangles between its outer and inner vertices
            const Vec2 o0 = at(r1, s, segments), o1 = at(r1, s + 1, segments);
            const Vec2 i0 = at(r0, s * inner / segments, inner), i1 = at(r0, (s + 1) * inner / segments, inner);
            out.push_back({i0, o0, o1});
            if (ring > 0 && !(i0 == i1)) out.push_back({i0, o1, i1});
        }
    }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    std::string lesson1, lesson2;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (std::string(argv[i]) == "--lesson1") lesson1 = argv[i + 1];
        if (std::string(argv[i]) == "--lesson2") lesson2 = argv[i + 1];
    }
    std::printf("Reference solutions, one thread, %dx%d image, build %s (%s)\n\n", kSize, kSize, RASTER_BUILD_TYPE,
                RASTER_BUILD_FLAGS);
    const int rounds = 9;

    // ---- part 1: against the naive methods ----
    std::vector<Comparison> m1_rows, m2_rows;
    {
        const auto lines = random_segments(2000, 0, kSize, 11);
        long long pixels = 0;
        for (const Segment& s : lines) {
            pixels += 1 + long(std::max(std::abs(std::floor(s.b.x) - std::floor(s.a.x)), std::abs(std::floor(s.b.y) - std::floor(s.a.y))));
        }
        std::printf("milestone 1: 2,000 random lines inside the image, %lld pixels in all\n", pixels);
        m1_rows.push_back(compare("draw_line (Bresenham) vs a floating-point DDA", pixels, "pixel",
                                  [&](Image& img) { for (const Segment& s : lines) m1::reference::draw_line(img, s.a, s.b, raster::colors::white); },
                                  [&](Image& img) { for (const Segment& s : lines) naive_dda(img, s.a, s.b, raster::colors::white); },
                                  rounds));
        m1_rows.push_back(compare("draw_line_aa (Wu) vs Wu in floating point per pixel", pixels, "column",
                                  [&](Image& img) { for (const Segment& s : lines) m1::reference::draw_line_aa(img, s.a, s.b, {255, 200, 80}); },
                                  [&](Image& img) { for (const Segment& s : lines) naive_wu(img, s.a, s.b, {255, 200, 80}); },
                                  rounds));
    }
    {
        const auto disc = disc_triangles();
        std::mt19937 rng(2);
        std::uniform_real_distribution<double> pos(20, kSize - 20), off(-6, 6);
        std::vector<std::array<Vec2, 3>> small;
        for (int i = 0; i < 2500; ++i) {
            const Vec2 a{pos(rng), pos(rng)};
            small.push_back({a, a + Vec2{off(rng), off(rng)}, a + Vec2{off(rng), off(rng)}});
        }
        std::printf("\nmilestone 2: %zu triangles tiling a disc, 2,500 small random ones\n", disc.size());
        const long long nd = static_cast<long long>(disc.size());
        auto ref_fill = [](const std::vector<std::array<Vec2, 3>>& tris) {
            return [&tris](Image& img) { for (const auto& v : tris) m2::reference::fill_triangle(img, v[0], v[1], v[2], raster::colors::white); };
        };
        auto naive_fill = [](const std::vector<std::array<Vec2, 3>>& tris) {
            return [&tris](Image& img) { for (const auto& v : tris) naive_triangle(img, v[0], v[1], v[2], raster::colors::white); };
        };
        m2_rows.push_back(compare("fill_triangle, disc of small triangles", nd, "triangle", ref_fill(disc), naive_fill(disc), rounds));
        m2_rows.push_back(compare("fill_triangle, small random triangles", 2500, "triangle", ref_fill(small), naive_fill(small), rounds));
        for (int n : {2, 4}) {
            char what[96];
            std::snprintf(what, sizeof what, "fill_triangle_aa, %d samples, disc", n * n);
            m2_rows.push_back(compare(
                what, nd, "triangle",
                [&](Image& img) { for (const auto& v : disc) m2::reference::fill_triangle_aa(img, v[0], v[1], v[2], {255, 200, 80}, n); },
                [&](Image& img) { for (const auto& v : disc) naive_triangle_aa(img, v[0], v[1], v[2], {255, 200, 80}, n); },
                rounds));
        }
    }
    bool all = true;
    for (const auto* rows : {&m1_rows, &m2_rows}) {
        for (const Comparison& c : *rows) all &= c.items == 0 || c.ratio >= 2;
    }
    std::printf("\n%s\n\n", all ? "Every reference is at least 2x its naive method." : "NOT every reference is at least 2x its naive method.");
    int rc = 0;
    // Each build writes its own table (markers m1-bench-<build type>), so a lesson shows the
    // default build and a Release build side by side.
    const std::string build = RASTER_BUILD_TYPE;
    if (!lesson1.empty() && !write_between_markers(lesson1, "m1-bench-" + build, table_of(m1_rows))) rc = 1;
    if (!lesson2.empty() && !write_between_markers(lesson2, "m2-bench-" + build, table_of(m2_rows))) rc = 1;
    if (std::getenv("BENCH_COMPARE_ONLY")) return rc;

    // ---- part 2: the reference alone ----

    // ---- milestone 1 ----
    const auto inside = random_segments(20000, 0, kSize, 1);
    // The same lines, stretched a million times beyond their ends: the visible parts are
    // longer, but the invisible billions of pixels must cost nothing.
    std::vector<Segment> huge;  // filled below; const from then on
    for (const Segment& s : inside) {
        const Vec2 d = s.b - s.a;
        huge.push_back({s.a - d * 1e6, s.b + d * 1e6});
    }
    const std::vector<Segment>& huge_lines = huge;
    for (const auto& [name, lines] : {std::pair{"m1 draw_line: 20000 lines inside the image", &inside},
                                      std::pair{"m1 draw_line: the same lines reaching 1e9 pixels away", &huge_lines}}) {
        Image img(kSize, kSize);
        const double t = cp::time_best_of([&] {
            img.fill(raster::colors::black);
            for (const Segment& s : *lines) m1::reference::draw_line(img, s.a, s.b, raster::colors::white);
        });
        report(name, t, 20000, "line");
        std::printf("%-58s %9lld lit pixels, %lld stray writes\n", "", lit_pixels(img), img.stray_writes());
    }
    {
        Image img(kSize, kSize);
        const double t = cp::time_best_of([&] {
            img.fill(raster::colors::black);
            for (const Segment& s : inside) m1::reference::draw_line_aa(img, s.a, s.b, raster::colors::white);
        });
        report("m1 draw_line_aa: 20000 lines inside the image", t, 20000, "line");
    }

    // ---- milestone 2 ----
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> pos(0, kSize), off(-15, 15);
    std::vector<std::array<Vec2, 3>> small;
    for (int i = 0; i < 20000; ++i) {
        const Vec2 a{pos(rng), pos(rng)};
        small.push_back({a, a + Vec2{off(rng), off(rng)}, a + Vec2{off(rng), off(rng)}});
    }
    for (int n : {1, 2, 4, 8}) {
        Image img(kSize, kSize);
        const double t = cp::time_best_of([&] {
            img.fill(raster::colors::black);
            for (const auto& v : small) {
                if (n == 1) {
                    m2::reference::fill_triangle(img, v[0], v[1], v[2], raster::colors::white);
                } else {
                    m2::reference::fill_triangle_aa(img, v[0], v[1], v[2], raster::colors::white, n);
                }
            }
        });
        char label[96];
        std::snprintf(label, sizeof label, "m2 %s: 20000 small triangles, %d sample(s)",
                      n == 1 ? "fill_triangle" : "fill_triangle_aa", n * n);
        report(label, t, 20000, "triangle");
    }
    {
        // Two triangles covering the image, one with vertices near it and one with vertices
        // ten million pixels away: the clamped bounding box makes them cost the same.
        const std::array<Vec2, 3> near{{{-1, -1}, {2 * kSize + 1.0, -1}, {-1, 2 * kSize + 1.0}}};
        const std::array<Vec2, 3> far{{{-1e7, -1e7}, {1e7, -1e7}, {-1e7, 1e7}}};
        for (const auto& [name, v] : {std::pair{"m2 fill_triangle: covering the image, vertices nearby", &near},
                                      std::pair{"m2 fill_triangle: covering the image, vertices at 1e7", &far}}) {
            Image img(kSize, kSize);
            const double t = cp::time_best_of(
                [&] { m2::reference::fill_triangle(img, (*v)[0], (*v)[1], (*v)[2], raster::colors::white); });
            report(name, t, static_cast<long long>(kSize) * kSize, "pixel");
        }
    }
    return rc;
}
