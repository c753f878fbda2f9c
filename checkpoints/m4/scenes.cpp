#include "m4/scenes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "harness/checkpoint.h"
#include "harness/scene_builders.h"
#include "variant_random.h"

namespace m4cp {

Mesh sphere_mesh(int segments, bool with_normals) {
    Mesh m;
    const int rings = std::max(2, segments / 2);
    segments = std::max(3, segments);
    const double pi = std::numbers::pi;
    // Rows of vertices from the north pole (y = 1) to the south pole; each pole is one vertex.
    m.positions.push_back({0, 1, 0});
    for (int r = 1; r < rings; ++r) {
        const double theta = pi * r / rings;
        for (int s = 0; s < segments; ++s) {
            const double phi = 2 * pi * s / segments;
            m.positions.push_back({std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi)});
        }
    }
    m.positions.push_back({0, -1, 0});
    const int south = static_cast<int>(m.positions.size()) - 1;
    auto at = [segments](int ring, int s) { return 1 + (ring - 1) * segments + (s % segments); };
    // Seen from outside, with phi growing counter-clockwise about +y as seen from above.
    for (int s = 0; s < segments; ++s) m.triangles.push_back({0, at(1, s), at(1, s + 1)});
    for (int r = 1; r + 1 < rings; ++r) {
        for (int s = 0; s < segments; ++s) {
            m.triangles.push_back({at(r, s), at(r + 1, s), at(r + 1, s + 1)});
            m.triangles.push_back({at(r, s), at(r + 1, s + 1), at(r, s + 1)});
        }
    }
    for (int s = 0; s < segments; ++s) m.triangles.push_back({at(rings - 1, s), south, at(rings - 1, s + 1)});
    m.face_colors.assign(m.triangles.size(), Color{200, 200, 200});
    if (with_normals) m.normals = m.positions;
    return m;
}

Mesh quad_mesh(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Color color) {
    Mesh m;
    m.positions = {a, b, c, d};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    m.face_colors = {color, color};
    m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    return m;
}

Panel shading_panel(Shade shading, int segments, int x0, int y0, int size) {
    Panel p;
    p.camera.eye = {0.03, 0.05, 3.2};
    p.camera.target = {0.013, -0.021, 0.007};
    Item ball;
    ball.mesh = sphere_mesh(segments, shading != Shade::kFlat);
    ball.material = {210, 190, 160};
    p.items = {ball};
    p.x0 = x0;
    p.y0 = y0;
    p.w = p.h = size;
    p.shading = shading;
    p.cull = true;
    p.lights = {{false, {-0.6, -0.7, -1}, {0.6, 0.6, 0.6}}, {true, {2.5, 1.5, 2}, {0.3, 0.3, 0.3}}};
    p.timed = true;
    return p;
}

