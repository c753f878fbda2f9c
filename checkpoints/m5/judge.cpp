// Judge half of the milestone-5 checkpoints (trusted: it runs no code under test).
//
// Oracles: the pinned rules recomputed here (wrapping, texel fetches, nearest and bilinear
// samples, the mipmap pyramid, level of detail, the filters, Blinn-Phong, tangent frames and
// normal maps, the light's matrix and shadow lookups), hand-worked values, the reference's
// numbers on the same inputs (derivatives, lambda, the light's matrix, stage counts), the
// expected picture, and pictures computed here from the scene alone by ray casting: the exact
// nearest-texel picture, a 16x supersampled bilinear truth for the filters, the exact spheres
// lit with Blinn-Phong, and the exact light state of every pixel (a ray cast to the light).
#include "m5/judge.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <set>

#include "harness/diagnosis.h"
#include "harness/judging.h"
#include "m5/scenes.h"
#include "raster/plot.h"

namespace m5cp {

namespace {

using cp::get;
using cp::max_diff;
using cp::num;
using cp::plural;
using cp::str;
using cp::Values;
using cp::vec3;

// cp::close, but an infinity only matches itself.
bool close(double a, double b, double tol) { return std::isinf(a) || std::isinf(b) ? a == b : cp::close(a, b, tol); }

std::string str(Vec2 p) { return "(" + num(p.x) + ", " + num(p.y) + ")"; }
bool same3(Vec3 a, Vec3 b, double tol) { return close(a.x, b.x, tol) && close(a.y, b.y, tol) && close(a.z, b.z, tol); }
Vec3 mul(Vec3 a, Vec3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }

// Whether `mine` misses `want` by no more than float's rounding would (a relative 1e-5, far above
// double's 1e-16 and the 1e-9 the numbers are judged with), and then what to say.
std::string float_rounding(Vec3 mine, Vec3 want) {
    double worst = 0;
    for (auto [a, b] : {std::pair{mine.x, want.x}, std::pair{mine.y, want.y}, std::pair{mine.z, want.z}}) {
        if (!std::isfinite(a) || !std::isfinite(b)) return "";
        worst = std::max(worst, std::abs(a - b) / std::max(1.0, std::abs(b)));
    }
    if (!(worst <= 1e-5)) return "";
    return ": off by " + num(worst) + " relative, the size of FLOAT's rounding; the header asks for double everywhere "
           "until a color is stored (numbers are judged within 1e-9 relative): keep every weight, coordinate and sum "
           "a double";
}

Vec3 unit_or_zero(Vec3 v) {
    const double len = raster::length(v);
    if (!(len > 0) || !std::isfinite(len)) return {};
    return v / len;
}

Color to_color(Vec3 v) {
    auto ch = [](double x) { return static_cast<std::uint8_t>(std::isnan(x) ? 0 : std::lround(std::clamp(x, 0.0, 255.0))); };
    return {ch(v.x), ch(v.y), ch(v.z)};
}

const char* wrap_name(Wrap w) {
    switch (w) {
        case Wrap::kRepeat: return "repeat";
        case Wrap::kClampToEdge: return "clamp to edge";
        default: return "mirrored repeat";
    }
}
const char* filter_name(Filter f) {
    switch (f) {
        case Filter::kNearest: return "kNearest";
        case Filter::kBilinear: return "kBilinear";
        case Filter::kNearestMip: return "kNearestMip";
        default: return "kTrilinear";
    }
}

struct Ctx {
    const Scene& s;
    const Values& mine;
    const Values& ref;
    cp::Judgement& j;
    // "TODO 5: message" puts "TODO 5" into the finding's todo.
    void add(const std::string& topic, const std::string& msg) { cp::add_finding(j, topic, msg); }
};

// At most this many findings per function in one group, then a count of the rest.
struct Limited {
    Ctx& c;
    std::string what;
    int shown = 0, more = 0;
    void add(const std::string& topic, const std::string& msg) {
        if (shown == 0) topic_of_rest = topic;
        if (shown < 4) {
            c.add(topic, msg);
            ++shown;
        } else {
            ++more;
        }
    }
    ~Limited() {
        if (more > 0) c.add(topic_of_rest, "TODO " + todo + ": " + plural(more, "more case") + " of " + what + (more == 1 ? " is" : " are") + " wrong too");
    }
    std::string topic_of_rest = "pipeline", todo = "9";
};

// ---- the pinned rules, recomputed here ----

double t_wrap(double i, int n, Wrap mode) {
    if (!std::isfinite(i) || n < 1) return 0;
    switch (mode) {
        case Wrap::kRepeat: {
            double m = std::fmod(i, double(n));
            if (m < 0) m += n;
            return m;
        }
        case Wrap::kClampToEdge: return std::min(std::max(i, 0.0), double(n - 1));
        default: {
            double m = std::fmod(i, 2.0 * n);
            if (m < 0) m += 2.0 * n;
            return m < n ? m : 2.0 * n - 1 - m;
        }
    }
}

Vec3 t_fetch(const LevelData& l, double i, double j, Wrap wu, Wrap wv) {
    if (l.width <= 0 || l.height <= 0 || l.texels.empty()) return {};
    const double x = t_wrap(i, l.width, wu), y = t_wrap(j, l.height, wv);
    return l.texels[std::size_t(y) * std::size_t(l.width) + std::size_t(x)];
}

Vec3 t_nearest(const LevelData& l, Vec2 uv, Wrap wu, Wrap wv) {
    if (l.texels.empty()) return {};
    const double x = uv.x * l.width, y = uv.y * l.height;
    if (!std::isfinite(x) || !std::isfinite(y)) return {};
    return t_fetch(l, std::floor(x), std::floor(y), wu, wv);
}

// shift: 0.5 by the rule; 0 is the "texel centers at integers" mistake. swap: the weights swapped.
Vec3 t_bilinear(const LevelData& l, Vec2 uv, Wrap wu, Wrap wv, double shift = 0.5, bool swap = false) {
    if (l.texels.empty()) return {};
    const double x = uv.x * l.width - shift, y = uv.y * l.height - shift;
    if (!std::isfinite(x) || !std::isfinite(y)) return {};
    const double i = std::floor(x), j = std::floor(y);
    double a = x - i, b = y - j;
    if (swap) {
        a = 1 - a;
        b = 1 - b;
    }
    return t_fetch(l, i, j, wu, wv) * ((1 - a) * (1 - b)) + t_fetch(l, i + 1, j, wu, wv) * (a * (1 - b)) +
           t_fetch(l, i, j + 1, wu, wv) * ((1 - a) * b) + t_fetch(l, i + 1, j + 1, wu, wv) * (a * b);
}

std::vector<LevelData> t_pyramid(const LevelData& base) {
    std::vector<LevelData> out = {base};
    if (base.texels.empty()) return out;
    while (out.back().width > 1 || out.back().height > 1) {
        const LevelData& k = out.back();
        LevelData next;
        next.width = std::max(1, k.width / 2);
        next.height = std::max(1, k.height / 2);
        auto at = [&k](int i, int j) {
            return k.texels[std::size_t(std::min(j, k.height - 1)) * std::size_t(k.width) + std::size_t(std::min(i, k.width - 1))];
        };
        for (int j = 0; j < next.height; ++j) {
            for (int i = 0; i < next.width; ++i) {
                next.texels.push_back((at(2 * i, 2 * j) + at(2 * i + 1, 2 * j) + at(2 * i, 2 * j + 1) + at(2 * i + 1, 2 * j + 1)) / 4);
            }
        }
        out.push_back(next);
    }
    return out;
}

struct Derivs {
    double du_dx = 0, dv_dx = 0, du_dy = 0, dv_dy = 0;
    bool defined = false;  // false (all zero) for a degenerate triangle or B not > 0 and finite
};
// perspective false: the screen-space (affine) derivatives, the mistake of ignoring w. The uv
// are taken relative to vertex 0 (the derivatives do not change, and far from 0, at uv 1e7,
// fewer digits cancel).
Derivs t_derivatives(const LodCase& c, bool perspective = true) {
    const auto& s = c.screen;
    const double area = (s[1].x - s[0].x) * (s[2].y - s[0].y) - (s[1].y - s[0].y) * (s[2].x - s[0].x);
    if (area == 0 || !std::isfinite(area)) return {};
    double l[3], lx[3], ly[3];
    for (int i = 0; i < 3; ++i) {
        const Vec3 a = s[std::size_t((i + 1) % 3)], b = s[std::size_t((i + 2) % 3)];
        l[i] = ((a.x - c.x) * (b.y - c.y) - (a.y - c.y) * (b.x - c.x)) / area;
        lx[i] = (a.y - b.y) / area;
        ly[i] = (b.x - a.x) / area;
    }
    double A[2] = {0, 0}, Ax[2] = {0, 0}, Ay[2] = {0, 0}, B = 0, Bx = 0, By = 0;
    for (int i = 0; i < 3; ++i) {
        const double q = perspective ? 1 / c.w[std::size_t(i)] : 1;
        const double uv[2] = {c.uv[std::size_t(i)].x - c.uv[0].x, c.uv[std::size_t(i)].y - c.uv[0].y};
        for (int k = 0; k < 2; ++k) {
            A[k] += l[i] * uv[k] * q;
            Ax[k] += lx[i] * uv[k] * q;
            Ay[k] += ly[i] * uv[k] * q;
        }
        B += l[i] * q;
        Bx += lx[i] * q;
        By += ly[i] * q;
    }
    if (!(B > 0) || !std::isfinite(B)) return {};
    Derivs d;
    d.du_dx = (Ax[0] * B - A[0] * Bx) / (B * B);
    d.dv_dx = (Ax[1] * B - A[1] * Bx) / (B * B);
    d.du_dy = (Ay[0] * B - A[0] * By) / (B * B);
    d.dv_dy = (Ay[1] * B - A[1] * By) / (B * B);
    d.defined = true;
    return d;
}

double t_lambda(double du_dx, double dv_dx, double du_dy, double dv_dy, double w, double h) {
    const double rho = std::max(std::sqrt((w * du_dx) * (w * du_dx) + (h * dv_dx) * (h * dv_dx)),
                                std::sqrt((w * du_dy) * (w * du_dy) + (h * dv_dy) * (h * dv_dy)));
    return std::log2(rho);
}

Vec3 t_sample(const std::vector<LevelData>& pyr, Vec2 uv, double lambda, Filter f, Wrap wu, Wrap wv, bool blend = true) {
    if (pyr.empty()) return {};
    if (f == Filter::kNearest) return t_nearest(pyr[0], uv, wu, wv);
    if (f == Filter::kBilinear || !(lambda > 0)) return t_bilinear(pyr[0], uv, wu, wv);
    const double top = double(pyr.size() - 1), lam = std::min(lambda, top);
    if (f == Filter::kNearestMip) return t_bilinear(pyr[std::size_t(std::floor(lam + 0.5))], uv, wu, wv);
    const double k = std::floor(lam), frac = lam - k;
    const std::size_t k0 = std::size_t(k), k1 = std::min(k0 + 1, pyr.size() - 1);
    const Vec3 a = t_bilinear(pyr[k0], uv, wu, wv), b = t_bilinear(pyr[k1], uv, wu, wv);
    if (!blend) return a;
    return a * (1 - frac) + b * frac;
}

// unnormalized_h: the mistake of H = L + V without normalizing; behind: specular even when c <= 0.
Vec3 t_phong(const PhongCase& k, bool unnormalized_h = false, bool behind = false) {
    const Vec3 n = unit_or_zero(k.normal), v = unit_or_zero(k.to_eye), l = unit_or_zero(k.to_light);
    if (n == Vec3{} || v == Vec3{} || l == Vec3{}) return {};
    const double c = raster::dot(n, l);
    const Vec3 h = unnormalized_h ? l + v : unit_or_zero(l + v);
    const double s = std::pow(std::max(0.0, raster::dot(n, h)), k.shininess);
    if (!(c > 0)) return behind ? mul(k.specular, k.intensity) * s : Vec3{};
    return mul(k.base, k.intensity) * c + mul(k.specular, k.intensity) * s;
}

struct Frame {
    Vec3 t, b;
    bool valid = false;
};
Frame t_frame(const FrameCase& c) {
    const Vec3 e1 = c.p[1] - c.p[0], e2 = c.p[2] - c.p[0];
    const double du1 = c.uv[1].x - c.uv[0].x, dv1 = c.uv[1].y - c.uv[0].y;
    const double du2 = c.uv[2].x - c.uv[0].x, dv2 = c.uv[2].y - c.uv[0].y;
    const double r = du1 * dv2 - du2 * dv1;
    if (r == 0 || !std::isfinite(r)) return {};
    const Vec3 t = (e1 * dv2 - e2 * dv1) / r, b = (e2 * du1 - e1 * du2) / r;
    if (!raster::is_finite(t) || !raster::is_finite(b)) return {};
    return {t, b, true};
}

// mode 0: the rule; 1: the texel read as t / 255 (no 2 t - 1); 2: T and B used without
// making them orthonormal (each only normalized); 3: B' = cross(n, T') never negated to agree
// with B; 4: B' = B made orthogonal to n alone (not to T'); 5: the green channel read as -B'
// (green up the image).
Vec3 t_perturb(const PerturbCase& c, int mode = 0) {
    const Vec3 n = c.n;
    if (!c.valid || n == Vec3{} || !raster::is_finite(n) || !raster::is_finite(c.texel) || !raster::is_finite(c.tangent) ||
        !raster::is_finite(c.bitangent)) {
        return n;
    }
    const Vec3 tp = mode == 2 || mode == 6 ? unit_or_zero(c.tangent) : unit_or_zero(c.tangent - n * raster::dot(n, c.tangent));
    if (tp == Vec3{}) return n;
    Vec3 bp = raster::cross(n, tp);
    if (raster::dot(bp, c.bitangent) < 0 && mode != 3) bp = -bp;
    if (mode == 2) bp = unit_or_zero(c.bitangent);
    if (mode == 4) bp = unit_or_zero(c.bitangent - n * raster::dot(n, c.bitangent));  // against n, not T'
    const Vec3 m = mode == 1   ? c.texel / 255
                   : mode == 7 ? (c.texel - Vec3{128, 128, 128}) / 127
                   : mode == 8 ? (c.texel - Vec3{128, 128, 128}) / 128
                   : mode == 9 ? (c.texel - Vec3{127, 127, 127}) / 128
                               : c.texel * 2.0 / 255 - Vec3{1, 1, 1};
    const Vec3 r = unit_or_zero(tp * m.x + bp * (mode == 5 ? -m.y : m.y) + n * m.z);
    return r == Vec3{} ? n : r;
}

// Why perturb_normal must return n itself here, or "" when it perturbs it (t_perturb's early
// returns, in its order).
std::string unchanged_because(const PerturbCase& c) {
    const Vec3 n = c.n;
    if (!c.valid) return "the frame is not valid";
    if (n == Vec3{} || !raster::is_finite(n)) return "n is zero or not finite";
    if (!raster::is_finite(c.texel)) return "the texel is not finite";
    if (!raster::is_finite(c.tangent) || !raster::is_finite(c.bitangent)) return "T or B is not finite";
    if (unit_or_zero(c.tangent - n * raster::dot(n, c.tangent)) == Vec3{}) return "T is along n, so T' is zero";
    if (c.texel * 2.0 / 255 - Vec3{1, 1, 1} == Vec3{}) return "the texel decodes to the zero vector";
    return "";
}

struct M4 {
    double m[4][4] = {};
};
M4 mul(const M4& a, const M4& b) {
    M4 r;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            for (int k = 0; k < 4; ++k) r.m[i][j] += a.m[i][k] * b.m[k][j];
        }
    }
    return r;
}
Vec4 mul(const M4& a, Vec4 v) {
    const double in[4] = {v.x, v.y, v.z, v.w};
    double out[4] = {0, 0, 0, 0};
    for (int i = 0; i < 4; ++i) {
        for (int k = 0; k < 4; ++k) out[i] += a.m[i][k] * in[k];
    }
    return {out[0], out[1], out[2], out[3]};
}
M4 t_look_at(Vec3 eye, Vec3 target, Vec3 up) {
    const Vec3 f = unit_or_zero(target - eye), r = unit_or_zero(raster::cross(f, up)), u = raster::cross(r, f);
    M4 m;
    const Vec3 rows[3] = {r, u, -f};
    for (int i = 0; i < 3; ++i) {
        m.m[i][0] = rows[i].x;
        m.m[i][1] = rows[i].y;
        m.m[i][2] = rows[i].z;
        m.m[i][3] = -raster::dot(rows[i], eye);
    }
    m.m[3][3] = 1;
    return m;
}
M4 t_ortho(double l, double r, double b, double t, double n, double f) {
    M4 m;
    m.m[0][0] = 2 / (r - l);
    m.m[0][3] = -(r + l) / (r - l);
    m.m[1][1] = 2 / (t - b);
    m.m[1][3] = -(t + b) / (t - b);
    m.m[2][2] = -2 / (f - n);
    m.m[2][3] = -(f + n) / (f - n);
    m.m[3][3] = 1;
    return m;
}
// flip: the eye on the wrong side (center + 2r d), a light looking against its direction.
M4 t_light(Vec3 direction, Vec3 center, double r, bool flip = false) {
    const Vec3 d = unit_or_zero(direction);
    if (d == Vec3{} || !raster::is_finite(center) || !std::isfinite(r)) return {};
    const Vec3 up = std::abs(d.y) > 0.99 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    return mul(t_ortho(-r, r, -r, r, r, 3 * r), t_look_at(center + d * (flip ? 2 * r : -2 * r), center, up));
}

// x to 4 decimals, as a finding prints a worked number.
double round4(double x) { return std::round(x * 1e4) / 1e4; }

// The rule, and the mistakes the findings name.
enum class Lookup {
    kRule,
    kReversed,    // the comparison the wrong way round
    kBiasAdded,   // d + bias / (2r)
    kWorldBias,   // d - bias, the bias in world units not converted to depth
    kUncapped,    // tan(theta) not capped at 10
    kOverR,       // d - bias / r: the bias converted to depth with half the box's depth
    kRawDirection,  // c = dot(n, -direction) with the direction as passed, not normalized
    kUnflipped,   // the row from NDC y as it is, without to_screen's flip
    kTieShadowed, // d - bias / (2r) >= stored: a tie shadowed
    kAlongRays,   // c = dot(n, +normalize(direction)): L the way the rays travel, so c <= 0 and the cap
    kNdcDepth,    // z_ndc - bias / (2r): the point's z_ndc compared as it is, not its depth (z_ndc + 1) / 2
    kPcfAhead,    // the PCF kernel off centre: offsets 0, 1, 2 instead of -1, 0, 1
    kPcfBehind,   // the PCF kernel off centre: offsets -2, -1, 0
    kRounded,     // the texel by rounding, floor(x + 0.5), not floor(x)
    kRoundedDown, // the same, a hair below: a point at a texel's center (x + 0.5 whole) may round either way
    kGridShort,   // the texel from to_screen on a (resolution - 1)^2 grid: x = (x_ndc + 1) / 2 * (resolution - 1)
    kPcfOver8,    // the lit count of the 3x3 divided by 8 (9 of 9 lit taken as 1, as a min(1, ...) keeps it)
    kPcf2x2,      // a 2x2 kernel, offsets 0 and 1, lit / 4
    kPcf2x2Behind,  // a 2x2 kernel, offsets -1 and 0, lit / 4
};

// The bias of a shadow case in world units: constant + slope * min(tan(theta), 10), with
// c = cos(theta) from the light's direction normalized; or as `mode`'s mistake takes it.
double t_bias(const TinyMap& map, const ShadowCase& c, Lookup mode = Lookup::kRule) {
    const Vec3 direction = map.direction * c.direction_scale;
    const double cos_t = raster::dot(c.n, mode == Lookup::kRawDirection ? -direction
                                          : mode == Lookup::kAlongRays  ? unit_or_zero(direction)
                                                                        : -unit_or_zero(direction));
    // c <= 0 (no light arrives; the header asks only for c > 0) takes the cap, as the reference does.
    const double tan_t = cos_t > 0 ? std::sqrt(std::max(0.0, 1 - cos_t * cos_t)) / cos_t : 10.0;
    return c.constant_bias + c.slope_bias * (mode == Lookup::kUncapped ? tan_t : std::min(tan_t, 10.0));
}

// d - bias / (2r), the biased depth the rule compares with the stored one.
double t_shadow_depth(const TinyMap& map, const ShadowCase& c) {
    const Vec4 clip = mul(t_light(map.direction, map.center, map.radius), Vec4{c.p.x, c.p.y, c.p.z, 1});
    return (clip.z / clip.w + 1) / 2 - t_bias(map, c) / (2 * map.radius);
}

