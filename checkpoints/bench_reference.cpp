// Benchmarks of the reference solutions (`make bench`). Speed is measured here, never in the
// checkpoints. Each figure is the best of several runs, so a busy machine disturbs it little.
//
// What the numbers should show: the work of clipping first is proportional to the visible
// pixels (a line or triangle reaching a billion pixels away costs what its visible part
// costs), and supersampling costs about n * n times the plain fill.
#include <cstdio>
#include <array>
#include <random>
#include <vector>

#include "harness/checkpoint.h"
#include "lines.h"
#include "raster/image.h"
#include "triangles.h"

namespace {

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

}  // namespace

int main() {
    std::printf("Reference solutions, one thread, %dx%d image\n\n", kSize, kSize);

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
    return 0;
}
