// `make bench`, milestone 5: the reference's textured, specular, shadowed frame against a
// baseline measured in the same run, on a sphere of about 2,600 triangles and one of about a
// million standing on a floor, single-threaded, 800 x 800, in CPU time; then what each pass of
// the reference costs. Never a timed test: the numbers are printed, and `bench_m5 --lesson
// FILE` writes them into lesson 5's table.
//
// The baseline has the structure of the best-known tutorial renderer's last lessons (the goal
// is ten times its throughput): a shader object whose virtual vertex() runs for every corner of
// every triangle, at every pixel of a triangle's bounding box the barycentric coordinates
// solved from scratch (the inverse of a 3x3 matrix), and a virtual fragment() that does the
// reference's work with the milestone's public functions: the level of detail from
// uv_derivatives() and sample() with trilinear filtering, Blinn-Phong, and the shadow map looked
// up with the same bias and 3x3 PCF at every pixel it shades, wherever the light arrives or not.
// Its shadow pass is the same rasterizer with a depth-only shader. Both draw the same picture
// (the table says in how many pixels they differ), so the ratio measures the structure alone.
//
// A second table splits the frame: the structure (both renderers drawing a plain color with no
// shadow pass) and the scene's work (the rest of the reference's frame, which any renderer must
// do), and the ceiling the latter sets: the baseline's frame over the reference's work, the
// speedup a reference whose structure cost nothing would reach.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "harness/bench_build.h"
#include "m4/scenes.h"
#include "raster/io.h"
#include "textures_shadows.h"