// The shadow factor on the tiny map.
double t_shadow(const TinyMap& map, const ShadowCase& c, Lookup mode = Lookup::kRule) {
    const M4 m = t_light(map.direction, map.center, map.radius);
    const Vec4 clip = mul(m, Vec4{c.p.x, c.p.y, c.p.z, 1});
    const double res = map.resolution;
    const double grid = mode == Lookup::kGridShort ? res - 1 : res;
    const double x = (clip.x / clip.w + 1) / 2 * grid, z = clip.z / clip.w;
    const double y = mode == Lookup::kUnflipped ? (clip.y / clip.w + 1) / 2 * grid : (1 - clip.y / clip.w) / 2 * grid;
    const double d = mode == Lookup::kNdcDepth ? z : (z + 1) / 2;
    const double bias = t_bias(map, c, mode);
    const double test = mode == Lookup::kBiasAdded   ? d + bias / (2 * map.radius)
                        : mode == Lookup::kWorldBias ? d - bias
                        : mode == Lookup::kOverR     ? d - bias / map.radius
                                                     : d - bias / (2 * map.radius);
    auto lit = [&](double col, double row) {
        if (col < 0 || row < 0 || col >= res || row >= res) return 1.0;
        const std::uint32_t key = map.keys[std::size_t(row) * std::size_t(map.resolution) + std::size_t(col)];
        if (key == 0xFFFFFFFFu) return 1.0;
        const double stored = std::bit_cast<float>(key);
        const bool shadowed = mode == Lookup::kReversed       ? test < stored
                              : mode == Lookup::kTieShadowed ? test >= stored
                                                              : test > stored;
        return shadowed ? 0.0 : 1.0;
    };
    const double half = mode == Lookup::kRounded ? 0.5 : mode == Lookup::kRoundedDown ? 0.5 - 1e-9 : 0;
    const double col = std::floor(x + half), row = std::floor(y + half);
    if (!c.pcf) return lit(col, row);
    if (mode == Lookup::kPcf2x2 || mode == Lookup::kPcf2x2Behind) {
        const int from = mode == Lookup::kPcf2x2 ? 0 : -1;
        double quad = 0;
        for (int dy = from; dy <= from + 1; ++dy) {
            for (int dx = from; dx <= from + 1; ++dx) quad += lit(col + dx, row + dy);
        }
        return quad / 4;
    }
    const int shift = mode == Lookup::kPcfAhead ? 1 : mode == Lookup::kPcfBehind ? -1 : 0;
    double sum = 0;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) sum += lit(col + dx + shift, row + dy + shift);
    }
    return mode == Lookup::kPcfOver8 ? std::min(1.0, sum / 8) : sum / 9;  // (with or without the min, when all nine are lit)
}

// ---- the number groups ----

void judge_wrap(Ctx& c) {
    const Values& v = c.mine;
    {
        Limited out{c, "wrap_index", 0, 0, "wrap", "1"};
        const auto cases = wrap_cases();
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const auto& k = cases[i];
            const double mine = get(v, "wrap" + std::to_string(i)), want = t_wrap(k.i, k.n, k.mode);
            if (mine == want) continue;
            std::string why;
            const double trunc = std::fmod(k.i, double(k.mode == Wrap::kMirroredRepeat ? 2 * k.n : k.n));
            // Mirrored repeat turning m in [n, 2n) into 2n - m instead of 2n - 1 - m.
            const double period = 2.0 * k.n, m = std::isfinite(k.i) ? std::fmod(std::fmod(k.i, period) + period, period) : 0;
            const bool mirror_off_by_one = k.mode == Wrap::kMirroredRepeat && m >= k.n && mine == period - m;
            if (!std::isfinite(k.i)) {
                why = ": a non-finite index gives 0 (never a crash, never an index out of range)";
            } else if (mirror_off_by_one) {
                why = ": mirrored repeat maps m = i mod 2n in [n, 2n) to 2n - 1 - m (the edge texel is read twice at "
                      "the turn, as n - 1 then n - 1 again), not 2n - m";
            } else if (k.i < 0 && k.mode != Wrap::kClampToEdge && mine == trunc) {
                why = ": std::fmod (and %) truncate toward zero and keep the sign of i, so -1 mod n is -1; add n (2n "
                      "for mirrored repeat) when the result is negative, so -1 becomes n - 1";
            } else if (k.i < 0 && k.mode != Wrap::kClampToEdge && mine == -trunc) {
                why = ": that is |i| mod n, a mirror image of the pattern about 0: -1 must land on n - 1 (the texel "
                      "left of 0 is the last one), not on 1; take i mod n with a result in [0, n), adding n (2n for "
                      "mirrored repeat) when it is negative";
            } else if (std::abs(k.i) > 1e15) {
                why = ": a huge index must wrap exactly: std::fmod is exact for any finite double (a cast to an "
                      "integer type overflows, and i - n floor(i / n) rounds once |i| passes 2^52)";
            }
            out.add("wrap", "TODO 1: wrap_index(" + num(k.i) + ", " + std::to_string(k.n) + ", " + wrap_name(k.mode) +
                                ") gave " + num(mine) + ", expected " + num(want) + why);
        }
    }
    Limited out{c, "fetch", 0, 0, "wrap", "1"};
    const auto cases = fetch_cases();
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const auto& k = cases[i];
        const LevelData l = sample_level(k.level);
        const Vec3 mine = vec3(v, "fetch" + std::to_string(i)), want = t_fetch(l, k.i, k.j, k.wu, k.wv);
        if (same3(mine, want, 1e-12)) continue;
        out.add("wrap", "TODO 1: fetch on a " + std::to_string(l.width) + "x" + std::to_string(l.height) + " level at (" + num(k.i) +
                            ", " + num(k.j) + ") with u " + wrap_name(k.wu) + " and v " + wrap_name(k.wv) + " gave " + str(mine) +
                            ", expected " + str(want) +
                            (l.texels.empty() ? " (a level with no texels is black)"
                                              : " (texel (" + num(t_wrap(k.i, l.width, k.wu)) + ", " + num(t_wrap(k.j, l.height, k.wv)) +
                                                    "), at index j * width + i)"));
    }
}

void judge_sampling(Ctx& c) {
    const Values& v = c.mine;
    const auto cases = sample_cases();
    Limited nearest{c, "sample_nearest", 0, 0, "nearest", "2"};
    Limited bilinear{c, "sample_bilinear", 0, 0, "bilinear", "2"};
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const auto& k = cases[i];
        const LevelData l = sample_level(k.level);
        const std::string inputs = "uv " + str(k.uv) + " on a " + std::to_string(l.width) + "x" + std::to_string(l.height) +
                                   " level, u " + wrap_name(k.wu) + ", v " + wrap_name(k.wv);
        const bool bad_uv = !std::isfinite(k.uv.x * l.width) || !std::isfinite(k.uv.y * l.height);
        const bool huge_uv = !bad_uv && std::max(std::abs(k.uv.x * l.width), std::abs(k.uv.y * l.height)) > 1e15;
        const std::string huge_why =
            ": a huge uv wraps exactly: keep floor(u * w) a double and wrap it with std::fmod (wrap_index); a cast to "
            "an integer type overflows, which is undefined (on x86 it gives -2^63, the right texel of a power-of-two "
            "level only by luck)";
        // uv reduced to [0, 1) before sampling: repeat's answer whatever the modes (the texels near
        // the border still wrap by the modes, so this differs from a repeat-only sampler).
        const Vec2 fract_uv{k.uv.x - std::floor(k.uv.x), k.uv.y - std::floor(k.uv.y)};
        const bool outside = !bad_uv && (k.uv.x < 0 || k.uv.x >= 1 || k.uv.y < 0 || k.uv.y >= 1);
        const std::string fract_why =
            ": that is the sample at uv reduced to [0, 1) first (its fraction); clamp to edge and mirrored repeat need "
            "the whole uv: wrap the texel INDICES with wrap_index, not uv";
        {
            const Vec3 mine = vec3(v, "nearest" + std::to_string(i)), want = t_nearest(l, k.uv, k.wu, k.wv);
            if (!same3(mine, want, 1e-12)) {
                std::string why, topic = "nearest";
                if (bad_uv) {
                    topic = "non-finite uv";
                    why = ": a NaN or infinite uv (or a u * w that overflows) samples black";
                } else if (outside && same3(mine, t_nearest(l, fract_uv, k.wu, k.wv), 1e-12)) {
                    why = fract_why;
                } else if (huge_uv) {
                    why = huge_why;
                } else if (same3(mine, t_fetch(l, std::round(k.uv.x * l.width), std::round(k.uv.y * l.height), k.wu, k.wv), 1e-12)) {
                    topic = "texel centers";
                    why = ": that is texel (round(u * w), round(v * h)); texel i COVERS [i, i + 1) in texel units, so "
                          "nearest reads floor(u * w)";
                }
                nearest.add(topic, "TODO 2: sample_nearest at " + inputs + " gave " + str(mine) + ", expected " + str(want) + why);
            }
        }
        const Vec3 mine = vec3(v, "bilinear" + std::to_string(i)), want = t_bilinear(l, k.uv, k.wu, k.wv);
        if (same3(mine, want, 1e-9)) continue;
        std::string why, topic = "bilinear";
        if (bad_uv) {
            topic = "non-finite uv";
            why = ": a NaN or infinite uv (or a u * w that overflows) samples black";
        } else if (outside && same3(mine, t_bilinear(l, fract_uv, k.wu, k.wv), 1e-9)) {
            why = fract_why;
        } else if (huge_uv) {
            why = huge_why;
        } else if (same3(mine, t_bilinear(l, k.uv, k.wu, k.wv, 0), 1e-9)) {
            topic = "texel centers";
            why = ": that is the blend with texel centers at INTEGERS; they are at half-integers, so take x' = u * w - "
                  "0.5 before floor (at a texel's center the sample is that texel exactly)";
        } else if (same3(mine, t_bilinear(l, k.uv, k.wu, k.wv, 0.5, true), 1e-9)) {
            why = ": the weights are swapped: texel i gets (1 - a), texel i + 1 gets a, where a = x' - floor(x')";
        } else {
            why = float_rounding(mine, want);
        }
        bilinear.add(topic, "TODO 2: sample_bilinear at " + inputs + " gave " + str(mine) + ", expected " + str(want) + why);
    }
}

std::string size_name(const LevelData& l) { return std::to_string(l.width) + "x" + std::to_string(l.height); }

void judge_mipmaps(Ctx& c) {
    const Values& v = c.mine;
    const auto bases = mip_bases();
    for (std::size_t b = 0; b < bases.size(); ++b) {
        const auto want = t_pyramid(bases[b]);
        const std::string key = "mip" + std::to_string(b), name = "the " + size_name(bases[b]) + " texture";
        std::string sizes;
        for (const LevelData& l : want) sizes += (sizes.empty() ? "" : ", ") + size_name(l);
        const double levels = get(v, key + ".levels");
        if (levels != double(want.size())) {
            c.add("mipmap", "TODO 3: build_mipmaps on " + name + " made " + plural(levels, "level") + ", expected " +
                                std::to_string(want.size()) + " (" + sizes + "): each level max(1, floor(w / 2)) by max(1, "
                                "floor(h / 2)), down to and including 1x1");
            continue;
        }
        if (get(v, key + ".mipmapped") != 1) c.add("mipmap", "TODO 3: build_mipmaps must set texture.mipmapped");
        if (get(v, key + ".again.levels") != double(want.size())) {
            c.add("mipmap", "TODO 3: build_mipmaps called a second time on " + name + " left " +
                                plural(get(v, key + ".again.levels"), "level") + ": it replaces the levels above 0, it does not add more");
        }
        bool reported = false;
        for (std::size_t k = 0; k < want.size() && !reported; ++k) {
            const std::string lk = key + ".L" + std::to_string(k);
            const LevelData& l = want[k];
            if (get(v, lk + ".w") != l.width || get(v, lk + ".h") != l.height || get(v, lk + ".n") != double(l.texels.size())) {
                c.add("mipmap", "TODO 3: level " + std::to_string(k) + " of " + name + " is " + num(get(v, lk + ".w")) + "x" +
                                    num(get(v, lk + ".h")) + " with " + plural(get(v, lk + ".n"), "texel") + ", expected " + size_name(l) +
                                    " (the pyramid: " + sizes + ")");
                reported = true;
                break;
            }
            for (std::size_t i = 0; i < l.texels.size() && i < 64; ++i) {
                const Vec3 mine = vec3(v, lk + ".t" + std::to_string(i));
                if (same3(mine, l.texels[i], 1e-9)) continue;
                const int ti = int(i) % l.width, tj = int(i) / l.width;
                std::string msg = "TODO 3: level " + std::to_string(k) + " (" + size_name(l) + ") of " + name + ": texel (" +
                                  std::to_string(ti) + ", " + std::to_string(tj) + ") is " + str(mine) + ", expected " + str(l.texels[i]);
                // Whole numbers where the average is not: the average rounded (or cut) to a level.
                const auto whole_of = [&](double (*f)(double)) {
                    const Vec3 w{f(l.texels[i].x), f(l.texels[i].y), f(l.texels[i].z)};
                    return same3(mine, w, 1e-9) && !same3(w, l.texels[i], 1e-9);
                };
                if (k > 0 && (whole_of([](double x) { return std::round(x); }) || whole_of([](double x) { return std::floor(x); }) ||
                              whole_of([](double x) { return std::nearbyint(x); }))) {
                    msg += ": yours is the average made a whole number. A level's texels are Vec3 of doubles (levels "
                           "0-255, not bytes): keep the plain average of the 2x2 block as it is, unrounded (rounding at "
                           "every level adds up down the pyramid)";
                } else if (k == 0) {
                    msg += ": level 0 is the texture itself and stays as it is";
                } else {
                    const LevelData& up = want[k - 1];
                    msg += ", the plain average of level " + std::to_string(k - 1) + "'s texels (" + std::to_string(2 * ti) + ", " +
                           std::to_string(2 * tj) + ") to (" + std::to_string(2 * ti + 1) + ", " + std::to_string(2 * tj + 1) + ")";
                    // What this texel's 2x2 block meets in level k - 1: a side of 1 texel (the index 2i + 1
                    // or 2j + 1 past it is clamped to 0), or an odd side (its last column or row is dropped).
                    const bool past_w = 2 * ti + 1 >= up.width, past_h = 2 * tj + 1 >= up.height;
                    const bool odd = (up.width > 1 && up.width % 2 == 1) || (up.height > 1 && up.height % 2 == 1);
                    if (past_w || past_h) {
                        const std::string clamp = past_w && past_h ? "min(2i + 1, w - 1) and min(2j + 1, h - 1)"
                                                  : past_w           ? "min(2i + 1, w - 1)"
                                                                     : "min(2j + 1, h - 1)";
                        msg += "; level " + std::to_string(k - 1) + " is " + size_name(up) + ", 1 texel " +
                               (past_w && past_h ? "wide and high" : past_w ? "wide" : "high") +
                               ": the index past that side must be CLAMPED to it, " + clamp +
                               " (its texels counted twice); unclamped it reads another row or outside the level";
                    } else if (odd) {
                        msg += "; level " + std::to_string(k - 1) + " is " + size_name(up) +
                               ", and an odd last row or column is DROPPED (a 5-wide level makes a 2-wide one from its texels 0 "
                               "to 3)";
                    }
                }
                c.add("mipmap", msg);
                reported = true;
                break;
            }
        }
    }
    if (get(v, "empty.levels") != 1 || get(v, "empty.mipmapped") != 0) {
        c.add("mipmap", "TODO 3: build_mipmaps on a texture with no texels must leave it as it is (1 level, mipmapped "
                        "false); it made " + plural(get(v, "empty.levels"), "level"));
    }
    if (get(v, "none.levels") != 0) {
        c.add("mipmap", "TODO 3: build_mipmaps on a texture with no levels at all must leave it as it is");
    }
}

void judge_lod(Ctx& c) {
    const Values& v = c.mine;
    const auto cases = lod_cases();
    Limited out{c, "uv_derivatives", 0, 0, "level of detail", "4"};
    // Hand-worked: case 0 (1/100 exactly), cases 4 and 5 (all zero).
    const std::map<std::size_t, Derivs> hand = {{0, {0.01, 0, 0, 0.01}}, {4, {}}, {5, {}}};
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const auto& k = cases[i];
        const std::string key = "lod" + std::to_string(i);
        const char* names[4] = {".du_dx", ".dv_dx", ".du_dy", ".dv_dy"};
        double want[4], mine[4];
        const auto h = hand.find(i);
        for (int n = 0; n < 4; ++n) {
            mine[n] = get(v, key + names[n]);
            want[n] = get(c.ref, key + names[n]);
        }
        if (h != hand.end()) {
            const double hw[4] = {h->second.du_dx, h->second.dv_dx, h->second.du_dy, h->second.dv_dy};
            std::copy(hw, hw + 4, want);
        }
        double scale = 0;
        for (double w : want) scale = std::max(scale, std::isfinite(w) ? std::abs(w) : 0.0);
        bool ok = true;
        for (int n = 0; n < 4; ++n) ok &= std::abs(mine[n] - want[n]) <= 1e-6 * scale || mine[n] == want[n];
        if (ok) continue;
        std::string inputs;
        for (int n = 0; n < 3; ++n) {
            inputs += std::string(n ? "; " : "") + "(" + num(k.screen[std::size_t(n)].x) + ", " + num(k.screen[std::size_t(n)].y) +
                      ") w " + num(k.w[std::size_t(n)]) + " uv " + str(k.uv[std::size_t(n)]);
        }
        std::string why;
        const Derivs affine = t_derivatives(k, false);
        const double aff[4] = {affine.du_dx, affine.dv_dx, affine.du_dy, affine.dv_dy};
        bool is_affine = scale > 0;
        for (int n = 0; n < 4; ++n) is_affine &= std::abs(mine[n] - aff[n]) <= 1e-6 * scale;
        if (scale == 0) {
            why = ": a triangle of zero area, or a point where B = sum l_i / w_i is not > 0 and finite, gives all zero";
        } else if (is_affine) {
            why = ": those are the derivatives of the SCREEN-space interpolation; uv is A / B (perspective-correct), "
                  "so du/dx = (A_x B - A B_x) / B^2";
        } else if (const auto same = [&](int n, double sign) { return std::abs(mine[n] - sign * want[n]) <= 1e-6 * scale; };
                   (same(0, 1) && same(1, 1) && same(2, -1) && same(3, -1) && (want[2] != 0 || want[3] != 0)) ||
                   (same(0, -1) && same(1, -1) && same(2, 1) && same(3, 1) && (want[0] != 0 || want[1] != 0))) {
            const bool y = same(2, -1) && (want[2] != 0 || want[3] != 0);
            why = std::string(": the ") + (y ? "y" : "x") + " derivatives have the wrong SIGN: they are the change of "
                  "u and v as the pixel center moves one pixel toward +" + (y ? "y (DOWN the screen, y grows downward)" : "x") +
                  "; differentiate the screen weights l_i(x, y) as they are, without flipping the " + (y ? "y" : "x") +
                  " axis (the sign does not change lambda, but it is the derivative the header asks for)";
        } else {
            why = " (the exact derivative of A / B: du/dx = (A_x B - A B_x) / B^2, with A = sum l_i u_i / w_i, B = "
                  "sum l_i / w_i and l_i the screen weights)";
        }
        out.add("level of detail", "TODO 4: uv_derivatives of the triangle " + inputs + " at (" + num(k.x) + ", " + num(k.y) +
                                       ") gave du/dx " + num(mine[0]) + ", dv/dx " + num(mine[1]) + ", du/dy " + num(mine[2]) +
                                       ", dv/dy " + num(mine[3]) + "; expected " + num(want[0]) + ", " + num(want[1]) + ", " +
                                       num(want[2]) + ", " + num(want[3]) + why);
    }
    const auto lambdas = lambda_cases();
    Limited lo{c, "level_of_detail", 0, 0, "level of detail", "4"};
    for (std::size_t i = 0; i < lambdas.size(); ++i) {
        const auto& k = lambdas[i];
        const double mine = get(v, "lambda" + std::to_string(i));
        const double want = t_lambda(k.du_dx, k.dv_dx, k.du_dy, k.dv_dy, k.width, k.height);
        if (close(mine, want, 1e-6) || (std::isinf(want) && mine == want)) continue;
        std::string why;
        if (close(mine, t_lambda(k.du_dx, k.dv_dx, k.du_dy, k.dv_dy, 1, 1), 1e-6)) {
            why = ": that is rho in uv units per pixel; rho is in TEXEL units: multiply du by the width and dv by the "
                  "height of level 0 first";
        } else if (const bool x_only = close(mine, t_lambda(k.du_dx, k.dv_dx, 0, 0, k.width, k.height), 1e-6);
                   x_only || close(mine, t_lambda(0, 0, k.du_dy, k.dv_dy, k.width, k.height), 1e-6)) {
            why = std::string(": that is the length of the ") + (x_only ? "x" : "y") +
                  " derivatives alone; rho is the LARGER of the two screen directions' lengths in texels, "
                  "max(|(W du/dx, H dv/dx)|, |(W du/dy, H dv/dy)|): a surface receding along the other direction "
                  "shrinks its texels there";
        } else if (k.width != k.height && (close(mine, t_lambda(k.du_dx, k.dv_dx, k.du_dy, k.dv_dy, k.width, k.width), 1e-6) ||
                                            close(mine, t_lambda(k.du_dx, k.dv_dx, k.du_dy, k.dv_dy, k.height, k.height), 1e-6) ||
                                            close(mine, t_lambda(k.du_dx, k.dv_dx, k.du_dy, k.dv_dy, k.height, k.width), 1e-6))) {
            why = ": that scales u and v by the same size, or each by the other's; a texture that is not square has "
                  "W texels across u and H down v: du times the WIDTH, dv times the HEIGHT";
        } else if (const double ux = k.width * k.du_dx, vx = k.height * k.dv_dx, uy = k.width * k.du_dy, vy = k.height * k.dv_dy;
                   close(mine, std::log2(std::max(std::max(std::abs(ux), std::abs(vx)), std::max(std::abs(uy), std::abs(vy)))), 1e-6)) {
            why = ": that is rho from the largest single component; the header's rho is the LENGTH of each screen "
                  "direction's texel step, sqrt((W du/dx)^2 + (H dv/dx)^2), and the larger of the two lengths "
                  "(a step diagonal in the texture covers more texels than either component)";
        } else if (close(mine, 0.5 * std::log2(ux * ux + vx * vx + uy * uy + vy * vy), 1e-6) ||
                   close(mine, std::log2(std::sqrt(ux * ux + vx * vx) + std::sqrt(uy * uy + vy * vy)), 1e-6) ||
                   close(mine, std::log2((std::sqrt(ux * ux + vx * vx) + std::sqrt(uy * uy + vy * vy)) / 2), 1e-6)) {
            why = ": that combines the two screen directions (a sum, a mean or one length of all four numbers); rho is "
                  "the LARGER of the two directions' lengths, max(|(W du/dx, H dv/dx)|, |(W du/dy, H dv/dy)|)";
        } else if (std::isfinite(want) && close(mine, want * std::log(2.0), 1e-6)) {
            why = ": lambda is log2(rho), not the natural logarithm";
        } else if (std::isinf(want)) {
            why = ": rho 0 gives log2(0) = -infinity (not clamped here)";
        }
        lo.add("level of detail", "TODO 4: level_of_detail(du/dx " + num(k.du_dx) + ", dv/dx " + num(k.dv_dx) + ", du/dy " +
                                      num(k.du_dy) + ", dv/dy " + num(k.dv_dy) + ", " + std::to_string(k.width) + "x" +
                                      std::to_string(k.height) + ") gave " + num(mine) + ", expected " + num(want) + why);
    }
}

