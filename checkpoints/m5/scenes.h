// Milestone 5 scenes: the trusted description of every texture, specular and shadow checkpoint.
// Plain data (no milestone-5 types), so one copy serves the student's and the reference's render
// halves and the judge. Every texture is made here, in code, from a TextureSpec: nothing is
// fetched or read from disk.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "m4/scenes.h"
#include "raster/color.h"
#include "raster/image.h"
#include "raster/vec.h"

namespace m5cp {

using raster::Color;
using raster::Vec2;
using raster::Vec3;
using raster::Vec4;
// Positions, triangles (counter-clockwise from outside), uvs and normals per position.
using Mesh = m4cp::Mesh;

// Mirror m5::Wrap and m5::Filter (same order).
enum class Wrap { kRepeat, kClampToEdge, kMirroredRepeat };
enum class Filter { kNearest, kBilinear, kNearestMip, kTrilinear };

// A texture made in code.
enum class Pattern {
    kChecker,   // cells x cells squares of a and b
    kFine,      // a checker of 2 x 2 texel squares (minification aliases it)
    kGradient,  // a left to right, b top to bottom, and a mark in the top-left corner
    kBricks,    // rows of bricks (a) with mortar (b)
    kBumps,     // a tangent-space normal map: cells x cells round bumps
    kArrow,     // an asymmetric shape (a) on b: every mirror and flip shows
    kNoise,     // a fixed pseudo-random level per texel and channel (distinct numbers)
};
struct TextureSpec {
    Pattern pattern = Pattern::kChecker;
    int width = 8, height = 8;
    int cells = 2;
    Color a{230, 200, 150}, b{60, 40, 30};
    Wrap wrap_u = Wrap::kRepeat, wrap_v = Wrap::kRepeat;
    std::uint32_t seed = 1;  // kNoise
    double bump_height = 0.1;  // kBumps: each bump's height, in cells
    bool bumps_top_half = false;  // kBumps: bumps only in the top half of the image (y < h / 2), flat below
};
raster::Image texture_image(const TextureSpec& t);

struct MaterialSpec {
    Color color{200, 200, 200};
    int texture = -1;  // index into the panel's textures, or none
    Filter filter = Filter::kTrilinear;
    Vec3 specular{0, 0, 0};
    double shininess = 32;
    int normal_map = -1;  // index into the panel's textures, or none
    bool lit = true;
};

// model matrix = translate(position) * rotate(axis, angle) * scale(size)
struct Item {
    Mesh mesh;
    Vec3 position{};
    Vec3 axis{0, 1, 0};
    double angle = 0;
    Vec3 size{1, 1, 1};
    MaterialSpec material;
    bool casts_shadow = true;
};

struct Camera {
    Vec3 eye{0, 0, 5}, target{}, up{0, 1, 0};
    double fovy = 50;  // degrees
    double near = 0.5, far = 100;
};

struct LightSpec {
    Vec3 direction{0, 0, -1};  // where the rays go
    Vec3 intensity{1, 1, 1};
    bool casts_shadows = false;
};

struct ShadowSpec {
    int resolution = 512;
    Vec3 center{0, 0, 0};
    double radius = 4;
    double constant_bias = 0.02, slope_bias = 0.02;
    bool pcf = true;
};

// A triangle given straight on the screen (pixels, z_ndc, clip w, uv), for the checkpoint that
// draws with fill_triangle alone.
struct ScreenTri {
    std::array<Vec3, 3> screen;
    std::array<double, 3> w;
    std::array<Vec2, 3> uv;
    MaterialSpec material;  // unlit
};

// One picture: a camera, items, textures, lights and shadow settings, drawn with draw_scene
// into the rectangle (x0, y0, w, h) of the main image (the frame cleared first); or, when
// screen_tris is not empty, those triangles through fill_triangle alone.
struct Panel {
    Camera camera;
    std::vector<Item> items;
    std::vector<TextureSpec> textures;
    int x0 = 0, y0 = 0, w = 0, h = 0;
    Color background{20, 22, 30};
    Vec3 ambient{0.15, 0.15, 0.15};
    std::vector<LightSpec> lights;
    ShadowSpec shadows;
    std::vector<ScreenTri> screen_tris;
    bool clipped = false;  // some triangle is clipped: fan counts may differ by rounding
    bool timed = false;    // timed on its own (best of a few runs)
};

// Number groups: each calls some functions of the milestone on fixed inputs; the judge checks
// the results against the rules recomputed in the judge, hand-worked values and the reference's.
enum class Group { kWrap, kSampling, kMipmaps, kLod, kFilter, kBlinnPhong, kTangent, kShadow };

// Checks beyond the expected picture.
struct Checks {
    bool filter_error = false;     // per panel: error against a 16x supersampled bilinear truth (item 0, a quad)
    bool nearest_truth = false;    // per panel: pixels off the exact nearest-texel picture (item 0, a quad)
    bool shadow_state = false;     // per panel: pixels in the wrong light state against a ray cast to the light
    bool sphere_error = false;     // per panel: error against the exact Blinn-Phong spheres (every item a sphere)
    std::vector<std::array<int, 2>> same_panels;  // panel pairs whose pictures must agree
    int same_tolerance = 0;                       // within this many levels per channel
};

struct Scene {
    std::string id;
    std::string title;
    std::string hint;
    std::vector<int> todos;  // the TODOs this checkpoint exercises, first the main one
    int width = 96, height = 96;
    std::vector<Panel> panels;
    std::vector<Group> groups;
    Checks checks;
    bool demo = false;
};

const std::vector<Scene>& scenes();
// Grading's scene variants: seed 0 restores the public scenes (see checkpoints/README.md).
void use_variant(std::uint64_t seed);
std::uint64_t variant_seed();
const Scene& scene(const std::string& id);

// The number groups a picture scene is drawn with (the functions of TODOs 1-4 and 6-8 its
// panels call through fill_triangle and draw_scene), besides its own. The render half records
// them under "pre<group>."; the judge checks them when the picture fails, and a failure says
// "fix TODO N first (see <prerequisite_checkpoint>)".
// Number groups of other scenes that a group's functions call (sample_bilinear calls fetch,
// sample() the samplers and build_mipmaps): a numbers scene lists them as its prerequisites too.
std::vector<Group> group_dependencies(Group g);
std::vector<Group> prerequisite_groups(const Scene& s);
std::string prerequisite_key(Group g);         // "pre3."
std::string prerequisite_checkpoint(Group g);  // the public numbers scene that judges g
// A scene drawn through draw_scene also draws kFillScene's ready-made triangles with
// fill_triangle; their values are stored under kFillKey and their picture as the image
// "fill_triangle", so the judge can tell a wrong fill_triangle (TODO 5) from a wrong draw_scene.
inline const std::string kFillScene = "m5.fill_triangle";
inline const std::string kFillKey = "fill_triangle.";

// Shapes shared with the demo and the playground.
// A quad from its four corners (counter-clockwise seen from its front) with uv (u0, v0) at a,
// (u1, v0) at b, (u1, v1) at c, (u0, v1) at d, and the normal of its plane at every corner.
Mesh quad(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec2 uv0 = {0, 0}, Vec2 uv1 = {1, 1});
// A box of half-size 1 centered at the origin: 24 vertices (four per face, with the face's
// normal and uv (0,0)-(1,1)), 12 triangles counter-clockwise from outside.
Mesh box_mesh();
// A unit sphere, `segments` around: u = s / segments (the seam's vertices doubled), v from 0 at
// the north pole to 1 at the south pole, exact normals.
Mesh uv_sphere(int segments);

// The fixed inputs of the number groups (trusted; some vary with the seed like the pictures).
struct WrapCase {
    double i;
    int n;
    Wrap mode;
};
std::vector<WrapCase> wrap_cases();
// A small level with distinct texels for fetch and the samplers: width x height, texel (i, j)
// at index j * width + i, in levels (whole numbers).
struct LevelData {
    int width = 0, height = 0;
    std::vector<Vec3> texels;
};
LevelData sample_level(int which);  // 0: 4 x 2, 1: 5 x 3, 2: empty
struct FetchCase {
    int level;
    double i, j;
    Wrap wu, wv;
};
std::vector<FetchCase> fetch_cases();
struct SampleCase {
    int level;
    Vec2 uv;
    Wrap wu, wv;
};
std::vector<SampleCase> sample_cases();
// The base levels of the mipmap checkpoint: 8 x 8, 1 x 1, 3 x 5, 7 x 1, 5 x 2.
std::vector<LevelData> mip_bases();
struct LodCase {
    std::array<Vec3, 3> screen;
    std::array<double, 3> w;
    std::array<Vec2, 3> uv;
    double x, y;
    int width, height;  // the base level for level_of_detail
};
std::vector<LodCase> lod_cases();
// level_of_detail on given derivatives and a base level width x height.
struct LambdaCase {
    double du_dx, dv_dx, du_dy, dv_dy;
    int width, height;
};
std::vector<LambdaCase> lambda_cases();
struct FilterCase {
    int base;  // index into mip_bases()
    Filter filter;
    Vec2 uv;
    double lambda;
    Wrap wrap_u = Wrap::kRepeat, wrap_v = Wrap::kRepeat;
};
// In call order: each (base, filter) pair gets a fresh texture, so the first case of a pair
// that needs a level above 0 builds its pyramid.
std::vector<FilterCase> filter_cases();
struct PhongCase {
    Vec3 base, specular;
    double shininess;
    Vec3 normal, to_eye, to_light, intensity;
};
std::vector<PhongCase> phong_cases();
struct FrameCase {
    std::array<Vec3, 3> p;
    std::array<Vec2, 3> uv;
};
std::vector<FrameCase> frame_cases();
struct PerturbCase {
    Vec3 tangent, bitangent;
    bool valid;
    Vec3 n, texel;
};
std::vector<PerturbCase> perturb_cases();
struct LightMatrixCase {
    Vec3 direction;
    Vec3 center;
    double radius;
};
std::vector<LightMatrixCase> light_matrix_cases();
// The tiny shadow map of the shadow checkpoint: the light looks straight down (direction
// (0, -1, 0)) at the box of radius 2 around the origin, 4 x 4 texels of 1 world unit; texel
// column c covers world z in [c - 2, c - 1), row r world x in (1 - r, 2 - r].
struct TinyMap {
    Vec3 direction{0, -1, 0};
    Vec3 center{0, 0, 0};
    double radius = 2;
    int resolution = 4;
    std::vector<std::uint32_t> keys;  // float-Z keys, row-major, row 0 at the top
};
TinyMap tiny_map();
struct ShadowCase {
    Vec3 p, n;
    double constant_bias, slope_bias;
    bool pcf;
    double direction_scale = 1;  // the light's direction is passed this many times as long
    double settings_radius = 0;  // 0: the settings passed carry the map's radius; else this one
};
std::vector<ShadowCase> shadow_cases();

}  // namespace m5cp
