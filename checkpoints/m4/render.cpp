// Render half: turns a scene into calls to the milestone-4 functions. Everything here runs
// the code under test, so nothing here decides a verdict. Value keys are read by judge.cpp.
// The matrices come from milestone 3 (the reference, in the checkpoint programs).
#include "m4/render.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "depth_lighting.h"
#include "m4/scenes.h"
#include "variant_random.h"

namespace m4cp {
namespace RASTER_FLAVOUR {

namespace {

using m3::Mat4;
using Values = std::map<std::string, double>;

// Every call into the code under test goes through cp::traced: CALL("name", expression).
cp::Artifacts* g_out = nullptr;
#define CALL(name, ...) cp::traced(*g_out, name, [&] { return __VA_ARGS__; })

void put(Values& v, const std::string& key, Vec3 p) {
    v[key + ".x"] = p.x;
    v[key + ".y"] = p.y;
    v[key + ".z"] = p.z;
}
void put(Values& v, const std::string& key, Color c) {
    v[key + ".r"] = c.r;
    v[key + ".g"] = c.g;
    v[key + ".b"] = c.b;
}
void put(Values& v, const std::string& key, const Mat4& m) {
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) v[key + "." + std::to_string(i) + std::to_string(j)] = m.m[i][j];
    }
}

m4::Lighting to_lighting(Vec3 ambient, const std::vector<LightSpec>& lights) {
    m4::Lighting l;
    l.ambient = ambient;
    for (const LightSpec& s : lights) {
        l.lights.push_back({s.point ? m4::Light::Kind::kPoint : m4::Light::Kind::kDirectional, s.vector, s.intensity});
    }
    return l;
}

m4::Mesh to_mesh(const Mesh& m) { return {m.positions, m.triangles, m.face_colors, m.vertex_colors, m.uvs, m.normals}; }

Mat4 model_matrix(const Item& it) {
    return m3::translate(it.position) * m3::rotate(it.axis, it.angle) * m3::scale(it.size);
}

void numbers(Group g, Values& v) {
    switch (g) {
        case Group::kDepthKeys: {
            const auto cases = key_cases();
            for (std::size_t i = 0; i < cases.size(); ++i) {
                const auto& c = cases[i];
                v["key" + std::to_string(i)] =
                    CALL("depth_key", m4::depth_key(static_cast<m4::DepthFormat>(c.format), c.z_ndc, c.w));
            }
            break;
        }
        case Group::kDepthTest: {
            const Color dark{10, 200, 30}, bright{11, 0, 0}, same{10, 200, 30};
            struct Case {
                std::uint32_t key;
                Color c;
                std::uint32_t stored;
                Color t;
            };
            const Case cases[] = {
                {5, dark, 6, bright},       {6, bright, 5, dark},          {5, bright, 5, dark},
                {5, dark, 5, bright},       {5, same, 5, dark},            {m4::kClearKey, bright, m4::kClearKey, dark},
                {0, dark, m4::kClearKey, bright}, {m4::kClearKey - 1, dark, m4::kClearKey, bright},
                {7, {10, 201, 0}, 7, dark}, {7, {10, 200, 31}, 7, dark},   {7, {10, 199, 255}, 7, dark},
            };
            int i = 0;
            for (const Case& c : cases) v["pass" + std::to_string(i++)] = CALL("depth_passes", m4::depth_passes(c.key, c.c, c.stored, c.t));
            break;
        }
        case Group::kClearFrame: {
            m4::Frame frame;
            frame.color = cp::guarded_image(7, 5);
            frame.depth.assign(3, 42);
            cp::traced(*g_out, "clear_frame", frame.color, [&] { m4::clear_frame(frame, {9, 8, 7}, true, m4::DepthFormat::kFixed24); });
            v["depth.size"] = double(frame.depth.size());
            long long not_clear = 0;
            for (std::uint32_t k : frame.depth) not_clear += k != m4::kClearKey;
            v["depth.not_clear"] = double(not_clear);
            v["format"] = double(static_cast<int>(frame.format));
            long long wrong_color = 0;
            for (int y = 0; y < frame.color.height(); ++y) {
                for (int x = 0; x < frame.color.width(); ++x) wrong_color += !(frame.color.at(x, y) == Color{9, 8, 7});
            }
            v["color.wrong"] = double(wrong_color);
            v["color.width"] = frame.color.width();
            if (frame.depth.size() > 4) frame.depth[4] = 3;  // (a student's buffer may be too small)
            cp::traced(*g_out, "clear_frame", frame.color, [&] { m4::clear_frame(frame, {1, 2, 3}, true, m4::DepthFormat::kFloatZ); });
            v["again.key4"] = frame.depth.size() > 4 ? double(frame.depth[4]) : -1;
            cp::traced(*g_out, "clear_frame", frame.color, [&] { m4::clear_frame(frame, {1, 2, 3}, false, m4::DepthFormat::kFloatZ); });
            v["off.capacity"] = double(frame.depth.capacity());
            g_out->stray_writes += frame.color.stray_writes();
            break;
        }
        case Group::kWeights: {
            const auto cases = weight_cases();
            for (std::size_t i = 0; i < cases.size(); ++i) {
                const auto p = CALL("perspective_weights", m4::perspective_weights(cases[i].screen, cases[i].w));
                for (int k = 0; k < 3; ++k) v["w" + std::to_string(i) + "." + std::to_string(k)] = p[k];
            }
            break;
        }
        case Group::kNormals: {
            put(v, "face", CALL("face_normal", m4::face_normal({0, 0, 0}, {2, 0, 0}, {0, 3, 0})));
            put(v, "face_tilted", CALL("face_normal", m4::face_normal({1, 0, 0}, {0, 1, 0}, {0, 0, 1})));
            put(v, "face_cw", CALL("face_normal", m4::face_normal({0, 0, 0}, {0, 3, 0}, {2, 0, 0})));
            put(v, "face_degenerate", CALL("face_normal", m4::face_normal({1, 1, 1}, {2, 2, 2}, {3, 3, 3})));
            // A big triangle facing +z and a small one facing +x share vertex 0: area weighting
            // tilts its normal mostly toward +z.
            const std::vector<Vec3> pos = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, -1}, {0, 1, 0}, {7, 7, 7}};
            const std::vector<std::array<int, 3>> tris = {{0, 1, 2}, {0, 3, 4}, {1, 9, 2}};
            const auto vn = CALL("vertex_normals", m4::vertex_normals(pos, tris));
            v["vn.size"] = double(vn.size());
            for (std::size_t i = 0; i < vn.size() && i < 6; ++i) put(v, "vn" + std::to_string(i), vn[i]);
            put(v, "nm", CALL("normal_matrix", m4::normal_matrix(m3::translate({5, 6, 7}) * m3::scale({2, 0.5, 1}) * m3::rotate_z(0.3))));
            put(v, "nm_singular", CALL("normal_matrix", m4::normal_matrix(m3::scale({1, 0, 1}))));
            break;
        }
        case Group::kLambert: {
            const auto cases = lambert_cases();
            for (std::size_t i = 0; i < cases.size(); ++i) {
                const auto& c = cases[i];
                const Vec3 levels = CALL("shade", m4::shade(to_lighting(c.ambient, c.lights), c.base, c.position, c.normal));
                put(v, "shade" + std::to_string(i), levels);
            }
            const Vec3 to_colors[] = {{12.4, 12.6, 128.2}, {300, -20, 255.4}, {1e9, -1e9, 254.6}, {std::nan(""), 0.49, 127.7}};
            for (int i = 0; i < 4; ++i) put(v, "color" + std::to_string(i), CALL("to_color", m4::to_color(to_colors[i])));
            break;
        }
        case Group::kDebugColors: {
            const double zs[] = {-1, 1, 0.1, 0.5, -3, 2};
            for (int i = 0; i < 6; ++i) put(v, "gray" + std::to_string(i), CALL("depth_gray", m4::depth_gray(zs[i])));
            const Vec3 ns[] = {{0, 0, 1}, {1, 0, 0}, {0, -2, 0}, {1, 1, 1}, {0, 0, 0}, {1e200, -1e200, 0},
                               {std::numeric_limits<double>::infinity(), 0, 0}};
            for (int i = 0; i < 7; ++i) put(v, "ncolor" + std::to_string(i), CALL("normal_color", m4::normal_color(ns[i])));
            break;
        }
        case Group::kClip: {
            const auto cases = clip_cases();
            for (std::size_t i = 0; i < cases.size(); ++i) {
                std::array<m4::ClipVertex, 3> tri;
                for (int k = 0; k < 3; ++k) {
                    tri[k].clip = cases[i].clip[k];
                    tri[k].color = cases[i].color[k];
                    tri[k].uv = cases[i].uv[k];
                    tri[k].normal = {double(k), 1, -double(k)};
                    tri[k].world = cases[i].color[k] / 100;
                }
                const auto poly = CALL("clip_triangle", m4::clip_triangle(tri));
                const std::string key = "clip" + std::to_string(i);
                v[key + ".n"] = double(poly.size());
                for (std::size_t j = 0; j < poly.size() && j < 16; ++j) {
                    const std::string k = key + "." + std::to_string(j);
                    v[k + ".cx"] = poly[j].clip.x;
                    v[k + ".cy"] = poly[j].clip.y;
                    v[k + ".cz"] = poly[j].clip.z;
                    v[k + ".cw"] = poly[j].clip.w;
                    put(v, k + ".color", poly[j].color);
                    put(v, k + ".normal", poly[j].normal);
                    put(v, k + ".world", poly[j].world);
                    v[k + ".u"] = poly[j].uv.x;
                    v[k + ".v"] = poly[j].uv.y;
                }
            }
            break;
        }
    }
}