void judge_filter(Ctx& c) {
    const Values& v = c.mine;
    const auto bases = mip_bases();
    const auto cases = filter_cases();
    Limited out{c, "sample", 0, 0, "filter", "4"};
    bool lo = false, hi = false;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const auto& k = cases[i];
        if (i == 0 || k.base != cases[i - 1].base || k.filter != cases[i - 1].filter) lo = hi = false;
        const auto pyr = t_pyramid(bases[std::size_t(k.base)]);
        const bool mip = k.filter == Filter::kNearestMip || k.filter == Filter::kTrilinear;
        // Whether a level above 0 is read (the pyramid must exist), and whether lambda > 0 (it may).
        if (mip && k.lambda > 0) {
            hi = true;
            const double lam = std::min(k.lambda, double(pyr.size() - 1));
            lo |= pyr.size() > 1 && (k.filter == Filter::kTrilinear || std::floor(lam + 0.5) >= 1);
        }
        const std::string key = "filter" + std::to_string(i);
        const Vec3 mine = vec3(v, key), want = t_sample(pyr, k.uv, k.lambda, k.filter, k.wrap_u, k.wrap_v);
        const bool repeats = k.wrap_u == Wrap::kRepeat && k.wrap_v == Wrap::kRepeat;
        const std::string inputs = "sample(" + size_name(bases[std::size_t(k.base)]) + " texture" +
                                   (repeats ? std::string() : std::string(" (u ") + wrap_name(k.wrap_u) + ", v " + wrap_name(k.wrap_v) + ")") +
                                   ", uv " + str(k.uv) + ", lambda " + num(k.lambda) + ", " + filter_name(k.filter) + ")";
        if (!same3(mine, want, 1e-9)) {
            std::string why, topic = "filter";
            const double top = double(pyr.size() - 1);
            if (!mip) {
                why = ": kNearest and kBilinear read level 0 only, whatever lambda is";
            } else if (!(k.lambda > 0)) {
                why = ": lambda <= 0 (or NaN) magnifies: bilinear on level 0";
            } else if (k.lambda > top) {
                topic = "lambda clamp";
                why = ": lambda is clamped to [0, L - 1] = [0, " + num(top) + "], so the last level (" +
                      size_name(pyr.back()) + ") is read";
            } else if (!repeats && same3(mine, t_sample(pyr, k.uv, k.lambda, k.filter, Wrap::kRepeat, Wrap::kRepeat), 1e-9)) {
                topic = "wrap";
                why = std::string(": that is the sample with repeat on both axes; every level is read with the texture's "
                                  "own wrap modes (here ") + wrap_name(k.wrap_u) + " in u, " + wrap_name(k.wrap_v) +
                      " in v), not only level 0";
            } else if (k.filter == Filter::kTrilinear &&
                       same3(mine, t_sample(pyr, k.uv, k.lambda, k.filter, k.wrap_u, k.wrap_v, false), 1e-9)) {
                topic = "trilinear";
                why = ": that is level floor(lambda) alone; trilinear BLENDS the bilinear samples of levels floor(lambda) "
                      "and floor(lambda) + 1 by the fraction of lambda";
            } else if (const double lam = std::min(k.lambda, top), f = lam - std::floor(lam);
                       k.filter == Filter::kTrilinear && f != 0.5 &&
                       same3(mine,
                             t_bilinear(pyr[std::size_t(std::floor(lam))], k.uv, k.wrap_u, k.wrap_v) * f +
                                 t_bilinear(pyr[std::min(std::size_t(std::floor(lam)) + 1, pyr.size() - 1)], k.uv, k.wrap_u,
                                            k.wrap_v) * (1 - f),
                             1e-9)) {
                topic = "trilinear";
                why = ": that is the blend the wrong way round, f = " + num(f) + " on level floor(lambda) = " +
                      num(std::floor(lam)) + " and 1 - f on the next; the fraction f = lambda - floor(lambda) is the "
                      "weight of the NEXT level: (1 - f) bilinear(level floor(lambda)) + f bilinear(level floor(lambda) + 1)";
            } else if (const std::string rounding = float_rounding(mine, want); !rounding.empty()) {
                why = rounding;
            } else if (k.filter == Filter::kNearestMip) {
                why = ": nearest-mip reads level floor(lambda + 0.5) (here " + num(std::floor(std::min(k.lambda, top) + 0.5)) +
                      ") bilinearly";
            } else {
                why = ": trilinear: (1 - f) bilinear(level floor(lambda)) + f bilinear(level floor(lambda) + 1), f the "
                      "fraction of lambda, the last level when there is no next";
            }
            out.add(topic, "TODO 4: " + inputs + " gave " + str(mine) + ", expected " + str(want) + why);
        }
        const double builds = get(v, key + ".builds");
        const double want_lo = lo ? 1 : 0, want_hi = hi ? 1 : 0;
        if (!(builds >= want_lo && builds <= want_hi)) {
            std::string why;
            if (builds > 1) {
                why = ": the pyramid is built once per texture (build it only when texture.mipmapped is false)";
            } else if (builds > want_hi) {
                why = ": this and every earlier call on this texture had lambda <= 0 or a filter without mipmaps, so no "
                      "level above 0 was needed and no pyramid may be built";
            } else {
                why = ": a mip filter that needs a level above 0 builds the pyramid first (build_mipmaps) and adds 1 to "
                      "*mipmap_builds";
            }
            out.add("mipmap builds", "TODO 4: after " + inputs + " (and the calls before it on the same texture) the count of "
                                     "pyramids built is " + num(builds) + ", expected " + num(want_lo) + why);
        }
    }
    const Vec3 null_sample = vec3(v, "filter.null");
    const auto pyr = t_pyramid(bases[0]);
    if (out.shown == 0 && !same3(null_sample, t_sample(pyr, {0.3, 0.7}, 1.5, Filter::kTrilinear, Wrap::kRepeat, Wrap::kRepeat), 1e-9)) {
        c.add("filter", "TODO 4: sample() with mipmap_builds == nullptr (uv (0.3, 0.7), lambda 1.5, kTrilinear) gave " +
                            str(null_sample) + ": it must still build and sample, only not count");
    }
    {
        const Vec3 e0 = vec3(v, "filter.empty0"), e1 = vec3(v, "filter.empty1");
        const double builds = get(v, "filter.empty.builds");
        if (!same3(e0, Vec3{}, 0) || !same3(e1, Vec3{}, 0)) {
            c.add("filter", "TODO 4: sample() of a texture whose level 0 has no texels (uv (0.3, 0.7), lambda 1.5, "
                            "kTrilinear) gave " + str(e0) + " and " + str(e1) + ", expected black: there is no texel to read");
        }
        if (!(builds <= 1)) {
            c.add("mipmap builds",
                  "TODO 4: two calls of sample() on a texture whose level 0 has no texels (lambda 1.5, kTrilinear) counted " +
                      num(builds) + " pyramids built, expected at most 1: build_mipmaps leaves such a texture as it is "
                      "(mipmapped stays false), so a count taken whenever mipmapped is false grows with every call. "
                      "Return black for it before building (the reference counts nothing), or count a build once");
        }
    }
}

// What blinn_phong gives with the specular term raised from `x` instead of dot(N, H).
Vec3 with_specular_base(const PhongCase& k, double x) {
    const double c = raster::dot(unit_or_zero(k.normal), unit_or_zero(k.to_light));
    return mul(k.base, k.intensity) * c + mul(k.specular, k.intensity) * std::pow(std::max(0.0, x), k.shininess);
}

// Phong's dot(R, V), R = 2 dot(N, L) N - L, for unit N, V and L.
double phong_rv(const PhongCase& k) {
    const Vec3 n = unit_or_zero(k.normal), v = unit_or_zero(k.to_eye), l = unit_or_zero(k.to_light);
    return raster::dot(n * (2 * raster::dot(n, l)) - l, v);
}

// Blinn-Phong with N, V and L used as given (not normalized).
Vec3 unnormalized_phong(const PhongCase& k) {
    const double c = raster::dot(k.normal, k.to_light);
    if (!(c > 0)) return {};
    const double s = std::pow(std::max(0.0, raster::dot(k.normal, k.to_light + k.to_eye)), k.shininess);
    return mul(k.base, k.intensity) * c + mul(k.specular, k.intensity) * s;
}

// Blinn-Phong with the specular term from the halfway vector normalize(h), N and L unit.
Vec3 phong_with_halfway(const PhongCase& k, Vec3 h) {
    const Vec3 n = unit_or_zero(k.normal);
    return with_specular_base(k, raster::dot(n, unit_or_zero(h)));
}

// The exponent that `mine`'s specular part was raised with, when its diffuse part is right, every
// channel agrees on it and it is not the shininess asked for; NaN otherwise.
double implied_shininess(const PhongCase& k, Vec3 mine) {
    const Vec3 n = unit_or_zero(k.normal), v = unit_or_zero(k.to_eye), l = unit_or_zero(k.to_light);
    const double c = raster::dot(n, l), nh = raster::dot(n, unit_or_zero(l + v));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (!(c > 0) || !(nh > 0 && nh < 0.999)) return nan;
    const Vec3 rest = mine - mul(k.base, k.intensity) * c, scale = mul(k.specular, k.intensity);
    double s = nan;
    for (const auto& [r, w] : {std::pair{rest.x, scale.x}, std::pair{rest.y, scale.y}, std::pair{rest.z, scale.z}}) {
        if (!(w > 0)) continue;
        const double f = r / w;
        if (!(f > 0 && f < 1)) return nan;
        const double e = std::log(f) / std::log(nh);
        if (std::isnan(s)) s = e;
        else if (std::abs(e - s) > 1e-6 * std::max(1.0, std::abs(s))) return nan;
    }
    if (std::isnan(s) || std::abs(s - k.shininess) < 1e-6 * std::max(1.0, k.shininess)) return nan;
    return std::round(s * 1e6) / 1e6;
}

void judge_phong(Ctx& c) {
    const Values& v = c.mine;
    const auto cases = phong_cases();
    Limited out{c, "blinn_phong", 0, 0, "specular", "6"};
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const auto& k = cases[i];
        const Vec3 mine = vec3(v, "phong" + std::to_string(i)), want = t_phong(k);
        if (same3(mine, want, 1e-9)) continue;
        std::string why, topic = "specular";
        bool zero_vector = false;
        const double cl = raster::dot(unit_or_zero(k.normal), unit_or_zero(k.to_light));
        // The specular term raised from dot(N, L), or from Phong's dot(R, V), instead of dot(N, H).
        const bool from_nl = cl > 0 && same3(mine, with_specular_base(k, cl), 1e-9);
        const bool from_rv = cl > 0 && same3(mine, with_specular_base(k, phong_rv(k)), 1e-9);
        if (same3(mine, t_phong(k, true), 1e-9)) {
            topic = "halfway vector";
            why = ": H = L + V must be NORMALIZED before the dot product (its length is up to 2, and raised to the "
                  "shininess that is far too bright)";
        } else if (!(cl > 0) && !same3(mine, Vec3{}, 1e-12)) {
            topic = "light behind";
            why = ": dot(N, L) = " + num(cl) + " <= 0, so this light adds NOTHING: no diffuse and no specular either";
        } else if (same3(mine, Vec3{}, 1e-12)) {
            why = ": blinn_phong returned nothing";
        } else if (const char* zero = unit_or_zero(k.normal) == Vec3{}     ? "N (normal)"
                                      : unit_or_zero(k.to_eye) == Vec3{}   ? "V (to_eye)"
                                      : unit_or_zero(k.to_light) == Vec3{} ? "L (to_light)"
                                                                           : nullptr) {
            // A zero vector cannot be normalized: the header makes that light add nothing
            // (with V = 0, H = L and the result looks like a specular term raised from dot(N, L)).
            topic = "specular";
            zero_vector = true;
            why = std::string(": ") + zero + " is the zero vector, and a zero one makes the light add NOTHING (the header): "
                  "return zero, no diffuse and no specular, before normalizing (never NaN)";
        } else if (from_nl || from_rv) {
            // Phong's dot(R, V) equals dot(N, L) where V = N: one message names both.
            why = std::string(": the specular term was raised from ") +
                  (from_nl && from_rv ? "dot(N, L) (or from Phong's dot(R, V), R = 2 dot(N, L) N - L: the same number "
                                        "here, where V = N)"
                   : from_nl          ? "dot(N, L)"
                                      : "Phong's dot(R, V), R = 2 dot(N, L) N - L, the mirror direction") +
                  "; Blinn-Phong's is max(0, dot(N, H))^shininess, H = normalize(L + V), the halfway vector between the "
                  "directions to the light and to the eye";
        } else if (const Vec3 diffuse = mul(k.base, k.intensity) * cl;
                   cl > 0 && !same3(want, diffuse, 1e-9) && same3(mine, diffuse + mul(want - diffuse, k.base / 255.0), 1e-9)) {
            why = ": the diffuse part is right, but the specular part was tinted by the base color (times base / 255): "
                  "a highlight is the light's color times the material's own specular color, specular * "
                  "max(0, dot(N, H))^shininess * I, with no base in it (white plastic under a white light shines white)";
        } else if (const Vec3 l = unit_or_zero(k.to_light), e = unit_or_zero(k.to_eye);
                   cl > 0 && ((k.to_light != l && same3(mine, phong_with_halfway(k, k.to_light + e), 1e-9)) ||
                              (k.to_eye != e && same3(mine, phong_with_halfway(k, l + k.to_eye), 1e-9)) ||
                              ((k.to_light != l || k.to_eye != e) &&
                               same3(mine, phong_with_halfway(k, k.to_light + k.to_eye), 1e-9)))) {
            // L or V added into H before it was normalized (here they are not of length 1).
            topic = "halfway vector";
            why = ": the diffuse part is right, but H was built from L or V before normalizing them (here L is " +
                  num(raster::length(k.to_light)) + " and V " + num(raster::length(k.to_eye)) +
                  " long): H = normalize(L + V) is halfway between the two only when both have length 1, so normalize "
                  "L and V first, then add them";
        } else if (const double s = implied_shininess(k, mine); cl > 0 && std::isfinite(s)) {
            why = ": the diffuse part is right and the specular part is max(0, dot(N, H))^" + num(s) +
                  ", not ^shininess (" + num(k.shininess) + ")" +
                  (k.shininess != std::floor(k.shininess) && (s == std::floor(k.shininess) || s == std::round(k.shininess))
                       ? ": the shininess was made a whole number; it is a double (a loop of multiplications, or "
                         "repeated squaring, gives only whole powers: use std::pow where it is not whole)"
                       : ": raise dot(N, H) to the material's shininess itself");
        } else if (const double nh = raster::dot(unit_or_zero(k.normal),
                                                 unit_or_zero(unit_or_zero(k.to_light) + unit_or_zero(k.to_eye)));
                   cl > 0 && nh < 0 && !same3(mine, want, 1e-9)) {
            topic = "specular";
            why = ": dot(N, H) = " + num(nh) + " < 0 here (the eye is on the far side of the surface): the specular "
                  "part is max(0, dot(N, H))^shininess = 0; clamp dot(N, H) at 0 BEFORE raising it (an even power "
                  "of a negative number is positive)";
        } else if ((raster::length(k.normal) != 1 || raster::length(k.to_eye) != 1 || raster::length(k.to_light) != 1) &&
                   same3(mine, unnormalized_phong(k), 1e-9)) {
            why = ": normalize N, V and L first (here they are not of length 1; a zero one makes the light add nothing)";
        } else {
            why = float_rounding(mine, want);
        }
        if (why.empty() && cl > 0) {
            // Which half is off: the diffuse part is base * c * I, the rest must be the specular term.
            const Vec3 diffuse = mul(k.base, k.intensity) * cl, spec = want - diffuse;
            why = ": expected the diffuse part base * dot(N, L) * I = " + str(diffuse) + " plus the specular part " + str(spec) +
                  " (specular * max(0, dot(N, H))^shininess * I); your result minus that diffuse part is " + str(mine - diffuse);
        }
        out.add(topic, "TODO 6: blinn_phong(base " + str(k.base) + ", specular " + str(k.specular) + ", shininess " +
                           num(k.shininess) + ", N " + str(k.normal) + ", V " + str(k.to_eye) + ", L " + str(k.to_light) +
                           ", I " + str(k.intensity) + ") gave " + str(mine) + ", expected " + str(want) + why);
        if (zero_vector && out.more == 0) {
            c.j.findings.back().hint = "a zero N, V or L makes the light add nothing: return zero before normalizing";
        }
    }
}

void judge_tangent(Ctx& c) {
    const Values& v = c.mine;
    {
        const auto cases = frame_cases();
        Limited out{c, "tangent_frame", 0, 0, "tangent frame", "7"};
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const auto& k = cases[i];
            const std::string key = "frame" + std::to_string(i);
            const Frame want = t_frame(k);
            const bool valid = get(v, key + ".valid") == 1;
            const Vec3 t = vec3(v, key + ".t"), b = vec3(v, key + ".b");
            if (valid == want.valid && (!valid || (same3(t, want.t, 1e-9) && same3(b, want.b, 1e-9)))) continue;
            const std::string inputs = "tangent_frame(p " + str(k.p[0]) + ", " + str(k.p[1]) + ", " + str(k.p[2]) + "; uv " +
                                       str(k.uv[0]) + ", " + str(k.uv[1]) + ", " + str(k.uv[2]) + ")";
            if (valid != want.valid) {
                out.add("tangent frame", "TODO 7: " + inputs + " is " + (valid ? "" : "not ") + "valid, expected " +
                                             (want.valid ? "valid: r = du1 dv2 - du2 dv1 is small here but neither 0 nor "
                                                           "infinite, and T and B are finite; a frame is invalid only when "
                                                           "r == 0 exactly or something is not finite (no epsilon)"
                                                         : "NOT valid: r = du1 dv2 - du2 dv1 is 0 or not finite "
                                                           "(or T or B is not finite), so there is no tangent frame"));
            } else {
                out.add("tangent frame", "TODO 7: " + inputs + " gave T " + str(t) + ", B " + str(b) + "; expected T " + str(want.t) +
                                             ", B " + str(want.b) + " (T = (e1 dv2 - e2 dv1) / r, B = (e2 du1 - e1 du2) / r)");
            }
        }
    }
    const auto cases = perturb_cases();
    Limited out{c, "perturb_normal", 0, 0, "normal map", "7"};
    // Green read as -B' explains every case (where B' had to be negated it looks like a B' left
    // unnegated, so only all cases together tell the two apart).
    bool green_flipped = true;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        green_flipped &= same3(vec3(v, "perturb" + std::to_string(i)), t_perturb(cases[i], 5), 1e-9);
    }
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const auto& k = cases[i];
        const Vec3 mine = vec3(v, "perturb" + std::to_string(i)), want = t_perturb(k);
        if (same3(mine, want, 1e-9)) continue;
        // T and B used as they are; B' orthogonal to n alone (the same numbers where B is already).
        const bool raw_frame = same3(mine, t_perturb(k, 2), 1e-9), n_only_bitangent = same3(mine, t_perturb(k, 4), 1e-9);
        std::string why;
        if (same3(mine, t_perturb(k, 1), 1e-9)) {
            why = ": the texel was read as t / 255 in [0, 1]; a normal-map texel is 2 t / 255 - 1, in [-1, 1] (128 "
                  "means 0)";
        } else if (raw_frame && n_only_bitangent) {
            why = ": B' is not orthogonal to T' (B used as it is, or made orthogonal to n alone: where the uv mapping is "
                  "sheared B is not perpendicular to T); make the frame orthonormal: T' = normalize(T - n dot(n, T)), "
                  "B' = cross(n, T') (negated when it points away from B)";
        } else if (raw_frame) {
            why = ": T and B were used as they are; make the frame orthonormal: T' = normalize(T - n dot(n, T)), "
                  "B' = cross(n, T') (negated when it points away from B)";
        } else if (same3(mine, t_perturb(k, 6), 1e-9)) {
            why = ": T' is T only normalized, not made orthogonal to n first: T' = normalize(T - n dot(n, T)) "
                  "(Gram-Schmidt). Here T leans out of the surface's plane (dot(n, T) = " +
                  num(round4(raster::dot(k.n, k.tangent))) + "), and a T' that is not perpendicular to n tilts every "
                  "bump out of the surface";
        } else if (const int decode = same3(mine, t_perturb(k, 7), 1e-9)   ? 7
                                      : same3(mine, t_perturb(k, 8), 1e-9) ? 8
                                      : same3(mine, t_perturb(k, 9), 1e-9) ? 9
                                                                            : 0) {
            why = std::string(": the texel was decoded as ") +
                  (decode == 7 ? "(t - 128) / 127" : decode == 8 ? "(t - 128) / 128" : "(t - 127) / 128") +
                  "; the header's decode is 2 t / 255 - 1 = (t - 127.5) / 127.5, which takes 0 to -1, 255 to +1 and "
                  "127.5 to 0 exactly";
        } else if (green_flipped) {
            why = ": the texel's green channel tilted the normal along -B' (green up the image, as OpenGL's normal "
                  "maps have it); here green runs along +B', the way v grows, DOWN the image: m.y multiplies B' as it "
                  "is";
        } else if (same3(mine, t_perturb(k, 3), 1e-9)) {
            why = ": B' = cross(n, T') points away from B here (dot(B', B) < 0) and was not negated: B' must agree with "
                  "B, if (dot(B', B) < 0) B' = -B', or a texel's y (green) tilts the normal the wrong way along v";
        } else if (n_only_bitangent) {
            why = ": B' was made orthogonal to n but not to T' (B - n dot(n, B), normalized). Where the uv mapping is "
                  "sheared B is not perpendicular to T, so that B' is not either: take B' = cross(n, T') (negated when "
                  "it points away from B), or Gram-Schmidt B against both n and T'";
        } else if (const std::string because = unchanged_because(k); !because.empty()) {
            why = ": here the normal must come back unchanged: " + because;
        } else {
            why = " (T' = normalize(T - n dot(n, T)), B' = cross(n, T') negated when dot(B', B) < 0, m = 2 t / 255 - 1; "
                  "the result is normalize(m.x T' + m.y B' + m.z n))";
        }
        out.add("normal map", "TODO 7: perturb_normal(T " + str(k.tangent) + ", B " + str(k.bitangent) + ", valid " +
                                  (k.valid ? "true" : "false") + ", n " + str(k.n) + ", texel " + str(k.texel) + ") gave " +
                                  str(mine) + ", expected " + str(want) + why);
    }
}

