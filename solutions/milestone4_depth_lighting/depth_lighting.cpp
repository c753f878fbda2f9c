// BEGIN SOLUTION
// Milestone 4 reference solution. The student's skeleton,
// milestone4_depth_lighting/depth_lighting.cpp, is generated from this file by `make skeletons`.
// SKELETON: // Milestone 4: depth and lighting. Fill in the numbered TODOs; depth_lighting.h says
// SKELETON: // exactly what each function must do, and README.md walks through them in order.
// SKELETON: // Run `make check-m4` in your build folder to see which checkpoints pass.
// END SOLUTION
#include "depth_lighting.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <utility>

#include "triangles.h"

namespace m4 {
inline namespace RASTER_FLAVOUR {

// ---- TODO 1: depth keys ----

// BEGIN SOLUTION
namespace {

// depth_key's body, inline: fill_triangle calls it for every fragment.
inline std::uint32_t key_of(DepthFormat format, double z_ndc, double w) {
    if (std::isnan(z_ndc)) return kClearKey;
    const double d = std::clamp((z_ndc + 1) / 2, 0.0, 1.0);
    switch (format) {
        case DepthFormat::kFloatZ:
            return std::bit_cast<std::uint32_t>(static_cast<float>(d));
        case DepthFormat::kReversedZ: {
            const double r = std::clamp((1 - z_ndc) / 2, 0.0, 1.0);
            return kReversedBase - std::bit_cast<std::uint32_t>(static_cast<float>(r));
        }
        case DepthFormat::kFixed24:
            return static_cast<std::uint32_t>(std::llround(d * kFixed24Max));
        case DepthFormat::kInverseW:
            if (!(w > 0) || !std::isfinite(w)) return kClearKey;
            return kReversedBase - std::bit_cast<std::uint32_t>(static_cast<float>(1 / w));
    }
    return kClearKey;
}

}  // namespace
// END SOLUTION

std::uint32_t depth_key(DepthFormat format, double z_ndc, double w) {
    // TODO 1: NaN gives kClearKey; clamp d (or (1 - z_ndc) / 2) to [0, 1]; then each format as
    // depth_lighting.h describes it. std::bit_cast<std::uint32_t>(float_value) gives the bits.
    // BEGIN SOLUTION
    return key_of(format, z_ndc, w);
    // SKELETON: return 0;
    // END SOLUTION
}

// ---- TODO 2: the depth buffer ----

bool depth_passes(std::uint32_t key, Color color, std::uint32_t stored_key, Color stored_color) {
    // TODO 2: nearer wins; an exact tie goes to the brighter color (r, then g, then b).
    // BEGIN SOLUTION
    if (key == kClearKey) return false;
    if (key != stored_key) return key < stored_key;
    if (color.r != stored_color.r) return color.r > stored_color.r;
    if (color.g != stored_color.g) return color.g > stored_color.g;
    return color.b > stored_color.b;
    // SKELETON: return true;
    // END SOLUTION
}

void clear_frame(Frame& frame, Color background, bool depth_test, DepthFormat format) {
    // TODO 2: fill the color image; allocate and clear the keys only when the scene
    // depth-tests, and otherwise free them (a vector keeps its memory after clear()).
    // BEGIN SOLUTION
    frame.color.fill(background);
    frame.format = format;
    if (depth_test) {
        frame.depth.assign(static_cast<std::size_t>(frame.color.width()) * frame.color.height(), kClearKey);
    } else {
        std::vector<std::uint32_t>().swap(frame.depth);
    }
    // END SOLUTION
}

// ---- TODO 3: perspective-correct weights ----

std::array<double, 3> perspective_weights(const std::array<double, 3>& screen, const std::array<double, 3>& w) {
    // TODO 3: divide each weight by its vertex's w, then normalize so they sum to 1.
    // BEGIN SOLUTION
    const double q0 = screen[0] / w[0], q1 = screen[1] / w[1], q2 = screen[2] / w[2];
    const double sum = q0 + q1 + q2;
    if (!(sum > 0) || !std::isfinite(sum)) return screen;
    return {q0 / sum, q1 / sum, q2 / sum};
    // SKELETON: return screen;
    // END SOLUTION
}

// ---- TODO 4: normals ----

// BEGIN SOLUTION
namespace {

// normalize, but the zero vector for a zero or non-finite vector.
Vec3 unit_or_zero(Vec3 v) {
    const double len = raster::length(v);
    if (!(len > 0) || !std::isfinite(len)) return {};
    return v * (1 / len);  // one division instead of three
}

}  // namespace
// END SOLUTION

Vec3 face_normal(Vec3 p0, Vec3 p1, Vec3 p2) {
    // TODO 4a: the normalized cross product of two edges; zero for a degenerate triangle.
    // BEGIN SOLUTION
    return unit_or_zero(raster::cross(p1 - p0, p2 - p0));
    // SKELETON: return {};
    // END SOLUTION
}

std::vector<Vec3> vertex_normals(const std::vector<Vec3>& positions, const std::vector<std::array<int, 3>>& triangles) {
    // TODO 4b: add each triangle's UNnormalized cross product to its three vertices, then
    // normalize every sum.
    std::vector<Vec3> normals(positions.size());
    // BEGIN SOLUTION
    const int n = static_cast<int>(positions.size());
    for (const auto& t : triangles) {
        if (t[0] < 0 || t[0] >= n || t[1] < 0 || t[1] >= n || t[2] < 0 || t[2] >= n) continue;
        const Vec3 c = raster::cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]]);
        for (int k : t) normals[k] = normals[k] + c;
    }
    for (Vec3& v : normals) v = unit_or_zero(v);
    // END SOLUTION
    return normals;
}