// Under a scene variant (grading), the number checkpoints whose public inputs stay fixed also
// call their functions on inputs drawn from the seed, stored as "probe.<topic>.<name>"; the judge
// compares each with the reference's result on the same inputs, so answers learned for the
// public inputs do not pass.
void probes(Group g, Values& v) {
    cp::VariantRng rng(variant_seed(), "m4.probes");
    auto real = [&rng](int lo, int hi, double scale) { return rng.uniform(lo, hi) / scale; };
    auto color = [&rng] {
        return Color{static_cast<std::uint8_t>(rng.uniform(0, 255)), static_cast<std::uint8_t>(rng.uniform(0, 255)),
                     static_cast<std::uint8_t>(rng.uniform(0, 255))};
    };
    switch (g) {
        case Group::kDepthTest:
            for (int i = 0; i < 12; ++i) {
                // Keys close together (ties are common), colors that often share channels.
                const std::uint32_t a = std::uint32_t(rng.uniform(0, 3)), b = std::uint32_t(rng.uniform(0, 3));
                Color c = color(), t = color();
                if (rng.coin()) t.r = c.r;
                if (rng.coin()) t.g = c.g;
                v["probe.depth_test.case" + std::to_string(i)] = CALL("depth_passes", m4::depth_passes(a, c, b, t));
            }
            break;
        case Group::kWeights:
            for (int i = 0; i < 6; ++i) {
                const double l0 = real(0, 1000, 1000), l1 = real(0, 1000, 1000) * (1 - l0);
                const std::array<double, 3> l = {l0, l1, 1 - l0 - l1};
                const std::array<double, 3> w = {real(10, 50000, 1000), real(10, 50000, 1000), real(10, 50000, 1000)};
                const auto p = CALL("perspective_weights", m4::perspective_weights(l, w));
                for (int k = 0; k < 3; ++k) v["probe.perspective.w" + std::to_string(i) + "." + std::to_string(k)] = p[k];
            }
            break;
        case Group::kNormals: {
            auto point = [&] { return Vec3{real(-300, 300, 100), real(-300, 300, 100), real(-300, 300, 100)}; };
            for (int i = 0; i < 4; ++i) {
                put(v, "probe.normals.face" + std::to_string(i), CALL("face_normal", m4::face_normal(point(), point(), point())));
            }
            std::vector<Vec3> pos;
            for (int i = 0; i < 5; ++i) pos.push_back(point());
            const std::vector<std::array<int, 3>> tris = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {1, 4, 2}};
            const auto vn = CALL("vertex_normals", m4::vertex_normals(pos, tris));
            for (std::size_t i = 0; i < vn.size() && i < 5; ++i) put(v, "probe.normals.vertex" + std::to_string(i), vn[i]);
            const Mat4 model = m3::translate(point()) * m3::rotate(point(), real(-300, 300, 100)) *
                               m3::scale({real(20, 300, 100), real(20, 300, 100), real(20, 300, 100)});
            put(v, "probe.normal_matrix.nm", CALL("normal_matrix", m4::normal_matrix(model)));
            break;
        }
        case Group::kDebugColors:
            for (int i = 0; i < 6; ++i) {
                put(v, "probe.debug_view.gray" + std::to_string(i), CALL("depth_gray", m4::depth_gray(real(-1200, 1200, 1000))));
                const Vec3 n{real(-100, 100, 37), real(-100, 100, 37), real(-100, 100, 37)};
                put(v, "probe.debug_view.normal" + std::to_string(i), CALL("normal_color", m4::normal_color(n)));
            }
            break;
        default:
            break;  // their public inputs already vary (scenes.cpp), or there is nothing to vary
    }
}

