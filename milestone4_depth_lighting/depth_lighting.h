// Milestone 4: depth and lighting. The functions you implement in depth_lighting.cpp.
//
// Conventions. Each one is a TESTED rule: a checkpoint draws a scene where breaking it changes
// pixels or numbers. "Advice" marks how the reference does something; the checkpoints cannot
// see it, so another correct way passes too.
//
//  * Everything of milestones 1 to 3 holds: pixel centers at (x + 0.5, y + 0.5), row 0 at the
//    top, milestone 2's 1/16-pixel snapping, exact integer edge functions and TOP-LEFT fill
//    rule (m2::snap, m2::edge, m2::bounding_box are yours to call), milestone 3's matrices
//    (m[row][col], column vectors), right-handed world, camera looking down -z, OpenGL clip
//    space and NDC (z_ndc = -1 at the near plane, +1 at the far plane), viewport with y down,
//    and back faces (signed screen area >= 0 in pixel coordinates).
//
//  * Depth. The depth of a fragment is its WINDOW DEPTH d = (z_ndc + 1) / 2, in [0, 1], 0 at
//    the near plane. z_ndc is an affine function of the screen position, so d is interpolated
//    with the SCREEN-SPACE barycentric weights (no perspective correction), in double. The
//    buffer does not store d itself but a 32-bit KEY of it in one of four formats
//    (depth_key); SMALLER KEYS ARE NEARER in every format, and kClearKey means "nothing drawn".
//
//  * The depth test (tested rule, order-independent): a fragment with key k and color c
//    replaces the stored (key s, color t) when k < s, or when k == s, k != kClearKey and c is
//    BRIGHTER than t: larger r, or equal r and larger g, or equal r, g and larger b. Because
//    this is a strict total order, the final picture does not depend on the order in which
//    triangles are drawn, not even for exactly coplanar ones. A fragment whose key is
//    kClearKey never passes. The test comes BEFORE the write: a fragment that fails writes
//    neither color nor depth.
//
//  * Interpolation. The screen-space barycentric weights l0, l1, l2 are milestone 2's
//    (edge values over twice the area, summing to 1). An attribute a (color, normal, world
//    position, uv) is interpolated PERSPECTIVE-CORRECTLY: with the clip-space w of each
//    vertex, weights p_i = (l_i / w_i) / (l0 / w0 + l1 / w1 + l2 / w2), and a = sum p_i a_i.
//    Needs::perspective_correct = false asks for plain screen-space weights (p_i = l_i): the
//    lesson's comparison, tested as well.
//
//  * Normals and lighting happen in WORLD space. A normal goes from model to world space by
//    the normal matrix (the inverse transpose of the model matrix's upper-left 3x3) and is
//    then normalized. A normal of length 0 (or not finite) stays the zero vector, and lights
//    nothing: such a surface shows its ambient color, never NaN. (raster::normalize gives zero
//    for a zero or NaN length, but NaN for a vector with an infinite component, inf / inf: so
//    check the length.)
//
//  * Lambert. For base color B (levels 0..255), ambient A and lights with intensity I_k (all
//    per channel, 1 = full strength) and unit directions L_k from the surface TOWARD light k,
//    a channel's level is B * (A + sum_k I_k * max(0, dot(N, L_k))). A DIRECTIONAL light is
//    given by the direction its rays TRAVEL, so L = -normalize(direction); a POINT light by
//    its position, so L = normalize(light - position), with no fall-off with distance.
//    Levels are clamped to [0, 255] and rounded to nearest (to_color): too much light is
//    white, never wrapped around.
//
//  * Shading modes (Needs::shading):
//     - kFaceColor: each triangle in its face color, unlit.
//     - kVertexColor: the vertex colors interpolated, unlit.
//     - kFlat: lit once per triangle with its face normal (face_normal of the world-space
//       positions) at the centroid of its three world-space positions; base: the material.
//     - kGouraud: every position lit once per draw with its vertex normal; the lit levels
//       (unclamped) interpolated, to_color per fragment. (No checkpoint lights a Gouraud
//       vertex above 255, so clamping at the vertices passes too.)
//     - kPerPixel: the normal interpolated, normalized per fragment, and lit there; the world
//       position is interpolated too only when a point light needs it.
//     - kChecker: checker(uv) of the interpolated uv, unlit (the perspective test).
//     - kDepthView / kNormalView: the debug views depth_gray(z_ndc) and normal_color(normal).
//    Vertex normals come from Mesh::normals when the mesh has them, else from
//    vertex_normals() of the model-space positions, computed only in a mode that uses them.
//
//  * Only what a scene needs (tested through Stats and the frame): the depth buffer is
//    allocated only when Needs::depth_test, vertex normals are computed only for kGouraud,
//    kPerPixel and kNormalView, and each fragment interpolates only the attributes its mode
//    reads: 3 values for vertex colors (kVertexColor, kGouraud), 2 for uv (kChecker), 3 for
//    the normal (kPerPixel, kNormalView) plus 3 for the world position (kPerPixel with a
//    point light), none otherwise. Depth is not counted as an attribute.
//
//  * Precision. Everything is double until a key or a color is stored. Pictures allow pixels
//    next to an edge (and next to a change of shade) to differ a little, and lit pixels by up
//    to 3 levels per channel; shade() values are compared within 1e-9 relative and debug colors
//    within 1 level; depth_key of the float formats within 1 unit in the last place.
//    Nothing is timed.
//
//  * Bad input never crashes, hangs or writes outside the image: a vertex with NaN or
//    infinite coordinates drops its triangle; zero-area and needle triangles draw what the
//    fill rule says (often nothing) without dividing by zero; vertices behind the camera are
//    clipped away in clip space (milestone 3), as are vertices beyond the far plane. Extreme
//    values elsewhere: a w so small that 1 / w overflows (a near plane of 1e-320) falls back
//    to the screen weights (fill_triangle), a uv of NaN or infinity is dark in checker(), an
//    infinite light never meets a zero dot product (shade). The project fuzzes the reference
//    with all of this under AddressSanitizer and UndefinedBehaviorSanitizer; `make fuzz-m4
//    FUZZ_STUDENT=1` in your build folder does the same to your code (it needs clang).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "raster/color.h"
#include "raster/flavour.h"
#include "raster/image.h"
#include "raster/vec.h"
#include "transforms.h"