Mat4 normal_matrix(const Mat4& model) {
    // TODO 4c: copy the 3x3 into an identity Mat4, invert it with m3::inverse, transpose.
    Mat4 r;
    // BEGIN SOLUTION
    Mat4 upper = m3::identity();
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) upper.m[i][j] = model.m[i][j];
    }
    Mat4 inv;
    if (!m3::inverse(upper, inv)) return r;
    r = m3::transpose(inv);
    // END SOLUTION
    return r;
}

// ---- TODO 5: lighting ----

// BEGIN SOLUTION
namespace {

// L, the unit vector from the surface point toward the light.
inline Vec3 toward_light(const Light& light, Vec3 position) {
    return light.kind == Light::Kind::kDirectional ? unit_or_zero(-light.vector) : unit_or_zero(light.vector - position);
}

// shade()'s sum for a normal n already normalized (or zero). `directional`, when given, holds
// L of each directional light (at its index in lighting.lights): that L is the same at every
// surface point, so draw_mesh, lighting every position with the same lights, computes it once
// per draw instead of once per position.
inline Vec3 lit_levels(const Lighting& lighting, const Vec3* directional, Color base, Vec3 position, Vec3 n) {
    Vec3 sum = lighting.ambient;
    for (std::size_t k = 0; k < lighting.lights.size(); ++k) {
        const Light& light = lighting.lights[k];
        const bool known = directional && light.kind == Light::Kind::kDirectional;
        const double lambert = raster::dot(n, known ? directional[k] : toward_light(light, position));
        // A light that does not reach the surface adds nothing, even an infinite one (inf * 0
        // would be NaN).
        if (lambert > 0) sum = sum + light.intensity * lambert;
    }
    return {base.r * sum.x, base.g * sum.y, base.b * sum.z};
}

}  // namespace
// END SOLUTION

Vec3 shade(const Lighting& lighting, Color base, Vec3 position, Vec3 normal) {
    // TODO 5a: sum the ambient and every light's intensity * max(0, N . L) per channel, then
    // multiply by the base color. Mind the direction of L: from the surface TOWARD the light.
    Vec3 levels;
    // BEGIN SOLUTION
    const Vec3 n = unit_or_zero(normal);
    levels = lit_levels(lighting, nullptr, base, position, n);
    // END SOLUTION
    return levels;
}

