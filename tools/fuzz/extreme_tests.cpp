// What extreme input gives, pinned in the headers and held here on the reference: each case
// below was found by fuzzing (issue 19) and is kept as a test. The fuzzing harnesses check the
// same promises on random input (tools/fuzz/fuzz_m*.cpp).
#include "raster_catch.h"

#include <cfloat>
#include <cmath>
#include <limits>

#include "depth_lighting.h"
#include "transforms.h"

namespace {

using m3::Mat4;
using raster::Color;
using raster::Vec2;
using raster::Vec3;
using raster::Vec4;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kTiny = std::numeric_limits<double>::denorm_min();

bool finite(const Mat4& m) {
    for (const auto& row : m.m) {
        for (double e : row) {
            if (!std::isfinite(e)) return false;
        }
    }
    return true;
}
bool is_zero(const Mat4& m) {
    for (const auto& row : m.m) {
        for (double e : row) {
            if (e != 0) return false;
        }
    }
    return true;
}
bool finite(Vec4 p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w); }

// The pixels of the image that differ from the background.
int drawn(const raster::Image& img, Color background) {
    int n = 0;
    for (int y = 0; y < img.height(); ++y) {
        for (int x = 0; x < img.width(); ++x) {
            const Color c = img.at(x, y);
            n += c.r != background.r || c.g != background.g || c.b != background.b;
        }
    }
    return n;
}

// fill_triangle in kChecker mode on a 48x48 frame, vertex 0 with the given w and uv.
m4::Frame fill_checker(double w0, Vec2 uv0, bool depth = false, m4::DepthFormat format = m4::DepthFormat::kFloatZ) {
    m4::Frame frame;
    frame.color = raster::Image(48, 48);
    m4::clear_frame(frame, {0, 0, 0}, depth, format);
    m4::Lighting lighting;
    m4::FillState state;
    state.needs.shading = m4::Shading::kChecker;
    state.needs.depth_test = depth;
    state.needs.depth_format = format;
    state.lighting = &lighting;
    std::array<m4::ScreenVertex, 3> v;
    v[0].screen = {2, 2, 0};
    v[1].screen = {40, 2, 0};
    v[2].screen = {2, 40, 0};
    v[0].w = w0;
    v[0].uv = uv0;
    v[1].uv = {1, 0};
    v[2].uv = {0, 1};
    m4::Stats stats;
    m4::fill_triangle(frame, v, state, stats);
    return frame;
}

// A 64x64 scene: one triangle in front of a camera at the origin with perspective(90, 1,
// near, 10), one vertex on the near plane itself.
raster::Image near_plane_scene(double near, m4::Shading shading, bool depth, m4::DepthFormat format) {
    m4::Frame frame;
    frame.color = raster::Image(64, 64);
    m4::Needs needs;
    needs.shading = shading;
    needs.depth_test = depth;
    needs.depth_format = format;
    m4::clear_frame(frame, {0, 0, 0}, depth, format);
    m4::Mesh mesh;
    mesh.positions = {{0, 0, -near}, {2, -1, -4}, {-1, 2, -5}};
    mesh.triangles = {{0, 1, 2}};
    mesh.uvs = {{0, 0}, {1, 0}, {0, 1}};
    mesh.face_colors = {{200, 50, 50}};
    (void)m4::draw_mesh(frame, mesh, m3::identity(), m3::identity(), m3::perspective(90, 1, near, 10), {}, {255, 255, 255},
                        needs);
    return frame.color;
}

}  // namespace

TEST_CASE("m4 fill_triangle: a w of denorm_min, 0 or NaN falls back to the screen weights") {
    const m4::Frame good = fill_checker(1, {0, 0});
    for (double w : {kTiny, 0.0, kNaN, -0.0, 1e-320}) {
        INFO("w = " << w);
        const m4::Frame f = fill_checker(w, {0, 0});
        CHECK(drawn(f.color, {0, 0, 0}) == drawn(good.color, {0, 0, 0}));
    }
}

