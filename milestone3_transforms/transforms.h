// Milestone 3: transforms. The functions you implement in transforms.cpp.
//
// Conventions (the checkpoints test every one of them):
//
//  * Matrices. Mat4 stores m[row][col] (row-major STORAGE) and acts on COLUMN vectors:
//    v' = M * v, (M * v)[r] = sum over c of m[r][c] * v[c]. So a translation sits in the last
//    column (m[0][3], m[1][3], m[2][3]), and A * B applied to v means "first B, then A":
//    translate(t) * rotate_z(a) turns a point, then moves it. This is the convention of
//    OpenGL's documentation and of GLM (which stores columns, but multiplies the same way).
//
//  * Points and directions. A point has w = 1 and is moved by translations; a direction
//    (an edge, a normal, a velocity) has w = 0 and is not. transform_point and
//    transform_direction drop the fourth row: they are for model and view matrices, whose
//    last row is (0, 0, 0, 1). Projections go through M * Vec4 and the perspective divide.
//
//  * Angles. Rotations take RADIANS; perspective() takes its field of view in DEGREES (as a
//    camera is usually specified). A positive angle turns counter-clockwise when you look
//    from the tip of the axis towards the origin (right-hand rule): rotate_z(pi / 2) maps
//    +x to +y.
//
//  * World and camera. Right-handed world. The camera sits at the origin of VIEW space and
//    looks down -z, with +y up and +x to the right (OpenGL's convention).
//
//  * Clip space and NDC. A projection maps view space to clip space (x, y, z, w). A point is
//    inside the view volume when -w <= x <= w, -w <= y <= w and -w <= z <= w (six closed
//    planes). After the perspective divide, normalized device coordinates (NDC) are x/w, y/w,
//    z/w, each in [-1, 1]; z = -1 is the near plane and +1 the far plane (OpenGL's depth range,
//    so GLM's glm::perspective and glm::ortho build the very same matrices).
//
//  * Viewport. NDC to pixels of a W x H image: x_pixel = (x_ndc + 1) / 2 * W and
//    y_pixel = (1 - y_ndc) / 2 * H. The y flip: NDC's y points up, the image's rows grow
//    downward (milestones 1 and 2), so the top of the view (y_ndc = 1) is row 0.
//
//  * Winding and back faces. A model lists each triangle's vertices counter-clockwise when
//    seen from outside the object. Seen through the camera, a front face is counter-clockwise
//    on the screen too; but in pixel coordinates (y down) its signed area
//    cross(s1 - s0, s2 - s0) is NEGATIVE. is_back_facing is true when that value is >= 0 (an
//    edge-on face, of zero area, is culled as well).
//
//  * Clipping happens in clip space, BEFORE the divide, so a vertex behind the camera
//    (w < 0) or in its plane (w = 0) never reaches a division. After clipping against the six
//    planes every vertex has w >= near > 0 for a perspective and w = 1 for an orthographic
//    projection. The order of the planes is yours; the result is the same polygon.
//
//  * Precision. Everything is double. Matrices are compared with a tolerance of about 1e-9
//    (1e-9 relative to the size of the numbers); images allow pixels next to an edge to differ
//    a little, since a vertex may round to a neighbouring pixel. Nothing is timed.
//
//  * Bad input never crashes, hangs or returns NaN where this file says otherwise: see each
//    function. The picture checkpoints give NaN-free but extreme input (far planes of 1e6,
//    fields of view of 1 and 179 degrees, models 1e6 units away, vertices exactly in the
//    camera's plane). What each function returns for NaN, infinities, coordinates near 1e308
//    and subnormals is said below (rotate, inverse, look_at, the projections, clipping), and
//    the checkpoint m3.nonfinite tests those answers. draw_model must skip a triangle or edge
//    with an index outside [0, positions.size()) (tested); one with a non-finite clip
//    coordinate draws nothing without a check of yours (milestones 1 and 2 draw nothing for a
//    non-finite point), so whether you skip it first is yours. The project also fuzzes the reference with such input
//    under AddressSanitizer and UndefinedBehaviorSanitizer; `make fuzz-m3 FUZZ_STUDENT=1` in
//    your build folder does the same to your code (it needs clang).
#pragma once

