#include "m5/scenes.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>
#include <tuple>

#include "harness/checkpoint.h"
#include "harness/scene_builders.h"
#include "variant_random.h"

namespace m5cp {

namespace {

std::uint8_t byte(double v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 255.0))); }

// A fixed pseudo-random byte per (x, y, channel, seed): the same on every platform.
std::uint8_t hash_byte(std::uint32_t x, std::uint32_t y, std::uint32_t c, std::uint32_t seed) {
    std::uint32_t h = x * 73856093u ^ y * 19349663u ^ c * 83492791u ^ seed * 2654435761u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return static_cast<std::uint8_t>(h & 0xFFu);
}

Vec3 unit(Vec3 v) {
    const double len = raster::length(v);
    return len > 0 ? v / len : Vec3{};
}

}  // namespace

raster::Image texture_image(const TextureSpec& t) {
    const int w = std::max(0, t.width), h = std::max(0, t.height);
    raster::Image img(std::max(1, w), std::max(1, h));
    if (w == 0 || h == 0) return raster::Image();
    const int cells = std::max(1, t.cells);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            Color c = t.a;
            switch (t.pattern) {
                case Pattern::kChecker: c = ((x * cells / w) + (y * cells / h)) % 2 == 0 ? t.a : t.b; break;
                case Pattern::kFine: c = ((x / 2) + (y / 2)) % 2 == 0 ? t.a : t.b; break;
                case Pattern::kGradient: {
                    const double fx = w > 1 ? double(x) / (w - 1) : 0.5, fy = h > 1 ? double(y) / (h - 1) : 0.5;
                    c = {byte(t.a.r + (t.b.r - t.a.r) * fx), byte(t.a.g + (t.b.g - t.a.g) * fy), byte(40 + 150 * fx * fy)};
                    if (x < std::max(1, w / 8) && y < std::max(1, h / 8)) c = {255, 255, 255};
                    break;
                }
                case Pattern::kBricks: {
                    const int bh = std::max(2, h / cells), bw = 2 * bh;
                    const int row = y / bh;
                    const int xs = x + (row % 2) * (bw / 2);
                    const bool mortar = y % bh == 0 || xs % bw == 0;
                    const int brick = (xs / bw) * 7 + row * 13;
                    const int shade = int(hash_byte(std::uint32_t(brick), 0, 0, t.seed) % 40) - 20;
                    c = mortar ? t.b : Color{byte(t.a.r + shade), byte(t.a.g + shade * 0.6), byte(t.a.b + shade * 0.4)};
                    break;
                }
                case Pattern::kBumps: {
                    // Round bumps h = A (1 - q)^2 (q = r^2 / R^2, r < R), their normals
                    // normalize(-dh/dx, -dh/dy, 1) with x right (+u) and y DOWN the image (+v).
                    // bumps_top_half: the bottom half flat (whole cells when cells is even).
                    const double cw = double(w) / cells, ch = double(h) / cells;
                    const double lx = (x + 0.5) / cw - std::floor((x + 0.5) / cw) - 0.5;
                    const double ly = (y + 0.5) / ch - std::floor((y + 0.5) / ch) - 0.5;
                    const double R = 0.4, A = t.bump_height, q = (lx * lx + ly * ly) / (R * R);
                    Vec3 n{0, 0, 1};
                    if (q < 1 && !(t.bumps_top_half && 2 * y >= h)) n = unit(Vec3{4 * A * lx * (1 - q) / (R * R), 4 * A * ly * (1 - q) / (R * R), 1});
                    c = {byte(255 * (n.x + 1) / 2), byte(255 * (n.y + 1) / 2), byte(255 * (n.z + 1) / 2)};
                    break;
                }
                case Pattern::kArrow: {
                    const double fx = (x + 0.5) / w, fy = (y + 0.5) / h;
                    const bool stem = fx >= 0.2 && fx < 0.38 && fy >= 0.12 && fy < 0.88;
                    const bool top = fx >= 0.2 && fx < 0.85 && fy >= 0.12 && fy < 0.3;
                    const bool mid = fx >= 0.2 && fx < 0.65 && fy >= 0.45 && fy < 0.6;
                    c = stem || top || mid ? t.a : Color{byte(t.b.r + 120 * fx), t.b.g, byte(t.b.b + 120 * fy)};
                    break;
                }
                case Pattern::kNoise:
                    c = {hash_byte(std::uint32_t(x), std::uint32_t(y), 0, t.seed), hash_byte(std::uint32_t(x), std::uint32_t(y), 1, t.seed),
                         hash_byte(std::uint32_t(x), std::uint32_t(y), 2, t.seed)};
                    break;
            }
            img.set(x, y, c);
        }
    }
    return img;
}

Mesh quad(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec2 uv0, Vec2 uv1) {
    Mesh m;
    m.positions = {a, b, c, d};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    m.uvs = {{uv0.x, uv0.y}, {uv1.x, uv0.y}, {uv1.x, uv1.y}, {uv0.x, uv1.y}};
    const Vec3 n = unit(raster::cross(b - a, d - a));
    m.normals = {n, n, n, n};
    return m;
}

Mesh box_mesh() {
    Mesh m;
    const Vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const Vec3& n : normals) {
        const Vec3 t = std::abs(n.y) > 0.5 ? Vec3{0, 0, -n.y} : Vec3{0, 1, 0};
        const Vec3 s = raster::cross(t, n);  // (s, t, n) right-handed: counter-clockwise from outside
        const int base = int(m.positions.size());
        m.positions.push_back(n - s - t);
        m.positions.push_back(n + s - t);
        m.positions.push_back(n + s + t);
        m.positions.push_back(n - s + t);
        m.uvs.insert(m.uvs.end(), {{0, 1}, {1, 1}, {1, 0}, {0, 0}});
        for (int k = 0; k < 4; ++k) m.normals.push_back(n);
        m.triangles.push_back({base, base + 1, base + 2});
        m.triangles.push_back({base, base + 2, base + 3});
    }
    return m;
}

Mesh uv_sphere(int segments) {
    Mesh m;
    segments = std::max(3, segments);
    const int rings = std::max(2, segments / 2);
    const double pi = std::numbers::pi;
    for (int r = 0; r <= rings; ++r) {
        const double theta = pi * r / rings;
        for (int s = 0; s <= segments; ++s) {
            const double phi = 2 * pi * s / segments;
            const Vec3 p{std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi)};
            m.positions.push_back(p);
            m.normals.push_back(p);
            m.uvs.push_back({double(s) / segments, double(r) / rings});
        }
    }
    auto at = [segments](int r, int s) { return r * (segments + 1) + s; };
    for (int r = 0; r < rings; ++r) {
        for (int s = 0; s < segments; ++s) {
            if (r > 0) m.triangles.push_back({at(r, s), at(r + 1, s + 1), at(r, s + 1)});
            if (r + 1 < rings) m.triangles.push_back({at(r, s), at(r + 1, s), at(r + 1, s + 1)});
        }
    }
    return m;
}

