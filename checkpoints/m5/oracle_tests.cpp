// The project's own test of the milestone-5 reference against INDEPENDENT oracles: each
// expected value comes from another computation of the same rule (wrapping by walking a
// periodic or bouncing table one step at a time, bilinear as a sum of tent weights, mipmap
// texels as the plain average of the base block they cover, derivatives as finite differences
// of the exact perspective uv and of a GLM ray cast, the tangent frame as the solution of its
// 2x2 system, shadows as a ray cast to the light), plus hand-worked values and the extreme
// inputs of the header. Students never run this; it guards the reference the checkpoints
// compare them with.
#define GLM_FORCE_SILENT_WARNINGS
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "raster_catch.h"
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "textures_shadows.h"

namespace {

namespace ref = m5::reference;
namespace m4r = m4::reference;
namespace m3r = m3::reference;
using raster::Color;
using raster::Vec2;
using raster::Vec3;
using ref::Wrap;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
const Wrap kModes[] = {Wrap::kRepeat, Wrap::kClampToEdge, Wrap::kMirroredRepeat};

bool close(double a, double b, double rel, double abs = 0) {
    return std::abs(a - b) <= std::max(abs, rel * std::max(std::abs(a), std::abs(b)));
}
bool close(Vec3 a, Vec3 b, double rel, double abs = 0) {
    return close(a.x, b.x, rel, abs) && close(a.y, b.y, rel, abs) && close(a.z, b.z, rel, abs);
}

// ---- wrapping oracles ----

// The wrapped index of a small integer i, found by walking from index 0 (value 0) one step at
// a time: repeat steps and jumps from n - 1 to 0 (and back); mirrored repeat BOUNCES, staying
// on an end for one step and then turning around; clamp stops at the ends.
int walk(long long i, int n, Wrap mode) {
    int value = 0, dir = i >= 0 ? 1 : -1;
    const int step = dir;
    for (long long k = 0; k != i; k += step) {
        if (mode == Wrap::kRepeat) {
            value += step;
            if (value == n) value = 0;
            if (value == -1) value = n - 1;
        } else if (mode == Wrap::kClampToEdge) {
            value = std::clamp(value + step, 0, n - 1);
        } else {
            const int next = value + dir;
            if (next < 0 || next >= n) {
                dir = -dir;  // the end texel shows twice, then the walk turns
            } else {
                value = next;
            }
        }
    }
    return value;
}

// i mod n, exactly, for any finite whole double i: |i| = m * 2^e with m a 53-bit integer, so
// the remainder is (m mod n) * (2^e mod n) mod n, in integers.
long long exact_mod(double i, long long n) {
    int e = 0;
    const double f = std::frexp(std::abs(i), &e);
    long long m = static_cast<long long>(std::ldexp(f, 53));
    e -= 53;
    long long r;
    if (e < 0) {
        r = (m >> -e) % n;  // i is a whole number: the low bits are zero
    } else {
        long long p = 1 % n, base = 2 % n;
        for (int k = e; k > 0; k >>= 1) {
            if (k & 1) p = static_cast<long long>((static_cast<__int128>(p) * base) % n);
            base = static_cast<long long>((static_cast<__int128>(base) * base) % n);
        }
        r = static_cast<long long>((static_cast<__int128>(m % n) * p) % n);
    }
    return i < 0 ? (n - r) % n : r;
}

// ---- texture helpers ----

// A level of w x h texels with distinct whole-number levels per texel (from a seed).
ref::Level random_level(int w, int h, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> level(0, 255);
    ref::Level l;
    l.width = w;
    l.height = h;
    for (int k = 0; k < w * h; ++k) l.texels.push_back({double(level(rng)), double(level(rng)), double(level(rng))});
    return l;
}

ref::Texture texture_of(ref::Level base, Wrap wu = Wrap::kRepeat, Wrap wv = Wrap::kRepeat) {
    ref::Texture t;
    t.levels.push_back(std::move(base));
    t.wrap_u = wu;
    t.wrap_v = wv;
    return t;
}

Vec3 texel_walked(const ref::Level& l, long long i, long long j, Wrap wu, Wrap wv) {
    return l.texels[static_cast<std::size_t>(walk(j, l.height, wv)) * l.width + walk(i, l.width, wu)];
}

// Bilinear as a sum over every texel of its tent weight: max(0, 1 - |x - center|) per axis,
// with texel centers at half-integers. No floor, no fraction.
Vec3 tent_sum(const ref::Level& l, Vec2 uv, Wrap wu, Wrap wv) {
    const double x = uv.x * l.width, y = uv.y * l.height;
    Vec3 sum;
    for (long long j = static_cast<long long>(std::floor(y)) - 3; j <= static_cast<long long>(std::floor(y)) + 3; ++j) {
        for (long long i = static_cast<long long>(std::floor(x)) - 3; i <= static_cast<long long>(std::floor(x)) + 3; ++i) {
            const double wx = std::max(0.0, 1 - std::abs(x - (i + 0.5))), wy = std::max(0.0, 1 - std::abs(y - (j + 0.5)));
            if (wx * wy > 0) sum = sum + texel_walked(l, i, j, wu, wv) * (wx * wy);
        }
    }
    return sum;
}

// Mipmap level k straight from the base: each texel the plain average of the base block it
// covers. Along an axis the block doubles at every level whose previous size was at least 2
// (a side of 1 texel averages its clamped copy with itself: the block stays).
ref::Level block_average_level(const ref::Level& base, int k) {
    int w = base.width, h = base.height, bx = 1, by = 1;
    for (int level = 0; level < k; ++level) {
        if (w >= 2) bx *= 2;
        if (h >= 2) by *= 2;
        w = std::max(1, w / 2);
        h = std::max(1, h / 2);
    }
    ref::Level out;
    out.width = w;
    out.height = h;
    for (int j = 0; j < h; ++j) {
        for (int i = 0; i < w; ++i) {
            Vec3 sum;
            for (int y = j * by; y < (j + 1) * by; ++y) {
                for (int x = i * bx; x < (i + 1) * bx; ++x) sum = sum + base.texels[static_cast<std::size_t>(y) * base.width + x];
            }
            out.texels.push_back(sum / double(bx * by));
        }
    }
    return out;
}

// ---- geometry helpers (GLM) ----

m3r::Mat4 from_glm(const glm::dmat4& g) {
    m3r::Mat4 m;
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) m.m[r][c] = g[c][r];  // GLM stores columns
    }
    return m;
}

// The world-space ray through the screen point (x, y) (pixels, row 0 at the top) of a camera
// with view-projection vp on a width x height image: the inverse matrix takes the points at
// z_ndc = -1 and 1 back to the world.
struct Ray {
    glm::dvec3 origin, direction;
};
Ray pixel_ray(const glm::dmat4& vp, double x, double y, int width, int height) {
    const glm::dmat4 inv = glm::inverse(vp);
    const double nx = 2 * x / width - 1, ny = 1 - 2 * y / height;
    glm::dvec4 a = inv * glm::dvec4(nx, ny, -1, 1), b = inv * glm::dvec4(nx, ny, 1, 1);
    const glm::dvec3 pa = glm::dvec3(a) / a.w, pb = glm::dvec3(b) / b.w;
    return {pa, pb - pa};
}

// Where the ray meets the triangle's plane, as barycentric weights of v0, v1, v2 (areas).
glm::dvec3 ray_barycentric(const Ray& ray, glm::dvec3 v0, glm::dvec3 v1, glm::dvec3 v2) {
    const glm::dvec3 n = glm::cross(v1 - v0, v2 - v0);
    const double t = glm::dot(v0 - ray.origin, n) / glm::dot(ray.direction, n);
    const glm::dvec3 p = ray.origin + ray.direction * t;
    const double area = glm::dot(n, n);
    return {glm::dot(glm::cross(v1 - p, v2 - p), n) / area, glm::dot(glm::cross(v2 - p, v0 - p), n) / area,
            glm::dot(glm::cross(v0 - p, v1 - p), n) / area};
}

