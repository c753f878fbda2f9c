// One flavour's table (flavour_api.h). This file is compiled TWICE: once with
// RASTER_FLAVOUR=student against the student's milestone libraries, once with
// RASTER_FLAVOUR=reference against the reference solutions. Every m1:: to m5:: name
// below therefore means "this flavour's" (the inline namespace picks it), and the table is
// defined as viewer::student::flavour() or viewer::reference::flavour() accordingly.
//
// Everything here runs per frame, per line or per triangle; the pixels are the milestones' own
// loops.
#include <algorithm>
#include <cstddef>
#include <exception>
#include <utility>

#include "depth_lighting.h"
#include "flavour_api.h"
#include "lines.h"
#include "raster/flavour.h"
#include "scene.h"
#include "textures_shadows.h"
#include "transforms.h"
#include "triangles.h"

namespace viewer::RASTER_FLAVOUR {
namespace {

#define VIEWER_STRINGIFY2(x) #x
#define VIEWER_STRINGIFY(x) VIEWER_STRINGIFY2(x)

using m3::Mat4;
using raster::Color;
using raster::Image;
using raster::Vec2;
using raster::Vec3;
using raster::Vec4;

// ---- the camera, with this flavour's milestone 3 ----

struct Matrices {
    Mat4 model, view, projection;
};

Matrices matrices(const View& v, int width, int height) {
    return {m3::rotate_y(v.model_yaw), m3::look_at(v.eye, v.target, v.up),
            m3::perspective(v.fovy_degrees, static_cast<double>(width) / height, v.near, v.far)};
}

// Inside the view volume: the six closed planes -w <= x, y, z <= w.
bool inside(Vec4 c) {
    return -c.w <= c.x && c.x <= c.w && -c.w <= c.y && c.y <= c.w && -c.w <= c.z && c.z <= c.w;
}

Vec2 xy(Vec3 s) { return {s.x, s.y}; }

// ---- milestone 3: the viewer's loops ----

// Every edge: clip in clip space (m3::clip_line), to the screen (m3::to_screen), then `line`.
DrawCounts wireframe(Image& img, const Geometry& g, const View& v, LineFn line, Color color) {
    DrawCounts counts;
    if (g.mesh == nullptr || g.edges == nullptr || line == nullptr) return counts;
    const Matrices mx = matrices(v, img.width(), img.height());
    const Mat4 mvp = mx.projection * (mx.view * mx.model);
    const std::vector<Vec3>& positions = g.mesh->positions;
    std::vector<Vec4> clip(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const Vec3 p = positions[i];
        clip[i] = mvp * Vec4{p.x, p.y, p.z, 1};
    }
    for (const auto& [i, j] : *g.edges) {
        Vec4 a = clip[static_cast<std::size_t>(i)], b = clip[static_cast<std::size_t>(j)];
        if (!m3::clip_line(a, b)) continue;
        if (!(a.w > 0 && b.w > 0)) continue;  // clipping promises w >= near; never divide by 0
        line(img, xy(m3::to_screen(a, img.width(), img.height())), xy(m3::to_screen(b, img.width(), img.height())),
             color);
        ++counts.lines;
    }
    return counts;
}

// The painter's algorithm of milestone 3 (no depth buffer before milestone 4): triangles far to
// near by m3::painter_order, each clipped (m3::clip_polygon) when not entirely inside, fanned,
// culled (m3::is_back_facing), lit once (`shade`) and filled (`fill`).
DrawCounts painter(Image& img, const Geometry& g, const View& v, const LightSetup& light, TriangleFn fill,
                   FaceShadeFn shade) {
    DrawCounts counts;
    if (g.mesh == nullptr || fill == nullptr || shade == nullptr) return counts;
    const int w = img.width(), h = img.height();
    const Matrices mx = matrices(v, w, h);
    const Mat4 model_view = mx.view * mx.model;
    const raster::Mesh& mesh = *g.mesh;
    const std::size_t n = mesh.positions.size();
    std::vector<Vec3> world(n), eye(n);
    std::vector<Vec4> clip(n);
    for (std::size_t i = 0; i < n; ++i) {
        world[i] = m3::transform_point(mx.model, mesh.positions[i]);
        eye[i] = m3::transform_point(model_view, mesh.positions[i]);
        clip[i] = mx.projection * Vec4{eye[i].x, eye[i].y, eye[i].z, 1};
    }
    std::vector<std::array<Vec3, 3>> view_triangles;
    view_triangles.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles) view_triangles.push_back({eye[t[0]], eye[t[1]], eye[t[2]]});
    const std::vector<int> order = m3::painter_order(view_triangles);

