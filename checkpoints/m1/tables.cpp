// Measures, for lesson 1: how far each way of drawing a line is from the ideal line one pixel
// wide, and what it costs. The ideal line is the rectangle of width 1 centred on the segment
// from a to b (flat ends at a and b); a pixel's exact intensity is the area of that rectangle
// inside the pixel's square, computed by clipping the rectangle to the square. Each line is
// drawn alone, white on black, so an intensity is a channel / 255. Errors come first, the time
// (machine-dependent) is the last column.
#include "m1/tables.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>
#include <vector>

#include "harness/checkpoint.h"
#include "lines.h"
#include "raster/image.h"

namespace m1cp {

namespace {

using raster::Image;
using raster::Vec2;

constexpr int kSide = 64;    // each line is drawn alone in an image this size
constexpr int kLines = 400;  // random lines, endpoints inside the image

struct Segment {
    Vec2 a, b;
};

// The four corners of the ideal line (counter-clockwise or clockwise, consistently).
std::vector<Vec2> rectangle(const Segment& s) {
    const Vec2 d = s.b - s.a;
    const double len = std::sqrt(d.x * d.x + d.y * d.y);
    const Vec2 n = len > 0 ? Vec2{-d.y / len * 0.5, d.x / len * 0.5} : Vec2{0, 0};
    return {s.a + n, s.b + n, s.b - n, s.a - n};
}

// Sutherland-Hodgman: the polygon clipped to one half-plane (keep where along(p) <= limit).
template <class F>
std::vector<Vec2> clip(const std::vector<Vec2>& poly, F along, double limit) {
    std::vector<Vec2> out;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const Vec2 p = poly[i], q = poly[(i + 1) % poly.size()];
        const double fp = along(p) - limit, fq = along(q) - limit;
        if (fp <= 0) out.push_back(p);
        if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0)) out.push_back(p + (q - p) * (fp / (fp - fq)));
    }
    return out;
}

double area(const std::vector<Vec2>& poly) {
    double a = 0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const Vec2 p = poly[i], q = poly[(i + 1) % poly.size()];
        a += p.x * q.y - q.x * p.y;
    }
    return std::abs(a) / 2;
}

// Exact coverage of every pixel of the image by the ideal line.
std::vector<double> exact(const Segment& s) {
    std::vector<double> cov(kSide * kSide, 0.0);
    const std::vector<Vec2> rect = rectangle(s);
    for (int y = 0; y < kSide; ++y) {
        for (int x = 0; x < kSide; ++x) {
            std::vector<Vec2> p = clip(rect, [](Vec2 v) { return -v.x; }, -double(x));
            p = clip(p, [](Vec2 v) { return v.x; }, x + 1.0);
            p = clip(p, [](Vec2 v) { return -v.y; }, -double(y));
            p = clip(p, [](Vec2 v) { return v.y; }, y + 1.0);
            cov[y * kSide + x] = p.size() >= 3 ? area(p) : 0.0;
        }
    }
    return cov;
}

// Supersampling: the share of an n x n grid of samples per pixel that lie in the rectangle,
// over the pixels the rectangle's box overlaps.
void supersampled(Image& img, const Segment& s, int n) {
    const Vec2 d = s.b - s.a;
    const double len = std::sqrt(d.x * d.x + d.y * d.y);
    if (!(len > 0)) return;
    const Vec2 u{d.x / len, d.y / len};
    const int x0 = std::max(0, int(std::floor(std::min(s.a.x, s.b.x) - 0.5)));
    const int x1 = std::min(img.width() - 1, int(std::floor(std::max(s.a.x, s.b.x) + 0.5)));
    const int y0 = std::max(0, int(std::floor(std::min(s.a.y, s.b.y) - 0.5)));
    const int y1 = std::min(img.height() - 1, int(std::floor(std::max(s.a.y, s.b.y) + 0.5)));
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            int in = 0;
            for (int j = 0; j < n; ++j) {
                for (int i = 0; i < n; ++i) {
                    const Vec2 p{x + (i + 0.5) / n - s.a.x, y + (j + 0.5) / n - s.a.y};
                    const double along = p.x * u.x + p.y * u.y, across = p.x * u.y - p.y * u.x;
                    in += along >= 0 && along <= len && std::abs(across) <= 0.5;
                }
            }
            if (in > 0) img.blend(x, y, raster::colors::white, double(in) / (n * n));
        }
    }
}

struct Method {
    const char* name;
    void (*draw)(Image&, const Segment&);
};

void bresenham(Image& img, const Segment& s) { m1::reference::draw_line(img, s.a, s.b, raster::colors::white); }
void wu(Image& img, const Segment& s) { m1::reference::draw_line_aa(img, s.a, s.b, raster::colors::white); }
void ss4(Image& img, const Segment& s) { supersampled(img, s, 2); }
void ss16(Image& img, const Segment& s) { supersampled(img, s, 4); }
void ss64(Image& img, const Segment& s) { supersampled(img, s, 8); }

}  // namespace

std::string error_time_table() {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> d(4, kSide - 4);
    std::vector<Segment> lines;
    for (int i = 0; i < kLines; ++i) lines.push_back({{d(rng), d(rng)}, {d(rng), d(rng)}});
    std::vector<std::vector<double>> truth;
    for (const Segment& s : lines) truth.push_back(exact(s));

    const Method methods[] = {{"Bresenham (`draw_line`)", bresenham},
                              {"Xiaolin Wu (`draw_line_aa`)", wu},
                              {"supersampled, 4 samples per pixel", ss4},
                              {"supersampled, 16 samples per pixel", ss16},
                              {"supersampled, 64 samples per pixel", ss64}};
    std::ostringstream out;
    out << "| method | mean intensity error | largest intensity error | time per line (µs) |\n"
        << "|---|---|---|---|\n";
    for (const Method& m : methods) {
        // Error: over the pixels that either the method or the ideal line touches.
        double sum = 0, worst = 0;
        long long counted = 0;
        for (std::size_t k = 0; k < lines.size(); ++k) {
            Image img(kSide, kSide);
            m.draw(img, lines[k]);
            for (int i = 0; i < kSide * kSide; ++i) {
                const double drawn = img.data()[3 * i] / 255.0, ideal = truth[k][i];
                if (drawn == 0 && ideal == 0) continue;
                const double e = std::abs(drawn - ideal);
                sum += e;
                worst = std::max(worst, e);
                ++counted;
            }
        }
        Image img(kSide, kSide);
        const double seconds = cp::time_best_of([&] {
            for (const Segment& s : lines) m.draw(img, s);
        });
        char row[200];
        std::snprintf(row, sizeof row, "| %s | %.3f | %.2f | %.2f |\n", m.name, sum / double(counted), worst,
                      seconds * 1e6 / kLines);
        out << row;
    }
    return out.str();
}

}  // namespace m1cp