glm::dvec3 g(Vec3 v) { return {v.x, v.y, v.z}; }

// A floor (y = 0, x and z in [-3, 3]) facing up, with uv = ((x + 3) / 3, (z + 3) / 3).
m4r::Mesh floor_mesh() {
    m4r::Mesh m;
    m.positions = {{-3, 0, -3}, {3, 0, -3}, {3, 0, 3}, {-3, 0, 3}};
    m.triangles = {{0, 2, 1}, {0, 3, 2}};
    m.uvs = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    m.normals = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
    return m;
}

// A square at height y = 1 (x and z in [-1, 1]), both faces drawn, casting on the floor.
m4r::Mesh blocker_mesh() {
    m4r::Mesh m;
    m.positions = {{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}};
    m.triangles = {{0, 2, 1}, {0, 3, 2}};
    m.normals = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
    return m;
}

struct View {
    glm::dmat4 vp;
    ref::Camera camera;
};
View camera_view(glm::dvec3 eye, int width, int height) {
    const glm::dmat4 view = glm::lookAt(eye, glm::dvec3(0, 0, 0), glm::dvec3(0, 1, 0));
    const glm::dmat4 projection = glm::perspective(glm::radians(60.0), double(width) / height, 0.5, 50.0);
    View v;
    v.vp = projection * view;
    v.camera.view = from_glm(view);
    v.camera.projection = from_glm(projection);
    v.camera.eye = {eye.x, eye.y, eye.z};
    return v;
}

m4r::Frame new_frame(int width, int height) {
    m4r::Frame f;
    f.color = raster::Image(width, height);
    m4r::clear_frame(f, {0, 0, 0}, true, m4r::DepthFormat::kFloatZ);
    return f;
}

}  // namespace

// ---- TODO 1: wrapping ----

TEST_CASE("wrap_index agrees with walking the table, for every mode and size", "[m5][wrap]") {
    for (int n : {1, 2, 3, 5, 8}) {
        for (Wrap mode : kModes) {
            for (long long i = -60; i <= 60; ++i) {
                INFO("n = " << n << ", mode " << int(mode) << ", i = " << i);
                REQUIRE(ref::wrap_index(double(i), n, mode) == walk(i, n, mode));
            }
        }
    }
}

TEST_CASE("wrap_index of huge and non-finite indices", "[m5][wrap][extreme]") {
    const double huge[] = {1e300, -1e300, 9007199254740993.0 /* rounds to 2^53 */, 9007199254740994.0, -9007199254740994.0,
                           1e16 + 2, -(1e16 + 2), 123456789012345678.0, 4.5e15 + 1,
                           4503599627370495.0 /* 2^52 - 1 */, -4503599627370495.0, 4503599627370496.0, -4503599627370497.0,
                           4503599627370498.0, 1e9 + 7, -(1e9 + 7), 2147483647.0, -2147483649.0};
    for (int n : {1, 3, 5, 7, 8, 640, 16384, 1000003}) {
        for (double i : huge) {
            INFO("n = " << n << ", i = " << i);
            const long long r = exact_mod(i, n);
            CHECK(ref::wrap_index(i, n, Wrap::kRepeat) == double(r));
            const long long m = exact_mod(i, 2LL * n);
            CHECK(ref::wrap_index(i, n, Wrap::kMirroredRepeat) == double(m < n ? m : 2LL * n - 1 - m));
            CHECK(ref::wrap_index(i, n, Wrap::kClampToEdge) == (i < 0 ? 0.0 : n - 1.0));
        }
        for (Wrap mode : kModes) {
            CHECK(ref::wrap_index(kNaN, n, mode) == 0);
            CHECK(ref::wrap_index(kInf, n, mode) == 0);
            CHECK(ref::wrap_index(-kInf, n, mode) == 0);
        }
    }
    // The oracle itself on numbers small enough to check directly.
    CHECK(exact_mod(-1, 5) == 4);
    CHECK(exact_mod(1e15, 7) == static_cast<long long>(1000000000000000LL % 7));
}

TEST_CASE("fetch wraps u and v independently on a 3x5 level", "[m5][wrap]") {
    const ref::Level l = random_level(3, 5, 7);
    for (Wrap wu : kModes) {
        for (Wrap wv : kModes) {
            for (int j = -12; j <= 12; ++j) {
                for (int i = -12; i <= 12; ++i) {
                    INFO("i = " << i << ", j = " << j);
                    REQUIRE(ref::fetch(l, i, j, wu, wv) == texel_walked(l, i, j, wu, wv));
                }
            }
        }
    }
    CHECK(ref::fetch(ref::Level{}, 0, 0, Wrap::kRepeat, Wrap::kRepeat) == Vec3{});
}

// ---- TODO 2: sampling ----

TEST_CASE("nearest reads the texel whose square holds the point", "[m5][sample]") {
    const ref::Level l = random_level(3, 5, 11);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> coord(-3, 3);
    for (int k = 0; k < 2000; ++k) {
        const Vec2 uv{coord(rng), coord(rng)};
        // The square [i, i + 1) holding x, found by search rather than floor.
        const double x = uv.x * l.width, y = uv.y * l.height;
        long long i = -20, j = -20;
        while (!(i <= x && x < i + 1)) ++i;
        while (!(j <= y && y < j + 1)) ++j;
        for (Wrap mode : kModes) {
            INFO("uv = " << uv.x << ", " << uv.y);
            REQUIRE(ref::sample_nearest(l, uv, mode, Wrap::kRepeat) == texel_walked(l, i, j, mode, Wrap::kRepeat));
        }
    }
    // Texel centers are at half-integers: the center of texel (1, 2) reads it.
    CHECK(ref::sample_nearest(l, {1.5 / 3, 2.5 / 5}, Wrap::kRepeat, Wrap::kRepeat) == l.texels[2 * 3 + 1]);
}

TEST_CASE("bilinear equals the sum of tent weights", "[m5][sample]") {
    for (auto [w, h] : {std::pair{3, 5}, std::pair{1, 1}, std::pair{8, 8}, std::pair{7, 2}}) {
        const ref::Level l = random_level(w, h, 100 + w * h);
        std::mt19937 rng(w * 31 + h);
        std::uniform_real_distribution<double> coord(-2.5, 2.5);
        for (int k = 0; k < 1500; ++k) {
            const Vec2 uv{coord(rng), coord(rng)};
            for (Wrap wu : kModes) {
                for (Wrap wv : kModes) {
                    INFO(w << "x" << h << ", uv = " << uv.x << ", " << uv.y);
                    REQUIRE(close(ref::sample_bilinear(l, uv, wu, wv), tent_sum(l, uv, wu, wv), 1e-12, 1e-9));
                }
            }
        }
        // At a texel center the sample is that texel, exactly.
        for (int j = 0; j < h; ++j) {
            for (int i = 0; i < w; ++i) {
                CHECK(ref::sample_bilinear(l, {(i + 0.5) / w, (j + 0.5) / h}, Wrap::kRepeat, Wrap::kRepeat) ==
                      l.texels[static_cast<std::size_t>(j) * w + i]);
            }
        }
    }
}

