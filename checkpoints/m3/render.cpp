// Render half: turns a scene into calls to the milestone-3 functions. Everything here runs
// the code under test, so nothing here decides a verdict. Value keys are read by judge.cpp.
#include "m3/render.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "m3/scenes.h"
#include "transforms.h"
#include "variant_random.h"

namespace m3cp {
namespace RASTER_FLAVOUR {

namespace {

using m3::Mat4;
using Values = std::map<std::string, double>;

// Every call into the code under test goes through cp::traced (which function ran, what it
// drew, what the watchdog names if it never returns): CALL("name", expression). The products
// are traced as "operator*".
cp::Artifacts* g_out = nullptr;
#define CALL(name, ...) cp::traced(*g_out, name, [&] { return __VA_ARGS__; })
Mat4 mul(const Mat4& a, const Mat4& b) { return CALL("operator*", a * b); }
Vec4 mul(const Mat4& a, Vec4 v) { return CALL("operator*", a * v); }

Mat4 to_mat4(const Matrix& a) {
    Mat4 r;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) r.m[i][j] = a[i][j];
    }
    return r;
}

void put(Values& v, const std::string& key, const Mat4& m) {
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) v[key + "." + std::to_string(i) + std::to_string(j)] = m.m[i][j];
    }
}
void put(Values& v, const std::string& key, Vec3 p) {
    v[key + ".x"] = p.x;
    v[key + ".y"] = p.y;
    v[key + ".z"] = p.z;
}
void put(Values& v, const std::string& key, Vec4 p) {
    v[key + ".x"] = p.x;
    v[key + ".y"] = p.y;
    v[key + ".z"] = p.z;
    v[key + ".w"] = p.w;
}
void put_polygon(Values& v, const std::string& key, const std::vector<Vec4>& poly) {
    v[key + ".n"] = static_cast<double>(poly.size());
    for (std::size_t i = 0; i < poly.size() && i < 32; ++i) put(v, key + "." + std::to_string(i), poly[i]);
}

m3::Model to_model(const Mesh& m) { return {m.positions, m.triangles, m.edges, m.face_colors}; }