void judge_shadow(Ctx& c) {
    const Values& v = c.mine;
    {
        const auto cases = light_matrix_cases();
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const auto& k = cases[i];
            const M4 want = t_light(k.direction, k.center, k.radius), flipped = t_light(k.direction, k.center, k.radius, true);
            bool ok = true, ref_ok = true, flip = true;
            M4 mine;
            for (int r = 0; r < 4; ++r) {
                for (int col = 0; col < 4; ++col) {
                    const std::string e = "light" + std::to_string(i) + "." + std::to_string(r) + std::to_string(col);
                    mine.m[r][col] = get(v, e);
                    ok &= close(mine.m[r][col], want.m[r][col], 1e-9);
                    ref_ok &= close(mine.m[r][col], get(c.ref, e), 1e-9);
                    flip &= close(mine.m[r][col], flipped.m[r][col], 1e-9);
                }
            }
            if (ok && ref_ok) continue;
            const std::string inputs = "light_view_projection(direction " + str(k.direction) + ", center " + str(k.center) +
                                       ", radius " + num(k.radius) + ")";
            std::string why;
            const Vec3 d = unit_or_zero(k.direction);
            bool zero = true;
            for (int r = 0; r < 4; ++r) {
                for (int col = 0; col < 4; ++col) zero &= mine.m[r][col] == 0;
            }
            if (d == Vec3{} || !raster::is_finite(k.direction)) {
                why = " is not the zero matrix: a zero or non-finite direction gives the zero matrix";
            } else if (zero) {
                why = " is the zero matrix, expected orthographic(-r, r, -r, r, r, 3r) * look_at(center - 2r * "
                      "normalize(direction), center, up)";
            } else if (flip) {
                why = " looks AGAINST the light: the eye is center - 2r * normalize(direction), so the light looks along "
                      "the direction its rays travel";
            } else {
                const Vec4 at_center = mul(mine, Vec4{k.center.x, k.center.y, k.center.z, 1});
                const Vec3 near_point = k.center - d * k.radius;
                const Vec4 at_near = mul(mine, Vec4{near_point.x, near_point.y, near_point.z, 1});
                if (!close(at_center.x, 0, 1e-9) || !close(at_center.y, 0, 1e-9) || !close(at_center.z, 0, 1e-9)) {
                    why = " does not take the center to the middle of the box: it gives " + str(xyz(at_center)) +
                          ", expected (0, 0, 0) (the eye 2r before the center, near r and far 3r)";
                } else if (!close(at_near.z, -1, 1e-9)) {
                    why = " puts the point r before the center (toward the light) at z_ndc " + num(at_near.z) +
                          ", expected -1: orthographic(-r, r, -r, r, r, 3r)";
                } else {
                    why = " differs from orthographic(-r, r, -r, r, r, 3r) * look_at(eye, center, up): up is (0, 1, 0), "
                          "or (1, 0, 0) when |normalize(direction).y| > 0.99";
                }
            }
            c.add("light matrix", "TODO 8: " + inputs + why);
        }
    }
    const TinyMap map = tiny_map();
    const auto cases = shadow_cases();
    // A mistake in the bias that explains every case without PCF (and changes one of them).
    auto fits = [&](Lookup mode) {
        bool changes = false;
        for (std::size_t i = 0; i < cases.size(); ++i) {
            if (cases[i].pcf) continue;
            const double wrong = t_shadow(map, cases[i], mode);
            if (!close(get(v, "shadow" + std::to_string(i)), wrong, 1e-9)) return false;
            changes |= !close(wrong, t_shadow(map, cases[i]), 1e-9);
        }
        return changes;
    };
    // The PCF kernel off centre: every PCF case as the 3x3 shifted by one texel along both axes.
    auto pcf_fits = [&](Lookup mode) {
        bool changes = false;
        for (std::size_t i = 0; i < cases.size(); ++i) {
            if (!cases[i].pcf) continue;
            const double wrong = t_shadow(map, cases[i], mode);
            if (!close(get(v, "shadow" + std::to_string(i)), wrong, 1e-9)) return false;
            changes |= !close(wrong, t_shadow(map, cases[i]), 1e-9);
        }
        return changes;
    };
    const bool pcf_ahead = pcf_fits(Lookup::kPcfAhead), pcf_behind = pcf_fits(Lookup::kPcfBehind);
    // Divided by 8: every PCF case lit / 8, where all nine lit gives 9 / 8 or 1 (a min keeps it).
    const bool pcf_over_8 = [&] {
        bool changes = false;
        for (std::size_t i = 0; i < cases.size(); ++i) {
            if (!cases[i].pcf) continue;
            const double mine = get(v, "shadow" + std::to_string(i)), right = t_shadow(map, cases[i]);
            const double eighths = t_shadow(map, cases[i], Lookup::kPcfOver8);
            if (!close(mine, eighths, 1e-9) && !(right == 1 && close(mine, 9.0 / 8, 1e-9))) return false;
            changes |= !close(mine, right, 1e-9);
        }
        return changes;
    }();
    // A point's position on the map in texels: m3::to_screen's x and y of light * p.
    const M4 light = t_light(map.direction, map.center, map.radius);
    auto on_map = [&](Vec3 p) {
        const Vec4 q = mul(light, Vec4{p.x, p.y, p.z, 1});
        return Vec2{(q.x / q.w + 1) / 2 * map.resolution, (1 - q.y / q.w) / 2 * map.resolution};
    };
    // A mistake in finding the texel that explains every case, with and without PCF (the PCF
    // cases may also be right), and changes one of them. Rounding: the cases' points lie at
    // texel centers, where x + 0.5 is whole and a rounding the last bit below it (to_screen's
    // arithmetic is not the judge's) reads the texel before: either is the same mistake.
    // at_center: whether case i's point lies at a texel's center along x or y; with `positive`,
    // only where x and y are both above 0 (there a cast to int agrees with floor).
    auto at_center = [&](std::size_t i, bool positive = false) {
        const Vec2 xy = on_map(cases[i].p);
        const auto center = [](double t) { return std::abs(t + 0.5 - std::round(t + 0.5)) < 1e-9; };
        return (center(xy.x) || center(xy.y)) && (!positive || (xy.x > 0 && xy.y > 0));
    };
    auto is_mode = [&](std::size_t i, Lookup mode) {
        const double mine = get(v, "shadow" + std::to_string(i));
        return close(mine, t_shadow(map, cases[i], mode), 1e-9) ||
               (mode == Lookup::kRounded && at_center(i) && close(mine, t_shadow(map, cases[i], Lookup::kRoundedDown), 1e-9));
    };
    auto texel_fits = [&](Lookup mode) {
        // Rounding must show where only it can: a point at a texel's center right of 0 read in
        // the NEXT texel (a cast to int, or floor, never does that; left of 0 a cast does too).
        bool changes = false, plain = true, rounds_up = mode != Lookup::kRounded;
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const double mine = get(v, "shadow" + std::to_string(i)), right = t_shadow(map, cases[i]);
            if (!is_mode(i, mode) && !(cases[i].pcf && close(mine, right, 1e-9))) return false;
            plain &= cases[i].pcf || is_mode(i, mode);
            changes |= !close(mine, right, 1e-9);
            rounds_up |= at_center(i, true) && !close(mine, right, 1e-9);
        }
        return changes && plain && rounds_up;
    };
    const bool rounded = texel_fits(Lookup::kRounded), grid_short = texel_fits(Lookup::kGridShort);
    Limited out{c, "shadow_factor", 0, 0, "shadow", "8"};
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const auto& k = cases[i];
        const double mine = get(v, "shadow" + std::to_string(i)), want = t_shadow(map, k);
        if (close(mine, want, 1e-9)) continue;
        std::string why, topic = k.pcf ? "pcf" : "shadow";
        // The comparison reversed: the plain lit and shadowed cases (0 and 1) both come out the other way.
        const bool reversed = close(get(v, "shadow0"), t_shadow(map, cases[0], Lookup::kReversed), 1e-9) &&
                              close(get(v, "shadow1"), t_shadow(map, cases[1], Lookup::kReversed), 1e-9) &&
                              !close(get(v, "shadow0"), t_shadow(map, cases[0]), 1e-9);
        const double bias = t_bias(map, k), depth_bias = bias / (2 * map.radius);
        if (grid_short) {
            topic = "shadow";  // PCF cases too: the texel is wrong before any is counted
            const double x = on_map(k.p).x;
            why = ": every case comes out as if the texel were found on a " + num(map.resolution - 1) + " x " +
                  num(map.resolution - 1) + " grid: NDC -1 .. 1 spans all " + num(map.resolution) +
                  " texels, so x = (x_ndc + 1) / 2 * resolution (here " + num(round4(x)) + ", column " +
                  num(std::floor(x)) + "): m3::to_screen(light * p, resolution, resolution), as the depth pass drew it";
        } else if (rounded && is_mode(i, Lookup::kRounded)) {
            const double x = on_map(k.p).x;
            why = ": the texel is found by ROUNDING: x = " + num(round4(x)) + " lies in column " + num(std::floor(x)) +
                  " = floor(x), and floor(x + 0.5) reads column " + num(std::floor(x + 0.5)) +
                  ". Texel (col, row) covers [col, col + 1) x [row, row + 1), its center at col + 0.5 (as the depth "
                  "pass drew it), so the texel a point falls in is (floor(x), floor(y)) of m3::to_screen";
        } else if (reversed && !k.pcf) {
            why = ": the comparison is reversed: a point is in shadow when it is FARTHER from the light than the stored "
                  "depth, d - bias / (2r) > stored";
        } else if (fits(Lookup::kBiasAdded) && close(mine, t_shadow(map, k, Lookup::kBiasAdded), 1e-9)) {
            topic = "shadow bias";
            why = ": the bias was ADDED to the point's depth: the test is d - bias / (2r) > stored, which moves the point "
                  "TOWARD the light (here by " + num(round4(bias)) + " world units, " + num(round4(depth_bias)) +
                  " in depth); adding it pushes a lit surface behind its own stored depth, so it shadows itself";
        } else if (fits(Lookup::kWorldBias) && close(mine, t_shadow(map, k, Lookup::kWorldBias), 1e-9)) {
            topic = "shadow bias";
            why = ": the bias (here " + num(round4(bias)) + " world units) was subtracted from d as it is, not converted "
                  "to depth units: d runs from 0 to 1 over the light's box, 2r = " + num(2 * map.radius) + " world units "
                  "deep, so the test is d - bias / (2r) = d - " + num(round4(depth_bias)) + " > stored";
        } else if (fits(Lookup::kOverR) && close(mine, t_shadow(map, k, Lookup::kOverR), 1e-9)) {
            topic = "shadow bias";
            why = ": the bias (here " + num(round4(bias)) + " world units) was divided by r = " + num(map.radius) +
                  ", not 2r: d runs from 0 to 1 over the light's box, 2r = " + num(2 * map.radius) +
                  " world units deep, so the test is d - bias / (2r) = d - " + num(round4(depth_bias)) +
                  " > stored; with r the bias is twice too large";
        } else if (fits(Lookup::kRawDirection) && close(mine, t_shadow(map, k, Lookup::kRawDirection), 1e-9)) {
            topic = "shadow bias";
            why = ": the light's direction was passed " + num(k.direction_scale) +
                  " times as long as a unit vector, and c = dot(n, -direction) was taken from it as it is: normalize "
                  "the direction first (c = " + num(round4(raster::dot(k.n, -unit_or_zero(map.direction)))) +
                  " here, tan(theta) = " + num(round4((bias - k.constant_bias) / k.slope_bias)) + ")";
        } else if (fits(Lookup::kAlongRays) && close(mine, t_shadow(map, k, Lookup::kAlongRays), 1e-9)) {
            topic = "shadow bias";
            why = ": every case here takes the capped bias, constant + slope * 10 (" +
                  num(round4(t_bias(map, k, Lookup::kAlongRays))) + " world units here), as if no surface faced the "
                  "light: c = dot(n, L) with L = -normalize(direction), the way TOWARD the light (a light's direction "
                  "is the way its rays travel); with +direction a surface facing the light gets c <= 0 (here c = " +
                  num(round4(raster::dot(k.n, -unit_or_zero(map.direction)))) + ")";
        } else if (fits(Lookup::kNdcDepth) && close(mine, t_shadow(map, k, Lookup::kNdcDepth), 1e-9)) {
            topic = "shadow";  // PCF cases too: the depth is wrong before any texel is counted
            why = ": the point's depth was taken as z_ndc itself (in [-1, 1]), which puts it nearer the light than "
                  "every stored depth: the stored keys are window depths d = (z_ndc + 1) / 2 in [0, 1], as "
                  "m4::depth_key made them, so compare d - bias / (2r) with them (here d = " +
                  num(round4(t_shadow_depth(map, k) + bias / (2 * map.radius))) + ")";
        } else if (fits(Lookup::kUncapped) && close(mine, t_shadow(map, k, Lookup::kUncapped), 1e-9)) {
            topic = "shadow bias";
            why = ": tan(theta) = " + num(round4((t_bias(map, k, Lookup::kUncapped) - k.constant_bias) / k.slope_bias)) +
                  " here was not capped: bias = constant + slope * min(tan(theta), 10) = " + num(round4(bias)) + " world units";
        } else if (fits(Lookup::kTieShadowed) && close(mine, t_shadow(map, k, Lookup::kTieShadowed), 1e-9)) {
            why = ": here d - bias / (2r) EQUALS the stored depth (" + num(round4(t_shadow_depth(map, k))) +
                  ", a surface at exactly the depth it drew), and that is lit: the point is in shadow only when it is "
                  "strictly farther, d - bias / (2r) > stored (>= shadows a tie)";
        } else if (fits(Lookup::kUnflipped) && close(mine, t_shadow(map, k, Lookup::kUnflipped), 1e-9)) {
            why = ": the map is read upside down: the texel's row is floor(y) of m3::to_screen, which flips NDC y "
                  "(y = (1 - y_ndc) / 2 * resolution, row 0 at the top, as the depth pass drew it)";
        } else if (k.pcf && pcf_over_8) {
            why = ": every PCF case comes out as the lit texels of the 3x3 divided by 8: a 3x3 has NINE texels (the "
                  "center one too), so the factor is lit / 9";
        } else if (k.pcf && (pcf_fits(Lookup::kPcf2x2) || pcf_fits(Lookup::kPcf2x2Behind))) {
            why = ": every PCF case comes out as a 2x2 kernel (four texels, lit / 4): the header's PCF is the 3x3 "
                  "texels around the one p falls in, offsets -1, 0, 1 along each axis, lit / 9";
        } else if (k.pcf && (pcf_ahead || pcf_behind)) {
            why = std::string(": every PCF case comes out as a 3x3 kernel OFF CENTRE, texels ") +
                  (pcf_ahead ? "col .. col + 2 and row .. row + 2 (offsets 0, 1, 2)" : "col - 2 .. col and row - 2 .. row (offsets -2, -1, 0)") +
                  ": the kernel is centered on the texel (col, row) p falls in, offsets -1, 0, 1 along each axis";
        } else if (i == 2) {
            topic = "shadow bias";
            why = ": the point is 0.001 below the floor's stored depth; the constant bias (0.02 world units, 0.02 / (2r) in "
                  "depth) keeps it lit: without a bias a surface shadows itself (acne)";
        } else if (i == 3) {
            topic = "shadow bias";
            why = ": here c = dot(N, L) = 0.2, so tan(theta) = sqrt(1 - c^2) / c = 4.9 and the bias is 0.02 + 0.02 * 4.9 = "
                  "0.118 world units: that slope term keeps it lit";
        } else if (i == 4) {
            topic = "shadow bias";
            why = ": here c = 0.01, tan(theta) = 99.99 is capped at 10: bias = 0.02 + 0.02 * 10 = 0.22 world units, and the "
                  "point 0.3 below the floor is in shadow";
        } else if (i == 16) {
            why = ": the point is 0.05 below the floor, so each of the 4 texels of the 3x3 inside the map shadows it, and "
                  "the 5 outside the map are lit (not the edge texels again): 5 of 9";
        } else if (i == 17) {
            why = ": p falls in column -1, just outside the map, but with PCF the 3x3 around it still has column 0's 3 "
                  "texels inside the map, which shadow it, and 6 outside it, which are lit: a factor of 6 / 9 (only a 3x3 "
                  "wholly outside the map is wholly lit)";
        } else if (i == 18) {
            why = ": here x = -0.3 texels: column floor(-0.3) = -1 is outside the map, so the point is lit; a cast to int "
                  "truncates toward zero and reads column 0";
        } else if (i == 19) {
            why = ": the texel was never drawn (kClearKey), so the point is lit whatever its depth (here d = 1.125, beyond "
                  "the box's far side): kClearKey is not the depth 1";
        } else if (i == 20) {
            topic = "shadow bias";
            why = ": the point is 0.03 below the floor, beyond the constant bias of 0.02 world units (0.02 / (2r) in "
                  "depth, as the floor faces the light: tan(theta) = 0), so the floor's texel shadows it";
        } else if (i == 21) {
            topic = "shadow bias";
            why = ": this is case 3 with the direction passed 3 times as long; c = dot(n, -normalize(direction)) = 0.2 "
                  "still, so the slope term keeps it lit";
        } else if (i == 22 || i == 23) {
            why = ": here d - bias / (2r) EQUALS the stored depth (" + num(round4(t_shadow_depth(map, k))) +
                  (i == 23 ? ", with the bias 0.25 / (2r) = 0.0625 taken off d = 0.5625" : ", with no bias") +
                  "), and a tie is lit: the point is in shadow only when d - bias / (2r) > stored, strictly";
        } else if (k.settings_radius > 0 && k.settings_radius != map.radius) {
            topic = "shadow bias";
            why = ": the settings passed here have radius " + num(k.settings_radius) + ", the map was drawn with radius " +
                  num(map.radius) + ": d spans the MAP's box, so the bias converts to depth as bias / (2 * map.radius) "
                  "(textures_shadows.h: r = map.radius), not with the settings' radius";
        } else if (k.pcf) {
            why = ": with PCF the factor is the lit fraction of the 3x3 texels around the one p falls in (a texel outside "
                  "the map, or never drawn, is lit)";
        } else {
            why = ": the texel is column floor(x), row floor(y) of m3::to_screen(light * p) on a resolution^2 map, d = (z_ndc "
                  "+ 1) / 2; outside or never drawn is lit";
        }
        out.add(topic, "TODO 8: shadow_factor at p " + str(k.p) + " with n " + str(k.n) + " (constant bias " + num(k.constant_bias) +
                           ", slope bias " + num(k.slope_bias) + ", pcf " + (k.pcf ? "on" : "off") +
                           ") on the 4x4 map of a light looking straight down at radius 2" +
                           (k.direction_scale != 1 ? ", its direction passed as " + str(map.direction * k.direction_scale) + ","
                                                   : std::string()) +
                           (k.settings_radius > 0 ? ", the settings' radius " + num(k.settings_radius) + "," : std::string()) +
                           " gave " + num(mine) + ", expected " +
                           num(want) + why);
    }
}

void judge_group(Group g, Ctx& c) {
    switch (g) {
        case Group::kWrap: judge_wrap(c); break;
        case Group::kSampling: judge_sampling(c); break;
        case Group::kMipmaps: judge_mipmaps(c); break;
        case Group::kLod: judge_lod(c); break;
        case Group::kFilter: judge_filter(c); break;
        case Group::kBlinnPhong: judge_phong(c); break;
        case Group::kTangent: judge_tangent(c); break;
        case Group::kShadow: judge_shadow(c); break;
    }
}

// ---- pictures ----

// Pixels next to an edge or a color boundary of the expected image (a neighbour differs by more
// than 16 levels) may differ, up to a fifth of them; elsewhere 3 levels (rounding). So may the
// pixels of scene s where kNearestMip's choice of level is ambiguous (mip_ambiguous below).
cp::Tolerance tolerance_for(const Scene& s, const raster::Image& expected);

