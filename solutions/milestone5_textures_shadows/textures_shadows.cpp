// BEGIN SOLUTION
// Milestone 5 reference solution. The student's skeleton,
// milestone5_textures_shadows/textures_shadows.cpp, is generated from this file by `make skeletons`.
// SKELETON: // Milestone 5: textures, specular light and shadows. Fill in the numbered TODOs;
// SKELETON: // textures_shadows.h says exactly what each function must do, and README.md walks
// SKELETON: // through them in order. Run `make check-m5` in your build folder to see which
// SKELETON: // checkpoints pass.
// END SOLUTION
#include "textures_shadows.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <utility>

#include "triangles.h"

namespace m5 {
inline namespace RASTER_FLAVOUR {

// ---- TODO 1: textures and wrapping ----

// BEGIN SOLUTION
namespace {

// A level whose texels are all there (a default Level, or a malformed one, has none).
inline bool has_texels(const Level& level) {
    return level.width > 0 && level.height > 0 &&
           level.texels.size() == static_cast<std::size_t>(level.width) * static_cast<std::size_t>(level.height);
}

// i mod m in [0, m), exactly, for a whole-number i and m <= 2^32. While |i| < 2^52 the quotient
// i / m cannot round across a whole number, so i - m floor(i / m) is exact, and several times
// faster than std::fmod (the common case: a texture repeated a few times); beyond, std::fmod,
// exact for any size but slow. (std::fmod keeps the sign of i: -1 mod n is -1, not n - 1.)
inline double positive_mod(double i, double m) {
    if (std::abs(i) < 0x1p52) return i - m * std::floor(i / m);
    const double r = std::fmod(i, m);
    return r < 0 ? r + m : r;
}

// wrap_index's body, inline: every bilinear sample wraps four indices.
inline double wrapped(double i, int n, Wrap mode) {
    if (!std::isfinite(i) || n < 1) return 0;
    if (i >= 0 && i < n) return i;  // inside the level already: every mode keeps it
    switch (mode) {
        case Wrap::kRepeat:
            return positive_mod(i, n);
        case Wrap::kClampToEdge:
            return i < 0 ? 0 : n - 1;
        case Wrap::kMirroredRepeat: {
            const double period = 2.0 * n;
            const double m = positive_mod(i, period);
            return m < n ? m : period - 1 - m;
        }
    }
    return 0;
}

// The texel at indices already wrapped into the level (whole numbers in [0, n - 1]).
inline const Vec3& texel_at(const Level& level, double i, double j) {
    return level.texels[static_cast<std::size_t>(j) * static_cast<std::size_t>(level.width) + static_cast<std::size_t>(i)];
}

// The index after a wrapped one: for repeat simply the next (or 0 past the end), one wrap
// instead of two; clamp and mirror may turn back, so they wrap i + 1 themselves.
inline double next_wrapped(double i, double wrapped_i, int n, Wrap mode) {
    if (mode == Wrap::kRepeat) return wrapped_i + 1 < n ? wrapped_i + 1 : 0;
    return wrapped(i + 1, n, mode);
}

// sample_bilinear's body, inline: the hot path of every filtered sample (trilinear reads two).
inline Vec3 bilinear(const Level& level, Vec2 uv, Wrap wrap_u, Wrap wrap_v) {
    if (!has_texels(level)) return {};
    const double x = uv.x * level.width - 0.5, y = uv.y * level.height - 0.5;
    if (!std::isfinite(x) || !std::isfinite(y)) return {};
    const double i = std::floor(x), j = std::floor(y);
    const double a = x - i, b = y - j;
    const double i0 = wrapped(i, level.width, wrap_u), i1 = next_wrapped(i, i0, level.width, wrap_u);
    const double j0 = wrapped(j, level.height, wrap_v), j1 = next_wrapped(j, j0, level.height, wrap_v);
    return texel_at(level, i0, j0) * ((1 - a) * (1 - b)) + texel_at(level, i1, j0) * (a * (1 - b)) +
           texel_at(level, i0, j1) * ((1 - a) * b) + texel_at(level, i1, j1) * (a * b);
}

}  // namespace
// END SOLUTION

double wrap_index(double i, int n, Wrap mode) {
    // TODO 1a: repeat, clamp to edge and mirrored repeat on a whole-number index, in double
    // (std::fmod): converting a huge i to an int would overflow. Mind negative i: std::fmod
    // keeps the sign of i, so -1 mod n comes out as -1, not n - 1.
    // BEGIN SOLUTION
    return wrapped(i, n, mode);
    // SKELETON: return 0;
    // END SOLUTION
}

Vec3 fetch(const Level& level, double i, double j, Wrap wrap_u, Wrap wrap_v) {
    // TODO 1b: wrap both indices, then read texels[j * width + i]. Black for an empty level.
    // BEGIN SOLUTION
    if (!has_texels(level)) return {};
    // floor: an index that is not whole (the header asks for whole ones) still lands inside.
    return texel_at(level, wrapped(std::floor(i), level.width, wrap_u), wrapped(std::floor(j), level.height, wrap_v));
    // SKELETON: return {};
    // END SOLUTION
}

// ---- TODO 2: nearest and bilinear sampling ----

Vec3 sample_nearest(const Level& level, Vec2 uv, Wrap wrap_u, Wrap wrap_v) {
    // TODO 2a: texel units x = u * width, y = v * height; a NaN or infinite one is black.
    // BEGIN SOLUTION
    if (!has_texels(level)) return {};
    const double x = std::floor(uv.x * level.width), y = std::floor(uv.y * level.height);
    if (!std::isfinite(x) || !std::isfinite(y)) return {};
    return texel_at(level, wrapped(x, level.width, wrap_u), wrapped(y, level.height, wrap_v));
    // SKELETON: return {};
    // END SOLUTION
}

Vec3 sample_bilinear(const Level& level, Vec2 uv, Wrap wrap_u, Wrap wrap_v) {
    // TODO 2b: texel centers are at half-integers: shift by 0.5 before taking floor and
    // fraction, then blend the four texels around the point (each index wrapped).
    // BEGIN SOLUTION
    return bilinear(level, uv, wrap_u, wrap_v);
    // SKELETON: return {};
    // END SOLUTION
}

// ---- TODO 3: mipmaps ----

void build_mipmaps(Texture& texture) {
    // TODO 3: keep level 0, then halve (max(1, floor(n / 2)) per side) and average 2x2 blocks
    // until the level is 1x1. Mind odd sizes: the last row or column is dropped, and a side
    // of 1 texel clamps its index. Set texture.mipmapped.
    // BEGIN SOLUTION
    if (texture.levels.empty() || !has_texels(texture.levels[0])) return;
    texture.levels.resize(1);
    int count = 1;  // levels in the pyramid, so that push_back never moves them mid-build
    for (int w = texture.levels[0].width, h = texture.levels[0].height; w > 1 || h > 1; ++count) {
        w = std::max(1, w / 2);
        h = std::max(1, h / 2);
    }
    texture.levels.reserve(count);
    while (texture.levels.size() < static_cast<std::size_t>(count)) {
        const Level& src = texture.levels.back();
        Level dst;
        dst.width = std::max(1, src.width / 2);
        dst.height = std::max(1, src.height / 2);
        dst.texels.resize(static_cast<std::size_t>(dst.width) * static_cast<std::size_t>(dst.height));
        for (int j = 0; j < dst.height; ++j) {
            const int y0 = 2 * j, y1 = std::min(2 * j + 1, src.height - 1);
            for (int i = 0; i < dst.width; ++i) {
                const int x0 = 2 * i, x1 = std::min(2 * i + 1, src.width - 1);
                // Exact: the levels are sums of at most 2^28 base texels divided by powers of 4.
                dst.texels[static_cast<std::size_t>(j) * dst.width + i] =
                    (texel_at(src, x0, y0) + texel_at(src, x1, y0) + texel_at(src, x0, y1) + texel_at(src, x1, y1)) * 0.25;
            }
        }
        texture.levels.push_back(std::move(dst));
    }
    texture.mipmapped = true;
    // END SOLUTION
}

// ---- TODO 4: level of detail and filtering ----

// BEGIN SOLUTION
namespace {

// The three planes of the perspective-correct uv over the screen: U = (u - u0) / w,
// V = (v - v0) / w and Q = 1 / w are affine in x and y (sums of the screen weights, which
// are). Each is stored as its value at vertex 0 and its two slopes, so fill_triangle builds
// them once per triangle and evaluates them per pixel with six multiply-adds. Taking uv
// relative to vertex 0 changes no derivative, but keeps the digits: near u = 1e7, U_x Q - U Q_x
// would subtract two numbers of about 1e7 to leave one of about 0.01, and equal uv give
// exactly zero.
struct UvPlanes {
    double x0 = 0, y0 = 0;
    double u = 0, u_x = 0, u_y = 0;
    double v = 0, v_x = 0, v_y = 0;
    double q = 0, q_x = 0, q_y = 0;
    bool valid = false;  // false for a triangle of zero (or non-finite) area
};

UvPlanes uv_planes(const std::array<Vec2, 3>& p, const std::array<double, 3>& w, const std::array<Vec2, 3>& uv) {
    UvPlanes planes;
    const double area2 = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[1].y - p[0].y) * (p[2].x - p[0].x);
    if (area2 == 0 || !std::isfinite(area2)) return planes;
    // The slopes of the screen weights: l0 = edge(p1, p2, .) / area2, l1 = edge(p2, p0, .) /
    // area2, l2 = edge(p0, p1, .) / area2, and d edge(a, b, .) / dx = -(b.y - a.y),
    // d edge(a, b, .) / dy = b.x - a.x.
    const double lx[3] = {-(p[2].y - p[1].y) / area2, -(p[0].y - p[2].y) / area2, -(p[1].y - p[0].y) / area2};
    const double ly[3] = {(p[2].x - p[1].x) / area2, (p[0].x - p[2].x) / area2, (p[1].x - p[0].x) / area2};
    const double q[3] = {1 / w[0], 1 / w[1], 1 / w[2]};
    planes.x0 = p[0].x;
    planes.y0 = p[0].y;
    planes.q = q[0];  // U and V are 0 at vertex 0
    for (int i = 1; i < 3; ++i) {
        const double u = (uv[i].x - uv[0].x) * q[i], v = (uv[i].y - uv[0].y) * q[i];
        planes.u_x += lx[i] * u;
        planes.u_y += ly[i] * u;
        planes.v_x += lx[i] * v;
        planes.v_y += ly[i] * v;
    }
    for (int i = 0; i < 3; ++i) {
        planes.q_x += lx[i] * q[i];
        planes.q_y += ly[i] * q[i];
    }
    planes.valid = true;
    return planes;
}

// lambda = log2(rho) = log2(max(rho_x^2, rho_y^2)) / 2: one logarithm and no square root.
// (Squaring first overflows or underflows exactly where the square roots' arguments would.)
inline double lod(const UvDerivatives& d, int width, int height) {
    const double ux = width * d.du_dx, vx = height * d.dv_dx, uy = width * d.du_dy, vy = height * d.dv_dy;
    const double rx2 = ux * ux + vx * vx, ry2 = uy * uy + vy * vy;
    if (std::isnan(rx2) || std::isnan(ry2)) return std::numeric_limits<double>::quiet_NaN();
    return 0.5 * std::log2(std::max(rx2, ry2));  // log2(0) is -infinity
}

// The quotient rule at (x, y): du/dx = (U_x Q - U Q_x) / Q^2, and likewise (u = u0 + U / Q).
inline UvDerivatives derivatives_at(const UvPlanes& planes, double x, double y) {
    if (!planes.valid) return {};
    const double dx = x - planes.x0, dy = y - planes.y0;
    const double q = planes.q + planes.q_x * dx + planes.q_y * dy;
    if (!(q > 0) || !std::isfinite(q)) return {};
    const double u = planes.u + planes.u_x * dx + planes.u_y * dy;
    const double v = planes.v + planes.v_x * dx + planes.v_y * dy;
    const double inv_q2 = 1 / (q * q);
    return {(planes.u_x * q - u * planes.q_x) * inv_q2, (planes.v_x * q - v * planes.q_x) * inv_q2,
            (planes.u_y * q - u * planes.q_y) * inv_q2, (planes.v_y * q - v * planes.q_y) * inv_q2};
}

}  // namespace
// END SOLUTION

UvDerivatives uv_derivatives(const std::array<Vec3, 3>& screen, const std::array<double, 3>& w,
                             const std::array<Vec2, 3>& uv, double x, double y) {
    // TODO 4a: the planes A = sum l_i u_i / w_i (and for v) and B = sum l_i / w_i are affine
    // in x and y: find their slopes from the screen weights' slopes (edge functions divided by
    // twice the area), then the quotient rule (A_x B - A B_x) / B^2.
    // BEGIN SOLUTION
    return derivatives_at(uv_planes({Vec2{screen[0].x, screen[0].y}, Vec2{screen[1].x, screen[1].y},
                                     Vec2{screen[2].x, screen[2].y}},
                                    w, uv),
                          x, y);
    // SKELETON: return {};
    // END SOLUTION
}

double level_of_detail(const UvDerivatives& d, int width, int height) {
    // TODO 4b: rho from the derivatives in TEXELS (times width and height), lambda = log2(rho).
    // BEGIN SOLUTION
    return lod(d, width, height);
    // SKELETON: return 0;
    // END SOLUTION
}

Vec3 sample(Texture& texture, Vec2 uv, double lambda, Filter filter, long long* mipmap_builds) {
    // TODO 4c: kNearest and kBilinear read level 0; the mip filters magnify with bilinear on
    // level 0 when lambda <= 0 (or NaN), else build the pyramid if there is none (count it;
    // free where only level 0 is read, see the header), clamp lambda to the last level and read
    // one level (kNearestMip) or blend two.
    // BEGIN SOLUTION
    if (texture.levels.empty() || !has_texels(texture.levels[0])) return {};
    if (filter == Filter::kNearest) return sample_nearest(texture.levels[0], uv, texture.wrap_u, texture.wrap_v);
    const bool mip = filter == Filter::kNearestMip || filter == Filter::kTrilinear;
    if (!mip || !(lambda > 0)) return bilinear(texture.levels[0], uv, texture.wrap_u, texture.wrap_v);
    if (!texture.mipmapped) {
        build_mipmaps(texture);
        if (mipmap_builds) ++*mipmap_builds;
    }
    const std::size_t last = texture.levels.size() - 1;
    const double clamped = std::min(lambda, static_cast<double>(last));  // > 0, at most last
    if (filter == Filter::kNearestMip) {
        const auto k = static_cast<std::size_t>(std::floor(clamped + 0.5));
        return bilinear(texture.levels[k], uv, texture.wrap_u, texture.wrap_v);
    }
    const auto k = static_cast<std::size_t>(std::floor(clamped));
    const double fraction = clamped - static_cast<double>(k);
    const Vec3 lower = bilinear(texture.levels[k], uv, texture.wrap_u, texture.wrap_v);
    if (k == last || fraction == 0) return lower;  // no next level, or none needed
    const Vec3 upper = bilinear(texture.levels[k + 1], uv, texture.wrap_u, texture.wrap_v);
    return lower * (1 - fraction) + upper * fraction;
    // SKELETON: return {};
    // END SOLUTION
}

// ---- TODO 6: Blinn-Phong ----

// BEGIN SOLUTION
namespace {

// normalize, but the zero vector for a zero or non-finite vector.
inline Vec3 unit_or_zero(Vec3 v) {
    const double len = raster::length(v);
    if (!(len > 0) || !std::isfinite(len)) return {};
    return v * (1 / len);
}

inline Vec3 times(Vec3 a, Vec3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }

// m4::to_color, inline (milestone 4's reference inlines it the same way): called out of line
// for every fragment, returning the three-byte Color through memory cost more than all the
// rest of a plain fragment. Clamp to [0, 255], then round to nearest; a NaN gives 0.
inline std::uint8_t channel(double v) { return static_cast<std::uint8_t>(std::min(std::max(0.0, v), 255.0) + 0.5); }
inline Color color_of(Vec3 levels) { return {channel(levels.x), channel(levels.y), channel(levels.z)}; }

// m4::depth_key(kFloatZ, z, 1), inline, for the same reason: NaN is kClearKey, else the float
// of (z + 1) / 2 clamped to [0, 1].
inline std::uint32_t float_z_key(double z) {
    if (std::isnan(z)) return m4::kClearKey;
    return std::bit_cast<std::uint32_t>(static_cast<float>(std::clamp((z + 1) / 2, 0.0, 1.0)));
}

// x^s: a whole-number exponent up to 1024 (the usual shininess) by repeated squaring, a few
// multiplications instead of std::pow's logarithm and exponential; any other by std::pow.
inline double power(double x, double s) {
    if (!(s >= 0 && s <= 1024 && s == std::floor(s))) return std::pow(x, s);
    double result = 1;
    for (unsigned e = static_cast<unsigned>(s); e != 0; e >>= 1, x *= x) {
        if (e & 1u) result *= x;
    }
    return result;
}

// blinn_phong's body for n, v and l already unit (or zero), with c = dot(n, l) > 0 known:
// fill_triangle normalizes each of them once per fragment, not once per light.
inline Vec3 lit_by(Vec3 base, Vec3 specular, double shininess, Vec3 n, Vec3 v, Vec3 l, double c, Vec3 intensity) {
    Vec3 levels = times(base, intensity) * c;
    if (!(specular == Vec3{})) {
        const Vec3 h = unit_or_zero(l + v);
        const double s = power(std::max(0.0, raster::dot(n, h)), shininess);
        if (s > 0) levels = levels + times(specular, intensity) * s;  // s = 0: nothing (even for I = inf)
    }
    return levels;
}

}  // namespace
// END SOLUTION

Vec3 blinn_phong(Vec3 base, Vec3 specular, double shininess, Vec3 normal, Vec3 to_eye, Vec3 to_light, Vec3 intensity) {
    // TODO 6: normalize N, V and L; nothing at all when dot(N, L) <= 0; else the diffuse
    // base * c * I plus specular * max(0, dot(N, H))^shininess * I with H = normalize(L + V).
    // BEGIN SOLUTION
    const Vec3 n = unit_or_zero(normal), v = unit_or_zero(to_eye), l = unit_or_zero(to_light);
    const double c = raster::dot(n, l);
    // A light behind the surface adds nothing; a zero N, L (so c = 0) or V adds nothing either.
    if (!(c > 0) || v == Vec3{}) return {};
    return lit_by(base, specular, shininess, n, v, l, c, intensity);
    // SKELETON: return {};
    // END SOLUTION
}

// ---- TODO 7: tangent-space normal maps ----

TangentFrame tangent_frame(Vec3 p0, Vec3 p1, Vec3 p2, Vec2 uv0, Vec2 uv1, Vec2 uv2) {
    // TODO 7a: solve [e1 e2] = [T B] [[du1 du2] [dv1 dv2]] for T and B (Cramer's rule with the
    // determinant r); no frame when r is 0 or the result is not finite.
    TangentFrame frame;
    // BEGIN SOLUTION
    const Vec3 e1 = p1 - p0, e2 = p2 - p0;
    const double du1 = uv1.x - uv0.x, dv1 = uv1.y - uv0.y, du2 = uv2.x - uv0.x, dv2 = uv2.y - uv0.y;
    const double r = du1 * dv2 - du2 * dv1;
    if (r == 0 || !std::isfinite(r)) return frame;
    const Vec3 t = (e1 * dv2 - e2 * dv1) / r, b = (e2 * du1 - e1 * du2) / r;
    if (!raster::is_finite(t) || !raster::is_finite(b)) return frame;
    frame = {t, b, true};
    // END SOLUTION
    return frame;
}

Vec3 perturb_normal(const TangentFrame& frame, Vec3 n, Vec3 texel) {
    // TODO 7b: Gram-Schmidt T against n, B' = cross(n, T') (flipped to agree with B), the
    // texel from [0, 255] to [-1, 1], and the mapped vector to world space, normalized.
    // BEGIN SOLUTION
    if (!frame.valid || !raster::is_finite(n) || n == Vec3{} || !raster::is_finite(texel)) return n;
    const Vec3 t = unit_or_zero(frame.tangent - n * raster::dot(n, frame.tangent));
    if (t == Vec3{}) return n;
    Vec3 b = raster::cross(n, t);
    if (raster::dot(b, frame.bitangent) < 0) b = -b;
    const Vec3 m = texel * 2.0 / 255 - Vec3{1, 1, 1};  // in this order, the texel 127.5 maps to 0 exactly
    const Vec3 mapped = unit_or_zero(t * m.x + b * m.y + n * m.z);
    return mapped == Vec3{} ? n : mapped;
    // SKELETON: return {};
    // END SOLUTION
}

// ---- TODO 8: shadow mapping ----

Mat4 light_view_projection(Vec3 direction, const ShadowSettings& settings) {
    // TODO 8a: the eye 2r behind the center against the light's direction, looking at the
    // center, and an orthographic box of radius r from depth r to 3r.
    // BEGIN SOLUTION
    const Vec3 d = unit_or_zero(direction);
    if (d == Vec3{}) return Mat4{};
    const double r = settings.radius;
    const Vec3 eye = settings.center - d * (2 * r);
    const Vec3 up = std::abs(d.y) > 0.99 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    return m3::orthographic(-r, r, -r, r, r, 3 * r) * m3::look_at(eye, settings.center, up);
    // SKELETON: return Mat4{};
    // END SOLUTION
}

// BEGIN SOLUTION
namespace {

// shadow_factor's body, inline, with c = dot(n, L) given (fill_triangle has it already).
inline double lit_fraction(const ShadowMap& map, Vec3 p, double c, const ShadowSettings& settings) {
    const int res = map.resolution;
    if (res < 1 || map.keys.size() != static_cast<std::size_t>(res) * static_cast<std::size_t>(res)) return 1;
    // m3::to_screen(map.light * point(p), res, res), written out: this runs per fragment.
    const auto& m = map.light.m;
    const double cx = m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3];
    const double cy = m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3];
    const double cz = m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3];
    const double cw = m[3][0] * p.x + m[3][1] * p.y + m[3][2] * p.z + m[3][3];
    const Vec3 s{(cx / cw + 1) / 2 * res, (1 - cy / cw) / 2 * res, cz / cw};
    const double column = std::floor(s.x), row = std::floor(s.y);
    // Every texel of the 3x3 outside the map (or no position at all: NaN): lit. What passes
    // this test converts to int safely.
    if (!(column >= -1 && column <= res && row >= -1 && row <= res)) return 1;
    constexpr double kMaxSlope = 10;
    const double tan_theta = c > 0 ? std::sqrt(std::max(0.0, 1 - c * c)) / c : kMaxSlope;
    const double bias = settings.constant_bias + settings.slope_bias * std::min(tan_theta, kMaxSlope);
    const double depth = (s.z + 1) / 2 - bias / (2 * map.radius);
    // Lit unless the stored depth is nearer. kClearKey is a NaN as a float, so nothing drawn
    // there compares as lit without a test of its own; a NaN depth is lit too.
    auto lit = [&](std::size_t at) { return !(depth > static_cast<double>(std::bit_cast<float>(map.keys[at]))); };
    const int i = static_cast<int>(column), j = static_cast<int>(row);
    const std::size_t width = static_cast<std::size_t>(res);
    auto lit_at = [&](int ii, int jj) { return ii < 0 || jj < 0 || ii >= res || jj >= res || lit(static_cast<std::size_t>(jj) * width + ii); };
    if (!settings.pcf) return lit_at(i, j) ? 1 : 0;
    int count = 0;
    if (i >= 1 && j >= 1 && i + 1 < res && j + 1 < res) {  // all nine inside: no bounds to test
        std::size_t at = static_cast<std::size_t>(j - 1) * width + static_cast<std::size_t>(i - 1);
        for (int r = 0; r < 3; ++r, at += width) count += int(lit(at)) + int(lit(at + 1)) + int(lit(at + 2));
    } else {
        for (int dj = -1; dj <= 1; ++dj) {
            for (int di = -1; di <= 1; ++di) count += lit_at(i + di, j + dj) ? 1 : 0;
        }
    }
    return count / 9.0;
}

}  // namespace
// END SOLUTION