void add_stats(m4::Stats& total, const m4::Stats& st) {
    total.triangles_clipped += st.triangles_clipped;
    total.triangles_culled += st.triangles_culled;
    total.triangles_drawn += st.triangles_drawn;
    total.fragments += st.fragments;
    total.depth_tests += st.depth_tests;
    total.depth_writes += st.depth_writes;
    total.vertex_normals += st.vertex_normals;
    total.shade_calls += st.shade_calls;
    total.interpolated += st.interpolated;
}

void draw_panels(const Scene& s, raster::Image& img, cp::Artifacts& out) {
    for (std::size_t p = 0; p < s.panels.size(); ++p) {
        const Panel& panel = s.panels[p];
        const Camera& c = panel.camera;
        const double aspect = double(panel.w) / panel.h;
        const Mat4 view = m3::look_at(c.eye, c.target, c.up);
        const Mat4 proj = c.ortho ? m3::orthographic(-c.half_height * aspect, c.half_height * aspect, -c.half_height,
                                                     c.half_height, c.near, c.far)
                                  : m3::perspective(c.fovy, aspect, c.near, c.far);
        m4::Needs needs;
        needs.depth_test = panel.depth_test;
        needs.depth_format = static_cast<m4::DepthFormat>(panel.format);
        needs.shading = static_cast<m4::Shading>(panel.shading);
        needs.perspective_correct = panel.perspective_correct;
        needs.cull = panel.cull;
        const m4::Lighting lighting = to_lighting(panel.ambient, panel.lights);
        std::vector<std::vector<int>> frames = panel.frames;
        if (frames.empty()) {
            frames.emplace_back();
            for (std::size_t i = 0; i < panel.items.size(); ++i) frames[0].push_back(static_cast<int>(i));
        }
        std::vector<m4::Mesh> meshes;
        std::vector<Mat4> models;
        for (const Item& it : panel.items) {
            meshes.push_back(to_mesh(it.mesh));
            models.push_back(model_matrix(it));
        }

        m4::Frame frame;
        frame.color = cp::guarded_image(panel.w, panel.h);
        m4::Stats total;
        auto draw = [&] {
            total = {};
            if (!panel.screen_tris.empty()) {
                // fill_triangle alone: the frame is cleared here (as clear_frame would) and the
                // triangles come ready-made, so this picture depends on TODO 8 and what it calls.
                frame.color.fill(panel.background);
                frame.format = needs.depth_format;
                frame.depth.assign(needs.depth_test ? std::size_t(panel.w) * std::size_t(panel.h) : 0, m4::kClearKey);
                m4::FillState state;
                state.needs = needs;
                state.lighting = &lighting;
                for (const ScreenTri& t : panel.screen_tris) {
                    std::array<m4::ScreenVertex, 3> sv;
                    for (int k = 0; k < 3; ++k) sv[std::size_t(k)] = {t.screen[std::size_t(k)], t.w[std::size_t(k)], t.color[std::size_t(k)], {}, {}, {}};
                    cp::traced(*g_out, "fill_triangle", frame.color, [&] { m4::fill_triangle(frame, sv, state, total); });
                }
                return;
            }
            for (const auto& items : frames) {
                cp::traced(*g_out, "clear_frame", frame.color,
                           [&] { m4::clear_frame(frame, panel.background, needs.depth_test, needs.depth_format); });
                for (int i : items) {
                    const Item& it = panel.items[std::size_t(i)];
                    const m4::Stats st = cp::traced(*g_out, "draw_mesh", frame.color, [&] {
                        return m4::draw_mesh(frame, meshes[std::size_t(i)], models[std::size_t(i)], view, proj,
                                             lighting, it.material, needs);
                    });
                    add_stats(total, st);
                }
            }
        };
        const std::string key = "panel" + std::to_string(p);
        out.values[key + ".seconds"] = cp::seconds_of(draw, panel.timed);
        // Read by the render half itself, not reported by the code under test.
        out.values[key + ".depth_capacity"] = double(frame.depth.capacity());
        for (std::size_t k = 0; k < panel.depth_probes.size(); ++k) {
            const auto [x, y] = panel.depth_probes[k];
            const std::size_t at = std::size_t(y) * std::size_t(panel.w) + std::size_t(x);
            out.values[key + ".probe" + std::to_string(k)] = at < frame.depth.size() ? double(frame.depth[at]) : -1;
            // Where a buffer indexed column by column (x * height + y) keeps this pixel's key.
            const std::size_t column = std::size_t(x) * std::size_t(panel.h) + std::size_t(y);
            out.values[key + ".probe" + std::to_string(k) + ".column"] =
                column < frame.depth.size() ? double(frame.depth[column]) : -1;
        }
        out.values[key + ".stats.triangles_clipped"] = double(total.triangles_clipped);
        out.values[key + ".stats.triangles_culled"] = double(total.triangles_culled);
        out.values[key + ".stats.triangles_drawn"] = double(total.triangles_drawn);
        out.values[key + ".stats.fragments"] = double(total.fragments);
        out.values[key + ".stats.depth_tests"] = double(total.depth_tests);
        out.values[key + ".stats.depth_writes"] = double(total.depth_writes);
        out.values[key + ".stats.vertex_normals"] = double(total.vertex_normals);
        out.values[key + ".stats.shade_calls"] = double(total.shade_calls);
        out.values[key + ".stats.interpolated"] = double(total.interpolated);
        cp::place_panel(out, key, frame.color, img, panel.x0, panel.y0, panel.w, panel.h);
    }
}

}  // namespace