LevelData level_of(const TextureSpec& spec) {
    const raster::Image img = texture_image(spec);
    LevelData l;
    l.width = img.width();
    l.height = img.height();
    for (int y = 0; y < l.height; ++y) {
        for (int x = 0; x < l.width; ++x) {
            const Color c = img.at(x, y);
            l.texels.push_back({double(c.r), double(c.g), double(c.b)});
        }
    }
    return l;
}

Vec3 rotate(Vec3 axis, double angle, Vec3 v) {
    const Vec3 k = unit_or_zero(axis);
    if (k == Vec3{}) return v;
    const double c = std::cos(angle), s = std::sin(angle);
    return v * c + raster::cross(k, v) * s + k * (raster::dot(k, v) * (1 - c));
}

struct WorldTri {
    Vec3 a, b, c;
    Vec2 ua, ub, uc;
    int item;
};
std::vector<WorldTri> world_triangles(const Panel& p, bool first_only) {
    std::vector<WorldTri> out;
    for (std::size_t i = 0; i < p.items.size() && (!first_only || i == 0); ++i) {
        const Item& it = p.items[i];
        std::vector<Vec3> w;
        for (const Vec3& q : it.mesh.positions) w.push_back(it.position + rotate(it.axis, it.angle, mul(it.size, q)));
        for (const auto& t : it.mesh.triangles) {
            if (t[0] < 0 || t[1] < 0 || t[2] < 0 || std::size_t(std::max({t[0], t[1], t[2]})) >= w.size()) continue;
            WorldTri tri{w[std::size_t(t[0])], w[std::size_t(t[1])], w[std::size_t(t[2])], {}, {}, {}, int(i)};
            if (it.mesh.uvs.size() == w.size()) {
                tri.ua = it.mesh.uvs[std::size_t(t[0])];
                tri.ub = it.mesh.uvs[std::size_t(t[1])];
                tri.uc = it.mesh.uvs[std::size_t(t[2])];
            }
            out.push_back(tri);
        }
    }
    return out;
}

struct Hit {
    double t = std::numeric_limits<double>::infinity();
    const WorldTri* tri = nullptr;
    double b1 = 0, b2 = 0;
};
// Moller-Trumbore, both faces; the nearest hit with t > t_min.
Hit cast(const std::vector<WorldTri>& tris, Vec3 o, Vec3 d, double t_min) {
    Hit best;
    for (const WorldTri& tri : tris) {
        const Vec3 e1 = tri.b - tri.a, e2 = tri.c - tri.a;
        const Vec3 p = raster::cross(d, e2);
        const double det = raster::dot(e1, p);
        if (det == 0 || !std::isfinite(det)) continue;
        const Vec3 s = o - tri.a;
        const double u = raster::dot(s, p) / det;
        if (u < 0 || u > 1) continue;
        const Vec3 q = raster::cross(s, e1);
        const double w = raster::dot(d, q) / det;
        if (w < 0 || u + w > 1) continue;
        const double t = raster::dot(e2, q) / det;
        if (t > t_min && t < best.t) best = {t, &tri, u, w};
    }
    return best;
}

struct Basis {
    Vec3 r, u, f;
};
Basis basis(const Camera& c) {
    Vec3 f = unit_or_zero(c.target - c.eye);
    if (f == Vec3{}) f = {0, 0, -1};
    const Vec3 r = unit_or_zero(raster::cross(f, unit_or_zero(c.up)));
    return {r, raster::cross(r, f), f};
}
// The ray through the point (x, y) (pixels) of a panel.
Vec3 ray(const Panel& p, const Basis& b, double x, double y) {
    const double t = std::tan(p.camera.fovy * std::numbers::pi / 360), aspect = double(p.w) / p.h;
    const double nx = 2 * x / p.w - 1, ny = 1 - 2 * y / p.h;
    return b.r * (nx * t * aspect) + b.u * (ny * t) + b.f;
}

Vec2 uv_at(const Hit& h) {
    const double b0 = 1 - h.b1 - h.b2;
    return h.tri->ua * b0 + h.tri->ub * h.b1 + h.tri->uc * h.b2;
}

const TextureSpec* first_texture(const Panel& p) {
    if (p.items.empty()) return nullptr;
    const int t = p.items[0].material.texture;
    return t >= 0 && std::size_t(t) < p.textures.size() ? &p.textures[std::size_t(t)] : nullptr;
}

// ---- where kNearestMip's level is ambiguous ----
//
// The header lets lambda come from the snapped or the unsnapped screen positions, with the
// arithmetic in any order, with or without FMA. kNearestMip reads level floor(lambda + 0.5), so where lambda lies
// within reach of a boundary k + 0.5 those choices read different levels, and every one of them
// is right. The judge recomputes lambda at each pixel center from the scene (the triangle the
// pixel shows) and its reach: how far lambda moves when each vertex coordinate moves by one
// step of the snapping grid (a bound on snapped against unsnapped, which differ by half a
// step at most), plus 1e-3 for rounding (derivatives computed in float, which m5.lod rejects,
// stay within it on every seed tried). Such a pixel joins the lenient mask.

// lambda by the lesson's rule at c's pixel (x, y), for a base level c.width x c.height; NaN where
// the derivatives are undefined.
double lambda_of(const LodCase& c) {
    const Derivs d = t_derivatives(c);
    return d.defined ? t_lambda(d.du_dx, d.dv_dx, d.du_dy, d.dv_dy, c.width, c.height)
                     : std::numeric_limits<double>::quiet_NaN();
}

// Whether kNearestMip may read either of two levels at c's pixel (x, y) of its triangle, for a
// base level c.width x c.height.
bool nearest_mip_ambiguous(const LodCase& t) {
    int last = 0;
    for (int n = std::max(t.width, t.height); n > 1; n /= 2) ++last;
    if (last == 0) return false;
    const double lambda = lambda_of(t);
    if (!std::isfinite(lambda)) return false;
    double reach = 1e-3;
    const double step = 1.0 / 16;  // milestone 2's snapping grid (m2::kSubpixelSteps)
    for (int i = 0; i < 3; ++i) {
        for (int axis = 0; axis < 2; ++axis) {
            LodCase moved = t;
            (axis == 0 ? moved.screen[std::size_t(i)].x : moved.screen[std::size_t(i)].y) += step;
            const double l = lambda_of(moved);
            reach += std::isfinite(l) ? std::abs(l - lambda) : std::numeric_limits<double>::infinity();
        }
    }
    // Boundaries between levels that can be read: 0.5, 1.5, ..., last - 0.5 (lambda is clamped
    // to the last level, and at or below 0.5 level 0 is read either way).
    const double k = std::floor(lambda);
    for (double boundary : {k - 0.5, k + 0.5, k + 1.5}) {
        if (boundary >= 0.5 && boundary <= last - 0.5 && std::abs(lambda - boundary) <= reach) return true;
    }
    return false;
}

// The base level of a nearest-mip material's texture, or nullptr for any other material.
const TextureSpec* nearest_mip_texture(const Panel& p, const MaterialSpec& m) {
    if (m.filter != Filter::kNearestMip || m.texture < 0 || std::size_t(m.texture) >= p.textures.size()) return nullptr;
    const TextureSpec& t = p.textures[std::size_t(m.texture)];
    return t.width > 0 && t.height > 0 ? &t : nullptr;
}

// Marks in `mask` (the scene's image) the pixels of panel p where kNearestMip's level is
// ambiguous: for triangles given on the screen every pixel center on one (within a tenth of a
// pixel), for a scene drawn through draw_scene the triangle a ray through the pixel center
// meets first, projected by the panel's camera (clipped at the near plane first).
void mark_mip_ambiguous(const Panel& p, raster::Mask& mask) {
    for (const ScreenTri& st : p.screen_tris) {
        const TextureSpec* tex = nearest_mip_texture(p, st.material);
        if (!tex) continue;
        LodCase t{st.screen, st.w, st.uv, 0, 0, tex->width, tex->height};
        const auto& q = st.screen;
        const double area2 = (q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[1].y - q[0].y) * (q[2].x - q[0].x);
        if (area2 == 0 || !std::isfinite(area2)) continue;
        const double x_lo = std::min({q[0].x, q[1].x, q[2].x}), x_hi = std::max({q[0].x, q[1].x, q[2].x});
        const double y_lo = std::min({q[0].y, q[1].y, q[2].y}), y_hi = std::max({q[0].y, q[1].y, q[2].y});
        for (int y = std::max(0, int(std::floor(y_lo)) - 1); y < std::min(p.h, int(std::ceil(y_hi)) + 1); ++y) {
            for (int x = std::max(0, int(std::floor(x_lo)) - 1); x < std::min(p.w, int(std::ceil(x_hi)) + 1); ++x) {
                const double px = x + 0.5, py = y + 0.5;
                bool inside = true;
                for (int i = 0; i < 3 && inside; ++i) {
                    const Vec3 a = q[std::size_t(i)], b = q[std::size_t((i + 1) % 3)];
                    const double e = ((b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x)) / (area2 > 0 ? 1 : -1);
                    inside = e >= -0.1 * std::hypot(b.x - a.x, b.y - a.y);
                }
                t.x = px;
                t.y = py;
                if (inside && nearest_mip_ambiguous(t)) mask.set(p.x0 + x, p.y0 + y);
            }
        }
    }
    if (p.items.empty() || p.w <= 0 || p.h <= 0) return;
    bool any = false;
    for (const Item& it : p.items) any |= nearest_mip_texture(p, it.material) != nullptr;
    if (!any) return;
    const auto tris = world_triangles(p, false);
    const Basis b = basis(p.camera);
    const double t = std::tan(p.camera.fovy * std::numbers::pi / 360), aspect = double(p.w) / p.h;
    auto project = [&](Vec3 q) {
        const Vec3 d = q - p.camera.eye;
        const double z = raster::dot(d, b.f);
        return Vec3{(raster::dot(d, b.r) / (z * t * aspect) + 1) * p.w / 2, (1 - raster::dot(d, b.u) / (z * t)) * p.h / 2, 0};
    };
    for (int y = 0; y < p.h; ++y) {
        for (int x = 0; x < p.w; ++x) {
            const Hit h = cast(tris, p.camera.eye, ray(p, b, x + 0.5, y + 0.5), 0);
            if (!h.tri) continue;
            const TextureSpec* tex = nearest_mip_texture(p, p.items[std::size_t(h.tri->item)].material);
            if (!tex) continue;
            // The triangle clipped at the near plane (view depth >= near), fanned from its first corner.
            struct Corner {
                Vec3 q;
                Vec2 uv;
                double z;
            };
            std::vector<Corner> in = {{h.tri->a, h.tri->ua, 0}, {h.tri->b, h.tri->ub, 0}, {h.tri->c, h.tri->uc, 0}}, out;
            for (Corner& k : in) k.z = raster::dot(k.q - p.camera.eye, b.f);
            const double near = p.camera.near;
            for (std::size_t i = 0; i < in.size(); ++i) {
                const Corner &c0 = in[i], &c1 = in[(i + 1) % in.size()];
                if (c0.z >= near) out.push_back(c0);
                if ((c0.z >= near) != (c1.z >= near)) {
                    const double s = (near - c0.z) / (c1.z - c0.z);
                    out.push_back({c0.q + (c1.q - c0.q) * s, c0.uv + (c1.uv - c0.uv) * s, near});
                }
            }
            for (std::size_t i = 1; i + 1 < out.size(); ++i) {
                const LodCase st{{project(out[0].q), project(out[i].q), project(out[i + 1].q)},
                                 {out[0].z, out[i].z, out[i + 1].z},
                                 {out[0].uv, out[i].uv, out[i + 1].uv},
                                 x + 0.5,
                                 y + 0.5,
                                 tex->width,
                                 tex->height};
                if (nearest_mip_ambiguous(st)) {
                    mask.set(p.x0 + x, p.y0 + y);
                    break;
                }
            }
        }
    }
}

// ---- where the shadow normal's choice decides the light state ----
//
// The header lets fill_triangle pass shadow_factor the shading normal (after the normal map,
// the reference's) or the interpolated one before the map, and the slope bias follows it. On a
// normal-mapped surface the two differ. The map's texels hold the surface's own depth, up to
// `reach` texels from the point (about 0.7 without PCF, 2 with its 3x3), so tan(theta) * reach
// nearer the light. A mapped normal tilted toward the light by up to `tilt` (the largest angle of
// the normal map's texels from straight up) gives the smallest bias; where even that bias may
// fall short of tan(theta) * reach, or where the geometric normal faces away from the light while
// a mapped one may face it (the lookup is made by the shading normal), the two choices can differ
// in the light state: such pixels join the lenient mask. theta is the flat triangle's (the scenes'
// normal-mapped items are flat-faced or finely tessellated). (A walk-through found 2 or 3 such
// pixels on m5.showcase's box, on its face away from the light, at some grading seeds.)
double normal_map_tilt(const TextureSpec& spec) {
    double tilt = 0;
    for (const Vec3& c : level_of(spec).texels) {
        const Vec3 n = unit_or_zero(c * (2.0 / 255) - Vec3{1, 1, 1});
        tilt = std::max(tilt, std::acos(std::clamp(n.z, -1.0, 1.0)));
    }
    return tilt;
}

// The panel's (last) light that casts shadows, or nullptr.
const LightSpec* shadow_light(const Panel& p) {
    const LightSpec* light = nullptr;
    for (const LightSpec& l : p.lights) {
        if (l.casts_shadows) light = &l;
    }
    return light;
}

void mark_shadow_normal_ambiguous(const Panel& p, raster::Mask& mask) {
    if (p.items.empty() || p.w <= 0 || p.h <= 0 || !(p.shadows.resolution > 0)) return;
    const LightSpec* light = shadow_light(p);
    if (!light) return;
    std::vector<double> tilt(p.items.size(), -1);  // -1: no normal map
    bool mapped = false;
    for (std::size_t i = 0; i < p.items.size(); ++i) {
        const int m = p.items[i].material.normal_map;
        if (m >= 0 && std::size_t(m) < p.textures.size()) {
            tilt[i] = normal_map_tilt(p.textures[std::size_t(m)]);
            mapped = true;
        }
    }
    if (!mapped) return;
    const double texel = 2 * p.shadows.radius / p.shadows.resolution;
    const double reach = (p.shadows.pcf ? 2.0 : 0.75) * texel;
    const double right_angle = std::numbers::pi / 2;
    const Vec3 to_light = -unit_or_zero(light->direction);
    const auto tris = world_triangles(p, false);
    const Basis b = basis(p.camera);
    for (int y = 0; y < p.h; ++y) {
        for (int x = 0; x < p.w; ++x) {
            const Vec3 d = ray(p, b, x + 0.5, y + 0.5);
            const Hit h = cast(tris, p.camera.eye, d, 0);
            if (!h.tri || tilt[std::size_t(h.tri->item)] <= 0) continue;
            Vec3 n = unit_or_zero(raster::cross(h.tri->b - h.tri->a, h.tri->c - h.tri->a));
            if (raster::dot(n, d) > 0) n = -n;  // the side the camera sees, whatever the winding
            const double theta = std::acos(std::clamp(raster::dot(n, to_light), -1.0, 1.0));
            const double least = theta - tilt[std::size_t(h.tri->item)];  // the mapped normal's smallest angle
            if (least >= right_angle) continue;  // no normal faces the light: no lookup either way
            const bool ambiguous =
                theta >= right_angle ||
                p.shadows.constant_bias + p.shadows.slope_bias * std::tan(std::max(0.0, least)) < reach * std::tan(theta);
            if (ambiguous) mask.set(p.x0 + x, p.y0 + y);
        }
    }
}

cp::Tolerance tolerance_for(const Scene& s, const raster::Image& expected) {
    cp::Tolerance tol = cp::edge_tolerance(
        expected, "pixels next to an edge, a texel or shadow boundary or a change of mip level depend on rounding");
    const long long band = tol.lenient.count();
    raster::Mask mip(expected.width(), expected.height());
    for (const Panel& p : s.panels) {
        mark_mip_ambiguous(p, mip);
        mark_shadow_normal_ambiguous(p, mip);
    }
    long long added = 0;
    for (int y = 0; y < expected.height(); ++y) {
        for (int x = 0; x < expected.width(); ++x) {
            if (mip.get(x, y) && !tol.lenient.get(x, y)) {
                tol.lenient.set(x, y);
                ++added;
            }
        }
    }
    // Every ambiguous pixel may read the other level (or take the other light state); the edge
    // band keeps its fifth.
    tol.max_lenient_diffs = band / 5 + added;
    return tol;
}

}  // namespace

// The 16x supersampled bilinear truth of item 0 (an unlit textured quad): per pixel the mean of
// 4x4 bilinear samples at the exact uv of the ray through each; pixels not wholly on the quad
// are left out (-1 in `valid`).
Truth bilinear_truth(const Panel& p) {
    Truth t{raster::Image(p.w, p.h, p.background), std::vector<char>(std::size_t(p.w) * std::size_t(p.h), 0)};
    const TextureSpec* spec = first_texture(p);
    if (!spec) return t;
    const LevelData level = level_of(*spec);
    const auto tris = world_triangles(p, true);
    const Basis b = basis(p.camera);
    for (int y = 0; y < p.h; ++y) {
        for (int x = 0; x < p.w; ++x) {
            Vec3 sum{};
            int hits = 0;
            for (int sy = 0; sy < 4; ++sy) {
                for (int sx = 0; sx < 4; ++sx) {
                    const Hit h = cast(tris, p.camera.eye, ray(p, b, x + (sx + 0.5) / 4, y + (sy + 0.5) / 4), 0);
                    if (!h.tri) continue;
                    ++hits;
                    sum = sum + t_bilinear(level, uv_at(h), spec->wrap_u, spec->wrap_v);
                }
            }
            if (hits < 16) continue;
            t.img.set(x, y, to_color(sum / 16));
            t.valid[std::size_t(y) * std::size_t(p.w) + std::size_t(x)] = 1;
        }
    }
    return t;
}

// The mean absolute channel difference over the valid pixels of a panel.
double truth_error(const raster::Image& img, const Panel& p, const Truth& t) {
    double sum = 0;
    long long n = 0;
    for (int y = 0; y < p.h; ++y) {
        for (int x = 0; x < p.w; ++x) {
            if (!t.valid[std::size_t(y) * std::size_t(p.w) + std::size_t(x)]) continue;
            const Color a = img.at(p.x0 + x, p.y0 + y), e = t.img.at(x, y);
            sum += std::abs(a.r - e.r) + std::abs(a.g - e.g) + std::abs(a.b - e.b);
            ++n;
        }
    }
    return n ? sum / (3.0 * double(n)) : 0;
}