TEST_CASE("a texture coordinate near 1e7 in double, and what float does to it", "[m5][sample][extreme]") {
    // A 64-texel ramp: texel i has red level 4 i.
    ref::Level ramp;
    ramp.width = 64;
    ramp.height = 1;
    for (int i = 0; i < 64; ++i) ramp.texels.push_back({4.0 * i, 0, 0});
    for (int i = 0; i < 64; ++i) {
        const double u = 1e7 + (i + 0.5) / 64;  // the center of texel i, 10 million periods away
        CHECK(ref::sample_nearest(ramp, {u, 0.5}, Wrap::kRepeat, Wrap::kRepeat).x == 4.0 * i);
        // float has 24 bits: at 1e7 its spacing is 1, so the fraction is gone (u rounds to 1e7
        // or 1e7 + 1) and every texel reads texel 0.
        const float uf = static_cast<float>(u);
        CHECK(std::floor(double(uf)) == double(uf));
        CHECK(std::abs(double(uf) - u) <= 0.5);
        CHECK(ref::sample_nearest(ramp, {double(uf), 0.5}, Wrap::kRepeat, Wrap::kRepeat).x == 0);
        // double still resolves 1/64 of a texel there: bilinear between texels i and i + 1.
        if (i < 63) {
            for (int k = 0; k < 64; k += 7) {
                const double uk = 1e7 + (i + 0.5 + k / 64.0) / 64;
                CHECK(close(ref::sample_bilinear(ramp, {uk, 0.5}, Wrap::kRepeat, Wrap::kRepeat).x, 4.0 * i + 4.0 * k / 64, 0, 1e-5));
            }
        }
    }
}

TEST_CASE("huge, infinite and NaN texture coordinates", "[m5][sample][extreme]") {
    const ref::Level l = random_level(3, 5, 21);
    // 1e300 wraps exactly: x = 1e300 * 3 (rounded) is a whole number whose remainder the
    // integer oracle finds.
    for (double u : {1e300, -1e300, 3e299}) {
        const auto i = exact_mod(std::floor(u * 3), 3);
        CHECK(ref::sample_nearest(l, {u, 0.5}, Wrap::kRepeat, Wrap::kRepeat) == l.texels[2 * 3 + i]);
        CHECK(ref::sample_bilinear(l, {u, 0.1}, Wrap::kRepeat, Wrap::kClampToEdge) == l.texels[0 * 3 + i]);
    }
    // Infinite or NaN: black, for every sampler and filter.
    ref::Texture t = texture_of(random_level(8, 8, 5));
    const auto filters = {ref::Filter::kNearest, ref::Filter::kBilinear, ref::Filter::kNearestMip, ref::Filter::kTrilinear};
    for (Vec2 uv : {Vec2{kNaN, 0.5}, Vec2{0.5, kNaN}, Vec2{kInf, 0.5}, Vec2{0.5, -kInf}, Vec2{kNaN, kInf}}) {
        CHECK(ref::sample_nearest(l, uv, Wrap::kRepeat, Wrap::kRepeat) == Vec3{});
        CHECK(ref::sample_bilinear(l, uv, Wrap::kMirroredRepeat, Wrap::kClampToEdge) == Vec3{});
        for (auto f : filters) {
            for (double lambda : {-1.0, 0.5, 2.5, kNaN, kInf}) CHECK(ref::sample(t, uv, lambda, f, nullptr) == Vec3{});
        }
    }
    // Finite, but infinite in texel units (1e308 * 8): black wherever level 0 is read. (A
    // coarse level, fewer texels wide, may hold the product: it then wraps like any other.)
    for (Vec2 uv : {Vec2{1e308, 0.5}, Vec2{0.5, -1e308}}) {
        CHECK(ref::sample_nearest(t.levels[0], uv, Wrap::kRepeat, Wrap::kRepeat) == Vec3{});
        CHECK(ref::sample_bilinear(t.levels[0], uv, Wrap::kRepeat, Wrap::kRepeat) == Vec3{});
        for (auto f : filters) CHECK(ref::sample(t, uv, -1, f, nullptr) == Vec3{});
        for (double lambda : {2.5, kInf}) CHECK(raster::is_finite(ref::sample(t, uv, lambda, ref::Filter::kTrilinear, nullptr)));
    }
    // A texture of size 0 samples black and builds nothing.
    ref::Texture empty;
    long long builds = 0;
    CHECK(ref::sample(empty, {0.5, 0.5}, 3, ref::Filter::kTrilinear, &builds) == Vec3{});
    ref::Texture zero = texture_of(ref::Level{});
    CHECK(ref::sample(zero, {0.5, 0.5}, 3, ref::Filter::kTrilinear, &builds) == Vec3{});
    ref::build_mipmaps(zero);
    CHECK(zero.levels.size() == 1);
    CHECK_FALSE(zero.mipmapped);
    CHECK(builds == 0);
}

// ---- TODO 3: mipmaps ----

TEST_CASE("every mipmap level is the plain average of the base block it covers", "[m5][mipmap]") {
    for (auto [w, h] : {std::pair{1, 1}, std::pair{3, 5}, std::pair{5, 3}, std::pair{7, 1}, std::pair{1, 6}, std::pair{16, 16},
                        std::pair{13, 6}, std::pair{64, 1}, std::pair{37, 23}}) {
        ref::Texture t = texture_of(random_level(w, h, 1000 + w * 7 + h));
        ref::build_mipmaps(t);
        CHECK(t.mipmapped);
        // The sizes: max(1, floor(n / 2)) down to 1x1.
        int ew = w, eh = h;
        std::size_t count = 1;
        while (ew > 1 || eh > 1) {
            ew = std::max(1, ew / 2);
            eh = std::max(1, eh / 2);
            ++count;
        }
        REQUIRE(t.levels.size() == count);
        for (std::size_t k = 0; k < count; ++k) {
            const ref::Level expected = block_average_level(t.levels[0], int(k));
            INFO(w << "x" << h << ", level " << k);
            REQUIRE(t.levels[k].width == expected.width);
            REQUIRE(t.levels[k].height == expected.height);
            CHECK(t.levels[k].texels == expected.texels);  // exact in double
        }
        // Building again replaces the pyramid with the same one.
        ref::Texture again = t;
        ref::build_mipmaps(again);
        CHECK(again.levels.size() == count);
    }
}

TEST_CASE("the 3x5 pyramid by hand (an odd column and row dropped)", "[m5][mipmap][extreme]") {
    ref::Level base;
    base.width = 3;
    base.height = 5;
    for (int k = 0; k < 15; ++k) base.texels.push_back({double(k), 0, 0});  // texel (i, j) = 3 j + i
    ref::Texture t = texture_of(base);
    ref::build_mipmaps(t);
    REQUIRE(t.levels.size() == 3);
    // Level 1 is 1x2: columns 0 and 1 of rows 0-1 and 2-3 (column 2 and row 4 dropped).
    CHECK(t.levels[1].width == 1);
    CHECK(t.levels[1].height == 2);
    CHECK(t.levels[1].texels[0].x == (0 + 1 + 3 + 4) / 4.0);
    CHECK(t.levels[1].texels[1].x == (6 + 7 + 9 + 10) / 4.0);
    // Level 2 is 1x1: the two texels of level 1 (each column index clamped to 0).
    CHECK(t.levels[2].texels[0].x == (2 + 8) / 2.0);
}

// ---- TODO 4: level of detail and filtering ----