namespace {

Mesh triangle_mesh(Vec3 a, Vec3 b, Vec3 c, Color color) {
    Mesh m;
    m.positions = {a, b, c};
    m.triangles = {{0, 1, 2}};
    m.face_colors = {color};
    return m;
}

Item item(Mesh mesh) {
    Item it;
    it.mesh = std::move(mesh);
    return it;
}

// The floor y = -1 over x in [x0, x1] and z from z0 to z1, as n x n tiles of two triangles each,
// facing up.
Mesh floor_mesh(int n, double x0, double x1, double z0, double z1) {
    Mesh floor;
    for (int i = 0; i <= n; ++i) {
        for (int k = 0; k <= n; ++k) floor.positions.push_back({x0 + (x1 - x0) * k / n, -1, z0 + (z1 - z0) * i / n});
    }
    for (int i = 0; i < n; ++i) {
        for (int k = 0; k < n; ++k) {
            // a, b along this row (x growing), d, c along the next (toward z1): facing up
            const int a = i * (n + 1) + k, b = a + 1, c = a + n + 2, d = a + n + 1;
            floor.triangles.push_back({a, b, c});
            floor.triangles.push_back({a, c, d});
        }
    }
    return floor;
}

constexpr auto numbers = &cp::numbers_scene<Scene>;
constexpr auto picture = &cp::picture_scene<Scene>;

// A camera at a generic position (no vertex lands exactly on a pixel boundary).
Camera cam(Vec3 eye, Vec3 target = {0.013, -0.021, 0.007}, double near = 0.5, double far = 100) {
    return cp::camera_at<Camera>(eye, target, near, far);
}

Panel panel(Camera c, std::vector<Item> items, int x0, int y0, int w, int h, Shade shading, bool depth = true) {
    Panel p;
    p.camera = c;
    p.items = std::move(items);
    p.x0 = x0;
    p.y0 = y0;
    p.w = w;
    p.h = h;
    p.shading = shading;
    p.depth_test = depth;
    return p;
}

LightSpec directional(Vec3 travel, Vec3 intensity = {0.9, 0.9, 0.9}) { return {false, travel, intensity}; }
LightSpec point(Vec3 position, Vec3 intensity = {0.9, 0.9, 0.9}) { return {true, position, intensity}; }

const Color kRed{220, 70, 60}, kGreen{70, 190, 90}, kBlue{70, 110, 230}, kYellow{250, 220, 80}, kDim{60, 90, 200};

std::vector<Item> layered_triangles() {
    return {item(triangle_mesh({-1.4, -1.0, 1.0}, {0.9, -1.2, 1.0}, {-0.3, 1.1, 1.0}, kRed)),
            item(triangle_mesh({-0.6, -0.7, 0.0}, {1.6, -0.5, 0.0}, {0.6, 1.5, 0.0}, kGreen)),
            item(triangle_mesh({-1.7, 0.2, -1.0}, {1.2, -1.5, -1.0}, {1.3, 1.3, -1.0}, kBlue))};
}

// The pairs of nearly coplanar quads of the z-fighting checkpoint: at view distances 5, 50, 500
// and 5000, a dim quad in front and a bright one 0.2% of the distance behind it, each pair in
// its own band of the picture and tilted so its depth varies across it.
std::vector<Item> zfight_items() {
    std::vector<Item> items;
    const double distances[4] = {5, 50, 500, 5000};
    const double band[4] = {0.255, 0.085, -0.085, -0.255};  // tan of each band's angle
    for (int k = 0; k < 4; ++k) {
        const double dist = distances[k];
        const double y = dist * band[k], half_h = dist * 0.06, half_w = dist * 0.3;
        for (int layer = 0; layer < 2; ++layer) {
            const double z = -dist * (1 + 0.002 * layer);
            const double tilt = dist * 0.05;  // the top is farther than the bottom
            Item it = item(quad_mesh({-half_w, y - half_h, z + tilt}, {half_w, y - half_h, z + tilt},
                                     {half_w, y + half_h, z - tilt}, {-half_w, y + half_h, z - tilt},
                                     layer == 0 ? kDim : kYellow));
            items.push_back(it);
        }
    }
    return items;
}

std::vector<Scene> build() {
    std::vector<Scene> all;
    auto add = [&all](Scene s) { all.push_back(std::move(s)); };

    // ---- numbers ----
    add(numbers("m4.depth_keys", "Depth keys in four formats",
                "each format's key of known depths: d = (z_ndc + 1) / 2 clamped, float bits, reversed bits, 24-bit "
                "fixed point, 1/w",
                {1}, {Group::kDepthKeys}));
    add(numbers("m4.depth_test_rule", "The depth test and its tie rule",
                "nearer (smaller key) wins; an exact tie goes to the brighter color; kClearKey never passes", {2},
                {Group::kDepthTest, Group::kClearFrame}));
    add(numbers("m4.weights", "Perspective-correct weights", "p_i = (l_i / w_i) / sum of (l_j / w_j)", {3},
                {Group::kWeights}));
    add(numbers("m4.normals", "Face normals, vertex normals, the normal matrix",
                "normalized cross products; vertex normals sum the UNnormalized ones; the normal matrix is the "
                "inverse transpose",
                {4}, {Group::kNormals}));
    add(numbers("m4.lambert", "Lambert shading values",
                "B * (ambient + sum of I * max(0, N . L)), with L toward the light; clamp before rounding", {5},
                {Group::kLambert}));
    add(numbers("m4.debug_colors", "Depth and normal debug colors",
                "gray = round(255 * (1 - d)); color = round(255 * (n + 1) / 2) of the normalized normal", {6},
                {Group::kDebugColors}));
    add(numbers("m4.clip_attributes", "Clipping carries the attributes",
                "every attribute of a new vertex is interpolated with the same t as its position", {7},
                {Group::kClip}));

    // ---- the rasterizer alone ----
    {
        Scene s = picture("m4.fill_triangle", "Three triangles straight through fill_triangle",
                          "per covered pixel center: weights, key, depth test, perspective-correct colors; an exact "
                          "tie goes through depth_passes",
                          {8, 1, 2, 5}, 128, 96);
        Panel pn = panel(cam({0, 0, 5}), {}, 0, 0, 128, 96, Shade::kVertexColor);
        const Vec3 red{230, 40, 40}, green{40, 220, 60}, blue{50, 70, 240};
        // Counter-clockwise on the screen, with w from 1 to 4: the colors bend toward the near corner.
        const ScreenTri lit{{Vec3{10.3, 9.6, -0.2}, Vec3{118.4, 20.2, 0.5}, Vec3{40.2, 90.7, 0.1}}, {1, 4, 2}, {red, green, blue}};
        // Clockwise, and through the first one: each is in front along part of the crossing.
        const ScreenTri crossing{{Vec3{20.6, 80.3, 0.6}, Vec3{109.7, 85.1, -0.4}, Vec3{70.1, 5.4, 0.3}},
                                 {1.5, 1, 3},
                                 {Vec3{240, 220, 60}, Vec3{60, 220, 230}, Vec3{220, 60, 220}}};
        // The first one's geometry again in one gray: every key ties with it, and the brighter
        // color (r first) wins pixel by pixel.
        ScreenTri gray = lit;
        gray.color = {Vec3{150, 150, 150}, Vec3{150, 150, 150}, Vec3{150, 150, 150}};
        // Left of them, a vertex of w = 1e-320 (a near plane of 1e-320): 1 / w overflows, so
        // sum(l_i / w_i) is infinite wherever that vertex weighs anything, and those fragments
        // fall back to the screen weights l (the header's rule), never to NaN.
        // Its colors change slowly, so a wrong pixel inside it is wrong beyond any edge tolerance.
        const ScreenTri tiny_w{{Vec3{1.6, 24.4, 0.2}, Vec3{17.2, 56.7, 0.4}, Vec3{2.1, 94.2, 0.3}},
                               {1e-320, 1, 2},
                               {Vec3{230, 150, 60}, Vec3{120, 200, 120}, Vec3{90, 120, 230}}};
        // Over the top-right corner, most of it outside the image: the loop must stay inside it
        // (clamp the bounding box; "never writes outside the image").
        const ScreenTri corner{{Vec3{112.3, -30.6, 0.3}, Vec3{170.2, 2.3, 0.2}, Vec3{124.8, 13.1, 0.4}},
                               {1, 2, 1.5},
                               {Vec3{90, 200, 210}, Vec3{200, 200, 90}, Vec3{210, 120, 200}}};
        pn.screen_tris = {lit, crossing, gray, tiny_w, corner};
        pn.depth_probes = {{40, 30}, {70, 50}, {90, 70}};
        s.panels.push_back(pn);
        add(s);
    }

    {
        Scene s = picture("m4.shared_edges", "A grid and two fans whose shared edges run through pixel centers",
                          "a center exactly on an edge belongs to one triangle only: milestone 2's top-left rule, "
                          "in fill_triangle too",
                          {8}, 96, 96);
        Panel pn = panel(cam({0, 0, 5}), {}, 0, 0, 96, 96, Shade::kVertexColor, false);
        const Color palette[7] = {kRed, kGreen, kBlue, kYellow, kDim, Color{240, 130, 40}, Color{200, 90, 210}};
        // Every vertex on a pixel center, so every horizontal and vertical edge and every edge of
        // slope 1, 2, 1/2, 3/2 or 2/3 runs through centers: the fill rule alone decides them.
        // Both windings, in an order where the later triangle of a shared edge is sometimes the
        // one the rule gives its centers to and sometimes not.
        auto add_tri = [&](Vec3 a, Vec3 b, Vec3 c) {
            const Color col = palette[pn.screen_tris.size() % 7];
            const Vec3 v{double(col.r), double(col.g), double(col.b)};
            const bool flip = pn.screen_tris.size() % 3 == 1;
            pn.screen_tris.push_back({{a, flip ? c : b, flip ? b : c}, {1, 1.5, 2}, {v, v, v}});
        };
        // A grid of 5 x 5 cells of 8 pixels, each cut along one of its diagonals.
        for (int j = 0; j < 5; ++j) {
            for (int i = 0; i < 5; ++i) {
                const double x0 = 4.5 + 8 * i, y0 = 4.5 + 8 * j, x1 = x0 + 8, y1 = y0 + 8;
                if ((i + j) % 2 == 0) {
                    add_tri({x0, y0, 0}, {x1, y0, 0}, {x1, y1, 0});
                    add_tri({x0, y0, 0}, {x1, y1, 0}, {x0, y1, 0});
                } else {
                    add_tri({x1, y0, 0}, {x0, y1, 0}, {x0, y0, 0});
                    add_tri({x1, y0, 0}, {x1, y1, 0}, {x0, y1, 0});
                }
            }
        }
        // Two fans of twelve triangles around a center.
        const int spokes[2][12][2] = {
            {{20, 0}, {20, 10}, {10, 20}, {0, 20}, {-10, 20}, {-20, 10}, {-20, 0}, {-20, -10}, {-10, -20}, {0, -20}, {10, -20}, {20, -10}},
            {{18, 0}, {18, 12}, {12, 18}, {0, 18}, {-12, 18}, {-18, 12}, {-18, 0}, {-18, -12}, {-12, -18}, {0, -18}, {12, -18}, {18, -12}}};
        const Vec3 centers[2] = {{71.5, 25.5, 0}, {49.5, 73.5, 0}};
        for (int f = 0; f < 2; ++f) {
            for (int k = 0; k < 12; ++k) {
                const auto& a = spokes[f][k];
                const auto& b = spokes[f][(k + 1) % 12];
                const Vec3 c = centers[f];
                add_tri(c, c + Vec3{double(a[0]), double(a[1]), 0}, c + Vec3{double(b[0]), double(b[1]), 0});
            }
        }
        s.panels.push_back(pn);
        s.checks.fill_rule = true;
        add(s);
    }

    // ---- occlusion ----
    {
        Scene s = picture("m4.occlusion_order", "Three overlapping triangles, drawn in two orders",
                          "the depth test must decide, not the drawing order: test, then write", {8, 9, 2}, 192, 96);
        for (int p = 0; p < 2; ++p) {
            Panel pn = panel(cam({0.05, 0.1, 5}), layered_triangles(), 96 * p, 0, 96, 96, Shade::kFaceColor);
            pn.camera.near = 1;
            pn.camera.far = 20;
            pn.frames = {p == 0 ? std::vector<int>{0, 2, 1} : std::vector<int>{1, 2, 0}};
            s.panels.push_back(pn);
        }
        s.checks.same_panels = {{0, 1}};
        add(s);
    }
    {
        Scene s = picture("m4.interpenetrating", "Two triangles that pass through each other",
                          "per pixel the nearer surface wins, so they split along the line where they cross", {8, 9},
                          192, 96);
        const std::vector<Item> items = {
            item(triangle_mesh({-1.6, -1.1, -1}, {1.5, -1.2, -1}, {0.1, 1.3, 1}, kRed)),
            item(triangle_mesh({-1.4, -1.0, 1}, {1.6, -0.9, 1}, {-0.1, 1.25, -1}, kBlue))};
        for (int p = 0; p < 2; ++p) {
            Panel pn = panel(cam({0.4, 0.3, 5}), items, 96 * p, 0, 96, 96, Shade::kFaceColor);
            pn.frames = {p == 0 ? std::vector<int>{0, 1} : std::vector<int>{1, 0}};
            s.panels.push_back(pn);
        }
        s.checks.same_panels = {{0, 1}};
        add(s);
    }
    {
        Scene s = picture("m4.depth_view", "Depth as gray levels, and the keys at known pixels",
                          "gray = round(255 * (1 - d)), d interpolated with screen-space weights; the 1/w key of "
                          "the pixel's own w, 1 / sum(l_i / w_i)",
                          {8, 6, 1}, 192, 96);
        Panel pn = panel(cam({0.3, 1.6, 4.2}, {0.01, -0.2, 0.02}, 2.5, 8), {}, 0, 0, 96, 96, Shade::kDepthView);
        pn.items.push_back(item(quad_mesh({-1.8, -0.8, 1.7}, {1.8, -0.8, 1.7}, {1.8, -0.8, -1.9}, {-1.8, -0.8, -1.9}, kRed)));
        Item box = item(sphere_mesh(12, true));
        box.position = {0.2, 0.1, 0.1};
        box.size = {0.7, 0.7, 0.7};
        pn.items.push_back(box);
        // Probes only where the key is pinned: on the sphere, which lies inside the view volume.
        // The floor is clipped, and a clipped polygon's fan (hence each fan triangle's plane
        // through vertices snapped to 1/16 pixel) depends on the start vertex and the plane order
        // the header leaves free: its keys move by thousands of float steps between correct
        // clippers (the picture's 3 gray levels absorb that).
        pn.depth_probes = {{48, 50}, {50, 30}, {53, 41}, {45, 40}, {61, 38}, {57, 48}};
        s.panels.push_back(pn);
        // Right: a floor from w = 3 to w = 12 in the 1/w format, wholly inside the view volume
        // (so its two triangles are the mesh's own), its keys read back well inside each
        // triangle, where w interpolated with the screen weights is 25% to 60% too far.
        Panel floor = panel(cam({0.05, 0.9, 3.2}, {0.0, -0.6, -2.0}, 0.5, 20), {}, 96, 0, 96, 96, Shade::kDepthView);
        floor.format = Format::kInverseW;
        floor.items.push_back(item(quad_mesh({-0.9, -0.8, 0.4}, {0.9, -0.8, 0.4}, {1.5, -0.8, -9}, {-1.5, -0.8, -9}, kRed)));
        floor.depth_probes = {{58, 68}, {33, 56}, {40, 46}};
        s.panels.push_back(floor);
        add(s);
    }
    {
        Scene s = picture("m4.clear_between_frames", "Two frames in one buffer: the second must not see the first",
                          "clear_frame resets every key to kClearKey before each frame", {2, 9}, 96, 96);
        Panel pn = panel(cam({0.02, 0.03, 5}), {}, 0, 0, 96, 96, Shade::kFaceColor);
        pn.items.push_back(item(quad_mesh({-3, -3, 2.5}, {3, -3, 2.5}, {3, 3, 2.5}, {-3, 3, 2.5}, kGreen)));
        pn.items.push_back(item(triangle_mesh({-1.3, -1.1, -1}, {1.4, -0.8, -1}, {0.1, 1.4, -1}, kYellow)));
        pn.frames = {{0}, {1}};
        s.panels.push_back(pn);
        add(s);
    }

    // ---- perspective-correct interpolation ----
    for (int correct = 1; correct >= 0; --correct) {
        Scene s = picture(correct ? "m4.perspective_checker" : "m4.screen_space_checker",
                          correct ? "A checkerboard floor, interpolated perspective-correctly"
                                  : "The same floor with screen-space weights (the lesson's wrong way)",
                          correct ? "interpolate u/w, v/w and 1/w linearly on the screen, then divide"
                                  : "with needs.perspective_correct false, the weights are the screen weights l_i",
                          correct ? std::vector<int>{3, 8, 9} : std::vector<int>{8, 9}, 128, 96);
        // The whole floor is inside the view volume: the screen-space picture depends on how a
        // polygon is fanned into triangles, and clipping (whose plane order is free) would
        // change that; the two triangles of the quad are the same for everyone.
        Panel pn = panel(cam({0.05, 0.9, 4.5}, {0.02, -0.9, -3}, 0.5, 50), {}, 0, 0, 128, 96, Shade::kChecker, false);
        pn.items.push_back(item(quad_mesh({-1.5, -1, 1.5}, {1.5, -1, 1.5}, {1.5, -1, -9}, {-1.5, -1, -9}, kRed)));
        pn.perspective_correct = correct;
        s.panels.push_back(pn);
        s.checks.checker_error = true;
        s.demo = correct;
        add(s);
    }

    // ---- lighting ----
    {
        Scene s = picture("m4.flat_sphere", "A sphere, flat-shaded: one light value per face",
                          "face normal of the world positions, lit at the centroid", {5, 4, 9}, 96, 96);
        // Turned, so that a face normal of the model-space positions lights the wrong faces.
        Item ball = item(sphere_mesh(12, false));
        ball.axis = {1, 0.4, 0.2};
        ball.angle = 0.9;
        Panel pn = panel(cam({0.03, 0.05, 3.2}), {ball}, 0, 0, 96, 96, Shade::kFlat);
        pn.cull = true;
        pn.lights = {directional({-0.6, -0.7, -1})};
        s.panels.push_back(pn);
        s.checks.sphere_error = true;
        add(s);
    }
    {
        Scene s = picture("m4.gouraud_sphere", "A sphere, Gouraud-shaded: lit per vertex, colors interpolated",
                          "light each vertex once with its normal; interpolate the lit colors perspective-correctly",
                          {5, 4, 8, 9}, 96, 96);
        // Turned and moved, so that model-space normals or positions light the wrong vertices.
        Item ball = item(sphere_mesh(16, false));
        ball.axis = {0.3, 1, 0.2};
        ball.angle = 0.8;
        ball.position = {0.25, -0.15, 0};
        Panel pn = panel(cam({0.03, 0.05, 3.2}), {ball}, 0, 0, 96, 96, Shade::kGouraud);
        pn.cull = true;
        pn.lights = {directional({-0.6, -0.7, -1}, {0.5, 0.5, 0.5}), point({2.5, -1.5, 2}, {0.4, 0.3, 0.2})};
        s.panels.push_back(pn);
        s.checks.sphere_error = true;
        add(s);
    }
    {
        Scene s = picture("m4.per_pixel_sphere", "A coarse sphere lit per pixel by a point light",
                          "interpolate the normal, NORMALIZE it, then light; the world position too for a point light",
                          {8, 5, 4, 3}, 96, 96);
        // Turned and moved, so that a model-space position aims the point light at the wrong place.
        Item ball = item(sphere_mesh(8, false));
        ball.axis = {1, 0.2, 0.5};
        ball.angle = 0.7;
        ball.position = {-0.3, 0.2, 0.1};
        Panel pn = panel(cam({0.03, 0.05, 3.2}), {ball}, 0, 0, 96, 96, Shade::kPerPixel);
        pn.cull = true;
        pn.lights = {point({2, 2.2, 2.5})};
        s.panels.push_back(pn);
        s.checks.sphere_error = true;
        s.demo = true;
        add(s);
    }
    {
        Scene s = picture("m4.light_behind", "Light from behind the surface: ambient only",
                          "max(0, N . L): a light behind the surface adds nothing", {5, 9}, 192, 96);
        for (int p = 0; p < 2; ++p) {
            Panel pn = panel(cam({0.02, 0.04, 4}), {}, 96 * p, 0, 96, 96, p == 0 ? Shade::kFlat : Shade::kPerPixel);
            pn.items.push_back(item(quad_mesh({-1.5, -1.4, 0}, {1.6, -1.5, 0}, {1.5, 1.4, 0}, {-1.4, 1.5, 0}, kRed)));
            pn.items[0].material = {200, 160, 90};
            pn.ambient = {0.25, 0.25, 0.25};
            pn.lights = {directional({0.2, 0.1, 1}), point({0.3, 0.2, -2})};
            s.panels.push_back(pn);
        }
        add(s);
    }
    {
        Scene s = picture("m4.nonuniform_scale",
                          "A squashed sphere: normals need the inverse transpose (right: normalized, then interpolated)",
                          "the model matrix tilts normals the wrong way under non-uniform scale, and the normal matrix "
                          "changes their lengths: normalize each one",
                          {4, 5, 9}, 192, 96);
        Item it = item(sphere_mesh(24, true));
        it.size = {1.7, 0.55, 1};
        it.axis = {0, 0, 1};
        it.angle = 0.5;
        Panel pn = panel(cam({0.03, 0.05, 4}), {it}, 0, 0, 96, 96, Shade::kPerPixel);
        pn.cull = true;
        pn.lights = {directional({-1, -1.2, -0.4})};
        s.panels.push_back(pn);
        // Right: a quad with its own normals, squashed harder, as normal colors. The normal
        // matrix shortens normals along x and lengthens those along y, so normals left at the
        // lengths it gives them and then interpolated lean toward the longer ones.
        Item quad = item(quad_mesh({-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, kRed));
        quad.mesh.normals = {{-0.8, -0.15, 0.5}, {0.75, -0.2, 0.55}, {0.15, 0.85, 0.5}, {-0.2, 0.8, 0.45}};
        quad.size = {1.5, 0.5, 1};
        quad.axis = {0, 0, 1};
        quad.angle = 0.2;
        Panel normals = panel(pn.camera, {quad}, 96, 0, 96, 96, Shade::kNormalView);
        s.panels.push_back(normals);
        s.checks.normal_lengths = true;
        add(s);
    }
    {
        Scene s = picture("m4.grazing_light", "A light exactly along the floor: the floor gets ambient only",
                          "N . L = 0 exactly: no light, and no NaN", {5, 9}, 192, 96);
        for (int p = 0; p < 2; ++p) {
            Panel pn = panel(cam({0.02, 1.2, 4}, {0.01, -0.4, 0}), {}, 96 * p, 0, 96, 96,
                             p == 0 ? Shade::kFlat : Shade::kPerPixel);
            pn.items.push_back(item(quad_mesh({-2, -1, 2}, {2, -1, 2}, {2, -1, -2}, {-2, -1, -2}, kRed)));
            Item ball = item(sphere_mesh(12, true));
            ball.size = {0.6, 0.6, 0.6};
            pn.items.push_back(ball);
            pn.ambient = {0.2, 0.2, 0.2};
            pn.lights = {directional({1, 0, 0})};
            s.panels.push_back(pn);
        }
        add(s);
    }
    {
        Scene s = picture("m4.overflow", "Too much light: colors saturate at white, never wrap",
                          "clamp each channel to [0, 255] before converting to 8 bits", {5, 9}, 192, 96);
        for (int p = 0; p < 2; ++p) {
            Item ball = item(sphere_mesh(16, true));
            ball.material = {220, 180, 120};
            Panel pn = panel(cam({0.03, 0.05, 3.2}), {ball}, 96 * p, 0, 96, 96, p == 0 ? Shade::kFlat : Shade::kPerPixel);
            pn.cull = true;
            pn.ambient = {0.3, 0.3, 0.3};
            pn.lights = {directional({-0.5, -0.6, -1}, {1.5, 1.5, 1.5}), point({-2, 1, 2}, {1.2, 1.2, 1.2})};
            s.panels.push_back(pn);
        }
        add(s);
    }
    {
        Scene s = picture("m4.flat_clipped", "A flat-shaded floor cut by the view volume, under a low point light",
                          "a clipped triangle is still ONE face: lit once, at the centroid of its three world "
                          "positions, whatever fan its polygon is cut into",
                          {9, 5, 4, 7}, 192, 96);
        // Left: two big triangles, each cut by the near plane and the sides into a polygon of
        // several fan triangles. A point light just above the floor gives every point of it
        // another light value, so lighting each fan triangle at its own centroid paints every
        // fan triangle in its own color. Right: the same floor as nine tiles, all clipped but
        // the far middle one.
        for (int p = 0; p < 2; ++p) {
            Panel pn = panel(cam({0.02, 0.7, 3}, {0.01, -0.6, -1.5}), {}, 96 * p, 0, 96, 96, Shade::kFlat);
            Item it = item(floor_mesh(p == 0 ? 1 : 3, -5, 5, 5, -7));
            it.material = {220, 200, 170};
            pn.items.push_back(it);
            pn.ambient = {0.08, 0.08, 0.08};
            pn.lights = {point({0.4, -0.4, 0.3}, {1.1, 1.0, 0.9})};
            s.panels.push_back(pn);
        }
        add(s);
    }
    {
        Scene s = picture("m4.point_light_floor",
                          "A floor lit per pixel by a low point light: world positions interpolated perspective-correctly",
                          "interpolate the world position with the perspective-correct weights p_i, like every "
                          "attribute: with the screen weights l_i a pixel is lit as if it were another point of "
                          "the floor (nearer the camera), and the pool of light slides toward the viewer",
                          {8, 3, 9, 5, 4, 7}, 192, 96);
        // Left: the floor as two triangles reaching far into the distance, where screen and
        // perspective-correct weights differ most (with the screen weights the pool of light
        // breaks up along the diagonal the two share). Right: the same floor as 6 x 6 tiles,
        // where they differ less, though still beyond the tolerance near the light.
        for (int p = 0; p < 2; ++p) {
            Panel pn = panel(cam({0.03, 0.3, 3}, {0.02, -0.5, -2}), {}, 96 * p, 0, 96, 96, Shade::kPerPixel);
            Mesh floor = floor_mesh(p == 0 ? 1 : 6, -4, 4, 3, -25);
            floor.normals.assign(floor.positions.size(), Vec3{0, 1, 0});
            Item it = item(floor);
            it.material = {210, 200, 180};
            pn.items.push_back(it);
            pn.cull = true;
            pn.ambient = {0.05, 0.05, 0.05};
            pn.lights = {point({0.2, -0.55, -3}, {1.4, 1.3, 1.1})};
            s.panels.push_back(pn);
        }
        add(s);
    }
    {
        Scene s = picture("m4.normal_view", "Normals as colors (right: the ball seen from the side and above)",
                          "round(255 * (n + 1) / 2) of the WORLD-space normal, whatever the camera",
                          {6, 4, 9}, 192, 96);
        Item ball = item(sphere_mesh(16, false));
        ball.axis = {1, 0.4, 0};
        ball.angle = 0.6;
        Panel pn = panel(cam({0.03, 0.05, 3.2}), {ball}, 0, 0, 96, 96, Shade::kNormalView);
        pn.cull = true;
        s.panels.push_back(pn);
        // Right: the same ball seen from the side and above. The colors are those of the WORLD
        // normals, whatever the camera: a camera looking down -z hardly turns them, this one
        // turns view-space normals far from the world's.
        Panel side = panel(cam({2.6, 1.9, 0.9}), {ball}, 96, 0, 96, 96, Shade::kNormalView);
        side.cull = true;
        s.panels.push_back(side);
        add(s);
    }

    {
        Scene s = picture("m4.shading_error_time", "Error against run time: flat, Gouraud, per-pixel on four spheres",
                          "each sphere's error against a perfect sphere must be as small as the reference's",
                          {9, 8, 5}, 256, 192);
        const Shade rows[3] = {Shade::kFlat, Shade::kGouraud, Shade::kPerPixel};
        for (int r = 0; r < 3; ++r) {
            for (int k = 0; k < 4; ++k) s.panels.push_back(shading_panel(rows[r], kChartSegments[k], 64 * k, 64 * r, 64));
        }
        s.checks.shading_chart = true;
        s.demo = true;
        add(s);
    }

    // ---- stiff and extreme cases ----
    {
        Scene s = picture("m4.zfight_formats", "Near 0.001, far 100000: z-fighting in four depth formats",
                          "reversed-Z and 1/w keep precision far away; float z and 24-bit fixed point do not (the "
                          "keys of depth_key, TODO 1, from z_ndc interpolated with the SCREEN weights in "
                          "fill_triangle, TODO 8)",
                          {1, 8, 9}, 384, 96);
        const Format formats[4] = {Format::kFloatZ, Format::kReversedZ, Format::kFixed24, Format::kInverseW};
        for (int p = 0; p < 4; ++p) {
            Panel pn = panel(cam({0.0003, 0.0002, 0}, {0.0003, 0.0002, -1}, 1e-3, 1e5), zfight_items(), 96 * p, 0, 96,
                             96, Shade::kFaceColor);
            pn.camera.fovy = 40;
            pn.format = formats[p];
            s.panels.push_back(pn);
        }
        s.checks.zfight = true;
        s.demo = true;
        add(s);
    }
    {
        Scene s = picture("m4.coplanar", "Exactly coplanar triangles: the pinned tie rule decides, in either order",
                          "an exact tie of keys goes to the brighter color, whatever the order", {2, 8}, 192, 96);
        for (int p = 0; p < 2; ++p) {
            Panel pn = panel(cam({0.02, 0.03, 5}), {}, 96 * p, 0, 96, 96, Shade::kFaceColor);
            pn.camera.ortho = true;
            pn.items.push_back(item(triangle_mesh({-1.5, -1.2, 0.3}, {1.3, -1.4, 0.3}, {0.2, 1.5, 0.3}, kRed)));
            pn.items.push_back(item(triangle_mesh({-1.5, -1.2, 0.3}, {1.3, -1.4, 0.3}, {0.2, 1.5, 0.3}, kGreen)));
            pn.items.push_back(item(triangle_mesh({-1.7, 0.4, 0.3}, {1.6, 0.2, 0.3}, {1.7, 1.7, 0.3}, kBlue)));
            pn.frames = {p == 0 ? std::vector<int>{0, 1, 2} : std::vector<int>{2, 1, 0}};
            s.panels.push_back(pn);
        }
        s.checks.same_panels = {{0, 1}};
        add(s);
    }
    {
        Scene s = picture("m4.degenerate_normals",
                          "Zero-area and needle triangles in a lit mesh: no NaN (right: back faces culled)",
                          "a zero normal stays zero and gives the ambient color; a zero-area triangle is a back face",
                          {4, 5, 8, 9}, 192, 96);
        Mesh m;
        m.positions = {{-1.5, -1.2, 0}, {1.4, -1.3, 0.2}, {0.1, 1.4, -0.1}, {1.4, -1.3, 0.2},  // 3 repeats 1
                       {-1.5, -1.2, 0}, {0.1, 1.4, -0.1},  {1.8, 1.2, 0.1},  {1.8000001, 1.2, 0.1},
                       {-1.6, 1.3, 0.4}};
        m.triangles = {{0, 1, 2}, {1, 3, 6}, {4, 0, 4}, {2, 6, 7}, {5, 8, 0}, {6, 7, 6}, {0, 2, 8}};
        m.face_colors.assign(m.triangles.size(), kRed);
        Panel pn = panel(cam({0.02, 0.03, 4}), {item(m)}, 0, 0, 96, 96, Shade::kPerPixel);
        pn.lights = {point({1, 1, 3})};
        s.panels.push_back(pn);
        // Right: the same mesh with back faces culled. A fan triangle of zero area (triangles 1, 2
        // and 5 repeat a position) is a back face too (signed area >= 0): culled, and counted.
        Panel culled = pn;
        culled.x0 = 96;
        culled.cull = true;
        s.panels.push_back(culled);
        add(s);
    }
    {
        Scene s = picture("m4.near_eye",
                          "A vertex almost at the eye, one behind it: clipped, with attributes (right: back faces culled)",
                          "clip in clip space with every attribute; perspective weights stay finite; cull each fan "
                          "triangle after clipping, by its own screen positions",
                          {7, 3, 9}, 192, 96);
        Mesh m;
        m.positions = {{-0.004, -0.003, -0.0101}, {1.5, -1.2, -3}, {-1.2, 1.6, -4},   // one just past near
                       {0.0, 0.0, 0.0},           {-2.0, -1.5, -5}, {2.2, -0.3, -6},  // one AT the eye
                       {0.2, 0.1, 0.5},           {1.8, 1.5, -4.5}, {-1.5, 0.2, -3.5}};  // one behind
        m.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}};
        m.vertex_colors = {{255, 40, 40}, {40, 255, 40}, {40, 40, 255}, {255, 255, 0}, {0, 255, 255},
                           {255, 0, 255}, {255, 255, 255}, {250, 120, 0}, {0, 120, 250}};
        Panel pn = panel(cam({0, 0, 0}, {0.001, 0.0007, -1}, 0.01, 50), {item(m)}, 0, 0, 96, 96, Shade::kVertexColor);
        s.panels.push_back(pn);
        // Right: back faces culled, the triangle behind the eye wound to face it. Culling must
        // keep both clipped triangles, which it does only on the fan triangles' own screen
        // positions: culling before clipping (a vertex behind the eye flips the projected
        // winding), or a fan that reverses the polygon's winding, drops them.
        Mesh facing = m;
        facing.triangles = {{0, 1, 2}, {6, 8, 7}};
        Panel culled = panel(pn.camera, {item(facing)}, 96, 0, 96, 96, Shade::kVertexColor);
        culled.cull = true;
        s.panels.push_back(culled);
        add(s);
    }
    {
        Scene s = picture("m4.extreme_input", "NaN, infinite and huge coordinates beside one good triangle",
                          "a non-finite clip coordinate drops its triangle; huge ones are clipped, never overflow",
                          {9, 7, 8}, 96, 96);
        const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
        Mesh m;
        // The good triangle has vertices of its own: a vertex shared with a non-finite triangle
        // would get a non-finite normal sum, hence the zero normal (ambient only), by the rule.
        m.positions = {{-1.2, -1.0, 0}, {1.3, -1.1, 0}, {0.1, 1.2, 0},  // good
                       {nan, 0, 0},     {0.5, 0.5, 0},  {inf, 1, 0},     // non-finite
                       {1e30, -1, 0.2}, {-1e30, 1e29, 0.1}, {0.3, 1e31, -0.2},  // huge
                       {0.4, 0.3, 1e300}, {-0.4, 0.2, -1e300},  // far beyond both planes
                       {-1.2, -1.0, 0}, {1.3, -1.1, 0}, {0.1, 1.2, 0}};  // the good ones again
        m.triangles = {{0, 1, 2}, {3, 4, 11}, {5, 12, 4}, {6, 7, 8}, {9, 10, 13}, {0, 1, 40}, {-3, 1, 2}};
        m.face_colors.assign(m.triangles.size(), kGreen);
        Panel pn = panel(cam({0.02, 0.03, 4}), {item(m)}, 0, 0, 96, 96, Shade::kPerPixel);
        pn.lights = {directional({-0.3, -0.4, -1}), point({0.5, 0.5, 2})};
        s.panels.push_back(pn);
        add(s);
    }

