#include "scene.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <tuple>

namespace viewer {

using raster::Color;
using raster::Image;
using raster::Vec2;
using raster::Vec3;

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// Area-weighted vertex normals: per position the sum of cross(b - a, c - a) of its triangles,
// normalized (zero where the sum is zero or not finite), as milestone 4's vertex_normals.
std::vector<Vec3> area_weighted_normals(const raster::Mesh& mesh) {
    const std::size_t n = mesh.positions.size();
    std::vector<Vec3> sum(n);
    for (const auto& t : mesh.triangles) {
        if (t[0] < 0 || t[1] < 0 || t[2] < 0 || static_cast<std::size_t>(t[0]) >= n ||
            static_cast<std::size_t>(t[1]) >= n || static_cast<std::size_t>(t[2]) >= n)
            continue;
        const Vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
        const Vec3 face = raster::cross(b - a, c - a);
        for (const int i : t) sum[static_cast<std::size_t>(i)] = sum[static_cast<std::size_t>(i)] + face;
    }
    for (Vec3& s : sum) {
        const double len = raster::length(s);
        s = (len > 0 && std::isfinite(len)) ? s / len : Vec3{};
    }
    return sum;
}

// The angle around the y axis as a fraction of a turn in [0, 1): 0 along +x, a quarter along -z
// (the direction milestone 3's rotate_y turns +x to, and make_torus's rings go).
double turn_around_y(Vec3 p) {
    const double u = std::atan2(-p.z, p.x) / kTwoPi;
    return u < 0 ? u + 1 : u;
}

// The raw uv of one position in [0, 1] (before the seams are fixed); `pole` when u has no
// meaning there (spherical mapping on the y axis).
struct RawUv {
    Vec2 uv;
    bool pole = false;
};

RawUv raw_uv(Vec3 p, UvMapping mapping, double ring_radius) {
    const double rho = std::hypot(p.x, p.z);
    if (mapping == UvMapping::kTorus) {
        double v = std::atan2(p.y, rho - ring_radius) / kTwoPi;
        if (v < 0) v += 1;
        return {{turn_around_y(p), v}, false};
    }
    const double r = raster::length(p);
    if (!(r > 0)) return {{0, 0.5}, true};
    const double v = std::acos(std::clamp(p.y / r, -1.0, 1.0)) / std::numbers::pi;  // 0 at the top pole
    const bool pole = rho <= 1e-12 * r;
    return {{pole ? 0 : turn_around_y(p), v}, pole};
}

// A triangle's three corner coordinates along one wrapping axis: when they span more than half
// a turn, the small ones go once around (+1), so that the triangle takes the short way.
void unwrap(double& a, double& b, double& c) {
    if (std::max({a, b, c}) - std::min({a, b, c}) <= 0.5) return;
    for (double* x : {&a, &b, &c})
        if (*x < 0.5) *x += 1;
}

std::uint32_t hash(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

// A deterministic offset in [-amplitude, amplitude] for the integers (a, b, salt).
int jitter(int a, int b, int salt, int amplitude) {
    const std::uint32_t h = hash(static_cast<std::uint32_t>(a) * 73856093U ^ static_cast<std::uint32_t>(b) * 19349663U ^
                                 static_cast<std::uint32_t>(salt) * 83492791U);
    return static_cast<int>(h % static_cast<std::uint32_t>(2 * amplitude + 1)) - amplitude;
}

std::uint8_t level(int v) { return static_cast<std::uint8_t>(std::clamp(v, 0, 255)); }

}  // namespace

UvRepeats uv_repeats(UvMapping mapping) {
    // Square texture tiles on the surface, roughly: the torus's ring is about 3.4 times as long
    // as its tube's circle, the sphere's equator twice its meridian.
    return mapping == UvMapping::kTorus ? UvRepeats{12, 4} : UvRepeats{8, 4};
}

TexturedMesh with_uvs(const raster::Mesh& mesh, UvMapping mapping, double ring_radius, UvRepeats repeats) {
    const std::size_t n = mesh.positions.size();
    const std::vector<Vec3> normals = mesh.normals.size() == n ? mesh.normals : area_weighted_normals(mesh);
    std::vector<RawUv> raw(n);
    for (std::size_t i = 0; i < n; ++i) raw[i] = raw_uv(mesh.positions[i], mapping, ring_radius);

    TexturedMesh out;
    out.positions.reserve(n);
    out.normals.reserve(n);
    out.uvs.reserve(n);
    out.triangles.reserve(mesh.triangles.size());
    std::map<std::tuple<int, double, double>, int> made;  // (position, u, v) -> vertex
    const auto vertex = [&](int i, Vec2 uv) {
        const auto key = std::make_tuple(i, uv.x, uv.y);
        const auto found = made.find(key);
        if (found != made.end()) return found->second;
        const int index = static_cast<int>(out.positions.size());
        out.positions.push_back(mesh.positions[static_cast<std::size_t>(i)]);
        out.normals.push_back(normals[static_cast<std::size_t>(i)]);
        out.uvs.push_back(uv);
        made.emplace(key, index);
        return index;
    };
    for (const auto& t : mesh.triangles) {
        if (t[0] < 0 || t[1] < 0 || t[2] < 0 || static_cast<std::size_t>(t[0]) >= n ||
            static_cast<std::size_t>(t[1]) >= n || static_cast<std::size_t>(t[2]) >= n)
            continue;
        RawUv c[3] = {raw[static_cast<std::size_t>(t[0])], raw[static_cast<std::size_t>(t[1])],
                      raw[static_cast<std::size_t>(t[2])]};
        // u: the corners that have one take the short way round; a pole takes their mean.
        double known[3];
        int count = 0;
        for (const RawUv& r : c)
            if (!r.pole) known[count++] = r.uv.x;
        if (count == 3) unwrap(known[0], known[1], known[2]);
        if (count == 2 && std::abs(known[0] - known[1]) > 0.5) (known[0] < 0.5 ? known[0] : known[1]) += 1;
        double mean = 0;
        for (int k = 0; k < count; ++k) mean += known[k];
        mean = count > 0 ? mean / count : 0;
        for (int k = 0, j = 0; k < 3; ++k) c[k].uv.x = c[k].pole ? mean : known[j++];
        if (mapping == UvMapping::kTorus) unwrap(c[0].uv.y, c[1].uv.y, c[2].uv.y);
        std::array<int, 3> tri{};
        for (int k = 0; k < 3; ++k) {
            tri[static_cast<std::size_t>(k)] = vertex(t[static_cast<std::size_t>(k)], {c[k].uv.x * repeats.u, c[k].uv.y * repeats.v});
        }
        out.triangles.push_back(tri);
    }
    return out;
}

Image brick_texture() {
    constexpr int kSide = 128, kCourse = 32, kBrick = 64, kMortar = 4;
    Image img(kSide, kSide);
    for (int y = 0; y < kSide; ++y) {
        const int course = y / kCourse;
        const int shift = (course % 2) * (kBrick / 2);
        for (int x = 0; x < kSide; ++x) {
            const int along = (x + shift) % kSide;
            const int brick = along / kBrick;
            const bool mortar = y % kCourse < kMortar || along % kBrick < kMortar;
            const int grain = jitter(x, y, 7, 6);
            if (mortar) {
                img.set(x, y, Color{level(196 + grain), level(192 + grain), level(180 + grain)});
            } else {
                const int tone = jitter(course, brick, 3, 22);  // each brick its own shade
                img.set(x, y, Color{level(168 + tone + grain), level(72 + tone / 2 + grain), level(50 + tone / 3 + grain)});
            }
        }
    }
    return img;
}

Image checker_texture() {
    constexpr int kSide = 64, kSquare = 32;
    Image img(kSide, kSide);
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
            const bool light = (x / kSquare + y / kSquare) % 2 == 0;
            img.set(x, y, light ? Color{214, 212, 200} : Color{112, 120, 134});
        }
    return img;
}

