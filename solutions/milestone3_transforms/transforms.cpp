// BEGIN SOLUTION
// Milestone 3 reference solution. The student's skeleton, milestone3_transforms/transforms.cpp,
// is generated from this file by `make skeletons`.
// SKELETON: // Milestone 3: transforms. Fill in the numbered TODOs; transforms.h says exactly what
// SKELETON: // each function must do, and README.md walks through them in the same order.
// SKELETON: // Run `make check-m3` in your build folder to see which checkpoints pass.
// END SOLUTION
#include "transforms.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "lines.h"
#include "triangles.h"

namespace m3 {
inline namespace RASTER_FLAVOUR {

// ---- TODO 1: matrix operations ----

Mat4 operator*(const Mat4& a, const Mat4& b) {
    // TODO 1: r[i][j] = sum over k of a[i][k] * b[k][j].
    Mat4 r;
    // BEGIN SOLUTION
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            double s = 0;
            for (int k = 0; k < 4; ++k) s += a.m[i][k] * b.m[k][j];
            r.m[i][j] = s;
        }
    }
    // END SOLUTION
    return r;
}

Vec4 operator*(const Mat4& a, Vec4 v) {
    // TODO 1: row r of the result is the dot product of row r of a with v.
    // BEGIN SOLUTION
    const double in[4] = {v.x, v.y, v.z, v.w};
    double out[4] = {};
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) out[r] += a.m[r][c] * in[c];
    }
    return {out[0], out[1], out[2], out[3]};
    // SKELETON: return {};
    // END SOLUTION
}

Mat4 transpose(const Mat4& a) {
    Mat4 r;
    // BEGIN SOLUTION
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) r.m[i][j] = a.m[j][i];
    }
    // END SOLUTION
    return r;
}

Vec3 transform_point(const Mat4& a, Vec3 p) {
    // TODO 1: a point has w = 1.
    // BEGIN SOLUTION
    return raster::xyz(a * raster::point(p));
    // SKELETON: return {};
    // END SOLUTION
}

Vec3 transform_direction(const Mat4& a, Vec3 d) {
    // TODO 1: a direction has w = 0, so the translation column does not touch it.
    // BEGIN SOLUTION
    return raster::xyz(a * raster::direction(d));
    // SKELETON: return {};
    // END SOLUTION
}

// ---- TODO 2: building blocks ----

Mat4 translate(Vec3 t) {
    // TODO 2: the identity with t in the last column.
    // BEGIN SOLUTION
    Mat4 r = identity();
    r.m[0][3] = t.x;
    r.m[1][3] = t.y;
    r.m[2][3] = t.z;
    return r;
    // SKELETON: return {};
    // END SOLUTION
}

Mat4 scale(Vec3 s) {
    // BEGIN SOLUTION
    Mat4 r = identity();
    r.m[0][0] = s.x;
    r.m[1][1] = s.y;
    r.m[2][2] = s.z;
    return r;
    // SKELETON: return {};
    // END SOLUTION
}

Mat4 rotate_x(double radians) {
    // TODO 2: y turns towards z.
    // BEGIN SOLUTION
    const double c = std::cos(radians), s = std::sin(radians);
    Mat4 r = identity();
    r.m[1][1] = c;
    r.m[1][2] = -s;
    r.m[2][1] = s;
    r.m[2][2] = c;
    return r;
    // SKELETON: return {};
    // END SOLUTION
}

Mat4 rotate_y(double radians) {
    // TODO 2: z turns towards x (careful with the signs).
    // BEGIN SOLUTION
    const double c = std::cos(radians), s = std::sin(radians);
    Mat4 r = identity();
    r.m[0][0] = c;
    r.m[0][2] = s;
    r.m[2][0] = -s;
    r.m[2][2] = c;
    return r;
    // SKELETON: return {};
    // END SOLUTION
}