#include <array>
#include <vector>

#include "raster/color.h"
#include "raster/flavour.h"
#include "raster/image.h"
#include "raster/vec.h"

namespace m3 {
inline namespace RASTER_FLAVOUR {

using raster::Color;
using raster::Image;
using raster::Vec2;
using raster::Vec3;
using raster::Vec4;

// Row-major storage, column vectors (see above). Default: all zeros.
struct Mat4 {
    double m[4][4] = {};
};

inline Mat4 identity() {
    Mat4 r;
    for (int i = 0; i < 4; ++i) r.m[i][i] = 1;
    return r;
}

// ---- TODO 1: matrix operations ----
Mat4 operator*(const Mat4& a, const Mat4& b);  // the product a * b: first b, then a
Vec4 operator*(const Mat4& a, Vec4 v);          // a * v
Mat4 transpose(const Mat4& a);
Vec3 transform_point(const Mat4& a, Vec3 p);      // xyz of a * (p, 1)
Vec3 transform_direction(const Mat4& a, Vec3 d);  // xyz of a * (d, 0): no translation

// ---- TODO 2: building blocks ----
Mat4 translate(Vec3 t);
Mat4 scale(Vec3 s);
Mat4 rotate_x(double radians);
Mat4 rotate_y(double radians);
Mat4 rotate_z(double radians);
// TODO 2b: rotation about any axis through the origin (Rodrigues' formula). The axis need not
// have length 1 (normalize it; as in look_at, an axis whose squared length underflows, such as
// (1e-200, 0, 0), or overflows, such as (1e200, 0, 0), is scaled by a power of two first, so
// it keeps its direction); the zero axis (or a non-finite one) gives the identity. A
// non-finite angle is not tested: the reference returns the identity, and NaN entries (what
// std::cos(inf) gives, as in rotate_x, y and z) pass as well.
Mat4 rotate(Vec3 axis, double radians);

// ---- TODO 3: inverses ----
// TODO 3a: the general inverse (Gauss-Jordan elimination with partial pivoting, or
// cofactors). Returns false, leaving `out` alone, when `a` is singular. Tested rule: a matrix
// whose singularity is exact (a zero column, two equal rows) must give false; a matrix with a
// condition number up to 1e12 (the checkpoint's is R1 * D * R2, with rotations R1, R2 and the
// diagonal D = (1, 1e-6, 1e-6, 1e-12): entries at most 1, a last pivot near 1e-12) must give
// true with |a * out - I| <= 1e-3 in every entry. Between the two the choice is yours, as long
// as it scales with the entries (the reference reports a pivot <= 1e-14 times the largest
// |entry|; a fixed threshold such as 1e-6 fails). A matrix with an entry that is NaN or
// infinite returns false too, and so does one whose inverse would have an entry too large for a
// double (a matrix of entries near 1e-320: check the result is finite before writing `out`;
// m3.nonfinite tests these three cases).
bool inverse(const Mat4& a, Mat4& out);
// TODO 3b: the inverse of a rigid transform (a rotation R and a translation t, last row
// 0 0 0 1): R transposed, and -R^T t. No elimination, no test for singularity.
Mat4 rigid_inverse(const Mat4& a);

// ---- TODO 4: the camera ----
// The view matrix of a camera at `eye` looking at `target`, with `up` roughly upward:
// f = normalize(target - eye), r = normalize(cross(f, up)), u = cross(r, f). The matrix's
// rows are r, u and -f (then 0 0 0 1), and its last column is -(R * eye), so eye goes to the
// origin and target onto the -z axis. The basis r, u, -f is right-handed.
// Fallbacks (never NaN):
//  * eye not finite: the zero matrix (which draws nothing).
//  * eye == target (or target - eye is not finite): f = (0, 0, -1).
//  * Normalizing never loses a direction: a target - eye (or an up) whose length overflows
//    (components near 1e308) or whose square underflows (2e-162 apart) is scaled by a power
//    of two first, so f still has length 1 and points from eye to target.
//  * The last column may overflow to +/-infinity for an eye beyond about 1e308 (never NaN).
//  * up parallel to f, i.e. |cross(f, normalize(up))| < 1e-9, or up zero or not finite: up
//    is replaced by the world axis x, y or z along which |f| has its smallest component (the
//    first of them on a tie), e.g. looking straight down (f = (0, -1, 0)) uses up = (1, 0, 0).
Mat4 look_at(Vec3 eye, Vec3 target, Vec3 up);

// ---- TODO 5: projections (view space to clip space), OpenGL's matrices ----
// Perspective: vertical field of view in DEGREES, aspect = width / height, 0 < near < far.
// With f = 1 / tan(fovy / 2): x' = f / aspect * x, y' = f * y,
// z' = (far + near) / (near - far) * z + 2 * far * near / (near - far), w' = -z.
// Invalid arguments (fovy outside (0, 180), aspect <= 0, near <= 0, far <= near, anything not
// finite) give the zero matrix, which draws nothing; so do arguments that would put an
// infinite entry in the matrix (f / aspect overflowing, or 2 * far * near as written above,
// e.g. far = DBL_MAX). There the entry's value, about -2, is finite: computing it in an order
// that does not overflow (2 * near * (far / (near - far))) and returning that matrix passes too.
Mat4 perspective(double fovy_degrees, double aspect, double near, double far);
// Orthographic: the box [left, right] x [bottom, top] x [-near, -far] of view space becomes
// the NDC cube; w' = 1. Invalid arguments (left == right, bottom == top, near == far,
// anything not finite) give the zero matrix; so do arguments that would put an infinite
// entry in the matrix (a range so small that 2 / range overflows, e.g. near = 1e-309, far = 0).
// Not tested: a sum that overflows though its entry is finite, e.g. left = 1e308,
// right = 1.5e308, where -(right + left) / (right - left) is -5. The reference computes the
// sum as written, hence infinity, and returns the zero matrix; the finite matrix, computed in an
// order that does not overflow, passes too.
Mat4 orthographic(double left, double right, double bottom, double top, double near, double far);

// ---- TODO 6: from clip space to pixels ----
// The perspective divide and the viewport map (see above): returns (x_pixel, y_pixel, z_ndc).
// Only called with w > 0 (clipping guarantees it).
Vec3 to_screen(Vec4 clip, int width, int height);

// ---- TODO 7: clipping in homogeneous clip space ----
// TODO 7a: Sutherland-Hodgman: the part of the convex polygon `poly` (vertices in order)
// inside all six planes, as a polygon in the same orientation. A new vertex on the edge from
// a to b, where the signed distances to the plane are da >= 0 > db (for the plane x <= w,
// d = w - x), is a + (b - a) * da / (da - db). A vertex on a plane (d = 0) is inside it (the
// planes are closed: a triangle touching the volume at one vertex gives that point, three
// times). Empty (or fewer than 3 vertices) when nothing is inside. Any order of the planes;
// any start vertex. The caller cuts the result into n - 2 triangles of its own vertices: the
// reference fans it, (0, i, i + 1); any other triangulation (a fan from another vertex, a strip)
// covers the same pixels but for rounding at the edges, and the start vertex is free anyway.
// Huge coordinates: a plane distance such as w + x overflows to infinity for coordinates near
// 1e308, and infinity / infinity makes NaN vertices. When some |coordinate| exceeds 2^500, the
// reference scales every vertex by the same power of two first (exact, and the same points in
// projective space), clips, and scales the result back: finite input gives finite output.
std::vector<Vec4> clip_polygon(const std::vector<Vec4>& poly);
// TODO 7b: the part of the segment a-b inside all six planes: false when none is, else true
// with a and b moved onto the planes where they were outside. Huge coordinates as in
// clip_polygon: finite ends give finite ends. That holds for a moved end too: a + (b - a) * t0,
// taken from the outside end, can round past b near 1e308 (t0 = 1 when the segment enters a
// plane exactly at b), and scaled back it overflows. Compute a moved end from the inside end,
// or clamp each of its coordinates between the ends' (the reference clamps).
bool clip_line(Vec4& a, Vec4& b);

// ---- TODO 8: back-face culling, in pixel coordinates (y down), as pinned above ----
bool is_back_facing(Vec3 s0, Vec3 s1, Vec3 s2);

// ---- TODO 9: a cubic Bezier curve by de Casteljau's construction, t in [0, 1] ----
Vec3 bezier(Vec3 p0, Vec3 p1, Vec3 p2, Vec3 p3, double t);

// ---- TODO 10: the painter's algorithm ----
// The order in which to fill triangles given in VIEW space: farthest first, by the mean z of
// each triangle's three vertices (the camera looks down -z, so the most negative mean comes
// first). Returns a permutation of 0 .. n-1; the order of equal means is yours, and so is the
// place of a NaN mean (a vertex not finite; draw_model skips that triangle anyway). Advice, not
// a checkpoint (the fuzzer checks the permutation): std::sort with a < b on NaN keys is
// undefined behaviour and can read past the vector, so give NaN keys a place of their own.
std::vector<int> painter_order(const std::vector<std::array<Vec3, 3>>& view_triangles);

// ---- TODO 11: the pipeline ----
// A model in its own coordinates. triangles: counter-clockwise from outside; edges: the
// wireframe's segments; face_colors: one per triangle (missing ones are white).
struct Model {
    std::vector<Vec3> positions;
    std::vector<std::array<int, 3>> triangles;
    std::vector<std::array<int, 2>> edges;
    std::vector<Color> face_colors;
};

// The stages a scene needs; draw_model runs only these.
struct Needs {
    bool fill = false;       // solid triangles (milestone 2's fill_triangle)
    bool wireframe = false;  // the edges as lines (milestone 1's draw_line), drawn after fills
    bool cull = false;       // skip back faces
    bool clip = false;       // clip against the view volume (a scene inside it may skip this)
    bool painter = false;    // fill far to near (painter_order) instead of in list order
};

// What draw_model did, counted (the checkpoints compare these numbers).
struct Stats {
    long long vertices_transformed = 0;  // positions taken to clip space (each once)
    long long triangles_clipped = 0;     // triangles not entirely inside, sent to clip_polygon
    long long triangles_culled = 0;      // fan triangles skipped as back faces
    long long triangles_filled = 0;      // fan triangles passed to m2::fill_triangle
    long long lines_clipped = 0;         // edges not entirely inside, sent to clip_line
    long long lines_drawn = 0;           // edges passed to m1::draw_line
};

// Draws the model with the camera: clip = projection * view * model_matrix * (p, 1) for every
// position. Fill (if needed), per triangle in list order (or painter_order of the view-space
// triangles): clip if needed and not all three vertices are inside, fan the polygon, take
// each fan triangle to the screen, cull it if needed, else fill it in its face color. Then the
// wireframe (if needed), per edge: clip if needed and not both ends are inside, take the ends
// to the screen (dropping z) and draw the line in `line_color`.
Stats draw_model(Image& img, const Model& model, const Mat4& model_matrix, const Mat4& view,
                 const Mat4& projection, const Needs& needs, Color line_color);

}  // namespace RASTER_FLAVOUR
}  // namespace m3
