#include "m3/scenes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "harness/checkpoint.h"
#include "harness/scene_builders.h"
#include "variant_random.h"
#include "raster/mesh.h"

namespace m3cp {

namespace {

const Color kPalette[] = {{230, 80, 60},  {60, 170, 90},  {70, 110, 230}, {230, 200, 60},
                          {170, 80, 200}, {60, 190, 200}, {240, 140, 40}, {200, 200, 200}};

// A convex mesh centered on the origin from polygon faces: each face is turned to face
// outward (counter-clockwise seen from outside), fanned into triangles in one color, and its
// edges listed once.
Mesh from_faces(std::vector<Vec3> positions, std::vector<std::vector<int>> faces, bool colored) {
    Mesh m;
    m.positions = std::move(positions);
    std::map<std::pair<int, int>, bool> seen;
    for (std::size_t f = 0; f < faces.size(); ++f) {
        std::vector<int> face = faces[f];
        Vec3 normal{}, center{};
        for (std::size_t i = 0; i < face.size(); ++i) {
            const Vec3 a = m.positions[face[i]], b = m.positions[face[(i + 1) % face.size()]];
            normal = normal + raster::cross(a, b);
            center = center + a;
        }
        if (raster::dot(normal, center) < 0) std::reverse(face.begin(), face.end());
        for (std::size_t i = 1; i + 1 < face.size(); ++i) {
            m.triangles.push_back({face[0], face[i], face[i + 1]});
            m.face_colors.push_back(colored ? kPalette[f % 8] : raster::colors::white);
        }
        for (std::size_t i = 0; i < face.size(); ++i) {
            const int a = face[i], b = face[(i + 1) % face.size()];
            if (!seen[{std::min(a, b), std::max(a, b)}]) {
                seen[{std::min(a, b), std::max(a, b)}] = true;
                m.edges.push_back({a, b});
            }
        }
    }
    return m;
}

constexpr auto numbers = &cp::numbers_scene<Scene>;
constexpr auto picture = &cp::picture_scene<Scene>;

Panel panel(Camera c, std::vector<Item> items, int x0, int y0, int w, int h) { return {c, std::move(items), x0, y0, w, h}; }

// A camera at a generic position: the numbers in the scenes are chosen so that no vertex
// lands exactly on a pixel boundary, where rounding alone could decide a pixel.
Camera cam(Vec3 eye, Vec3 target = {0.013, -0.021, 0.007}) {
    Camera c;
    c.eye = eye;
    c.target = target;
    return c;
}

Item item(Mesh m, Vec3 pos = {}, Vec3 axis = {0, 1, 0}, double angle = 0, Vec3 size = {1, 1, 1}) {
    return {std::move(m), pos, axis, angle, size};
}

// A single triangle (counter-clockwise from +z) with its three edges.
Mesh triangle_mesh(Vec3 a, Vec3 b, Vec3 c, Color color) {
    Mesh m;
    m.positions = {a, b, c};
    m.triangles = {{0, 1, 2}};
    m.edges = {{0, 1}, {1, 2}, {2, 0}};
    m.face_colors = {color};
    return m;
}

std::vector<Scene> build() {
    std::vector<Scene> out;
    const double pi = std::numbers::pi;

    // ---- numbers against hand-worked values ----
    out.push_back(numbers("m3.matrix_ops", "Matrix product, transpose, points and directions",
                          "Mat4 is m[row][col] and acts on column vectors: (M v)[r] = sum_c m[r][c] v[c]. A point has "
                          "w = 1, a direction w = 0.",
                          {1}, {Group::kMatrixOps}));
    out.push_back(numbers("m3.builders", "translate, scale, rotate_x, rotate_y, rotate_z",
                          "Translation goes in the last column. rotate_z(pi/2) takes +x to +y, rotate_x takes +y to +z, "
                          "rotate_y takes +z to +x (right-hand rule, radians).",
                          {2}, {Group::kBuilders}));
    out.push_back(numbers("m3.rodrigues", "Rotation about any axis (Rodrigues)",
                          "Normalize the axis; R = I + sin(a) K + (1 - cos(a)) K^2. A turn of 120 degrees about (1, 1, 1) "
                          "takes x to y, y to z, z to x. The zero axis gives the identity.",
                          {2}, {Group::kRodrigues}));
    out.push_back(numbers("m3.composition", "Composition order: A * B means first B, then A",
                          "translate(t) * rotate_z(a) turns the point about the origin and then moves it; the other "
                          "product moves it first and turns the moved point.",
                          {1, 2}, {Group::kComposition}));
    out.push_back(numbers("m3.inverse", "General inverse, singular matrices, rigid inverse",
                          "Gauss-Jordan with partial pivoting on [M | I]; a zero pivot means singular: return false. The "
                          "rigid inverse is R^T with -R^T t.",
                          {3}, {Group::kInverse}));
    out.push_back(numbers("m3.near_singular", "A nearly singular matrix (condition number 1e12)",
                          "Pivot on the largest entry of the column, and compare pivots with a threshold relative to the "
                          "matrix's entries, not a fixed 1e-6.",
                          {3}, {Group::kNearSingular}));
    out.push_back(numbers("m3.look_at", "The view matrix, and its fallbacks",
                          "f = normalize(target - eye), r = normalize(cross(f, up)), u = cross(r, f); rows r, u, -f. "
                          "When up is parallel to f, or eye == target, use the fallbacks transforms.h pins.",
                          {4}, {Group::kLookAt}));
    out.push_back(numbers("m3.projection", "Perspective and orthographic: known points to known pixels",
                          "perspective() takes DEGREES. Divide by w, then x = (x + 1) / 2 * W and y = (1 - y) / 2 * H: "
                          "the top of the view is row 0.",
                          {5, 6}, {Group::kProjection}));
    out.push_back(numbers("m3.clip_numbers", "Clipping polygons and lines in clip space",
                          "Clip against all six planes -w <= x, y, z <= w; points behind the camera (w < 0) or in its "
                          "plane (w = 0) are outside the near plane z >= -w.",
                          {7}, {Group::kClip}));
    out.push_back(numbers("m3.bezier", "A cubic Bezier curve by de Casteljau",
                          "Three rounds of linear interpolation at t: 4 points, then 3, 2, 1.", {9}, {Group::kBezier}));
    out.push_back(numbers("m3.rotation_drift", "10,000 composed rotations",
                          "Compose with doubles; each product must stay a rotation (orthonormal) to about 1e-12.",
                          {1, 2}, {Group::kRotationDrift}));
    out.push_back(numbers("m3.nonfinite", "NaN, infinities, 1e308, subnormals and indices out of range: the fallbacks transforms.h pins",
                          "A non-finite axis gives the identity, a non-finite eye the zero matrix, inverse() false for "
                          "non-finite entries or result, a projection that would hold infinity the zero matrix; huge "
                          "vectors are scaled by a power of two before normalizing or clipping; draw_model skips a "
                          "triangle or edge with an index outside positions.",
                          {2, 3, 4, 5, 7, 11}, {Group::kNonFinite}));

    // ---- pictures ----
    {
        Scene s = picture("m3.wireframe_cube", "Wireframe cube in perspective",
                          "Model, view, projection, divide, viewport, then milestone 1's draw_line for every edge.",
                          {11, 1, 4, 5, 6}, 96, 96);
        s.panels = {panel(cam({2.3, 1.7, 4.1}), {item(cube_mesh(false), {0, 0, 0}, {0, 1, 0}, 0.3)}, 0, 0, 96, 96)};
        s.wireframe = s.clip = true;
        s.demo = true;
        out.push_back(s);
    }
    {
        Scene s = picture("m3.soccer_ball", "Soccer ball wireframe (truncated icosahedron: 60 vertices, 90 edges)",
                          "The same pipeline as the cube: every edge drawn once.", {11}, 128, 128);
        Mesh ball = soccer_ball_mesh();
        ball.triangles.clear();
        ball.face_colors.clear();
        s.panels = {panel(cam({0.4, 0.9, 4.1}), {item(ball, {0, 0, 0}, {1, 2, 0.5}, 0.4)}, 0, 0, 128, 128)};
        s.wireframe = s.clip = true;
        s.demo = true;
        out.push_back(s);
    }
    {
        Scene s = picture("m3.solid_cube", "Solid cube with back faces culled",
                          "A front face is counter-clockwise on screen, which in pixel coordinates (y down) is a NEGATIVE "
                          "signed area: cull when cross(s1 - s0, s2 - s0) >= 0.",
                          {8, 11}, 96, 96);
        s.panels = {panel(cam({2.7, 2.1, 3.9}), {item(cube_mesh(true), {0, 0, 0}, {0, 1, 0}, 0.2)}, 0, 0, 96, 96)};
        s.fill = s.cull = s.clip = true;
        s.groups = {Group::kCulling};
        s.demo = true;
        out.push_back(s);
    }
    {
        Scene s = picture("m3.persp_ortho", "Perspective (left) and orthographic (right) views of one scene",
                          "Orthographic: the box [l, r] x [b, t] x [-near, -far] becomes the NDC cube, w stays 1.",
                          {5, 11}, 160, 80);
        std::vector<Item> row;
        for (int i = 0; i < 3; ++i) row.push_back(item(cube_mesh(true), {-2.6 + 2.6 * i, 0, -2.0 * i}, {0, 1, 0}, 0.5, {0.8, 0.8, 0.8}));
        Camera p = cam({1.1, 2.2, 7.3});
        p.far = 60;
        Camera o = p;
        o.ortho = true;
        o.half_height = 3.1;
        s.panels = {panel(p, row, 0, 0, 80, 80), panel(o, row, 80, 0, 80, 80)};
        s.fill = s.cull = s.clip = true;
        s.demo = true;
        out.push_back(s);
    }
    {
        Scene s = picture("m3.orbit", "A camera orbiting the scene: four look_at views",
                          "look_at from four sides: the object must turn, never mirror.", {4, 11}, 128, 128);
        std::vector<Item> items = {item(cube_mesh(true), {0, 0, 0}, {0, 1, 0}, 0.1),
                                   item(pyramid_mesh(), {0, 1.9, 0}, {0, 1, 0}, 0.25, {0.8, 0.8, 0.8})};
        for (int k = 0; k < 4; ++k) {
            const double a = 0.4 + k * pi / 2;
            Camera c = cam({6.1 * std::sin(a), 2.9, 6.1 * std::cos(a)}, {0.011, 0.52, -0.017});
            s.panels.push_back(panel(c, items, (k % 2) * 64, (k / 2) * 64, 64, 64));
        }
        s.fill = s.cull = s.clip = true;
        s.demo = true;
        out.push_back(s);
    }
    {
        Scene s = picture("m3.models", "The shipped OBJ models: octahedron, pyramid, soccer ball, solid and culled",
                          "Every model's triangles are counter-clockwise from outside: culling keeps exactly the faces "
                          "that turn towards the camera.",
                          {8, 11}, 192, 64);
        s.panels = {panel(cam({1.9, 2.3, 4.4}), {item(obj_mesh("octahedron", true), {}, {1, 0, 1}, 0.3, {1.5, 1.5, 1.5})}, 0, 0, 64, 64),
                    panel(cam({2.4, 1.6, 4.3}), {item(obj_mesh("pyramid", true), {}, {0, 1, 0}, 0.6, {1.4, 1.4, 1.4})}, 64, 0, 64, 64),
                    panel(cam({1.3, 1.1, 4.6}), {item(soccer_ball_mesh(), {}, {1, 2, 0.5}, 0.4, {1.6, 1.6, 1.6})}, 128, 0, 64, 64)};
        s.fill = s.cull = s.clip = true;
        s.demo = true;
        out.push_back(s);
    }
    {
        Scene s = picture("m3.behind_camera", "Triangles reaching behind the camera and into its plane (w = 0)",
                          "Clip in clip space, before the divide: a vertex with w <= 0 divided by w lands on the wrong "
                          "side of the screen (or at infinity).",
                          {7, 11}, 96, 96);
        Camera c;
        c.eye = {0, 0, 0};
        c.target = {0, 0, -1};
        c.near = 0.5;
        c.far = 50;
        c.fovy = 60;
        // One vertex exactly in the camera's plane (view z = 0, so w = 0), one behind it.
        Mesh a = triangle_mesh({-1.3, -0.9, -3.1}, {0.6, -1.1, 0.0}, {0.9, 0.7, -4.2}, {230, 80, 60});
        Mesh b = triangle_mesh({-0.2, 0.45, -2.3}, {-1.6, 0.9, 2.7}, {-0.35, 1.7, -5.1}, {70, 110, 230});
        s.panels = {panel(c, {item(a), item(b)}, 0, 0, 96, 96)};
        s.fill = s.wireframe = s.clip = true;
        s.line = {255, 255, 255};
        out.push_back(s);
    }
    {
        Scene s = picture("m3.near_crossing", "A triangle crossing the near plane, its far vertices 1e6 away",
                          "The near plane cuts the triangle into a quadrilateral (fan it); the far vertices stay finite "
                          "in clip space and reach milestone 2 inside its coordinate range.",
                          {7, 11}, 96, 96);
        Camera c;
        c.eye = {0, 0, 0};
        c.target = {0, 0, -1};
        c.near = 0.1;
        c.far = 2e6;
        c.fovy = 70;
        Mesh m = triangle_mesh({0.03, -0.02, 0.3}, {-3.1e5, -2.3e5, -1e6}, {2.9e5, 1.7e5, -1e6}, {60, 190, 200});
        s.panels = {panel(c, {item(m)}, 0, 0, 96, 96)};
        s.fill = s.wireframe = s.clip = true;
        out.push_back(s);
    }
    {
        Scene s = picture("m3.fov_extremes", "Fields of view of 1 and 179 degrees",
                          "1 / tan(fovy / 2) with fovy converted to radians: 1 degree is a telescope, 179 a fisheye.",
                          {5, 11}, 128, 64);
        Camera narrow = cam({0.03, 0.02, 170.0});
        narrow.fovy = 1;
        narrow.far = 400;
        Camera wide = cam({0.3, 0.2, 0.031});
        wide.fovy = 179;
        wide.near = 0.001;
        std::vector<Item> grid;
        for (int i = -2; i <= 2; ++i) grid.push_back(item(cube_mesh(true), {i * 0.6, 0, -0.6 * std::abs(i)}, {0, 1, 0}, 0.35, {0.25, 0.25, 0.25}));
        s.panels = {panel(narrow, grid, 0, 0, 64, 64), panel(wide, grid, 64, 0, 64, 64)};
        s.fill = s.cull = s.clip = true;
        out.push_back(s);
    }
    {
        Scene s = picture("m3.near_far_extreme", "near = 1e-4, far = 1e6",
                          "Extreme near/far ratios squeeze depth, not x and y: the picture must be the ordinary one.",
                          {5, 11}, 96, 96);
        Camera c = cam({2.3, 1.7, 4.1});
        c.near = 1e-4;
        c.far = 1e6;
        s.panels = {panel(c, {item(cube_mesh(true), {0, 0, 0}, {0, 1, 0}, 0.3)}, 0, 0, 96, 96)};
        s.fill = s.cull = s.clip = s.wireframe = true;
        s.line = {20, 20, 20};
        out.push_back(s);
    }
    {
        Scene s = picture("m3.far_model", "A model 1e6 units from the origin, seen from nearby",
                          "Compose view * model before applying it: the large translations cancel in the matrix, and "
                          "the vertices stay close to the camera.",
                          {1, 4, 11}, 96, 96);
        const Vec3 far{1e6, -2.5e5, 7.5e5};
        Camera c = cam(far + Vec3{2.3, 1.7, 4.1}, far + Vec3{0.013, -0.021, 0.007});
        s.panels = {panel(c, {item(cube_mesh(true), far, {0, 1, 0}, 0.3)}, 0, 0, 96, 96)};
        s.fill = s.cull = s.clip = true;
        out.push_back(s);
    }
    {
        Scene s = picture("m3.painter", "Painter's algorithm: far faces first",
                          "Sort by the mean view-space z of each triangle, most negative (farthest) first, then fill in "
                          "that order so near faces cover far ones.",
                          {10, 11}, 96, 96);
        Mesh m;
        // Three overlapping quads at different depths, listed near to far (so list order is wrong).
        const double zs[3] = {-0.4, -1.7, -3.1};
        for (int q = 0; q < 3; ++q) {
            const int base = static_cast<int>(m.positions.size());
            const double x = -0.9 + 0.7 * q, y = 0.5 - 0.55 * q, z = zs[q];
            m.positions.push_back({x - 1.05, y - 0.95, z});
            m.positions.push_back({x + 1.1, y - 0.9, z + 0.06});
            m.positions.push_back({x + 1.0, y + 1.05, z + 0.11});
            m.positions.push_back({x - 0.95, y + 1.0, z + 0.05});
            m.triangles.push_back({base, base + 1, base + 2});
            m.triangles.push_back({base, base + 2, base + 3});
            m.face_colors.push_back(kPalette[q]);
            m.face_colors.push_back(kPalette[q]);
        }
        s.panels = {panel(cam({0.2, 0.3, 4.2}, {0.01, -0.02, -1.0}), {item(m)}, 0, 0, 96, 96)};
        s.fill = s.clip = s.painter = true;
        s.groups = {Group::kPainter};
        out.push_back(s);
    }
    {
        Scene s = picture("m3.painter_fails", "Where the painter's algorithm fails: two triangles passing through each other",
                          "This picture is wrong on purpose (see the lesson): the blue triangle's mean depth is nearer, "
                          "so it is drawn last and covers the red one everywhere, even where it passes behind it. The "
                          "checkpoint checks that you sort by the pinned rule.",
                          {10, 11}, 96, 96);
        Mesh m;
        // Listed near to far by mean z (-2.73, then -3.0), so list order would draw red last.
        m.positions = {{-1.0, 0.35, -1.8}, {1.05, 0.3, -1.85}, {0.04, -1.15, -4.55},
                       {-1.25, -0.85, -3.0}, {1.2, -0.8, -3.0}, {-0.05, 1.05, -3.0}};
        m.triangles = {{0, 2, 1}, {3, 4, 5}};
        m.face_colors = {{70, 110, 230}, {230, 80, 60}};
        Camera c = cam({0.02, 0.03, 0.0}, {0.0, 0.0, -1.0});
        s.panels = {panel(c, {item(m)}, 0, 0, 96, 96)};
        s.fill = s.clip = s.painter = true;
        s.demo = true;
        out.push_back(s);
    }
    return out;
}

}  // namespace

Mesh cube_mesh(bool colored) {
    std::vector<Vec3> p;
    for (int i = 0; i < 8; ++i) p.push_back({i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0});
    return from_faces(p, {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}}, colored);
}