// BEGIN SOLUTION
namespace {

// One channel of to_color, inline for the fill loop: clamp to [0, 255], then round to
// nearest (the value is >= 0 by then). std::max(0.0, NaN) is 0, so a NaN gives 0; written
// this way round, the clamp compiles to two instructions and no branch.
inline std::uint8_t channel(double v) {
    return static_cast<std::uint8_t>(std::min(std::max(0.0, v), 255.0) + 0.5);
}

inline Color color_of(Vec3 levels) { return {channel(levels.x), channel(levels.y), channel(levels.z)}; }

}  // namespace
// END SOLUTION

Color to_color(Vec3 levels) {
    // TODO 5b: clamp each channel to [0, 255] BEFORE converting to an 8-bit channel.
    // BEGIN SOLUTION
    return color_of(levels);
    // SKELETON: return {};
    // END SOLUTION
}

// ---- TODO 6: debug views ----

Color depth_gray(double z_ndc) {
    // BEGIN SOLUTION
    const double d = std::clamp((z_ndc + 1) / 2, 0.0, 1.0);
    const double level = std::isnan(d) ? 0 : 255 * (1 - d);
    return to_color({level, level, level});
    // SKELETON: return {};
    // END SOLUTION
}

Color normal_color(Vec3 normal) {
    // BEGIN SOLUTION
    const Vec3 n = unit_or_zero(normal);
    return to_color({255 * (n.x + 1) / 2, 255 * (n.y + 1) / 2, 255 * (n.z + 1) / 2});
    // SKELETON: return {};
    // END SOLUTION
}

// ---- TODO 7: clipping with attributes ----

ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, double t) {
    // TODO 7a: every member moves the same fraction t of the way from a to b.
    ClipVertex r;
    // BEGIN SOLUTION
    r.clip = a.clip + (b.clip - a.clip) * t;
    r.color = a.color + (b.color - a.color) * t;
    r.normal = a.normal + (b.normal - a.normal) * t;
    r.world = a.world + (b.world - a.world) * t;
    r.uv = a.uv + (b.uv - a.uv) * t;
    // END SOLUTION
    return r;
}

// BEGIN SOLUTION
namespace {

// The six planes as signed distances: >= 0 inside (as in milestone 3).
double plane_distance(Vec4 p, int plane) {
    switch (plane) {
        case 0: return p.w + p.x;
        case 1: return p.w - p.x;
        case 2: return p.w + p.y;
        case 3: return p.w - p.y;
        case 4: return p.w + p.z;
        default: return p.w - p.z;
    }
}

bool inside(Vec4 p) {
    for (int plane = 0; plane < 6; ++plane) {
        if (!(plane_distance(p, plane) >= 0)) return false;
    }
    return true;
}

}  // namespace
// END SOLUTION

std::vector<ClipVertex> clip_triangle(const std::array<ClipVertex, 3>& triangle) {
    // TODO 7b: milestone 3's Sutherland-Hodgman loop over the six planes, with lerp() making
    // the new vertices.
    std::vector<ClipVertex> out;
    // BEGIN SOLUTION
    out.assign(triangle.begin(), triangle.end());
    std::vector<ClipVertex> next;
    for (int plane = 0; plane < 6 && !out.empty(); ++plane) {
        next.clear();
        for (std::size_t i = 0; i < out.size(); ++i) {
            const ClipVertex& a = out[i];
            const ClipVertex& b = out[(i + 1) % out.size()];
            const double da = plane_distance(a.clip, plane), db = plane_distance(b.clip, plane);
            if (da >= 0) next.push_back(a);
            if ((da >= 0) != (db >= 0)) {
                next.push_back(da >= 0 ? lerp(a, b, da / (da - db)) : lerp(b, a, db / (db - da)));
            }
        }
        out.swap(next);
    }
    // Exactly, every vertex inside has w >= near > 0; rounding between two huge vertices can
    // cancel every digit and leave (0, 0, 0, 0), which lies on all six planes. It has no place
    // on the screen: drop it.
    std::erase_if(out, [](const ClipVertex& c) { return !(c.clip.w > 0); });
    if (out.size() < 3) out.clear();
    // END SOLUTION
    return out;
}

// ---- TODO 8: the triangle with depth and attributes ----