TEST_CASE("uv derivatives against finite differences of the exact perspective uv", "[m5][lod]") {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> pos(10, 300), wd(0.2, 20), uvd(-3, 3), bary(0.1, 0.8);
    int checked = 0;
    for (int k = 0; k < 300; ++k) {
        const std::array<Vec3, 3> s = {Vec3{pos(rng), pos(rng), 0}, Vec3{pos(rng), pos(rng), 0}, Vec3{pos(rng), pos(rng), 0}};
        const std::array<double, 3> w = {wd(rng), wd(rng), wd(rng)};
        const std::array<Vec2, 3> uv = {Vec2{uvd(rng), uvd(rng)}, Vec2{uvd(rng), uvd(rng)}, Vec2{uvd(rng), uvd(rng)}};
        // The exact uv at (x, y): screen weights from a 2x2 solve, then sum(l u / w) / sum(l / w).
        const double ax = s[1].x - s[0].x, bx = s[2].x - s[0].x, ay = s[1].y - s[0].y, by = s[2].y - s[0].y;
        const double det = ax * by - bx * ay;
        if (std::abs(det) < 100) continue;  // nearly degenerate: finite differences say little
        auto exact = [&](double x, double y) {
            const double l1 = ((x - s[0].x) * by - bx * (y - s[0].y)) / det, l2 = (ax * (y - s[0].y) - (x - s[0].x) * ay) / det;
            const double l[3] = {1 - l1 - l2, l1, l2};
            double a = 0, b = 0, c = 0;
            for (int i = 0; i < 3; ++i) {
                a += l[i] * uv[i].x / w[i];
                b += l[i] * uv[i].y / w[i];
                c += l[i] / w[i];
            }
            return Vec2{a / c, b / c};
        };
        // A point inside the triangle.
        double b1 = bary(rng), b2 = bary(rng);
        if (b1 + b2 > 0.9) b1 = 0.9 - b2 > 0.05 ? 0.9 - b2 : 0.05;
        const double x = s[0].x + b1 * ax + b2 * bx, y = s[0].y + b1 * ay + b2 * by;
        const double h = 1e-4;
        const Vec2 dx = (exact(x + h, y) - exact(x - h, y)) / (2 * h), dy = (exact(x, y + h) - exact(x, y - h)) / (2 * h);
        const ref::UvDerivatives d = ref::uv_derivatives(s, w, uv, x, y);
        const double scale = std::max({std::abs(dx.x), std::abs(dx.y), std::abs(dy.x), std::abs(dy.y)});
        INFO("triangle " << k);
        CHECK(close(d.du_dx, dx.x, 1e-6, 1e-7 * scale));
        CHECK(close(d.dv_dx, dx.y, 1e-6, 1e-7 * scale));
        CHECK(close(d.du_dy, dy.x, 1e-6, 1e-7 * scale));
        CHECK(close(d.dv_dy, dy.y, 1e-6, 1e-7 * scale));
        // lambda from them, against lambda from the finite differences.
        const double rho = std::max(std::hypot(64 * dx.x, 32 * dx.y), std::hypot(64 * dy.x, 32 * dy.y));
        CHECK(close(ref::level_of_detail(d, 64, 32), std::log2(rho), 1e-6, 1e-7));
        ++checked;
    }
    CHECK(checked > 200);
}

TEST_CASE("uv derivatives against a GLM ray cast through the pixel", "[m5][lod]") {
    // A floor triangle seen at a grazing angle, its screen positions from GLM's matrices.
    const int width = 320, height = 240;
    const View v = camera_view({0.5, 1.2, 5}, width, height);
    const glm::dvec3 p[3] = {{-3, 0, -8}, {3, 0, 2}, {-2, 0, 3}};
    const std::array<Vec2, 3> uv = {Vec2{0, 0}, Vec2{4, 1}, Vec2{0.5, 5}};
    std::array<Vec3, 3> screen;
    std::array<double, 3> w;
    for (int i = 0; i < 3; ++i) {
        const glm::dvec4 c = v.vp * glm::dvec4(p[i], 1);
        screen[i] = {(c.x / c.w + 1) / 2 * width, (1 - c.y / c.w) / 2 * height, c.z / c.w};
        w[i] = c.w;
    }
    auto cast = [&](double x, double y) {
        const glm::dvec3 b = ray_barycentric(pixel_ray(v.vp, x, y, width, height), p[0], p[1], p[2]);
        return uv[0] * b.x + uv[1] * b.y + uv[2] * b.z;
    };
    int checked = 0;
    for (int py = 0; py < height; py += 9) {
        for (int px = 0; px < width; px += 9) {
            const double x = px + 0.5, y = py + 0.5;
            const glm::dvec3 b = ray_barycentric(pixel_ray(v.vp, x, y, width, height), p[0], p[1], p[2]);
            if (b.x < 0.01 || b.y < 0.01 || b.z < 0.01) continue;  // inside the triangle only
            const double h = 1e-3;
            const Vec2 dx = (cast(x + h, y) - cast(x - h, y)) / (2 * h), dy = (cast(x, y + h) - cast(x, y - h)) / (2 * h);
            const ref::UvDerivatives d = ref::uv_derivatives(screen, w, uv, x, y);
            INFO("pixel " << px << ", " << py);
            CHECK(close(d.du_dx, dx.x, 1e-6, 1e-9));
            CHECK(close(d.dv_dx, dx.y, 1e-6, 1e-9));
            CHECK(close(d.du_dy, dy.x, 1e-6, 1e-9));
            CHECK(close(d.dv_dy, dy.y, 1e-6, 1e-9));
            ++checked;
        }
    }
    CHECK(checked > 100);
}

TEST_CASE("level of detail by hand, and degenerate triangles", "[m5][lod][extreme]") {
    // One texel per pixel across, two down: rho = 2, lambda = 1.
    CHECK(ref::level_of_detail({1.0 / 64, 0, 0, 2.0 / 32}, 64, 32) == Approx(1).epsilon(1e-12));
    // sqrt((64 * 3/64)^2 + (32 * 4/32)^2) = 5.
    CHECK(ref::level_of_detail({3.0 / 64, 4.0 / 32, 0, 0}, 64, 32) == Approx(std::log2(5.0)).epsilon(1e-12));
    CHECK(ref::level_of_detail({}, 64, 32) == -kInf);
    // An affine triangle (all w = 1): u = x / 10 exactly, so du/dx = 0.1 everywhere.
    const std::array<Vec3, 3> s = {Vec3{0, 0, 0}, Vec3{10, 0, 0}, Vec3{0, 10, 0}};
    const ref::UvDerivatives a = ref::uv_derivatives(s, {1, 1, 1}, {Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 2}}, 3, 3);
    CHECK(a.du_dx == Approx(0.1).epsilon(1e-12));
    CHECK(a.dv_dy == Approx(0.2).epsilon(1e-12));
    CHECK(std::abs(a.du_dy) < 1e-15);
    CHECK(std::abs(a.dv_dx) < 1e-15);
    // Zero area, B not > 0, w = 0, and equal uv (no change at all).
    auto zero = [](const ref::UvDerivatives& d) { return d.du_dx == 0 && d.dv_dx == 0 && d.du_dy == 0 && d.dv_dy == 0; };
    const std::array<Vec2, 3> uv = {Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}};
    CHECK(zero(ref::uv_derivatives({Vec3{0, 0, 0}, Vec3{5, 5, 0}, Vec3{10, 10, 0}}, {1, 2, 3}, uv, 3, 3)));
    CHECK(zero(ref::uv_derivatives(s, {-1, -1, -1}, uv, 3, 3)));
    CHECK(zero(ref::uv_derivatives(s, {0, 1, 1}, uv, 3, 3)));
    // Equal uv: u is constant, its derivatives exactly zero (the reference takes uv relative to
    // vertex 0), lambda -infinity: magnification.
    CHECK(zero(ref::uv_derivatives(s, {1, 2, 3}, {Vec2{0.3, 0.3}, Vec2{0.3, 0.3}, Vec2{0.3, 0.3}}, 3, 3)));
    CHECK(ref::level_of_detail(ref::uv_derivatives(s, {1, 2, 3}, {Vec2{0.3, 0.3}, Vec2{0.3, 0.3}, Vec2{0.3, 0.3}}, 3, 3), 8, 8) == -kInf);
}