SceneAssets make_scene_assets(const Model& model) {
    SceneAssets a;
    a.model = with_uvs(model.mesh, model.uv_mapping, model.ring_radius, uv_repeats(model.uv_mapping));
    double lowest = 0;
    for (const Vec3 p : model.mesh.positions) lowest = std::min(lowest, p.y);  // the model's yaw keeps y
    a.floor_y = std::max(lowest, -1.0) - 0.12;
    const double f = kFloorHalfSide, y = a.floor_y;
    // Counter-clockwise seen from above: the normal is +y. One texture per world unit.
    a.floor.positions = {{-f, y, f}, {f, y, f}, {f, y, -f}, {-f, y, -f}};
    a.floor.triangles = {{0, 1, 2}, {0, 2, 3}};
    a.floor.normals.assign(4, Vec3{0, 1, 0});
    for (const Vec3 p : a.floor.positions) a.floor.uvs.push_back({p.x, p.z});
    a.model_texture = brick_texture();
    a.floor_texture = checker_texture();
    a.scene_radius = std::max(1.0, std::sqrt(2 * f * f + y * y));
    return a;
}

SceneSetup scene_setup(Mode mode, const SceneAssets& assets) {
    SceneSetup s;
    switch (mode) {
        case Mode::kTextured: s.model.textured = true; break;
        case Mode::kSpecular:
            s.model.specular = 190;
            s.model.shininess = 48;
            break;
        case Mode::kShadowed: {
            s.model.specular = 120;
            s.model.shininess = 32;
            s.floor = true;
            s.floor_surface.textured = true;
            s.shadows = true;
            // The light's box: a sphere around the middle between floor and the model's top
            // that holds the floor's corners and the unit sphere.
            const double f = kFloorHalfSide;
            const double middle = (assets.floor_y + 1) / 2;
            const double below = middle - assets.floor_y;
            s.shadow_center = {0, middle, 0};
            s.shadow_radius = std::max(std::sqrt(2 * f * f + below * below), std::abs(middle) + 1) * 1.01;
            break;
        }
        default: break;
    }
    return s;
}

}  // namespace viewer