Mat4 rotate_z(double radians) {
    // TODO 2: x turns towards y.
    // BEGIN SOLUTION
    const double c = std::cos(radians), s = std::sin(radians);
    Mat4 r = identity();
    r.m[0][0] = c;
    r.m[0][1] = -s;
    r.m[1][0] = s;
    r.m[1][1] = c;
    return r;
    // SKELETON: return {};
    // END SOLUTION
}

// BEGIN SOLUTION
namespace {

// normalize(v), also where v's length overflows or its square underflows: then v is first
// scaled by a power of two (exactly) so that its largest component is about 1. Zero or not
// finite: the zero vector.
Vec3 unit(Vec3 v) {
    if (!raster::is_finite(v)) return {};
    const double len = raster::length(v);
    if (len > 1e-150 && std::isfinite(len)) return raster::normalize(v);
    const double big = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    if (!(big > 0)) return {};
    const int e = std::ilogb(big);
    return raster::normalize(Vec3{std::ldexp(v.x, -e), std::ldexp(v.y, -e), std::ldexp(v.z, -e)});
}

}  // namespace
// END SOLUTION

Mat4 rotate(Vec3 axis, double radians) {
    // TODO 2b: with k = the unit axis and K its cross-product matrix,
    // R = I + sin(a) K + (1 - cos(a)) K^2; written out, R[i][j] = cos(a) delta_ij
    // + (1 - cos(a)) k_i k_j - sin(a) epsilon_ijl k_l.
    // BEGIN SOLUTION
    if (!std::isfinite(radians)) return identity();
    const Vec3 k = unit(axis);  // zero for the zero axis or a non-finite one
    if (k == Vec3{}) return identity();
    const double c = std::cos(radians), s = std::sin(radians), t = 1 - c;
    Mat4 r = identity();
    r.m[0][0] = c + t * k.x * k.x;
    r.m[0][1] = t * k.x * k.y - s * k.z;
    r.m[0][2] = t * k.x * k.z + s * k.y;
    r.m[1][0] = t * k.y * k.x + s * k.z;
    r.m[1][1] = c + t * k.y * k.y;
    r.m[1][2] = t * k.y * k.z - s * k.x;
    r.m[2][0] = t * k.z * k.x - s * k.y;
    r.m[2][1] = t * k.z * k.y + s * k.x;
    r.m[2][2] = c + t * k.z * k.z;
    return r;
    // SKELETON: return {};
    // END SOLUTION
}

// ---- TODO 3: inverses ----

bool inverse(const Mat4& a, Mat4& out) {
    // TODO 3a: Gauss-Jordan on [a | I]: for each column pick the row with the largest |entry|
    // as pivot (partial pivoting), report a (near-)zero pivot as singular, scale the pivot
    // row, and eliminate the column from every other row. The right half is then a^-1.
    // BEGIN SOLUTION
    double m[4][8];
    double largest = 0;
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) {
            m[r][c] = a.m[r][c];
            m[r][c + 4] = r == c ? 1 : 0;
            largest = std::max(largest, std::abs(a.m[r][c]));
        }
    }
    if (!(largest > 0) || !std::isfinite(largest)) return false;
    for (const auto& row : a.m) {
        for (double e : row) {
            if (std::isnan(e)) return false;  // std::max above skips a NaN
        }
    }
    const double tiny = 1e-14 * largest;
    for (int col = 0; col < 4; ++col) {
        int pivot = col;
        for (int r = col + 1; r < 4; ++r) {
            if (std::abs(m[r][col]) > std::abs(m[pivot][col])) pivot = r;
        }
        if (!(std::abs(m[pivot][col]) > tiny)) return false;
        if (pivot != col) std::swap(m[pivot], m[col]);
        const double p = m[col][col];
        for (int c = 0; c < 8; ++c) m[col][c] /= p;
        for (int r = 0; r < 4; ++r) {
            if (r == col || m[r][col] == 0) continue;
            const double f = m[r][col];
            for (int c = 0; c < 8; ++c) m[r][c] -= f * m[col][c];
        }
    }
    // A matrix of tiny entries (all near 1e-320, say) passes the relative pivot test, but its
    // inverse is too large for a double: infinite or NaN entries mean "no inverse" too.
    for (int r = 0; r < 4; ++r) {
        for (int c = 4; c < 8; ++c) {
            if (!std::isfinite(m[r][c])) return false;
        }
    }
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) out.m[r][c] = m[r][c + 4];
    }
    return true;
    // SKELETON: return false;
    // END SOLUTION
}

