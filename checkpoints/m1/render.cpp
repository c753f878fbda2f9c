// Render half: turns a scene into calls to the milestone-1 functions. Everything here runs
// the code under test, so nothing here decides a verdict.
#include "m1/render.h"

#include <algorithm>

#include "lines.h"
#include "m1/scenes.h"

namespace m1cp {
namespace RASTER_FLAVOUR {

namespace {

m1::Rect to_rect(const Box& b) { return {b.xmin, b.ymin, b.xmax, b.ymax}; }

// Every call into the code under test goes through cp::traced, which counts its calls and
// the pixels it writes, per function (see harness/checkpoint.h).
void line(cp::Artifacts& out, raster::Image& img, Vec2 a, Vec2 b, Color c) {
    cp::traced(out, "draw_line", img, [&] { m1::draw_line(img, a, b, c); });
}

void draw(cp::Artifacts& out, raster::Image& img, const Segment& s, bool reversed) {
    const Vec2 a = reversed ? s.b : s.a;
    const Vec2 b = reversed ? s.a : s.b;
    if (s.aa) {
        cp::traced(out, "draw_line_aa", img, [&] { m1::draw_line_aa(img, a, b, s.color); });
    } else {
        line(out, img, a, b, s.color);
    }
}

// The code under test's outcodes of points on the rectangle's border (see border_probes).
void probe_border(cp::Artifacts& out, const std::string& prefix, const Box& box) {
    const m1::Rect r = to_rect(box);
    const std::vector<Vec2> probes = border_probes(box);
    for (std::size_t k = 0; k < probes.size(); ++k) {
        out.values[prefix + std::to_string(k)] = cp::traced(out, "outcode", [&] { return m1::outcode(probes[k], r); });
    }
}

void draw_scene(const Scene& s, raster::Image& img, cp::Artifacts& out) {
    // draw_line clips every line to the rectangle of pixel centers (only scenes that use it ask:
    // a scene of Wu lines alone needs no outcode).
    if (std::any_of(s.lines.begin(), s.lines.end(), [](const Segment& g) { return !g.aa; })) {
        probe_border(out, "border_outcode.", pixel_center_box(s.width, s.height));
    }
    switch (s.kind) {
        case Kind::kLines:
            for (const Segment& seg : s.lines) draw(out, img, seg, false);
            if (s.check_reversed) {
                raster::Image& rev = out.images["reversed"] = cp::guarded_image(s.width, s.height);
                for (const Segment& seg : s.lines) draw(out, rev, seg, true);
            }
            if (s.clip_nonfinite) {
                const m1::Rect r{0.5, 0.5, s.width - 0.5, s.height - 0.5};
                for (std::size_t i = 0; i < s.lines.size(); ++i) {
                    const Segment& seg = s.lines[i];
                    if (seg.aa || (raster::is_finite(seg.a) && raster::is_finite(seg.b))) continue;
                    Vec2 a = seg.a, b = seg.b;
                    const bool kept = cp::traced(out, "clip_line", [&] { return m1::clip_line(a, b, r); });
                    out.values["nonfinite_clip." + std::to_string(i)] = kept;
                }
            }
            break;
        case Kind::kOutcodes: {
            const m1::Rect r = to_rect(s.viewport);
            for (int y = 0; y < s.height; ++y) {
                for (int x = 0; x < s.width; ++x) {
                    const int code = cp::traced(out, "outcode", [&] { return m1::outcode({x + 0.5, y + 0.5}, r); });
                    img.set(x, y, outcode_color(code));
                }
            }
            break;
        }
        case Kind::kClip: {
            probe_border(out, "viewport_outcode.", s.viewport);
            const m1::Rect r = to_rect(s.viewport);
            for (const Segment& seg : s.lines) line(out, img, seg.a, seg.b, kUnclippedColor);
            const Box& v = s.viewport;
            const Vec2 corners[] = {{v.xmin, v.ymin}, {v.xmax, v.ymin}, {v.xmax, v.ymax}, {v.xmin, v.ymax}};
            for (int k = 0; k < 4; ++k) line(out, img, corners[k], corners[(k + 1) % 4], kViewportColor);
            for (std::size_t i = 0; i < s.lines.size(); ++i) {
                Vec2 a = s.lines[i].a, b = s.lines[i].b;
                const bool kept = cp::traced(out, "clip_line", [&] { return m1::clip_line(a, b, r); });
                const std::string key = "clip." + std::to_string(i) + ".";
                out.values[key + "kept"] = kept;
                out.values[key + "ax"] = a.x;
                out.values[key + "ay"] = a.y;
                out.values[key + "bx"] = b.x;
                out.values[key + "by"] = b.y;
                if (kept) line(out, img, a, b, s.lines[i].color);
            }
            break;
        }
    }
}

}  // namespace

cp::Artifacts render(const std::string& id) {
    const Scene& s = scene(id);
    return cp::render_guarded(s.width, s.height, [&](raster::Image& img, cp::Artifacts& out) { draw_scene(s, img, out); });
}

}  // namespace RASTER_FLAVOUR
}  // namespace m1cp