void numbers(Group g, Values& v) {
    const double pi = std::numbers::pi;
    switch (g) {
        case Group::kMatrixOps: {
            const Mat4 a = to_mat4({{{1, 2, 0, 4}, {0, 1, 3, 0}, {2, 0, 1, -1}, {0, 0, 0, 1}}});
            const Mat4 b = to_mat4({{{0, 1, 0, 2}, {1, 0, 0, 0}, {0, 0, 2, 1}, {0, 0, 0, 1}}});
            put(v, "ab", mul(a, b));
            put(v, "at", CALL("transpose", m3::transpose(a)));
            put(v, "av", mul(a, Vec4{1, 2, 3, 1}));
            put(v, "pt", CALL("transform_point", m3::transform_point(a, {1, 2, 3})));
            put(v, "dir", CALL("transform_direction", m3::transform_direction(a, {1, 2, 3})));
            break;
        }
        case Group::kBuilders:
            put(v, "translate", CALL("translate", m3::translate({1, -2, 3})));
            put(v, "scale", CALL("scale", m3::scale({2, 3, 4})));
            put(v, "rx", CALL("rotate_x", m3::rotate_x(0.3)));
            put(v, "ry", CALL("rotate_y", m3::rotate_y(0.3)));
            put(v, "rz", CALL("rotate_z", m3::rotate_z(0.3)));
            put(v, "rz90", CALL("transform_point", m3::transform_point(CALL("rotate_z", m3::rotate_z(pi / 2)), {1, 0, 0})));
            put(v, "rx90", CALL("transform_point", m3::transform_point(CALL("rotate_x", m3::rotate_x(pi / 2)), {0, 1, 0})));
            put(v, "ry90", CALL("transform_point", m3::transform_point(CALL("rotate_y", m3::rotate_y(pi / 2)), {0, 0, 1})));
            break;
        case Group::kRodrigues:
            put(v, "r111", CALL("rotate", m3::rotate({1, 1, 1}, 2 * pi / 3)));
            put(v, "rz", CALL("rotate", m3::rotate({0, 0, 2}, 0.7)));
            put(v, "zero", CALL("rotate", m3::rotate({0, 0, 0}, 1.0)));
            put(v, "general", CALL("rotate", m3::rotate({1, -2, 0.5}, 1.3)));
            break;
        case Group::kComposition:
            put(v, "tr", CALL("transform_point", m3::transform_point(mul(CALL("translate", m3::translate({3, 0, 0})), CALL("rotate_z", m3::rotate_z(pi / 2))), {1, 0, 0})));
            put(v, "rt", CALL("transform_point", m3::transform_point(mul(CALL("rotate_z", m3::rotate_z(pi / 2)), CALL("translate", m3::translate({3, 0, 0}))), {1, 0, 0})));
            put(v, "srt", CALL("transform_point", m3::transform_point(mul(mul(CALL("translate", m3::translate({0, 0, -5})), CALL("rotate_x", m3::rotate_x(pi / 2))), CALL("scale", m3::scale({2, 2, 2}))),
                                              {0, 1, 0})));
            break;
        case Group::kInverse: {
            const Matrix cases[] = {
                {{{2, 1, 0, 3}, {0, 1, 4, -1}, {1, 0, 1, 2}, {0, 0, 0, 1}}},
                {{{0, 2, 1, 0}, {1, 0, 0, 3}, {0, 1, 0, 1}, {2, 0, 1, 0}}},  // needs a row swap
                {{{1.5, 0, 0, 0}, {0, 2.5, 0, 0}, {0, 0, -1.2, -2.2}, {0, 0, -1, 0}}},  // a perspective
                {{{1, 0, 0, 2}, {0, 0, 0, 3}, {0, 0, 1, 4}, {0, 0, 0, 1}}},  // zero column: singular
                {{{1, 2, 3, 4}, {5, 6, 7, 8}, {1, 2, 3, 4}, {0, 1, 0, 1}}},  // equal rows: singular
                // Far from singular (its inverse is about [[-1, 1], [1, 0]] in the corner), but
                // its first pivot is 1e-17: without a row swap, rounding loses the answer.
                {{{1e-17, 1, 0, 0}, {1, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}},
            };
            for (int k = 0; k < 6; ++k) {
                Mat4 out = to_mat4({{{-7, -7, -7, -7}, {-7, -7, -7, -7}, {-7, -7, -7, -7}, {-7, -7, -7, -7}}});
                v["inv" + std::to_string(k) + ".ok"] = CALL("inverse", m3::inverse(to_mat4(cases[k]), out));
                put(v, "inv" + std::to_string(k), out);
            }
            const double c = std::cos(0.5), s = std::sin(0.5);
            put(v, "rigid", CALL("rigid_inverse", m3::rigid_inverse(to_mat4({{{c, -s, 0, 3}, {s, c, 0, -1}, {0, 0, 1, 2}, {0, 0, 0, 1}}}))));
            break;
        }
        case Group::kNearSingular: {
            Mat4 out;
            v["ok"] = CALL("inverse", m3::inverse(to_mat4(near_singular_matrix()), out));
            put(v, "inv", out);
            break;
        }
        case Group::kLookAt:
            put(v, "plain", CALL("look_at", m3::look_at({1, 2, 3}, {0, 0, 0}, {0, 1, 0})));
            put(v, "general", CALL("look_at", m3::look_at({-2, 1, 4}, {1, 0.5, -1}, {0.2, 1, 0.1})));
            put(v, "down", CALL("look_at", m3::look_at({0, 5, 0}, {0, 0, 0}, {0, 1, 0})));
            put(v, "same", CALL("look_at", m3::look_at({1, 1, 1}, {1, 1, 1}, {0, 1, 0})));
            put(v, "noup", CALL("look_at", m3::look_at({3, 0, 0}, {0, 0, 0}, {0, 0, 0})));
            break;
        case Group::kProjection: {
            put(v, "persp", CALL("perspective", m3::perspective(90, 2, 1, 10)));
            put(v, "persp60", CALL("perspective", m3::perspective(60, 1.5, 0.5, 50)));
            put(v, "fov1", CALL("perspective", m3::perspective(1, 1, 0.1, 10)));
            put(v, "fov179", CALL("perspective", m3::perspective(179, 1, 0.1, 10)));
            put(v, "ortho", CALL("orthographic", m3::orthographic(-2, 2, -1, 1, 1, 11)));
            put(v, "bad_fov", CALL("perspective", m3::perspective(180, 1, 1, 10)));
            put(v, "bad_near", CALL("perspective", m3::perspective(60, 1, 0, 10)));
            put(v, "bad_ortho", CALL("orthographic", m3::orthographic(1, 1, -1, 1, 1, 10)));
            put(v, "s0", CALL("to_screen", m3::to_screen({0, 0, 0, 1}, 100, 50)));
            put(v, "s1", CALL("to_screen", m3::to_screen({0.5, 0.5, 0.2, 2}, 100, 50)));
            const Mat4 p = CALL("perspective", m3::perspective(90, 1, 1, 10));
            put(v, "chain0", CALL("to_screen", m3::to_screen(mul(p, Vec4{0, 0, -5, 1}), 64, 64)));
            put(v, "chain1", CALL("to_screen", m3::to_screen(mul(p, Vec4{1, 1, -2, 1}), 64, 64)));
            put(v, "chain2", CALL("to_screen", m3::to_screen(mul(CALL("orthographic", m3::orthographic(-2, 2, -2, 2, 1, 10)), Vec4{1, -1, -3, 1}), 64, 64)));
            break;
        }
        case Group::kClip: {
            const auto tris = clip_cases();
            for (std::size_t k = 0; k < tris.size(); ++k) {
                put_polygon(v, "poly" + std::to_string(k), CALL("clip_polygon", m3::clip_polygon({tris[k][0], tris[k][1], tris[k][2]})));
            }
            const auto lines = clip_line_cases();
            for (std::size_t k = 0; k < lines.size(); ++k) {
                Vec4 a = lines[k][0], b = lines[k][1];
                v["line" + std::to_string(k) + ".ok"] = CALL("clip_line", m3::clip_line(a, b));
                put(v, "line" + std::to_string(k) + ".a", a);
                put(v, "line" + std::to_string(k) + ".b", b);
            }
            break;
        }
        case Group::kCulling:
            v["cull.cw"] = CALL("is_back_facing", m3::is_back_facing({10, 10, 0}, {20, 10, 0}, {10, 20, 0}));
            v["cull.ccw"] = CALL("is_back_facing", m3::is_back_facing({10, 10, 0}, {10, 20, 0}, {20, 10, 0}));
            v["cull.flat"] = CALL("is_back_facing", m3::is_back_facing({10, 10, 0}, {20, 20, 0}, {30, 30, 0}));
            break;
        case Group::kBezier: {
            const double ts[] = {0, 0.25, 0.5, 0.8, 1};
            for (int k = 0; k < 5; ++k) {
                put(v, "b" + std::to_string(k), CALL("bezier", m3::bezier({0, 0, 0}, {1, 2, 0}, {3, 2, 1}, {4, 0, 2}, ts[k])));
            }
            break;
        }
        case Group::kPainter: {
            const std::vector<std::array<Vec3, 3>> tris = {
                {{{0, 0, -2}, {1, 0, -2}, {0, 1, -2}}},       // mean -2
                {{{0, 0, -9}, {1, 0, -1}, {0, 1, -5}}},       // mean -5
                {{{0, 0, -0.5}, {1, 0, -0.7}, {0, 1, -0.6}}},  // mean -0.6
                {{{0, 0, -3}, {1, 0, -4}, {0, 1, -3.5}}},     // mean -3.5
                {{{0, 0, -7}, {1, 0, -6}, {0, 1, -8}}},       // mean -7
            };
            const std::vector<int> order = CALL("painter_order", m3::painter_order(tris));
            v["order.n"] = static_cast<double>(order.size());
            for (std::size_t k = 0; k < order.size() && k < 16; ++k) v["order." + std::to_string(k)] = order[k];
            break;
        }
        case Group::kRotationDrift: {
            const Mat4 step = CALL("rotate", m3::rotate({1, 2, 3}, 0.001));
            Mat4 r = m3::identity();
            for (int k = 0; k < 10000; ++k) r = mul(step, r);
            put(v, "r", r);
            break;
        }
        case Group::kNonFinite: {
            // The inputs are listed with their rules in judge.cpp (kNonFinite).
            const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
            const double max = std::numeric_limits<double>::max();
            put(v, "rot.nan", CALL("rotate", m3::rotate({nan, 0, 1}, 0.7)));
            put(v, "rot.inf", CALL("rotate", m3::rotate({inf, 1, 0}, 0.7)));
            put(v, "rot.tiny", CALL("rotate", m3::rotate({1e-200, 0, 2e-200}, 0.7)));
            put(v, "rot.huge", CALL("rotate", m3::rotate({1e200, -2e200, 0}, 0.7)));
            for (const auto& c : nonfinite_inverse_cases()) {
                // Filled with -7: inverse() that returns false must leave it alone.
                Mat4 out = to_mat4({{{-7, -7, -7, -7}, {-7, -7, -7, -7}, {-7, -7, -7, -7}, {-7, -7, -7, -7}}});
                const Mat4 a = to_mat4(c.second);
                v[c.first + ".ok"] = CALL("inverse", m3::inverse(a, out));
                put(v, c.first, out);
            }
            put(v, "la.nan_eye", CALL("look_at", m3::look_at({nan, 1, 2}, {0, 0, 0}, {0, 1, 0})));
            put(v, "la.inf_eye", CALL("look_at", m3::look_at({0, -inf, 0}, {0, 0, 0}, {0, 1, 0})));
            put(v, "la.nan_target", CALL("look_at", m3::look_at({1, 2, 3}, {nan, 0, 0}, {0, 1, 0})));
            put(v, "la.inf_target", CALL("look_at", m3::look_at({1, 2, 3}, {inf, 0, 0}, {0.3, 1, 0})));
            put(v, "la.huge", CALL("look_at", m3::look_at({0, 0, 0}, {1e308, -1e308, 5e307}, {0, 1, 0})));
            put(v, "la.tiny", CALL("look_at", m3::look_at({1e-310, 0, 0}, {0, 3e-310, -2e-310}, {0, 1, 0})));
            put(v, "la.huge_up", CALL("look_at", m3::look_at({1, 2, 3}, {0, 0, 0}, {0, 1e308, 1e308})));
            put(v, "la.tiny_up", CALL("look_at", m3::look_at({1, 2, 3}, {0, 0, 0}, {1e-170, 1e-170, 0})));
            const Vec3 far_eye{1.7e308, -1.2e308, 0.9e308};
            put(v, "la.huge_eye", CALL("look_at", m3::look_at(far_eye, far_eye + Vec3{-1e307, 5e306, -3e306}, {0, 1, 0})));
            put(v, "la.nan_up", CALL("look_at", m3::look_at({1, 2, 3}, {0, 0, 0}, {0, nan, 1})));
            put(v, "p.nan_fov", CALL("perspective", m3::perspective(nan, 1, 0.1, 10)));
            put(v, "p.inf_far", CALL("perspective", m3::perspective(60, 1, 0.1, inf)));
            put(v, "p.max_far", CALL("perspective", m3::perspective(60, 1, 1, max)));
            put(v, "p.tiny_aspect", CALL("perspective", m3::perspective(60, 1e-320, 0.1, 10)));
            put(v, "p.huge_far", CALL("perspective", m3::perspective(60, 1.5, 0.1, 1e300)));
            put(v, "p.subnormal_near", CALL("perspective", m3::perspective(60, 1.5, 5e-324, 1)));
            put(v, "o.nan", CALL("orthographic", m3::orthographic(nan, 1, -1, 1, 0.1, 10)));
            put(v, "o.inf", CALL("orthographic", m3::orthographic(-1, 1, -inf, 1, 0.1, 10)));
            put(v, "o.tiny_range", CALL("orthographic", m3::orthographic(-1, 1, -1, 1, 1e-309, 0)));
            put(v, "o.huge", CALL("orthographic", m3::orthographic(-1e300, 1e300, -1e300, 1e300, 1, 1e300)));
            const auto cases = nonfinite_clip_cases();
            const std::array<Vec4, 3>& tri = cases.first;
            const std::array<Vec4, 2>& seg = cases.second;
            put_polygon(v, "c.poly", CALL("clip_polygon", m3::clip_polygon({tri[0], tri[1], tri[2]})));
            const std::array<Vec4, 3> edge = inside_end_clip_case();
            put_polygon(v, "c.inside_end", CALL("clip_polygon", m3::clip_polygon({edge[0], edge[1], edge[2]})));
            {
                // The same edge as a segment: a is outside, and the line enters at b.
                Vec4 ea = edge[0], eb = edge[1];
                v["c.inside_end_line.ok"] = CALL("clip_line", m3::clip_line(ea, eb));
                put(v, "c.inside_end_line.a", ea);
                put(v, "c.inside_end_line.b", eb);
            }
            Vec4 a = seg[0], b = seg[1];
            v["c.line.ok"] = CALL("clip_line", m3::clip_line(a, b));
            put(v, "c.line.a", a);
            put(v, "c.line.b", b);
            {
                // Indices outside positions (-1 and 3 of 3) name no vertex: draw_model skips
                // those triangles and edges and draws the valid ones.
                m3::Model bad;
                bad.positions = {{-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0, 0.5, 0}};
                bad.triangles = {{0, 1, 2}, {-1, 0, 1}, {0, 1, 3}};
                bad.edges = {{0, 1}, {-1, 2}, {1, 3}};
                bad.face_colors = {{200, 200, 200}};
                raster::Image img = cp::guarded_image(16, 16);
                const Mat4 id = m3::identity();
                const m3::Stats st = cp::traced(*g_out, "draw_model", img, [&] {
                    return m3::draw_model(img, bad, id, id, id, {true, true, false, true, false}, {250, 250, 250});
                });
                v["dm.bad_index.filled"] = double(st.triangles_filled);
                v["dm.bad_index.lines"] = double(st.lines_drawn);
            }
            break;
        }
    }
}

// Under a scene variant (grading), each number checkpoint also calls its functions on inputs
// drawn from the variant's seed, stored as "probe.<topic>.<name>": the public inputs and their
// hand-worked answers stay, and an implementation that only knows those answers fails here.
// The judge compares every probe with the reference's.
void probes(Group g, Values& v) {
    cp::VariantRng rng(variant_seed(), "m3.probe." + std::to_string(static_cast<int>(g)));
    auto r = [&](int lo, int hi) { return rng.uniform(lo * 100, hi * 100) / 100.0; };  // hundredths
    auto vec = [&](int lo, int hi) { return Vec3{r(lo, hi), r(lo, hi), r(lo, hi)}; };
    auto affine = [&] {
        Mat4 m = m3::identity();
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 4; ++j) m.m[i][j] = r(-3, 3);
        }
        for (int i = 0; i < 3; ++i) m.m[i][i] += 4;  // diagonally dominant: well conditioned
        return m;
    };
    switch (g) {
        case Group::kMatrixOps: {
            const Mat4 a = affine(), b = affine();
            const Vec3 p = vec(-5, 5);
            put(v, "probe.matrix.ab", mul(a, b));
            put(v, "probe.matrix.at", CALL("transpose", m3::transpose(a)));
            put(v, "probe.matrix.av", mul(a, Vec4{p.x, p.y, p.z, 1}));
            put(v, "probe.matrix.pt", CALL("transform_point", m3::transform_point(a, p)));
            put(v, "probe.direction.dir", CALL("transform_direction", m3::transform_direction(a, p)));
            break;
        }
        case Group::kBuilders:
            put(v, "probe.builders.translate", CALL("translate", m3::translate(vec(-5, 5))));
            put(v, "probe.builders.scale", CALL("scale", m3::scale(vec(1, 4))));
            put(v, "probe.builders.rx", CALL("rotate_x", m3::rotate_x(r(-3, 3))));
            put(v, "probe.builders.ry", CALL("rotate_y", m3::rotate_y(r(-3, 3))));
            put(v, "probe.builders.rz", CALL("rotate_z", m3::rotate_z(r(-3, 3))));
            break;
        case Group::kRodrigues:
            put(v, "probe.rotation.r", CALL("rotate", m3::rotate(vec(1, 3), r(-3, 3))));
            put(v, "probe.rotation.neg", CALL("rotate", m3::rotate(vec(-3, -1), r(-3, 3))));
            break;
        case Group::kComposition: {
            const Mat4 t = CALL("translate", m3::translate(vec(-4, 4)));
            const Mat4 rz = CALL("rotate_z", m3::rotate_z(r(-3, 3)));
            const Mat4 sc = CALL("scale", m3::scale(vec(1, 3)));
            put(v, "probe.composition.trs", CALL("transform_point", m3::transform_point(mul(mul(t, rz), sc), vec(-2, 2))));
            break;
        }
        case Group::kInverse: {
            Mat4 out;
            v["probe.inverse.ok"] = CALL("inverse", m3::inverse(affine(), out));
            put(v, "probe.inverse.m", out);
            const Mat4 rigid = mul(CALL("translate", m3::translate(vec(-4, 4))), CALL("rotate", m3::rotate(vec(1, 3), r(-3, 3))));
            put(v, "probe.inverse.rigid", CALL("rigid_inverse", m3::rigid_inverse(rigid)));
            break;
        }
        case Group::kLookAt: {
            const Vec3 eye = vec(-6, 6);
            const Vec3 target{eye.x + r(1, 3), eye.y + r(-2, 2), eye.z - r(1, 3)};
            put(v, "probe.look_at.m", CALL("look_at", m3::look_at(eye, target, {r(-1, 1) / 4, 1, r(-1, 1) / 4})));
            break;
        }
        case Group::kProjection: {
            const double n = r(1, 2) / 4, f = r(20, 90);
            put(v, "probe.projection.persp", CALL("perspective", m3::perspective(r(20, 120), r(1, 2), n, f)));
            put(v, "probe.projection.ortho", CALL("orthographic", m3::orthographic(-r(1, 4), r(1, 4), -r(1, 3), r(1, 3), n, f)));
            put(v, "probe.viewport.s", CALL("to_screen", m3::to_screen({r(-1, 1), r(-1, 1), r(-1, 1) / 2, r(1, 3)}, 64 + rng.uniform(0, 64), 48 + rng.uniform(0, 64))));
            break;
        }
        case Group::kCulling: {
            const Vec3 a{r(0, 60), r(0, 60), 0}, b{r(0, 60), r(0, 60), 0}, c{r(0, 60), r(0, 60), 0};
            v["probe.culling.abc"] = CALL("is_back_facing", m3::is_back_facing(a, b, c));
            v["probe.culling.acb"] = CALL("is_back_facing", m3::is_back_facing(a, c, b));
            break;
        }
        case Group::kBezier:
            put(v, "probe.bezier.p", CALL("bezier", m3::bezier(vec(-3, 3), vec(-3, 3), vec(-3, 3), vec(-3, 3), r(0, 1))));
            break;
        case Group::kPainter: {
            std::vector<std::array<Vec3, 3>> tris;
            for (int k = 0; k < 6; ++k) {
                const double z = -0.5 - 1.5 * k;  // distinct means, in shuffled order
                tris.push_back({{{0, 0, z - 0.25}, {1, 0, z}, {0, 1, z + 0.25}}});
            }
            rng.shuffle(tris);
            const std::vector<int> order = CALL("painter_order", m3::painter_order(tris));
            v["probe.painter.n"] = static_cast<double>(order.size());
            for (std::size_t k = 0; k < order.size() && k < 16; ++k) v["probe.painter." + std::to_string(k)] = order[k];
            break;
        }
        case Group::kRotationDrift: {
            const Mat4 step = CALL("rotate", m3::rotate(vec(-3, 3), r(1, 3) / 1000));
            Mat4 acc = m3::identity();
            for (int k = 0; k < 10000; ++k) acc = mul(step, acc);
            put(v, "probe.precision.r", acc);
            break;
        }
        case Group::kNearSingular:
        case Group::kClip:
            break;  // their public inputs already vary (scenes.cpp)
        case Group::kNonFinite: {
            // The fallbacks at other finite arguments: a look_at whose target is not finite, a
            // rotation about an axis with an infinite component.
            const Vec3 eye = vec(-6, 6);
            const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
            put(v, "probe.look_at.nan_target", CALL("look_at", m3::look_at(eye, {r(-3, 3), nan, r(-3, 3)}, {r(-1, 1) / 4, 1, r(-1, 1) / 4})));
            put(v, "probe.rotation.inf_axis", CALL("rotate", m3::rotate({r(-3, 3), r(-3, 3), -inf}, r(-3, 3))));
            break;
        }
    }
}

