// The viewer's handle on ONE implementation of the five milestones: the student's or the
// reference.
//
// Why a table. Every milestone header wraps its functions in `inline namespace RASTER_FLAVOUR`
// (common/include/raster/flavour.h): the student's code is m1::student::draw_line, the
// reference's m1::reference::draw_line, and one translation unit sees only one of them. So
// flavour.cpp is compiled twice, once per flavour, and each copy fills a Flavour table of plain
// function pointers. The viewer then picks, per milestone, which table to call (see plan.h).
//
// Nothing in this header includes a milestone header: the types that cross the table are the
// shared ones of common/ (raster::Image, raster::Vec3, raster::Mesh...) and the plain structs
// below, never m3::Mat4, m4::Mesh or m5::Texture, which are different types in each flavour.
//
// Cost. A table call is one indirect call per frame (draw_mesh), per line or per triangle (the
// fallback loops): never per pixel.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "raster/color.h"
#include "raster/image.h"
#include "raster/mesh.h"
#include "raster/vec.h"

namespace viewer {

// The camera and the model's pose for one frame, as plain numbers. Each flavour builds its own
// matrices from them with its own m3::look_at, m3::perspective and m3::rotate_y.
struct View {
    raster::Vec3 eye{0, 0, 3};
    raster::Vec3 target{0, 0, 0};
    raster::Vec3 up{0, 1, 0};
    double fovy_degrees = 45;
    double near = 0.1, far = 100;
    double model_yaw = 0;  // the model's spin about its own y axis, in radians
};

// One directional light with ambient, and the model's material.
struct LightSetup {
    raster::Vec3 direction{-0.5, -0.6, -1};  // the direction the rays TRAVEL (world space)
    double intensity = 0.85;
    double ambient = 0.15;
    raster::Color material{225, 170, 110};
};

// What the viewer can show. The order is the order of the keys 1 to 9. The last three are
// milestone 5's scenes (scene.h says what each holds).
enum class Mode { kWireframe, kFlat, kGouraud, kPerPixel, kDepth, kNormals, kTextured, kSpecular, kShadowed };
inline constexpr int kModeCount = 9;
const char* mode_name(Mode mode);
// Drawn by m5::draw_scene (textured, specular, shadowed), not by milestone 4's draw_mesh.
constexpr bool is_scene_mode(Mode mode) {
    return mode == Mode::kTextured || mode == Mode::kSpecular || mode == Mode::kShadowed;
}

// The mesh with its wireframe: every polygon edge once (raster::unique_edges).
struct Geometry {
    const raster::Mesh* mesh = nullptr;
    const std::vector<std::array<int, 2>>* edges = nullptr;
};

// What one frame drew, counted (0 of both: nothing was in view).
struct DrawCounts {
    long long triangles = 0;  // triangles filled (after clipping and culling)
    long long lines = 0;      // lines drawn
};

// Milestone 1 and 2 primitives, as the fallback loops call them.
using LineFn = void (*)(raster::Image&, raster::Vec2, raster::Vec2, raster::Color);
using TriangleFn = void (*)(raster::Image&, raster::Vec2, raster::Vec2, raster::Vec2, raster::Color);
// Milestone 4's lighting of one world-space triangle (flat: face normal at the centroid).
using FaceShadeFn = raster::Color (*)(const LightSetup&, raster::Vec3, raster::Vec3, raster::Vec3);

// A mesh converted once into one flavour's m4::Mesh (with its vertex normals), kept between
// frames. Only the flavour that made it can draw it.
class PreparedMesh {
public:
    virtual ~PreparedMesh() = default;
};

// The color image and depth buffer of a frame, owned by the caller and lent to draw_mesh.
struct Target {
    raster::Image color;
    std::vector<std::uint32_t> depth;
};

// ---- milestone 5's scenes, as plain data (scene.h makes them; each flavour converts them) ----

// A mesh with texture coordinates: one uv and one normal per position (positions repeated
// where a seam of the uv mapping needs two uvs at one point).
struct TexturedMesh {
    std::vector<raster::Vec3> positions;
    std::vector<std::array<int, 3>> triangles;
    std::vector<raster::Vec3> normals;
    std::vector<raster::Vec2> uvs;
};

// What milestone 5's modes draw, made once per model: the model with its uvs, the floor under
// it, and the generated textures (images, row 0 at the top).
struct SceneAssets {
    TexturedMesh model;  // turns with the model (View::model_yaw)
    TexturedMesh floor;  // a square under the model, still
    raster::Image model_texture;  // bricks
    raster::Image floor_texture;  // a checkerboard
    double floor_y = -1;       // the floor's height
    double scene_radius = 1;   // every point of model and floor within this of the origin
};

// One surface's material in a scene mode.
struct SurfaceSetup {
    bool textured = false;   // the scene's texture for it (trilinear), else LightSetup::material
    double specular = 0;     // levels (0: no specular term), gray
    double shininess = 32;
};

// What one scene mode draws (scene_setup in scene.h).
struct SceneSetup {
    SurfaceSetup model;
    bool floor = false;  // the floor, which receives shadows and casts none
    SurfaceSetup floor_surface;
    bool shadows = false;  // the light casts shadows (shadow map, PCF)
    int shadow_resolution = 1024;
    raster::Vec3 shadow_center{0, 0, 0};
    double shadow_radius = 1;
    double constant_bias = 0.02, slope_bias = 0.02;
    bool pcf = true;
};

// The scene converted once into one flavour's m4::Mesh and m5::Texture objects (the textures'
// mipmaps are built by the first frame that minifies them, and kept).
class PreparedScene {
public:
    virtual ~PreparedScene() = default;
};

struct Flavour {
    const char* name = "";  // "student" or "reference"