    {
        Scene s = picture("m4.missing_face_colors", "Fewer face colors than triangles: the rest are white",
                          "a triangle without a face color (past the end of face_colors, or none at all) is drawn "
                          "white",
                          {9, 8}, 96, 96);
        // A hexagon of six triangles with six face colors for its eight faces, and a quad with
        // none. Face 1 lies far outside the view: wholly clipped, it draws nothing, yet it owns
        // face color 1. Face 4 faces away, behind the hexagon (culled; drawn, it would be
        // hidden): it owns face color 4. So the faces after each keep their own indices; a count
        // of the faces drawn so far, or of those not culled, shifts the later colors.
        Mesh hexagon;
        hexagon.positions.push_back({-0.5, 0.2, 0});
        for (int k = 0; k < 6; ++k) {
            const double a = std::numbers::pi * (0.1 + k / 3.0);
            hexagon.positions.push_back({-0.5 + 1.3 * std::cos(a), 0.2 + 1.3 * std::sin(a), 0});
        }
        hexagon.positions.push_back({-40, -1, 0});
        hexagon.positions.push_back({-38, -1, 0});
        hexagon.positions.push_back({-39, 1, 0});
        hexagon.positions.push_back({-0.9, -0.1, -0.3});  // clockwise on the screen: a back face
        hexagon.positions.push_back({-0.5, 0.6, -0.3});
        hexagon.positions.push_back({-0.1, -0.1, -0.3});
        for (int k = 0; k < 6; ++k) {
            hexagon.triangles.push_back({0, 1 + k, 1 + (k + 1) % 6});
            if (k == 0) hexagon.triangles.push_back({7, 8, 9});
            if (k == 2) hexagon.triangles.push_back({10, 11, 12});
        }
        hexagon.face_colors = {kRed, kYellow, kGreen, kBlue, Color{200, 90, 210}, Color{240, 130, 40}};
        Mesh quad = quad_mesh({0.6, -1.6, -0.5}, {1.7, -1.5, -0.5}, {1.6, -0.4, -0.5}, {0.5, -0.5, -0.5}, kRed);
        quad.face_colors.clear();
        Panel pn = panel(cam({0.02, 0.03, 4.5}), {item(hexagon), item(quad)}, 0, 0, 96, 96, Shade::kFaceColor);
        pn.cull = true;
        s.panels.push_back(pn);
        add(s);
    }