void draw_panels(const Scene& s, raster::Image& img, cp::Artifacts& out) {
    m3::Stats total;
    for (std::size_t p = 0; p < s.panels.size(); ++p) {
        const Panel& panel = s.panels[p];
        const Camera& c = panel.camera;
        const double aspect = double(panel.w) / panel.h;
        const Mat4 view = CALL("look_at", m3::look_at(c.eye, c.target, c.up));
        const Mat4 proj = c.ortho ? CALL("orthographic", m3::orthographic(-c.half_height * aspect, c.half_height * aspect, -c.half_height,
                                                     c.half_height, c.near, c.far))
                                  : CALL("perspective", m3::perspective(c.fovy, aspect, c.near, c.far));
        const std::string key = "panel" + std::to_string(p);
        put(out.values, key + ".view", view);
        put(out.values, key + ".proj", proj);
        raster::Image sub = cp::guarded_image(panel.w, panel.h);
        const m3::Needs needs{s.fill, s.wireframe, s.cull, s.clip, s.painter};
        for (std::size_t i = 0; i < panel.items.size(); ++i) {
            const Item& it = panel.items[i];
            const Mat4 model = mul(mul(CALL("translate", m3::translate(it.position)), CALL("rotate", m3::rotate(it.axis, it.angle))),
                                   CALL("scale", m3::scale(it.size)));
            // (The reference's model matrices tell the judge where its clipped lines end.)
            put(out.values, key + ".model" + std::to_string(i), model);
            const m3::Stats st = cp::traced(*g_out, "draw_model", sub, [&] { return m3::draw_model(sub, to_model(it.mesh), model, view, proj, needs, s.line); });
            total.vertices_transformed += st.vertices_transformed;
            total.triangles_clipped += st.triangles_clipped;
            total.triangles_culled += st.triangles_culled;
            total.triangles_filled += st.triangles_filled;
            total.lines_clipped += st.lines_clipped;
            total.lines_drawn += st.lines_drawn;
            // The clipper on this item's triangles, for the judge to check its output alone.
            if (s.clip && s.panels.size() == 1 && it.mesh.triangles.size() <= 2) {
                const Mat4 mvp = mul(mul(proj, view), model);
                for (std::size_t t = 0; t < it.mesh.triangles.size(); ++t) {
                    std::vector<Vec4> tri;
                    for (int k : it.mesh.triangles[t]) tri.push_back(mul(mvp, raster::point(it.mesh.positions[k])));
                    put_polygon(out.values, "clip" + std::to_string(i) + "_" + std::to_string(t), CALL("clip_polygon", m3::clip_polygon(tri)));
                }
            }
        }
        out.stray_writes += sub.stray_writes();
        for (int y = 0; y < panel.h; ++y) {
            for (int x = 0; x < panel.w; ++x) img.set(panel.x0 + x, panel.y0 + y, sub.at(x, y));
        }
    }
    out.values["stats.vertices_transformed"] = double(total.vertices_transformed);
    out.values["stats.triangles_clipped"] = double(total.triangles_clipped);
    out.values["stats.triangles_culled"] = double(total.triangles_culled);
    out.values["stats.triangles_filled"] = double(total.triangles_filled);
    out.values["stats.lines_clipped"] = double(total.lines_clipped);
    out.values["stats.lines_drawn"] = double(total.lines_drawn);
}