namespace m4 {
inline namespace RASTER_FLAVOUR {

using m3::Mat4;
using raster::Color;
using raster::Image;
using raster::Vec2;
using raster::Vec3;
using raster::Vec4;

// ---- TODO 1: depth keys ----
// The four formats the lesson compares. In each, the key of the near plane is smaller than
// the key of the far plane.
enum class DepthFormat {
    kFloatZ,     // float(d), stored as its bit pattern (positive floats order like their bits)
    kReversedZ,  // float((1 - z_ndc) / 2), computed in double: 1 at near, 0 at far. Key:
                 // kReversedBase - bits, so larger values (nearer) give smaller keys
    kFixed24,    // llround(d * (2^24 - 1)): a 24-bit integer, as many GPUs store depth
    kInverseW,   // float(1 / w): 1/near at near, 1/far at far. Key: kReversedBase - bits
};
inline constexpr std::uint32_t kClearKey = 0xFFFFFFFFu;
inline constexpr std::uint32_t kReversedBase = 0x7F800000u;  // the bits of +infinity
inline constexpr std::uint32_t kFixed24Max = (1u << 24) - 1;

// The key of a fragment at z_ndc with clip-space w. d = (z_ndc + 1) / 2 is first clamped to
// [0, 1] (and (1 - z_ndc) / 2 likewise), so a fragment a rounding error outside the view
// volume gets the key of the near or the far plane. kClearKey when z_ndc is NaN, or, for
// kInverseW, when w is not > 0 or not finite. Float bits: std::bit_cast<std::uint32_t>(f).
std::uint32_t depth_key(DepthFormat format, double z_ndc, double w);

// ---- TODO 2: the depth buffer ----
// The depth test with the order-independent tie rule (see above).
bool depth_passes(std::uint32_t key, Color color, std::uint32_t stored_key, Color stored_color);

// A frame: the color image and, for a scene that depth-tests, one key per pixel (row-major,
// index y * width + x).
struct Frame {
    Image color;
    DepthFormat format = DepthFormat::kFloatZ;
    std::vector<std::uint32_t> depth;  // empty (capacity 0) unless the scene depth-tests
};

// Starts a frame: fills frame.color with `background` (keeping the Image object and its size:
// do not assign a new Image), sets the format, and gives frame.depth width * height keys of
// kClearKey when depth_test, or releases it entirely (size AND capacity 0) when not.
void clear_frame(Frame& frame, Color background, bool depth_test, DepthFormat format);

// ---- TODO 3: perspective-correct weights ----
// p_i = (l_i / w_i) / sum_j (l_j / w_j). When that sum is not > 0 or not finite, returns the
// screen weights unchanged.
std::array<double, 3> perspective_weights(const std::array<double, 3>& screen, const std::array<double, 3>& w);

// ---- TODO 4: normals ----
// normalize(cross(p1 - p0, p2 - p0)): counter-clockwise triangles face their normal. The zero
// vector when the cross product has length 0 or is not finite (degenerate triangles).
Vec3 face_normal(Vec3 p0, Vec3 p1, Vec3 p2);
// Area-weighted vertex normals: for each position, the sum of cross(p1 - p0, p2 - p0) of every
// triangle using it (that cross product's length is twice the area, so big faces weigh more),
// normalized; zero where the sum is zero or not finite. Triangles with an index out of range
// are skipped. Returns one normal per position.
std::vector<Vec3> vertex_normals(const std::vector<Vec3>& positions, const std::vector<std::array<int, 3>>& triangles);
// The normal matrix: the inverse transpose of the model matrix's upper-left 3x3, as a Mat4
// whose last row and column are (0, 0, 0, 1). The zero matrix when that 3x3 is singular
// (m3::inverse says so). Use it with m3::transform_direction, then normalize.
Mat4 normal_matrix(const Mat4& model);

// ---- TODO 5: lighting ----
struct Light {
    enum class Kind { kDirectional, kPoint };
    Kind kind = Kind::kDirectional;
    Vec3 vector{0, 0, -1};  // directional: the direction the rays travel; point: the position
    Vec3 intensity{1, 1, 1};
};
struct Lighting {
    Vec3 ambient{0.1, 0.1, 0.1};
    std::vector<Light> lights;
};
// Lambert with ambient, in levels, unclamped and unrounded (see above). `normal` need not
// have length 1 (normalize it; zero stays zero). A normal whose length is not finite, e.g.
// (inf, 0, 0), counts as the zero normal, as in normal_color: ambient only (raster::normalize
// would make it NaN: inf / inf). A zero light vector (a directional light of
// direction 0, a point light at `position`) lights nothing. A light with max(0, dot(N, L)) = 0
// adds nothing at all, whatever its intensity: a zero normal under an infinite light gives
// the ambient color, never NaN (infinity * 0).
Vec3 shade(const Lighting& lighting, Color base, Vec3 position, Vec3 normal);
// Each channel clamped to [0, 255] and rounded to nearest; NaN gives 0.
Color to_color(Vec3 levels);

// ---- TODO 6: debug views ----
// Depth as gray: level round(255 * (1 - d)) with d = (z_ndc + 1) / 2 clamped to [0, 1]: near
// is white, far is black.
Color depth_gray(double z_ndc);
// A normal as a color: each channel round(255 * (n + 1) / 2) of the NORMALIZED normal
// (x -> red, y -> green, z -> blue); the zero normal gives (128, 128, 128), and so does a normal
// whose length is not finite: (inf, 0, 0), and (1e200, -1e200, 0), whose length overflows (for
// that one the color of its direction, found by scaling it down first, passes too).
Color normal_color(Vec3 normal);

// The checkerboard of the perspective checkpoints (given): kCheckerCells cells along u and
// along v in [0, 1]; white where floor(u * cells) + floor(v * cells) is even, else dark.
// Any uv is fine: the parity is taken in double (no conversion to an integer type can
// overflow), a u or v whose u * cells is NaN or infinite gives the dark color, and beyond
// 2^53 every double is an even integer.
inline constexpr int kCheckerCells = 8;
inline Color checker(Vec2 uv) {
    const double u = std::floor(uv.x * kCheckerCells), v = std::floor(uv.y * kCheckerCells);
    if (!std::isfinite(u) || !std::isfinite(v)) return Color{32, 32, 32};
    const bool even = std::fabs(std::fmod(u, 2.0)) == std::fabs(std::fmod(v, 2.0));  // exact
    return even ? Color{255, 255, 255} : Color{32, 32, 32};
}

// ---- TODO 7: clipping with attributes ----
// A vertex in clip space with everything a fragment may interpolate. Colors are levels
// (0..255, unclamped doubles); normal and world are in world space.
struct ClipVertex {
    Vec4 clip;
    Vec3 color;
    Vec3 normal;
    Vec3 world;
    Vec2 uv;
};
// a + (b - a) * t for the position AND every attribute.
ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, double t);
// Milestone 3's clip_polygon for a triangle whose vertices carry attributes: the part inside
// the six planes -w <= x, y, z <= w, as a polygon in the same orientation (the reference fans
// it from vertex 0). A vertex on a plane (d = 0) is inside it (the planes are closed; where its
// neighbour is outside, the new vertex on the edge between them is that same point, so the
// polygon holds it twice, and the checkpoints count it). A new vertex where the edge a-b
// leaves a plane (da >= 0 > db) is lerp(a, b, da / (da - db)), or lerp(b, a, db / (db - da))
// when a is the outside end (interpolating from the inside end gives two triangles sharing an
// edge the very same new vertex). Then every vertex whose w is not > 0 is dropped: exactly, a
// vertex inside has w >= near > 0, but rounding between two huge vertices can cancel every
// digit and leave (0, 0, 0, 0), which lies on all six planes.
// Empty when fewer than 3 vertices remain. Any order of the planes; any start vertex.
std::vector<ClipVertex> clip_triangle(const std::array<ClipVertex, 3>& triangle);

// ---- TODO 8: the triangle with depth and attributes ----
// A vertex on the screen: x, y in pixels and z_ndc; w is its clip-space w (1 / w is what
// perspective correction and kInverseW use); the attributes as in ClipVertex.
struct ScreenVertex {
    Vec3 screen;
    double w = 1;
    Vec3 color;
    Vec3 normal;
    Vec3 world;
    Vec2 uv;
};

enum class Shading { kFaceColor, kVertexColor, kFlat, kGouraud, kPerPixel, kChecker, kDepthView, kNormalView };

// What a scene needs; draw_mesh runs and allocates only this.
struct Needs {
    bool depth_test = false;
    DepthFormat depth_format = DepthFormat::kFloatZ;
    Shading shading = Shading::kFaceColor;
    bool perspective_correct = true;  // false: screen-space weights (the lesson's comparison)
    bool cull = false;                // skip back faces
};

// What was done, counted (the checkpoints compare these with the reference's counts).
struct Stats {
    long long triangles_clipped = 0;  // mesh triangles not entirely inside, sent to clip_triangle
    long long triangles_culled = 0;   // fan triangles skipped as back faces (area >= 0: zero area too)
    long long triangles_drawn = 0;    // fan triangles passed to fill_triangle
    long long fragments = 0;          // pixel centers covered (inside the image)
    long long depth_tests = 0;        // fragments tested against the depth buffer
    long long depth_writes = 0;       // of those, the ones that passed and were written
    long long vertex_normals = 0;     // normals computed by vertex_normals() (one per position)
    long long shade_calls = 0;        // calls of shade()
    long long interpolated = 0;       // attribute values interpolated, summed over fragments
};

// What fill_triangle needs besides the vertices.
struct FillState {
    Needs needs;
    const Lighting* lighting = nullptr;  // kPerPixel
    Color material;                      // kPerPixel's base color
    Color flat_color;                    // kFaceColor and kFlat: the triangle's one color
    bool point_light = false;            // kPerPixel: some light is a point light (interpolate world)
};

// Fills one triangle (both windings, milestone 2's snapping and top-left fill rule: a center on
// an edge two triangles share is drawn by exactly one of them) into the frame.
// Per covered pixel center: the screen weights l; d from them; with depth_test, the key
// depth_key(format, z_ndc, w) (format: frame.format, which clear_frame set from needs.depth_format,
// so the two agree) with the pixel's w = 1 / sum(l_i / w_i) and the depth test; the color of its mode; then
// color and key written. A fragment's attributes are interpolated (and a kPerPixel fragment
// lit) only when it gets a color: always without a depth test, and with one only when its key
// is <= the stored key (a hidden fragment costs nothing; a tie needs the color to decide).
// Counts fragments, depth tests and writes, shade() calls and interpolated values in `stats`.
// Extreme w: where sum(l_i / w_i) is not > 0 or not finite (a w of 0, NaN, or so small that
// 1 / w overflows, e.g. a vertex on a near plane of 1e-320), the fragment does what
// perspective_weights does: its weights are the screen weights l, and its w is then
// sum(l_i * w_i) (the same w they interpolate). So a tiny near plane draws like a small one,
// and no NaN reaches an attribute through the weights.
void fill_triangle(Frame& frame, const std::array<ScreenVertex, 3>& v, const FillState& state, Stats& stats);

// ---- TODO 9: the pipeline ----
// A model in its own coordinates (triangles counter-clockwise from outside). Per-position
// arrays may be empty when no mode reads them; a missing face color is white, a missing
// vertex color or uv is zero.
struct Mesh {
    std::vector<Vec3> positions;
    std::vector<std::array<int, 3>> triangles;
    std::vector<Color> face_colors;    // kFaceColor
    std::vector<Color> vertex_colors;  // kVertexColor, per position
    std::vector<Vec2> uvs;             // kChecker, per position
    std::vector<Vec3> normals;         // per position, model space; empty (or any other
                                       // size than positions): vertex_normals()
};

// Draws the mesh into the frame (already cleared by clear_frame for this scene's needs):
// 1. every position once to clip space (projection * view * model) and, for modes that light
//    or show normals, to world space with its normal (normal_matrix, normalized); kGouraud
//    lights every position once here (material as base);
// 2. per triangle in list order (skipping any with an index out of range or a non-finite clip
//    coordinate): clip_triangle unless all three vertices are inside (on or within all six
//    planes; the clip-space origin (0, 0, 0, 0) lies on every one, and a triangle using it is
//    counted as drawn or culled but covers no pixel, its x / w being NaN); kFlat lights the
//    triangle once, when the first of its fan triangles that survives culling is drawn; fan (0, i, i + 1); each fan
//    triangle to the screen (m3::to_screen), culled if needs.cull and back-facing, else
//    fill_triangle. The fan is the reference's choice: any triangulation of the convex
//    polygon into n - 2 triangles of its own vertices (a fan from another vertex, a strip) is
//    as right. It covers the same pixels but for rounding at the edges, kFlat's one color is
//    the mesh triangle's, and the checkpoints judge nothing else it could change (as for
//    clip_triangle's start vertex, which moves the fan's apex).
Stats draw_mesh(Frame& frame, const Mesh& mesh, const Mat4& model, const Mat4& view, const Mat4& projection,
                const Lighting& lighting, Color material, const Needs& needs);

}  // namespace RASTER_FLAVOUR
}  // namespace m4