    // ---- only what a scene needs ----
    {
        Scene s = picture("m4.needs", "One sphere, five sets of needs: what each stage costs",
                          "allocate the depth buffer, compute normals and interpolate attributes only when needed",
                          {9, 2, 8}, 360, 72);
        // Per-pixel twice: with a point light (normal and world position interpolated), and
        // with the directional light alone (the normal only).
        const Shade modes[5] = {Shade::kFaceColor, Shade::kFaceColor, Shade::kGouraud, Shade::kPerPixel, Shade::kPerPixel};
        for (int p = 0; p < 5; ++p) {
            Item ball = item(sphere_mesh(16, false));
            for (std::size_t f = 0; f < ball.mesh.face_colors.size(); ++f) {
                ball.mesh.face_colors[f] = (f % 3 == 0) ? kRed : (f % 3 == 1) ? kGreen : kBlue;
            }
            Panel pn = panel(cam({0.03, 0.05, 3.2}), {ball}, 72 * p, 0, 72, 72, modes[p], p > 0);
            pn.lights = {directional({-0.6, -0.7, -1}, {0.6, 0.6, 0.6})};
            if (p == 3) pn.lights.push_back(point({2, 2, 2}, {0.3, 0.3, 0.3}));
            s.panels.push_back(pn);
        }
        add(s);
    }
    return all;
}