namespace {

using raster::Vec2;
using raster::Vec3;
using raster::Vec4;

constexpr int kSize = 800;
constexpr int kShadowSize = 1024;

raster::Image checker_image(int n, int cells) {
    raster::Image img(n, n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const bool even = ((x * cells / n) + (y * cells / n)) % 2 == 0;
            img.set(x, y, even ? raster::Color{230, 200, 150} : raster::Color{90, 60, 40});
        }
    return img;
}

// A unit sphere with spherical uv (u around, v from the north pole down) and exact normals.
m4::Mesh sphere(int segments) {
    const m4cp::Mesh s = m4cp::sphere_mesh(segments, true);
    m4::Mesh m;
    m.positions = s.positions;
    m.triangles = s.triangles;
    m.normals = s.normals;
    for (const Vec3& p : m.positions) {
        const double u = std::atan2(-p.z, p.x) / (2 * std::numbers::pi) + 0.5;
        const double v = std::acos(std::clamp(p.y, -1.0, 1.0)) / std::numbers::pi;
        m.uvs.push_back({u * 4, v * 2});
    }
    return m;
}

// The floor lies wholly in front of the eye: the tutorial baseline does not clip, and a vertex
// behind the eye would turn its triangle inside out.
m4::Mesh floor_mesh() {
    m4::Mesh m;
    m.positions = {{-4, -1, 2.5}, {4, -1, 2.5}, {4, -1, -4}, {-4, -1, -4}};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    m.uvs = {{0, 6.5}, {8, 6.5}, {8, 0}, {0, 0}};
    m.normals = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
    return m;
}

struct Scene {
    m4::Mesh ball, ground;
    m5::Texture texture;
    m5::Camera camera;
    m5::Lighting lighting;
    m5::ShadowSettings shadows;
    Vec3 specular{120, 120, 120};
    double shininess = 40;
};

Scene make_scene(int segments) {
    Scene sc;
    sc.ball = sphere(segments);
    sc.ground = floor_mesh();
    sc.texture = m5::make_texture(checker_image(256, 16));
    const Vec3 eye{0.4, 1.2, 3.4};
    sc.camera.eye = eye;
    sc.camera.view = m3::look_at(eye, {0, -0.3, 0}, {0, 1, 0});
    sc.camera.projection = m3::perspective(50, 1, 0.5, 20);
    sc.lighting.lights.push_back({{-0.5, -1, -0.4}, {0.9, 0.9, 0.9}, true});
    sc.shadows.resolution = kShadowSize;
    sc.shadows.center = {0, 0, 0};
    sc.shadows.radius = 4.5;
    return sc;
}

// What the reference draws: which parts are on (the pass costs compare frames without one).
// lit = false draws every object in its plain base color: the frame's structure alone (every
// position transformed, every triangle set up and rasterized, the depth test), none of the
// work the scene asks of a fragment.
struct Parts {
    bool texture = true, specular = true, shadows = true, lit = true;
};

struct Result {
    double seconds = 0;
    m5::Stats stats;
    raster::Image image;
};

Result run_reference(Scene& sc, Parts parts) {
    m5::Frame frame;
    frame.color = raster::Image(kSize, kSize);
    m5::Lighting lighting = sc.lighting;
    for (m5::Light& l : lighting.lights) l.casts_shadows = parts.shadows;
    std::vector<m5::Object> objects(2);
    objects[0].mesh = &sc.ball;
    objects[1].mesh = &sc.ground;
    for (m5::Object& o : objects) {
        o.material.color = {200, 180, 150};
        o.material.texture = parts.texture ? &sc.texture : nullptr;
        o.material.filter = m5::Filter::kTrilinear;
        o.material.specular = parts.specular ? sc.specular : Vec3{};
        o.material.shininess = sc.shininess;
        o.material.lit = parts.lit;
    }
    Result r;
    r.seconds = bench::best_cpu_seconds([&] {
        m4::clear_frame(frame, {0, 0, 0}, true, m4::DepthFormat::kFloatZ);
        r.stats = m5::draw_scene(frame, objects, sc.camera, lighting, sc.shadows);
    });
    r.image = std::move(frame.color);
    return r;
}

// ---- the tutorial baseline ----
struct TutorialShader {
    virtual ~TutorialShader() = default;
    virtual Vec4 vertex(int face, int corner) = 0;  // clip position
    // weights: perspective-corrected; (x, y): the pixel center. true: discard.
    virtual bool fragment(const double weights[3], double x, double y, raster::Color& out) = 0;
};

// The 3x3 solve at every pixel of the bounding box, perspective-corrected weights, a depth
// buffer of doubles; fragment() for the pixels that pass the depth test.
template <class Shader>
long long rasterize(const m4::Mesh& mesh, Shader& shader, int size, std::vector<double>& zbuffer, raster::Image* img) {
    long long shaded = 0;
    for (int face = 0; face < int(mesh.triangles.size()); ++face) {
        Vec4 clip[3];
        double sx[3], sy[3];
        for (int k = 0; k < 3; ++k) {
            clip[k] = shader.vertex(face, k);
            sx[k] = (clip[k].x / clip[k].w + 1) / 2 * size;
            sy[k] = (1 - clip[k].y / clip[k].w) / 2 * size;
        }
        const int x0 = std::max(0, int(std::floor(std::min({sx[0], sx[1], sx[2]}))));
        const int x1 = std::min(size - 1, int(std::ceil(std::max({sx[0], sx[1], sx[2]}))));
        const int y0 = std::max(0, int(std::floor(std::min({sy[0], sy[1], sy[2]}))));
        const int y1 = std::min(size - 1, int(std::ceil(std::max({sy[0], sy[1], sy[2]}))));
        for (int x = x0; x <= x1; ++x) {
            for (int y = y0; y <= y1; ++y) {
                const double m[3][3] = {{sx[0], sx[1], sx[2]}, {sy[0], sy[1], sy[2]}, {1, 1, 1}};
                double cof[3][3];
                for (int i = 0; i < 3; ++i)
                    for (int j = 0; j < 3; ++j) {
                        const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
                        cof[i][j] = m[i1][j1] * m[i2][j2] - m[i1][j2] * m[i2][j1];
                    }
                const double det = m[0][0] * cof[0][0] + m[0][1] * cof[0][1] + m[0][2] * cof[0][2];
                if (std::abs(det) < 1e-9) continue;
                const double p[3] = {x + 0.5, y + 0.5, 1};
                double b[3];
                for (int i = 0; i < 3; ++i) b[i] = (cof[0][i] * p[0] + cof[1][i] * p[1] + cof[2][i] * p[2]) / det;
                if (b[0] < 0 || b[1] < 0 || b[2] < 0) continue;
                double q[3] = {b[0] / clip[0].w, b[1] / clip[1].w, b[2] / clip[2].w};
                const double sum = q[0] + q[1] + q[2];
                for (double& v : q) v /= sum;
                const double z = b[0] * clip[0].z / clip[0].w + b[1] * clip[1].z / clip[1].w + b[2] * clip[2].z / clip[2].w;
                double& stored = zbuffer[std::size_t(y) * size + x];
                if (z > stored) continue;
                raster::Color c;
                if (shader.fragment(q, x + 0.5, y + 0.5, c)) continue;
                stored = z;
                if (img) img->set(x, y, c);
                ++shaded;
            }
        }
    }
    return shaded;
}

struct DepthShader final : TutorialShader {
    const m4::Mesh* mesh = nullptr;
    m3::Mat4 mvp;
    Vec4 vertex(int face, int corner) override { return mvp * raster::point(mesh->positions[mesh->triangles[face][corner]]); }
    bool fragment(const double*, double, double, raster::Color&) override { return false; }
};

struct PhongShader final : TutorialShader {
    const m4::Mesh* mesh = nullptr;
    Scene* sc = nullptr;
    m3::Mat4 mvp, light_mvp;
    const std::vector<double>* shadow = nullptr;  // the light's depth pass: NDC z per texel
    bool structure_only = false;                  // true: a plain color, no texture, light or shadow
    Vec2 uv[3];
    Vec3 normal[3], world[3];
    std::array<Vec3, 3> screen;
    std::array<double, 3> w;
    Vec4 vertex(int face, int corner) override {
        const int i = mesh->triangles[face][corner];
        uv[corner] = mesh->uvs[i];
        normal[corner] = mesh->normals[i];
        world[corner] = mesh->positions[i];
        const Vec4 clip = mvp * raster::point(world[corner]);
        screen[corner] = m3::to_screen(clip, kSize, kSize);
        w[corner] = clip.w;
        return clip;
    }
    // The lit fraction of the 3x3 texels around p (PCF), with the reference's bias.
    double lit_fraction(Vec3 p, Vec3 n, Vec3 l) const {
        const m5::ShadowSettings& set = sc->shadows;
        const Vec4 s = light_mvp * raster::point(p);
        const int sx = int(std::floor((s.x + 1) / 2 * kShadowSize));
        const int sy = int(std::floor((1 - s.y) / 2 * kShadowSize));
        const double c = raster::dot(n, l);
        const double tan_theta = c > 0 ? std::sqrt(std::max(0.0, 1 - c * c)) / c : 10;
        const double bias = set.constant_bias + set.slope_bias * std::min(tan_theta, 10.0);
        const double depth = s.z - bias / set.radius;  // NDC z spans 2r world units in [-1, 1]
        int lit = 0;
        for (int j = sy - 1; j <= sy + 1; ++j)
            for (int i = sx - 1; i <= sx + 1; ++i)
                lit += i < 0 || j < 0 || i >= kShadowSize || j >= kShadowSize ||
                       !(depth > (*shadow)[std::size_t(j) * kShadowSize + i]);
        return lit / 9.0;
    }
    bool fragment(const double q[3], double x, double y, raster::Color& out) override {
        if (structure_only) {
            out = {200, 180, 150};
            return false;
        }
        const Vec2 t = uv[0] * q[0] + uv[1] * q[1] + uv[2] * q[2];
        m5::Texture& tex = sc->texture;
        const double lambda =
            m5::level_of_detail(m5::uv_derivatives(screen, w, {uv[0], uv[1], uv[2]}, x, y), tex.levels[0].width, tex.levels[0].height);
        const Vec3 base = m5::sample(tex, t, lambda, m5::Filter::kTrilinear, nullptr);
        const Vec3 n = raster::normalize(normal[0] * q[0] + normal[1] * q[1] + normal[2] * q[2]);
        const Vec3 p = world[0] * q[0] + world[1] * q[1] + world[2] * q[2];
        const m5::Light& light = sc->lighting.lights[0];
        const Vec3 l = raster::normalize(-light.direction);
        const Vec3 v = raster::normalize(sc->camera.eye - p);
        // The shadow map, looked up at every shaded pixel whatever the light does there.
        const double lit = lit_fraction(p, n, l);
        const double diffuse = std::max(0.0, raster::dot(n, l));
        const Vec3 h = raster::normalize(l + v);
        const double spec = diffuse > 0 ? std::pow(std::max(0.0, raster::dot(n, h)), sc->shininess) : 0.0;
        const Vec3 a = sc->lighting.ambient, in = light.intensity;
        const Vec3 c{base.x * a.x + lit * in.x * (base.x * diffuse + sc->specular.x * spec),
                     base.y * a.y + lit * in.y * (base.y * diffuse + sc->specular.y * spec),
                     base.z * a.z + lit * in.z * (base.z * diffuse + sc->specular.z * spec)};
        out = m4::to_color(c);
        return false;
    }
};

// structure_only: no shadow pass, and every fragment a plain color (the baseline's structure).
Result run_tutorial(Scene& sc, bool structure_only = false) {
    const m3::Mat4 light = m5::light_view_projection(sc.lighting.lights[0].direction, sc.shadows);
    const m3::Mat4 vp = sc.camera.projection * sc.camera.view;
    raster::Image img(kSize, kSize);
    std::vector<double> zbuffer(std::size_t(kSize) * kSize), shadow(std::size_t(kShadowSize) * kShadowSize);
    Result r;
    r.seconds = bench::best_cpu_seconds([&] {
        std::fill(shadow.begin(), shadow.end(), std::numeric_limits<double>::infinity());
        for (const m4::Mesh* mesh : {&sc.ball, &sc.ground}) {
            if (structure_only) break;
            DepthShader d;
            d.mesh = mesh;
            d.mvp = light;
            rasterize(*mesh, d, kShadowSize, shadow, nullptr);
        }
        std::fill(zbuffer.begin(), zbuffer.end(), std::numeric_limits<double>::infinity());
        img.fill({0, 0, 0});
        r.stats.shaded = 0;
        for (const m4::Mesh* mesh : {&sc.ball, &sc.ground}) {
            PhongShader s;
            s.mesh = mesh;
            s.sc = &sc;
            s.mvp = vp;
            s.light_mvp = light;
            s.shadow = &shadow;
            s.structure_only = structure_only;
            r.stats.shaded += rasterize(*mesh, s, kSize, zbuffer, &img);
        }
    });
    r.image = std::move(img);
    return r;
}

}  // namespace