// BEGIN SOLUTION
namespace {

// How many attribute values a fragment of this mode interpolates (depth_lighting.h).
int attribute_count(const FillState& s) {
    switch (s.needs.shading) {
        case Shading::kVertexColor:
        case Shading::kGouraud:
        case Shading::kNormalView: return 3;
        case Shading::kChecker: return 2;
        case Shading::kPerPixel: return s.point_light ? 6 : 3;
        default: return 0;
    }
}

// fill_triangle once the vertices are snapped: f[i] is m2::snap of v[i]'s screen x and y.
// draw_mesh snaps every position once and calls this directly (a position is shared by about
// six triangles); fill_triangle snaps its three vertices first.
void fill_snapped(Frame& frame, std::array<const ScreenVertex*, 3> v, std::array<m2::Fixed, 3> f,
                  const FillState& state, Stats& stats) {
    Image& img = frame.color;
    std::int64_t area2 = m2::edge(f[0], f[1], f[2]);
    if (area2 == 0) return;
    // Orient counter-clockwise on the screen's y-down axes (positive area), keeping the
    // vertices in step with their snapped points.
    if (area2 < 0) {
        std::swap(f[1], f[2]);
        std::swap(v[1], v[2]);
        area2 = -area2;
    }
    const ScreenVertex& a0 = *v[0];
    const ScreenVertex& a1 = *v[1];
    const ScreenVertex& a2 = *v[2];
    const m2::PixelRect box = m2::bounding_box(f[0], f[1], f[2], img.width(), img.height());
    if (box.x0 >= box.x1 || box.y0 >= box.y1) return;

    // Edge i runs from f[i] to f[i + 1]; its value is 0 on that edge and weighs the vertex
    // opposite it. Top-left rule: a zero counts only on a top or left edge (bias 0, else 1).
    constexpr std::int64_t S = m2::kSubpixelSteps;
    std::int64_t step_x[3], step_y[3], row[3], bias[3];
    const m2::Fixed start{std::int64_t(box.x0) * S + S / 2, std::int64_t(box.y0) * S + S / 2};
    for (int i = 0; i < 3; ++i) {
        const m2::Fixed a = f[i], b = f[i == 2 ? 0 : i + 1];
        const bool top_left = (b.y == a.y && b.x > a.x) || b.y < a.y;
        bias[i] = top_left ? 0 : 1;
        step_x[i] = -(b.y - a.y) * S;
        step_y[i] = (b.x - a.x) * S;
        row[i] = m2::edge(a, b, start);
    }

    const bool test = state.needs.depth_test && frame.depth.size() == static_cast<std::size_t>(img.width()) * img.height();
    std::uint32_t* const depth = test ? frame.depth.data() : nullptr;
    const DepthFormat format = frame.format;
    const Shading mode = state.needs.shading;
    const int attributes = attribute_count(state);
    const bool perspective = state.needs.perspective_correct;
    const double inv_area = 1.0 / static_cast<double>(area2);
    // 1 / w of each vertex, once per triangle: a pixel's perspective weights (the formula of
    // perspective_weights) then cost one division instead of six.
    const double iw0 = 1 / a0.w, iw1 = 1 / a1.w, iw2 = 1 / a2.w;
    const double z0 = a0.screen.z, z1 = a1.screen.z, z2 = a2.screen.z;
    // The counts stay in registers while the loop runs and go into `stats` at the end.
    long long fragments = 0, tests = 0, writes = 0, shaded = 0;

    for (int y = box.y0; y < box.y1; ++y) {
        std::int64_t e0 = row[0], e1 = row[1], e2 = row[2];
        std::size_t at = static_cast<std::size_t>(y) * img.width() + box.x0;
        for (int x = box.x0; x < box.x1; ++x, ++at, e0 += step_x[0], e1 += step_x[1], e2 += step_x[2]) {
            if (e0 < bias[0] || e1 < bias[1] || e2 < bias[2]) continue;
            ++fragments;
            // The screen weights, straight from the exact integer edge values (e1 is opposite
            // vertex 0, e2 opposite vertex 1, e0 opposite vertex 2): every triangle that
            // covers this pixel computes the same depth here, whatever its bounding box.
            const double l0 = double(e1) * inv_area, l1 = double(e2) * inv_area, l2 = double(e0) * inv_area;
            const double z = l0 * z0 + l1 * z1 + l2 * z2;
            const double q0 = l0 * iw0, q1 = l1 * iw1, q2 = l2 * iw2;
            const double q = q0 + q1 + q2;
            // perspective_weights' fallback: a sum that is not > 0 or not finite (a w of 0, NaN
            // or below about 1e-308, whose 1 / w overflows) leaves the screen weights, and the
            // pixel's w is then the one they interpolate.
            const bool correctable = q > 0 && std::isfinite(q);
            std::uint32_t key = 0;
            if (test) {
                ++tests;
                // Only the 1/w format reads the pixel's w; the others skip the division.
                const double w_key = format != DepthFormat::kInverseW ? 1.0
                                     : correctable                    ? 1 / q
                                                                      : l0 * a0.w + l1 * a1.w + l2 * a2.w;
                key = key_of(format, z, w_key);
                if (key > depth[at] || key == kClearKey) continue;  // hidden: no color needed
            }
            Color c = state.flat_color;
            if (attributes > 0) {
                shaded += attributes;
                double p0 = l0, p1 = l1, p2 = l2;
                if (perspective && correctable) {
                    const double w_here = 1 / q;  // the clip-space w of this pixel
                    p0 = q0 * w_here, p1 = q1 * w_here, p2 = q2 * w_here;
                }
                auto mix3 = [&](Vec3 v0, Vec3 v1, Vec3 v2) { return v0 * p0 + v1 * p1 + v2 * p2; };
                switch (mode) {
                    case Shading::kVertexColor:
                    case Shading::kGouraud: c = color_of(mix3(a0.color, a1.color, a2.color)); break;
                    case Shading::kNormalView: c = normal_color(mix3(a0.normal, a1.normal, a2.normal)); break;
                    case Shading::kChecker:
                        c = checker({a0.uv.x * p0 + a1.uv.x * p1 + a2.uv.x * p2, a0.uv.y * p0 + a1.uv.y * p1 + a2.uv.y * p2});
                        break;
                    case Shading::kPerPixel: {
                        const Vec3 world = state.point_light ? mix3(a0.world, a1.world, a2.world) : Vec3{};
                        ++stats.shade_calls;
                        c = color_of(shade(*state.lighting, state.material, world, mix3(a0.normal, a1.normal, a2.normal)));
                        break;
                    }
                    default: break;
                }
            } else if (mode == Shading::kDepthView) {
                c = depth_gray(z);
            }
            if (test) {
                // Nearer keys were let through above; only an exact tie needs the stored color.
                if (key == depth[at] && !depth_passes(key, c, depth[at], img.at(x, y))) continue;
                depth[at] = key;
                ++writes;
            }
            img.set(x, y, c);
        }
        for (int i = 0; i < 3; ++i) row[i] += step_y[i];
    }
    stats.fragments += fragments;
    stats.depth_tests += tests;
    stats.depth_writes += writes;
    stats.interpolated += shaded;
}

}  // namespace
// END SOLUTION