namespace {

// A prism of `sides` faces around the y axis (radius 1, y from -height to height, no caps) with
// SMOOTH normals: each corner's normal points straight out from the axis, so inside a face the
// interpolated normal is shorter than 1 (cos(pi / sides) at the face's middle). u goes `turns`
// times around, v from 0 at the top to 1 at the bottom.
Mesh smooth_prism(int sides, double height, double turns) {
    Mesh m;
    const double pi = std::numbers::pi;
    for (int r = 0; r <= 1; ++r) {
        for (int s = 0; s <= sides; ++s) {
            const double phi = 2 * pi * s / sides;
            const Vec3 out{std::cos(phi), 0, -std::sin(phi)};
            m.positions.push_back(out + Vec3{0, r == 0 ? height : -height, 0});
            m.normals.push_back(out);
            m.uvs.push_back({turns * s / sides, double(r)});
        }
    }
    for (int s = 0; s < sides; ++s) {
        const int top = s, bottom = sides + 1 + s;
        m.triangles.push_back({top, bottom, bottom + 1});
        m.triangles.push_back({top, bottom + 1, top + 1});
    }
    return m;
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

Item item(Mesh mesh, MaterialSpec material = {}) {
    Item it;
    it.mesh = std::move(mesh);
    it.material = material;
    return it;
}

MaterialSpec unlit(int texture, Filter filter) {
    MaterialSpec m;
    m.texture = texture;
    m.filter = filter;
    m.lit = false;
    return m;
}

MaterialSpec plain(Color c, Vec3 specular = {}, double shininess = 32) {
    MaterialSpec m;
    m.color = c;
    m.specular = specular;
    m.shininess = shininess;
    return m;
}

TextureSpec tex(Pattern p, int w, int h, int cells = 2, Wrap wu = Wrap::kRepeat, Wrap wv = Wrap::kRepeat) {
    TextureSpec t;
    t.pattern = p;
    t.width = w;
    t.height = h;
    t.cells = cells;
    t.wrap_u = wu;
    t.wrap_v = wv;
    return t;
}

constexpr auto numbers = &cp::numbers_scene<Scene>;
constexpr auto picture = &cp::picture_scene<Scene>;

// A camera at a generic position (no vertex lands exactly on a pixel boundary).
Camera cam(Vec3 eye, Vec3 target = {0.013, -0.021, 0.007}, double near = 0.5, double far = 100) {
    return cp::camera_at<Camera>(eye, target, near, far);
}

Panel panel(Camera c, std::vector<Item> items, std::vector<TextureSpec> textures, int x0, int y0, int w, int h) {
    Panel p;
    p.camera = c;
    p.items = std::move(items);
    p.textures = std::move(textures);
    p.x0 = x0;
    p.y0 = y0;
    p.w = w;
    p.h = h;
    return p;
}

LightSpec sun(Vec3 travel, Vec3 intensity = {0.85, 0.85, 0.85}, bool shadows = false) { return {travel, intensity, shadows}; }

const Color kFloor{200, 200, 190}, kBoxColor{210, 120, 80}, kRed{220, 70, 60}, kGreen{70, 190, 90}, kBlue{70, 110, 230};

// A floor quad at height y, x in [-s, s], z in [z_near, z_far] (z_far < z_near), facing up, uv
// (0, 0) at the near left corner to (u, v) at the far right one.
Mesh floor_quad(double y, double s, double z_near, double z_far, Vec2 uv) {
    return quad({-s, y, z_near}, {s, y, z_near}, {s, y, z_far}, {-s, y, z_far}, {0, 0}, uv);
}

// A quad facing +z in the plane z, half-size s, uv from uv0 (top left) to uv1 (bottom right):
// v grows DOWN the quad, as it does down the texture image.
Mesh facing_quad(double s, double z, Vec2 uv0, Vec2 uv1) {
    Mesh m = quad({-s, s, z}, {-s, -s, z}, {s, -s, z}, {s, s, z}, {0, 0}, {1, 1});
    m.uvs = {{uv0.x, uv0.y}, {uv0.x, uv1.y}, {uv1.x, uv1.y}, {uv1.x, uv0.y}};
    return m;
}

// A floor trapezoid at height y, from half-width near_half at z_near to far_half at z_far, chosen
// to lie inside the view volume: nothing is clipped (a clipped polygon's fan is free, and the
// uv and level of detail of a far, minified fragment depend on the fan triangle's snapped
// corners). Its uv are the world x and -z times k, one affine map for both triangles.
Mesh ground(double y, double near_half, double z_near, double far_half, double z_far, double k) {
    Mesh m;
    m.positions = {{-near_half, y, z_near}, {near_half, y, z_near}, {far_half, y, z_far}, {-far_half, y, z_far}};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    for (const Vec3& q : m.positions) {
        m.uvs.push_back({q.x * k, -q.z * k});
        m.normals.push_back({0, 1, 0});
    }
    return m;
}

// The shadow scenes' floor and box (standing on the floor, turned about y). The floor lies
// inside the view volume of the shadow scenes' cameras: a clipped polygon's fan is free, and
// another fan moves each fragment's world position by up to a 32nd of a pixel, which may move a
// lookup near a texel boundary into the next texel (a step of a ninth with PCF, which the
// picture's tolerance would not absorb).
std::vector<Item> floor_and_box(Vec3 box_at, double box_half, double turn) {
    Item floor = item(floor_quad(0, 2.2, 2.2, -2.2, {1, 1}), plain(kFloor));
    Item box = item(box_mesh(), plain(kBoxColor));
    box.position = box_at;
    box.size = {box_half, box_half, box_half};
    box.angle = turn;
    return {floor, box};
}

std::vector<Scene> build() {
    std::vector<Scene> all;
    auto add = [&all](Scene s) { all.push_back(std::move(s)); };

    // ---- numbers ----
    add(numbers("m5.wrap", "Wrap modes on whole-number texel indices, negative and huge",
                "repeat is i mod n in [0, n) (so -1 is n - 1), clamp min(max(i, 0), n - 1), mirrored m = i mod 2n, "
                "then m or 2n - 1 - m; any finite index (1e300 included) wraps exactly with std::fmod",
                {1}, {Group::kWrap}));
    add(numbers("m5.sampling", "Nearest and bilinear samples: texel centers at half-integers",
                "x = u * w; nearest reads texel floor(x); bilinear uses x - 0.5, i = floor, a = the fraction, and "
                "weights (1 - a)(1 - b), a(1 - b), (1 - a)b, ab; NaN or infinite uv is black",
                {2, 1}, {Group::kSampling}));
    add(numbers("m5.mipmaps", "Mipmap pyramids of 8x8, 1x1, 3x5, 7x1 and 5x2 textures",
                "level k + 1 is max(1, floor(w / 2)) by max(1, floor(h / 2)); each texel the plain average of 2x2 "
                "texels of level k (an odd last row or column is dropped); down to 1x1",
                {3}, {Group::kMipmaps}));
    add(numbers("m5.lod", "Screen-space uv derivatives and the level of detail",
                "du/dx = (A_x B - A B_x) / B^2 with A = sum l_i u_i / w_i and B = sum l_i / w_i; rho in TEXEL units "
                "(W du/dx, H dv/dx), lambda = log2(rho), not clamped",
                {4}, {Group::kLod}));
    add(numbers("m5.filters", "sample(): nearest, bilinear, nearest-mip and trilinear, lambda clamped",
                "lambda <= 0 (or NaN) magnifies with bilinear on level 0; else clamp to [0, L - 1]; nearest-mip reads "
                "level floor(lambda + 0.5); trilinear blends floor(lambda) and the next by the fraction; build the "
                "pyramid once, when a level above 0 is read (free where only level 0 is)",
                {4, 3, 2}, {Group::kFilter}));
    add(numbers("m5.blinn_phong", "Blinn-Phong values: halfway vector, shininess, a light behind",
                "normalize N, V, L; nothing at all when dot(N, L) <= 0; else base c I + specular max(0, N.H)^s I with "
                "H = normalize(L + V)",
                {6}, {Group::kBlinnPhong}));
    add(numbers("m5.normal_maps", "Tangent frames and normal-mapped normals",
                "T = (e1 dv2 - e2 dv1) / r, B = (e2 du1 - e1 du2) / r; Gram-Schmidt T against n, B' = cross(n, T') "
                "(negated if it points away from B); texel to 2 t / 255 - 1; no frame: n unchanged",
                {7}, {Group::kTangent}));
    add(numbers("m5.shadow_lookup", "The light's matrix and shadow lookups on a 4x4 map",
                "orthographic(-r, r, -r, r, r, 3r) * look_at(center - 2r dir, center, up); shadowed when d - bias / "
                "(2r) > stored, bias = constant + slope * min(tan, 10); outside or never drawn is lit; PCF: lit "
                "fraction of 3x3",
                {8}, {Group::kShadow}));

    // ---- the rasterizer alone ----
    {
        constexpr double kRecedeUv = 1.0;
        Scene s = picture("m5.fill_triangle", "Three textured triangles and two exact ties straight through fill_triangle",
                          "per covered pixel center: key and depth pre-test, perspective-correct uv (u/w, v/w, 1/w), "
                          "lambda from uv_derivatives at the pixel center (x + 0.5, y + 0.5) for a mip filter, sample(), "
                          "to_color; a tie of keys goes to "
                          "m4::depth_passes (the brighter color stays, whichever is drawn last)",
                          {5, 2, 4}, 192, 96);
        Panel pn = panel(cam({0, 0, 5}), {}, {tex(Pattern::kChecker, 16, 16, 8), tex(Pattern::kFine, 64, 64), tex(Pattern::kNoise, 64, 64)}, 0, 0, 192, 96);
        pn.textures[1].a = {240, 240, 250};
        pn.textures[1].b = {40, 60, 140};
        // Counter-clockwise, w from 1 to 5: the checker squares bend toward the near corner.
        pn.screen_tris.push_back({{Vec3{6.3, 8.6, 0.2}, Vec3{120.4, 14.2, 0.6}, Vec3{30.2, 88.7, -0.1}},
                                  {1, 5, 2},
                                  {Vec2{0, 0}, Vec2{2, 0}, Vec2{0, 2}},
                                  unlit(0, Filter::kNearest)});
        // Clockwise, in front of the first along part of it, minified: trilinear.
        pn.screen_tris.push_back({{Vec3{20.6, 84.3, 0.5}, Vec3{112.7, 80.1, -0.3}, Vec3{80.1, 6.4, 0.4}},
                                  {1.5, 1, 6},
                                  {Vec2{0, 0}, Vec2{2, 0}, Vec2{1, 2}},
                                  unlit(1, Filter::kTrilinear)});
        // On the right, steeply receding (w from 1 at the bottom to 60 along the top edge), noise
        // with nearest-mip: near the top lambda grows by about half a level per pixel, so along
        // each row where it crosses 0.5, 1.5, 2.5, ... lambda taken at the pixel's corner instead
        // of its center reads the other level (noise levels differ everywhere).
        pn.screen_tris.push_back({{Vec3{160.7, 92.6, 0.3}, Vec3{189.4, 4.2, 0.9}, Vec3{130.3, 3.4, 0.9}},
                                  {1, 60, 60},
                                  {Vec2{kRecedeUv / 2, 2 * kRecedeUv}, Vec2{kRecedeUv, 0}, Vec2{0, 0}},
                                  unlit(2, Filter::kNearestMip)});
        // Two exact ties, in front of everything: each small triangle drawn twice with the same
        // positions and w (so the same keys) in two plain colors, the brighter one (larger red)
        // first on the left and last on the right. m4::depth_passes keeps the brighter color
        // whichever comes last; a fill_triangle that skips it keeps the last (or the first) copy.
        const Color brighter{235, 190, 70}, darker{80, 200, 235};
        const std::array<Vec3, 3> left = {Vec3{2.3, 66.4, -0.5}, Vec3{26.6, 93.2, -0.4}, Vec3{3.1, 93.6, -0.6}};
        const std::array<Vec3, 3> right = {Vec3{104.2, 28.3, -0.5}, Vec3{125.7, 31.6, -0.6}, Vec3{117.4, 66.2, -0.4}};
        for (const auto& [at, first, last] : {std::tuple{left, brighter, darker}, std::tuple{right, darker, brighter}}) {
            for (const Color& color : {first, last}) {
                MaterialSpec m;
                m.color = color;
                m.lit = false;
                pn.screen_tris.push_back({at, {1, 1.5, 2}, {Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}}, m});
            }
        }
        s.panels.push_back(pn);
        add(s);
    }

    // ---- filtering ----
    {
        Scene s = picture("m5.magnify", "Pure magnification: nearest, bilinear, and trilinear (no pyramid)",
                          "a 4x4 texture over 80 pixels: nearest shows squares, bilinear blends between texel CENTERS; "
                          "a mip filter with lambda <= 0 is bilinear on level 0 and builds no pyramid",
                          {2, 4, 5}, 288, 96);
        const Filter filters[3] = {Filter::kNearest, Filter::kBilinear, Filter::kTrilinear};
        for (int p = 0; p < 3; ++p) {
            Panel pn = panel(cam({0.02, 0.03, 4.2}), {item(facing_quad(1.6, 0, {0, 0}, {1, 1}), unlit(0, filters[p]))},
                             {tex(Pattern::kNoise, 4, 4, 1, Wrap::kClampToEdge, Wrap::kClampToEdge)}, 96 * p, 0, 96, 96);
            s.panels.push_back(pn);
        }
        s.checks.same_panels = {{1, 2}};
        s.checks.same_tolerance = 0;
        add(s);
    }
    {
        Scene s = picture("m5.receding_filters", "A receding textured plane with each filter, against a 16x supersampled truth",
                          "nearest and bilinear alias far away; nearest-mip and trilinear pick the level from lambda, taken at "
                          "each pixel center (x + 0.5, y + 0.5); "
                          "each panel's error must be close to the reference's",
                          {4, 3, 2, 5}, 256, 160);
        const Filter filters[4] = {Filter::kNearest, Filter::kBilinear, Filter::kNearestMip, Filter::kTrilinear};
        for (int p = 0; p < 4; ++p) {
            TextureSpec t = tex(Pattern::kFine, 32, 32);
            t.a = {235, 225, 200};
            t.b = {50, 70, 120};
            Panel pn = panel(cam({0.04, 0.6, 4}, {0.01, -0.6, -6}, 0.5, 100),
                             {item(ground(-1, 1.8, 1, 38, -60, 0.5), unlit(0, filters[p]))}, {t}, 128 * (p % 2), 80 * (p / 2),
                             128, 80);
            pn.timed = true;
            s.panels.push_back(pn);
        }
        s.checks.filter_error = true;
        s.demo = true;
        add(s);
    }
    {
        Scene s = picture("m5.wrap_quad", "Wrap modes on a quad whose uv runs from -1.25 to 2.25",
                          "repeat tiles, clamp to edge stretches the border texels, mirrored repeat flips every other "
                          "copy; u and v wrap independently (the last panel repeats u and mirrors v)",
                          {1, 2, 5}, 384, 96);
        const Wrap wu[4] = {Wrap::kRepeat, Wrap::kClampToEdge, Wrap::kMirroredRepeat, Wrap::kRepeat};
        const Wrap wv[4] = {Wrap::kRepeat, Wrap::kClampToEdge, Wrap::kMirroredRepeat, Wrap::kMirroredRepeat};
        for (int p = 0; p < 4; ++p) {
            TextureSpec t = tex(Pattern::kArrow, 16, 16, 1, wu[p], wv[p]);
            t.a = {250, 230, 90};
            t.b = {40, 60, 90};
            Panel pn = panel(cam({0.02, 0.03, 4.2}), {item(facing_quad(1.7, 0, {-1.25, -1.25}, {2.25, 2.25}), unlit(0, Filter::kNearest))},
                             {t}, 96 * p, 0, 96, 96);
            s.panels.push_back(pn);
        }
        s.checks.nearest_truth = true;
        add(s);
    }
    {
        Scene s = picture("m5.tiny_textures", "A 1x1, a 3x5 and a 7x1 texture, minified with trilinear",
                          "a 1x1 texture has one level (lambda clamps to 0); a 3x5 one has levels 3x5, 1x2, 1x1; "
                          "7x1 has 7x1, 3x1, 1x1 (odd last columns dropped)",
                          {3, 4}, 288, 96);
        const TextureSpec texs[3] = {tex(Pattern::kNoise, 1, 1), tex(Pattern::kNoise, 3, 5), tex(Pattern::kNoise, 7, 1)};
        for (int p = 0; p < 3; ++p) {
            TextureSpec t = texs[p];
            t.seed = 7 + std::uint32_t(p);
            Panel pn = panel(cam({0.04, 0.6, 4}, {0.01, -0.6, -6}, 0.5, 100),
                             {item(ground(-1, 1.1, 1, 23, -60, 0.5), unlit(0, Filter::kTrilinear))}, {t}, 96 * p, 0, 96, 96);
            s.panels.push_back(pn);
        }
        add(s);
    }
    {
        Scene s = picture("m5.perspective_uv", "Floors through draw_scene: perspective-correct uv (left) and normals (right)",
                          "interpolate u/w, v/w and 1/w linearly on the screen, then divide (m4::perspective_weights); "
                          "the normal and the world position of a lit material go through the same weights",
                          {5, 9, 6}, 256, 96);
        // The whole floor lies inside the view volume: nothing is clipped.
        const Camera view = cam({0.05, 0.9, 4.5}, {0.02, -0.9, -3}, 0.5, 50);
        Panel pn = panel(view, {item(floor_quad(-1, 1.5, 1.5, -9, {1, 1}), unlit(0, Filter::kNearest))},
                         {tex(Pattern::kChecker, 8, 8, 8)}, 0, 0, 128, 96);
        pn.textures[0].a = {255, 255, 255};
        pn.textures[0].b = {32, 32, 32};
        s.panels.push_back(pn);
        // The same floor, plain and lit, its normals leaning toward the eye at the near edge and
        // away from it at the far one: interpolated with the screen weights instead, the light
        // falls off at the wrong depth (w runs from about 3 to 13 over the floor).
        Mesh leaning = floor_quad(-1, 1.5, 1.5, -9, {1, 1});
        const Vec3 near_n = unit({0, 0.5, 0.85}), far_n = unit({0, 0.5, -0.85});
        leaning.normals = {near_n, near_n, far_n, far_n};
        Panel lit = panel(view, {item(leaning, plain(kFloor))}, {}, 128, 0, 128, 96);
        lit.lights = {sun({0, -0.5, -0.85}, {0.85, 0.85, 0.85})};
        s.panels.push_back(lit);
        s.checks.nearest_truth = true;  // on the textured panel
        add(s);
    }
    {
        Scene s = picture("m5.huge_uv", "uv near 1e7: double keeps the fraction (float would not)",
                          "keep uv in double from the vertices to the sample: at 1e7 a float's spacing is 1, so every "
                          "texel between whole numbers would be lost",
                          {2, 1, 5}, 288, 96);
        const double offsets[3] = {0, 1e7, 1e7};
        const Filter filters[3] = {Filter::kBilinear, Filter::kBilinear, Filter::kTrilinear};
        for (int p = 0; p < 3; ++p) {
            const double o = offsets[p];
            TextureSpec t = tex(Pattern::kGradient, 16, 16);
            t.a = {30, 40, 0};
            t.b = {240, 230, 0};
            Panel pn = panel(cam({0.02, 0.03, 4.2}), {item(facing_quad(1.6, 0, {o, o}, {o + 1, o + 1}), unlit(0, filters[p]))},
                             {t}, 96 * p, 0, 96, 96);
            s.panels.push_back(pn);
        }
        s.checks.same_panels = {{0, 1}, {0, 2}};
        s.checks.same_tolerance = 1;
        add(s);
    }
    {
        Scene s = picture("m5.grazing", "A plane at a grazing angle: lambda at its clamp far away",
                          "far away rho is huge: clamp lambda to L - 1, so the 1x1 level (the texture's average) is "
                          "read; never index past the last level",
                          {4, 3, 5}, 256, 64);
        const Filter filters[2] = {Filter::kTrilinear, Filter::kNearestMip};
        for (int p = 0; p < 2; ++p) {
            TextureSpec t = tex(Pattern::kChecker, 16, 16, 4);
            t.a = {240, 120, 60};
            t.b = {30, 90, 200};
            // Rows at the clamp grow as sqrt(eye height * repeats per unit / pixel angle): at 0.5 above the
            // floor (a scene seed moves the eye by up to 0.1) and a repeat per unit, about six rows read
            // the 1x1 level, most of them away from the horizon's edge, where any difference counts.
            const Mesh floor = ground(0, 0.8, 3, 150, -200, 1);
            Panel pn = panel(cam({0.03, 0.5, 4}, {0.01, 0.02, -10}, 0.05, 300), {item(floor, unlit(0, filters[p]))}, {t},
                             128 * p, 0, 128, 64);
            s.panels.push_back(pn);
        }
        add(s);
    }

    // ---- light ----
    {
        Scene s = picture("m5.specular_spheres", "Three spheres, shininess 8, 32 and 128: Blinn-Phong per pixel",
                          "per fragment: N normalized, V toward the eye, H = normalize(L + V), specular max(0, N.H)^s; "
                          "each sphere within half a level of the reference's error against the exact spheres",
                          {6, 5, 9}, 240, 96);
        Panel pn = panel(cam({0.02, 0.3, 6}, {0.01, 0, 0}), {}, {}, 0, 0, 240, 96);
        const double shininess[3] = {8, 32, 128};
        const Color colors[3] = {kRed, kGreen, kBlue};
        for (int k = 0; k < 3; ++k) {
            Item ball = item(uv_sphere(32), plain(colors[k], {200, 200, 200}, shininess[k]));
            ball.position = {-2.3 + 2.3 * k, 0, 0};
            ball.size = {0.95, 0.95, 0.95};
            pn.items.push_back(ball);
        }
        pn.lights = {sun({-0.5, -0.6, -1}, {0.8, 0.8, 0.8}), sun({0.8, -0.2, -0.4}, {0.25, 0.2, 0.15})};
        s.panels.push_back(pn);
        s.checks.sphere_error = true;
        s.demo = true;
        add(s);
    }
    {
        // A non-uniform scale makes m4::normal_matrix's normals of different lengths: along y
        // (squashed to 0.5) twice as long as unit, along x (stretched to 1.7) less than 0.6. On a
        // coarse sphere each triangle spans a wide turn of the normal, so normals interpolated
        // before they are normalized lean toward the long ones, and the highlights move.
        Scene s = picture("m5.squashed_sphere",
                          "A coarse sphere squashed to an ellipsoid, lit with highlights: world normals normalized",
                          "draw_scene turns each vertex normal with m4::normal_matrix(model) and NORMALIZES it before "
                          "it is interpolated: under a non-uniform scale the turned normals have different lengths, and "
                          "interpolating them as they are leans every fragment's normal toward the longer ones",
                          {9, 5, 6}, 128, 96);
        Item ball = item(uv_sphere(10), plain({90, 150, 210}, {220, 220, 220}, 12));
        ball.size = {1.7, 0.5, 1.0};
        ball.axis = {0, 1, 0};
        ball.angle = 0.3;
        Panel pn = panel(cam({0.02, 1.0, 3.1}, {0.01, -0.05, 0}), {ball}, {}, 0, 0, 128, 96);
        pn.lights = {sun({-0.4, -0.8, -0.6}, {0.75, 0.75, 0.75}), sun({0.7, -0.1, -0.5}, {0.35, 0.3, 0.25})};
        s.panels.push_back(pn);
        add(s);
    }
    {
        Scene s = picture("m5.normal_map",
                          "Normal-mapped: a quad with sheared uv, one square but turned, a coarse prism with smooth "
                          "normals, a quad whose map clamps u and mirrors v, and a textured quad (nearest) on a coarse "
                          "map (left to right)",
                          "T and B from the WORLD positions and uv; T' = T made orthogonal to N, B' = cross(N, T') (not "
                          "B itself: with sheared uv it is not perpendicular to T); the texel as 2 t / 255 - 1; N "
                          "normalized before perturb_normal (inside a triangle of the prism the interpolated normal is "
                          "shorter than 1); the map read with its own wrap modes (on the fourth quad, uv outside [0, 1]: "
                          "clamp to edge in u stretches the flat edge texels; the bumps lie in the map's top half, and "
                          "mirrored repeat in v reads that half again above the map and the flat bottom half below it); "
                          "the map read with sample_bilinear on level 0 whatever the material's filter (on the far right "
                          "the texture is nearest, and the 8x8 map, magnified, stays smooth); a second light grazes "
                          "the turned quad from behind its plane, and only the bumps that face it catch it: whether a "
                          "light arrives, c = dot(N, L) > 0, is asked of the PERTURBED normal",
                          {7, 6, 5, 9}, 640, 96);
        for (int p = 0; p < 2; ++p) {
            Mesh q = quad({-1.7, -1.2, 0}, {1.7, -1.2, 0}, {1.7, 1.2, 0}, {-1.7, 1.2, 0});
            // uv at the corners: v grows down the quad; the sheared one slides u by 0.9 per v.
            const double shear = p == 0 ? 0.9 : 0;
            q.uvs = {{0, 2}, {3, 2}, {3 + 2 * shear, 0}, {2 * shear, 0}};
            MaterialSpec m = plain({200, 180, 160}, {140, 140, 140}, 24);
            m.normal_map = 0;
            Item it = item(q, m);
            // The square one is turned in its own plane: its tangent frame must come from the
            // world positions (the model's frame, not turned, lights the bumps from the wrong side).
            if (p == 1) {
                it.axis = {0, 0, 1};
                it.angle = 0.6;
            }
            Panel pn = panel(cam({0.02, 0.03, 4.2}), {it}, {tex(Pattern::kBumps, 64, 64, 4)}, 128 * p, 0, 128, 96);
            pn.lights = {sun({-0.6, -0.5, -0.8}, {0.8, 0.8, 0.8})};
            // On the turned quad, a second light from the right, 7 degrees behind its plane: the
            // geometry faces away from it, the bumps' slopes toward it catch it.
            if (p == 1) pn.lights.push_back(sun({-0.99, 0.05, 0.12}, {0.9, 0.7, 0.5}));
            s.panels.push_back(pn);
        }
        // Six faces with smooth normals: in the middle of a face the interpolated normal has
        // length cos(30 degrees), so a normal not normalized before perturb_normal tilts the bumps
        // too far from it (the bumps' slopes weigh more against a shorter n).
        MaterialSpec m = plain({200, 180, 160}, {140, 140, 140}, 24);
        m.normal_map = 0;
        Item prism = item(smooth_prism(4, 1.1, 4), m);
        prism.axis = {0.45, 1, 0.25};
        prism.angle = 0.6;
        TextureSpec bumps = tex(Pattern::kBumps, 32, 32, 1);
        bumps.bump_height = 0.2;
        Panel pn = panel(cam({0.02, 0.03, 4.2}), {prism}, {bumps}, 256, 0, 128, 96);
        pn.lights = {sun({-0.6, -0.5, -0.8}, {0.8, 0.8, 0.8})};
        s.panels.push_back(pn);
        // The normal map has wrap modes of its own: clamp to edge in u, mirrored repeat in v, and
        // the quad's uv run past [0, 1] on every side. Left and right of the middle third, clamp
        // stretches the map's flat edge texels (no bump reaches the edge), so the expected surface
        // is smooth there; read with repeat, steep bumps appear, lit by a light raking along u.
        // The map's bumps lie in its top half only: above the map (v < 0) mirrored repeat reads
        // that top half again, and below it (v > 1) the flat bottom half, so the expected surface
        // is smooth below the middle; read with repeat in v, the two swap and bumps rise there.
        Mesh wq = quad({-1.7, -1.2, 0}, {1.7, -1.2, 0}, {1.7, 1.2, 0}, {-1.7, 1.2, 0});
        wq.uvs = {{-1, 1.5}, {2, 1.5}, {2, -0.5}, {-1, -0.5}};
        MaterialSpec wm = plain({200, 180, 160}, {140, 140, 140}, 24);
        wm.normal_map = 0;
        TextureSpec half_bumps = tex(Pattern::kBumps, 32, 32, 2, Wrap::kClampToEdge, Wrap::kMirroredRepeat);
        half_bumps.bumps_top_half = true;
        Panel pw = panel(cam({0.02, 0.03, 4.2}), {item(wq, wm)}, {half_bumps}, 384, 0, 128, 96);
        pw.lights = {sun({-0.9, -0.25, -0.45}, {0.8, 0.8, 0.8})};
        s.panels.push_back(pw);
        // A textured material whose filter is nearest, on a coarse 8x8 map magnified about 9
        // times: the normal map is read with sample_bilinear on level 0 whatever the material's
        // filter, so the bump is smooth; read through sample() with the material's filter, it
        // breaks into flat facets, one per texel. The texture's two colors are close (no texel
        // edge is a color edge).
        MaterialSpec nm = plain({200, 180, 160}, {140, 140, 140}, 24);
        nm.texture = 0;
        nm.filter = Filter::kNearest;
        nm.normal_map = 1;
        TextureSpec base = tex(Pattern::kChecker, 16, 16, 4);
        base.a = {205, 185, 165};
        base.b = {195, 178, 156};
        TextureSpec coarse = tex(Pattern::kBumps, 8, 8, 1);
        coarse.bump_height = 0.25;
        Panel pc = panel(cam({0.02, 0.03, 4.2}), {item(facing_quad(1.4, 0, {0, 0}, {1, 1}), nm)}, {base, coarse}, 512, 0, 128, 96);
        pc.lights = {sun({-0.6, -0.5, -0.8}, {0.8, 0.8, 0.8})};
        s.panels.push_back(pc);
        s.demo = true;
        add(s);
    }
    {
        Scene s = picture("m5.degenerate_uv", "Normal-mapped triangles whose uv make no tangent frame: no NaN",
                          "when r = du1 dv2 - du2 dv1 is 0 (all three uv equal, or on one line) or not finite, "
                          "tangent_frame is not valid and the normal stays unperturbed",
                          {7, 9}, 96, 96);
        Mesh m;
        m.positions = {{-1.6, -1.4, 0}, {0, -1.5, 0.1}, {-0.8, 0.1, 0},     // good uv
                       {0.1, -1.4, 0},  {1.6, -1.3, 0}, {0.8, 0.1, 0.1},    // all three uv equal
                       {-1.6, 0.2, 0},  {0, 0.1, 0.1},  {-0.7, 1.6, 0},     // uv on one line
                       {0.1, 0.2, 0.1}, {1.6, 0.1, 0},  {0.8, 1.6, 0}};     // a NaN uv
        m.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}};
        m.uvs = {{0, 1}, {1, 1}, {0.5, 0}, {0.3, 0.3}, {0.3, 0.3}, {0.3, 0.3},
                 {0, 0}, {0.5, 0.5}, {1, 1}, {0, 1}, {kNaN, 1}, {0.5, 0}};
        const Vec3 n = unit(Vec3{0.02, 0.03, 1});
        m.normals.assign(m.positions.size(), n);
        MaterialSpec mat = plain({190, 200, 170}, {150, 150, 150}, 16);
        mat.normal_map = 0;
        Panel pn = panel(cam({0.02, 0.03, 4}), {item(m, mat)}, {tex(Pattern::kBumps, 32, 32, 2)}, 0, 0, 96, 96);
        pn.lights = {sun({-0.5, -0.4, -1})};
        s.panels.push_back(pn);
        add(s);
    }

    // ---- shadows ----
    {
        Scene s = picture("m5.shadow_box", "A box on a floor and its shadow, against a ray cast to the light",
                          "depth pass from the light (orthographic, light_view_projection), then per fragment the "
                          "map's texel and d - bias / (2r) > stored",
                          {8, 9}, 128, 96);
        std::vector<Item> items = floor_and_box({0.2, 0.6, -0.1}, 0.6, 0.4);
        Item small = item(box_mesh(), plain({90, 160, 210}));
        small.position = {-1.3, 1.5, 0.8};
        small.size = {0.3, 0.3, 0.3};
        items.push_back(small);
        Panel pn = panel(cam({0.3, 3.2, 5.5}, {0.01, 0.2, 0.02}, 0.5, 50), items, {}, 0, 0, 128, 96);
        pn.lights = {sun({-0.5, -1, -0.35}, {0.85, 0.85, 0.85}, true)};
        pn.shadows.resolution = 1024;
        pn.shadows.center = {0, 0.5, 0};
        pn.shadows.radius = 3.6;
        pn.shadows.pcf = false;
        s.panels.push_back(pn);
        s.checks.shadow_state = true;
        add(s);
    }
    {
        Scene s = picture("m5.two_suns", "Two suns that cast shadows, one that casts none, and a box that casts none",
                          "one shadow map per light that casts shadows (none for the others), each looked up by its own "
                          "light; the depth passes draw only the objects that cast shadows",
                          {8, 9}, 128, 96);
        std::vector<Item> items = floor_and_box({0.3, 0.6, 0.1}, 0.6, 0.4);
        Item hover = item(box_mesh(), plain({90, 160, 210}));
        hover.position = {-1.1, 1.15, -0.5};
        hover.size = {0.45, 0.45, 0.45};
        hover.casts_shadow = false;  // lit like the rest, but the floor under it stays lit
        items.push_back(hover);
        Panel pn = panel(cam({0.3, 3.2, 5.5}, {0.01, 0.2, 0.02}, 0.5, 50), items, {}, 0, 0, 128, 96);
        // The first light casts no shadow, so the second light's map is not the first map made
        // if maps are numbered by light; the two casting suns throw two shadows of the box.
        pn.lights = {sun({0.2, -1, 0.6}, {0.25, 0.25, 0.3}), sun({-0.6, -1, -0.3}, {0.5, 0.45, 0.4}, true),
                     sun({0.8, -1, -0.2}, {0.35, 0.4, 0.5}, true)};
        pn.shadows.resolution = 1024;
        pn.shadows.center = {0, 0.5, 0};
        pn.shadows.radius = 3.6;
        pn.shadows.pcf = false;
        s.panels.push_back(pn);
        add(s);
    }
    {
        Scene s = picture("m5.shadow_acne", "A light 9 degrees above the floor: acne without bias, peter panning with too much",
                          "bias = constant + slope * min(tan(theta), 10) in world units, compared as d - bias / (2r) > "
                          "stored; the right panel's bias is too large on purpose (its shadow detaches)",
                          {8, 9}, 256, 96);
        for (int p = 0; p < 2; ++p) {
            Panel pn = panel(cam({0.3, 3.0, 5.5}, {0.01, 0.1, 0.02}, 0.5, 50), floor_and_box({0.8, 0.3, 0.1}, 0.3, 0.3), {},
                             128 * p, 0, 128, 96);
            pn.lights = {sun({-1, -0.17, -0.3}, {0.85, 0.85, 0.85}, true)};
            pn.shadows.resolution = 512;
            pn.shadows.center = {0, 0, 0};
            pn.shadows.radius = 4.3;
            pn.shadows.pcf = false;
            if (p == 1) pn.shadows.constant_bias = 0.6;
            s.panels.push_back(pn);
        }
        s.checks.shadow_state = true;
        add(s);
    }
    {
        Scene s = picture("m5.pcf", "A coarse shadow map (128 texels) without and with 3x3 PCF",
                          "PCF: the lit fraction of the 3x3 texels around the one p falls in, each compared with the "
                          "same biased depth; a texel outside the map counts as lit",
                          {8, 9}, 256, 96);
        for (int p = 0; p < 2; ++p) {
            Panel pn = panel(cam({0.3, 3.2, 5.5}, {0.01, 0.2, 0.02}, 0.5, 50), floor_and_box({0.1, 0.7, 0}, 0.7, 0.6), {},
                             128 * p, 0, 128, 96);
            pn.lights = {sun({-0.7, -1, 0.45}, {0.85, 0.85, 0.85}, true)};  // the shadow falls toward the camera
            pn.shadows.resolution = 128;
            pn.shadows.center = {0, 0.5, 0};
            pn.shadows.radius = 3.6;
            // PCF compares the point's depth with texels up to 1.5 texels away, so on a surface
            // sloped against the light it needs more bias than one texel's lookup: 0.06 + 0.1 tan.
            pn.shadows.constant_bias = 0.06;
            pn.shadows.slope_bias = 0.1;
            pn.shadows.pcf = p == 1;
            s.panels.push_back(pn);
        }
        s.checks.shadow_state = true;
        s.demo = true;
        add(s);
    }
    {
        Scene s = picture("m5.light_behind", "A shadow-casting light from below the floor: ambient only",
                          "where dot(N, L) <= 0 the light adds nothing (no diffuse, no specular) and no shadow lookup "
                          "is made; the depth pass still runs, with both faces: the floor, seen from below, shadows "
                          "the ball's underside, the one surface that faces the light",
                          {6, 8, 9}, 128, 96);
        std::vector<Item> items = floor_and_box({0.2, 0.9, -0.1}, 0.6, 0);
        items[1].material.specular = {200, 200, 200};
        Item ball = item(uv_sphere(24), plain(kGreen, {200, 200, 200}, 16));
        ball.position = {-1.3, 0.7, 0.6};
        ball.size = {0.5, 0.5, 0.5};
        items.push_back(ball);
        Panel pn = panel(cam({0.3, 3.2, 5.5}, {0.01, 0.2, 0.02}, 0.5, 50), items, {}, 0, 0, 128, 96);
        pn.lights = {sun({0, 1, 0}, {0.85, 0.85, 0.85}, true)};
        pn.shadows.center = {0, 0.5, 0};
        pn.shadows.radius = 3.6;
        s.panels.push_back(pn);
        s.checks.shadow_state = true;  // the undersides the light faces are shadowed by the floor's back
        add(s);
    }

    // ---- only what a scene needs ----
    {
        Scene s = picture("m5.needs", "Four panels, four sets of needs: what each stage costs",
                          "untextured materials never sample; lambda only for mip filters; the pyramid only when a "
                          "fragment has lambda > 0, once per texture; an unlit material's normal map is never read "
                          "(no tangent frame either); the shadow pass only for a light that casts",
                          {9, 5, 4}, 288, 72);
        for (int p = 0; p < 4; ++p) {
            Panel pn = panel(cam({0.03, 0.05, 3.2}), {}, {}, 72 * p, 0, 72, 72);
            pn.lights = {sun({-0.6, -0.7, -1}, {0.7, 0.7, 0.7})};
            if (p == 0) pn.items.push_back(item(uv_sphere(24), plain(kRed)));
            if (p == 1) {
                pn.textures = {tex(Pattern::kChecker, 32, 16, 8)};
                MaterialSpec m = plain(kRed);
                m.texture = 0;
                m.filter = Filter::kBilinear;
                pn.items.push_back(item(uv_sphere(24), m));
            }
            if (p == 2) {
                // Unlit, with a normal map it never uses: no tangent frame, no normal-map read.
                pn.textures = {tex(Pattern::kNoise, 4, 4), tex(Pattern::kBumps, 16, 16, 2)};
                MaterialSpec m = unlit(0, Filter::kTrilinear);
                m.normal_map = 1;
                pn.items.push_back(item(facing_quad(1.0, 0, {0, 0}, {1, 1}), m));
            }
            if (p == 3) {
                // Two floors share one texture (one pyramid); one light casts shadows, one does not.
                // Inside the view volume: nothing is clipped.
                pn.camera = cam({0.03, 1.6, 5.5}, {0.01, -0.5, -2});
                pn.textures = {tex(Pattern::kFine, 64, 64)};
                MaterialSpec m = plain(kFloor);
                m.texture = 0;
                m.filter = Filter::kTrilinear;
                Item a = item(floor_quad(-1, 0.9, 1, -8, {4, 24}), m);
                a.position = {-1.1, 0, 0};
                Item b = a;
                b.position = {1.1, 0, 0};
                pn.items = {a, b};
                pn.lights = {sun({-0.6, -0.7, -1}, {0.5, 0.5, 0.5}, true), sun({0.6, -0.7, -0.3}, {0.3, 0.3, 0.3})};
                pn.shadows.resolution = 256;
                pn.shadows.radius = 5;
                pn.shadows.center = {0, -1, -3};
                pn.shadows.pcf = false;  // (PCF would need more than the default bias here)
            }
            s.panels.push_back(pn);
        }
        add(s);
    }

    // ---- extreme input ----
    {
        Scene s = picture("m5.extreme_input", "NaN and infinite uv, huge coordinates, needles, a vertex behind the eye; near 1e-6, far 1e6",
                          "NaN or infinite uv samples black, huge uv wraps exactly, a non-finite position drops its "
                          "triangle, clipping keeps w > 0; nothing may crash, hang or write outside the image",
                          {9, 5, 4, 1}, 192, 96);
        Mesh m;
        m.positions = {{-1.5, -1.3, 0}, {0.2, -1.4, 0}, {-0.6, 0.3, 0},            // good
                       {0.3, -1.3, 0},  {1.6, -1.2, 0}, {0.9, 0.2, 0},              // NaN uv
                       {-1.5, 0.5, 0},  {-0.2, 0.4, 0}, {-0.9, 1.6, 0},             // infinite uv
                       {-1.4, 1.7, 0},  {1.5, 1.72, 0}, {1.5, 1.7200001, 0},        // a needle
                       {kNaN, 0, 0},    {0.5, 0.5, 0},  {1e30, -1e30, -1},          // non-finite; huge (1 behind the rest)
                       {0.2, -0.1, 0.5}, {1.8, 1.6, 0.4}, {-1.6, 0.9, 5},           // one behind the eye
                       {0.5, 0.5, -1},  {0.2, -1.4, -1}};
        m.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}, {12, 13, 0}, {14, 18, 19}, {0, 1, 99}, {-1, 0, 1}};
        m.uvs = {{0, 0}, {2, 0}, {1, 2},  {kNaN, 0}, {1, 1}, {0, kNaN},  {kInf, 0}, {1, -kInf}, {0, 0},
                 {0, 0}, {5, 0}, {5, 1e-7}, {0, 0}, {0.5, 0.5}, {2, 0},  {0, 0}, {1, 0}, {0, 1},  {0, 2}, {1, 1}};
        m.normals.assign(m.positions.size(), Vec3{0, 0, 1});
        // The triangle through the eye's plane is tilted: its normal is its own, so that the
        // shadow's slope bias fits the surface (a normal far from the geometric one makes acne,
        // whose pattern any rounding moves).
        const Vec3 tilted = unit(raster::cross(m.positions[16] - m.positions[15], m.positions[17] - m.positions[15]));
        for (int k = 15; k <= 17; ++k) m.normals[std::size_t(k)] = tilted.z < 0 ? -tilted : tilted;
        MaterialSpec mat = plain({200, 200, 200}, {100, 100, 100}, 16);
        mat.texture = 0;
        mat.filter = Filter::kTrilinear;
        mat.normal_map = 1;
        // u = 2^996 at every corner: interpolated (with any rounding) it stays a multiple of a huge
        // power of two, so it wraps exactly to texel column 0. Bilinear: lambda is not needed
        // (its u derivative, exactly 0, would cancel catastrophically in the textbook formula).
        Mesh huge = quad({0.1, 0.5, 0}, {1.5, 0.4, 0}, {1.5, 1.5, 0}, {0.1, 1.5, 0});
        const double big = std::ldexp(1.0, 996);
        huge.uvs = {{big, 0}, {big, 0}, {big, 3}, {big, 3}};
        MaterialSpec huge_mat = plain({200, 200, 200});
        huge_mat.texture = 0;
        huge_mat.filter = Filter::kBilinear;
        // The triangle through the eye's plane, clipped by the near plane: its fan is free, and a
        // sliver of another fan has another level of detail (from its own snapped corners), so it
        // is sampled bilinearly (with its normal map).
        Mesh near = m;
        near.triangles = {{15, 16, 17}};
        MaterialSpec near_mat = mat;
        near_mat.filter = Filter::kBilinear;
        Panel p0 = panel(cam({0.02, 0.03, 4}), {item(m, mat), item(huge, huge_mat), item(near, near_mat)},
                         {tex(Pattern::kChecker, 16, 16, 4), tex(Pattern::kBumps, 16, 16, 2)}, 0, 0, 96, 96);
        p0.lights = {sun({-0.3, -0.4, -1}, {0.8, 0.8, 0.8}, true)};
        p0.shadows.resolution = 512;  // fine enough for the default bias on the tilted triangle (no acne)
        p0.shadows.pcf = false;  // a hard shadow edge: the clipped triangle's fan is free (see floor_and_box)
        s.panels.push_back(p0);
        // Near 1e-6 and far 1e6: a floor and a box floating above it, seen from just above the
        // floor. Float-Z keys there resolve only about half a unit at distance 3, so the box is
        // well apart from the floor behind it (surfaces closer than that would z-fight, and the
        // winner would depend on rounding that a correct triangulation of the clipped floor may
        // change).
        Panel p1 = panel(cam({0.03, 0.4, 3}, {0.01, 0.1, -2}, 1e-6, 1e6), floor_and_box({0.2, 1.6, -0.5}, 0.4, 0.3),
                         {tex(Pattern::kChecker, 16, 16, 4)}, 96, 0, 96, 96);
        p1.items[0].mesh = floor_quad(0, 1e5, 1e5, -1e5, {1e5, 1e5});
        p1.items[0].material.texture = 0;
        p1.items[0].material.filter = Filter::kTrilinear;
        p1.lights = {sun({-0.5, -1, -0.35}, {0.85, 0.85, 0.85}, true)};
        p1.shadows.resolution = 256;
        p1.shadows.radius = 3;
        p1.shadows.pcf = false;
        s.panels.push_back(p1);
        add(s);
    }

    // ---- everything at once ----
    {
        Scene s = picture("m5.showcase", "Textured, normal-mapped, specular and shadowed: the whole milestone",
                          "a checkered floor (trilinear), a brick box with a bump map, a shiny textured sphere, a "
                          "shadow-casting light with PCF and a second light without shadows",
                          {9, 5, 8, 6, 7}, 192, 128);
        std::vector<TextureSpec> textures = {tex(Pattern::kChecker, 64, 64, 8), tex(Pattern::kBricks, 64, 64, 8),
                                             tex(Pattern::kBumps, 64, 64, 4), tex(Pattern::kGradient, 32, 32)};
        textures[0].a = {225, 220, 205};
        textures[0].b = {90, 100, 120};
        textures[1].a = {170, 80, 55};
        textures[1].b = {200, 195, 185};
        textures[3].a = {60, 120, 0};
        textures[3].b = {230, 200, 0};
        MaterialSpec floor_m = plain(kFloor);
        floor_m.texture = 0;
        Item floor = item(floor_quad(0, 2.2, 2.2, -2.2, {2.2, 2.2}), floor_m);  // inside the view volume
        MaterialSpec box_m = plain(kBoxColor, {60, 60, 60}, 16);
        box_m.texture = 1;
        box_m.normal_map = 2;
        Item box = item(box_mesh(), box_m);
        box.position = {0.6, 0.6, -0.4};
        box.size = {0.6, 0.6, 0.6};
        box.angle = 0.5;
        MaterialSpec ball_m = plain(kBlue, {220, 220, 220}, 48);
        ball_m.texture = 3;
        Item ball = item(uv_sphere(32), ball_m);
        ball.position = {-1.0, 0.55, 0.5};
        // Squashed: its normals need milestone 4's normal matrix (the model matrix tilts them).
        ball.size = {0.7, 0.55, 0.5};
        Panel pn = panel(cam({0.4, 2.6, 5}, {0.01, 0.3, 0.02}, 0.5, 50), {floor, box, ball}, textures, 0, 0, 192, 128);
        pn.lights = {sun({-0.6, -1, -0.45}, {0.75, 0.75, 0.7}, true), sun({0.7, -0.4, -0.2}, {0.2, 0.22, 0.3})};
        pn.shadows.resolution = 1024;
        pn.shadows.center = {0, 0.5, 0};
        pn.shadows.radius = 3.6;
        s.panels.push_back(pn);
        s.demo = true;
        add(s);
    }
    return all;
}

