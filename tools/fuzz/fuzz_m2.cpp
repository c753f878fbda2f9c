// Milestone 2's harness: snapping, edge functions and boxes on snapped points, and the three
// triangle fills, with ordinary, needle, huge and non-finite vertices (see fuzz_input.h).
#include "fuzz_input.h"
#include "triangles.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::Input in(data, size);
    fuzz::Guard guard;
    raster::Image img = fuzz::image(in);
    static constexpr int kSamples[] = {1, 2, 4, 8, 0, 3, -1, 16};
    for (int step = 0; step < 6 && !in.empty(); ++step) {
        // A vertex: anywhere (real()), or one of the previous ones (shared edges, needles).
        raster::Vec2 v[3];
        for (int i = 0; i < 3; ++i) v[i] = (i > 0 && in.byte() < 40) ? v[in.range(0, i - 1)] : in.vec2();
        switch (in.byte() % 5) {
            case 0: {
                m2::Fixed f[3];
                bool ok = true;
                for (int i = 0; i < 3; ++i) ok = m2::snap(v[i], f[i]) && ok;
                if (!ok) break;  // edge and bounding_box are specified for snapped points only
                (void)m2::edge(f[0], f[1], f[2]);
                const m2::PixelRect r = m2::bounding_box(f[0], f[1], f[2], img.width(), img.height());
                if (r.x0 < r.x1 && r.y0 < r.y1 && (r.x0 < 0 || r.y0 < 0 || r.x1 > img.width() || r.y1 > img.height())) {
                    fuzz::broken("m2::bounding_box is not clamped to the image",
                                 "TODO 3 (triangles.h): the box is clamped to the image and must not overflow for "
                                 "coordinates up to kMaxCoordinate: clamp before narrowing to int");
                }
                break;
            }
            case 1: m2::fill_triangle(img, v[0], v[1], v[2], in.color()); break;
            case 2: {
                const auto [c0, c1, c2] = std::tuple{in.color(), in.color(), in.color()};
                m2::fill_triangle_gradient(img, v[0], v[1], v[2], c0, c1, c2);
                break;
            }
            case 3: {
                // Up to 64 samples a pixel: on an image of at most 16 x 16, so that an input
                // costs milliseconds and the fuzzer tries many (the vertices still reach far
                // outside it).
                const auto [c, n, w, h] = std::tuple{in.color(), kSamples[in.byte() % 8], in.range(1, 16), in.range(1, 16)};
                raster::Image small(w, h);
                small.limit_stray_writes(1000);
                m2::fill_triangle_aa(small, v[0], v[1], v[2], c, n);
                break;
            }
            default: {
                m2::Fixed f;
                (void)m2::snap(v[0], f);
            }
        }
    }
    return 0;
}
