// GENERATED from solutions/milestone4_depth_lighting/depth_lighting.cpp by `make skeletons`. Fill in the TODOs; do not edit the rest.
// Milestone 4: depth and lighting. Fill in the numbered TODOs; depth_lighting.h says
// exactly what each function must do, and README.md walks through them in order.
// Run `make check-m4` in your build folder to see which checkpoints pass.
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
    return 0;
}

// ---- TODO 2: the depth buffer ----

bool depth_passes(std::uint32_t key, Color color, std::uint32_t stored_key, Color stored_color) {
    // TODO 2: nearer wins; an exact tie goes to the brighter color (r, then g, then b).
    return true;
}

void clear_frame(Frame& frame, Color background, bool depth_test, DepthFormat format) {
    // TODO 2: fill the color image; allocate and clear the keys only when the scene
    // depth-tests, and otherwise free them (a vector keeps its memory after clear()).
}

// ---- TODO 3: perspective-correct weights ----

std::array<double, 3> perspective_weights(const std::array<double, 3>& screen, const std::array<double, 3>& w) {
    // TODO 3: divide each weight by its vertex's w, then normalize so they sum to 1.
    return screen;
}

// ---- TODO 4: normals ----

Vec3 face_normal(Vec3 p0, Vec3 p1, Vec3 p2) {
    // TODO 4a: the normalized cross product of two edges; zero for a degenerate triangle.
    return {};
}

std::vector<Vec3> vertex_normals(const std::vector<Vec3>& positions, const std::vector<std::array<int, 3>>& triangles) {
    // TODO 4b: add each triangle's UNnormalized cross product to its three vertices, then
    // normalize every sum.
    std::vector<Vec3> normals(positions.size());
    return normals;
}

Mat4 normal_matrix(const Mat4& model) {
    // TODO 4c: copy the 3x3 into an identity Mat4, invert it with m3::inverse, transpose.
    Mat4 r;
    return r;
}

// ---- TODO 5: lighting ----

Vec3 shade(const Lighting& lighting, Color base, Vec3 position, Vec3 normal) {
    // TODO 5a: sum the ambient and every light's intensity * max(0, N . L) per channel, then
    // multiply by the base color. Mind the direction of L: from the surface TOWARD the light.
    Vec3 levels;
    return levels;
}

Color to_color(Vec3 levels) {
    // TODO 5b: clamp each channel to [0, 255] BEFORE converting to an 8-bit channel.
    return {};
}

// ---- TODO 6: debug views ----

Color depth_gray(double z_ndc) {
    return {};
}

Color normal_color(Vec3 normal) {
    return {};
}

// ---- TODO 7: clipping with attributes ----

ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, double t) {
    // TODO 7a: every member moves the same fraction t of the way from a to b.
    ClipVertex r;
    return r;
}

std::vector<ClipVertex> clip_triangle(const std::array<ClipVertex, 3>& triangle) {
    // TODO 7b: milestone 3's Sutherland-Hodgman loop over the six planes, with lerp() making
    // the new vertices.
    std::vector<ClipVertex> out;
    return out;
}

// ---- TODO 8: the triangle with depth and attributes ----

void fill_triangle(Frame& frame, const std::array<ScreenVertex, 3>& v, const FillState& state, Stats& stats) {
    // TODO 8: milestone 2's fill_triangle_gradient, extended: snap, orient (swapping the whole
    // vertex), bounding box, and per covered pixel center the weights, the depth test, the
    // color of the mode and the writes. Advice: step the three integer edge values from pixel
    // to pixel instead of recomputing them (an addition each).
}

// ---- TODO 9: the pipeline ----

Stats draw_mesh(Frame& frame, const Mesh& mesh, const Mat4& model, const Mat4& view, const Mat4& projection,
                const Lighting& lighting, Color material, const Needs& needs) {
    // TODO 9: follow the two steps of depth_lighting.h, computing only what needs.shading reads.
    Stats stats;
    return stats;
}

}  // namespace RASTER_FLAVOUR
}  // namespace m4