double shadow_factor(const ShadowMap& map, Vec3 p, Vec3 n, Vec3 direction, const ShadowSettings& settings) {
    // TODO 8b: p to the map's texel and depth d (m3::to_screen of map.light); the bias in world
    // units to depth units (divide by 2r); compare with the stored depth (the float of the key)
    // at one texel, or count the lit ones of the 3x3 around it with PCF.
    // BEGIN SOLUTION
    return lit_fraction(map, p, raster::dot(n, unit_or_zero(-direction)), settings);
    // SKELETON: return 1;
    // END SOLUTION
}

// ---- TODO 5: the textured, lit, shadowed triangle ----

// BEGIN SOLUTION
namespace {

// fill_triangle's work, from vertices already snapped: draw_scene snaps every position once
// (as milestone 4's draw_mesh does) rather than once per triangle that uses it, and passes
// pointers rather than copies of three vertices of fifteen doubles each.
void fill_snapped(Frame& frame, std::array<const ScreenVertex*, 3> p, std::array<m2::Fixed, 3> f, const FillState& state,
                  Stats& stats) {
    Image& img = frame.color;
    const int width = img.width(), height = img.height();
    if (!state.material || frame.depth.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) return;
    std::int64_t area2 = m2::edge(f[0], f[1], f[2]);
    if (area2 == 0) return;
    if (area2 < 0) {  // counter-clockwise on the screen, the whole vertex moving with its point
        std::swap(f[1], f[2]);
        std::swap(p[1], p[2]);
        area2 = -area2;
    }
    const ScreenVertex &a0 = *p[0], &a1 = *p[1], &a2 = *p[2];
    const m2::PixelRect box = m2::bounding_box(f[0], f[1], f[2], width, height);
    if (box.x0 >= box.x1 || box.y0 >= box.y1) return;

    // Milestone 4's incremental edge values: edge i runs from f[i] to f[i + 1]; top-left rule.
    constexpr std::int64_t S = m2::kSubpixelSteps;
    std::int64_t step_x[3], step_y[3], row[3], bias[3];
    const m2::Fixed start{std::int64_t(box.x0) * S + S / 2, std::int64_t(box.y0) * S + S / 2};
    for (int i = 0; i < 3; ++i) {
        const m2::Fixed a = f[i], b = f[i == 2 ? 0 : i + 1];
        bias[i] = (b.y == a.y && b.x > a.x) || b.y < a.y ? 0 : 1;
        step_x[i] = -(b.y - a.y) * S;
        step_y[i] = (b.x - a.x) * S;
        row[i] = m2::edge(a, b, start);
    }

    // Once per triangle: what the material needs, and the uv planes of the level of detail
    // (from the snapped positions, which the screen weights come from).
    const Material& material = *state.material;
    Texture* const texture = material.texture;
    const bool mip = texture && (material.filter == Filter::kNearestMip || material.filter == Filter::kTrilinear);
    const bool lit = material.lit && state.lighting;
    const Texture* const normal_map = lit ? material.normal_map : nullptr;
    const bool need_uv = texture || normal_map;
    const bool interpolates = need_uv || lit;  // uv, or the normal and the world position
    const bool has_specular = !(material.specular == Vec3{});
    const int base_width = texture && !texture->levels.empty() ? texture->levels[0].width : 0;
    const int base_height = texture && !texture->levels.empty() ? texture->levels[0].height : 0;
    static const Level kNoLevel;
    const Level& normal_level = normal_map && !normal_map->levels.empty() ? normal_map->levels[0] : kNoLevel;
    static const ShadowSettings kDefaultShadows;
    const ShadowSettings& shadow_settings = state.shadow_settings ? *state.shadow_settings : kDefaultShadows;
    const std::array<double, 3> w = {a0.w, a1.w, a2.w};
    // Built at the first fragment that needs them: most triangles of a fine mesh cover no
    // pixel center at all.
    UvPlanes planes;
    bool planes_built = false;
    const Vec3 plain{double(material.color.r), double(material.color.g), double(material.color.b)};
    // 1 / area and 1 / w_i once per triangle, at its first fragment (most triangles of a fine
    // mesh have none): the screen weights then cost multiplications, and the perspective-correct
    // weights (m4::perspective_weights) one division per fragment instead of four.
    double inv_area = 0, iw0 = 0, iw1 = 0, iw2 = 0;
    bool divided = false;
    std::uint32_t* const depth = frame.depth.data();
    long long fragments = 0, shaded = 0;

    for (int y = box.y0; y < box.y1; ++y) {
        std::int64_t e0 = row[0], e1 = row[1], e2 = row[2];
        std::size_t at = static_cast<std::size_t>(y) * width + box.x0;
        for (int x = box.x0; x < box.x1; ++x, ++at, e0 += step_x[0], e1 += step_x[1], e2 += step_x[2]) {
            if (e0 < bias[0] || e1 < bias[1] || e2 < bias[2]) continue;
            ++fragments;
            if (!divided) {
                inv_area = 1.0 / static_cast<double>(area2);
                iw0 = 1 / a0.w;
                iw1 = 1 / a1.w;
                iw2 = 1 / a2.w;
                divided = true;
            }
            const double l0 = double(e1) * inv_area, l1 = double(e2) * inv_area, l2 = double(e0) * inv_area;
            const double z = l0 * a0.screen.z + l1 * a1.screen.z + l2 * a2.screen.z;
            // A fragment behind the stored one is not shaded.
            const std::uint32_t key = float_z_key(z);
            if (key == m4::kClearKey || key > depth[at]) continue;
            ++shaded;
            // The perspective-correct weights, for materials that interpolate anything.
            std::array<double, 3> pw = {l0, l1, l2};
            if (interpolates) {
                pw = {l0 * iw0, l1 * iw1, l2 * iw2};
                const double sum = pw[0] + pw[1] + pw[2];
                if (sum > 0 && std::isfinite(sum)) {
                    const double inv_sum = 1 / sum;
                    pw = {pw[0] * inv_sum, pw[1] * inv_sum, pw[2] * inv_sum};
                } else {
                    pw = {l0, l1, l2};  // as m4::perspective_weights: the screen weights
                }
            }
            const Vec2 uv = need_uv ? a0.uv * pw[0] + a1.uv * pw[1] + a2.uv * pw[2] : Vec2{};

            Vec3 base = plain;
            if (texture) {
                double lambda = 0;
                if (mip) {
                    ++stats.lod_computed;
                    if (!planes_built) {
                        auto pixels = [](m2::Fixed s) { return Vec2{double(s.x) / S, double(s.y) / S}; };
                        planes = uv_planes({pixels(f[0]), pixels(f[1]), pixels(f[2])}, w, {a0.uv, a1.uv, a2.uv});
                        planes_built = true;
                    }
                    lambda = lod(derivatives_at(planes, x + 0.5, y + 0.5), base_width, base_height);
                }
                ++stats.texture_samples;
                base = sample(*texture, uv, lambda, material.filter, &stats.mipmap_builds);
            }
            Vec3 levels = base;
            if (lit) {
                Vec3 n = unit_or_zero(a0.normal * pw[0] + a1.normal * pw[1] + a2.normal * pw[2]);
                if (normal_map) {
                    ++stats.normal_map_samples;
                    n = perturb_normal(state.tangent, n, sample_bilinear(normal_level, uv, normal_map->wrap_u, normal_map->wrap_v));
                }
                const Vec3 world = a0.world * pw[0] + a1.world * pw[1] + a2.world * pw[2];
                const Vec3 to_eye = unit_or_zero(state.eye - world);  // once for all lights
                const Lighting& lighting = *state.lighting;
                levels = times(base, lighting.ambient);
                for (std::size_t k = 0; k < lighting.lights.size(); ++k) {
                    const Light& light = lighting.lights[k];
                    const Vec3 to_light = unit_or_zero(-light.direction);
                    const double c = raster::dot(n, to_light);
                    if (!(c > 0)) continue;  // no light, no shadow lookup
                    double factor = 1;
                    const ShadowMap* map = state.shadow_maps && k < state.shadow_maps->size() ? (*state.shadow_maps)[k] : nullptr;
                    if (map) {
                        ++stats.shadow_lookups;
                        factor = lit_fraction(*map, world, c, shadow_settings);
                    }
                    if (has_specular) ++stats.specular_terms;
                    // blinn_phong(), with N, V and L normalized once; 0 * an infinite light would be NaN
                    if (factor > 0 && !(to_eye == Vec3{})) {
                        levels = levels + lit_by(base, material.specular, material.shininess, n, to_eye, to_light, c, light.intensity) * factor;
                    }
                }
            }
            const Color c = color_of(levels);
            // Nearer keys passed above; only an exact tie needs the colors.
            if (key == depth[at] && !m4::depth_passes(key, c, depth[at], img.at(x, y))) continue;
            depth[at] = key;
            img.set(x, y, c);
        }
        for (int i = 0; i < 3; ++i) row[i] += step_y[i];
    }
    stats.fragments += fragments;
    stats.shaded += shaded;
}

}  // namespace
// END SOLUTION