TEST_CASE("m4 checker: any uv gives one of its two colors, NaN and infinity the dark one") {
    const Color dark{32, 32, 32}, white{255, 255, 255};
    for (Vec2 uv : {Vec2{kNaN, 0}, Vec2{0, kInf}, Vec2{-kInf, 1}, Vec2{1e300, 0}, Vec2{DBL_MAX, DBL_MAX}}) {
        INFO("uv = " << uv.x << ", " << uv.y);
        const Color c = m4::checker(uv);
        if (std::isfinite(uv.x * m4::kCheckerCells) && std::isfinite(uv.y * m4::kCheckerCells)) {
            CHECK((c == white || c == dark));
        } else {
            CHECK(c == dark);
        }
    }
    // Ordinary cells, negative ones included, as before.
    CHECK(m4::checker({0.01, 0.01}) == white);
    CHECK(m4::checker({0.13, 0.01}) == dark);
    CHECK(m4::checker({-0.01, 0.01}) == dark);
    CHECK(m4::checker({-0.01, -0.01}) == white);
    CHECK(m4::checker({1e300, 1e300}) == white);  // beyond 2^53 every cell index is even
}

TEST_CASE("m4 fill_triangle: a uv of NaN, infinity or 1e300 draws the triangle, without undefined behaviour") {
    const int full = drawn(fill_checker(1, {0, 0}).color, {0, 0, 0});
    for (Vec2 uv : {Vec2{kNaN, 1}, Vec2{kInf, -kInf}, Vec2{1e300, 1e300}}) {
        const m4::Frame f = fill_checker(1, uv);
        // Dark (32) and white cells both differ from the black background.
        CHECK(drawn(f.color, {0, 0, 0}) == full);
    }
}

TEST_CASE("m4 draw_mesh: near = denorm_min draws like near = 1e-300, in every depth format") {
    for (m4::DepthFormat format : {m4::DepthFormat::kFloatZ, m4::DepthFormat::kReversedZ, m4::DepthFormat::kFixed24,
                                   m4::DepthFormat::kInverseW}) {
        INFO("format " << static_cast<int>(format));
        const raster::Image small = near_plane_scene(1e-300, m4::Shading::kFaceColor, true, format);
        const raster::Image tiny = near_plane_scene(kTiny, m4::Shading::kFaceColor, true, format);
        CHECK(drawn(small, {0, 0, 0}) > 50);
        CHECK(drawn(tiny, {0, 0, 0}) == drawn(small, {0, 0, 0}));
    }
    // The checkerboard at a subnormal near plane (the uv went NaN there before).
    CHECK(drawn(near_plane_scene(kTiny, m4::Shading::kChecker, false, m4::DepthFormat::kFloatZ), {0, 0, 0}) > 50);
}

TEST_CASE("m4 shade: a zero normal under an infinite light gives the ambient color") {
    m4::Lighting l;
    l.ambient = {0.25, 0.5, 0.75};
    l.lights.push_back({m4::Light::Kind::kDirectional, {0, 0, -1}, {kInf, kInf, kInf}});
    const Vec3 s = m4::shade(l, {100, 100, 100}, {0, 0, 0}, {0, 0, 0});
    CHECK(s.x == 25);
    CHECK(s.y == 50);
    CHECK(s.z == 75);
    // A surface the infinite light reaches is white, never NaN.
    const Vec3 lit = m4::shade(l, {100, 100, 100}, {0, 0, 0}, {0, 0, 1});
    CHECK(std::isinf(lit.x));
    CHECK(m4::to_color(lit) == Color{255, 255, 255});
}