Mat4 rigid_inverse(const Mat4& a) {
    // TODO 3b: the transpose of the 3x3 rotation, and -R^T t in the last column.
    Mat4 r = identity();
    // BEGIN SOLUTION
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) r.m[i][j] = a.m[j][i];
    }
    for (int i = 0; i < 3; ++i) {
        r.m[i][3] = -(r.m[i][0] * a.m[0][3] + r.m[i][1] * a.m[1][3] + r.m[i][2] * a.m[2][3]);
    }
    // END SOLUTION
    return r;
}

// ---- TODO 4: the camera ----

Mat4 look_at(Vec3 eye, Vec3 target, Vec3 up) {
    // TODO 4: build f, r, u as transforms.h says (with both fallbacks), then the rows r, u, -f
    // and the last column -(r . eye), -(u . eye), f . eye.
    // BEGIN SOLUTION
    if (!raster::is_finite(eye)) return Mat4{};
    Vec3 f = unit(target - eye);
    if (!(raster::length(f) > 0)) f = {0, 0, -1};
    Vec3 side = raster::cross(f, unit(up));
    if (!raster::is_finite(side) || !(raster::length(side) >= 1e-9)) {
        const double ax = std::abs(f.x), ay = std::abs(f.y), az = std::abs(f.z);
        const Vec3 world_up = ax <= ay && ax <= az ? Vec3{1, 0, 0} : ay <= az ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
        side = raster::cross(f, world_up);
    }
    const Vec3 r = raster::normalize(side);
    const Vec3 u = raster::cross(r, f);
    Mat4 v = identity();
    const Vec3 rows[3] = {r, u, -f};
    for (int i = 0; i < 3; ++i) {
        v.m[i][0] = rows[i].x;
        v.m[i][1] = rows[i].y;
        v.m[i][2] = rows[i].z;
        v.m[i][3] = -raster::dot(rows[i], eye);
    }
    return v;
    // SKELETON: return {};
    // END SOLUTION
}

// ---- TODO 5: projections ----

Mat4 perspective(double fovy_degrees, double aspect, double near, double far) {
    // TODO 5: check the arguments, convert the field of view to radians, then fill in the
    // five entries transforms.h lists.
    Mat4 p;
    // BEGIN SOLUTION
    const bool ok = std::isfinite(fovy_degrees) && std::isfinite(aspect) && std::isfinite(near) &&
                    std::isfinite(far) && fovy_degrees > 0 && fovy_degrees < 180 && aspect > 0 && near > 0 &&
                    far > near;
    if (!ok) return p;
    const double f = 1 / std::tan(fovy_degrees * std::numbers::pi / 180 / 2);
    p.m[0][0] = f / aspect;
    p.m[1][1] = f;
    p.m[2][2] = (far + near) / (near - far);
    p.m[2][3] = 2 * far * near / (near - far);
    p.m[3][2] = -1;
    if (!std::isfinite(p.m[0][0]) || !std::isfinite(p.m[2][3])) return Mat4{};  // f / aspect, 2 far near
    // END SOLUTION
    return p;
}