// ---- scene variants (grading): see "Scene variants (grading)" in checkpoints/README.md ----

using Rng = cp::VariantRng;

Scene vary(const Scene& pub, Rng& rng) {
    Scene s = pub;
    if (s.panels.empty()) return s;  // numbers: their case generators read variant_seed()
    // The camera moved a little (the same move for every panel, so panels that must agree still
    // do), and the lights turned a little: the same ideas on other numbers.
    if (s.id != kFillScene) {
        const Vec3 d{rng.uniform(-10, 10) / 100.0, rng.uniform(-10, 10) / 100.0, rng.uniform(-10, 10) / 100.0};
        for (Panel& p : s.panels) p.camera.eye = p.camera.eye + d;
        // (m5.light_behind's light stays exactly vertical: the box's sides stay edge-on to it.)
        const double turn = rng.uniform(-8, 8) / 100.0;
        for (Panel& p : s.panels) {
            for (LightSpec& l : p.lights) {
                if (s.id != "m5.light_behind") l.direction.x += turn;
            }
        }
    }
    // The ready-made triangles moved by up to two pixels, the same move for the k-th vertex.
    for (Panel& p : s.panels) {
        if (p.screen_tris.empty()) continue;
        std::array<Vec3, 3> move;
        for (Vec3& m : move) m = {rng.uniform(-200, 200) / 100.0, rng.uniform(-200, 200) / 100.0, 0};
        for (ScreenTri& t : p.screen_tris) {
            for (int k = 0; k < 3; ++k) t.screen[std::size_t(k)] = t.screen[std::size_t(k)] + move[std::size_t(k)];
        }
    }
    // Generated textures with other numbers.
    const std::uint32_t seed = std::uint32_t(rng.uniform(2, 1000));
    for (Panel& p : s.panels) {
        for (TextureSpec& t : p.textures) t.seed += seed;
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

LevelData level_from(const raster::Image& img) {
    LevelData l;
    l.width = img.width();
    l.height = img.height();
    for (int y = 0; y < l.height; ++y) {
        for (int x = 0; x < l.width; ++x) {
            const Color c = img.at(x, y);
            l.texels.push_back({double(c.r), double(c.g), double(c.b)});
        }
    }
    return l;
}

std::uint32_t numbers_seed(const char* id) {
    if (variant_seed() == 0) return 0;
    Rng rng(variant_seed(), id);
    return std::uint32_t(rng.uniform(1, 100000));
}

}  // namespace

std::vector<WrapCase> wrap_cases() {
    std::vector<WrapCase> cases;
    const double is[] = {0, 3, 4, 5, 9, -1, -4, -5, -6, -9, 13, 1e300, -1e300, 9007199254740993.0, -7.0e15, kNaN, kInf, -kInf};
    for (int mode = 0; mode < 3; ++mode) {
        // 7 too: i - n floor(i / n) is exact for i below 2^52 only; at 1e300 it misses 1e300 mod 7 = 1.
        for (int n : {4, 5, 7}) {
            for (double i : is) cases.push_back({i, n, static_cast<Wrap>(mode)});
        }
        cases.push_back({0, 1, static_cast<Wrap>(mode)});
        cases.push_back({-3, 1, static_cast<Wrap>(mode)});
        cases.push_back({1e300, 1, static_cast<Wrap>(mode)});
    }
    if (variant_seed() != 0) {
        Rng rng(variant_seed(), "m5.wrap");
        for (int k = 0; k < 18; ++k) {
            cases.push_back({double(rng.uniform(-100000, 100000)), rng.uniform(1, 17), static_cast<Wrap>(k % 3)});
        }
    }
    return cases;
}

LevelData sample_level(int which) {
    LevelData l;
    if (which == 2) return l;
    l.width = which == 0 ? 4 : 5;
    l.height = which == 0 ? 2 : 3;
    const std::uint32_t seed = numbers_seed("m5.sampling");
    for (int j = 0; j < l.height; ++j) {
        for (int i = 0; i < l.width; ++i) {
            // Not linear in i or j, so swapped weights or a shifted center cannot come out right.
            Vec3 t{double(10 + 60 * i + 3 * j), double(200 - 50 * j - 7 * i * i), double(30 + 17 * i * j + 40 * j)};
            if (seed != 0) {
                t = {double(hash_byte(std::uint32_t(i), std::uint32_t(j), 0, seed)),
                     double(hash_byte(std::uint32_t(i), std::uint32_t(j), 1, seed)),
                     double(hash_byte(std::uint32_t(i), std::uint32_t(j), 2, seed))};
            }
            l.texels.push_back(t);
        }
    }
    return l;
}

std::vector<FetchCase> fetch_cases() {
    const Wrap R = Wrap::kRepeat, C = Wrap::kClampToEdge, M = Wrap::kMirroredRepeat;
    return {{0, 0, 0, R, R},     {0, 3, 1, R, R},      {0, -1, 0, R, R},    {0, 4, -1, R, R},     {0, 4, 1, C, C},
            {0, -2, -1, M, M},   {0, -5, 7, M, R},     {0, 1e300, 3, R, M}, {0, -1e300, -3, C, M}, {1, 7, -4, M, C},
            {1, -6, 5, R, M},    {1, 2, 1, C, R},      {2, 0, 0, R, R},     {0, kNaN, 0, R, R},   {1, 3, -kInf, C, C}};
}

std::vector<SampleCase> sample_cases() {
    const Wrap R = Wrap::kRepeat, C = Wrap::kClampToEdge, M = Wrap::kMirroredRepeat;
    std::vector<SampleCase> cases = {
        {0, {0.125, 0.25}, R, R},        // the center of texel (0, 0)
        {0, {0.625, 0.75}, R, R},        // the center of texel (2, 1)
        {0, {0.375, 0.25}, C, C},        // the center of texel (1, 0)
        {0, {0.3, 0.6}, R, R},           // between centers
        {0, {0.3, 0.6}, C, M},
        {0, {0.0, 0.0}, R, R},           // the corner: repeat blends the four corner texels
        {0, {0.0, 0.0}, C, C},           // clamp: texel (0, 0)
        {0, {0.5, 0.5}, R, R},           // a texel corner inside
        {0, {-0.1, -1.3}, R, R},         // negative
        {0, {-0.1, -1.3}, M, M},
        {0, {1.9, 2.2}, C, C},
        {0, {1.9, 2.2}, M, R},
        {0, {1e7 + 0.25, 0.625}, R, R},  // huge but exact in double
        {0, {1e7 + 0.375, 1e7 + 0.125}, M, M},
        {0, {1e300, 0.3}, R, R},         // wraps exactly
        {0, {kNaN, 0.5}, R, R},          // black
        {0, {kInf, 0.5}, R, R},
        {0, {0.5, -kInf}, C, C},
        {0, {1e308, 0.5}, R, R},         // u * w overflows: black
        {1, {0.5, 0.5}, R, R},           // a 5 x 3 level: the center of texel (2, 1)
        {1, {0.13, 0.91}, R, R},
        {1, {-0.77, 0.2}, M, C},
        {1, {0.95, 0.05}, C, R},
        // Huge on a level 5 wide and 3 high: an index cast to a 64-bit integer overflows (undefined;
        // x86 gives -2^63), which lands on the right texel of a power-of-two level by luck only.
        {1, {1e300, 0.5}, R, R},
        {1, {0.3, -1e300}, C, M},
        {2, {0.5, 0.5}, R, R},           // no texels: black
    };
    if (variant_seed() != 0) {
        Rng rng(variant_seed(), "m5.sampling.uv");
        for (int k = 0; k < 8; ++k) {
            cases.push_back({k % 2, {rng.uniform(-3000, 3000) / 1024.0, rng.uniform(-3000, 3000) / 1024.0},
                             static_cast<Wrap>(rng.uniform(0, 2)), static_cast<Wrap>(rng.uniform(0, 2))});
        }
    }
    return cases;
}

std::vector<LevelData> mip_bases() {
    const std::uint32_t seed = numbers_seed("m5.mipmaps");
    auto noise = [seed](int w, int h, std::uint32_t s) {
        TextureSpec t;
        t.pattern = Pattern::kNoise;
        t.width = w;
        t.height = h;
        t.seed = s + seed;
        return level_from(texture_image(t));
    };
    LevelData one;
    one.width = one.height = 1;
    one.texels = {{77, 155, 233}};
    return {noise(8, 8, 11), one, noise(3, 5, 12), noise(7, 1, 13), noise(5, 2, 14)};
}

std::vector<LodCase> lod_cases() {
    std::vector<LodCase> cases = {
        // Screen-aligned, w = 1: du/dx = dv/dy = 1/100 exactly; 256 texels: rho = 2.56.
        {{Vec3{0, 0, 0}, Vec3{100, 0, 0}, Vec3{0, 100, 0}}, {1, 1, 1}, {Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}}, 30.5, 40.5, 256, 256},
        // The same triangle in perspective.
        {{Vec3{0, 0, 0}, Vec3{100, 0, 0}, Vec3{0, 100, 0}}, {1, 2, 4}, {Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}}, 20.5, 30.5, 256, 256},
        // A turned triangle, a texture 64 wide and 32 high.
        {{Vec3{10.3, 5.1, 0}, Vec3{90.2, 30.7, 0}, Vec3{25.6, 80.4, 0}}, {2, 1.5, 3}, {Vec2{0.1, 0.2}, Vec2{3.1, 0.4}, Vec2{0.5, 2.7}},
         40.5, 38.5, 64, 32},
        // Strong perspective.
        {{Vec3{5.5, 60.2, 0}, Vec3{120.4, 58.7, 0}, Vec3{62.3, 2.2, 0}}, {0.5, 0.7, 20}, {Vec2{0, 4}, Vec2{4, 4}, Vec2{2, 0}},
         60.5, 40.5, 128, 128},
        // Zero area: all zero, lambda -infinity.
        {{Vec3{0, 0, 0}, Vec3{10, 10, 0}, Vec3{20, 20, 0}}, {1, 1, 1}, {Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}}, 5.5, 5.5, 64, 64},
        // B <= 0 where it is asked (a vertex behind the eye): all zero.
        {{Vec3{0, 0, 0}, Vec3{100, 0, 0}, Vec3{0, 100, 0}}, {1, 1, -1}, {Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}}, 5.5, 90.5, 64, 64},
        // Magnified: lambda < 0.
        {{Vec3{0, 0, 0}, Vec3{100, 0, 0}, Vec3{0, 100, 0}}, {1, 1.2, 1.1}, {Vec2{0, 0}, Vec2{0.1, 0}, Vec2{0, 0.1}}, 30.5, 30.5, 64, 64},
        // uv near 1e7: the derivatives are those of the first case.
        {{Vec3{0, 0, 0}, Vec3{100, 0, 0}, Vec3{0, 100, 0}}, {1, 1, 1}, {Vec2{1e7, 1e7}, Vec2{1e7 + 1, 1e7}, Vec2{1e7, 1e7 + 1}}, 30.5,
         40.5, 256, 256},
    };
    if (variant_seed() != 0) {
        Rng rng(variant_seed(), "m5.lod");
        for (int k = 0; k < 4; ++k) {
            LodCase c;
            for (int i = 0; i < 3; ++i) {
                c.screen[std::size_t(i)] = {rng.uniform(0, 12000) / 100.0, rng.uniform(0, 9000) / 100.0, 0};
                c.w[std::size_t(i)] = rng.uniform(50, 2000) / 100.0;
                c.uv[std::size_t(i)] = {rng.uniform(-400, 400) / 100.0, rng.uniform(-400, 400) / 100.0};
            }
            c.x = (c.screen[0].x + c.screen[1].x + c.screen[2].x) / 3;
            c.y = (c.screen[0].y + c.screen[1].y + c.screen[2].y) / 3;
            c.width = 1 << rng.uniform(2, 8);
            c.height = 1 << rng.uniform(2, 8);
            cases.push_back(c);
        }
    }
    return cases;
}

