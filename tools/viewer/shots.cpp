// viewer_shots: measures the viewer's screenshots for its tests (viewer_test.sh).
//
//   viewer_shots A.png            prints "size W H drawn N thin T"
//   viewer_shots A.png B.png      the same for A, then "differ D" (pixels that differ, A vs B)
//   viewer_shots --gif A.gif      prints "gif W H frames N delay C moving M drawn D": the size,
//                                 the frame count, the first frame's delay (centiseconds), the
//                                 pixels that differ between the first frame and the one half
//                                 way through, and the first frame's drawn pixels (whole frames:
//                                 the GIF carries no text)
//
// Only the middle of the window is measured, rows h/6 to h - h/8: the text the viewer draws
// at the top and the bottom (with --no-help) stays out of it. A pixel is "drawn" when it is far
// from the viewer's background color; "thin" counts drawn pixels next to a background pixel
// (a wireframe is almost all thin pixels, a shaded model almost none); "differ" counts pixels
// where a channel differs by more than 24 levels.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

#include "raster/gif.h"
#include "raster/image.h"
#include "raster/io.h"

namespace {

constexpr raster::Color kBackground{28, 32, 40};  // app.cpp's

int gap(raster::Color a, raster::Color b) {
    return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

bool drawn(const raster::Image& img, int x, int y) { return gap(img.at(x, y), kBackground) > 24; }

int top(const raster::Image& img) { return img.height() / 6; }
int bottom(const raster::Image& img) { return img.height() - img.height() / 8; }

void measure(const raster::Image& img) {
    long long count = 0, thin = 0;
    for (int y = top(img); y < bottom(img); ++y) {
        for (int x = 0; x < img.width(); ++x) {
            if (!drawn(img, x, y)) continue;
            ++count;
            const bool edge = (x > 0 && !drawn(img, x - 1, y)) || (x + 1 < img.width() && !drawn(img, x + 1, y)) ||
                              !drawn(img, x, y - 1) || !drawn(img, x, y + 1);
            thin += edge;
        }
    }
    std::cout << "size " << img.width() << " " << img.height() << " drawn " << count << " thin " << thin << "\n";
}

void measure_gif(const std::string& path) {
    const raster::GifInfo gif = raster::read_gif(path);
    long long moving = 0, count = 0;
    if (!gif.frames.empty()) {
        const raster::Image& first = gif.frames.front();
        const raster::Image& middle = gif.frames[gif.frames.size() / 2];
        for (int y = 0; y < first.height(); ++y)
            for (int x = 0; x < first.width(); ++x) {
                moving += gap(first.at(x, y), middle.at(x, y)) > 24;
                count += drawn(first, x, y);
            }
    }
    std::cout << "gif " << gif.width << " " << gif.height << " frames " << gif.frames.size() << " delay "
              << (gif.delays.empty() ? 0 : gif.delays.front()) << " moving " << moving << " drawn " << count << "\n";
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2 && argc != 3) {
        std::cerr << "usage: viewer_shots A.png [B.png] | viewer_shots --gif A.gif\n";
        return 2;
    }
    try {
        if (std::string(argv[1]) == "--gif") {
            if (argc != 3) {
                std::cerr << "usage: viewer_shots --gif A.gif\n";
                return 2;
            }
            measure_gif(argv[2]);
            return 0;
        }
        const raster::Image a = raster::read_png(argv[1]);
        measure(a);
        if (argc == 3) {
            const raster::Image b = raster::read_png(argv[2]);
            if (b.width() != a.width() || b.height() != a.height()) {
                std::cout << "differ " << static_cast<long long>(a.width()) * a.height() << "\n";
                return 0;
            }
            long long differ = 0;
            for (int y = top(a); y < bottom(a); ++y)
                for (int x = 0; x < a.width(); ++x) differ += gap(a.at(x, y), b.at(x, y)) > 24;
            std::cout << "differ " << differ << "\n";
        }
    } catch (const std::exception& e) {
        std::cerr << "viewer_shots: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