TEST_CASE("m3 look_at: a direction whose length overflows or underflows still has length 1") {
    const Mat4 far = m3::look_at({-DBL_MAX, 7.69, -7.94}, {1.125, -7.125, 7.76e68}, {0, 0, 0});
    const Mat4 near = m3::look_at({0, 0, 0}, {2e-162, 1e-162, -2e-162}, {0, 1, 0});
    for (const Mat4& v : {far, near}) {
        for (int r = 0; r < 3; ++r) {
            const double len = std::sqrt(v.m[r][0] * v.m[r][0] + v.m[r][1] * v.m[r][1] + v.m[r][2] * v.m[r][2]);
            CHECK(len == Approx(1).epsilon(1e-12));
        }
        for (const auto& row : v.m) {
            for (double e : row) CHECK(!std::isnan(e));
        }
    }
    // -f, the third row, points from the target back to the eye.
    CHECK(near.m[2][0] == Approx(-2 / 3.0).epsilon(1e-12));
    CHECK(near.m[2][1] == Approx(-1 / 3.0).epsilon(1e-12));
    CHECK(near.m[2][2] == Approx(2 / 3.0).epsilon(1e-12));
    // An eye that is not finite gives the zero matrix.
    CHECK(is_zero(m3::look_at({kInf, 0, 0}, {0, 0, 0}, {0, 1, 0})));
    CHECK(is_zero(m3::look_at({kNaN, 0, 0}, {0, 0, 0}, {0, 1, 0})));
}

TEST_CASE("m3 inverse: a matrix with a NaN or infinite entry is singular") {
    for (double bad : {kNaN, kInf, -kInf}) {
        Mat4 a = m3::identity();
        a.m[1][2] = bad;
        Mat4 out = m3::identity();
        CHECK_FALSE(m3::inverse(a, out));
        CHECK(finite(out));  // left alone
    }
}

TEST_CASE("m3 inverse: an inverse too large for a double is no inverse") {
    // Found by the fuzzer: entries of denorm_min pass the pivot test relative to the largest
    // entry, but the inverse's entries (about 2e323) overflow to infinite and NaN.
    const double d = std::numeric_limits<double>::denorm_min();
    Mat4 a{};
    const double rows[4][4] = {{d, d, d, 0}, {d, d, d, d}, {d, 0, d, 0}, {0, d, d, 0}};
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) a.m[r][c] = rows[r][c];
    }
    Mat4 out = m3::identity();
    CHECK_FALSE(m3::inverse(a, out));
    CHECK(finite(out));  // left alone
    // The same matrix scaled to entries of 1e-300 has an inverse of entries near 1e300: finite.
    for (auto& row : a.m) {
        for (double& e : row) e = e == 0 ? 0 : 1e-300;
    }
    REQUIRE(m3::inverse(a, out));
    CHECK(finite(out));
}

TEST_CASE("m3 projections: arguments that would overflow an entry give the zero matrix") {
    CHECK(is_zero(m3::perspective(60, 1, 1, DBL_MAX)));
    CHECK(is_zero(m3::perspective(60, 1e-320, 1, 10)));
    CHECK(is_zero(m3::orthographic(-1, 1, -1, 1, 1e-309, 0)));
    CHECK(is_zero(m3::orthographic(0, 1e-310, -1, 1, 1, 10)));
    // Ordinary ones are untouched.
    CHECK(finite(m3::perspective(60, 1, 0.1, 100)));
    CHECK(!is_zero(m3::perspective(60, 1, 1e-300, 1e6)));
    CHECK(finite(m3::orthographic(-1, 1, -1, 1, 0.1, 100)));
}

TEST_CASE("m3 clipping: finite coordinates near 1e308 give finite vertices") {
    for (double s : {1e262, 1e300, 1e308, DBL_MAX}) {
        INFO("scale " << s);
        const std::vector<Vec4> poly = {{-s, -s / 2, 0, s / 2}, {s, -s / 4, 0, s / 2}, {0, s, 0, s / 2}};
        const std::vector<Vec4> out = m3::clip_polygon(poly);
        CHECK(out.size() >= 3);
        for (const Vec4& p : out) CHECK(finite(p));
        Vec4 a{-s, 0, 0, s / 2}, b{s, 0, 0, s / 2};
        REQUIRE(m3::clip_line(a, b));
        CHECK(finite(a));
        CHECK(finite(b));
        CHECK(a.x / a.w == Approx(-1));
        CHECK(b.x / b.w == Approx(1));
    }
    // Ordinary coordinates are clipped exactly as before (no scaling).
    Vec4 a{-3, 0, 0, 1}, b{0.5, 0, 0, 1};
    REQUIRE(m3::clip_line(a, b));
    CHECK(a.x == -1);
    CHECK(b.x == 0.5);
}