void fill_triangle(Frame& frame, const std::array<ScreenVertex, 3>& v, const FillState& state, Stats& stats) {
    // TODO 5: milestone 4's fill_triangle with a new fragment: depth pre-test first (a hidden
    // fragment costs nothing), then perspective-correct uv, normal and world position, the
    // base color (color or sample(), lambda only for mip filters), and for lit materials the
    // normal map (reading it where state.tangent is not valid is free), ambient and every light
    // (blinn_phong, shadow_factor); then to_color and the depth test. Count what you do in stats.
    // BEGIN SOLUTION
    std::array<m2::Fixed, 3> f;
    for (int i = 0; i < 3; ++i) {
        if (!m2::snap({v[i].screen.x, v[i].screen.y}, f[i])) return;
    }
    fill_snapped(frame, {&v[0], &v[1], &v[2]}, f, state, stats);
    // END SOLUTION
}

// ---- TODO 9: the pipeline ----

// BEGIN SOLUTION
namespace {

// m3's Mat4 * Vec4 and to_screen with the same arithmetic in the same order (so the same
// bits), inline: the loop over positions runs them for every position of every frame, and a
// call into milestone 3's file per product costs about as much as the product.
inline Vec4 transformed(const Mat4& a, Vec4 v) {
    auto row = [&](const double (&m)[4]) { return 0.0 + m[0] * v.x + m[1] * v.y + m[2] * v.z + m[3] * v.w; };
    return {row(a.m[0]), row(a.m[1]), row(a.m[2]), row(a.m[3])};
}
inline Vec3 screen_of(Vec4 c, int width, int height) {
    const double x = c.x / c.w, y = c.y / c.w, z = c.z / c.w;
    return {(x + 1) / 2 * width, (1 - y) / 2 * height, z};
}

bool inside(Vec4 c) {
    return c.w + c.x >= 0 && c.w - c.x >= 0 && c.w + c.y >= 0 && c.w - c.y >= 0 && c.w + c.z >= 0 && c.w - c.z >= 0;
}

bool finite(Vec4 c) { return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && std::isfinite(c.w); }

// The depth pass of one light into `map`: every object that casts a shadow, depth only, both
// faces. The map's keys and the pass's color image keep their memory from the frame before
// (a map of 1024^2 keys is 4 MB: allocating and zeroing it anew each frame costs more than
// drawing the floor into it).
void shadow_pass(const std::vector<Object>& objects, Vec3 direction, const ShadowSettings& settings, ShadowMap& map) {
    map.light = light_view_projection(direction, settings);
    map.radius = settings.radius;
    map.resolution = settings.resolution;
    thread_local Frame pass;
    if (pass.color.width() != settings.resolution || pass.color.height() != settings.resolution) {
        pass.color = Image(settings.resolution, settings.resolution);
    }
    pass.depth = std::move(map.keys);
    m4::clear_frame(pass, raster::colors::black, true, m4::DepthFormat::kFloatZ);
    m4::Needs needs;
    needs.depth_test = true;
    needs.depth_format = m4::DepthFormat::kFloatZ;
    needs.shading = m4::Shading::kFaceColor;  // the cheapest mode: no attributes, no light
    for (const Object& object : objects) {
        if (!object.casts_shadow || !object.mesh) continue;
        // projection * (view * model) with the light's whole matrix as the view.
        m4::draw_mesh(pass, *object.mesh, object.model, map.light, m3::identity(), m4::Lighting{}, raster::colors::white, needs);
    }
    map.keys = std::move(pass.depth);
}

}  // namespace
// END SOLUTION