std::vector<LambdaCase> lambda_cases() {
    std::vector<LambdaCase> cases = {
        {1.0 / 64, 0, 0, 1.0 / 64, 64, 64},    // one texel per pixel: lambda 0
        {0.01, 0, 0, 0.01, 256, 256},          // rho 2.56
        {0.02, 0.01, -0.005, 0.03, 128, 64},   // the larger of the two lengths, in texel units
        {0.1, 0, 0, 0.001, 16, 16},            // anisotropic: x decides
        {0, 0.001, 0.25, 0, 32, 8},            // y decides
        {0, 0, 0, 0, 64, 64},                  // rho 0: -infinity
        {1e-3, 0, 0, 0, 1, 1},                 // magnified: negative
        {3, 4, 0, 0, 1, 1},                    // rho 5
    };
    if (variant_seed() != 0) {
        Rng rng(variant_seed(), "m5.lod.lambda");
        for (int k = 0; k < 4; ++k) {
            cases.push_back({rng.uniform(-1000, 1000) / 1e4, rng.uniform(-1000, 1000) / 1e4, rng.uniform(-1000, 1000) / 1e4,
                             rng.uniform(-1000, 1000) / 1e4, 1 << rng.uniform(0, 9), 1 << rng.uniform(0, 9)});
        }
    }
    return cases;
}

