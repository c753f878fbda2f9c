// Milestone 1's harness: outcodes, Cohen-Sutherland clipping and both line drawers, with
// ordinary and extreme endpoints and rectangles (see fuzz_input.h).
#include <cmath>

#include "fuzz_input.h"
#include "lines.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::Input in(data, size);
    fuzz::Guard guard;
    raster::Image img = fuzz::image(in);
    for (int step = 0; step < 8 && !in.empty(); ++step) {
        switch (in.byte() % 5) {
            case 0: {
                const m1::Rect r{in.real(), in.real(), in.real(), in.real()};
                (void)m1::outcode(in.vec2(), r);
                break;
            }
            case 1: {
                const m1::Rect r{in.real(), in.real(), in.real(), in.real()};
                raster::Vec2 a = in.vec2(), b = in.vec2();
                const bool finite = std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(b.x) && std::isfinite(b.y);
                if (m1::clip_line(a, b, r) && !finite) fuzz::broken("m1::clip_line accepted a non-finite end",
                                 "TODO 2 (lines.h): non-finite input returns false; test the ends before any "
                                 "arithmetic with them");
                break;
            }
            case 2: {
                const auto [a, b, c] = std::tuple{in.vec2(), in.vec2(), in.color()};
                m1::draw_line(img, a, b, c);
                break;
            }
            case 3: {
                const auto [a, b, c] = std::tuple{in.vec2(), in.vec2(), in.color()};
                m1::draw_line_aa(img, a, b, c);
                break;
            }
            default: {
                // A segment from inside the image to anywhere: the most common shape that needs
                // clipping on one end only.
                const raster::Vec2 a{in.range(0, img.width() * 16) / 16.0, in.range(0, img.height() * 16) / 16.0};
                const auto [aa, b, c] = std::tuple{in.flag(), in.vec2(), in.color()};
                if (aa) {
                    m1::draw_line_aa(img, b, a, c);
                } else {
                    m1::draw_line(img, a, b, c);
                }
            }
        }
    }
    return 0;
}