namespace {

// The exact nearest-texel picture of item 0 (an unlit textured quad) at pixel centers.
Truth nearest_truth(const Panel& p) {
    Truth t{raster::Image(p.w, p.h, p.background), std::vector<char>(std::size_t(p.w) * std::size_t(p.h), 0)};
    const TextureSpec* spec = first_texture(p);
    if (!spec) return t;
    const LevelData level = level_of(*spec);
    const auto tris = world_triangles(p, true);
    const Basis b = basis(p.camera);
    for (int y = 0; y < p.h; ++y) {
        for (int x = 0; x < p.w; ++x) {
            const Hit h = cast(tris, p.camera.eye, ray(p, b, x + 0.5, y + 0.5), 0);
            if (!h.tri) continue;
            t.img.set(x, y, to_color(t_nearest(level, uv_at(h), spec->wrap_u, spec->wrap_v)));
            t.valid[std::size_t(y) * std::size_t(p.w) + std::size_t(x)] = 1;
        }
    }
    return t;
}

double share_off(const raster::Image& img, const Panel& p, const Truth& t) {
    long long n = 0, off = 0;
    for (int y = 0; y < p.h; ++y) {
        for (int x = 0; x < p.w; ++x) {
            if (!t.valid[std::size_t(y) * std::size_t(p.w) + std::size_t(x)]) continue;
            ++n;
            off += max_diff(img.at(p.x0 + x, p.y0 + y), t.img.at(x, y)) > 3;
        }
    }
    return n ? 100.0 * double(off) / double(n) : 0;
}

// The pixels that differ from the expected image beyond the tolerance (strictly), split by what a
// ray through the pixel center meets first: a lit item with a normal map and no texture
// (`untextured`), or one with both (`textured`, of `textured_pixels` such pixels in all); and on
// the untextured ones, how many pairs of neighbouring pixels (on the same item) differ by more
// than 3 levels, in the expected image (`bumpy_expected`) and in yours (`bumpy_mine`). A
// normal map read without uv is read at (0, 0) all over: its bumps vanish, and those items come
// out as smooth as without a map, where the expected image shows bumps.
struct NormalUvDiff {
    long long strict = 0, untextured = 0, textured = 0, textured_pixels = 0, bumpy_expected = 0, bumpy_mine = 0;
};
NormalUvDiff normal_map_uv_diff(const Scene& s, const raster::Image& mine, const raster::Image& expected,
                                const cp::Tolerance& tol) {
    NormalUvDiff out;
    if (mine.width() != expected.width() || mine.height() != expected.height()) return out;
    for (const Panel& p : s.panels) {
        if (p.items.empty()) continue;
        const auto tris = world_triangles(p, false);
        const Basis b = basis(p.camera);
        // Per pixel: the untextured normal-mapped item it shows, or -1.
        std::vector<int> item(std::size_t(p.w) * std::size_t(p.h), -1);
        for (int y = 0; y < p.h; ++y) {
            for (int x = 0; x < p.w; ++x) {
                const int gx = p.x0 + x, gy = p.y0 + y;
                if (!expected.in_bounds(gx, gy)) continue;
                const bool strict = !tol.lenient.get(gx, gy) && max_diff(mine.at(gx, gy), expected.at(gx, gy)) > tol.strict_channel_diff;
                out.strict += strict;
                const Hit h = cast(tris, p.camera.eye, ray(p, b, x + 0.5, y + 0.5), 0);
                if (!h.tri) continue;
                const MaterialSpec& m = p.items[std::size_t(h.tri->item)].material;
                if (!m.lit || m.normal_map < 0 || std::size_t(m.normal_map) >= p.textures.size()) continue;
                if (m.texture >= 0 && std::size_t(m.texture) < p.textures.size()) {
                    ++out.textured_pixels;
                    out.textured += strict;
                } else {
                    out.untextured += strict;
                    item[std::size_t(y) * std::size_t(p.w) + std::size_t(x)] = h.tri->item;
                }
            }
        }
        for (int y = 0; y < p.h; ++y) {
            for (int x = 0; x < p.w; ++x) {
                const int it = item[std::size_t(y) * std::size_t(p.w) + std::size_t(x)];
                if (it < 0) continue;
                for (const auto& [nx, ny] : {std::pair{x + 1, y}, std::pair{x, y + 1}}) {
                    if (nx >= p.w || ny >= p.h || item[std::size_t(ny) * std::size_t(p.w) + std::size_t(nx)] != it) continue;
                    const int gx = p.x0 + x, gy = p.y0 + y, hx = p.x0 + nx, hy = p.y0 + ny;
                    out.bumpy_expected += max_diff(expected.at(gx, gy), expected.at(hx, hy)) > 3;
                    out.bumpy_mine += max_diff(mine.at(gx, gy), mine.at(hx, hy)) > 3;
                }
            }
        }
    }
    return out;
}

// The pixels that differ from the expected image beyond the tolerance (strictly), and how many of
// them a ray finds on an item whose normal map does not repeat, at uv outside [0, 1] on an axis
// that does not repeat: there the map's own wrap modes decide the texel. `modes` names the wrap
// modes of the first such map ("u clamp to edge, v mirrored repeat"), `where` its panel;
// `only_u` and `only_v` count those of them where only that axis is outside (the other inside
// [0, 1] or repeating), and `mode_u`, `mode_v` name that map's modes alone.
struct NormalWrapDiff {
    long long strict = 0, outside = 0, only_u = 0, only_v = 0;
    std::string modes, where, mode_u, mode_v;
};
NormalWrapDiff normal_map_wrap_diff(const Scene& s, const raster::Image& mine, const raster::Image& expected,
                                    const cp::Tolerance& tol) {
    NormalWrapDiff out;
    if (mine.width() != expected.width() || mine.height() != expected.height()) return out;
    auto map_of = [](const Panel& p, int item) -> const TextureSpec* {
        if (item < 0 || std::size_t(item) >= p.items.size()) return nullptr;
        const MaterialSpec& m = p.items[std::size_t(item)].material;
        if (!m.lit || m.normal_map < 0 || std::size_t(m.normal_map) >= p.textures.size()) return nullptr;
        const TextureSpec& t = p.textures[std::size_t(m.normal_map)];
        return t.wrap_u == Wrap::kRepeat && t.wrap_v == Wrap::kRepeat ? nullptr : &t;
    };
    for (std::size_t pi = 0; pi < s.panels.size(); ++pi) {
        const Panel& p = s.panels[pi];
        bool any = false;
        for (std::size_t i = 0; i < p.items.size(); ++i) any |= map_of(p, int(i)) != nullptr;
        const auto tris = any ? world_triangles(p, false) : std::vector<WorldTri>{};
        const Basis b = basis(p.camera);
        for (int y = 0; y < p.h; ++y) {
            for (int x = 0; x < p.w; ++x) {
                const int gx = p.x0 + x, gy = p.y0 + y;
                if (!expected.in_bounds(gx, gy) || tol.lenient.get(gx, gy) ||
                    max_diff(mine.at(gx, gy), expected.at(gx, gy)) <= tol.strict_channel_diff) {
                    continue;
                }
                ++out.strict;
                if (!any) continue;
                const Hit h = cast(tris, p.camera.eye, ray(p, b, x + 0.5, y + 0.5), 0);
                const TextureSpec* map = h.tri ? map_of(p, h.tri->item) : nullptr;
                if (!map) continue;
                const Vec2 uv = uv_at(h);
                const bool off_u = map->wrap_u != Wrap::kRepeat && (uv.x < 0 || uv.x > 1);
                const bool off_v = map->wrap_v != Wrap::kRepeat && (uv.y < 0 || uv.y > 1);
                if (off_u || off_v) {
                    ++out.outside;
                    out.only_u += off_u && !off_v;
                    out.only_v += off_v && !off_u;
                    if (out.modes.empty()) {
                        out.mode_u = wrap_name(map->wrap_u);
                        out.mode_v = wrap_name(map->wrap_v);
                        out.modes = "u " + out.mode_u + ", v " + out.mode_v;
                        out.where = s.panels.size() > 1 ? " of panel " + std::to_string(pi + 1) : "";
                    }
                }
            }
        }
    }
    return out;
}

// The known mistakes of the ambient term leave a lit surface of one plain color off by the same
// amount everywhere: base times lighting.ambient, times (lights - 1) when it is added once per
// light, times (intensity - 1) when a light's intensity scales it, times -1 when it is left out.
// For each panel whose lit items share one untextured color: the first of those offsets that
// nearly all of the panel's pixels beyond the tolerance show (within rounding, or clamped at 0 or
// 255 where the offset carries past them), with the panel and a phrase saying which mistake.
struct AmbientOffset {
    long long matching = 0, strict = 0;
    std::string where, mistake;
    Vec3 offset{};
};
AmbientOffset ambient_offset_diff(const Scene& s, const raster::Image& mine, const raster::Image& expected,
                                  const cp::Tolerance& tol) {
    AmbientOffset out;
    if (mine.width() != expected.width() || mine.height() != expected.height()) return out;
    for (std::size_t pi = 0; pi < s.panels.size(); ++pi) {
        const Panel& p = s.panels[pi];
        std::optional<Color> base;
        bool plain_lit = !p.lights.empty();
        for (const Item& it : p.items) {
            if (!it.material.lit) continue;
            const Color c = it.material.color;
            plain_lit &= it.material.texture < 0 && (!base || (base->r == c.r && base->g == c.g && base->b == c.b));
            base = c;
        }
        if (!plain_lit || !base) continue;
        const Vec3 bv{double(base->r), double(base->g), double(base->b)}, ambient = mul(bv, p.ambient);
        std::vector<std::pair<Vec3, std::string>> offsets;
        if (p.lights.size() > 1) {
            offsets.push_back({ambient * double(p.lights.size() - 1),
                               "added once per LIGHT (" + std::to_string(p.lights.size()) + " lights here)"});
        }
        Vec3 all{};
        for (const LightSpec& l : p.lights) all = all + l.intensity;
        offsets.push_back({mul(ambient, p.lights[0].intensity) - ambient, "scaled by the light's intensity"});
        if (p.lights.size() > 1) offsets.push_back({mul(ambient, all) - ambient, "scaled by the lights' intensities"});
        offsets.push_back({ambient * -1.0, "left out (surfaces no light reaches are black)"});
        std::vector<long long> hits(offsets.size(), 0);
        long long strict = 0;
        for (int y = 0; y < p.h; ++y) {
            for (int x = 0; x < p.w; ++x) {
                const int gx = p.x0 + x, gy = p.y0 + y;
                if (!expected.in_bounds(gx, gy) || tol.lenient.get(gx, gy)) continue;
                const Color a = mine.at(gx, gy), e = expected.at(gx, gy);
                if (max_diff(a, e) <= tol.strict_channel_diff) continue;
                ++strict;
                for (std::size_t k = 0; k < offsets.size(); ++k) {
                    const Vec3 o = offsets[k].first;
                    const auto fits = [](int got, int want, double off) {
                        // An expected 255 (or 0) was clamped: the value under it may lie anywhere
                        // above (below), so the offset one may too.
                        if (want >= 255) return got >= std::min(255.0, 255 + off) - 2;
                        if (want <= 0) return got <= std::max(0.0, off) + 2;
                        const double target = want + off;
                        if (target >= 254) return got >= 253;  // clamped at white
                        if (target <= 1) return got <= 2;      // clamped at black
                        return std::abs(got - target) <= 2;
                    };
                    hits[k] += fits(a.r, e.r, o.x) && fits(a.g, e.g, o.y) && fits(a.b, e.b, o.z);
                }
            }
        }
        for (std::size_t k = 0; k < offsets.size(); ++k) {
            // The offset must be visible (over the tolerance in some channel) to tell it from noise.
            const Vec3 o = offsets[k].first;
            const double size = std::max({std::abs(o.x), std::abs(o.y), std::abs(o.z)});
            if (size <= tol.strict_channel_diff + 2 || hits[k] < 20 || 10 * hits[k] < 9 * strict) continue;
            out.matching = hits[k];
            out.strict = strict;
            out.offset = o;
            out.mistake = offsets[k].second;
            out.where = s.panels.size() > 1 ? " of panel " + std::to_string(pi + 1) : "";
            return out;
        }
    }
    return out;
}

}  // namespace

// Pixels in the wrong light state: per pixel center the nearest surface by ray casting, lit or
// not by a ray to the light; the pixel's color is classified by the nearer of the two colors
// the rules give there (lit, shadowed). Surfaces the light does not face, and pixels where the
// two colors are close, are left out.
LightState wrong_light_state(const raster::Image& img, const Panel& p) {
    const auto tris = world_triangles(p, false);
    const Basis b = basis(p.camera);
    const LightSpec* light = shadow_light(p);
    if (!light) return {};
    const Vec3 to_light = -unit_or_zero(light->direction);
    LightState state;
    for (int y = 0; y < p.h; ++y) {
        for (int x = 0; x < p.w; ++x) {
            const Hit h = cast(tris, p.camera.eye, ray(p, b, x + 0.5, y + 0.5), 0);
            if (!h.tri) continue;
            const Vec3 n = unit_or_zero(raster::cross(h.tri->b - h.tri->a, h.tri->c - h.tri->a));
            const double c = raster::dot(n, to_light);
            const Color base = p.items[std::size_t(h.tri->item)].material.color;
            const Vec3 bv{double(base.r), double(base.g), double(base.b)};
            const Color shadowed = to_color(mul(bv, p.ambient));  // ambient only
            if (c < -0.1 && p.lights.size() == 1) {
                // A light adds nothing here; lit as if from the opposite side is L = +direction.
                const Color opposite = to_color(mul(bv, p.ambient + light->intensity * -c));
                if (max_diff(opposite, shadowed) >= 20) {
                    const Color mine = img.at(p.x0 + x, p.y0 + y);
                    ++state.facing_away;
                    state.lit_from_behind += max_diff(mine, opposite) < max_diff(mine, shadowed);
                }
            }
            if (!(c > 0)) continue;
            const Color lit = to_color(mul(bv, p.ambient + light->intensity * c));
            if (max_diff(lit, shadowed) < 12) continue;
            const Vec3 hit = p.camera.eye + ray(p, b, x + 0.5, y + 0.5) * h.t;
            const bool in_shadow = cast(tris, hit + n * 1e-6, to_light, 1e-9).tri != nullptr;
            const Color mine = img.at(p.x0 + x, p.y0 + y);
            ++state.counted;
            const bool looks_lit = max_diff(mine, lit) < max_diff(mine, shadowed);
            if (looks_lit && in_shadow) ++state.missing;
            if (!looks_lit && !in_shadow) ++state.spurious;
            if (in_shadow && max_diff(shadowed, Color{0, 0, 0}) >= 8) {
                ++state.in_shadow;
                state.too_dark += max_diff(mine, Color{0, 0, 0}) < max_diff(mine, shadowed);
            }
        }
    }
    return state;
}

