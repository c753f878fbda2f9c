// Milestone 4 scenes: the trusted description of every depth and lighting checkpoint. Plain
// data (no milestone-4 types), so one copy serves the student's and the reference's render
// halves and the judge.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "raster/color.h"
#include "raster/vec.h"

namespace m4cp {

using raster::Color;
using raster::Vec2;
using raster::Vec3;
using raster::Vec4;

struct Mesh {
    std::vector<Vec3> positions;
    std::vector<std::array<int, 3>> triangles;  // counter-clockwise from outside
    std::vector<Color> face_colors;
    std::vector<Color> vertex_colors;
    std::vector<Vec2> uvs;
    std::vector<Vec3> normals;
};

// model matrix = translate(position) * rotate(axis, angle) * scale(size)
struct Item {
    Mesh mesh;
    Vec3 position{};
    Vec3 axis{0, 1, 0};
    double angle = 0;
    Vec3 size{1, 1, 1};
    Color material{200, 200, 200};
};

struct Camera {
    Vec3 eye{0, 0, 5}, target{}, up{0, 1, 0};
    bool ortho = false;
    double fovy = 50;        // degrees
    double half_height = 2;  // orthographic
    double near = 0.5, far = 100;
};

struct LightSpec {
    bool point = false;
    Vec3 vector{0, 0, -1};  // directional: where the rays go; point: position
    Vec3 intensity{1, 1, 1};
};

// Mirrors m4::DepthFormat and m4::Shading (same order).
enum class Format { kFloatZ, kReversedZ, kFixed24, kInverseW };
enum class Shade { kFaceColor, kVertexColor, kFlat, kGouraud, kPerPixel, kChecker, kDepthView, kNormalView };

// A triangle given straight on the screen (pixels, z_ndc, clip w, vertex color in levels), for
// the checkpoint that draws with fill_triangle alone.
struct ScreenTri {
    std::array<Vec3, 3> screen;
    std::array<double, 3> w;
    std::array<Vec3, 3> color;
};

// One picture: a camera, items, lights and the needs, drawn into the rectangle (x0, y0, w, h)
// of the main image. `frames` lists which items each frame draws (the picture is the last
// frame's; the frame is cleared before each); empty: one frame with every item in order.
struct Panel {
    Camera camera;
    std::vector<Item> items;
    int x0 = 0, y0 = 0, w = 0, h = 0;
    Color background{20, 22, 30};
    bool depth_test = true;
    Format format = Format::kFloatZ;
    Shade shading = Shade::kFaceColor;
    bool perspective_correct = true;
    bool cull = false;
    Vec3 ambient{0.1, 0.1, 0.1};
    std::vector<LightSpec> lights;
    std::vector<std::vector<int>> frames;
    // When not empty: the render half clears the frame itself and draws these with
    // fill_triangle alone (no clear_frame, no draw_mesh); the camera and items are unused.
    std::vector<ScreenTri> screen_tris;
    std::vector<std::array<int, 2>> depth_probes;  // pixels (in the panel) whose keys are read back
    bool timed = false;  // timed on its own (best of a few runs), for the error-against-time chart
};

// Number groups: each calls some functions of the milestone on fixed inputs; the judge checks
// the results against hand-worked values and the reference's.
enum class Group { kDepthKeys, kDepthTest, kClearFrame, kWeights, kNormals, kLambert, kDebugColors, kClip };

// Checks beyond the expected picture.
struct Checks {
    std::vector<std::array<int, 2>> same_panels;  // panel pairs whose pictures must be identical
    bool checker_error = false;  // per panel: error against the analytic checkerboard (item 0, a quad)
    bool zfight = false;         // per panel: pixels where the far surface shows
    bool sphere_error = false;   // per panel: error against the analytic sphere (item 0)
    bool shading_chart = false;  // sphere_error per panel, held to the reference's, and charted against time
    bool normal_lengths = false;  // per kNormalView panel: its colors against the normals interpolated after and
                                  // before they are normalized, worked out here by ray casting
    bool fill_rule = false;      // per panel (screen_tris, no depth test): every pixel shows the one triangle that
                                 // covers its center by the top-left rule, worked out here in exact integers
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

// The number groups a picture scene is drawn with, besides its own: the functions of TODOs 1-7
// its panels call (through fill_triangle and draw_mesh), each on its own checkpoint's fixed
// inputs. The render half records them under "pre<group>."; the judge checks them before it
// judges the picture, and a failure says "fix TODO N first (see <prerequisite_checkpoint>)".
std::vector<Group> prerequisite_groups(const Scene& s);
std::string prerequisite_key(Group g);         // "pre3."
std::string prerequisite_checkpoint(Group g);  // the public numbers scene that judges g
// A scene drawn through draw_mesh also draws kFillScene's ready-made triangles with
// fill_triangle; their values are stored under kFillKey and their picture as the image
// "fill_triangle", so the judge can tell which caller is wrong.
inline const std::string kFillScene = "m4.fill_triangle";
inline const std::string kFillKey = "fill_triangle.";
// Likewise kFillRuleScene's triangles, whose shared edges run through pixel centers: a
// pipeline picture that differs by a pixel on such an edge is fill_triangle's fill rule.
inline const std::string kFillRuleScene = "m4.shared_edges";
inline const std::string kFillRuleKey = "shared_edges.";

// Shapes shared with the demo, the tables and the benchmark.
// A UV sphere of radius 1: `segments` around, segments / 2 from pole to pole, with its exact
// normals when `with_normals` (else the pipeline computes them).
Mesh sphere_mesh(int segments, bool with_normals);
// The shading modes and tessellations of the error-against-run-time checkpoint and lesson table:
// rows flat, Gouraud, per-pixel; columns these segment counts.
inline constexpr int kChartSegments[4] = {6, 12, 24, 48};
// One panel of that chart: a unit sphere of `segments` in `shading`, lit by a directional and a
// point light, `size` pixels square at (x0, y0).
Panel shading_panel(Shade shading, int segments, int x0, int y0, int size);
// A quad from its four corners (counter-clockwise seen from its front), uv (0,0), (1,0), (1,1),
// (0,1) at the corners, in one face color.
Mesh quad_mesh(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Color color);

// The fixed inputs of the number groups (trusted; they vary with the seed like the pictures).
struct KeyCase {
    int format;
    double z_ndc, w;
};
std::vector<KeyCase> key_cases();
struct ClipCase {
    std::array<Vec4, 3> clip;
    std::array<Vec3, 3> color;
    std::array<Vec2, 3> uv;
};
std::vector<ClipCase> clip_cases();
struct LambertCase {
    Vec3 ambient;
    std::vector<LightSpec> lights;
    Color base;
    Vec3 position, normal;
};
std::vector<LambertCase> lambert_cases();
// perspective_weights' inputs (m4.weights): screen weights and w per vertex.
struct WeightCase {
    std::array<double, 3> screen, w;
};
std::vector<WeightCase> weight_cases();

}  // namespace m4cp
