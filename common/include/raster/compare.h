// Comparing an image with its expected version.
//
// compare() gives the numbers every checkpoint reports; diff_image() gives the picture a
// student looks at: the expected image dimmed to a third, with every differing pixel painted
// red (brighter red for a larger difference), so the eye goes straight to the mistakes.
#pragma once

#include <vector>

#include "raster/image.h"

namespace raster {

struct ImageMetrics {
    bool same_size = true;
    int max_channel_diff = 0;        // largest |a - b| over all pixels and channels, 0..255
    long long differing_pixels = 0;  // pixels with any channel different
    double differing_share = 0;      // differing_pixels / pixel count, 0..1
    double mean_abs_error = 0;       // mean |a - b| over all channels, in levels 0..255
    double psnr_db = 0;              // peak signal-to-noise ratio; +infinity for identical images
};

// Images of different sizes give same_size = false, every pixel counted as differing and
// max_channel_diff = 255, so no caller can mistake them for a match.
ImageMetrics compare(const Image& actual, const Image& expected);

// Width x height of expected; pixels outside actual (size mismatch) count as differing.
Image diff_image(const Image& actual, const Image& expected);

// A per-pixel yes/no map the same size as an image (row-major), used for tolerance masks.
struct Mask {
    int width = 0, height = 0;
    std::vector<unsigned char> bits;

    Mask() = default;
    Mask(int w, int h) : width(w), height(h), bits(static_cast<std::size_t>(w) * h, 0) {}
    bool get(int x, int y) const {
        return x >= 0 && y >= 0 && x < width && y < height && bits[index(x, y)] != 0;
    }
    void set(int x, int y) {
        if (x >= 0 && y >= 0 && x < width && y < height) bits[index(x, y)] = 1;
    }
    long long count() const {
        long long n = 0;
        for (unsigned char b : bits) n += b;
        return n;
    }

private:
    std::size_t index(int x, int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
               static_cast<std::size_t>(x);
    }
};

}  // namespace raster