void fill_triangle(Frame& frame, const std::array<ScreenVertex, 3>& v, const FillState& state, Stats& stats) {
    // TODO 8: milestone 2's fill_triangle_gradient, extended: snap, orient (swapping the whole
    // vertex), bounding box, and per covered pixel center the weights, the depth test, the
    // color of the mode and the writes. Advice: step the three integer edge values from pixel
    // to pixel instead of recomputing them (an addition each).
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

// m3's Mat4 * Vec4 (the same sums in the same order, starting from 0, so the same bits),
// inline and written out for the loop over positions, where a call or a loop per product
// would cost as much as the product.
inline Vec4 times(const Mat4& a, Vec4 v) {
    auto row = [&](const double (&m)[4]) { return 0.0 + m[0] * v.x + m[1] * v.y + m[2] * v.z + m[3] * v.w; };
    return {row(a.m[0]), row(a.m[1]), row(a.m[2]), row(a.m[3])};
}

// m3::to_screen, inline for the same loop, with the same divisions (so the same bits).
inline Vec3 screen_of(Vec4 c, int width, int height) {
    const double x = c.x / c.w, y = c.y / c.w, z = c.z / c.w;
    return {(x + 1) / 2 * width, (1 - y) / 2 * height, z};
}

// Where a position lies after step 1. kInside: in the view volume, with its screen position
// snapped. kInsideUnsnapped: in the view volume but with no screen position: the origin of
// clip space, (0, 0, 0, 0), lies on all six planes and x / w is NaN there; a triangle using
// it is counted (culled or drawn) like any other and fills nothing.
enum class Where : unsigned char { kInside, kInsideUnsnapped, kOutside, kNotFinite };

// Step 1's results, one entry per position: the ScreenVertex the fill reads (only the
// attributes this mode reads are set; the screen position only for a position inside) and
// its snapped screen point. They live from call to call (one set per thread): a renderer
// draws the same mesh frame after frame, and reusing the arrays spares it allocating, and the
// system zeroing, megabytes per frame.
struct PerPosition {
    std::vector<Where> where;
    std::vector<m2::Fixed> snapped;
    std::vector<ScreenVertex> vertex;
};

PerPosition& per_position_arrays() {
    thread_local PerPosition arrays;
    return arrays;
}

}  // namespace
// END SOLUTION


