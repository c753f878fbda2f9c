#include "raster/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wconversion"
#endif
#include "stb_easy_font.h"
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace raster {

namespace {

void rect(Image& img, int x0, int y0, int x1, int y1, Color c) {
    for (int y = std::max(0, y0); y < std::min(img.height(), y1); ++y) {
        for (int x = std::max(0, x0); x < std::min(img.width(), x1); ++x) img.set(x, y, c);
    }
}

// A line of the given thickness, by stepping along its longer axis.
void line(Image& img, double x0, double y0, double x1, double y1, Color c, int thick = 1) {
    const double dx = x1 - x0, dy = y1 - y0;
    const int steps = static_cast<int>(std::ceil(std::max(std::abs(dx), std::abs(dy))));
    for (int i = 0; i <= std::max(steps, 0) && steps < 100000; ++i) {
        const double t = steps == 0 ? 0 : double(i) / steps;
        const int x = static_cast<int>(std::lround(x0 + dx * t)), y = static_cast<int>(std::lround(y0 + dy * t));
        rect(img, x - thick / 2, y - thick / 2, x - thick / 2 + thick, y - thick / 2 + thick, c);
    }
}

std::string number(double v) {
    char buf[32];
    if (v != 0 && (std::abs(v) >= 1e5 || std::abs(v) < 1e-3)) {
        std::snprintf(buf, sizeof buf, "%.0e", v);
    } else {
        std::snprintf(buf, sizeof buf, "%g", v);
    }
    return buf;
}

// An axis: the data range mapped to pixels, and its ticks.
struct Axis {
    bool log = false;
    double lo = 0, hi = 1;  // in axis units (log10 of the value on a log axis)
    double unit(double v) const { return log ? std::log10(v) : v; }
    bool usable(double v) const { return std::isfinite(v) && (!log || v > 0); }
    std::vector<double> ticks() const {  // values (not units)
        std::vector<double> out;
        if (log) {
            for (double e = std::ceil(lo - 1e-9); e <= hi + 1e-9 && out.size() < 20; e += 1) out.push_back(std::pow(10, e));
            return out;
        }
        const double span = hi - lo, raw = span / 5;
        const double mag = std::pow(10, std::floor(std::log10(raw)));
        double step = mag;
        for (double m : {1.0, 2.0, 5.0, 10.0}) {
            if (raw <= m * mag) {
                step = m * mag;
                break;
            }
        }
        for (double v = std::ceil(lo / step) * step; v <= hi + step * 1e-9 && out.size() < 20; v += step) {
            out.push_back(std::abs(v) < step * 1e-9 ? 0 : v);
        }
        return out;
    }
};

Axis make_axis(bool log, const std::vector<double>& values) {
    Axis a;
    a.log = log;
    double lo = INFINITY, hi = -INFINITY;
    for (double v : values) {
        if (!a.usable(v)) continue;
        lo = std::min(lo, a.unit(v));
        hi = std::max(hi, a.unit(v));
    }
    if (!(lo <= hi)) {
        lo = 0;
        hi = 1;
    }
    if (log) {
        lo = std::floor(lo);
        hi = std::ceil(hi);
        if (hi <= lo) hi = lo + 1;
    } else {
        const double pad = hi > lo ? (hi - lo) * 0.08 : std::max(1.0, std::abs(hi) * 0.1);
        lo = lo >= 0 && lo - pad < 0 ? 0 : lo - pad;
        hi += pad;
    }
    a.lo = lo;
    a.hi = hi;
    return a;
}

}  // namespace

int text_width(const std::string& text, int scale) {
    std::vector<char> s(text.begin(), text.end());
    s.push_back('\0');
    return stb_easy_font_width(s.data()) * scale;
}

void draw_text(Image& img, int x, int y, const std::string& text, Color color, int scale) {
    std::vector<char> s(text.begin(), text.end());
    s.push_back('\0');
    std::vector<char> buffer(text.size() * 1024 + 256);  // a quad is 64 bytes; "8" takes 7
    const int quads = stb_easy_font_print(0, 0, s.data(), nullptr, buffer.data(), static_cast<int>(buffer.size()));
    // Each quad: four vertices of x, y, z (float) and a color (4 bytes); the quads are axis-aligned.
    for (int q = 0; q < quads; ++q) {
        float lo_x = 1e9f, lo_y = 1e9f, hi_x = -1e9f, hi_y = -1e9f;
        for (int v = 0; v < 4; ++v) {
            float px, py;
            std::memcpy(&px, buffer.data() + (q * 4 + v) * 16, sizeof px);
            std::memcpy(&py, buffer.data() + (q * 4 + v) * 16 + 4, sizeof py);
            lo_x = std::min(lo_x, px);
            lo_y = std::min(lo_y, py);
            hi_x = std::max(hi_x, px);
            hi_y = std::max(hi_y, py);
        }
        rect(img, x + static_cast<int>(lo_x) * scale, y + static_cast<int>(lo_y) * scale, x + static_cast<int>(hi_x) * scale,
             y + static_cast<int>(hi_y) * scale, color);
    }
}

Image plot(const PlotSpec& spec) {
    const Color white{255, 255, 255}, ink{40, 40, 40}, grid{225, 225, 225};
    Image img(std::max(spec.width, 160), std::max(spec.height, 120), white);
    const int left = 64, right = img.width() - 44, top = 46, bottom = img.height() - 46;
    std::vector<double> xs, ys;
    for (const PlotSeries& s : spec.series) {
        for (Vec2 p : s.points) {
            xs.push_back(p.x);
            ys.push_back(p.y);
        }
    }
    const Axis ax = make_axis(spec.log_x, xs), ay = make_axis(spec.log_y, ys);
    auto px = [&](double v) { return left + (ax.unit(v) - ax.lo) / (ax.hi - ax.lo) * (right - left); };
    auto py = [&](double v) { return bottom - (ay.unit(v) - ay.lo) / (ay.hi - ay.lo) * (bottom - top); };

    // Grid, ticks and their labels.
    for (double t : ax.ticks()) {
        const double x = px(t);
        line(img, x, top, x, bottom, grid);
        line(img, x, bottom, x, bottom + 4, ink);
        const std::string label = number(t);
        draw_text(img, static_cast<int>(x) - text_width(label) / 2, bottom + 8, label, ink);
    }
    for (double t : ay.ticks()) {
        const double y = py(t);
        line(img, left, y, right, y, grid);
        line(img, left - 4, y, left, y, ink);
        const std::string label = number(t);
        draw_text(img, left - 8 - text_width(label), static_cast<int>(y) - 3, label, ink);
    }
    line(img, left, top, left, bottom, ink);
    line(img, left, bottom, right, bottom, ink);
    draw_text(img, left, 6, spec.title, ink, 2);
    draw_text(img, (left + right - text_width(spec.x_label)) / 2, bottom + 26, spec.x_label, ink);
    draw_text(img, 4, top - 16, spec.y_label, ink);

    // The series, then the legend.
    for (const PlotSeries& s : spec.series) {
        bool have_prev = false;
        double prev_x = 0, prev_y = 0;
        for (std::size_t i = 0; i < s.points.size(); ++i) {
            const Vec2 p = s.points[i];
            if (!ax.usable(p.x) || !ay.usable(p.y)) continue;
            const double x = px(p.x), y = py(p.y);
            if (have_prev) line(img, prev_x, prev_y, x, y, s.color, 2);
            rect(img, static_cast<int>(x) - 3, static_cast<int>(y) - 3, static_cast<int>(x) + 4, static_cast<int>(y) + 4, s.color);
            if (i < s.labels.size()) draw_text(img, static_cast<int>(x) + 6, static_cast<int>(y) - 10, s.labels[i], s.color);
            have_prev = true;
            prev_x = x;
            prev_y = y;
        }
    }
    int ly = top + 6;
    for (const PlotSeries& s : spec.series) {
        const int width = text_width(s.name) + 24;
        const int lx = right - width - 4;
        rect(img, lx - 4, ly - 3, right - 2, ly + 11, white);
        rect(img, lx, ly + 1, lx + 14, ly + 7, s.color);
        draw_text(img, lx + 18, ly, s.name, ink);
        ly += 14;
    }
    return img;
}

}  // namespace raster