namespace {

// The exact spheres (every item a uv_sphere of radius size.x), lit with Blinn-Phong per pixel;
// the ambient term base times `ambient` (the panel's: the rule; others: known mistakes),
// L = to_light_sign * direction (-1: the rule; +1: the light's direction taken as L, a mistake).
raster::Image exact_spheres(const Panel& p, std::optional<Vec3> ambient = {}, double to_light_sign = -1) {
    raster::Image img(p.w, p.h, p.background);
    const Basis b = basis(p.camera);
    for (int y = 0; y < p.h; ++y) {
        for (int x = 0; x < p.w; ++x) {
            const Vec3 d = unit_or_zero(ray(p, b, x + 0.5, y + 0.5));
            double best = std::numeric_limits<double>::infinity();
            const Item* hit_item = nullptr;
            for (const Item& it : p.items) {
                const Vec3 oc = p.camera.eye - it.position;
                const double r = it.size.x, half_b = raster::dot(oc, d), cc = raster::dot(oc, oc) - r * r;
                const double disc = half_b * half_b - cc;
                if (disc < 0) continue;
                const double t = -half_b - std::sqrt(disc);
                if (t > 0 && t < best) {
                    best = t;
                    hit_item = &it;
                }
            }
            if (!hit_item) continue;
            const Vec3 hit = p.camera.eye + d * best;
            const Vec3 n = unit_or_zero(hit - hit_item->position);
            const Color base = hit_item->material.color;
            const Vec3 bv{double(base.r), double(base.g), double(base.b)};
            Vec3 sum = mul(bv, ambient.value_or(p.ambient));
            for (const LightSpec& l : p.lights) {
                PhongCase k{bv, hit_item->material.specular, hit_item->material.shininess, n, p.camera.eye - hit, l.direction * to_light_sign,
                            l.intensity};
                sum = sum + t_phong(k);
            }
            img.set(x, y, to_color(sum));
        }
    }
    return img;
}

double panel_error(const raster::Image& img, const Panel& p, const raster::Image& truth) {
    return cp::rect_error(img, p.x0, p.y0, p.w, p.h, truth);
}

double round2(double x) { return std::round(x * 100) / 100; }

// The theme of a picture and what its caller must do, when the functions it is drawn with pass
// their own checks: the concept tag and "TODO N: advice".
std::pair<std::string, std::string> picture_theme(const std::string& id) {
    static const std::map<std::string, std::pair<std::string, std::string>> themes = {
        {"m5.fill_triangle",
         {"rasterizer", "TODO 5: fill_triangle tests each fragment's key first, weighs uv with m4::perspective_weights, "
                        "computes lambda at the pixel center (x + 0.5, y + 0.5) for a mip filter only, and calls sample()"}},
        {"m5.magnify",
         {"filter", "TODO 5: fill_triangle passes the material's filter and, for a mip filter, lambda = "
                    "level_of_detail(uv_derivatives(...) at the pixel center (x + 0.5, y + 0.5), level 0's size) to "
                    "sample()"}},
        {"m5.receding_filters",
         {"filter", "TODO 5: fill_triangle passes the material's filter and, for a mip filter, lambda = "
                    "level_of_detail(uv_derivatives(screen positions, w, uv, x + 0.5, y + 0.5), level 0's size) to "
                    "sample(): the derivatives at the pixel CENTER (x + 0.5, y + 0.5), not its corner (x, y)"}},
        {"m5.tiny_textures",
         {"filter", "TODO 5: fill_triangle computes lambda at the pixel center (x + 0.5, y + 0.5) with level 0's size "
                    "and lets sample() clamp it"}},
        {"m5.grazing",
         {"filter", "TODO 5: fill_triangle computes lambda at the pixel center (x + 0.5, y + 0.5) with level 0's size "
                    "and lets sample() clamp it"}},
        {"m5.wrap_quad", {"wrap", "TODO 5: fill_triangle samples with the texture's own wrap modes (wrap_u, wrap_v)"}},
        {"m5.perspective_uv",
         {"perspective uv", "TODO 5: fill_triangle interpolates uv (left floor), and for a lit material the normal "
                            "(right floor) and the world position, with the perspective-correct weights "
                            "(m4::perspective_weights of the screen weights and w), not the screen weights"}},
        {"m5.huge_uv",
         {"perspective uv", "TODO 5: keep uv in double from the vertices through the interpolation to sample(): a float "
                            "cannot hold the fraction of 1e7"}},
        {"m5.specular_spheres",
         {"specular", "TODO 5: fill_triangle normalizes the interpolated normal, takes V = eye - world position, and adds "
                      "the ambient term once and blinn_phong for each light"}},
        {"m5.squashed_sphere",
         {"normals", "TODOs 5 and 9: draw_scene turns each vertex normal with m4::normal_matrix(model) and normalizes "
                     "it BEFORE it is interpolated (under a non-uniform scale the turned normals differ in length); "
                     "fill_triangle interpolates it with the perspective-correct weights and normalizes it once more"}},
        {"m5.normal_map",
         {"normal map", "TODOs 5 and 9: draw_scene computes each mesh triangle's tangent_frame from its WORLD positions "
                        "and uv; fill_triangle perturbs the normalized normal with the normal map's bilinear level-0 "
                        "texel (sample_bilinear, whatever the material's filter), read with the normal map's own wrap "
                        "modes (wrap_u, wrap_v), and tests whether a light arrives (c = dot(N, L) > 0) with that perturbed normal"}},
        {"m5.degenerate_uv",
         {"normal map", "TODOs 5 and 9: a triangle whose tangent frame is not valid keeps its normal"}},
        {"m5.shadow_box",
         {"shadow", "TODOs 5 and 9: draw_scene's depth pass draws every casting object through m4::draw_mesh into a "
                    "resolution^2 float-Z frame with light_view_projection, and the map keeps that matrix for the "
                    "lookup; fill_triangle multiplies each light's term by shadow_factor at the world position "
                    "interpolated with the perspective-correct weights"}},
        {"m5.two_suns",
         {"shadow", "TODOs 5 and 9: draw_scene makes one shadow map per light that casts shadows (none for the "
                    "others), drawing only the objects that cast shadows into each, and fill_triangle looks each "
                    "light up in that light's own map"}},
        {"m5.shadow_acne",
         {"shadow", "TODOs 5 and 9: fill_triangle passes the normalized normal and the world position to "
                    "shadow_factor, which applies the settings' biases; draw_scene's depth pass uses "
                    "light_view_projection"}},
        {"m5.pcf", {"pcf", "TODOs 5 and 9: fill_triangle passes the settings (pcf on or off) to shadow_factor"}},
        {"m5.light_behind",
         {"light behind", "TODOs 5 and 9: where dot(N, L) <= 0 a light adds nothing (fill_triangle: no blinn_phong, "
                          "no shadow lookup); draw_scene's depth pass draws both faces (no culling), so the floor, seen "
                          "from below, still shadows the undersides the light faces"}},
        {"m5.needs", {"needs", "TODO 9: run only the passes the scene needs, as Stats says"}},
        {"m5.extreme_input",
         {"bad input", "TODO 9: skip a triangle with an index out of range or a non-finite clip coordinate; clip the "
                       "rest with m4::clip_triangle; NaN uv samples black"}},
        {"m5.showcase", {"pipeline", "TODO 9: follow draw_scene's steps in textures_shadows.h"}},
    };
    const auto it = themes.find(id);
    return it == themes.end() ? std::pair<std::string, std::string>{"pipeline", "TODO 9: follow draw_scene's steps"} : it->second;
}

// The exact ties of m5.fill_triangle: two ready-made triangles in a row with the same positions
// and w (the same keys) in two plain colors. At pixels well inside them where the reference shows
// the brighter copy, yours showing the other names the tie rule, and which copy it kept.
void judge_depth_ties(Ctx& c, const raster::Image& mine, const cp::Artifacts& ref, const Panel& panel) {
    const auto ref_it = ref.images.find("main");
    if (ref_it == ref.images.end()) return;
    for (std::size_t k = 0; k + 1 < panel.screen_tris.size(); ++k) {
        const ScreenTri &a = panel.screen_tris[k], &b = panel.screen_tris[k + 1];
        if (a.screen != b.screen || a.w != b.w || a.material.texture >= 0 || b.material.texture >= 0 ||
            max_diff(a.material.color, b.material.color) <= 10) {
            continue;
        }
        const double area = (a.screen[1].x - a.screen[0].x) * (a.screen[2].y - a.screen[0].y) -
                            (a.screen[1].y - a.screen[0].y) * (a.screen[2].x - a.screen[0].x);
        if (area == 0) continue;
        long long inside = 0, other = 0;
        bool last_kept = false;
        for (int y = 0; y < panel.h; ++y) {
            for (int x = 0; x < panel.w; ++x) {
                const double px = x + 0.5, py = y + 0.5;
                bool well_inside = true;
                for (int i = 0; i < 3; ++i) {
                    const Vec3 p = a.screen[std::size_t((i + 1) % 3)], q = a.screen[std::size_t((i + 2) % 3)];
                    well_inside &= ((p.x - px) * (q.y - py) - (p.y - py) * (q.x - px)) / area >= 0.05;
                }
                if (!well_inside) continue;
                const Color want = ref_it->second.at(panel.x0 + x, panel.y0 + y);
                const bool a_wins = max_diff(want, a.material.color) <= 3, b_wins = max_diff(want, b.material.color) <= 3;
                if (a_wins == b_wins) continue;
                ++inside;
                const Color loser = a_wins ? b.material.color : a.material.color;
                if (max_diff(mine.at(panel.x0 + x, panel.y0 + y), loser) <= 3) {
                    ++other;
                    last_kept = a_wins;  // the loser is the copy drawn last
                }
            }
        }
        if (other < 5 || 2 * other < inside) continue;
        c.add("rasterizer", "TODO 5: triangles " + std::to_string(k + 1) + " and " + std::to_string(k + 2) +
                                " are the same triangle drawn twice (the same keys: an exact tie), in " +
                                str(a.material.color) + " and then " + str(b.material.color) + "; at " +
                                std::to_string(other) + " of " + std::to_string(inside) +
                                " pixels inside them yours kept the copy drawn " + (last_kept ? "LAST" : "FIRST") +
                                ", the darker one: a fragment whose key equals the stored one passes the pre-test, and "
                                "m4::depth_passes then keeps the BRIGHTER color (larger red, then green, then blue), "
                                "whichever is drawn last, so the picture does not depend on the drawing order");
        ++k;
    }
}

// The ready-made triangles of m5.fill_triangle with a mip filter: at pixels well inside one where
// lambda taken at the pixel's corner (x, y) gives another color than at its center (x + 0.5,
// y + 0.5) and the reference shows the center's, more of yours matching the corner's names the
// mistake. The derivatives come from the corners snapped to 1/16 pixel, as fill_triangle's do.
void judge_lod_center(Ctx& c, const raster::Image& mine, const cp::Artifacts& ref, const Panel& panel) {
    const auto ref_it = ref.images.find("main");
    if (ref_it == ref.images.end()) return;
    // Two mistakes, each voted on its own: lambda at the corner, and lambda from derivatives that
    // leave out w (those of the screen-space uv: with every w_i = 1).
    cp::PixelVote corner, without_w;
    for (const ScreenTri& t : panel.screen_tris) {
        const MaterialSpec& m = t.material;
        if (m.texture < 0 || std::size_t(m.texture) >= panel.textures.size() ||
            (m.filter != Filter::kTrilinear && m.filter != Filter::kNearestMip)) {
            continue;
        }
        const TextureSpec& spec = panel.textures[std::size_t(m.texture)];
        const std::vector<LevelData> pyr = t_pyramid(level_of(spec));
        LodCase k{t.screen, t.w, t.uv, 0, 0, pyr[0].width, pyr[0].height};
        for (Vec3& v : k.screen) v = {std::round(v.x * 16) / 16, std::round(v.y * 16) / 16, v.z};
        const auto& s = k.screen;
        const double area = (s[1].x - s[0].x) * (s[2].y - s[0].y) - (s[1].y - s[0].y) * (s[2].x - s[0].x);
        if (area == 0) continue;
        for (int y = 0; y < panel.h; ++y) {
            for (int x = 0; x < panel.w; ++x) {
                const double px = x + 0.5, py = y + 0.5;
                double l[3], q[3], sum = 0;
                for (int i = 0; i < 3; ++i) {
                    const Vec3 a = s[std::size_t((i + 1) % 3)], b = s[std::size_t((i + 2) % 3)];
                    l[i] = ((a.x - px) * (b.y - py) - (a.y - py) * (b.x - px)) / area;
                }
                if (l[0] < 0.05 || l[1] < 0.05 || l[2] < 0.05) continue;
                for (int i = 0; i < 3; ++i) sum += q[i] = l[i] / k.w[std::size_t(i)];
                Vec2 uv{};
                for (int i = 0; i < 3; ++i) uv = uv + k.uv[std::size_t(i)] * (q[i] / sum);
                auto color_with_lambda_at = [&](double lx, double ly, bool perspective) {
                    k.x = lx;
                    k.y = ly;
                    const Derivs d = t_derivatives(k, perspective);
                    const double lambda = t_lambda(d.du_dx, d.dv_dx, d.du_dy, d.dv_dy, k.width, k.height);
                    return to_color(t_sample(pyr, uv, lambda, m.filter, spec.wrap_u, spec.wrap_v));
                };
                const Color at_center = color_with_lambda_at(px, py, true);
                if (max_diff(ref_it->second.at(panel.x0 + x, panel.y0 + y), at_center) > 3) continue;
                const Color got = mine.at(panel.x0 + x, panel.y0 + y);
                corner.cast(got, at_center, color_with_lambda_at(x, y, true));
                without_w.cast(got, at_center, color_with_lambda_at(px, py, false));
            }
        }
    }
    if (without_w.names_mistake() && without_w.mistake_like() >= corner.mistake_like()) {
        c.add("rasterizer", "TODO 5: " + without_w.tally() +
                                " of the triangles with a mip filter where it changes the level, your colors are "
                                "those of lambda from the derivatives of the SCREEN-SPACE uv (every w_i taken as 1): "
                                "pass uv_derivatives the clip-space w of the three vertices, so lambda follows the "
                                "perspective-correct uv the pixel is sampled at");
    } else if (corner.names_mistake()) {
        c.add("rasterizer", "TODO 5: " + corner.tally() +
                                " of the triangles with a mip filter where the level changes between a pixel's "
                                "corner and its center, your colors are those of lambda taken at the pixel's CORNER "
                                "(x, y): take uv_derivatives at its center (x + 0.5, y + 0.5), where the pixel is "
                                "sampled");
    }
}

// The ready-made triangle 0 (kNearest) of m5.fill_triangle: at pixels well inside it where the
// reference shows it, the texel of the perspective-correct uv and of the screen-space uv; more
// pixels matching the second name the mistake.
void judge_screen_uv(Ctx& c, const raster::Image& mine, const cp::Artifacts& ref, const Panel& panel) {
    const auto ref_it = ref.images.find("main");
    if (ref_it == ref.images.end() || panel.screen_tris.empty()) return;
    const ScreenTri& t = panel.screen_tris[0];
    const TextureSpec* spec = t.material.texture >= 0 && std::size_t(t.material.texture) < panel.textures.size()
                                  ? &panel.textures[std::size_t(t.material.texture)]
                                  : nullptr;
    if (!spec) return;
    const LevelData level = level_of(*spec);
    const double area = (t.screen[1].x - t.screen[0].x) * (t.screen[2].y - t.screen[0].y) -
                        (t.screen[1].y - t.screen[0].y) * (t.screen[2].x - t.screen[0].x);
    if (area == 0) return;
    // Both coordinates by the screen weights, or only one of them (the other perspective-correct).
    cp::PixelVote screen_space, u_only, v_only;
    for (int y = 0; y < panel.h; ++y) {
        for (int x = 0; x < panel.w; ++x) {
            const double px = x + 0.5, py = y + 0.5;
            double l[3];
            for (int i = 0; i < 3; ++i) {
                const Vec3 a = t.screen[std::size_t((i + 1) % 3)], b = t.screen[std::size_t((i + 2) % 3)];
                l[i] = ((a.x - px) * (b.y - py) - (a.y - py) * (b.x - px)) / area;
            }
            if (l[0] < 0.05 || l[1] < 0.05 || l[2] < 0.05) continue;
            double q[3], sum = 0;
            for (int i = 0; i < 3; ++i) sum += q[i] = l[i] / t.w[std::size_t(i)];
            Vec2 persp{}, flat{};
            for (int i = 0; i < 3; ++i) {
                persp = persp + t.uv[std::size_t(i)] * (q[i] / sum);
                flat = flat + t.uv[std::size_t(i)] * l[i];
            }
            const Color pc = to_color(t_nearest(level, persp, spec->wrap_u, spec->wrap_v));
            const Color sc = to_color(t_nearest(level, flat, spec->wrap_u, spec->wrap_v));
            if (max_diff(ref_it->second.at(panel.x0 + x, panel.y0 + y), pc) > 3) continue;
            const Color got = mine.at(panel.x0 + x, panel.y0 + y);
            screen_space.cast(got, pc, sc);
            u_only.cast(got, pc, to_color(t_nearest(level, {flat.x, persp.y}, spec->wrap_u, spec->wrap_v)));
            v_only.cast(got, pc, to_color(t_nearest(level, {persp.x, flat.y}, spec->wrap_u, spec->wrap_v)));
        }
    }
    const cp::PixelVote* best = nullptr;
    for (const cp::PixelVote* v : {&screen_space, &u_only, &v_only}) {
        if (v->names_mistake() && (!best || v->mistake_like() > best->mistake_like())) best = v;
    }
    if (best == &screen_space) {
        c.add("perspective uv", "TODO 5: " + screen_space.tally() +
                                    " inside the first triangle your texels are those of the SCREEN-space uv: weigh "
                                    "each vertex's uv by l_i / w_i and normalize (m4::perspective_weights)");
    } else if (best) {
        const bool u = best == &u_only;
        c.add("perspective uv", "TODO 5: " + best->tally() + " inside the first triangle your texels are those of a uv " +
                                    "whose " + (u ? "u" : "v") + " is interpolated with the SCREEN weights l_i and whose " +
                                    (u ? "v" : "u") + " is perspective-correct: both coordinates take the same " +
                                    "weights, m4::perspective_weights of l_i and w_i");
    }
    judge_depth_ties(c, mine, ref, panel);
    judge_lod_center(c, mine, ref, panel);
}

// fill_triangle (TODO 5) on m5.fill_triangle's own triangles, drawn by the render half of a
// scene that calls it through draw_scene (render.cpp, kFillKey): a finding when its picture
// differs from the reference's beyond the tolerance, naming screen-space uv when it sees them.
std::optional<cp::Finding> fill_triangle_fails(const cp::Artifacts& art, const cp::Artifacts& ref) {
    const std::string image = kFillKey.substr(0, kFillKey.size() - 1);
    const auto mine_it = art.images.find(image), ref_it = ref.images.find(image);
    if (ref_it == ref.images.end()) return std::nullopt;
    if (mine_it != art.images.end() && mine_it->second.width() == ref_it->second.width() &&
        mine_it->second.height() == ref_it->second.height() &&
        !cp::exceeds_tolerance(mine_it->second, ref_it->second, tolerance_for(scene(kFillScene), ref_it->second))) {
        return std::nullopt;
    }
    if (mine_it != art.images.end() && mine_it->second.width() == ref_it->second.width() &&
        mine_it->second.height() == ref_it->second.height()) {
        const Scene& fill = scene(kFillScene);
        cp::Artifacts ref_fill;
        ref_fill.images["main"] = ref_it->second;
        const Values none;
        cp::Judgement scratch;
        Ctx sub{fill, none, none, scratch};
        if (!fill.panels.empty()) judge_screen_uv(sub, mine_it->second, ref_fill, fill.panels[0]);
        if (!scratch.findings.empty()) return scratch.findings.front();
    }
    return cp::Finding{"rasterizer",
                       "fill_triangle draws m5.fill_triangle's two textured triangles differently from the reference "
                       "(beyond the tolerance)",
                       "", "TODO 5"};
}

void judge_filter_chart(Ctx& c, const raster::Image& mine, const cp::Artifacts& ref) {
    const Scene& s = c.s;
    const auto ref_it = ref.images.find("main");
    raster::PlotSpec chart;
    chart.title = "error against run time, per filter";
    chart.x_label = "milliseconds per panel, log scale";
    chart.y_label = "mean error vs 16x bilinear (levels)";
    chart.log_x = true;
    raster::PlotSeries yours{"yours", {210, 60, 50}, {}, {}}, theirs{"reference", {120, 150, 220}, {}, {}};
    for (std::size_t p = 0; p < s.panels.size(); ++p) {
        const Panel& panel = s.panels[p];
        if (panel.items.empty()) continue;
        const Truth truth = bilinear_truth(panel);
        const double err = truth_error(mine, panel, truth);
        const double ref_err = ref_it == ref.images.end() ? err : truth_error(ref_it->second, panel, truth);
        const std::string key = "panel" + std::to_string(p) + ".seconds";
        const double ms = 1e3 * get(c.mine, key), ref_ms = 1e3 * get(c.ref, key);
        const std::string name = filter_name(panel.items[0].material.filter);
        c.j.measures["error of " + name + " vs 16x supersampled bilinear, levels (reference " + num(round2(ref_err)) + ")"] = round2(err);
        c.j.measures["time of the " + name + " panel, ms (reference " + num(round2(ref_ms)) + ")"] = round2(ms);
        yours.points.push_back({ms, err});
        theirs.points.push_back({ref_ms, ref_err});
        yours.labels.push_back(name.substr(1));
        theirs.labels.push_back("");
        // Within 8% of the reference's error, and never more than half a level beyond it.
        if (err > ref_err * 1.08 + 0.5) {
            c.add("filter", "TODOs 4 and 5: the " + name + " panel is " + plural(round2(err), "level") +
                                " from the 16x supersampled bilinear truth on average, the reference's " +
                                num(round2(ref_err)) + " (allowed: " + num(round2(ref_err * 1.08 + 0.5)) +
                                "): the level of detail (lambda at the pixel center (x + 0.5, y + 0.5), in texel units of level 0) or the "
                                "filter's use of it is off");
        }
    }
    chart.series = {theirs, yours};
    c.j.pictures["error_vs_time"] = raster::plot(chart);
}

struct StatInfo {
    const char* name;
    const char* topic;  // when the reference's count is not 0
    const char* todo;
    const char* one;   // what is counted, told of a count of 1
    const char* what;  // of any other count
    bool exact;
};
constexpr StatInfo kStats[] = {
    {"shadow_passes", "shadow", "TODO 9", "shadow pass", "shadow passes", true},
    {"shadow_texels", "shadow", "TODO 9", "shadow-map texel allocated", "shadow-map texels allocated", true},
    {"triangles_drawn", "pipeline", "TODO 9", "fan triangle drawn", "fan triangles drawn", true},
    {"fragments", "rasterizer", "TODO 5", "fragment (covered pixel center)", "fragments (covered pixel centers)", false},
    {"shaded", "rasterizer", "TODO 5", "fragment shaded", "fragments shaded", false},
    {"texture_samples", "filter", "TODO 5", "texture sample", "texture samples", false},
    {"lod_computed", "level of detail", "TODO 5", "level-of-detail computation", "level-of-detail computations", false},
    {"mipmap_builds", "mipmap builds", "TODO 4", "pyramid built", "pyramids built", true},
    {"normal_map_samples", "normal map", "TODO 5", "normal-map sample", "normal-map samples", false},
    {"tangent_frames", "normal map", "TODO 9", "tangent frame", "tangent frames", true},
    {"specular_terms", "specular", "TODO 5", "specular term", "specular terms", false},
    {"shadow_lookups", "shadow", "TODO 5", "shadow lookup", "shadow lookups", false},
};

// The textures of a panel whose pyramid the header leaves free (see "Only what a scene needs"):
// those a mip filter may meet with lambda > 0 while reading only level 0, a 1x1 texture or one
// sampled with kNearestMip only (all its lambdas may lie in (0, 0.5)). The reference builds
// them at lambda > 0; code that builds only for a level above 0 builds fewer, never more.
// (m5.filters checks each sample() call's count exactly, within the same freedom.)
int free_pyramids(const Panel& panel) {
    int count = 0;
    for (std::size_t t = 0; t < panel.textures.size(); ++t) {
        bool mip = false, trilinear = false;
        for (const Item& it : panel.items) {
            if (it.material.texture != int(t)) continue;
            mip |= it.material.filter == Filter::kNearestMip || it.material.filter == Filter::kTrilinear;
            trilinear |= it.material.filter == Filter::kTrilinear;
        }
        const bool one_texel = panel.textures[t].width == 1 && panel.textures[t].height == 1;
        if (mip && (one_texel || !trilinear)) ++count;
    }
    return count;
}

// The textures of a panel that a mip filter samples on a mesh with a NaN or infinite uv: there
// lambda is NaN or infinite depending on how rho is written, so whether the pyramid is built
// is free both ways (the header's "Only what a scene needs", (c)).
int unsettled_pyramids(const Panel& panel) {
    int count = 0;
    for (std::size_t t = 0; t < panel.textures.size(); ++t) {
        bool unsettled = false;
        for (const Item& it : panel.items) {
            if (it.material.texture != int(t)) continue;
            if (it.material.filter != Filter::kNearestMip && it.material.filter != Filter::kTrilinear) continue;
            for (const Vec2& uv : it.mesh.uvs) unsettled |= !std::isfinite(uv.x) || !std::isfinite(uv.y);
        }
        count += unsettled ? 1 : 0;
    }
    return count;
}

// The pyramid counts a panel may show, given the reference's b: fewer by the free ones, and
// fewer or more by the unsettled ones (a range of one count where the header leaves nothing free).
std::pair<double, double> allowed_pyramid_builds(const Panel& panel, double b) {
    const int free_builds = free_pyramids(panel), unsettled_builds = unsettled_pyramids(panel);
    return {std::max(0.0, b - free_builds - unsettled_builds), b + unsettled_builds};
}

// Whether a lit, normal-mapped item of the panel has a triangle whose uv make no tangent frame
// (its object-space positions stand in for the world ones: the model matrix keeps a frame).
bool has_frameless_normal_mapped_triangle(const Panel& panel) {
    for (const Item& it : panel.items) {
        if (it.material.normal_map < 0 || !it.material.lit) continue;
        const Mesh& m = it.mesh;
        for (const auto& tri : m.triangles) {
            FrameCase f;
            bool in_range = true;
            for (std::size_t k = 0; k < 3; ++k) {
                const int i = tri[k];
                in_range = in_range && i >= 0 && std::size_t(i) < m.positions.size() && std::size_t(i) < m.uvs.size();
                if (!in_range) break;
                f.p[k] = m.positions[std::size_t(i)];
                f.uv[k] = m.uvs[std::size_t(i)];
            }
            if (in_range && !t_frame(f).valid) return true;
        }
    }
    return false;
}

void judge_picture(Ctx& c, const cp::Artifacts& art, const cp::Artifacts& ref, const raster::Image& expected) {
    const Scene& s = c.s;
    const auto main_it = art.images.find("main");
    const raster::Image* mine = main_it == art.images.end() ? nullptr : &main_it->second;
    const bool sized = mine && mine->width() == s.width && mine->height() == s.height;
    const auto [theme_topic, theme_advice] = picture_theme(s.id);
    const std::size_t first_finding = c.j.findings.size();
    const auto ref_main = ref.images.find("main");
    // c.j.tolerance is judge()'s tolerance_for(s, expected), computed once (it ray-casts every pixel).
    const bool differs = sized && !expected.empty() && cp::exceeds_tolerance(*mine, expected, c.j.tolerance);
    // judge() checked every function this picture is drawn with, and they pass. When the picture
    // differs and fill_triangle (TODO 5) draws m5.fill_triangle's own triangles wrong too, that is
    // the caller to fix, whatever the scene is about: every other finding would follow from it.
    const bool pipeline = std::any_of(s.panels.begin(), s.panels.end(), [](const Panel& p) { return p.screen_tris.empty(); });
    if (differs && pipeline) {
        if (const std::optional<cp::Finding> fill = fill_triangle_fails(art, ref)) {
            c.j.findings.push_back(cp::fix_first(*fill, kFillScene, "this picture is drawn with it",
                                                 "this picture cannot come out right before that checkpoint passes"));
            return;
        }
    }

    std::map<std::string, std::pair<double, double>> totals;
    bool counts_off = false;  // some count differs from the reference's
    for (std::size_t p = 0; p < s.panels.size(); ++p) {
        const Panel& panel = s.panels[p];
        const std::string key = "panel" + std::to_string(p);
        const std::string where = s.panels.size() > 1 ? " (panel " + std::to_string(p + 1) + ")" : "";
        if (get(c.mine, key + ".resized") == 1) {
            c.add("pipeline", "TODO 9: the frame's image was replaced by one of another size" + where);
        }
        const bool free_reads = has_frameless_normal_mapped_triangle(panel);
        // The per-fragment counts follow the fragments shaded: when those are off, only they are told.
        bool fragments_off = false;
        for (const StatInfo& st : kStats) {
            const std::string k = key + ".stats." + st.name;
            const double a = get(c.mine, k), b = get(c.ref, k);
            totals[st.name].first += a;
            totals[st.name].second += b;
            const std::string name = st.name;
            const bool per_fragment = !st.exact && name != "fragments" && name != "shaded";
            bool ok;
            if (name == "mipmap_builds") {
                const auto [low, high] = allowed_pyramid_builds(panel, b);
                ok = a >= low && a <= high;
            } else if (b == 0 || a == 0) {
                ok = a == b;
            } else if (st.exact) {
                ok = a == b;
            } else {
                ok = std::abs(a - b) <= 0.02 * b + 4;  // per-pixel counts: rounding at edges
            }
            // The header leaves free whether the normal map is read where the triangle has no
            // tangent frame (the texel is not used there; the reference reads it): fewer reads
            // than the reference's are fine in a panel that has such triangles.
            if (!ok && name == "normal_map_samples" && free_reads && a > 0 && a < b) ok = true;
            // Free too (the header's (d)): whether a 1x1 texture's fragments compute lambda. In a
            // panel where every mip-filtered texture is 1x1 any count up to the reference's
            // passes; beside bigger ones, any count short of it but not 0.
            if (!ok && name == "lod_computed" && a < b) {
                bool one_texel = false, bigger = false;
                for (const Item& it : panel.items) {
                    const MaterialSpec& m = it.material;
                    if ((m.filter != Filter::kNearestMip && m.filter != Filter::kTrilinear) || m.texture < 0 ||
                        std::size_t(m.texture) >= panel.textures.size()) {
                        continue;
                    }
                    const TextureSpec& t = panel.textures[std::size_t(m.texture)];
                    (t.width == 1 && t.height == 1 ? one_texel : bigger) = true;
                }
                ok = one_texel && (!bigger || a > 0);
            }
            // Who counts a fan triangle is free (the header): draw_scene as it passes one, or
            // fill_triangle as it is entered. A panel of fill_triangle calls alone shows 0 or one
            // per call.
            if (!ok && name == "triangles_drawn" && !panel.screen_tris.empty() && a == double(panel.screen_tris.size())) ok = true;
            if (ok) continue;
            counts_off = true;
            if (name == "fragments" || name == "shaded") fragments_off = true;
            if (per_fragment && fragments_off) continue;
            std::string why, topic = st.topic, todo = st.todo;
            const bool work = name != "fragments" && name != "shaded" && name != "triangles_drawn";
            // The normal maps of the panel (lit items only read them).
            std::set<int> normal_maps;
            for (const Item& it : panel.items) {
                if (it.material.normal_map >= 0 && it.material.lit) normal_maps.insert(it.material.normal_map);
            }
            if (b == 0) {
                topic = "needs";
                why = " [needs]: this scene does not need that stage, so it must not run";
                if (name == "lod_computed") why += " (the level of detail is computed for mip filters only)";
                const bool unlit_mapped = std::any_of(panel.items.begin(), panel.items.end(), [](const Item& it) {
                    return !it.material.lit && it.material.normal_map >= 0;
                });
                if ((name == "tangent_frames" || name == "normal_map_samples") && unlit_mapped) {
                    why += " (an unlit material uses no normal, so its normal map needs neither a tangent frame nor a "
                           "read: only a LIT material with a normal map gets them)";
                }
            } else if (work && a > b) {
                topic = "needs";
                why = ": more than this scene needs";
                if (name == "lod_computed") why += " (the level of detail is computed for mip filters only)";
                if (name == "mipmap_builds") why += " (one pyramid per texture, built the first time a mip filter reads a level above 0; none for lambda <= 0)";

                if (name == "shadow_passes" || name == "shadow_texels") why += " (a depth pass only for a light that casts shadows)";
                if (name == "shadow_lookups" || name == "specular_terms") why += " (none where dot(N, L) <= 0)";
                if (name == "tangent_frames") {
                    why += " (one per mesh triangle of a normal-mapped material, made before clipping: the fan "
                           "triangles of a clipped triangle share it)";
                }
            } else if (name == "tangent_frames") {
                why = ": one per mesh triangle of a normal-mapped material, made before clipping, whether or not "
                      "clipping leaves anything of it";
            } else if (name == "shaded" && a > b) {
                why = ": a fragment whose key is greater than the stored key is dropped before anything else (not "
                      "shaded)";
            } else if (name == "mipmap_builds") {
                why = ": one pyramid per texture, built the first time a mip filter reads a level above 0";
            } else if (name == "specular_terms" || name == "shadow_lookups") {
                // Fewer than the reference's: where does a light arrive?
                why = std::string(name == "specular_terms"
                                      ? ": one per light on each shaded fragment of a material with a specular color"
                                      : ": one per shadow-casting light on each shaded fragment") +
                      ", where dot(N, L) > 0 with L = -normalize(direction), the way TOWARD the light (a light's "
                      "direction is the way its rays travel)";
                if (name == "shadow_lookups") {
                    why += "; and each such light must find its own map: state.shadow_maps[k] for light k, nullptr only "
                           "for a light that casts none";
                }
            } else if (name == "triangles_drawn") {
                why = ": one per fan triangle passed to fill_triangle, counted once (by draw_scene or inside fill_triangle, "
                      "not both)";
            } else if (name == "shadow_texels") {
                why = ": each shadow pass allocates resolution^2 keys";
            }
            // Up to one extra pyramid per normal map: the map read through sample() with a mip filter.
            if (name == "mipmap_builds" && a > b && a - b <= double(normal_maps.size())) {
                todo = "TODO 5";  // fill_triangle's call, not sample()
                why += "; a normal map is read with sample_bilinear on its level 0, never through sample(), so it never "
                       "gets a pyramid";
            }
            // The hint of a count is what makes that count, not the rule of the function it counts.
            std::string hint;
            if (name == "specular_terms" && a > b) {
                why += "; a material whose specular color is zero (0, 0, 0) has no specular term at all (the header's "
                       "Material: \"zero: no specular term is computed\"), so its fragments count none";
                hint = "fill_triangle computes (and counts) a specular term only for a material whose specular color is "
                       "not zero, and only where the light arrives, dot(N, L) > 0";
            } else if ((name == "specular_terms" || name == "shadow_lookups") && a < b) {
                hint = std::string(name == "shadow_lookups" ? "fill_triangle looks light k up in its own map, state.shadow_maps[k], "
                                                            : "fill_triangle adds a light's specular term ") +
                       "wherever dot(N, L) > 0; where the counts fall short, N or L is not the one the header asks for: N "
                       "the world normal (draw_scene: m4::normal_matrix, normalized), interpolated, normalized and "
                       "perturbed; L = -normalize(direction)";
            }
            c.add(topic, todo + ": " + plural(a, st.one, st.what) + where + ", expected " +
                             (st.exact || b == 0 ? num(b) : "about " + num(b)) + why);
            if (!hint.empty()) c.j.findings.back().hint = hint;
        }
        if (!sized) continue;
        if (!panel.screen_tris.empty()) judge_screen_uv(c, *mine, ref, panel);
        if (s.checks.nearest_truth && !panel.textures.empty()) {
            const Truth truth = nearest_truth(panel);
            const double err = share_off(*mine, panel, truth);
            const double ref_err = ref_main == ref.images.end() ? 0 : share_off(ref_main->second, panel, truth);
            c.j.measures["pixels off the exact nearest-texel picture" + where + ", % (reference " + num(std::round(ref_err * 10) / 10) +
                         ")"] = std::round(err * 10) / 10;
            if (err > ref_err + 2) {
                c.add(theme_topic, theme_advice.substr(0, theme_advice.find(": ")) + ": " + num(std::round(err * 10) / 10) +
                                       "% of the quad's pixels" + where + " are off the exact nearest-texel picture (ray cast "
                                       "per pixel; reference " + num(std::round(ref_err * 10) / 10) + "%): " +
                                       theme_advice.substr(theme_advice.find(": ") + 2));
            }
        }
        if (s.checks.shadow_state) {
            const LightState state = wrong_light_state(*mine, panel);
            const LightState ref_state = ref_main == ref.images.end() ? LightState{} : wrong_light_state(ref_main->second, panel);
            const long long ref_wrong = ref_state.wrong();
            // Surfaces facing away from the light drawn lit: L taken as +direction.
            if (double(state.lit_from_behind) > 10 + 1.3 * double(ref_state.lit_from_behind) &&
                2 * state.lit_from_behind >= state.facing_away) {
                c.add("light behind", "TODO 5: " + std::to_string(state.lit_from_behind) + " of the " +
                                          std::to_string(state.facing_away) + " pixels" + where +
                                          " on surfaces that face away from the light are lit as if it shone from "
                                          "the opposite side (reference " + std::to_string(ref_state.lit_from_behind) +
                                          "): L, toward the light, is -direction (a Light's direction is the way its "
                                          "rays travel), normalized");
            }
            // Shadows darker than ambient alone: the shadow factor scaled the ambient term too.
            if (double(state.too_dark) > 10 + 1.3 * double(ref_state.too_dark) && 2 * state.too_dark >= state.in_shadow) {
                c.add("shadow", "TODO 5: " + std::to_string(state.too_dark) + " of the " + std::to_string(state.in_shadow) +
                                    " pixels" + where +
                                    " in shadow are nearer black than the ambient light alone gives (reference " +
                                    std::to_string(ref_state.too_dark) +
                                    "): a shadow takes away only its light's term (diffuse and specular times the "
                                    "shadow factor); ambient (base times lighting.ambient) is added once, unshadowed");
            }
            c.j.measures["pixels in the wrong light state" + where + " (reference " + std::to_string(ref_wrong) + ", of " +
                         std::to_string(state.counted) + " pixels that face the light)"] = double(state.wrong());
            const double allowed = double(ref_wrong) * 1.3 + 10 + 0.01 * double(state.counted);
            if (double(state.wrong()) > allowed) {
                // Which way they are wrong says where to look: shadows missing, or shadows where
                // the light arrives.
                auto of_them = [&](long long k) { return (k == state.wrong() ? std::string("all") : num(double(k))) + " of them"; };
                std::string which;
                if (3 * state.missing >= 2 * state.wrong()) {
                    which = ": " + of_them(state.missing) +
                            " should be in shadow and are lit, so shadows are missing: a caster left out of the "
                            "depth pass (it draws every object that casts a shadow, with both faces), a bias so "
                            "large that shadows come off their casters (peter panning), the comparison reversed, "
                            "or a highlight left unshadowed (the factor multiplies the light's whole term, diffuse "
                            "and specular)";
                } else if (3 * state.spurious >= 2 * state.wrong()) {
                    which = ": " + of_them(state.spurious) +
                            " are drawn in shadow where the light reaches them: spread over lit surfaces that is "
                            "shadow acne (a surface shadowing itself: too little bias); else a wrong light matrix, "
                            "the comparison reversed, or L with the wrong sign (L = -direction: with +direction "
                            "the light never arrives where it should)";
                } else {
                    which = " (" + num(double(state.missing)) + " in shadow but lit, " + num(double(state.spurious)) +
                            " lit but drawn in shadow): a wrong light matrix or comparison, or the bias";
                }
                c.add("shadow", theme_advice.substr(0, theme_advice.find(": ")) + ": " + std::to_string(state.wrong()) +
                                    " of " + std::to_string(state.counted) + " pixels" + where +
                                    " are in the wrong light state against a ray cast to the light (reference " +
                                    std::to_string(ref_wrong) + ", allowed " + num(std::floor(allowed)) + ")" + which +
                                    "; " + theme_advice.substr(theme_advice.find(": ") + 2));
                // Its hint is what this scene's caller must do (the theme), not shadow_factor's rule.
                c.j.findings.back().hint = theme_advice.substr(theme_advice.find(": ") + 2);
            }
        }
        if (s.checks.sphere_error) {
            const raster::Image truth = exact_spheres(panel);
            const double err = panel_error(*mine, panel, truth);
            const double ref_err = ref_main == ref.images.end() ? err : panel_error(ref_main->second, panel, truth);
            c.j.measures["mean error vs the exact Blinn-Phong spheres, levels (reference " + num(round2(ref_err)) + ")"] = round2(err);
            // Off on average, or a picture beyond the tolerance that is nearer the exact spheres lit
            // by one of the known mistakes than the right ones (a small ambient error stays within
            // half a level on average, but not within the picture's tolerance).
            const bool off = err > ref_err + 0.5;
            if (off || differs) {
                // The known mistakes of the ambient term, and L = +direction: the exact spheres with each.
                const auto matches = [&](std::optional<Vec3> ambient, double to_light_sign = -1) {
                    const double e = panel_error(*mine, panel, exact_spheres(panel, ambient, to_light_sign));
                    return e <= ref_err + 0.5 && (off || e + 0.2 < err);
                };
                Vec3 all_intensities{};
                for (const LightSpec& l : panel.lights) all_intensities = all_intensities + l.intensity;
                const double lights = double(panel.lights.size());
                std::string why, topic = "ambient";
                if (lights > 1 && matches(panel.ambient * lights)) {
                    why = ", but they match the exact spheres lit with the ambient term added once per LIGHT (as closely "
                          "as the reference matches the right ones): add ambient (base times lighting.ambient) once per "
                          "fragment, then blinn_phong for each light";
                } else if (!panel.lights.empty() && (matches(mul(panel.ambient, panel.lights[0].intensity)) ||
                                                     matches(mul(panel.ambient, all_intensities)))) {
                    why = ", but they match the exact spheres whose ambient term is scaled by the lights' intensity: "
                          "ambient is base times lighting.ambient alone, once per fragment (it stands for light from "
                          "everywhere, not from one of the lights); the intensity scales only blinn_phong's terms";
                } else if (matches(Vec3{})) {
                    why = ", but they match the exact spheres WITHOUT the ambient term (their dark sides are black): "
                          "every fragment gets base times lighting.ambient once, lit or not, then blinn_phong for each light";
                } else {
                    topic = "specular";
                    why = matches({}, 1) ? ", but they match the exact spheres lit from the OPPOSITE side: L, toward the "
                                           "light, is -direction (a Light's direction is the way its rays travel), normalized"
                          : off          ? ": " + theme_advice.substr(theme_advice.find(": ") + 2)
                                         : "";
                }
                if (!why.empty()) c.add(topic, "TODO 5: the spheres are " + plural(round2(err), "level") +
                                      " from the exact Blinn-Phong spheres on average, the reference's " +
                                      num(round2(ref_err)) + why);
            }
        }
    }
    cp::report_totals(c.j, totals);
    if (sized && s.checks.filter_error) judge_filter_chart(c, *mine, ref);
    for (const auto& [p, q] : s.checks.same_panels) {
        if (!sized) break;
        const Panel &a = s.panels[std::size_t(p)], &b = s.panels[std::size_t(q)];
        long long diff = 0;
        int worst = 0;
        for (int y = 0; y < a.h; ++y) {
            for (int x = 0; x < a.w; ++x) {
                const int d = max_diff(mine->at(a.x0 + x, a.y0 + y), mine->at(b.x0 + x, b.y0 + y));
                diff += d > s.checks.same_tolerance;
                worst = std::max(worst, d);
            }
        }
        if (diff == 0) continue;
        std::string why = s.id == "m5.magnify"
                              ? "a mip filter where lambda <= 0 (everywhere here: magnified) is bilinear on level 0, the "
                                "very same picture"
                              : "uv near 1e7 must give the picture of uv near 0 (repeat): keep uv in double, a float "
                                "cannot hold the fraction";
        c.add(theme_topic, theme_advice.substr(0, theme_advice.find(": ")) + ": panels " + std::to_string(p + 1) + " and " +
                               std::to_string(q + 1) + " must agree within " + plural(s.checks.same_tolerance, "level") +
                               ", but " + plural(double(diff), "pixel") + (diff == 1 ? " differs" : " differ") +
                               " (by up to " + std::to_string(worst) + "): " + why);
    }

    if (differs) {
        // The difference comes from the callers, fill_triangle (TODO 5) or draw_scene (TODO 9).
        // Nearly all of it where a normal map that does not repeat is read at uv outside [0, 1]:
        // the map was read with other wrap modes than its own (repeat).
        const NormalWrapDiff nw = normal_map_wrap_diff(s, *mine, expected, c.j.tolerance);
        if (nw.outside >= 10 && 10 * nw.outside >= 9 * nw.strict) {
            // Nearly all of them where only one axis leaves [0, 1]: that axis's mode was not its own.
            const std::string axis = 10 * nw.only_v >= 9 * nw.outside   ? "v"
                                     : 10 * nw.only_u >= 9 * nw.outside ? "u"
                                                                        : "";
            const std::string one_axis =
                axis.empty() ? std::string()
                             : "; all but a few of them where only " + axis + " is outside [0, 1] (" + (axis == "u" ? "v" : "u") +
                                   " inside it), so it is " + axis + " that was read with another mode than its own, " +
                                   (axis == "u" ? nw.mode_u : nw.mode_v) + ": pass wrap_" + axis + " for " + axis;
            c.add("normal map", "TODO 5: " + std::to_string(nw.outside) + " of the " + std::to_string(nw.strict) +
                                    " pixels that differ beyond the tolerance lie on the normal-mapped surface" + nw.where +
                                    " at uv outside [0, 1], where its normal map does not repeat (" + nw.modes +
                                    "): there the normal map's own wrap modes decide which texel is read (read with "
                                    "other modes, bumps rise where the map's own modes read flat texels, or vanish "
                                    "where they read bumps: clamp to edge stretches the flat edge texels, mirrored "
                                    "repeat reads the map again backwards)" + one_axis);
            c.j.findings.back().hint = "fill_triangle reads the normal map with sample_bilinear on level 0 and the map's own "
                                       "wrap modes: sample_bilinear(level 0, uv, normal_map->wrap_u, normal_map->wrap_v)";
        }
        // Nearly all of a panel's difference one offset of the ambient term's size.
        const AmbientOffset ao = ambient_offset_diff(s, *mine, expected, c.j.tolerance);
        if (ao.matching > 0) {
            const auto levels = [](Vec3 v) {
                const auto one = [](double x) { return (x > 0 ? "+" : "") + num(std::round(x)); };
                return "(" + one(v.x) + ", " + one(v.y) + ", " + one(v.z) + ")";
            };
            c.add("ambient", "TODO 5: " + std::to_string(ao.matching) + " of the " + std::to_string(ao.strict) +
                                 " pixels" + ao.where + " that differ beyond the tolerance are off by the same (red, green, blue) = " +
                                 levels(ao.offset) + " levels, lit or not: the size of the ambient term " +
                                 ao.mistake + ". Ambient is base times lighting.ambient, added once per fragment " +
                                 "(not per light, not scaled by an intensity), then blinn_phong for each light");
            c.j.findings.back().hint = "fill_triangle adds base times lighting.ambient once per fragment, then each light's "
                                       "blinn_phong term";
        }
        // Nearly all of it on normal-mapped items without a texture,
        const NormalUvDiff nu = normal_map_uv_diff(s, *mine, expected, c.j.tolerance);
        // and there as smooth as without a map where the expected image shows its bumps.
        if (nu.untextured >= 20 && 10 * nu.untextured >= 9 * nu.strict && nu.bumpy_expected >= 50 &&
            4 * nu.bumpy_mine <= nu.bumpy_expected) {
            const bool textured_right = nu.textured_pixels >= 50 && 100 * nu.textured <= nu.textured_pixels;
            c.add("normal map", "TODO 9: " + std::to_string(nu.untextured) + " of the " + std::to_string(nu.strict) +
                                    " pixels that differ beyond the tolerance lie on normal-mapped items WITHOUT a texture, "
                                    "and there your picture is smooth where the expected one shows the map's bumps (" +
                                    std::to_string(nu.bumpy_mine) + " steps between neighbouring pixels against " +
                                    std::to_string(nu.bumpy_expected) + ")" +
                                    (textured_right ? ", while the normal-mapped item with a texture is right" : "") +
                                    ": a normal map is read at uv too, so draw_scene must interpolate uv (give each "
                                    "screen vertex the mesh's uv) wherever the material has a texture OR a normal map "
                                    "(lesson section 10); without uv the map is read at (0, 0) all over");
            c.j.findings.back().hint = "draw_scene gives every screen vertex its uv when the material has a texture or a "
                                       "normal map (a lit one), not only for a texture";
        }
        {
            std::vector<std::string> passing;
            for (Group g : prerequisite_groups(s)) passing.push_back(prerequisite_checkpoint(g));
            const std::string list = cp::join_once(passing);
            const auto colon = theme_advice.find(": ");
            c.add(theme_topic, theme_advice.substr(0, colon) + ": the picture differs from the expected one beyond the tolerance "
                                                               "(see diff.png)" +
                                   (list.empty() ? std::string()
                                                 : ", though the functions it is drawn with " + std::string(cp::kPassOwnChecks) + " (" + list +
                                                       "), so look at how they are called") +
                                   ": " +
                                   (theme_topic == "needs" && !counts_off
                                        ? std::string("every count matches the reference's, so each pass ran where this "
                                                      "scene needs it: what differs is what a pass computes, not which "
                                                      "passes run (the other failing checkpoints say where)")
                                        : theme_advice.substr(colon + 2) + ". This scene is about: " + s.hint));
        }
    }
    // The picture's own findings blame the caller the theme names (fill_triangle, draw_scene):
    // their hint is what that caller must do, not the rules of the topic's function.
    const std::string theme_todo = theme_advice.substr(0, theme_advice.find(": "));
    for (std::size_t i = first_finding; i < c.j.findings.size(); ++i) {
        cp::Finding& f = c.j.findings[i];
        if (f.hint.empty() && f.topic == theme_topic && f.todo == theme_todo) f.hint = theme_advice.substr(theme_todo.size() + 2);
    }
}

}  // namespace