    std::vector<Vec4> polygon;
    for (const int index : order) {
        if (index < 0 || static_cast<std::size_t>(index) >= mesh.triangles.size()) continue;  // never trust an index
        const auto& t = mesh.triangles[static_cast<std::size_t>(index)];
        polygon = {clip[t[0]], clip[t[1]], clip[t[2]]};
        if (!(inside(polygon[0]) && inside(polygon[1]) && inside(polygon[2]))) polygon = m3::clip_polygon(polygon);
        bool lit = false;
        Color color;
        for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
            if (!(polygon[0].w > 0 && polygon[k].w > 0 && polygon[k + 1].w > 0)) continue;
            const Vec3 s0 = m3::to_screen(polygon[0], w, h);
            const Vec3 s1 = m3::to_screen(polygon[k], w, h);
            const Vec3 s2 = m3::to_screen(polygon[k + 1], w, h);
            if (m3::is_back_facing(s0, s1, s2)) continue;
            if (!lit) {  // once per mesh triangle, and only when some of it shows
                color = shade(light, world[t[0]], world[t[1]], world[t[2]]);
                lit = true;
            }
            fill(img, xy(s0), xy(s1), xy(s2), color);
            ++counts.triangles;
        }
    }
    return counts;
}

// ---- milestone 4 ----

m4::Lighting lighting_of(const LightSetup& light) {
    m4::Lighting lighting;
    lighting.ambient = {light.ambient, light.ambient, light.ambient};
    lighting.lights.push_back({m4::Light::Kind::kDirectional, light.direction,
                               {light.intensity, light.intensity, light.intensity}});
    return lighting;
}

Color shade_face(const LightSetup& light, Vec3 p0, Vec3 p1, Vec3 p2) {
    return m4::to_color(m4::shade(lighting_of(light), light.material, (p0 + p1 + p2) / 3, m4::face_normal(p0, p1, p2)));
}

m4::Shading shading_of(Mode mode) {
    switch (mode) {
        case Mode::kGouraud: return m4::Shading::kGouraud;
        case Mode::kPerPixel: return m4::Shading::kPerPixel;
        case Mode::kDepth: return m4::Shading::kDepthView;
        case Mode::kNormals: return m4::Shading::kNormalView;
        case Mode::kWireframe:  // not a milestone-4 mode; the plan never asks for it here
        case Mode::kFlat:
        case Mode::kTextured:  // milestone 5's: draw_scene below
        case Mode::kSpecular:
        case Mode::kShadowed: break;
    }
    return m4::Shading::kFlat;
}

// The mesh as this flavour's m4::Mesh, with vertex normals computed once here (draw_mesh would
// otherwise compute them every frame for a file without normals).
struct Prepared final : PreparedMesh {
    m4::Mesh mesh;
};

std::unique_ptr<PreparedMesh> prepare(const raster::Mesh& source) {
    auto prepared = std::make_unique<Prepared>();
    m4::Mesh& mesh = prepared->mesh;
    mesh.positions = source.positions;
    mesh.triangles = source.triangles;
    mesh.normals = source.normals.empty() ? m4::vertex_normals(source.positions, source.triangles) : source.normals;
    if (mesh.normals.size() != mesh.positions.size()) mesh.normals.clear();  // let draw_mesh compute them
    return prepared;
}

// m4::clear_frame and m4::draw_mesh into the caller's image and depth buffer, lent to an
// m4::Frame for the call (moved, not copied) and always given back, even on an exception.
DrawCounts draw_mesh(Target& target, const PreparedMesh& prepared, const View& v, const LightSetup& light, Mode mode,
                     bool cull, Color background) {
    const auto* mine = dynamic_cast<const Prepared*>(&prepared);
    if (mine == nullptr || target.color.empty()) return {};  // another flavour's mesh: not ours to draw
    m4::Needs needs;
    needs.depth_test = true;
    needs.shading = shading_of(mode);
    needs.cull = cull;

    m4::Frame frame;
    frame.color = std::move(target.color);
    frame.depth = std::move(target.depth);
    struct GiveBack {
        Target& target;
        m4::Frame& frame;
        ~GiveBack() {
            target.color = std::move(frame.color);
            target.depth = std::move(frame.depth);
        }
    } give_back{target, frame};

    m4::clear_frame(frame, background, needs.depth_test, needs.depth_format);
    const Matrices mx = matrices(v, frame.color.width(), frame.color.height());
    const m4::Stats stats =
        m4::draw_mesh(frame, mine->mesh, mx.model, mx.view, mx.projection, lighting_of(light), light.material, needs);
    return {stats.triangles_drawn, 0};
}