Stats draw_scene(Frame& frame, const std::vector<Object>& objects, const Camera& camera, const Lighting& lighting,
                 const ShadowSettings& shadow_settings) {
    // TODO 9: the shadow pass for each light that casts shadows (and only those), then every
    // object: positions to clip and world space, normals (lit materials only), and per mesh
    // triangle the tangent frame (with a normal map), clipping, the fan and fill_triangle.
    Stats stats;
    // BEGIN SOLUTION
    // 1. The shadow maps, one per light that casts shadows.
    const std::size_t light_count = lighting.lights.size();
    thread_local std::vector<ShadowMap> maps;  // kept between frames: see shadow_pass
    if (maps.size() < light_count) maps.resize(light_count);
    std::vector<const ShadowMap*> map_of(light_count, nullptr);
    const int res = shadow_settings.resolution;
    for (std::size_t k = 0; k < light_count; ++k) {
        if (!lighting.lights[k].casts_shadows || res < 1 || res > Image::kMaxSide) continue;
        shadow_pass(objects, lighting.lights[k].direction, shadow_settings, maps[k]);
        map_of[k] = &maps[k];
        ++stats.shadow_passes;
        stats.shadow_texels += static_cast<long long>(res) * res;
    }

    // 2. The objects.
    FillState state;
    state.lighting = &lighting;
    state.shadow_maps = &map_of;
    state.shadow_settings = &shadow_settings;
    state.eye = camera.eye;
    const int width = frame.color.width(), height = frame.color.height();
    // Per position, kept between calls (a million-vertex mesh needs about 200 MB here: asking
    // the system for it anew each frame, zeroed page by page, would cost more than using it).
    thread_local std::vector<Vec4> clip;
    thread_local std::vector<ScreenVertex> vertex;  // screen (for positions inside), w and the attributes
    // Where each position is, as milestone 4's draw_mesh keeps it: inside the clip volume and
    // snapped, inside but beyond the snapping range (fill_triangle would draw nothing), outside
    // (its triangles are clipped) or not finite (its triangles are skipped).
    enum class Where : unsigned char { kInside, kInsideUnsnapped, kOutside, kNotFinite };
    thread_local std::vector<Where> where;
    thread_local std::vector<m2::Fixed> snapped;  // the screen position in fixed point, once per position
    for (const Object& object : objects) {
        if (!object.mesh) continue;
        const m4::Mesh& mesh = *object.mesh;
        const Material& material = object.material;
        state.material = &material;
        state.tangent = {};
        const bool lit = material.lit;
        // An unlit material uses no normal: no tangent frame, and fill_triangle reads no normal map.
        const bool normal_mapped = lit && material.normal_map != nullptr;
        const bool need_world = lit;  // the lights' vectors and the tangent frames
        const bool need_uv = material.texture || normal_mapped;
        const int n = static_cast<int>(mesh.positions.size());

        // Every position once.
        const Mat4 mvp = camera.projection * (camera.view * object.model);
        const Mat4 to_world_normal = lit ? m4::normal_matrix(object.model) : Mat4{};
        std::vector<Vec3> computed;
        const std::vector<Vec3>* normals = &mesh.normals;
        if (lit && mesh.normals.size() != mesh.positions.size()) {
            computed = m4::vertex_normals(mesh.positions, mesh.triangles);
            normals = &computed;
        }
        // Grown, never shrunk (the floor after the sphere would otherwise make the sphere's
        // arrays be constructed anew, entry by entry, every frame).
        if (vertex.size() < static_cast<std::size_t>(n)) {
            clip.resize(n);
            vertex.resize(n);
            where.resize(n);
            snapped.resize(n);
        }
        for (int i = 0; i < n; ++i) {
            const Vec3 position = mesh.positions[i];
            clip[i] = transformed(mvp, raster::point(position));
            ScreenVertex& sv = vertex[i];
            sv = {};
            sv.w = clip[i].w;
            if (!finite(clip[i])) {
                where[i] = Where::kNotFinite;
            } else if (inside(clip[i])) {
                sv.screen = screen_of(clip[i], width, height);
                where[i] = m2::snap({sv.screen.x, sv.screen.y}, snapped[i]) ? Where::kInside : Where::kInsideUnsnapped;
            } else {
                where[i] = Where::kOutside;
            }
            if (need_world) sv.world = raster::xyz(transformed(object.model, raster::point(position)));
            if (lit) sv.normal = unit_or_zero(raster::xyz(transformed(to_world_normal, raster::direction((*normals)[i]))));
            if (need_uv && i < static_cast<int>(mesh.uvs.size())) sv.uv = mesh.uvs[i];
        }

        // Every triangle, in list order.
        auto fill = [&](const ScreenVertex& s0, const ScreenVertex& s1, const ScreenVertex& s2) {
            ++stats.triangles_drawn;
            fill_triangle(frame, {s0, s1, s2}, state, stats);
        };
        for (const auto& t : mesh.triangles) {
            if (t[0] < 0 || t[0] >= n || t[1] < 0 || t[1] >= n || t[2] < 0 || t[2] >= n) continue;
            const Where w0 = where[t[0]], w1 = where[t[1]], w2 = where[t[2]];
            if (w0 == Where::kNotFinite || w1 == Where::kNotFinite || w2 == Where::kNotFinite) continue;
            const ScreenVertex &v0 = vertex[t[0]], &v1 = vertex[t[1]], &v2 = vertex[t[2]];
            if (normal_mapped) {
                state.tangent = tangent_frame(v0.world, v1.world, v2.world, v0.uv, v1.uv, v2.uv);
                ++stats.tangent_frames;
            }
            if (w0 != Where::kOutside && w1 != Where::kOutside && w2 != Where::kOutside) {
                ++stats.triangles_drawn;
                if (w0 == Where::kInside && w1 == Where::kInside && w2 == Where::kInside) {
                    fill_snapped(frame, {&v0, &v1, &v2}, {snapped[t[0]], snapped[t[1]], snapped[t[2]]}, state, stats);
                }
                continue;
            }
            auto clip_vertex = [&](int i) {
                return m4::ClipVertex{clip[i], {}, vertex[i].normal, vertex[i].world, vertex[i].uv};
            };
            const std::vector<m4::ClipVertex> polygon = m4::clip_triangle({clip_vertex(t[0]), clip_vertex(t[1]), clip_vertex(t[2])});
            std::vector<ScreenVertex> on_screen;
            on_screen.reserve(polygon.size());
            for (const m4::ClipVertex& c : polygon) {
                on_screen.push_back({m3::to_screen(c.clip, width, height), c.clip.w, c.color, c.normal, c.world, c.uv});
            }
            for (std::size_t i = 1; i + 1 < on_screen.size(); ++i) fill(on_screen[0], on_screen[i], on_screen[i + 1]);
        }
    }
    // END SOLUTION
    return stats;
}

}  // namespace RASTER_FLAVOUR
}  // namespace m5
