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

std::uint32_t depth_key(DepthFormat format, double z_ndc, double w) {
    // TODO 1: NaN gives kClearKey; clamp d (or (1 - z_ndc) / 2) to [0, 1]; then each format as
    // depth_lighting.h describes it. std::bit_cast<std::uint32_t>(float_value) gives the bits.
    // BEGIN SOLUTION
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
    return v / len;
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

Vec3 shade(const Lighting& lighting, Color base, Vec3 position, Vec3 normal) {
    // TODO 5a: sum the ambient and every light's intensity * max(0, N . L) per channel, then
    // multiply by the base color. Mind the direction of L: from the surface TOWARD the light.
    Vec3 levels;
    // BEGIN SOLUTION
    const Vec3 n = unit_or_zero(normal);
    Vec3 sum = lighting.ambient;
    for (const Light& light : lighting.lights) {
        const Vec3 l = light.kind == Light::Kind::kDirectional ? unit_or_zero(-light.vector)
                                                               : unit_or_zero(light.vector - position);
        const double lambert = std::max(0.0, raster::dot(n, l));
        sum = sum + light.intensity * lambert;
    }
    levels = {base.r * sum.x, base.g * sum.y, base.b * sum.z};
    // END SOLUTION
    return levels;
}

Color to_color(Vec3 levels) {
    // TODO 5b: clamp each channel to [0, 255] BEFORE converting to an 8-bit channel.
    // BEGIN SOLUTION
    auto channel = [](double v) -> std::uint8_t {
        if (std::isnan(v)) return 0;
        return static_cast<std::uint8_t>(std::clamp(v, 0.0, 255.0) + 0.5);  // rounds to nearest: v >= 0 here
    };
    return {channel(levels.x), channel(levels.y), channel(levels.z)};
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

}  // namespace
// END SOLUTION

void fill_triangle(Frame& frame, const std::array<ScreenVertex, 3>& v, const FillState& state, Stats& stats) {
    // TODO 8: milestone 2's fill_triangle_gradient, extended: snap, orient (swapping the whole
    // vertex), bounding box, and per covered pixel center the weights, the depth test, the
    // color of the mode and the writes. Advice: step the three integer edge values from pixel
    // to pixel instead of recomputing them (an addition each).
    // BEGIN SOLUTION
    Image& img = frame.color;
    m2::Fixed f[3];
    for (int i = 0; i < 3; ++i) {
        if (!m2::snap({v[i].screen.x, v[i].screen.y}, f[i])) return;
    }
    std::int64_t area2 = m2::edge(f[0], f[1], f[2]);
    if (area2 == 0) return;
    // Orient counter-clockwise on the screen's y-down axes (positive area), keeping the
    // vertex order of the attributes in step with the snapped points.
    int order[3] = {0, 1, 2};
    if (area2 < 0) {
        std::swap(f[1], f[2]);
        std::swap(order[1], order[2]);
        area2 = -area2;
    }
    const ScreenVertex& a0 = v[order[0]];
    const ScreenVertex& a1 = v[order[1]];
    const ScreenVertex& a2 = v[order[2]];
    const m2::PixelRect box = m2::bounding_box(f[0], f[1], f[2], img.width(), img.height());
    if (box.x0 >= box.x1 || box.y0 >= box.y1) return;

    // Edge i runs from f[i] to f[i + 1]; its value is 0 on that edge and weighs the vertex
    // opposite it. Top-left rule: a zero counts only on a top or left edge (bias 0, else 1).
    constexpr std::int64_t S = m2::kSubpixelSteps;
    std::int64_t step_x[3], step_y[3], row[3], bias[3];
    const m2::Fixed start{std::int64_t(box.x0) * S + S / 2, std::int64_t(box.y0) * S + S / 2};
    for (int i = 0; i < 3; ++i) {
        const m2::Fixed a = f[i], b = f[(i + 1) % 3];
        const bool top_left = (b.y == a.y && b.x > a.x) || b.y < a.y;
        bias[i] = top_left ? 0 : 1;
        step_x[i] = -(b.y - a.y) * S;
        step_y[i] = (b.x - a.x) * S;
        row[i] = m2::edge(a, b, start);
    }

    const bool test = state.needs.depth_test && frame.depth.size() == static_cast<std::size_t>(img.width()) * img.height();
    const Shading mode = state.needs.shading;
    const int attributes = attribute_count(state);
    const double inv_area = 1.0 / static_cast<double>(area2);
    // 1 / w of each vertex, once per triangle: a pixel's perspective weights (the formula of
    // perspective_weights) then cost one division instead of six.
    const double iw0 = 1 / a0.w, iw1 = 1 / a1.w, iw2 = 1 / a2.w;
    const double z0 = a0.screen.z, z1 = a1.screen.z, z2 = a2.screen.z;

    for (int y = box.y0; y < box.y1; ++y) {
        std::int64_t e0 = row[0], e1 = row[1], e2 = row[2];
        for (int x = box.x0; x < box.x1; ++x, e0 += step_x[0], e1 += step_x[1], e2 += step_x[2]) {
            if (e0 < bias[0] || e1 < bias[1] || e2 < bias[2]) continue;
            ++stats.fragments;
            // e1 is opposite vertex 0, e2 opposite vertex 1, e0 opposite vertex 2.
            const std::array<double, 3> l = {double(e1) * inv_area, double(e2) * inv_area, double(e0) * inv_area};
            const double z = l[0] * z0 + l[1] * z1 + l[2] * z2;
            const std::size_t at = static_cast<std::size_t>(y) * img.width() + x;
            const double q0 = l[0] * iw0, q1 = l[1] * iw1, q2 = l[2] * iw2;
            const double w_here = 1 / (q0 + q1 + q2);  // the clip-space w of this pixel
            std::uint32_t key = 0;
            if (test) {
                ++stats.depth_tests;
                key = depth_key(frame.format, z, w_here);
                if (key > frame.depth[at] || key == kClearKey) continue;  // hidden: no color needed
            }
            Color c = state.flat_color;
            if (attributes > 0) {
                stats.interpolated += attributes;
                const std::array<double, 3> p =
                    state.needs.perspective_correct ? std::array<double, 3>{q0 * w_here, q1 * w_here, q2 * w_here} : l;
                auto mix3 = [&p](Vec3 q0, Vec3 q1, Vec3 q2) { return q0 * p[0] + q1 * p[1] + q2 * p[2]; };
                switch (mode) {
                    case Shading::kVertexColor:
                    case Shading::kGouraud: c = to_color(mix3(a0.color, a1.color, a2.color)); break;
                    case Shading::kNormalView: c = normal_color(mix3(a0.normal, a1.normal, a2.normal)); break;
                    case Shading::kChecker:
                        c = checker({a0.uv.x * p[0] + a1.uv.x * p[1] + a2.uv.x * p[2],
                                     a0.uv.y * p[0] + a1.uv.y * p[1] + a2.uv.y * p[2]});
                        break;
                    case Shading::kPerPixel: {
                        const Vec3 world = state.point_light ? mix3(a0.world, a1.world, a2.world) : Vec3{};
                        ++stats.shade_calls;
                        c = to_color(shade(*state.lighting, state.material, world, mix3(a0.normal, a1.normal, a2.normal)));
                        break;
                    }
                    default: break;
                }
            } else if (mode == Shading::kDepthView) {
                c = depth_gray(z);
            }
            if (test) {
                // Nearer keys were let through above; only an exact tie needs the stored color.
                if (key == frame.depth[at] && !depth_passes(key, c, frame.depth[at], img.at(x, y))) continue;
                frame.depth[at] = key;
                ++stats.depth_writes;
            }
            img.set(x, y, c);
        }
        for (int i = 0; i < 3; ++i) row[i] += step_y[i];
    }
    // END SOLUTION
}

// ---- TODO 9: the pipeline ----

Stats draw_mesh(Frame& frame, const Mesh& mesh, const Mat4& model, const Mat4& view, const Mat4& projection,
                const Lighting& lighting, Color material, const Needs& needs) {
    // TODO 9: follow the two steps of depth_lighting.h, computing only what needs.shading reads.
    Stats stats;
    // BEGIN SOLUTION
    const int n = static_cast<int>(mesh.positions.size());
    const Shading mode = needs.shading;
    const bool lit = mode == Shading::kFlat || mode == Shading::kGouraud || mode == Shading::kPerPixel;
    const bool vertex_normals_needed = mode == Shading::kGouraud || mode == Shading::kPerPixel || mode == Shading::kNormalView;
    bool point_light = false;
    for (const Light& l : lighting.lights) point_light |= l.kind == Light::Kind::kPoint;

    const Mat4 mvp = projection * (view * model);
    std::vector<ClipVertex> verts(n);
    std::vector<Vec3> normals;
    if (vertex_normals_needed) {
        if (mesh.normals.size() == mesh.positions.size()) {
            normals = mesh.normals;
        } else {
            normals = vertex_normals(mesh.positions, mesh.triangles);
            stats.vertex_normals += n;
        }
    }
    const Mat4 to_world_normal = vertex_normals_needed ? normal_matrix(model) : Mat4{};
    for (int i = 0; i < n; ++i) {
        ClipVertex& cv = verts[i];
        const Vec3 p = mesh.positions[i];
        cv.clip = mvp * raster::point(p);
        if (lit) cv.world = m3::transform_point(model, p);
        if (vertex_normals_needed) cv.normal = unit_or_zero(m3::transform_direction(to_world_normal, normals[i]));
        if (mode == Shading::kVertexColor && i < static_cast<int>(mesh.vertex_colors.size())) {
            const Color c = mesh.vertex_colors[i];
            cv.color = {double(c.r), double(c.g), double(c.b)};
        }
        if (mode == Shading::kGouraud) {
            cv.color = shade(lighting, material, cv.world, cv.normal);
            ++stats.shade_calls;
        }
        if (mode == Shading::kChecker && i < static_cast<int>(mesh.uvs.size())) cv.uv = mesh.uvs[i];
    }

    FillState state;
    state.needs = needs;
    state.lighting = &lighting;
    state.material = material;
    state.point_light = point_light;
    const int width = frame.color.width(), height = frame.color.height();
    // Per position, once: where it lies (inside the view volume, outside, or not finite) and,
    // inside, its screen position; a triangle that needs no clipping reuses them.
    enum Where : unsigned char { kInside, kOutside, kNotFinite };
    std::vector<Where> where(n);
    std::vector<Vec3> screen(n);
    for (int i = 0; i < n; ++i) {
        const Vec4 c = verts[i].clip;
        if (!(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && std::isfinite(c.w))) {
            where[i] = kNotFinite;
        } else if (inside(c)) {
            where[i] = kInside;
            screen[i] = m3::to_screen(c, width, height);
        } else {
            where[i] = kOutside;
        }
    }

    std::vector<ClipVertex> poly;  // a clipped triangle's polygon
    for (std::size_t face = 0; face < mesh.triangles.size(); ++face) {
        const auto& t = mesh.triangles[face];
        if (t[0] < 0 || t[0] >= n || t[1] < 0 || t[1] >= n || t[2] < 0 || t[2] >= n) continue;
        if (where[t[0]] == kNotFinite || where[t[1]] == kNotFinite || where[t[2]] == kNotFinite) continue;
        const ClipVertex &c0 = verts[t[0]], &c1 = verts[t[1]], &c2 = verts[t[2]];
        bool colored = false;
        // One triangle of the fan: cull it, or color it (the first time) and fill it.
        auto draw = [&](const ClipVertex* const src[3], const Vec3 scr[3]) {
            if (needs.cull && m3::is_back_facing(scr[0], scr[1], scr[2])) {
                ++stats.triangles_culled;
                return;
            }
            if (!colored) {
                colored = true;
                if (mode == Shading::kFaceColor) {
                    state.flat_color = face < mesh.face_colors.size() ? mesh.face_colors[face] : raster::colors::white;
                } else if (mode == Shading::kFlat) {
                    const Vec3 centroid = (c0.world + c1.world + c2.world) / 3;
                    ++stats.shade_calls;
                    state.flat_color = to_color(shade(lighting, material, centroid, face_normal(c0.world, c1.world, c2.world)));
                }
            }
            std::array<ScreenVertex, 3> s;
            for (int k = 0; k < 3; ++k) {
                s[k] = {scr[k], src[k]->clip.w, src[k]->color, src[k]->normal, src[k]->world, src[k]->uv};
            }
            fill_triangle(frame, s, state, stats);
            ++stats.triangles_drawn;
        };
        if (where[t[0]] == kInside && where[t[1]] == kInside && where[t[2]] == kInside) {
            const ClipVertex* src[3] = {&c0, &c1, &c2};
            const Vec3 scr[3] = {screen[t[0]], screen[t[1]], screen[t[2]]};
            draw(src, scr);
            continue;
        }
        ++stats.triangles_clipped;
        poly = clip_triangle({c0, c1, c2});
        for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
            const ClipVertex* src[3] = {&poly[0], &poly[i], &poly[i + 1]};
            const Vec3 scr[3] = {m3::to_screen(poly[0].clip, width, height), m3::to_screen(poly[i].clip, width, height),
                                 m3::to_screen(poly[i + 1].clip, width, height)};
            draw(src, scr);
        }
    }
    // END SOLUTION
    return stats;
}

}  // namespace RASTER_FLAVOUR
}  // namespace m4