// ---- scene variants (grading): see "Scene variants (grading)" in checkpoints/README.md ----

using Rng = cp::VariantRng;


Scene vary(const Scene& pub, Rng& rng) {
    Scene s = pub;
    const std::string& id = s.id;
    auto is = [&](std::initializer_list<const char*> names) {
        return std::any_of(names.begin(), names.end(), [&](const char* n) { return id == n; });
    };
    // The camera moved a little (the same move for every panel), and the sphere scenes' models
    // turned: the same ideas on other numbers.
    if (is({"m4.occlusion_order", "m4.interpenetrating", "m4.depth_view", "m4.clear_between_frames", "m4.flat_sphere",
            "m4.gouraud_sphere", "m4.per_pixel_sphere", "m4.nonuniform_scale", "m4.normal_view", "m4.needs",
            "m4.overflow", "m4.perspective_checker", "m4.screen_space_checker", "m4.light_behind",
            "m4.coplanar", "m4.flat_clipped", "m4.missing_face_colors", "m4.point_light_floor"})) {
        const Vec3 d{rng.uniform(-12, 12) / 100.0, rng.uniform(-12, 12) / 100.0, rng.uniform(-12, 12) / 100.0};
        for (Panel& p : s.panels) p.camera.eye = p.camera.eye + d;
    }
    // The ready-made triangles moved by up to two pixels, the same move for the k-th vertex of
    // each (the tie keeps its two identical triangles). A fill-rule scene moves all of its
    // vertices by the same whole pixels: they stay on pixel centers and shared.
    for (Panel& p : s.panels) {
        if (p.screen_tris.empty()) continue;
        if (s.checks.fill_rule) {
            const Vec3 whole{double(rng.uniform(-2, 2)), double(rng.uniform(-2, 2)), 0};
            for (ScreenTri& t : p.screen_tris) {
                for (Vec3& v : t.screen) v = v + whole;
            }
            continue;
        }
        std::array<Vec3, 3> move;
        for (Vec3& m : move) m = {rng.uniform(-200, 200) / 100.0, rng.uniform(-200, 200) / 100.0, 0};
        for (ScreenTri& t : p.screen_tris) {
            for (int k = 0; k < 3; ++k) t.screen[std::size_t(k)] = t.screen[std::size_t(k)] + move[std::size_t(k)];
        }
    }
    if (is({"m4.flat_sphere", "m4.gouraud_sphere", "m4.per_pixel_sphere", "m4.nonuniform_scale", "m4.normal_view",
            "m4.overflow", "m4.needs"})) {
        const double turn = rng.uniform(-30, 30) / 100.0;
        for (Panel& p : s.panels) {
            for (Item& it : p.items) it.angle += turn;
            for (LightSpec& l : p.lights) l.vector.x += rng.uniform(-20, 20) / 100.0;
        }
    }
    return s;
}