TEST_CASE("the filters against the block-average pyramid and tent sums", "[m5][filter]") {
    const ref::Level base = random_level(16, 8, 77);
    std::vector<ref::Level> pyramid;
    for (int k = 0; k < 5; ++k) pyramid.push_back(block_average_level(base, k));
    const Vec2 uv{0.37, -1.23};
    auto bil = [&](int k) { return tent_sum(pyramid[k], uv, Wrap::kRepeat, Wrap::kMirroredRepeat); };
    long long builds = 0;
    ref::Texture t = texture_of(base, Wrap::kRepeat, Wrap::kMirroredRepeat);
    // Magnification and the non-mip filters: level 0, no pyramid.
    CHECK(close(ref::sample(t, uv, 3, ref::Filter::kBilinear, &builds), bil(0), 1e-12, 1e-9));
    CHECK(ref::sample(t, uv, 3, ref::Filter::kNearest, &builds) == ref::sample_nearest(base, uv, Wrap::kRepeat, Wrap::kMirroredRepeat));
    for (double lambda : {0.0, -2.0, kNaN, -kInf}) {
        CHECK(close(ref::sample(t, uv, lambda, ref::Filter::kTrilinear, &builds), bil(0), 1e-12, 1e-9));
        CHECK(close(ref::sample(t, uv, lambda, ref::Filter::kNearestMip, &builds), bil(0), 1e-12, 1e-9));
    }
    CHECK(builds == 0);
    CHECK(t.levels.size() == 1);
    // Minification: the pyramid is built once and counted once.
    CHECK(close(ref::sample(t, uv, 1.3, ref::Filter::kTrilinear, &builds), bil(1) * 0.7 + bil(2) * 0.3, 1e-12, 1e-9));
    CHECK(builds == 1);
    CHECK(close(ref::sample(t, uv, 1.49, ref::Filter::kNearestMip, &builds), bil(1), 1e-12, 1e-9));
    CHECK(close(ref::sample(t, uv, 1.5, ref::Filter::kNearestMip, &builds), bil(2), 1e-12, 1e-9));
    CHECK(close(ref::sample(t, uv, 0.2, ref::Filter::kNearestMip, &builds), bil(0), 1e-12, 1e-9));
    CHECK(close(ref::sample(t, uv, 3.75, ref::Filter::kTrilinear, &builds), bil(3) * 0.25 + bil(4) * 0.75, 1e-12, 1e-9));
    // Clamped to the last level (4: 16x8 -> 8x4 -> 4x2 -> 2x1 -> 1x1).
    for (double lambda : {4.0, 4.7, 100.0, kInf}) {
        CHECK(close(ref::sample(t, uv, lambda, ref::Filter::kTrilinear, &builds), bil(4), 1e-12, 1e-9));
        CHECK(close(ref::sample(t, uv, lambda, ref::Filter::kNearestMip, &builds), bil(4), 1e-12, 1e-9));
    }
    CHECK(builds == 1);
    // A 1x1 texture: every filter gives its one texel.
    ref::Texture one = texture_of(random_level(1, 1, 9));
    const Vec3 only = one.levels[0].texels[0];
    for (double lambda : {-3.0, 0.0, 0.5, 7.0}) {
        for (auto f : {ref::Filter::kNearest, ref::Filter::kBilinear, ref::Filter::kNearestMip, ref::Filter::kTrilinear}) {
            CHECK(close(ref::sample(one, {0.3, 12.9}, lambda, f, &builds), only, 1e-14));
        }
    }
    CHECK(builds == 2);  // the 1x1 one built its (one-level) pyramid once
    CHECK(one.levels.size() == 1);
}

// ---- TODO 6: Blinn-Phong ----

TEST_CASE("Blinn-Phong by hand", "[m5][phong]") {
    // N = (0, 0, 1), L = (0.6, 0, 0.8), V = (0, 0, 1), none given with length 1: c = 0.8,
    // H = (0.6, 0, 1.8) / sqrt(3.6), N.H = 3 / sqrt(10), to the 4th: 0.81.
    const Vec3 r = ref::blinn_phong({200, 100, 50}, {100, 100, 100}, 4, {0, 0, 5}, {0, 0, 0.1}, {3, 0, 4}, {1, 0.5, 2});
    CHECK(r.x == Approx(200 * 0.8 + 81).epsilon(1e-12));
    CHECK(r.y == Approx(100 * 0.8 * 0.5 + 40.5).epsilon(1e-12));
    CHECK(r.z == Approx(50 * 0.8 * 2 + 162).epsilon(1e-12));
    // No specular color: the diffuse alone.
    const Vec3 d = ref::blinn_phong({200, 100, 50}, {}, 4, {0, 0, 5}, {0, 0, 0.1}, {3, 0, 4}, {1, 0.5, 2});
    CHECK(d.x == Approx(160).epsilon(1e-12));
    // The light behind the surface (or grazing it) adds nothing at all, not even a highlight
    // that H alone would allow; nor does a zero normal, light or eye vector.
    CHECK(ref::blinn_phong({200, 200, 200}, {255, 255, 255}, 2, {0, 0, 1}, {0, 0.9, 0.1}, {0, -1, -0.01}, {1, 1, 1}) == Vec3{});
    CHECK(ref::blinn_phong({200, 200, 200}, {255, 255, 255}, 2, {0, 0, 1}, {0, 0, 1}, {1, 0, 0}, {1, 1, 1}) == Vec3{});
    CHECK(ref::blinn_phong({200, 200, 200}, {255, 255, 255}, 2, {}, {0, 0, 1}, {0, 0, 1}, {1, 1, 1}) == Vec3{});
    CHECK(ref::blinn_phong({200, 200, 200}, {255, 255, 255}, 2, {0, 0, 1}, {0, 0, 1}, {}, {1, 1, 1}) == Vec3{});
    CHECK(ref::blinn_phong({200, 200, 200}, {255, 255, 255}, 2, {0, 0, 1}, {}, {0, 0, 1}, {1, 1, 1}) == Vec3{});
    // An infinite light never meets a zero factor: no NaN.
    const Vec3 big = ref::blinn_phong({200, 200, 200}, {255, 255, 255}, 8, {0, 0, 1}, {1, 0, -1}, {-1, 0, 1}, {kInf, kInf, kInf});
    CHECK_FALSE(std::isnan(big.x));
}

// ---- TODO 7: tangent-space normal maps ----