Mat4 orthographic(double left, double right, double bottom, double top, double near, double far) {
    // TODO 5: scale each range to [-1, 1] and move its middle to 0; z is negated (view space
    // looks down -z, NDC's near plane is z = -1).
    Mat4 p;
    // BEGIN SOLUTION
    const double all[6] = {left, right, bottom, top, near, far};
    for (double v : all) {
        if (!std::isfinite(v)) return p;
    }
    if (left == right || bottom == top || near == far) return p;
    p.m[0][0] = 2 / (right - left);
    p.m[1][1] = 2 / (top - bottom);
    p.m[2][2] = -2 / (far - near);
    p.m[0][3] = -(right + left) / (right - left);
    p.m[1][3] = -(top + bottom) / (top - bottom);
    p.m[2][3] = -(far + near) / (far - near);
    p.m[3][3] = 1;
    for (const auto& row : p.m) {
        for (double e : row) {
            if (!std::isfinite(e)) return Mat4{};  // a range so small (or large) it overflows
        }
    }
    // END SOLUTION
    return p;
}

// ---- TODO 6: from clip space to pixels ----

Vec3 to_screen(Vec4 clip, int width, int height) {
    // TODO 6: divide x, y, z by w, then map x and y to pixels (flipping y).
    // BEGIN SOLUTION
    const double x = clip.x / clip.w, y = clip.y / clip.w, z = clip.z / clip.w;
    return {(x + 1) / 2 * width, (1 - y) / 2 * height, z};
    // SKELETON: return {};
    // END SOLUTION
}

// ---- TODO 7: clipping ----

// BEGIN SOLUTION
namespace {

// The six planes as signed distances: >= 0 inside.
constexpr int kPlanes = 6;
const int kPlaneOrder[kPlanes] = {0, 1, 2, 3, 4, 5};

double distance(Vec4 p, int plane) {
    switch (plane) {
        case 0: return p.w + p.x;  // left
        case 1: return p.w - p.x;  // right
        case 2: return p.w + p.y;  // bottom
        case 3: return p.w - p.y;  // top
        case 4: return p.w + p.z;  // near
        default: return p.w - p.z;  // far
    }
}

// Beyond this magnitude a sum of two coordinates (a plane distance) may overflow.
constexpr double kHugeCoordinate = 0x1p500;

// The power of two by which to scale points whose largest |coordinate| is `big` so that none
// of the sums and differences clipping makes can overflow: 0 for ordinary points.
int huge_exponent(double big) { return big > kHugeCoordinate && std::isfinite(big) ? std::ilogb(big) : 0; }

double largest_coordinate(Vec4 p) { return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), std::abs(p.w)}); }

Vec4 scaled(Vec4 p, int e) { return {std::ldexp(p.x, e), std::ldexp(p.y, e), std::ldexp(p.z, e), std::ldexp(p.w, e)}; }

}  // namespace
// END SOLUTION

std::vector<Vec4> clip_polygon(const std::vector<Vec4>& poly) {
    // TODO 7a: for each plane, walk the edges (a, b) of the current polygon: keep a if it is
    // inside, and add the crossing point when a and b are on different sides.
    std::vector<Vec4> out;
    // BEGIN SOLUTION
    out = poly;
    // Huge coordinates (near 1e308) would overflow the plane distances into NaN vertices:
    // scaling every vertex by the same power of two (exact) moves none in projective space.
    double big = 0;
    for (const Vec4& p : poly) big = std::max(big, largest_coordinate(p));
    const int e = huge_exponent(big);
    if (e != 0) {
        for (Vec4& p : out) p = scaled(p, -e);
    }
    for (int plane : kPlaneOrder) {
        if (out.empty()) break;
        std::vector<Vec4> next;
        for (std::size_t i = 0; i < out.size(); ++i) {
            const Vec4 a = out[i], b = out[(i + 1) % out.size()];
            const double da = distance(a, plane), db = distance(b, plane);
            if (da >= 0) next.push_back(a);
            if ((da >= 0) != (db >= 0)) {
                // Interpolate from the inside end, so an edge shared by two triangles gets the
                // very same point from both.
                if (da >= 0) {
                    next.push_back(a + (b - a) * (da / (da - db)));
                } else {
                    next.push_back(b + (a - b) * (db / (db - da)));
                }
            }
        }
        out = std::move(next);
    }
    if (out.size() < 3) out.clear();
    if (e != 0) {
        for (Vec4& p : out) p = scaled(p, e);
    }
    // END SOLUTION
    return out;
}