// ---- milestone 5 ----

// The scene as this flavour's meshes and textures. The textures are kept between frames: the
// first frame that minifies one builds its mipmaps (m5::sample), and later frames reuse them.
struct PreparedM5 final : PreparedScene {
    m4::Mesh model, floor;
    m5::Texture bricks, checker;
};

m4::Mesh mesh_of(const TexturedMesh& t) {
    m4::Mesh mesh;
    mesh.positions = t.positions;
    mesh.triangles = t.triangles;
    mesh.uvs = t.uvs;
    mesh.normals = t.normals;
    return mesh;
}

std::unique_ptr<PreparedScene> prepare_scene(const SceneAssets& assets) {
    auto prepared = std::make_unique<PreparedM5>();
    prepared->model = mesh_of(assets.model);
    prepared->floor = mesh_of(assets.floor);
    prepared->bricks = m5::make_texture(assets.model_texture);
    prepared->checker = m5::make_texture(assets.floor_texture);
    return prepared;
}

m5::Material material_of(const SurfaceSetup& surface, const LightSetup& light, m5::Texture* texture) {
    m5::Material m;
    m.color = light.material;
    m.texture = surface.textured ? texture : nullptr;
    m.filter = m5::Filter::kTrilinear;
    m.specular = {surface.specular, surface.specular, surface.specular};
    m.shininess = surface.shininess;
    m.lit = true;
    return m;
}

// m4::clear_frame and m5::draw_scene into the caller's image and depth buffer (lent as in
// draw_mesh above): the model turned by the view's yaw, the floor still, one directional light.
DrawCounts draw_scene(Target& target, PreparedScene& prepared, const View& v, const LightSetup& light,
                      const SceneSetup& setup, Color background) {
    auto* mine = dynamic_cast<PreparedM5*>(&prepared);
    if (mine == nullptr || target.color.empty()) return {};
    m4::Frame frame;
    frame.color = std::move(target.color);
    frame.depth = std::move(target.depth);
    struct GiveBack {
        Target& target;
        m4::Frame& frame;
        ~GiveBack() {
            target.color = std::move(frame.color);
            target.depth = std::move(frame.depth);
        }
    } give_back{target, frame};

    m4::clear_frame(frame, background, true, m4::DepthFormat::kFloatZ);
    const Matrices mx = matrices(v, frame.color.width(), frame.color.height());
    m5::Camera camera;
    camera.view = mx.view;
    camera.projection = mx.projection;
    camera.eye = v.eye;
    m5::Lighting lighting;
    lighting.ambient = {light.ambient, light.ambient, light.ambient};
    m5::Light sun;
    sun.direction = light.direction;
    sun.intensity = {light.intensity, light.intensity, light.intensity};
    sun.casts_shadows = setup.shadows;
    lighting.lights.push_back(sun);

    std::vector<m5::Object> objects(1);
    objects[0].mesh = &mine->model;
    objects[0].model = mx.model;
    objects[0].material = material_of(setup.model, light, &mine->bricks);
    objects[0].casts_shadow = true;
    if (setup.floor) {
        m5::Object floor;
        floor.mesh = &mine->floor;
        floor.model = m3::identity();
        floor.material = material_of(setup.floor_surface, light, &mine->checker);
        floor.casts_shadow = false;  // it only receives
        objects.push_back(floor);
    }
    m5::ShadowSettings shadow;
    shadow.resolution = setup.shadow_resolution;
    shadow.center = setup.shadow_center;
    shadow.radius = setup.shadow_radius;
    shadow.constant_bias = setup.constant_bias;
    shadow.slope_bias = setup.slope_bias;
    shadow.pcf = setup.pcf;
    const m5::Stats stats = m5::draw_scene(frame, objects, camera, lighting, shadow);
    return {stats.triangles_drawn, 0};
}

// ---- the probes: small fixed tests, drawn the same way by both flavours (probe.cpp compares) ----

constexpr int kProbeW = 64, kProbeH = 48;