const std::vector<Scene>& public_scenes() {
    static const std::vector<Scene> all = build();
    return all;
}

// Made on first use: the checkpoints register (and list the scenes) during static initialization.
cp::SceneVariants<Scene>& variants() {
    static cp::SceneVariants<Scene> all(public_scenes, vary);
    return all;
}

}  // namespace

std::vector<KeyCase> key_cases() {
    std::vector<KeyCase> cases;
    const double zs[] = {-1, 1, 0, 0.3, -0.99, 0.999999, 1.5, -2};
    for (int f = 0; f < 4; ++f) {
        for (double z : zs) cases.push_back({f, z, 0.7 + z});
    }
    cases.push_back({3, 0.5, 0});
    cases.push_back({3, 0.5, -1});
    cases.push_back({0, std::numeric_limits<double>::quiet_NaN(), 1});
    cases.push_back({2, std::numeric_limits<double>::quiet_NaN(), 1});
    // NaN in the other two formats, and a 1/w key of a w that is not finite: kClearKey.
    cases.push_back({1, std::numeric_limits<double>::quiet_NaN(), 1});
    cases.push_back({3, std::numeric_limits<double>::quiet_NaN(), 1});
    cases.push_back({3, 0.5, std::numeric_limits<double>::infinity()});
    cases.push_back({3, 0.5, std::numeric_limits<double>::quiet_NaN()});
    if (variant_seed() != 0) {
        Rng rng(variant_seed(), "m4.depth_keys");
        for (int k = 0; k < 12; ++k) cases.push_back({k % 4, rng.uniform(-999, 999) / 1000.0, rng.uniform(1, 5000) / 100.0});
    }
    return cases;
}