Mesh pyramid_mesh() {
    // Base centered so that the centroid-based orientation test sees the origin inside.
    std::vector<Vec3> p = {{-1, -0.5, -1}, {1, -0.5, -1}, {1, -0.5, 1}, {-1, -0.5, 1}, {0, 1, 0}};
    return from_faces(p, {{0, 1, 2, 3}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}}, true);
}

Mesh obj_mesh(const std::string& name, bool colored) {
    const raster::Mesh obj = raster::load_obj(raster::model_path(name));
    Mesh m;
    m.positions = obj.positions;
    m.triangles = obj.triangles;
    // The loader fans each polygon face in order: face f gives size - 2 triangles.
    for (std::size_t f = 0; f < obj.faces.size(); ++f) {
        for (std::size_t k = 2; k < obj.faces[f].size(); ++k) {
            m.face_colors.push_back(colored ? kPalette[f % 8] : raster::colors::white);
        }
    }
    m.edges = raster::unique_edges(obj);
    return m;
}

Mesh soccer_ball_mesh() { return obj_mesh("soccer_ball", true); }

static Matrix public_near_singular_matrix(const double (&angles)[6]) {
    // Q1 * diag(1, 1e-6, 1e-6, 1e-12) * Q2 with 4D rotations Q1, Q2 (Givens rotations in several
    // planes), so every entry is mixed and the condition number is 1e12. Its entries are at most
    // 1, so the last pivot is far below a fixed threshold of 1e-6: only a threshold relative to
    // the entries inverts it (a uniform scale changes neither the condition nor the residual).
    auto givens = [](int i, int j, double a) {
        Matrix g{};
        for (int k = 0; k < 4; ++k) g[k][k] = 1;
        g[i][i] = g[j][j] = std::cos(a);
        g[i][j] = -std::sin(a);
        g[j][i] = std::sin(a);
        return g;
    };
    auto mul = [](const Matrix& a, const Matrix& b) {
        Matrix r{};
        for (int i = 0; i < 4; ++i) {
            for (int j = 0; j < 4; ++j) {
                for (int k = 0; k < 4; ++k) r[i][j] += a[i][k] * b[k][j];
            }
        }
        return r;
    };
    Matrix d{};
    d[0][0] = 1;
    d[1][1] = d[2][2] = 1e-6;
    d[3][3] = 1e-12;
    const Matrix q1 = mul(mul(givens(0, 3, angles[0]), givens(1, 2, angles[1])), givens(0, 1, angles[2]));
    const Matrix q2 = mul(mul(givens(2, 3, angles[3]), givens(0, 2, angles[4])), givens(1, 3, angles[5]));
    return mul(mul(q1, d), q2);
}