Image probe_m1() {
    Image img(kProbeW, kProbeH);
    const Vec2 c{32.5, 24.5};
    // A star: every octant, both axes and both diagonals, drawn from the center outward.
    const Vec2 ends[] = {{60.5, 24.5}, {60.5, 31.5}, {50.5, 44.5}, {32.5, 44.5}, {25.5, 44.5}, {4.5, 38.5},
                         {4.5, 24.5},  {4.5, 13.5},  {18.5, 2.5},  {32.5, 2.5},  {40.5, 2.5},  {54.5, 2.5},
                         {60.5, 18.5}, {46.5, 38.5}};
    for (const Vec2 e : ends) m1::draw_line(img, c, e, Color{255, 255, 255});
    // Lines that leave the image (clipped), one backwards, one outside entirely, one a single pixel.
    m1::draw_line(img, {-30.2, 5.7}, {90.6, 40.1}, Color{255, 0, 0});
    m1::draw_line(img, {20.3, 70.9}, {28.8, -20.4}, Color{0, 255, 0});
    m1::draw_line(img, {63.5, 47.5}, {2.5, 46.5}, Color{0, 0, 255});
    m1::draw_line(img, {-10, -10}, {-3, 100}, Color{255, 255, 0});
    m1::draw_line(img, {7.25, 7.75}, {7.25, 7.75}, Color{255, 0, 255});
    return img;
}

Image probe_m2() {
    Image img(kProbeW, kProbeH);
    // Both windings, a thin sliver, two triangles sharing an edge, one reaching outside.
    m2::fill_triangle(img, {4.5, 4.2}, {28.3, 8.9}, {10.1, 26.6}, Color{255, 80, 80});     // clockwise on screen
    m2::fill_triangle(img, {34.2, 3.1}, {40.7, 22.4}, {60.9, 6.3}, Color{80, 255, 80});    // the other winding
    m2::fill_triangle(img, {2.0, 44.0}, {60.0, 30.0}, {61.0, 31.5}, Color{80, 80, 255});   // sliver
    m2::fill_triangle(img, {20.0, 28.0}, {36.0, 28.0}, {20.0, 44.0}, Color{255, 255, 80});  // shared edge ...
    m2::fill_triangle(img, {36.0, 28.0}, {36.0, 44.0}, {20.0, 44.0}, Color{255, 80, 255});  // ... with this one
    m2::fill_triangle(img, {48.0, 30.0}, {90.0, 40.0}, {40.0, 70.0}, Color{80, 255, 255});  // clipped
    return img;
}

std::vector<double> probe_m3() {
    std::vector<double> out;
    const auto add = [&out](Vec3 v) { out.insert(out.end(), {v.x, v.y, v.z}); };
    const auto add4 = [&out](Vec4 v) { out.insert(out.end(), {v.x, v.y, v.z, v.w}); };
    const Mat4 model = m3::rotate_y(0.6);
    const Mat4 view = m3::look_at({1, 2, 4}, {0.1, 0, 0}, {0, 1, 0});
    const Mat4 projection = m3::perspective(50, 4.0 / 3.0, 0.5, 20);
    const Mat4 mvp = projection * (view * model);
    for (const auto& row : mvp.m) out.insert(out.end(), std::begin(row), std::end(row));
    const Vec3 points[] = {{0, 0, 0}, {1, -1, 0.5}, {-0.7, 0.3, 1.2}, {0.2, 0.9, -1}};
    for (const Vec3 p : points) {
        add(m3::transform_point(view * model, p));
        const Vec4 c = mvp * Vec4{p.x, p.y, p.z, 1};
        add4(c);
        add(c.w > 0 ? m3::to_screen(c, 80, 60) : Vec3{});
    }
    // A segment from in front of the camera to behind it.
    Vec4 a = mvp * Vec4{0, 0, 0, 1}, b = mvp * Vec4{2, 4, 8, 1};
    out.push_back(m3::clip_line(a, b) ? 1 : 0);
    add4(a);
    add4(b);
    // A triangle through the near plane and a side plane: vertex count and centroid (the first
    // vertex depends on the order of the planes, which is free).
    const std::vector<Vec4> clipped =
        m3::clip_polygon({mvp * Vec4{0, 0, 0, 1}, mvp * Vec4{3, 0, 0, 1}, mvp * Vec4{0, 3, 6, 1}});
    out.push_back(static_cast<double>(clipped.size()));
    Vec4 sum;
    for (const Vec4 v : clipped) sum = {sum.x + v.x, sum.y + v.y, sum.z + v.z, sum.w + v.w};
    add4(sum);
    out.push_back(m3::is_back_facing({10, 10, 0}, {20, 10, 0}, {10, 20, 0}) ? 1 : 0);
    out.push_back(m3::is_back_facing({10, 10, 0}, {10, 20, 0}, {20, 10, 0}) ? 1 : 0);
    const std::vector<int> order = m3::painter_order(
        {{{{0, 0, -2}, {1, 0, -2}, {0, 1, -2}}}, {{{0, 0, -9}, {1, 0, -8}, {0, 1, -7}}}, {{{0, 0, -1}, {1, 0, -1}, {0, 1, -1}}},
         {{{0, 0, -5}, {1, 0, -5}, {0, 1, -4}}}});
    out.push_back(static_cast<double>(order.size()));
    for (std::size_t i = 0; i < 4; ++i) out.push_back(i < order.size() ? order[i] : -1);
    return out;  // always the same count of numbers, so that the probe can say how many differ
}

