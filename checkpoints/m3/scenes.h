// Milestone 3 scenes: the trusted description of every transform checkpoint and demo picture.
// Plain data (no milestone-3 types), so one copy serves the student's and the reference's
// render halves and the judge.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "raster/color.h"
#include "raster/vec.h"

namespace m3cp {

using raster::Color;
using raster::Vec3;
using raster::Vec4;
using Matrix = std::array<std::array<double, 4>, 4>;  // m[row][col], as m3::Mat4

struct Mesh {
    std::vector<Vec3> positions;
    std::vector<std::array<int, 3>> triangles;  // counter-clockwise from outside
    std::vector<std::array<int, 2>> edges;
    std::vector<Color> face_colors;
};

// model matrix = translate(position) * rotate(axis, angle) * scale(size)
struct Item {
    Mesh mesh;
    Vec3 position{};
    Vec3 axis{0, 1, 0};
    double angle = 0;
    Vec3 size{1, 1, 1};
};

struct Camera {
    Vec3 eye{0, 0, 5}, target{}, up{0, 1, 0};
    bool ortho = false;
    double fovy = 50;          // degrees (perspective)
    double half_height = 2;    // orthographic: top = half_height, right = half_height * aspect
    double near = 0.5, far = 100;
};

// One picture: a camera and items, drawn into the rectangle (x0, y0, w, h) of the main image.
struct Panel {
    Camera camera;
    std::vector<Item> items;
    int x0 = 0, y0 = 0, w = 0, h = 0;
};

// Number groups: each calls some functions of the milestone on fixed inputs; the judge checks
// the results (hand-worked values, or the reference where hand-working is impractical).
enum class Group {
    kMatrixOps, kBuilders, kRodrigues, kComposition, kInverse, kNearSingular, kLookAt, kProjection,
    kClip, kCulling, kBezier, kPainter, kRotationDrift, kNonFinite,
};

struct Scene {
    std::string id;
    std::string title;
    std::string hint;
    std::vector<int> todos;  // the TODOs this checkpoint exercises, first the main one
    int width = 96, height = 96;
    std::vector<Panel> panels;   // pictures (none for a numbers-only checkpoint)
    bool fill = false, wireframe = false, cull = false, clip = false, painter = false;
    Color line = {255, 255, 255};
    std::vector<Group> groups;
    bool demo = false;
};

const std::vector<Scene>& scenes();
// Grading's scene variants: replaces every scene by a variant derived from (seed, scene id);
// seed 0 restores the public scenes. scenes() and scene() return the current ones.
void use_variant(std::uint64_t seed);
// The seed of the current variant (0: the public scenes). The number checkpoints add "probe"
// inputs drawn from it (render.cpp), which the judge compares with the reference's results.
std::uint64_t variant_seed();
const Scene& scene(const std::string& id);

// The number groups a picture scene is drawn with, besides its own: the functions draw_model
// calls, each tested on its own checkpoint's fixed inputs. The render half records them under
// "pre<group>."; the judge checks them before it guesses at the picture, and a failure says
// "fix TODO N first (see <prerequisite_checkpoint>)". Empty for a numbers scene.
std::vector<Group> prerequisite_groups(const Scene& s);  // in the order of the enum (of the TODOs)
// The groups whose functions group g's own checks go through (kBuilders: kMatrixOps, since it
// tests rotate_z through transform_point). Always earlier in the enum.
std::vector<Group> group_dependencies(Group g);
std::string prerequisite_key(Group g);           // "pre3."
std::string prerequisite_checkpoint(Group g);    // the public numbers scene that judges g

// Shapes shared with the demo and the tools.
Mesh cube_mesh(bool colored);
Mesh pyramid_mesh();
Mesh soccer_ball_mesh();  // common/models/soccer_ball.obj: 60 vertices, 90 edges, 32 faces
Mesh obj_mesh(const std::string& name, bool colored);  // a model shipped in common/models

// The fixed inputs of the number groups (trusted; the judge recomputes from these).
Matrix near_singular_matrix();
std::vector<std::array<Vec4, 3>> clip_cases();       // triangles in clip space
std::vector<std::array<Vec4, 2>> clip_line_cases();  // segments in clip space
// m3.nonfinite: matrices inverse() must refuse (a NaN entry, an infinite one, entries near
// 1e-320 whose inverse overflows), by value name; a triangle and a segment with coordinates
// near 1e308 (a plane distance such as w + x overflows), crossing the side planes.
std::vector<std::pair<std::string, Matrix>> nonfinite_inverse_cases();
std::pair<std::array<Vec4, 3>, std::array<Vec4, 2>> nonfinite_clip_cases();
// A triangle near 1e308 whose first edge enters the plane x = w exactly at its second vertex
// (d = 0 there): from the inside end the crossing is that vertex, exactly; from the outside
// end, o + (i - o) * 1 rounds w past DBL_MAX (after any power-of-two scaling) and overflows.
std::array<Vec4, 3> inside_end_clip_case();

}  // namespace m3cp
