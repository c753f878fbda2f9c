// GENERATED from solutions/milestone5_textures_shadows/textures_shadows.cpp by `make skeletons`. Fill in the TODOs; do not edit the rest.
// Milestone 5: textures, specular light and shadows. Fill in the numbered TODOs;
// textures_shadows.h says exactly what each function must do, and README.md walks
// through them in order. Run `make check-m5` in your build folder to see which
// checkpoints pass.
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

double wrap_index(double i, int n, Wrap mode) {
    // TODO 1a: repeat, clamp to edge and mirrored repeat on a whole-number index, in double
    // (std::fmod): converting a huge i to an int would overflow. Mind negative i: std::fmod
    // keeps the sign of i, so -1 mod n comes out as -1, not n - 1.
    return 0;
}

Vec3 fetch(const Level& level, double i, double j, Wrap wrap_u, Wrap wrap_v) {
    // TODO 1b: wrap both indices, then read texels[j * width + i]. Black for an empty level.
    return {};
}

// ---- TODO 2: nearest and bilinear sampling ----

Vec3 sample_nearest(const Level& level, Vec2 uv, Wrap wrap_u, Wrap wrap_v) {
    // TODO 2a: texel units x = u * width, y = v * height; a NaN or infinite one is black.
    return {};
}

Vec3 sample_bilinear(const Level& level, Vec2 uv, Wrap wrap_u, Wrap wrap_v) {
    // TODO 2b: texel centers are at half-integers: shift by 0.5 before taking floor and
    // fraction, then blend the four texels around the point (each index wrapped).
    return {};
}

// ---- TODO 3: mipmaps ----

void build_mipmaps(Texture& texture) {
    // TODO 3: keep level 0, then halve (max(1, floor(n / 2)) per side) and average 2x2 blocks
    // until the level is 1x1. Mind odd sizes: the last row or column is dropped, and a side
    // of 1 texel clamps its index. Set texture.mipmapped.
}

// ---- TODO 4: level of detail and filtering ----

UvDerivatives uv_derivatives(const std::array<Vec3, 3>& screen, const std::array<double, 3>& w,
                             const std::array<Vec2, 3>& uv, double x, double y) {
    // TODO 4a: the planes A = sum l_i u_i / w_i (and for v) and B = sum l_i / w_i are affine
    // in x and y: find their slopes from the screen weights' slopes (edge functions divided by
    // twice the area), then the quotient rule (A_x B - A B_x) / B^2.
    return {};
}

double level_of_detail(const UvDerivatives& d, int width, int height) {
    // TODO 4b: rho from the derivatives in TEXELS (times width and height), lambda = log2(rho).
    return 0;
}

Vec3 sample(Texture& texture, Vec2 uv, double lambda, Filter filter, long long* mipmap_builds) {
    // TODO 4c: kNearest and kBilinear read level 0; the mip filters magnify with bilinear on
    // level 0 when lambda <= 0 (or NaN), else build the pyramid if there is none (count it;
    // free where only level 0 is read, see the header), clamp lambda to the last level and read
    // one level (kNearestMip) or blend two.
    return {};
}

// ---- TODO 6: Blinn-Phong ----

Vec3 blinn_phong(Vec3 base, Vec3 specular, double shininess, Vec3 normal, Vec3 to_eye, Vec3 to_light, Vec3 intensity) {
    // TODO 6: normalize N, V and L; nothing at all when dot(N, L) <= 0; else the diffuse
    // base * c * I plus specular * max(0, dot(N, H))^shininess * I with H = normalize(L + V).
    return {};
}

// ---- TODO 7: tangent-space normal maps ----

TangentFrame tangent_frame(Vec3 p0, Vec3 p1, Vec3 p2, Vec2 uv0, Vec2 uv1, Vec2 uv2) {
    // TODO 7a: solve [e1 e2] = [T B] [[du1 du2] [dv1 dv2]] for T and B (Cramer's rule with the
    // determinant r); no frame when r is 0 or the result is not finite.
    TangentFrame frame;
    return frame;
}

Vec3 perturb_normal(const TangentFrame& frame, Vec3 n, Vec3 texel) {
    // TODO 7b: Gram-Schmidt T against n, B' = cross(n, T') (flipped to agree with B), the
    // texel from [0, 255] to [-1, 1], and the mapped vector to world space, normalized.
    return {};
}

// ---- TODO 8: shadow mapping ----

Mat4 light_view_projection(Vec3 direction, const ShadowSettings& settings) {
    // TODO 8a: the eye 2r behind the center against the light's direction, looking at the
    // center, and an orthographic box of radius r from depth r to 3r.
    return Mat4{};
}

double shadow_factor(const ShadowMap& map, Vec3 p, Vec3 n, Vec3 direction, const ShadowSettings& settings) {
    // TODO 8b: p to the map's texel and depth d (m3::to_screen of map.light); the bias in world
    // units to depth units (divide by 2r); compare with the stored depth (the float of the key)
    // at one texel, or count the lit ones of the 3x3 around it with PCF.
    return 1;
}

// ---- TODO 5: the textured, lit, shadowed triangle ----

void fill_triangle(Frame& frame, const std::array<ScreenVertex, 3>& v, const FillState& state, Stats& stats) {
    // TODO 5: milestone 4's fill_triangle with a new fragment: depth pre-test first (a hidden
    // fragment costs nothing), then perspective-correct uv, normal and world position, the
    // base color (color or sample(), lambda only for mip filters), and for lit materials the
    // normal map (reading it where state.tangent is not valid is free), ambient and every light
    // (blinn_phong, shadow_factor); then to_color and the depth test. Count what you do in stats.
}

// ---- TODO 9: the pipeline ----

Stats draw_scene(Frame& frame, const std::vector<Object>& objects, const Camera& camera, const Lighting& lighting,
                 const ShadowSettings& shadow_settings) {
    // TODO 9: the shadow pass for each light that casts shadows (and only those), then every
    // object: positions to clip and world space, normals (lit materials only), and per mesh
    // triangle the tangent frame (with a normal map), clipping, the fan and fill_triangle.
    Stats stats;
    return stats;
}

}  // namespace RASTER_FLAVOUR
}  // namespace m5