Image probe_m4() {
    constexpr int kSide = 48;
    const Mode modes[] = {Mode::kFlat, Mode::kGouraud, Mode::kPerPixel, Mode::kDepth};
    raster::Mesh sphere = raster::make_uv_sphere(8, 12);
    sphere.normals.clear();  // so that prepare() runs this flavour's vertex_normals too
    const std::unique_ptr<PreparedMesh> prepared = prepare(sphere);
    View v;
    v.eye = {0.6, 0.8, 2.6};
    v.near = 0.5;
    v.far = 10;
    v.model_yaw = 0.3;
    const LightSetup light;
    Image out(kSide * 4, kSide);
    int column = 0;
    for (const Mode mode : modes) {
        Target target{Image(kSide, kSide), {}};
        draw_mesh(target, *prepared, v, light, mode, true, Color{0, 0, 0});
        if (target.color.width() == kSide && target.color.height() == kSide) {  // a student may have resized it
            for (int y = 0; y < kSide; ++y)
                for (int x = 0; x < kSide; ++x) out.set(column * kSide + x, y, target.color.at(x, y));
        }
        ++column;
    }
    return out;
}

// A small sphere in the three scene modes, side by side: bricks minified (trilinear), a
// highlight, and the sphere's shadow on the floor (a small shadow map, PCF).
Image probe_m5() {
    constexpr int kSide = 64;
    const Mode modes[] = {Mode::kTextured, Mode::kSpecular, Mode::kShadowed};
    Model model;
    model.mesh = raster::make_uv_sphere(8, 12);
    model.name = "probe sphere";
    const SceneAssets assets = make_scene_assets(model);
    const std::unique_ptr<PreparedScene> prepared = prepare_scene(assets);
    View v;
    v.eye = {0.9, 2.4, 3.6};
    v.target = {0, -0.3, 0};
    v.near = 0.5;
    v.far = 12;
    v.model_yaw = 0.3;
    const LightSetup light;
    Image out(kSide * 3, kSide);
    int column = 0;
    for (const Mode mode : modes) {
        SceneSetup setup = scene_setup(mode, assets);
        setup.shadow_resolution = 256;
        Target target{Image(kSide, kSide), {}};
        draw_scene(target, *prepared, v, light, setup, Color{0, 0, 0});
        if (target.color.width() == kSide && target.color.height() == kSide) {
            for (int y = 0; y < kSide; ++y)
                for (int x = 0; x < kSide; ++x) out.set(column * kSide + x, y, target.color.at(x, y));
        }
        ++column;
    }
    return out;
}

}  // namespace

const Flavour& flavour() {
    static const Flavour table = [] {
        Flavour f;
        f.name = VIEWER_STRINGIFY(RASTER_FLAVOUR);
        f.draw_line = [](Image& img, Vec2 a, Vec2 b, Color c) { m1::draw_line(img, a, b, c); };
        f.fill_triangle = [](Image& img, Vec2 a, Vec2 b, Vec2 c, Color color) { m2::fill_triangle(img, a, b, c, color); };
        f.wireframe = wireframe;
        f.painter = painter;
        f.shade_face = shade_face;
        f.prepare = prepare;
        f.draw_mesh = draw_mesh;
        f.prepare_scene = prepare_scene;
        f.draw_scene = draw_scene;
        f.probe_m1 = probe_m1;
        f.probe_m2 = probe_m2;
        f.probe_m3 = probe_m3;
        f.probe_m4 = probe_m4;
        f.probe_m5 = probe_m5;
        return f;
    }();
    return table;
}

}  // namespace viewer::RASTER_FLAVOUR