bool clip_line(Vec4& a, Vec4& b) {
    // TODO 7b: Liang-Barsky: keep the parameter range [t0, t1] of a + t (b - a) inside every
    // plane; reject when it becomes empty.
    // BEGIN SOLUTION
    // Huge coordinates: as in clip_polygon, the distances are taken of the ends scaled by a
    // power of two, and the ends that move are moved along the scaled segment.
    const int e = huge_exponent(std::max(largest_coordinate(a), largest_coordinate(b)));
    const Vec4 sa = e != 0 ? scaled(a, -e) : a, sb = e != 0 ? scaled(b, -e) : b;
    double t0 = 0, t1 = 1;
    for (int plane : kPlaneOrder) {
        const double da = distance(sa, plane), db = distance(sb, plane);
        if (da < 0 && db < 0) return false;
        if (da < 0) {
            t0 = std::max(t0, da / (da - db));
        } else if (db < 0) {
            t1 = std::min(t1, da / (da - db));
        }
    }
    if (t0 > t1) return false;
    const Vec4 d = sb - sa;
    // A point of the segment lies between its ends in every coordinate; rounding may step one
    // unit past an end, which scaled back from the largest exponent would overflow.
    auto between = [&](Vec4 p) {
        auto in = [](double v, double x, double y) { return std::clamp(v, std::min(x, y), std::max(x, y)); };
        return Vec4{in(p.x, sa.x, sb.x), in(p.y, sa.y, sb.y), in(p.z, sa.z, sb.z), in(p.w, sa.w, sb.w)};
    };
    if (t0 > 0) a = e != 0 ? scaled(between(sa + d * t0), e) : sa + d * t0;
    if (t1 < 1) b = e != 0 ? scaled(between(sa + d * t1), e) : sa + d * t1;
    return true;
    // SKELETON: return false;
    // END SOLUTION
}

// ---- TODO 8: back faces ----

bool is_back_facing(Vec3 s0, Vec3 s1, Vec3 s2) {
    // TODO 8: the sign of cross(s1 - s0, s2 - s0) in pixel coordinates (y down).
    // BEGIN SOLUTION
    return (s1.x - s0.x) * (s2.y - s0.y) - (s1.y - s0.y) * (s2.x - s0.x) >= 0;
    // SKELETON: return false;
    // END SOLUTION
}

// ---- TODO 9: Bezier ----

Vec3 bezier(Vec3 p0, Vec3 p1, Vec3 p2, Vec3 p3, double t) {
    // TODO 9: interpolate each pair of neighbours at t, three times over.
    // BEGIN SOLUTION
    auto lerp = [t](Vec3 a, Vec3 b) { return a + (b - a) * t; };
    const Vec3 a = lerp(p0, p1), b = lerp(p1, p2), c = lerp(p2, p3);
    const Vec3 d = lerp(a, b), e = lerp(b, c);
    return lerp(d, e);
    // SKELETON: return {};
    // END SOLUTION
}

// ---- TODO 10: painter's algorithm ----

std::vector<int> painter_order(const std::vector<std::array<Vec3, 3>>& view_triangles) {
    // TODO 10: sort the indices by the mean z of their triangle, most negative first.
    std::vector<int> order;
    // BEGIN SOLUTION
    std::vector<double> key(view_triangles.size());
    for (std::size_t i = 0; i < view_triangles.size(); ++i) {
        const auto& t = view_triangles[i];
        const double mean = (t[0].z + t[1].z + t[2].z) / 3;
        // A NaN mean (a vertex not finite) sorts as the farthest: with NaN keys, < would not be
        // a strict weak order, and sorting with it is undefined behaviour.
        key[i] = std::isnan(mean) ? -std::numeric_limits<double>::infinity() : mean;
        order.push_back(static_cast<int>(i));
    }
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key[a] < key[b]; });
    // END SOLUTION
    return order;
}