std::vector<FilterCase> filter_cases() {
    std::vector<FilterCase> cases;
    const std::pair<Vec2, double> main[] = {
        {{0.3, 0.6}, -1},    {{0.3, 0.6}, 0},     {{0.41, 0.27}, 0.5}, {{0.41, 0.27}, 1.0}, {{0.7, 0.2}, 1.49},
        {{0.7, 0.2}, 1.51},  {{0.15, 0.85}, 2.7}, {{0.55, 0.45}, 3},   {{0.55, 0.45}, 5},   {{0.2, 0.3}, 1e9},
        {{0.2, 0.3}, kInf},  {{0.2, 0.3}, kNaN},  {{0.2, 0.3}, -kInf}, {{-1.3, 2.45}, 1.25}};
    for (int f = 0; f < 4; ++f) {
        for (const auto& [uv, lambda] : main) cases.push_back({0, static_cast<Filter>(f), uv, lambda});
    }
    // A 3 x 5 texture (levels 3x5, 1x2, 1x1), a 1x1 one, and a 7 x 1 one.
    for (Filter f : {Filter::kNearestMip, Filter::kTrilinear}) {
        for (double lambda : {0.7, 1.3, 2.0, 7.0}) cases.push_back({2, f, {0.62, 0.33}, lambda});
        for (double lambda : {-0.5, 0.6, 2.0}) cases.push_back({1, f, {0.25, 0.75}, lambda});
        for (double lambda : {0.4, 1.6, 9.0}) cases.push_back({3, f, {0.81, 0.5}, lambda});
    }
    // The texture's wrap modes hold on every level: clamp to edge in u, mirrored repeat in v,
    // outside [0, 1] and minified.
    for (Filter f : {Filter::kNearestMip, Filter::kTrilinear}) {
        for (double lambda : {0.8, 1.3, 2.2}) cases.push_back({0, f, {-0.3, 1.4}, lambda, Wrap::kClampToEdge, Wrap::kMirroredRepeat});
    }
    if (variant_seed() != 0) {
        Rng rng(variant_seed(), "m5.filters");
        for (int k = 0; k < 8; ++k) {
            cases.push_back({0, static_cast<Filter>(2 + k % 2), {rng.uniform(-2000, 2000) / 1000.0, rng.uniform(-2000, 2000) / 1000.0},
                             rng.uniform(1, 400) / 100.0});
        }
    }
    return cases;
}