cp::Artifacts render(const std::string& id) { return render_scene(scene(id)); }

cp::Artifacts render_scene(const Scene& s) {
    return cp::render_guarded(s.width, s.height, [&](raster::Image& img, cp::Artifacts& out) {
        g_out = &out;
        for (Group g : s.groups) {
            numbers(g, out.values);
            if (variant_seed() != 0) probes(g, out.values);
        }
        // The functions the picture is drawn with, each on its own checkpoint's inputs: the
        // judge checks them before it judges the picture (scenes.h, prerequisite_groups).
        for (Group g : prerequisite_groups(s)) cp::record_under(out, prerequisite_key(g), [&](Values& v) { numbers(g, v); });
        // fill_triangle on m4.fill_triangle's and m4.shared_edges' own triangles, for a scene
        // drawn through draw_mesh: when the picture differs, the judge tells a wrong
        // fill_triangle (TODO 8) from a wrong draw_mesh (TODO 9) by these, not by the scene's theme.
        const bool pipeline = std::any_of(s.panels.begin(), s.panels.end(), [](const Panel& p) { return p.screen_tris.empty(); });
        if (pipeline) {
            for (const auto& [id, fill_key] : {std::pair{kFillScene, kFillKey}, std::pair{kFillRuleScene, kFillRuleKey}}) {
                const Scene& fill = scene(id);
                cp::record_fill_scene(out, fill_key, fill.width, fill.height, [&](raster::Image& fill_img, cp::Artifacts& scratch) {
                    g_out = &scratch;
                    draw_panels(fill, fill_img, scratch);
                    g_out = &out;
                });
            }
        }
        if (!s.panels.empty()) draw_panels(s, img, out);
    });
}

#undef CALL

}  // namespace RASTER_FLAVOUR
}  // namespace m4cp