static std::vector<std::array<Vec4, 3>> public_clip_cases() {
    return {
        // inside: unchanged
        {{{0.1, 0.2, 0.3, 1}, {0.6, -0.1, 0.2, 1}, {-0.2, 0.5, -0.4, 1}}},
        // crossing the right plane x = w
        {{{0.2, 0.1, 0.0, 1}, {2.3, 0.3, 0.1, 1.2}, {0.4, 0.8, -0.2, 1}}},
        // crossing two planes (right and top): a pentagon
        {{{0.1, 0.1, 0.1, 1}, {1.9, 0.3, 0.2, 1}, {0.3, 1.7, 0.1, 1}}},
        // one vertex behind the camera (w < 0)
        {{{0.1, 0.2, 0.4, 1}, {0.4, -0.3, 1.3, -1.5}, {-0.5, 0.3, 1.2, 2}}},
        // one vertex exactly in the camera's plane (w = 0), as a perspective makes it
        {{{-0.3, -0.2, 0.5, 1.5}, {0.7, 0.35, -1.0, 0.0}, {0.2, 0.6, 0.9, 2.5}}},
        // crossing the near plane with the far vertices 1e6 away
        {{{0.03, -0.02, -0.35, 0.2}, {-3.1e5, -2.3e5, 9.99e5, 1e6}, {2.9e5, 1.7e5, 9.99e5, 1e6}}},
        // entirely outside (beyond the left plane): nothing
        {{{-2.1, 0.1, 0.0, 1}, {-3.0, 0.5, 0.2, 1}, {-1.6, -0.4, 0.1, 1.1}}},
        // beyond the right plane but for one vertex ON it (x = w): the planes are closed, so that
        // point is inside, and the rule keeps it (three times: a polygon of no area)
        {{{1.0, 0.2, 0.1, 1}, {2.0, 0.5, 0.0, 1}, {1.8, -0.4, 0.2, 1}}},
    };
}