std::vector<PhongCase> phong_cases() {
    const Vec3 base{200, 150, 100}, spec{255, 255, 255}, one{1, 1, 1};
    std::vector<PhongCase> cases = {
        {base, spec, 32, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, one},                   // head on: c = 1, H = N
        {base, spec, 32, {0, 0, 1}, {0, 0, 1}, {0, std::sqrt(3.0), 1}, one},     // light 60 degrees off: N.H = cos 30
        {base, spec, 32, {0, 0, 1}, {0, 0, 1}, {0, 0, -1}, one},                  // light behind: nothing
        {base, spec, 8, {0, 0, 1}, {0, 0, 1}, {1, 0, -0.2}, one},                 // behind, but H in front: still nothing
        {base, spec, 16, {0, 0, 3}, {0, 4, 4}, {0, -1, 2}, one},                  // long vectors: normalize all three
        {base, spec, 64, {0.3, 0.1, 1}, {-0.2, 0.5, 1}, {0.6, -0.2, 0.7}, {0.5, 0.8, 1}},  // colored light
        {base, {0, 0, 0}, 32, {0, 0, 1}, {0, 0, 1}, {0, 0.6, 0.8}, one},          // no specular color
        {base, {80, 120, 160}, 4, {0, 1, 0}, {1, 1, 0}, {-1, 0.4, 0}, {0.7, 0.7, 0.7}},
        {base, spec, 32, {0, 0, 1}, {0, 0, 1}, {1, 0, 0}, one},                   // grazing: c = 0
        {base, spec, 32, {0, 0, 0}, {0, 0, 1}, {0, 0, 1}, one},                   // zero normal
        {base, spec, 32, {0, 0, 1}, {0, 0, 0}, {0, 0, 1}, one},                   // zero view vector
        {base, spec, 16, {0, 0, 1}, {0, -0.6, -0.8}, {0, 0.6, 0.8}, one},         // V = -L: H is zero
        {base, spec, 1, {0, 0, 1}, {0.8, 0, 0.6}, {-0.8, 0, 0.6}, one},           // shininess 1
        {base, spec, 32, {0, 0, 1}, {-1, 0, -0.5}, {1, 0, 0.05}, one},            // c > 0 but dot(N, H) < 0: no specular
        {base, spec, 12.5, {0, 0, 1}, {0, 0, 1}, {0, std::sqrt(3.0), 1}, one},   // a shininess that is not whole
    };
    if (variant_seed() != 0) {
        Rng rng(variant_seed(), "m5.blinn_phong");
        auto dir = [&rng] { return Vec3{rng.uniform(-100, 100) / 50.0, rng.uniform(-100, 100) / 50.0, rng.uniform(1, 100) / 50.0}; };
        for (int k = 0; k < 6; ++k) {
            cases.push_back({{double(rng.uniform(0, 255)), double(rng.uniform(0, 255)), double(rng.uniform(0, 255))},
                             {double(rng.uniform(0, 255)), double(rng.uniform(0, 255)), double(rng.uniform(0, 255))},
                             double(rng.uniform(1, 128)), dir(), dir(), dir(), {0.8, 0.7, 0.9}});
        }
    }
    return cases;
}