    // ---- milestone 1 and 2: the primitives ----
    LineFn draw_line = nullptr;          // m1::draw_line
    TriangleFn fill_triangle = nullptr;  // m2::fill_triangle

    // ---- milestone 3: the viewer's own loops, written with THIS flavour's matrices, clipping,
    // projection, culling and painter's order; they draw with the primitive passed in, which
    // may be the other flavour's (the student's lines with the reference's transforms). ----
    DrawCounts (*wireframe)(raster::Image&, const Geometry&, const View&, LineFn, raster::Color) = nullptr;
    // Flat-lit solid without a depth buffer: back faces culled, the rest far to near.
    DrawCounts (*painter)(raster::Image&, const Geometry&, const View&, const LightSetup&, TriangleFn,
                          FaceShadeFn) = nullptr;

    // ---- milestone 4 ----
    FaceShadeFn shade_face = nullptr;  // m4::face_normal, m4::shade, m4::to_color
    std::unique_ptr<PreparedMesh> (*prepare)(const raster::Mesh&) = nullptr;
    // m4::clear_frame and m4::draw_mesh (depth test, culling when `cull`) in a shaded mode.
    DrawCounts (*draw_mesh)(Target&, const PreparedMesh&, const View&, const LightSetup&, Mode, bool cull,
                            raster::Color background) = nullptr;

    // ---- milestone 5 ----
    std::unique_ptr<PreparedScene> (*prepare_scene)(const SceneAssets&) = nullptr;
    // m4::clear_frame (depth test, float Z) and m5::draw_scene: the model (turned by
    // View::model_yaw) and, when setup.floor, the floor, lit by `light` (no culling).
    DrawCounts (*draw_scene)(Target&, PreparedScene&, const View&, const LightSetup&, const SceneSetup&,
                             raster::Color background) = nullptr;

    // ---- the probes (probe.h): small fixed tests of each milestone, run on both flavours
    // and compared ----
    raster::Image (*probe_m1)() = nullptr;        // lines in every octant, some clipped
    raster::Image (*probe_m2)() = nullptr;        // triangles of both windings, some clipped
    std::vector<double> (*probe_m3)() = nullptr;  // matrices, clipping, projection, culling, order
    raster::Image (*probe_m4)() = nullptr;        // a small lit sphere in four shaded modes
    raster::Image (*probe_m5)() = nullptr;        // a small sphere textured, specular, shadowed
};

// The two tables (flavour.cpp, compiled once per flavour).
namespace student {
const Flavour& flavour();
}
namespace reference {
const Flavour& flavour();
}

}  // namespace viewer