int main(int argc, char** argv) {
    std::string lesson;
    if (argc == 3 && std::string(argv[1]) == "--lesson") lesson = argv[2];
    std::printf("Milestone 5, one thread, %dx%d, trilinear texture, Blinn-Phong, a %dx%d shadow map with 3x3 PCF "
                "(reference against the tutorial baseline)\n",
                kSize, kSize, kShadowSize, kShadowSize);
    std::printf("build %s (%s): the ratios depend on it\n\n", RASTER_BUILD_TYPE, RASTER_BUILD_FLAGS);
    const int rounds = std::getenv("BENCH_M5_ROUNDS") ? std::max(1, std::atoi(std::getenv("BENCH_M5_ROUNDS"))) : 5;

    std::ostringstream speed, parts;
    speed << "Build: " << RASTER_BUILD_TYPE << " (`" << RASTER_BUILD_FLAGS << "`), one thread, CPU time, median of " << rounds
          << " alternating rounds.\n\n"
          << "| mesh | triangles | reference ms per frame | tutorial baseline ms | speedup (median) | speedup, slowest to "
             "fastest round | pixels that differ by more than 2 levels |\n"
             "|---|---|---|---|---|---|---|\n";
    parts << "Where the time goes (ms per frame; a part is the frame with it minus the frame without it):\n\n"
          << "| mesh | structure: reference | structure: baseline | structure speedup | the scene's work in the "
             "reference | of it: shadow pass and lookups | texture | specular | ceiling: baseline frame / the "
             "reference's work |\n"
             "|---|---|---|---|---|---|---|---|---|\n";
    bool goals = true;
    for (const auto& [name, segments] : {std::pair{"sphere, ~2,600 triangles, and a floor", 52},
                                         std::pair{"sphere, ~1,000,000 triangles, and a floor", 1002}}) {
        if ((std::getenv("BENCH_M5_SMALL") && segments > 100) || (std::getenv("BENCH_M5_LARGE") && segments < 100)) continue;
        Scene sc = make_scene(segments);
        std::vector<double> tr, tt, speedups, no_shadow, no_texture, no_specular, structure, tutorial_structure;
        Result ref, tutorial;
        for (int r = 0; r < rounds; ++r) {
            ref = run_reference(sc, {});
            tutorial = run_tutorial(sc);
            tr.push_back(ref.seconds);
            tt.push_back(tutorial.seconds);
            speedups.push_back(tutorial.seconds / ref.seconds);
            no_shadow.push_back(run_reference(sc, {true, true, false}).seconds);
            no_texture.push_back(run_reference(sc, {false, true, true}).seconds);
            no_specular.push_back(run_reference(sc, {true, false, true}).seconds);
            structure.push_back(run_reference(sc, {false, false, false, false}).seconds);
            tutorial_structure.push_back(run_tutorial(sc, true).seconds);
        }
        const double t_ref = bench::median(tr), t_tut = bench::median(tt), speedup = bench::median(speedups);
        const double lo = *std::min_element(speedups.begin(), speedups.end());
        const double hi = *std::max_element(speedups.begin(), speedups.end());
        // What a part costs: the frame with it minus the frame without it (medians).
        const double shadow_ms = (t_ref - bench::median(no_shadow)) * 1e3;
        const double texture_ms = (t_ref - bench::median(no_texture)) * 1e3;
        const double specular_ms = (t_ref - bench::median(no_specular)) * 1e3;
        // The structure: the main pass in a plain color, no shadow pass. The rest of the frame is
        // the work the scene asks for (the shadow pass, the texture, the light), which any renderer
        // drawing this picture must do. Were the reference's structure free, it would still spend
        // work_ms, so baseline / work_ms bounds what its structure can gain.
        const double structure_ms = bench::median(structure) * 1e3, tutorial_structure_ms = bench::median(tutorial_structure) * 1e3;
        const double work_ms = t_ref * 1e3 - structure_ms;
        const double ceiling = t_tut * 1e3 / work_ms;
        const double tris = double(sc.ball.triangles.size() + sc.ground.triangles.size());
        std::printf("%-44s %8.0f triangles\n", name, tris);
        std::printf("  reference:         %9.3f ms per frame (%lld fragments, %lld shaded, %lld texture samples, %lld "
                    "shadow lookups)\n",
                    t_ref * 1e3, ref.stats.fragments, ref.stats.shaded, ref.stats.texture_samples, ref.stats.shadow_lookups);
        const long long differing = bench::differing_pixels(ref.image, tutorial.image, 2);
        if (const char* dir = std::getenv("BENCH_M5_PICTURES")) {  // (to look at both pictures)
            raster::write_png(std::string(dir) + "/reference_" + std::to_string(segments) + ".png", ref.image);
            raster::write_png(std::string(dir) + "/tutorial_" + std::to_string(segments) + ".png", tutorial.image);
        }
        std::printf("  tutorial baseline: %9.3f ms per frame (%lld shaded; its picture differs from the reference's in %lld "
                    "pixels by more than 2 levels)\n",
                    t_tut * 1e3, tutorial.stats.shaded, differing);
        std::printf("  speedup %.1fx (rounds %.1fx to %.1fx; goal: at least 10x): %s\n", speedup, lo, hi,
                    speedup >= 10 ? "met" : "NOT met");
        std::printf("  the structure alone (main pass in a plain color, no shadow pass): reference %.3f ms, baseline %.3f ms "
                    "(%.1fx)\n",
                    structure_ms, tutorial_structure_ms, tutorial_structure_ms / structure_ms);
        std::printf("  the scene's work in the reference (frame minus structure): %.3f ms, of it shadow pass and lookups %.3f "
                    "ms, texture %.3f ms, specular %.3f ms\n",
                    work_ms, shadow_ms, texture_ms, specular_ms);
        std::printf("  ceiling: even with a structure that cost nothing, the reference would be at most %.1fx the baseline\n\n",
                    ceiling);
        goals &= speedup >= 10;
        char row[400];
        std::snprintf(row, sizeof row, "| %s | %.0f | %.3f | %.3f | %.1fx | %.1fx to %.1fx | %lld |\n", name, tris, t_ref * 1e3,
                      t_tut * 1e3, speedup, lo, hi, differing);
        speed << row;
        std::snprintf(row, sizeof row, "| %s | %.3f | %.3f | %.1fx | %.3f | %.3f | %.3f | %.3f | %.1fx |\n", name, structure_ms,
                      tutorial_structure_ms, tutorial_structure_ms / structure_ms, work_ms, shadow_ms, texture_ms, specular_ms,
                      ceiling);
        parts << row;
    }
    const std::string table = speed.str() + "\n" + parts.str();
    std::printf("%s\n", goals ? "The speed goal (10x the tutorial baseline) is met on both meshes."
                              : "The speed goal (10x the tutorial baseline) is NOT met on every mesh.");
    if (lesson.empty()) return 0;

    std::ifstream in(lesson);
    std::stringstream ss;
    ss << in.rdbuf();
    std::string text = ss.str();
    const std::string name = std::string("m5-bench-") + RASTER_BUILD_TYPE;
    const std::string begin = "<!-- " + name, end = "<!-- /" + name + " -->";
    const auto b = text.find(begin), e = text.find(end);
    if (!in || b == std::string::npos || e == std::string::npos || e < b) {
        std::cerr << lesson << ": no " << name << " markers; the table was not written\n";
        return 1;
    }
    const auto body = text.find('\n', b) + 1;
    text.replace(body, e - body, table);
    std::ofstream(lesson) << text;
    std::printf("wrote the table into %s\n", lesson.c_str());
    return 0;
}