TEST_CASE("the tangent frame solves its 2x2 system", "[m5][tangent]") {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> c(-4, 4);
    for (int k = 0; k < 500; ++k) {
        const Vec3 p0{c(rng), c(rng), c(rng)}, p1{c(rng), c(rng), c(rng)}, p2{c(rng), c(rng), c(rng)};
        const Vec2 uv0{c(rng), c(rng)}, uv1{c(rng), c(rng)}, uv2{c(rng), c(rng)};
        const ref::TangentFrame f = ref::tangent_frame(p0, p1, p2, uv0, uv1, uv2);
        REQUIRE(f.valid);
        // [e1 e2] = [T B] M with M = [[du1 du2] [dv1 dv2]]: [T B] = [e1 e2] M^-1, by GLM.
        const glm::dmat2 m(glm::dvec2(uv1.x - uv0.x, uv1.y - uv0.y), glm::dvec2(uv2.x - uv0.x, uv2.y - uv0.y));
        const glm::dmat2 inv = glm::inverse(m);
        const glm::dvec3 e1 = g(p1 - p0), e2 = g(p2 - p0);
        const glm::dvec3 t = e1 * inv[0][0] + e2 * inv[0][1], b = e1 * inv[1][0] + e2 * inv[1][1];
        const double scale = glm::length(t) + glm::length(b);
        INFO("triangle " << k);
        CHECK(glm::length(g(f.tangent) - t) <= 1e-9 * scale);
        CHECK(glm::length(g(f.bitangent) - b) <= 1e-9 * scale);
        // And the defining equations themselves: e1 = T du1 + B dv1, e2 = T du2 + B dv2.
        CHECK(raster::length(f.tangent * (uv1.x - uv0.x) + f.bitangent * (uv1.y - uv0.y) - (p1 - p0)) <= 1e-9 * scale);
        CHECK(raster::length(f.tangent * (uv2.x - uv0.x) + f.bitangent * (uv2.y - uv0.y) - (p2 - p0)) <= 1e-9 * scale);
    }
    // No frame: all three uv equal, uv on a line, NaN uv.
    for (auto uvs : {std::array<Vec2, 3>{Vec2{0.3, 0.3}, Vec2{0.3, 0.3}, Vec2{0.3, 0.3}},
                     std::array<Vec2, 3>{Vec2{0, 0}, Vec2{1, 1}, Vec2{2, 2}}, std::array<Vec2, 3>{Vec2{kNaN, 0}, Vec2{1, 0}, Vec2{0, 1}},
                     std::array<Vec2, 3>{Vec2{kInf, 0}, Vec2{1, 0}, Vec2{0, 1}}}) {
        const ref::TangentFrame f = ref::tangent_frame({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, uvs[0], uvs[1], uvs[2]);
        CHECK_FALSE(f.valid);
        CHECK(f.tangent == Vec3{});
        CHECK(f.bitangent == Vec3{});
    }
}

TEST_CASE("perturb_normal by hand", "[m5][tangent]") {
    // n = z; T = (2, 0, 1) orthonormalizes to x; cross(n, x) = y, but B points down -y: B' = -y.
    ref::TangentFrame f;
    f.tangent = {2, 0, 1};
    f.bitangent = {0, -3, 0.5};
    f.valid = true;
    const Vec3 n{0, 0, 1};
    // Texel (255, 0, 127.5) is (1, -1, 0): T' - B' = (1, 1, 0), normalized.
    const Vec3 r = ref::perturb_normal(f, n, {255, 0, 127.5});
    CHECK(close(r, Vec3{std::sqrt(0.5), std::sqrt(0.5), 0}, 1e-12, 1e-12));
    // The flat texel keeps n; a pure red texel gives T'.
    CHECK(close(ref::perturb_normal(f, n, {127.5, 127.5, 255}), n, 1e-12, 1e-12));
    CHECK(close(ref::perturb_normal(f, n, {255, 127.5, 127.5}), Vec3{1, 0, 0}, 1e-12, 1e-12));
    CHECK(close(ref::perturb_normal(f, n, {127.5, 255, 127.5}), Vec3{0, -1, 0}, 1e-12, 1e-12));
    // No frame, a tangent along n, a zero result, non-finite input: n unchanged.
    CHECK(ref::perturb_normal(ref::TangentFrame{}, n, {255, 0, 0}) == n);
    ref::TangentFrame along = f;
    along.tangent = {0, 0, 3};
    CHECK(ref::perturb_normal(along, n, {255, 0, 0}) == n);
    CHECK(ref::perturb_normal(f, n, {127.5, 127.5, 127.5}) == n);
    CHECK(ref::perturb_normal(f, n, {kNaN, 0, 0}) == n);
    // A random texel gives a unit vector in the span of T', B', n.
    const Vec3 q = ref::perturb_normal(f, n, {10, 200, 180});
    CHECK(raster::length(q) == Approx(1).epsilon(1e-12));
}

// ---- TODO 8: shadow mapping ----

namespace {

// The oracle's shadow: does the ray from p toward the light (-direction) cross the blocker
// square (y = 1, |x|, |z| <= 1)? margin: how far the crossing is from the square's border.
bool ray_blocked(glm::dvec3 p, glm::dvec3 direction, double& margin) {
    const glm::dvec3 l = -glm::normalize(direction);
    if (l.y <= 0 || p.y >= 1) {
        margin = 1e9;
        return false;
    }
    const glm::dvec3 q = p + l * ((1 - p.y) / l.y);
    margin = std::abs(std::max(std::abs(q.x), std::abs(q.z)) - 1);
    return std::abs(q.x) <= 1 && std::abs(q.z) <= 1;
}

ref::ShadowMap make_map(const std::vector<const m4r::Mesh*>& meshes, Vec3 direction, const ref::ShadowSettings& s) {
    ref::ShadowMap map;
    map.light = ref::light_view_projection(direction, s);
    map.radius = s.radius;
    map.resolution = s.resolution;
    m4r::Frame f = new_frame(s.resolution, s.resolution);
    m4r::Needs needs;
    needs.depth_test = true;
    for (const m4r::Mesh* m : meshes) m4r::draw_mesh(f, *m, m3r::identity(), map.light, m3r::identity(), {}, {255, 255, 255}, needs);
    map.keys = f.depth;
    return map;
}

}  // namespace

TEST_CASE("the light's matrix against GLM", "[m5][shadow]") {
    ref::ShadowSettings s;
    s.center = {0.5, -1, 2};
    s.radius = 3;
    for (Vec3 d : {Vec3{0.3, -1, 0.2}, Vec3{0, -1, 0}, Vec3{1, 0.2, 0}}) {
        const glm::dvec3 dir = glm::normalize(g(d)), center = g(s.center);
        const glm::dvec3 up = std::abs(dir.y) > 0.99 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        const glm::dmat4 expected = glm::ortho(-3.0, 3.0, -3.0, 3.0, 3.0, 9.0) * glm::lookAt(center - dir * 6.0, center, up);
        const m3r::Mat4 got = ref::light_view_projection(d, s);
        for (int r = 0; r < 4; ++r) {
            for (int c = 0; c < 4; ++c) CHECK(std::abs(got.m[r][c] - expected[c][r]) < 1e-12);
        }
    }
    for (Vec3 d : {Vec3{}, Vec3{kNaN, -1, 0}, Vec3{kInf, 0, 0}}) {
        const m3r::Mat4 z = ref::light_view_projection(d, s);
        bool all_zero = true;
        for (auto& row : z.m) {
            for (double v : row) all_zero = all_zero && v == 0;
        }
        CHECK(all_zero);
    }
}

TEST_CASE("the shadow factor against a ray cast to the light", "[m5][shadow]") {
    const m4r::Mesh floor = floor_mesh(), blocker = blocker_mesh();
    ref::ShadowSettings s;
    s.resolution = 512;
    s.radius = 4;
    const Vec3 direction{0.3, -1, 0.2};
    const ref::ShadowMap map = make_map({&floor, &blocker}, direction, s);
    const double texel = 2 * s.radius / s.resolution;  // world units per texel, across the light
    int lit = 0, dark = 0;
    for (double z = -2.9; z <= 2.9; z += 0.0731) {
        for (double x = -2.9; x <= 2.9; x += 0.0731) {
            double margin = 0;
            const bool blocked = ray_blocked({x, 0, z}, g(direction), margin);
            if (margin < 4 * texel) continue;  // near the border the map's texels decide
            INFO("floor point " << x << ", " << z);
            s.pcf = false;
            REQUIRE(ref::shadow_factor(map, {x, 0, z}, {0, 1, 0}, direction, s) == (blocked ? 0.0 : 1.0));
            s.pcf = true;
            REQUIRE(ref::shadow_factor(map, {x, 0, z}, {0, 1, 0}, direction, s) == (blocked ? 0.0 : 1.0));
            (blocked ? dark : lit) += 1;
        }
    }
    CHECK(dark > 200);
    CHECK(lit > 2000);
    // The blocker's top is lit (its own depth, with the bias), and so is a point outside the map.
    s.pcf = false;
    CHECK(ref::shadow_factor(map, {0.2, 1, 0.3}, {0, 1, 0}, direction, s) == 1);
    CHECK(ref::shadow_factor(map, {40, 0, 0}, {0, 1, 0}, direction, s) == 1);
    CHECK(ref::shadow_factor(map, {kNaN, 0, 0}, {0, 1, 0}, direction, s) == 1);
    // Without any bias, the floor shadows itself here and there (acne); with it, never.
    ref::ShadowSettings no_bias = s;
    no_bias.constant_bias = no_bias.slope_bias = 0;
    const Vec3 grazing{1, -0.08, 0.1};
    const ref::ShadowMap graze = make_map({&floor}, grazing, s);
    int acne = 0, clean = 0;
    for (double x = -2.5; x <= 2.5; x += 0.05) {
        for (double z = -2.5; z <= 2.5; z += 0.05) {
            acne += ref::shadow_factor(graze, {x, 0, z}, {0, 1, 0}, grazing, no_bias) < 1;
            clean += ref::shadow_factor(graze, {x, 0, z}, {0, 1, 0}, grazing, s) < 1;
        }
    }
    CHECK(acne > 100);
    CHECK(clean == 0);
    // PCF at the border: a fraction in ninths.
    bool partial = false;
    s.pcf = true;
    for (double x = 0.5; x <= 2; x += 0.002) {
        const double f = ref::shadow_factor(map, {x, 0, 0.2}, {0, 1, 0}, direction, s);
        CHECK(std::abs(f * 9 - std::round(f * 9)) < 1e-12);
        partial = partial || (f > 0 && f < 1);
    }
    CHECK(partial);
    // A map of the zero matrix (a zero direction) or with no keys: lit.
    ref::ShadowMap none;
    CHECK(ref::shadow_factor(none, {0, 0, 0}, {0, 1, 0}, direction, s) == 1);
    const ref::ShadowMap zero = make_map({&floor, &blocker}, Vec3{}, s);
    CHECK(ref::shadow_factor(zero, {0, 0, 0}, {0, 1, 0}, direction, s) == 1);
}

// ---- TODO 5 and 9: the pipeline ----

TEST_CASE("the pipeline's texture coordinates against a GLM ray cast", "[m5][pipeline]") {
    // An unlit floor with an 8x8 texture (nearest, repeated twice across it): every pixel shows
    // the texel of the uv where its ray meets the floor, away from texel borders.
    const int width = 160, height = 120;
    const View v = camera_view({0.4, 2.2, 4.5}, width, height);
    const m4r::Mesh floor = floor_mesh();
    ref::Texture tex = texture_of(random_level(8, 8, 123));
    ref::Object o;
    o.mesh = &floor;
    o.material.texture = &tex;
    o.material.filter = ref::Filter::kNearest;
    o.material.lit = false;
    m4r::Frame frame = new_frame(width, height);
    const ref::Stats stats = ref::draw_scene(frame, {o}, v.camera, ref::Lighting{}, ref::ShadowSettings{});
    int checked = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const Ray ray = pixel_ray(v.vp, x + 0.5, y + 0.5, width, height);
            if (ray.direction.y >= 0) continue;
            const glm::dvec3 p = ray.origin + ray.direction * (-ray.origin.y / ray.direction.y);
            if (std::abs(p.x) > 2.95 || std::abs(p.z) > 2.95) continue;
            const double tx = (p.x + 3) / 3 * 8, ty = (p.z + 3) / 3 * 8;  // in texels
            if (std::abs(tx - std::round(tx)) < 0.1 || std::abs(ty - std::round(ty)) < 0.1) continue;
            const Vec3 t = texel_walked(tex.levels[0], static_cast<long long>(std::floor(tx)), static_cast<long long>(std::floor(ty)),
                                        Wrap::kRepeat, Wrap::kRepeat);
            INFO("pixel " << x << ", " << y);
            REQUIRE(frame.color.at(x, y) == Color{std::uint8_t(t.x), std::uint8_t(t.y), std::uint8_t(t.z)});
            ++checked;
        }
    }
    CHECK(checked > 5000);
    // Only what the scene needs: one sample per shaded fragment, no level of detail, no pyramid.
    CHECK(stats.texture_samples == stats.shaded);
    CHECK(stats.lod_computed == 0);
    CHECK(stats.mipmap_builds == 0);
    CHECK(stats.shadow_passes == 0);
    CHECK(stats.shadow_texels == 0);
    CHECK(stats.shadow_lookups == 0);
    CHECK(stats.specular_terms == 0);
}

