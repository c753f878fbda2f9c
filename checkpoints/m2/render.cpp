// Render half: turns a scene into calls to the milestone-2 functions. Everything here runs
// the code under test, so nothing here decides a verdict.
#include "m2/render.h"

#include <cmath>
#include <cstdint>

#include "m2/scenes.h"
#include "triangles.h"

namespace m2cp {
namespace RASTER_FLAVOUR {

namespace {

// flip: list the vertices in the other order (v0, v2, v1), which reverses the winding.
// Every call into the code under test goes through cp::traced, which counts its calls and
// the pixels it writes, per function (see harness/checkpoint.h).
void draw(cp::Artifacts& out, raster::Image& img, const Tri& t, bool flip, bool white) {
    const int i1 = flip ? 2 : 1, i2 = flip ? 1 : 2;
    const Color c0 = white ? raster::colors::white : t.c[0];
    if (t.aa > 0) {
        cp::traced(out, "fill_triangle_aa", img,
                   [&] { m2::fill_triangle_aa(img, t.v[0], t.v[i1], t.v[i2], c0, t.aa); });
    } else if (t.gradient && !white) {
        cp::traced(out, "fill_triangle_gradient", img, [&] {
            m2::fill_triangle_gradient(img, t.v[0], t.v[i1], t.v[i2], t.c[0], t.c[i1], t.c[i2]);
        });
    } else {
        cp::traced(out, "fill_triangle", img, [&] { m2::fill_triangle(img, t.v[0], t.v[i1], t.v[i2], c0); });
    }
}

// The render half's own snapping, so that edge() and bounding_box() are tested on their own.
m2::Fixed fixed(Vec2 p) { return {std::llround(p.x * m2::kSubpixelSteps), std::llround(p.y * m2::kSubpixelSteps)}; }

void draw_scene(const Scene& s, raster::Image& img, cp::Artifacts& out) {
    // The numbers first: they cannot run away, and a picture stopped by a runaway loop then
    // leaves them computed (the judge would otherwise read values never written).
    for (std::size_t i = 0; i < s.numbers.snaps.size(); ++i) {
        m2::Fixed f{-1, -1};
        const bool ok = cp::traced(out, "snap", [&] { return m2::snap(s.numbers.snaps[i], f); });
        const std::string key = "snap." + std::to_string(i) + ".";
        out.values[key + "ok"] = ok;
        out.values[key + "x"] = double(f.x);
        out.values[key + "y"] = double(f.y);
    }
    for (std::size_t i = 0; i < s.numbers.boxes.size(); ++i) {
        const auto& v = s.numbers.boxes[i];
        const m2::Fixed a = fixed(v[0]), b = fixed(v[1]), c = fixed(v[2]);
        const m2::PixelRect r =
            cp::traced(out, "bounding_box", [&] { return m2::bounding_box(a, b, c, s.width, s.height); });
        const std::string key = "box." + std::to_string(i) + ".";
        out.values[key + "x0"] = r.x0;
        out.values[key + "y0"] = r.y0;
        out.values[key + "x1"] = r.x1;
        out.values[key + "y1"] = r.y1;
        const std::int64_t e = cp::traced(out, "edge", [&] { return m2::edge(a, b, c); });
        out.values["edge." + std::to_string(i)] = double(e);
        // Its last 16 bits too: a double holds 53 bits, and an edge near 1e7 needs 57.
        out.values["edge." + std::to_string(i) + ".low"] = double(static_cast<std::uint64_t>(e) & 0xFFFF);
    }
    for (const Tri& t : s.tris) draw(out, img, t, false, false);
    if (s.check_winding) {
        raster::Image& other = out.images["other_winding"] = cp::guarded_image(s.width, s.height);
        for (const Tri& t : s.tris) draw(out, other, t, true, false);
    }
    if (s.watertight) {
        // How many triangles cover each pixel: each is drawn alone in white, then counted.
        // Encoding: 0 black, 1 gray (110, 110, 110), n >= 2 red (255, 40, n).
        raster::Image& count = out.images["count"] = raster::Image(s.width, s.height);
        for (const Tri& t : s.tris) {
            raster::Image alone = cp::guarded_image(s.width, s.height);
            draw(out, alone, t, false, true);
            out.stray_writes += alone.stray_writes();
            for (int y = 0; y < s.height; ++y) {
                for (int x = 0; x < s.width; ++x) {
                    if (alone.at(x, y) != raster::colors::black) {
                        const Color c = count.at(x, y);
                        const int n = c == raster::colors::black ? 1 : c.r == 255 ? c.b + 1 : 2;
                        count.set(x, y, n == 1 ? Color{110, 110, 110} : Color{255, 40, static_cast<std::uint8_t>(n)});
                    }
                }
            }
        }
    }
}

}  // namespace

cp::Artifacts render(const std::string& id) {
    const Scene& s = scene(id);
    return cp::render_guarded(s.width, s.height, [&](raster::Image& img, cp::Artifacts& out) { draw_scene(s, img, out); });
}

}  // namespace RASTER_FLAVOUR
}  // namespace m2cp