std::vector<FrameCase> frame_cases() {
    std::vector<FrameCase> cases = {
        {{Vec3{0, 0, 0}, Vec3{2, 0, 0}, Vec3{0, 3, 0}}, {Vec2{0, 0}, Vec2{1, 0}, Vec2{0, 1}}},          // T = (2,0,0), B = (0,3,0)
        {{Vec3{0, 0, 0}, Vec3{2, 0, 0}, Vec3{0, 3, 0}}, {Vec2{0, 1}, Vec2{1, 1}, Vec2{0, 0}}},          // v flipped: B = (0,-3,0)
        {{Vec3{1, 2, 3}, Vec3{3, 2, 2}, Vec3{1.5, 4, 3.5}}, {Vec2{0.1, 0.2}, Vec2{0.9, 0.3}, Vec2{0.6, 1.4}}},  // sheared
        {{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}}, {Vec2{0.3, 0.3}, Vec2{0.3, 0.3}, Vec2{0.3, 0.3}}},  // all equal: none
        {{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}}, {Vec2{0, 0}, Vec2{0.5, 0.5}, Vec2{1, 1}}},     // on one line: none
        {{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}}, {Vec2{0, 0}, Vec2{kNaN, 0}, Vec2{0, 1}}},      // NaN: none
        {{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}}, {Vec2{0, 0}, Vec2{1e-300, 0}, Vec2{0, 1e-300}}},  // r underflows to 0: none
        {{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}}, {Vec2{1e7, 1e7}, Vec2{1e7 + 1, 1e7}, Vec2{1e7, 1e7 + 1}}},
        // r = 1e-8: small, but neither 0 nor infinite, so the frame is valid (T and B 1e4 long)
        {{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}}, {Vec2{0, 0}, Vec2{1e-4, 0}, Vec2{0, 1e-4}}},
    };
    if (variant_seed() != 0) {
        Rng rng(variant_seed(), "m5.normal_maps.frame");
        for (int k = 0; k < 4; ++k) {
            FrameCase c;
            for (int i = 0; i < 3; ++i) {
                c.p[std::size_t(i)] = {rng.uniform(-300, 300) / 100.0, rng.uniform(-300, 300) / 100.0, rng.uniform(-300, 300) / 100.0};
                c.uv[std::size_t(i)] = {rng.uniform(-200, 200) / 100.0, rng.uniform(-200, 200) / 100.0};
            }
            cases.push_back(c);
        }
    }
    return cases;
}