// How draw_model uses is_back_facing and painter_order, on two tiny models of its own: one
// triangle drawn both ways round (culling on: the reference fills one and culls the other), and
// a near triangle listed before a far one that covers it (painter on: the near one must be on
// top). The judge compares the pixels with the reference's to tell a wrong caller from a wrong
// callee (both of those functions pass their own checks when it looks).
void draw_model_use(const Scene& s, cp::Artifacts& out) {
    const Mat4 id = m3::identity();
    {
        // The order of the product, on a small triangle: `key`.n = its pixels, `key`.x = their
        // mean x (-1 for none). First model = a move right by 0.5, view = a uniform halving,
        // projection = identity: projection * view * model puts the triangle's middle at
        // x = 0.25 (pixel 30 of 48), model * view * projection at x = 0.5 (pixel 36), twice as
        // wide. Then view = that move, projection = that halving: pixel 30 again, and view *
        // projection * model (the halving before the move) at pixel 36.
        Mat4 move = id, halve = id;
        move.m[0][3] = 0.5;
        halve.m[0][0] = halve.m[1][1] = halve.m[2][2] = 0.5;
        m3::Model tri;
        tri.positions = {{-0.3, -0.3, 0}, {0.3, -0.3, 0}, {0, 0.3, 0}};
        tri.triangles = {{0, 1, 2}};
        tri.face_colors = {{250, 250, 250}};
        auto place = [&](const std::string& key, const Mat4& model, const Mat4& view, const Mat4& projection) {
            raster::Image img = cp::guarded_image(48, 48);
            cp::traced(*g_out, "draw_model", img, [&] {
                return m3::draw_model(img, tri, model, view, projection, {true, false, false, false, false}, {});
            });
            double n = 0, sum_x = 0;
            for (int y = 0; y < img.height(); ++y) {
                for (int x = 0; x < img.width(); ++x) {
                    if (img.at(x, y) == raster::Color{}) continue;
                    n += 1;
                    sum_x += x + 0.5;
                }
            }
            out.values[key + ".n"] = n;
            out.values[key + ".x"] = n > 0 ? sum_x / n : -1;
            out.stray_writes += img.stray_writes();
        };
        place("use.order", move, halve, id);
        place("use.order2", id, move, halve);
    }
    if (s.cull) {
        for (int way = 0; way < 2; ++way) {
            m3::Model tri;
            tri.positions = {{-0.8, -0.8, 0}, {0.8, -0.8, 0}, {0, 0.8, 0}};
            tri.triangles = {way == 0 ? std::array<int, 3>{0, 1, 2} : std::array<int, 3>{0, 2, 1}};
            tri.face_colors = {{250, 60, 60}};
            raster::Image img = cp::guarded_image(24, 24);
            cp::traced(*g_out, "draw_model", img, [&] { return m3::draw_model(img, tri, id, id, id, {true, false, true, false, false}, {}); });
            long long n = 0;
            for (int y = 0; y < img.height(); ++y) {
                for (int x = 0; x < img.width(); ++x) n += img.at(x, y) != raster::Color{};
            }
            out.values["use.cull" + std::to_string(way)] = double(n);
            out.stray_writes += img.stray_writes();
        }
    }
    if (s.painter) {
        m3::Model two;  // view space: the camera looks down -z, so z = -0.2 is nearer than z = -0.6
        two.positions = {{-0.5, -0.5, -0.2}, {0.5, -0.5, -0.2}, {0, 0.5, -0.2}, {-0.9, -0.9, -0.6}, {0.9, -0.9, -0.6}, {0, 0.9, -0.6}};
        two.triangles = {{0, 1, 2}, {3, 4, 5}};
        two.face_colors = {{40, 200, 60}, {60, 60, 230}};
        raster::Image img = cp::guarded_image(24, 24);
        cp::traced(*g_out, "draw_model", img, [&] { return m3::draw_model(img, two, id, id, id, {true, false, false, false, true}, {}); });
        put(out.values, "use.painter", Vec3{double(img.at(12, 12).r), double(img.at(12, 12).g), double(img.at(12, 12).b)});
        out.stray_writes += img.stray_writes();
    }
}

}  // namespace