TEST_CASE("the pipeline's shadow against a ray cast per pixel", "[m5][pipeline][shadow]") {
    const int width = 160, height = 120;
    const View v = camera_view({0.4, 4.5, 4.5}, width, height);
    const m4r::Mesh floor = floor_mesh(), blocker = blocker_mesh();
    const Vec3 direction{0.3, -1, 0.2};
    ref::Object f, b;
    f.mesh = &floor;
    b.mesh = &blocker;
    ref::Lighting lighting;
    lighting.lights.push_back({direction, {0.8, 0.8, 0.8}, true});
    ref::ShadowSettings s;
    s.pcf = false;
    m4r::Frame frame = new_frame(width, height);
    const ref::Stats stats = ref::draw_scene(frame, {f, b}, v.camera, lighting, s);
    const double c = glm::dot(glm::dvec3(0, 1, 0), -glm::normalize(g(direction)));
    const int lit_level = static_cast<int>(std::lround(200 * (0.1 + 0.8 * c))), dark_level = 20;
    int lit = 0, dark = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const Ray ray = pixel_ray(v.vp, x + 0.5, y + 0.5, width, height);
            if (ray.direction.y >= 0) continue;
            const glm::dvec3 p = ray.origin + ray.direction * (-ray.origin.y / ray.direction.y);
            if (std::abs(p.x) > 2.9 || std::abs(p.z) > 2.9) continue;
            // Skip pixels where the camera sees the blocker, or nearly.
            const glm::dvec3 q = ray.origin + ray.direction * ((1 - ray.origin.y) / ray.direction.y);
            if (std::abs(q.x) < 1.1 && std::abs(q.z) < 1.1) continue;
            double margin = 0;
            const bool blocked = ray_blocked(p, g(direction), margin);
            if (margin < 0.08) continue;
            INFO("pixel " << x << ", " << y);
            const Color got = frame.color.at(x, y);
            REQUIRE(std::abs(int(got.r) - (blocked ? dark_level : lit_level)) <= 1);
            (blocked ? dark : lit) += 1;
        }
    }
    CHECK(dark > 100);
    CHECK(lit > 2000);
    CHECK(stats.shadow_passes == 1);
    CHECK(stats.shadow_texels == 512LL * 512);
    CHECK(stats.shadow_lookups == stats.shaded);  // every visible surface faces the light
    CHECK(stats.texture_samples == 0);
    CHECK(stats.specular_terms == 0);
}

TEST_CASE("only what the scene needs, and a light behind everything", "[m5][pipeline]") {
    const int width = 96, height = 72;
    const View v = camera_view({0.4, 3, 4}, width, height);
    const m4r::Mesh floor = floor_mesh();
    ref::Texture tex = texture_of(random_level(64, 64, 4));
    ref::Object o;
    o.mesh = &floor;
    o.material.texture = &tex;
    o.material.filter = ref::Filter::kTrilinear;
    o.material.specular = {50, 50, 50};
    ref::Lighting below;
    below.lights.push_back({{0, 1, 0}, {1, 1, 1}, true});  // shines up from under the floor
    m4r::Frame frame = new_frame(width, height);
    const ref::Stats a = ref::draw_scene(frame, {o}, v.camera, below, ref::ShadowSettings{});
    CHECK(a.shadow_passes == 1);       // the light casts shadows: its pass runs
    CHECK(a.shadow_lookups == 0);      // but no surface faces it
    CHECK(a.specular_terms == 0);
    CHECK(a.lod_computed == a.shaded);
    CHECK(a.texture_samples == a.shaded);
    CHECK(a.mipmap_builds == 1);       // 64 texels over a few dozen pixels: minified
    // Every floor pixel shows the texture at ambient only: at most 0.1 * 255 + rounding.
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) CHECK(frame.color.at(x, y).r <= 26);
    }
    // Drawn again: the pyramid exists, nothing is built.
    frame = new_frame(width, height);
    const ref::Stats again = ref::draw_scene(frame, {o}, v.camera, below, ref::ShadowSettings{});
    CHECK(again.mipmap_builds == 0);
    // An untextured, unlit object with no shadow light: nothing but fragments.
    ref::Object plain;
    plain.mesh = &floor;
    plain.material.lit = false;
    frame = new_frame(width, height);
    const ref::Stats p = ref::draw_scene(frame, {plain}, v.camera, ref::Lighting{}, ref::ShadowSettings{});
    CHECK(p.shaded > 1000);
    CHECK(p.texture_samples + p.lod_computed + p.mipmap_builds + p.normal_map_samples + p.tangent_frames +
              p.specular_terms + p.shadow_lookups + p.shadow_passes + p.shadow_texels ==
          0);
    CHECK(frame.color.at(width / 2, height / 2 + 10) == Color{200, 200, 200});
}