std::vector<ClipCase> clip_cases() {
    std::vector<ClipCase> cases = {
        // entirely inside
        {{{{-0.5, -0.5, 0.2, 1}, {0.5, -0.4, 0.1, 1}, {0, 0.6, -0.3, 1}}}, {{{255, 0, 0}, {0, 255, 0}, {0, 0, 255}}},
         {{{0, 0}, {1, 0}, {0, 1}}}},
        // one vertex behind the near plane
        {{{{-0.5, -0.5, 1.5, 2}, {0.5, -0.4, 1.8, 2}, {0, 0.5, -3, -1}}}, {{{255, 0, 0}, {0, 255, 0}, {0, 0, 255}}},
         {{{0, 0}, {1, 0}, {0.5, 1}}}},
        // across the right and top planes
        {{{{0.2, 0.1, 0, 1}, {2.5, 0.3, 0.1, 1}, {0.4, 3, 0.2, 1}}}, {{{10, 20, 30}, {200, 40, 60}, {90, 250, 10}}},
         {{{0.1, 0.2}, {0.9, 0.3}, {0.4, 0.8}}}},
        // entirely outside (left)
        {{{{-3, 0, 0, 1}, {-2, 0.5, 0, 1}, {-2.5, -0.5, 0, 1}}}, {{{1, 2, 3}, {4, 5, 6}, {7, 8, 9}}}, {{{0, 0}, {1, 0}, {0, 1}}}},
        // one vertex ON the right plane (x = w), one inside, one outside: a vertex on a plane is
        // inside it, so it stays, and the edge between it and the outside vertex adds a new
        // vertex at the very same point (4 vertices, the first and the last equal)
        {{{{1, 0.2, 0.1, 1}, {0.2, -0.3, 0.2, 1}, {1.8, 0.6, 0, 1}}}, {{{255, 0, 0}, {0, 255, 0}, {0, 0, 255}}},
         {{{0, 0}, {1, 0}, {0, 1}}}},
    };
    if (variant_seed() != 0) {
        // Each vertex times its own positive factor: the same point of projective space.
        Rng rng(variant_seed(), "m4.clip_attributes");
        for (auto& c : cases) {
            for (Vec4& v : c.clip) v = v * (rng.uniform(50, 200) / 100.0);
        }
    }
    return cases;
}