cp::Artifacts render(const std::string& id) {
    const Scene& s = scene(id);
    return cp::render_guarded(s.width, s.height, [&](raster::Image& img, cp::Artifacts& out) {
        g_out = &out;
        for (Group g : s.groups) {
            numbers(g, out.values);
            if (variant_seed() != 0) probes(g, out.values);
        }
        // The functions the picture is drawn with, each on its own checkpoint's inputs: the
        // judge checks them before it blames draw_model (scenes.h, prerequisite_groups).
        for (Group g : prerequisite_groups(s)) {
            Values pre;
            numbers(g, pre);
            for (const auto& [key, value] : pre) out.values[prerequisite_key(g) + key] = value;
        }
        if (!s.panels.empty()) draw_panels(s, img, out);
        if (!s.panels.empty()) draw_model_use(s, out);
    });
}

#undef CALL

std::vector<raster::Image> animation() {
    const int frames = 36, width = 160, height = 120;
    Mesh wire_ball = soccer_ball_mesh();
    wire_ball.triangles.clear();
    const m3::Model cube = to_model(cube_mesh(false)), ball = to_model(wire_ball);
    const m3::Needs wire{false, true, false, true, false};
    std::vector<raster::Image> out;
    for (int f = 0; f < frames; ++f) {
        const double t = double(f) / (frames - 1);
        // The camera's path: a Bezier curve from the left, over the top, to the right.
        const Vec3 eye = m3::bezier({-6, 1, 7}, {-2, 6, 9}, {4, 5, 8}, {7, 0.5, 5}, t);
        const Mat4 view = m3::look_at(eye, {0, 0, 0}, {0, 1, 0});
        const Mat4 proj = m3::perspective(50, double(width) / height, 0.1, 100);
        const double spin = 2 * std::numbers::pi * t;
        raster::Image img(width, height, {16, 18, 28});
        m3::draw_model(img, cube, m3::translate({-1.8, 0, 0}) * m3::rotate({1, 1, 0}, spin), view, proj, wire,
                       {240, 200, 80});
        m3::draw_model(img, ball, m3::translate({1.8, 0, 0}) * m3::rotate({0, 1, 0.3}, -spin) * m3::scale({1.3, 1.3, 1.3}),
                       view, proj, wire, {120, 200, 255});
        out.push_back(img);
    }
    return out;
}

}  // namespace RASTER_FLAVOUR
}  // namespace m3cp