TEST_CASE("an unlit material with a normal map makes no tangent frame and reads no normal map", "[m5][pipeline][needs]") {
    const int width = 64, height = 48;
    const View v = camera_view({0, 3, 3}, width, height);
    m4r::Mesh floor = floor_mesh();
    ref::Texture normals = texture_of(random_level(4, 4, 8));
    ref::Object o;
    o.mesh = &floor;
    o.material.lit = false;
    o.material.normal_map = &normals;
    ref::Lighting lighting;
    lighting.lights.push_back({{0.2, -1, -0.3}, {0.9, 0.9, 0.9}, false});
    m4r::Frame frame = new_frame(width, height);
    const ref::Stats s = ref::draw_scene(frame, {o}, v.camera, lighting, ref::ShadowSettings{});
    CHECK(s.shaded > 100);
    CHECK(s.tangent_frames == 0);
    CHECK(s.normal_map_samples == 0);
    CHECK(frame.color.at(width / 2, height / 2 + 10) == Color{200, 200, 200});
}

TEST_CASE("a normal-mapped floor with a degenerate uv mapping keeps its normal", "[m5][pipeline][extreme]") {
    const int width = 64, height = 48;
    const View v = camera_view({0, 3, 3}, width, height);
    m4r::Mesh floor = floor_mesh();
    floor.uvs = {{0.3, 0.3}, {0.3, 0.3}, {0.3, 0.3}, {0.3, 0.3}};  // no tangent frame anywhere
    ref::Level bumpy = random_level(4, 4, 8);
    ref::Texture normals = texture_of(bumpy);
    ref::Object o;
    o.mesh = &floor;
    o.material.normal_map = &normals;
    ref::Object flat = o;
    flat.material.normal_map = nullptr;
    ref::Lighting lighting;
    lighting.lights.push_back({{0.2, -1, -0.3}, {0.9, 0.9, 0.9}, false});
    m4r::Frame with = new_frame(width, height), without = new_frame(width, height);
    const ref::Stats a = ref::draw_scene(with, {o}, v.camera, lighting, ref::ShadowSettings{});
    ref::draw_scene(without, {flat}, v.camera, lighting, ref::ShadowSettings{});
    CHECK(a.tangent_frames == 2);
    CHECK(a.normal_map_samples == a.shaded);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) REQUIRE(with.color.at(x, y) == without.color.at(x, y));
    }
}

TEST_CASE("derivatives near u = 1e7 equal those of the same mapping near 0", "[m5][lod][extreme]") {
    // Adding a whole number to every u changes no derivative: the mapping near 1e7 must give
    // the numbers of the mapping near 0 (within 1e-6), which it cannot if it loses the digits.
    const std::array<Vec3, 3> s = {Vec3{10, 20, 0}, Vec3{200, 40, 0}, Vec3{60, 180, 0}};
    const std::array<double, 3> w = {1.5, 7, 3};
    const std::array<Vec2, 3> near0 = {Vec2{0.25, 0.5}, Vec2{1.75, 0.625}, Vec2{0.5, 2.125}};
    std::array<Vec2, 3> far = near0;
    for (Vec2& uv : far) uv = uv + Vec2{1e7, -1e7};
    for (double x = 40; x < 150; x += 13.7) {
        const ref::UvDerivatives a = ref::uv_derivatives(s, w, near0, x, 80), b = ref::uv_derivatives(s, w, far, x, 80);
        CHECK(close(a.du_dx, b.du_dx, 1e-6));
        CHECK(close(a.dv_dx, b.dv_dx, 1e-6));
        CHECK(close(a.du_dy, b.du_dy, 1e-6));
        CHECK(close(a.dv_dy, b.dv_dy, 1e-6));
        CHECK(close(ref::level_of_detail(a, 256, 256), ref::level_of_detail(b, 256, 256), 1e-6));
    }
}

TEST_CASE("bad input to the pipeline neither crashes nor draws NaN", "[m5][pipeline][extreme]") {
    const int width = 64, height = 48;
    const View v = camera_view({0.3, 3, 3}, width, height);
    m4r::Mesh nan_uv = floor_mesh(), huge_uv = floor_mesh(), zero_normals = floor_mesh();
    for (Vec2& uv : nan_uv.uvs) uv = {kNaN, 0.5};
    for (Vec2& uv : huge_uv.uvs) uv = uv * 1e300;
    for (Vec3& n : zero_normals.normals) n = {};
    ref::Texture tex = texture_of(random_level(3, 5, 6)), normals = texture_of(random_level(2, 2, 7)), empty;
    ref::Lighting lighting;
    lighting.lights.push_back({{0, 0, 0}, {1, 1, 1}, true});            // a zero direction that casts shadows
    lighting.lights.push_back({{0.1, -1, 0}, {kInf, kInf, kInf}, true});  // an infinite light
    for (auto filter : {ref::Filter::kNearest, ref::Filter::kTrilinear}) {
        for (const m4r::Mesh* mesh : {&nan_uv, &huge_uv, &zero_normals}) {
            for (ref::Texture* t : {&tex, &empty}) {
                ref::Object o;
                o.mesh = mesh;
                o.material.texture = t;
                o.material.filter = filter;
                o.material.normal_map = &normals;
                o.material.specular = {10, 10, 10};
                m4r::Frame frame = new_frame(width, height);
                ref::ShadowSettings s;
                s.resolution = 64;
                const ref::Stats stats = ref::draw_scene(frame, {o}, v.camera, lighting, s);
                CHECK(stats.shadow_passes == 2);
                CHECK(stats.shaded > 500);
                CHECK(frame.color.stray_writes() == 0);
            }
        }
    }
    // The NaN-uv floor, unlit: black (NaN samples black), never garbage.
    ref::Object o;
    o.mesh = &nan_uv;
    o.material.texture = &tex;
    o.material.lit = false;
    m4r::Frame frame = new_frame(width, height);
    ref::draw_scene(frame, {o}, v.camera, lighting, ref::ShadowSettings{});
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) CHECK(frame.color.at(x, y) == Color{0, 0, 0});
    }
    // A zero normal under a normal map stays zero; a resolution of 0 makes no map.
    ref::TangentFrame f;
    f.tangent = {1, 0, 0};
    f.bitangent = {0, 1, 0};
    f.valid = true;
    CHECK(ref::perturb_normal(f, {}, {255, 0, 0}) == Vec3{});
    ref::ShadowSettings none;
    none.resolution = 0;
    ref::Object plain;
    plain.mesh = &nan_uv;
    frame = new_frame(width, height);
    const ref::Stats s0 = ref::draw_scene(frame, {plain}, v.camera, lighting, none);
    CHECK(s0.shadow_passes == 0);
    CHECK(s0.shadow_lookups == 0);
}