// ---- TODO 11: the pipeline ----

// BEGIN SOLUTION
namespace {

bool inside(Vec4 p) {
    for (int plane = 0; plane < kPlanes; ++plane) {
        if (!(distance(p, plane) >= 0)) return false;
    }
    return true;
}

Vec2 xy(Vec3 s) { return {s.x, s.y}; }

}  // namespace
// END SOLUTION

Stats draw_model(Image& img, const Model& model, const Mat4& model_matrix, const Mat4& view,
                 const Mat4& projection, const Needs& needs, Color line_color) {
    // TODO 11: transform every position once; fill the triangles, then draw the edges,
    // running only the stages in `needs`, and count the work in the Stats.
    Stats stats;
    // BEGIN SOLUTION
    const int n = static_cast<int>(model.positions.size());
    const Mat4 model_view = view * model_matrix;
    const Mat4 mvp = projection * model_view;
    std::vector<Vec4> clip(n);
    for (int i = 0; i < n; ++i) clip[i] = mvp * raster::point(model.positions[i]);
    stats.vertices_transformed = n;
    auto valid = [n](int i) { return i >= 0 && i < n; };

    if (needs.fill) {
        const int count = static_cast<int>(model.triangles.size());
        std::vector<int> order(count);
        for (int i = 0; i < count; ++i) order[i] = i;
        if (needs.painter) {
            std::vector<std::array<Vec3, 3>> view_tris(count);
            for (int i = 0; i < count; ++i) {
                for (int k = 0; k < 3; ++k) {
                    const int v = model.triangles[i][k];
                    view_tris[i][k] = valid(v) ? transform_point(model_view, model.positions[v]) : Vec3{};
                }
            }
            order = painter_order(view_tris);
        }
        for (int face : order) {
            if (face < 0 || face >= count) continue;
            const auto& t = model.triangles[face];
            if (!valid(t[0]) || !valid(t[1]) || !valid(t[2])) continue;
            const Color color = face < static_cast<int>(model.face_colors.size()) ? model.face_colors[face]
                                                                                  : raster::colors::white;
            std::vector<Vec4> poly = {clip[t[0]], clip[t[1]], clip[t[2]]};
            if (needs.clip && !(inside(poly[0]) && inside(poly[1]) && inside(poly[2]))) {
                ++stats.triangles_clipped;
                poly = clip_polygon(poly);
            }
            for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
                const Vec3 s0 = to_screen(poly[0], img.width(), img.height());
                const Vec3 s1 = to_screen(poly[i], img.width(), img.height());
                const Vec3 s2 = to_screen(poly[i + 1], img.width(), img.height());
                if (needs.cull && is_back_facing(s0, s1, s2)) {
                    ++stats.triangles_culled;
                    continue;
                }
                m2::fill_triangle(img, xy(s0), xy(s1), xy(s2), color);
                ++stats.triangles_filled;
            }
        }
    }

    if (needs.wireframe) {
        for (const auto& e : model.edges) {
            if (!valid(e[0]) || !valid(e[1])) continue;
            Vec4 a = clip[e[0]], b = clip[e[1]];
            if (needs.clip && !(inside(a) && inside(b))) {
                ++stats.lines_clipped;
                if (!clip_line(a, b)) continue;
            }
            m1::draw_line(img, xy(to_screen(a, img.width(), img.height())),
                          xy(to_screen(b, img.width(), img.height())), line_color);
            ++stats.lines_drawn;
        }
    }
    // END SOLUTION
    return stats;
}

}  // namespace RASTER_FLAVOUR
}  // namespace m3