std::vector<PerturbCase> perturb_cases() {
    const Vec3 z{0, 0, 1};
    const double h = 127.5;
    std::vector<PerturbCase> cases = {
        {{2, 0, 0}, {0, 3, 0}, true, z, {h, h, 255}},            // flat texel: n
        {{2, 0, 0}, {0, 3, 0}, true, z, {255, h, h}},            // along T
        {{2, 0, 0}, {0, 3, 0}, true, z, {h, 255, h}},            // along B
        {{2, 0, 0}, {0, -3, 0}, true, z, {h, 255, h}},           // B the other way: B' follows it
        {{2, 0, 0}, {0, 3, 0}, true, z, {200, 60, 220}},         // a typical texel
        {{1, 0, 0.5}, {0, 1, 0.7}, true, z, {180, 90, 230}},     // T and B not in the surface
        {{1, 0, 0}, {0.8, 0.6, 0}, true, z, {90, 200, 210}},     // B not perpendicular to T (sheared uv)
        {{1, 0, 0}, {0.8, 0.6, 0}, true, unit(Vec3{0.3, -0.2, 0.9}), {160, 100, 235}},
        {{}, {}, false, z, {255, 0, 128}},                       // no frame: n
        {{2, 0, 0}, {0, 3, 0}, true, z, {h, h, h}},              // the zero vector: n
        {{0, 0, 3}, {0, 3, 0}, true, z, {200, 60, 220}},         // T along n: T' is zero, n
        {{2, 0, 0}, {0, 3, 0}, true, z, {kNaN, 60, 220}},        // NaN texel: n
        {{2, 0, 0}, {0, 3, 0}, true, z, {0, 0, 0}},              // (-1, -1, -1)
    };
    if (variant_seed() != 0) {
        Rng rng(variant_seed(), "m5.normal_maps.perturb");
        for (int k = 0; k < 4; ++k) {
            auto v = [&rng] { return Vec3{rng.uniform(-100, 100) / 40.0, rng.uniform(-100, 100) / 40.0, rng.uniform(-100, 100) / 40.0}; };
            cases.push_back({v(), v(), true, unit(v() + Vec3{0, 0, 3}),
                             {double(rng.uniform(0, 255)), double(rng.uniform(0, 255)), double(rng.uniform(128, 255))}});
        }
    }
    return cases;
}

std::vector<LightMatrixCase> light_matrix_cases() {
    return {{{0, -1, 0}, {1, 0, 2}, 2},
            {{-1, -2, -0.5}, {0, 0, 0}, 4},
            {{0.05, -0.995, 0.08}, {0, 1, 0}, 3},   // |y| > 0.99 after normalizing: up = (1, 0, 0)
            {{0.1, -0.98, 0.2}, {0, 1, 0}, 3},      // |y| just below 0.99: up = (0, 1, 0)
            {{3, -4, 0}, {0.5, -0.25, 1}, 1.5},     // not of unit length
            {{0, 0, 0}, {0, 0, 0}, 4},              // zero: the zero matrix
            {{kNaN, -1, 0}, {0, 0, 0}, 4}};         // not finite: the zero matrix
}

TinyMap tiny_map() {
    TinyMap m;
    auto key = [](double d) { return std::bit_cast<std::uint32_t>(static_cast<float>(d)); };
    m.keys.assign(16, key(0.5));       // the floor, y = 0: d = (2 - y) / 4
    for (int at : {1 * 4 + 1, 1 * 4 + 2, 2 * 4 + 1}) m.keys[std::size_t(at)] = key(0.25);  // an occluder at y = 1
    m.keys[0 * 4 + 3] = 0xFFFFFFFFu;   // never drawn
    m.keys[3 * 4 + 3] = 0xFFFFFFFFu;
    return m;
}

std::vector<ShadowCase> shadow_cases() {
    const Vec3 up{0, 1, 0};
    const double s5 = std::sqrt(1 - 0.04), s6 = std::sqrt(1 - 1e-4);
    std::vector<ShadowCase> cases = {
        {{1.5, 0, -1.5}, up, 0.02, 0.02, false},      // on the floor, texel (row 0, col 0): lit
        {{0.5, 0, -0.5}, up, 0.02, 0.02, false},      // under the occluder (1, 1): shadowed
        {{1.5, -0.001, -0.5}, up, 0.02, 0.02, false}, // just below the floor's stored depth: the bias keeps it lit
        {{-1.5, -0.1, -1.5}, {s5, 0.2, 0}, 0.02, 0.02, false},   // c = 0.2: the slope term keeps it lit
        {{-1.5, -0.3, -0.5}, {s6, 0.01, 0}, 0.02, 0.02, false},  // c = 0.01: tan capped at 10, shadowed
        {{2.5, 0, 0}, up, 0.02, 0.02, false},         // outside the map: lit
        {{0, 0, 3}, up, 0.02, 0.02, true},            // outside, with PCF: lit
        {{1.5, -2, 1.5}, up, 0.02, 0.02, false},      // a texel never drawn: lit
        {{-0.5, 0, 0.5}, up, 0.02, 0.02, true},       // PCF at (2, 2): 6 of 9 lit
        {{1.5, 0, -1.5}, up, 0.02, 0.02, true},       // PCF at the corner (0, 0): 8 of 9 (outside is lit)
        {{0.5, 1.5, -0.5}, up, 0.02, 0.02, false},    // above the occluder: lit
        {{0.5, 0, 0.5}, up, 0.02, 0.02, true},        // PCF at (1, 2): 5 of 9 lit
        {{-0.5, 0, -0.5}, up, 0, 0, false},           // no bias at all, under the occluder (2, 1): shadowed
        {{1.5, -0.05, 0.5}, up, 0.02, 0.02, false},   // 0.05 below the floor, beyond the bias 0.02: shadowed
        // The occluder is not symmetric: a map read upside down or mirrored (a row from NDC y
        // without to_screen's flip) swaps one of these two.
        {{0.5, 0, 0.5}, up, 0.02, 0.02, false},       // under the occluder (1, 2): shadowed
        {{-0.5, 0, 0.5}, up, 0.02, 0.02, false},      // beside it, (2, 2): lit
        // 0.05 below the floor, so every floor texel shadows the point; outside the map is lit.
        {{1.5, -0.05, -1.5}, up, 0.02, 0.02, true},   // PCF at the corner (0, 0): the 5 outside lit, 5 of 9
        {{0.5, -0.05, -2.5}, up, 0.02, 0.02, true},   // PCF centered at column -1: column 0's 3 texels in the map, 6 of 9
        {{0.5, -0.05, -2.3}, up, 0.02, 0.02, false},  // x = -0.3: column floor(-0.3) = -1, outside: lit (truncating gives 0)
        {{1.5, -2.5, 1.5}, up, 0.02, 0.02, false},    // never drawn, the point beyond the box (d = 1.125): lit
        {{1.5, -0.03, -1.5}, up, 0.02, 0.02, false},  // 0.03 below the floor, beyond the bias 0.02: shadowed
        // Case 3 with the light's direction passed 3 times as long: c is taken from it normalized.
        {{-1.5, -0.1, -1.5}, {s5, 0.2, 0}, 0.02, 0.02, false, 3},
        // On the floor with no bias, texel (3, 0): d = 0.5 exactly (every step of the light's
        // matrix is exact here), the very float the floor stored. A tie is lit: shadowed needs >.
        {{-1.5, 0, -1.5}, up, 0, 0, false},
        // The same tie under a bias: d = 0.5625 and bias / (2r) = 0.25 / 4 = 0.0625, so
        // d - bias / (2r) = 0.5 exactly, and so is d > stored + bias / (2r) (every number is a
        // short binary fraction): lit, whichever side the bias is written on.
        {{-1.5, -0.25, -1.5}, up, 0.25, 0, false},
        // Case 20 with settings of radius 1 beside the map of radius 2: the bias is converted
        // with the map's radius (0.02 / 4 in depth, less than the 0.03 / 4 the point lies below:
        // shadowed); with the settings' it would be twice as large and keep the point lit.
        {{1.5, -0.03, -1.5}, up, 0.02, 0.02, false, 1, 1},
    };
    if (variant_seed() != 0) {
        Rng rng(variant_seed(), "m5.shadow_lookup");
        for (int k = 0; k < 6; ++k) {
            // Texel centers only (the row and column are never a rounding question).
            const double x = rng.uniform(-2, 1) + 0.5, z = rng.uniform(-2, 1) + 0.5;
            cases.push_back({{x, rng.uniform(-40, 150) / 100.0, z}, up, 0.02, 0.02, rng.coin()});
        }
    }
    return cases;
}

std::vector<Group> group_dependencies(Group g) {
    switch (g) {
        case Group::kSampling: return {Group::kWrap};
        case Group::kFilter: return {Group::kWrap, Group::kSampling, Group::kMipmaps};
        default: return {};
    }
}

std::vector<Group> prerequisite_groups(const Scene& s) {
    std::vector<Group> need;
    auto add = [&need](Group g) {
        if (std::find(need.begin(), need.end(), g) == need.end()) need.push_back(g);
        for (Group d : group_dependencies(g)) {
            if (std::find(need.begin(), need.end(), d) == need.end()) need.push_back(d);
        }
    };
    auto material = [&](const MaterialSpec& m) {
        if (m.texture >= 0) {
            add(Group::kFilter);  // sample(), and through it the samplers (and the pyramid)
            if (m.filter == Filter::kNearestMip || m.filter == Filter::kTrilinear) add(Group::kLod);
        }
        if (m.lit) add(Group::kBlinnPhong);
        if (m.lit && m.normal_map >= 0) {
            add(Group::kSampling);  // the normal map is read with sample_bilinear
            add(Group::kTangent);
        }
    };
    for (Group g : s.groups) add(g);
    for (const Panel& p : s.panels) {
        for (const Item& it : p.items) material(it.material);
        for (const ScreenTri& t : p.screen_tris) material(t.material);
        for (const LightSpec& l : p.lights) {
            if (l.casts_shadows && !p.items.empty()) add(Group::kShadow);
        }
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
    return "m5";
}

const std::vector<Scene>& scenes() { return variants().scenes(); }

std::uint64_t variant_seed() { return variants().seed(); }

const Scene& scene(const std::string& id) { return cp::find_scene(scenes(), id); }

void use_variant(std::uint64_t seed) { variants().use(seed); }

}  // namespace m5cp