static std::vector<std::array<Vec4, 2>> public_clip_line_cases() {
    return {
        {{{0.1, 0.2, 0.3, 1}, {-0.4, 0.5, 0.1, 1}}},     // inside
        {{{0.2, 0.1, 0.0, 1}, {2.4, 0.3, 0.1, 1.1}}},    // leaves through the right plane
        {{{-1.8, 0.2, 0.1, 1}, {1.9, -0.3, 0.2, 1}}},    // crosses both side planes
        {{{0.1, 0.2, 0.4, 1}, {0.4, -0.3, 1.3, -1.5}}},  // one end behind the camera
        {{{0.7, 0.35, -1.0, 0.0}, {0.2, 0.1, 0.9, 2.5}}},  // one end at w = 0
        {{{1.5, 0.1, 0.0, 1}, {2.5, 0.4, 0.1, 1}}},      // outside: nothing
        {{{1.0, 0.2, 0.1, 1}, {0.5, -0.3, 0.2, 0.5}}},   // on the plane x = w: all of it
    };
}

// ---- scene variants (grading): see "Scene variants (grading)" in checkpoints/README.md ----

namespace {

using Rng = cp::VariantRng;


constexpr double kPublicSingularAngles[6] = {0.7, 0.4, 1.1, 0.9, -0.6, 0.3};

// x + d with d a whole number of hundredths in [-n, n] / 100.
double jitter(Rng& rng, double x, int n) { return x + rng.uniform(-n, n) / 100.0; }

// The scene's face colors from kPalette permuted among themselves (distinct stay distinct).
void recolor(Scene& s, Rng& rng) {
    std::vector<int> perm{0, 1, 2, 3, 4, 5, 6, 7};
    rng.shuffle(perm);
    for (Panel& p : s.panels) {
        for (Item& it : p.items) {
            for (Color& c : it.mesh.face_colors) {
                for (int k = 0; k < 8; ++k) {
                    if (c == kPalette[k]) {
                        c = kPalette[perm[std::size_t(k)]];
                        break;
                    }
                }
            }
        }
    }
}

Scene vary(const Scene& pub, Rng& rng) {
    Scene s = pub;
    const std::string& id = s.id;
    auto is = [&](std::initializer_list<const char*> names) {
        return std::any_of(names.begin(), names.end(), [&](const char* n) { return id == n; });
    };
    // Models turned by up to 0.2 rad more about their axis.
    if (is({"m3.wireframe_cube", "m3.soccer_ball", "m3.solid_cube", "m3.persp_ortho", "m3.orbit", "m3.models",
            "m3.fov_extremes", "m3.near_far_extreme", "m3.far_model"})) {
        for (Panel& p : s.panels) {
            for (Item& it : p.items) it.angle = jitter(rng, it.angle, 20);
        }
    }
    // The camera moved by up to 0.15 per coordinate (the same move for panels that show one
    // scene side by side).
    if (is({"m3.wireframe_cube", "m3.soccer_ball", "m3.solid_cube", "m3.persp_ortho", "m3.orbit", "m3.models",
            "m3.near_far_extreme", "m3.far_model", "m3.painter"})) {
        const Vec3 d{rng.uniform(-15, 15) / 100.0, rng.uniform(-15, 15) / 100.0, rng.uniform(-15, 15) / 100.0};
        for (Panel& p : s.panels) p.camera.eye = p.camera.eye + d;
    }
    // Triangles at the camera: x and y of every vertex move by up to 5%, z stays, so the vertex
    // in the camera's plane (w = 0) stays there and the one behind it stays behind.
    // painter_fails too: its triangles keep their depths (and so their drawing order and the
    // line where they cross) while their outline changes.
    if (is({"m3.behind_camera", "m3.near_crossing", "m3.painter_fails"})) {
        for (Panel& p : s.panels) {
            for (Item& it : p.items) {
                for (Vec3& v : it.mesh.positions) {
                    v.x *= 1 + rng.uniform(-5, 5) / 100.0;
                    v.y *= 1 + rng.uniform(-5, 5) / 100.0;
                }
            }
        }
    }
    if (id != "m3.painter_fails") recolor(s, rng);  // its hint names the blue triangle
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

Matrix near_singular_matrix() {
    if (variant_seed() == 0) return public_near_singular_matrix(kPublicSingularAngles);
    // Other Givens angles (up to 0.25 rad away): still every entry mixed, condition number 1e12.
    Rng rng(variant_seed(), "m3.near_singular");
    double angles[6];
    for (int k = 0; k < 6; ++k) angles[k] = jitter(rng, kPublicSingularAngles[k], 25);
    return public_near_singular_matrix(angles);
}

// Each clip-space vertex multiplied by its own positive factor (0.5..2): the same point of
// projective space, so every case keeps its relation to the six planes (w = 0 stays 0, w < 0
// stays negative), while every number changes.
std::vector<std::array<Vec4, 3>> clip_cases() {
    auto cases = public_clip_cases();
    if (variant_seed() == 0) return cases;
    Rng rng(variant_seed(), "m3.clip_numbers.polygons");
    for (auto& c : cases) {
        for (Vec4& v : c) v = v * (rng.uniform(50, 200) / 100.0);
    }
    return cases;
}

std::vector<std::array<Vec4, 2>> clip_line_cases() {
    auto cases = public_clip_line_cases();
    if (variant_seed() == 0) return cases;
    Rng rng(variant_seed(), "m3.clip_numbers.lines");
    for (auto& c : cases) {
        for (Vec4& v : c) v = v * (rng.uniform(50, 200) / 100.0);
    }
    return cases;
}

std::vector<std::pair<std::string, Matrix>> nonfinite_inverse_cases() {
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    return {
        {"inv.nan", {{{2, 1, 0, 3}, {0, 1, nan, -1}, {1, 0, 1, 2}, {0, 0, 0, 1}}}},
        {"inv.inf", {{{1.5, 0, 0, 0}, {0, 2.5, 0, 0}, {0, 0, -inf, -2.2}, {0, 0, -1, 0}}}},
        // Invertible in exact arithmetic, but its inverse has entries near 1e320.
        {"inv.tiny", {{{2e-320, 1e-320, 0, 0}, {1e-320, 3e-320, 0, 1e-320}, {0, 0, 1e-320, 0}, {0, 1e-320, 0, 2e-320}}}},
    };
}

std::pair<std::array<Vec4, 3>, std::array<Vec4, 2>> nonfinite_clip_cases() {
    // m3.clip_numbers's segment across both side planes (and a triangle across them), scaled by
    // 9e307: w + x overflows at the right end, so an unscaled crossing is inf / inf or 0.
    const double s = 9e307;
    const std::array<Vec4, 3> tri = {Vec4{-1.8, 0.2, 0.1, 1} * s, Vec4{1.9, -0.3, 0.2, 1} * s, Vec4{0.1, 0.9, 0.3, 1} * s};
    const std::array<Vec4, 2> seg = {Vec4{-1.8, 0.2, 0.1, 1} * s, Vec4{1.9, -0.3, 0.2, 1} * s};
    return {tri, seg};
}

std::array<Vec4, 3> inside_end_clip_case() {
    // Found by search: only the first vertex is outside any plane (x > w), so the plane order
    // does not matter, and the polygon walks the edge outside -> inside whatever its start.
    return {Vec4{1.7148468443562371e+308, -5.2866414770436213e+307, 5.1477679070461008e+307, 8.7043766496172206e+307},
            Vec4{1.7976931348623157e+308, -3.4011914383546834e+307, 4.0083780542012492e+307, 1.7976931348623157e+308},
            Vec4{-1.6683788847215912e+307, 6.5093523754853325e+306, -1.765040776713766e+307, 1.7976931348623157e+308}};
}

std::vector<Group> group_dependencies(Group g) {
    // Number groups that reach their results through transform_point or a product (TODO 1),
    // or through the builders: a wrong product must not read as a wrong rotation.
    switch (g) {
        case Group::kBuilders:
        case Group::kProjection: return {Group::kMatrixOps};
        case Group::kComposition: return {Group::kMatrixOps, Group::kBuilders};
        case Group::kRotationDrift: return {Group::kMatrixOps, Group::kRodrigues};
        // Extreme input to the functions whose ordinary input those groups test (not
        // kProjection's, whose checks go through products and to_screen, TODOs this one does
        // not call; its ordinary projections are compared here directly).
        case Group::kNonFinite: return {Group::kRodrigues, Group::kInverse, Group::kLookAt, Group::kClip};
        default: return {};
    }
}

std::vector<Group> prerequisite_groups(const Scene& s) {
    if (s.panels.empty()) {
        std::vector<Group> out;
        for (Group g : s.groups) {
            for (Group d : group_dependencies(g)) {
                if (std::find(s.groups.begin(), s.groups.end(), d) == s.groups.end() &&
                    std::find(out.begin(), out.end(), d) == out.end()) {
                    out.push_back(d);
                }
            }
        }
        std::sort(out.begin(), out.end());
        return out;
    }
    std::vector<Group> all = {Group::kMatrixOps, Group::kBuilders, Group::kRodrigues, Group::kLookAt, Group::kProjection};
    if (s.clip) all.push_back(Group::kClip);
    if (s.cull) all.push_back(Group::kCulling);
    if (s.painter) all.push_back(Group::kPainter);
    std::vector<Group> out;
    for (Group g : all) {
        if (std::find(s.groups.begin(), s.groups.end(), g) == s.groups.end()) out.push_back(g);
    }
    return out;
}

std::string prerequisite_key(Group g) { return "pre" + std::to_string(static_cast<int>(g)) + "."; }

std::string prerequisite_checkpoint(Group g) {
    for (const Scene& s : public_scenes()) {
        if (std::find(s.groups.begin(), s.groups.end(), g) != s.groups.end()) return s.id;
    }
    return "m3";
}

const std::vector<Scene>& scenes() { return variants().scenes(); }

std::uint64_t variant_seed() { return variants().seed(); }

const Scene& scene(const std::string& id) { return cp::find_scene(scenes(), id); }

void use_variant(std::uint64_t seed) { variants().use(seed); }

}  // namespace m3cp
