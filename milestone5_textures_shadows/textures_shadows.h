// Milestone 5: textures, specular light and shadows. The functions you implement in
// textures_shadows.cpp.
//
// Conventions. Each one is a TESTED rule: a checkpoint draws a scene or computes numbers where
// breaking it shows beyond the tolerance. "Advice" marks how the reference does something; the
// checkpoints cannot see it, so another correct way passes too.
//
//  * Everything of milestones 1 to 4 holds: pixel centers at (x + 0.5, y + 0.5), row 0 at the
//    top, milestone 2's snapping and top-left fill rule, milestone 3's matrices and clip space,
//    milestone 4's window depth, float-Z keys (DepthFormat::kFloatZ, the only format here), its
//    depth test with the brighter-color tie rule, perspective-correct weights, normal matrix and
//    clipping with attributes (m4::clip_triangle). Your code here calls milestone 4's functions.
//
//  * Texture coordinates (uv) are double, always: u runs left to right across the texture,
//    v from the TOP row down (v = 0 is the top edge of the image, like every image in this
//    course). A float has 24 bits: at u = 1e7 it cannot hold the fraction at all (its spacing
//    there is 1), so a float texture coordinate shows one texel per whole unit of u. Tested with
//    uv near 1e7, where double still resolves 1/64 of a texel.
//
//  * Texel centers are at HALF-INTEGERS: texel (i, j) of a level w texels wide and h high covers
//    u in [i / w, (i + 1) / w) and v in [j / h, (j + 1) / h); its center is at
//    ((i + 0.5) / w, (j + 0.5) / h). In texel units a point is at x = u * w, y = v * h.
//
//  * Texel values are LEVELS: doubles in [0, 255] per channel (Vec3 r, g, b), never rounded
//    until the final to_color. A base level holds whole numbers (from an image); mipmap levels
//    and filtered samples hold fractions.
//
//  * Wrapping is done on WHOLE-NUMBER texel indices (doubles, so any finite index works, 1e300
//    included): repeat i mod n in [0, n) (so -1 is n - 1: a mod that truncates toward zero is
//    wrong for negative coordinates), clamp to edge min(max(i, 0), n - 1), mirrored repeat
//    m = i mod 2n, then m if m < n else 2n - 1 - m. u and v wrap independently.
//
//  * A sample whose u or v is NaN or infinite (or whose texel coordinate u * w overflows) is
//    BLACK (0, 0, 0): a defined answer, never a crash or an index out of range.
//
//  * Mipmaps. Level 0 is the texture. Level k + 1 is max(1, floor(w / 2)) by max(1, floor(h / 2))
//    texels, and its texel (i, j) is the plain average of level k's texels (2i, 2j), (2i + 1, 2j),
//    (2i, 2j + 1), (2i + 1, 2j + 1), an index past level k's last one (only when that side of
//    level k is 1 texel) clamped to it. So an odd last row or column is DROPPED (a 5-wide level
//    makes a 2-wide one from its texels 0 to 3), and non-power-of-two sizes are allowed. The
//    pyramid ends with the 1x1 level. The averages are exact in double: building each level from
//    the one before it (the reference) or each texel straight from the base texels it covers
//    gives the same numbers, and both pass.
//
//  * Level of detail (ANALYTIC, pinned): this rasterizer shades one pixel at a time, not 2x2
//    quads, so the derivatives come from the triangle itself. uv is the perspective-correct
//    ratio u(x, y) = A(x, y) / B(x, y) with the planes A = sum l_i u_i / w_i and B = sum l_i / w_i
//    (l_i the screen weights, affine in x and y); its exact derivative is
//    du/dx = (A_x B - A B_x) / B^2, and likewise for dy and for v. At the pixel center, with the
//    base level W x H: rho = max(sqrt((W du/dx)^2 + (H dv/dx)^2), sqrt((W du/dy)^2 + (H dv/dy)^2)),
//    lambda = log2(rho) (OpenGL's rho). Quads would give finite differences, which differ by a
//    second-order term that matters exactly where lambda crosses a level: the checkpoints ask
//    for the analytic value, within 1e-6 relative on the numbers.
//
//  * Filters. kNearest and kBilinear read level 0 only. kNearestMip and kTrilinear magnify with
//    bilinear on level 0 when lambda <= 0 (or NaN); else lambda is clamped to [0, L - 1] with L
//    levels; kNearestMip reads level floor(lambda + 0.5) bilinearly; kTrilinear blends the
//    bilinear samples of levels floor(lambda) and floor(lambda) + 1 (the last one when there is
//    no next) by the fraction of lambda. Nearest: texel (floor(x), floor(y)). Bilinear: x' = x - 0.5,
//    i = floor(x'), a = x' - i (and j, b for y); (1 - a)(1 - b) t(i, j) + a (1 - b) t(i + 1, j)
//    + (1 - a) b t(i, j + 1) + a b t(i + 1, j + 1), each index wrapped. Two lerps, four weights
//    or any other order of the same sums pass (they differ by rounding only).
//
//  * Blinn-Phong, per light, in WORLD space, for unit N (surface normal), V (toward the eye) and
//    L (toward the light, -direction for a directional light): with c = dot(N, L), a light adds
//    NOTHING when c <= 0 (no diffuse and no specular: a light behind the surface does not shine
//    on it); else base * c * I + specular * s * I, with H = normalize(L + V) and
//    s = max(0, dot(N, H))^shininess. base and specular are levels; I the light's intensity per
//    channel. A pixel's level is base * ambient + sum over lights of factor_k * (that), where
//    factor_k is the light's shadow factor (1 = lit). Clamped and rounded by m4::to_color.
//
//  * Normal maps (tangent space). A normal-map texel t (levels) is the vector 2 t / 255 - 1 in
//    [-1, 1] per channel: red along the tangent T (+u), green along the bitangent B (+v, DOWN the
//    texture image), blue along the surface normal N. T and B come per mesh triangle from its
//    world positions and uv (tangent_frame), are made orthonormal against the fragment's N
//    (Gram-Schmidt) and the mapped vector goes to world space as x T' + y B' + z N, normalized.
//    A triangle whose three uv make no frame (zero or non-finite determinant, e.g. all equal)
//    keeps N: no tangent frame, no perturbation.
//
//  * Shadows (one map per directional light that casts shadows). The light looks along its
//    direction at a box of radius r around `center` (ShadowSettings): light_view_projection(),
//    orthographic, depth over [r, 3r] from the light's eye. The depth pass draws every object
//    that casts shadows into a resolution x resolution float-Z depth buffer with milestone 4's
//    rules (m4::draw_mesh, depth only, both faces). A world point p maps through m3::to_screen
//    of that matrix to a texel column floor(x), row floor(y) and a depth d = (z_ndc + 1) / 2.
//    It is in shadow at a texel when d - bias / (2r) > the stored depth, strictly (a tie is lit;
//    r = map.radius, the settings' radius the map was drawn with: d spans the box's 2r world
//    units), with the bias in world units bias = constant + slope * min(tan(theta), 10),
//    tan(theta) = sqrt(1 - c^2) / c for c = dot(N, L) > 0. A texel outside the map, or never
//    drawn (kClearKey), is lit. Without PCF the factor is 1 (lit) or 0; with PCF it is the lit
//    fraction of the 3x3 texels around that one (any order of the nine). The biased depth may
//    be compared in double or rounded to a float first (as comparing float-Z keys would): that
//    moves the comparison by half a float step, far less than any bias, and both pass.
//
//  * Only what a scene needs (tested through Stats): untextured materials never sample, a
//    mipmap pyramid is built (once per texture) when a mip filter reads a level above 0, and
//    never for lambda <= 0 (or NaN) or for kNearest and kBilinear, the level of detail is
//    computed only for mip filters, a normal map is read (and a tangent frame made) only where a
//    LIT material has one (an unlit one uses no normal), the shadow pass runs (and its map is
//    allocated) only for a light that casts shadows, and shadows are looked up only where c > 0.
//    A fragment hidden behind a nearer one is not shaded (as in milestone 4). Four counts are
//    LEFT FREE, and both answers pass each:
//    (a) where lambda > 0 but only level 0 is read (a 1x1 texture, whose pyramid is itself, or
//    kNearestMip with lambda < 0.5), building the pyramid (and counting it) or not;
//    (b) where a triangle's tangent frame is not valid, reading the normal map (and counting it)
//    or not: perturb_normal does not use the texel there;
//    (c) where uv is NaN or infinite, building the pyramid or not: lambda there comes out NaN
//    or infinite depending only on how rho is written (std::max's argument order, std::hypot),
//    and the sample is black either way;
//    (d) for a mip-filtered material whose texture is 1x1, computing the level of detail (and
//    counting it) or not: every lambda reads its only level.
//    None changes a pixel, and each has two natural codes (test lambda > 0, or the level to
//    read; read the map and let perturb_normal ignore it, or skip the read), so the
//    checkpoints accept both.
//
//  * Precision. Everything is double until a key or a color is stored. Pictures allow pixels
//    next to an edge, a shadow boundary or a change of mip level to differ a little, and others
//    by up to 3 levels; numbers are compared within 1e-9 relative (1e-6 for derivatives and
//    lambda). Nothing is timed.
//
//  * Bad input never crashes, hangs or writes outside the image: NaN and infinite uv sample
//    black; a texture of size 0 samples black; huge uv wrap exactly; a light parallel to a
//    surface, a light behind everything, a degenerate uv mapping and extreme near/far ratios
//    draw what the rules above say.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "depth_lighting.h"
#include "raster/color.h"
#include "raster/flavour.h"
#include "raster/image.h"
#include "raster/vec.h"
#include "transforms.h"