std::vector<WeightCase> weight_cases() {
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    return {{{0.2, 0.3, 0.5}, {1, 2, 4}},
            {{1, 0, 0}, {3, 1, 1}},
            {{0.25, 0.25, 0.5}, {2, 2, 2}},
            {{0.6, 0.3, 0.1}, {0.01, 10, 100}},
            // A w of 0, one whose 1 / w overflows, a NaN: the screen weights come back.
            {{0.2, 0.3, 0.5}, {0, 1, 1}},
            {{0.5, 0.5, 0}, {1e-320, 1, 1}},
            {{0.3, 0.3, 0.4}, {kNaN, 1, 1}}};
}

std::vector<LambertCase> lambert_cases() {
    const Color base{200, 150, 100};
    constexpr double kInf = std::numeric_limits<double>::infinity();
    std::vector<LambertCase> cases = {
        {{0.1, 0.1, 0.1}, {directional({0, 0, -1}, {1, 1, 1})}, base, {0, 0, 0}, {0, 0, 1}},        // head on
        {{0.1, 0.1, 0.1}, {directional({0, 0, 1}, {1, 1, 1})}, base, {0, 0, 0}, {0, 0, 1}},         // from behind
        {{0.1, 0.1, 0.1}, {directional({1, 0, 0}, {1, 1, 1})}, base, {0, 0, 0}, {0, 0, 1}},         // grazing
        {{0.2, 0.1, 0.0}, {directional({-1, -1, -1}, {0.5, 0.8, 1})}, base, {0, 0, 0}, {0, 0, 3}},  // long normal
        {{0.1, 0.1, 0.1}, {point({3, 0, 4}, {1, 1, 1})}, base, {0, 0, 0}, {0, 0, 1}},                // point: 4/5
        {{0.1, 0.1, 0.1}, {point({1, 2, 3}, {1, 1, 1})}, base, {1, 2, 3}, {0, 0, 1}},                // light AT the point
        {{0.1, 0.1, 0.1}, {directional({0, 0, -1})}, base, {0, 0, 0}, {0, 0, 0}},                    // zero normal
        {{0.3, 0.3, 0.3}, {directional({0, -1, 0}, {1.5, 1.5, 1.5}), point({0, 5, 0}, {1, 1, 1})}, base, {0, 0, 0},
         {0, 1, 0}},  // too bright
        {{0.1, 0.1, 0.1}, {directional({0, 0, 0})}, base, {0, 0, 0}, {0, 1, 0}},  // zero light direction
        // short normal: as an interpolated one is between vertices
        {{0.1, 0.1, 0.1}, {directional({-1, 0, -1}, {1, 1, 1})}, base, {0, 0, 0}, {0, 0, 0.5}},
        // one light in front and one behind: each is clamped at 0 on its own, then they add
        {{0.1, 0.1, 0.1}, {directional({0, 0, -1}, {1, 1, 1}), directional({0.3, 0, 1}, {0.8, 0.7, 0.6})}, base, {0, 0, 0},
         {0, 0, 1}},
        // an infinite light exactly along the surface (N . L = 0): it adds nothing, never NaN
        {{0.1, 0.1, 0.1}, {directional({0, 0, -1}, {0.5, 0.5, 0.5}), directional({1, 0, 0}, {kInf, kInf, kInf})}, base,
         {0, 0, 0}, {0, 0, 1}},
        // a normal with an infinite component: its length is not finite, so it is the zero
        // normal (ambient only), though the light shines along +x; normalized, it is NaN
        {{0.1, 0.1, 0.1}, {directional({-1, 0, 0}, {1, 1, 1})}, base, {0, 0, 0}, {kInf, 0, 0}},
    };
    if (variant_seed() != 0) {
        Rng rng(variant_seed(), "m4.lambert");
        for (LambertCase& c : cases) {
            c.base = {static_cast<std::uint8_t>(rng.uniform(40, 255)), static_cast<std::uint8_t>(rng.uniform(40, 255)),
                      static_cast<std::uint8_t>(rng.uniform(40, 255))};
            c.position = c.position + Vec3{rng.uniform(-50, 50) / 100.0, 0, rng.uniform(-50, 50) / 100.0};
        }
    }
    return cases;
}

std::vector<Group> prerequisite_groups(const Scene& s) {
    std::vector<Group> need;
    auto add = [&need](Group g) {
        if (std::find(need.begin(), need.end(), g) == need.end()) need.push_back(g);
    };
    for (const Panel& p : s.panels) {
        const bool pipeline = p.screen_tris.empty();  // draw_mesh after clear_frame
        if (pipeline) {
            add(Group::kClearFrame);
            add(Group::kClip);
        }
        if (p.depth_test) {
            add(Group::kDepthKeys);
            add(Group::kDepthTest);
        }
        const bool interpolates = !pipeline || p.shading == Shade::kVertexColor || p.shading == Shade::kGouraud ||
                                  p.shading == Shade::kPerPixel || p.shading == Shade::kChecker ||
                                  p.shading == Shade::kNormalView;
        if (p.perspective_correct && interpolates) add(Group::kWeights);
        if (p.shading == Shade::kFlat || p.shading == Shade::kGouraud || p.shading == Shade::kPerPixel) {
            add(Group::kNormals);
            add(Group::kLambert);
        }
        if (p.shading == Shade::kNormalView) add(Group::kNormals);
        if (p.shading == Shade::kDepthView || p.shading == Shade::kNormalView) add(Group::kDebugColors);
        if (p.shading == Shade::kDepthView) add(Group::kDepthKeys);
    }
    std::vector<Group> out;
    for (Group g : need) {
        if (std::find(s.groups.begin(), s.groups.end(), g) == s.groups.end()) out.push_back(g);
    }
    std::sort(out.begin(), out.end());  // in the order of the TODOs
    return out;
}

std::string prerequisite_key(Group g) { return "pre" + std::to_string(static_cast<int>(g)) + "."; }

std::string prerequisite_checkpoint(Group g) {
    for (const Scene& s : public_scenes()) {
        if (std::find(s.groups.begin(), s.groups.end(), g) != s.groups.end()) return s.id;
    }
    return "m4";
}

const std::vector<Scene>& scenes() { return variants().scenes(); }

std::uint64_t variant_seed() { return variants().seed(); }

const Scene& scene(const std::string& id) { return cp::find_scene(scenes(), id); }

void use_variant(std::uint64_t seed) { variants().use(seed); }

}  // namespace m4cp
