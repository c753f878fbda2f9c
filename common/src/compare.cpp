#include "raster/compare.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace raster {

ImageMetrics compare(const Image& actual, const Image& expected) {
    ImageMetrics m;
    const long long pixels = static_cast<long long>(expected.width()) * expected.height();
    if (actual.width() != expected.width() || actual.height() != expected.height()) {
        m.same_size = false;
        m.max_channel_diff = 255;
        m.differing_pixels = pixels;
        m.differing_share = 1;
        m.mean_abs_error = 255;
        m.psnr_db = 0;
        return m;
    }
    const std::uint8_t* a = actual.data();
    const std::uint8_t* e = expected.data();
    double sum_abs = 0, sum_sq = 0;
    for (long long p = 0; p < pixels; ++p) {
        bool differs = false;
        for (int c = 0; c < 3; ++c) {
            const int d = std::abs(int(a[3 * p + c]) - int(e[3 * p + c]));
            differs |= d != 0;
            m.max_channel_diff = std::max(m.max_channel_diff, d);
            sum_abs += d;
            sum_sq += double(d) * d;
        }
        m.differing_pixels += differs;
    }
    const double samples = 3.0 * double(pixels);
    m.differing_share = pixels ? double(m.differing_pixels) / double(pixels) : 0;
    m.mean_abs_error = samples ? sum_abs / samples : 0;
    const double mse = samples ? sum_sq / samples : 0;
    m.psnr_db = mse > 0 ? 10 * std::log10(255.0 * 255.0 / mse)
                        : std::numeric_limits<double>::infinity();
    return m;
}

Image diff_image(const Image& actual, const Image& expected) {
    Image out(expected.width(), expected.height());
    for (int y = 0; y < expected.height(); ++y) {
        for (int x = 0; x < expected.width(); ++x) {
            const Color e = expected.at(x, y);
            int d = 255;
            if (actual.in_bounds(x, y)) {
                const Color a = actual.at(x, y);
                d = std::max({std::abs(a.r - e.r), std::abs(a.g - e.g), std::abs(a.b - e.b)});
            }
            if (d == 0) {
                out.set(x, y, {std::uint8_t(e.r / 3), std::uint8_t(e.g / 3), std::uint8_t(e.b / 3)});
            } else {
                // Even a one-level difference must be visible: start at 128 red.
                out.set(x, y, {std::uint8_t(128 + d / 2), 0, 0});
            }
        }
    }
    return out;
}

}  // namespace raster