namespace m5 {
inline namespace RASTER_FLAVOUR {

using m3::Mat4;
using m4::Frame;
using m4::ScreenVertex;
using raster::Color;
using raster::Image;
using raster::Vec2;
using raster::Vec3;
using raster::Vec4;

// ---- TODO 1: textures and wrapping ----
enum class Wrap { kRepeat, kClampToEdge, kMirroredRepeat };

// One level of a texture: width x height texels, row-major (index j * width + i), row 0 at the
// top, in levels (see above).
struct Level {
    int width = 0, height = 0;
    std::vector<Vec3> texels;
};

// A texture: levels[0] is the image; levels 1.. exist only once build_mipmaps has run.
struct Texture {
    std::vector<Level> levels;
    Wrap wrap_u = Wrap::kRepeat, wrap_v = Wrap::kRepeat;
    bool mipmapped = false;  // set by build_mipmaps
};

// Given: a texture from an image (each pixel's r, g, b as levels), no mipmaps yet.
inline Texture make_texture(const Image& image, Wrap wrap_u = Wrap::kRepeat, Wrap wrap_v = Wrap::kRepeat) {
    Texture t;
    t.wrap_u = wrap_u;
    t.wrap_v = wrap_v;
    Level base;
    base.width = image.width();
    base.height = image.height();
    base.texels.reserve(static_cast<std::size_t>(base.width) * static_cast<std::size_t>(base.height));
    for (int y = 0; y < base.height; ++y)
        for (int x = 0; x < base.width; ++x) {
            const Color c = image.at(x, y);
            base.texels.push_back(Vec3{double(c.r), double(c.g), double(c.b)});
        }
    t.levels.push_back(std::move(base));
    return t;
}

// The whole-number index i (a finite double) wrapped into [0, n - 1] by `mode` (see above).
// n >= 1. A non-finite i gives 0.
double wrap_index(double i, int n, Wrap mode);

// The texel at whole-number indices (i, j) after wrapping each (u by wrap_u, v by wrap_v).
// Black for a level with no texels.
Vec3 fetch(const Level& level, double i, double j, Wrap wrap_u, Wrap wrap_v);

// ---- TODO 2: nearest and bilinear sampling ----
// The texel whose square holds uv: (floor(u * w), floor(v * h)), wrapped.
Vec3 sample_nearest(const Level& level, Vec2 uv, Wrap wrap_u, Wrap wrap_v);
// The bilinear blend of the four texels whose centers surround uv (see Filters above).
Vec3 sample_bilinear(const Level& level, Vec2 uv, Wrap wrap_u, Wrap wrap_v);

// ---- TODO 3: mipmaps ----
// Builds levels 1.. down to 1x1 from levels[0] (see Mipmaps above), replacing any that exist,
// and sets mipmapped. A texture with no texels is left as it is.
void build_mipmaps(Texture& texture);

// ---- TODO 4: level of detail and filtering ----
struct UvDerivatives {
    double du_dx = 0, dv_dx = 0, du_dy = 0, dv_dy = 0;
};
// The exact screen-space derivatives of the perspective-correct uv at the point (x, y) (pixels)
// of the triangle with screen positions `screen` (x, y used; the positions the screen weights
// are computed from), clip-space w and uv per vertex (see Level of detail above). All zero for
// a triangle of zero area or where B is not > 0 and finite.
UvDerivatives uv_derivatives(const std::array<Vec3, 3>& screen, const std::array<double, 3>& w,
                             const std::array<Vec2, 3>& uv, double x, double y);
// lambda = log2(rho) for a base level width x height, NOT clamped: -infinity when rho is 0.
double level_of_detail(const UvDerivatives& d, int width, int height);

enum class Filter { kNearest, kBilinear, kNearestMip, kTrilinear };

// The filtered sample of the texture at uv for the unclamped `lambda` (see Filters above). A
// mip filter that reads a level above 0 builds the pyramid first if the texture has none
// (build_mipmaps) and then adds 1 to *mipmap_builds (when not null). Nothing is built for
// lambda <= 0 (or NaN) or for kNearest and kBilinear. With lambda > 0 but only level 0 read (a
// 1x1 texture; kNearestMip with lambda < 0.5) building is allowed, not required (see Only what
// a scene needs above). A texture whose level 0 has no texels samples black; sampling it counts
// no build or one, however often it is sampled, never one per call (build_mipmaps leaves such a
// texture as it is; the reference counts none).
Vec3 sample(Texture& texture, Vec2 uv, double lambda, Filter filter, long long* mipmap_builds);

// ---- TODO 6: Blinn-Phong ----
// One light's diffuse plus specular at a surface point (see Blinn-Phong above), unshadowed, in
// levels: zero when dot(N, L) <= 0. normal, to_eye and to_light need not have length 1
// (normalize each; a zero one, to_eye included, makes the light add nothing at all, its diffuse
// term too, never NaN). A vector so short or so
// long that x^2 + y^2 + z^2 underflows to 0 or overflows (components below about 1e-154 or above
// about 1e154) may count as zero or be normalized exactly (std::hypot, or scaled first): both
// are defined, and no checkpoint depends on which. The same holds for a light's direction.
Vec3 blinn_phong(Vec3 base, Vec3 specular, double shininess, Vec3 normal, Vec3 to_eye, Vec3 to_light, Vec3 intensity);

// ---- TODO 7: tangent-space normal maps ----
// A mesh triangle's tangent T = dP/du and bitangent B = dP/dv (world units per uv unit), not
// orthonormal. With e1 = p1 - p0, e2 = p2 - p0, (du1, dv1) = uv1 - uv0, (du2, dv2) = uv2 - uv0
// and r = du1 dv2 - du2 dv1: T = (e1 dv2 - e2 dv1) / r, B = (e2 du1 - e1 du2) / r. valid is
// false (T, B zero) when r is 0 or T or B is not finite.
struct TangentFrame {
    Vec3 tangent, bitangent;
    bool valid = false;
};
TangentFrame tangent_frame(Vec3 p0, Vec3 p1, Vec3 p2, Vec2 uv0, Vec2 uv1, Vec2 uv2);
// The normal-mapped normal for the unit surface normal n and a normal-map texel (levels):
// T' = normalize(T - n dot(n, T)); B' = cross(n, T'), negated when dot(B', B) < 0; the result
// normalize(x T' + y B' + z n) for (x, y, z) = 2 texel / 255 - 1. Returns n unchanged when the
// frame is not valid, when n, T' or the result is zero, or when anything is not finite (a zero
// normal lights nothing, as in milestone 4, normal map or not).
Vec3 perturb_normal(const TangentFrame& frame, Vec3 n, Vec3 texel);

// ---- TODO 8: shadow mapping ----
struct ShadowSettings {
    int resolution = 512;        // texels per side of each shadow map
    Vec3 center{0, 0, 0};        // the box the light sees: center and radius (world units)
    double radius = 4;
    double constant_bias = 0.02; // world units
    double slope_bias = 0.02;    // world units per unit of tan(theta)
    bool pcf = true;             // 3x3 percentage-closer filtering
};
// The light's view-projection: orthographic(-r, r, -r, r, r, 3r) * look_at(eye, center, up) with
// eye = center - 2r * normalize(direction) and up = (0, 1, 0), or (1, 0, 0) when
// |normalize(direction).y| > 0.99. The zero matrix for a zero or non-finite direction.
Mat4 light_view_projection(Vec3 direction, const ShadowSettings& settings);

// A shadow map: the light's matrix, its radius and a float-Z key per texel (m4's keys, row-major,
// row 0 at the top; kClearKey where nothing was drawn).
struct ShadowMap {
    Mat4 light;
    double radius = 0;
    int resolution = 0;
    std::vector<std::uint32_t> keys;
};
// The shadow factor (see Shadows above) at world point p with unit normal n, for a light of
// direction `direction` whose map is `map`: 1 when lit, 0 when shadowed, the lit fraction of the
// 3x3 texels with pcf; the slope bias follows n. Which normal fill_triangle passes is free: the
// shading normal blinn_phong gets (after the normal map, the reference's choice) or the
// interpolated one before the map (the geometry's slope, which is what the depth map has).
// fill_triangle never asks where the shading normal has dot(n, -direction) <= 0, so no
// checkpoint tests the answer there. With the interpolated normal it may ask where THAT one has
// c <= 0 (the map turned the shading normal toward the light): the bias there is free, either
// the capped constant + slope * 10 (the reference's) or the formula applied as it is, whose
// tan(theta) = sqrt(1 - c^2) / c is then negative (so its slope term lowers the bias).
double shadow_factor(const ShadowMap& map, Vec3 p, Vec3 n, Vec3 direction, const ShadowSettings& settings);

// ---- TODO 5 and TODO 9: the textured, lit, shadowed pipeline ----
struct Material {
    Color color{200, 200, 200};     // the base color when there is no texture
    Texture* texture = nullptr;     // the base color's texture (uv per position), or none
    Filter filter = Filter::kTrilinear;
    Vec3 specular{0, 0, 0};         // levels; zero: no specular term is computed
    double shininess = 32;
    Texture* normal_map = nullptr;  // tangent-space normals (read with sample_bilinear on level 0,
                                    // with the map's own wrap_u and wrap_v; `filter` is the
                                    // texture's only)
    bool lit = true;                // false: the base color as it is (the filter checkpoints)
};

struct Light {
    Vec3 direction{0, 0, -1};  // the direction the rays travel
    Vec3 intensity{1, 1, 1};
    bool casts_shadows = false;
};
struct Lighting {
    Vec3 ambient{0.1, 0.1, 0.1};
    std::vector<Light> lights;
};

struct Object {
    const m4::Mesh* mesh = nullptr;  // positions, triangles, uvs and normals (vertex_normals() if empty)
    Mat4 model = m3::identity();
    Material material;
    bool casts_shadow = true;
};

struct Camera {
    Mat4 view = m3::identity(), projection = m3::identity();
    Vec3 eye{0, 0, 0};  // the camera's world position (V points from the surface toward it)
};

// What was done, counted (the checkpoints compare these with the reference's counts).
struct Stats {
    long long shadow_passes = 0;       // depth passes from a light (one per light that casts shadows)
    long long shadow_texels = 0;       // keys allocated for shadow maps (resolution^2 per pass)
    long long triangles_drawn = 0;     // fan triangles passed to fill_triangle (main pass)
    long long fragments = 0;           // pixel centers covered, inside the image (main pass)
    long long shaded = 0;              // fragments that got a color (passed the depth pre-test)
    long long texture_samples = 0;     // calls of sample() for base colors
    long long lod_computed = 0;        // level-of-detail computations (mip filters only)
    long long mipmap_builds = 0;       // pyramids built (at most one per texture; see above)
    long long normal_map_samples = 0;  // normal-map reads: one per fragment, not per texel (free where no valid frame)
    long long tangent_frames = 0;      // tangent_frame() calls (one per mesh triangle with a normal map)
    long long specular_terms = 0;      // blinn_phong() calls with a nonzero specular color (where c > 0 only)
    long long shadow_lookups = 0;      // shadow_factor() calls
};

// What fill_triangle needs besides the vertices.
struct FillState {
    const Material* material = nullptr;
    const Lighting* lighting = nullptr;
    const std::vector<const ShadowMap*>* shadow_maps = nullptr;  // per light: its map, or nullptr
    const ShadowSettings* shadow_settings = nullptr;
    Vec3 eye;
    TangentFrame tangent;  // of the mesh triangle this fan triangle comes from
};

// TODO 5: one triangle (both windings, milestone 2's snapping and fill rule) into the frame,
// which always has a float-Z depth buffer. Per covered pixel center, in this order:
// 1. the screen weights l, and the key m4::depth_key(kFloatZ, z_ndc, w) of the z_ndc
//    interpolated with l (a float-Z key ignores w: pass the fragment's w, 1 / sum(l_i / w_i) as
//    in milestone 4, or any);
// 2. a fragment whose key is kClearKey or greater than the stored key is dropped here, before
//    anything else (not shaded);
// 3. the perspective-correct weights (m4::perspective_weights) interpolate uv, normal and world
//    position;
// 4. the base color: the material's color, or sample() of its texture; for mip filters only,
//    with lambda = level_of_detail(uv_derivatives(...) at the pixel center, level 0's size),
//    the derivatives taken from the vertex positions the screen weights come from (snapped as
//    the reference's, or unsnapped: where that moves lambda across kNearestMip's rounding
//    boundary k + 0.5 either level is tolerated, see README.md section 5);
// 5. an unlit material stops here. A lit one normalizes the normal, perturbs it by the normal
//    map if any (reading the map where state.tangent is not valid is free, see Only what a scene
//    needs above), and adds ambient and each light: blinn_phong with that normal, times
//    shadow_factor for a light with a map (whose n is free, see there), skipped where
//    dot(N, L) <= 0 for that same, perturbed N;
// 6. m4::to_color, and the depth test m4::depth_passes decides the write.
// Counts into stats what it does (fragments, shaded, texture_samples, ...). triangles_drawn is
// counted once per fan triangle, either here as fill_triangle is entered or by draw_scene as it
// passes one (the reference does the latter), not both.
void fill_triangle(Frame& frame, const std::array<ScreenVertex, 3>& v, const FillState& state, Stats& stats);

// TODO 9: draws every object into the frame (already cleared by m4::clear_frame with a depth
// test and kFloatZ):
// 1. for each light that casts shadows, and only then, the depth pass (see Shadows above):
//    every object with casts_shadow, through m4::draw_mesh into a resolution^2 frame;
// 2. each object: every position once to clip space and world space, its normal to world
//    space (m4::normal_matrix, normalized; m4::vertex_normals when the mesh has none, only for
//    lit materials); per mesh triangle in list order (skipping an index out of range or a
//    non-finite clip coordinate): the tangent frame when the material is lit and has a normal
//    map, m4::clip_triangle unless all three vertices are inside, the fan (0, i, i + 1) (any
//    triangulation passes, as in milestone 4), m3::to_screen, fill_triangle. No culling.
Stats draw_scene(Frame& frame, const std::vector<Object>& objects, const Camera& camera, const Lighting& lighting,
                 const ShadowSettings& shadow_settings);

}  // namespace RASTER_FLAVOUR
}  // namespace m5
