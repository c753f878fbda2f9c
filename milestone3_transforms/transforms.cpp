// GENERATED from solutions/milestone3_transforms/transforms.cpp by `make skeletons`. Fill in the TODOs; do not edit the rest.
// Milestone 3: transforms. Fill in the numbered TODOs; transforms.h says exactly what
// each function must do, and README.md walks through them in the same order.
// Run `make check-m3` in your build folder to see which checkpoints pass.
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
    return r;
}

Vec4 operator*(const Mat4& a, Vec4 v) {
    // TODO 1: row r of the result is the dot product of row r of a with v.
    return {};
}

Mat4 transpose(const Mat4& a) {
    Mat4 r;
    return r;
}

Vec3 transform_point(const Mat4& a, Vec3 p) {
    // TODO 1: a point has w = 1.
    return {};
}

Vec3 transform_direction(const Mat4& a, Vec3 d) {
    // TODO 1: a direction has w = 0, so the translation column does not touch it.
    return {};
}

// ---- TODO 2: building blocks ----

Mat4 translate(Vec3 t) {
    // TODO 2: the identity with t in the last column.
    return {};
}

Mat4 scale(Vec3 s) {
    return {};
}

Mat4 rotate_x(double radians) {
    // TODO 2: y turns towards z.
    return {};
}

Mat4 rotate_y(double radians) {
    // TODO 2: z turns towards x (careful with the signs).
    return {};
}

Mat4 rotate_z(double radians) {
    // TODO 2: x turns towards y.
    return {};
}

Mat4 rotate(Vec3 axis, double radians) {
    // TODO 2b: with k = the unit axis and K its cross-product matrix,
    // R = I + sin(a) K + (1 - cos(a)) K^2; written out, R[i][j] = cos(a) delta_ij
    // + (1 - cos(a)) k_i k_j - sin(a) epsilon_ijl k_l.
    return {};
}

// ---- TODO 3: inverses ----

bool inverse(const Mat4& a, Mat4& out) {
    // TODO 3a: Gauss-Jordan on [a | I]: for each column pick the row with the largest |entry|
    // as pivot (partial pivoting), report a (near-)zero pivot as singular, scale the pivot
    // row, and eliminate the column from every other row. The right half is then a^-1.
    return false;
}

Mat4 rigid_inverse(const Mat4& a) {
    // TODO 3b: the transpose of the 3x3 rotation, and -R^T t in the last column.
    Mat4 r = identity();
    return r;
}

// ---- TODO 4: the camera ----

Mat4 look_at(Vec3 eye, Vec3 target, Vec3 up) {
    // TODO 4: build f, r, u as transforms.h says (with both fallbacks), then the rows r, u, -f
    // and the last column -(r . eye), -(u . eye), f . eye.
    return {};
}

// ---- TODO 5: projections ----

Mat4 perspective(double fovy_degrees, double aspect, double near, double far) {
    // TODO 5: check the arguments, convert the field of view to radians, then fill in the
    // five entries transforms.h lists.
    Mat4 p;
    return p;
}

Mat4 orthographic(double left, double right, double bottom, double top, double near, double far) {
    // TODO 5: scale each range to [-1, 1] and move its middle to 0; z is negated (view space
    // looks down -z, NDC's near plane is z = -1).
    Mat4 p;
    return p;
}

// ---- TODO 6: from clip space to pixels ----

Vec3 to_screen(Vec4 clip, int width, int height) {
    // TODO 6: divide x, y, z by w, then map x and y to pixels (flipping y).
    return {};
}

// ---- TODO 7: clipping ----

std::vector<Vec4> clip_polygon(const std::vector<Vec4>& poly) {
    // TODO 7a: for each plane, walk the edges (a, b) of the current polygon: keep a if it is
    // inside, and add the crossing point when a and b are on different sides.
    std::vector<Vec4> out;
    return out;
}

bool clip_line(Vec4& a, Vec4& b) {
    // TODO 7b: Liang-Barsky: keep the parameter range [t0, t1] of a + t (b - a) inside every
    // plane; reject when it becomes empty.
    return false;
}

// ---- TODO 8: back faces ----

bool is_back_facing(Vec3 s0, Vec3 s1, Vec3 s2) {
    // TODO 8: the sign of cross(s1 - s0, s2 - s0) in pixel coordinates (y down).
    return false;
}

// ---- TODO 9: Bezier ----

Vec3 bezier(Vec3 p0, Vec3 p1, Vec3 p2, Vec3 p3, double t) {
    // TODO 9: interpolate each pair of neighbours at t, three times over.
    return {};
}

// ---- TODO 10: painter's algorithm ----

std::vector<int> painter_order(const std::vector<std::array<Vec3, 3>>& view_triangles) {
    // TODO 10: sort the indices by the mean z of their triangle, most negative first.
    std::vector<int> order;
    return order;
}

// ---- TODO 11: the pipeline ----

Stats draw_model(Image& img, const Model& model, const Mat4& model_matrix, const Mat4& view,
                 const Mat4& projection, const Needs& needs, Color line_color) {
    // TODO 11: transform every position once; fill the triangles, then draw the edges,
    // running only the stages in `needs`, and count the work in the Stats.
    Stats stats;
    return stats;
}

}  // namespace RASTER_FLAVOUR
}  // namespace m3