cp::Judgement judge(const std::string& id, const cp::Artifacts& artifacts, const cp::Artifacts& reference,
                    const raster::Image& expected) {
    const Scene& s = scene(id);
    cp::Judgement j;
    if (!expected.empty()) j.tolerance = tolerance_for(s, expected);
    Ctx c{s, artifacts.values, reference.values, j};
    if (artifacts.stray_writes > 0) {
        c.add("rasterizer", "TODO 5: " + plural(double(artifacts.stray_writes), "write") +
                                " outside the image: clamp the bounding box to the image");
    }
    // A function the reference draws with that drew nothing (most often draw_scene, TODO 9, not
    // written yet): the harness names it, and every finding about the picture would follow from it.
    // A failing picture first checks the functions of TODOs 1-4 and 6-8 its panels use, on their
    // own checkpoints' inputs. One that is wrong is the finding ("fix TODO 3 first, see
    // m5.mipmaps"), and the picture's own findings, which would blame fill_triangle or
    // draw_scene for what it did, are left out. A checkpoint that passes stays passed.
    // A group whose own prerequisite fails is not told (sample() is wrong when fetch is).
    auto prerequisites = [&] {
        std::vector<cp::Finding> first;
        std::set<Group> failed;
        for (Group g : prerequisite_groups(s)) {
            const auto f = cp::prerequisite_finding(artifacts, reference, prerequisite_key(g), prerequisite_checkpoint(g),
                                                    [&](const Values& mine, const Values& ref, cp::Judgement& scratch) {
                                                        Ctx sub{s, mine, ref, scratch};
                                                        judge_group(g, sub);
                                                    },
                                                    !s.panels.empty());
            if (!f) continue;
            failed.insert(g);
            const auto deps = group_dependencies(g);
            if (std::any_of(deps.begin(), deps.end(), [&failed](Group d) { return failed.count(d) > 0; })) continue;
            first.push_back(*f);
        }
        return first;
    };
    auto numbers = [&] {
        for (Group g : s.groups) judge_group(g, c);
    };
    cp::judge_pipeline(j, artifacts, reference, expected, !s.panels.empty(), numbers,
                       [&] { judge_picture(c, artifacts, reference, expected); }, prerequisites);
    return j;
}

}  // namespace m5cp