Stats draw_mesh(Frame& frame, const Mesh& mesh, const Mat4& model, const Mat4& view, const Mat4& projection,
                const Lighting& lighting, Color material, const Needs& needs) {
    // TODO 9: follow the two steps of depth_lighting.h, computing only what needs.shading reads.
    Stats stats;
    // BEGIN SOLUTION
    const int n = static_cast<int>(mesh.positions.size());
    const Shading mode = needs.shading;
    bool point_light = false;
    for (const Light& l : lighting.lights) point_light |= l.kind == Light::Kind::kPoint;
    // What this mode reads, and nothing more: normals for the modes that light or show them
    // per position, world positions where a point light or a face normal needs them, a color
    // per position for kGouraud and kVertexColor.
    const bool want_normals = mode == Shading::kGouraud || mode == Shading::kPerPixel || mode == Shading::kNormalView;
    const bool want_world = mode == Shading::kFlat || (point_light && (mode == Shading::kGouraud || mode == Shading::kPerPixel));
    const bool want_uv = mode == Shading::kChecker;

    const Mat4 mvp = projection * (view * model);
    const Mat4 to_world_normal = want_normals ? normal_matrix(model) : Mat4{};
    std::vector<Vec3> computed_normals;
    const std::vector<Vec3>* model_normals = &mesh.normals;
    if (want_normals && mesh.normals.size() != mesh.positions.size()) {
        computed_normals = vertex_normals(mesh.positions, mesh.triangles);
        stats.vertex_normals += n;
        model_normals = &computed_normals;
    }
    // L of every directional light, once for all positions (lit_levels()).
    std::vector<Vec3> directional(lighting.lights.size());
    for (std::size_t k = 0; k < directional.size(); ++k) directional[k] = toward_light(lighting.lights[k], {});

    // Step 1: every position once, to the vertex the fill reads, snapped once here rather than
    // once per triangle that uses it.
    PerPosition& pp = per_position_arrays();
    // Grown, never shrunk: resizing down for a small mesh and up again for the next frame's big
    // one would construct every entry of the big one anew each frame (step 1 sets each anyway).
    if (pp.vertex.size() < static_cast<std::size_t>(n)) {
        pp.where.resize(n);
        pp.snapped.resize(n);
        pp.vertex.resize(n);
    }
    const int width = frame.color.width(), height = frame.color.height();
    auto clip_of = [&](int i) { return times(mvp, raster::point(mesh.positions[i])); };
    for (int i = 0; i < n; ++i) {
        const Vec3 p = mesh.positions[i];
        const Vec4 c = clip_of(i);
        ScreenVertex& v = pp.vertex[i];
        v = {};
        v.w = c.w;
        if (!(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && std::isfinite(c.w))) {
            pp.where[i] = Where::kNotFinite;
        } else if (inside(c)) {
            v.screen = screen_of(c, width, height);
            pp.where[i] = m2::snap({v.screen.x, v.screen.y}, pp.snapped[i]) ? Where::kInside : Where::kInsideUnsnapped;
        } else {
            pp.where[i] = Where::kOutside;
        }
        if (want_world) v.world = raster::xyz(times(model, raster::point(p)));
        if (want_normals) {
            v.normal = unit_or_zero(raster::xyz(times(to_world_normal, raster::direction((*model_normals)[i]))));
        }
        if (want_uv && i < static_cast<int>(mesh.uvs.size())) v.uv = mesh.uvs[i];
        if (mode == Shading::kVertexColor) {
            const Color vc = i < static_cast<int>(mesh.vertex_colors.size()) ? mesh.vertex_colors[i] : Color{0, 0, 0};
            v.color = {double(vc.r), double(vc.g), double(vc.b)};
        } else if (mode == Shading::kGouraud) {
            v.color = lit_levels(lighting, directional.data(), material, v.world, v.normal);  // shade()
            ++stats.shade_calls;
        }
    }

    // Step 2: every triangle.
    FillState state;
    state.needs = needs;
    state.lighting = &lighting;
    state.material = material;
    state.point_light = point_light;
    for (std::size_t face = 0; face < mesh.triangles.size(); ++face) {
        const auto& t = mesh.triangles[face];
        if (t[0] < 0 || t[0] >= n || t[1] < 0 || t[1] >= n || t[2] < 0 || t[2] >= n) continue;
        const Where w0 = pp.where[t[0]], w1 = pp.where[t[1]], w2 = pp.where[t[2]];
        if (w0 == Where::kNotFinite || w1 == Where::kNotFinite || w2 == Where::kNotFinite) continue;
        bool colored = false;
        // One triangle of the fan, from its screen positions and a function that fills it:
        // cull it, or color it (the first time) and fill it.
        auto draw = [&](Vec3 s0, Vec3 s1, Vec3 s2, auto&& fill) {
            if (needs.cull && m3::is_back_facing(s0, s1, s2)) {
                ++stats.triangles_culled;
                return;
            }
            if (!colored) {
                colored = true;
                if (mode == Shading::kFaceColor) {
                    state.flat_color = face < mesh.face_colors.size() ? mesh.face_colors[face] : raster::colors::white;
                } else if (mode == Shading::kFlat) {
                    const Vec3 p0 = pp.vertex[t[0]].world, p1 = pp.vertex[t[1]].world, p2 = pp.vertex[t[2]].world;
                    ++stats.shade_calls;
                    state.flat_color = color_of(shade(lighting, material, (p0 + p1 + p2) / 3, face_normal(p0, p1, p2)));
                }
            }
            ++stats.triangles_drawn;
            fill();
        };
        if (w0 != Where::kOutside && w1 != Where::kOutside && w2 != Where::kOutside) {
            const ScreenVertex &v0 = pp.vertex[t[0]], &v1 = pp.vertex[t[1]], &v2 = pp.vertex[t[2]];
            draw(v0.screen, v1.screen, v2.screen, [&] {
                if (w0 != Where::kInside || w1 != Where::kInside || w2 != Where::kInside) return;
                fill_snapped(frame, {&v0, &v1, &v2}, {pp.snapped[t[0]], pp.snapped[t[1]], pp.snapped[t[2]]}, state, stats);
            });
            continue;
        }
        ++stats.triangles_clipped;
        auto clip_vertex = [&](int i) {
            const ScreenVertex& v = pp.vertex[i];
            return ClipVertex{clip_of(i), v.color, v.normal, v.world, v.uv};
        };
        const std::vector<ClipVertex> poly = clip_triangle({clip_vertex(t[0]), clip_vertex(t[1]), clip_vertex(t[2])});
        auto to_screen_vertex = [&](const ClipVertex& c) {
            return ScreenVertex{m3::to_screen(c.clip, width, height), c.clip.w, c.color, c.normal, c.world, c.uv};
        };
        for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
            const std::array<ScreenVertex, 3> sv = {to_screen_vertex(poly[0]), to_screen_vertex(poly[i]),
                                                    to_screen_vertex(poly[i + 1])};
            draw(sv[0].screen, sv[1].screen, sv[2].screen, [&] { fill_triangle(frame, sv, state, stats); });
        }
    }
    // END SOLUTION
    return stats;
}

}  // namespace RASTER_FLAVOUR
}  // namespace m4
