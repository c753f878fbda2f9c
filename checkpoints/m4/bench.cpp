// `make bench`, milestone 4: the reference pipeline (depth test, Gouraud shading) against two
// baselines measured in the same run, on a mesh of about 2,600 triangles and one of about a
// million, single-threaded, 800 x 800, in CPU time. Never a timed test: the numbers are
// printed, and `bench_m4 --lesson FILE` writes them into lesson 4's table.
//
// The tutorial baseline has the structure of the best-known tutorial renderer (the goal is
// ten times its throughput): a virtual vertex shader per corner of every triangle, and at
// every pixel of a triangle's bounding box the barycentric coordinates solved from scratch by
// inverting a 3x3 matrix, then a virtual fragment shader. The lean baseline keeps the
// per-pixel solve (a cross product) but shares and culls as the reference does; it shows
// what the per-pixel idea costs on its own. The reference steps three integer edge functions
// by constants and rejects hidden fragments before shading.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "depth_lighting.h"
#include "harness/bench_build.h"
#include "harness/checkpoint.h"
#include "m4/scenes.h"

namespace {

constexpr int kSize = 800;

struct Scene {
    m4::Mesh mesh;
    m4::Mat4 model, view, proj;
    m4::Lighting lighting;
    m4::Color material{210, 190, 160};
};

Scene make_scene(int segments) {
    const m4cp::Mesh s = m4cp::sphere_mesh(segments, true);
    Scene sc;
    sc.mesh = {s.positions, s.triangles, s.face_colors, {}, {}, s.normals};
    sc.model = m3::rotate({0.3, 1, 0.1}, 0.4);
    sc.view = m3::look_at({0.1, 0.2, 2.6}, {0, 0, 0}, {0, 1, 0});
    sc.proj = m3::perspective(50, 1, 0.5, 20);
    sc.lighting.lights.push_back({m4::Light::Kind::kDirectional, {-0.6, -0.7, -1}, {0.9, 0.9, 0.9}});
    return sc;
}

// How many runs best_cpu_seconds takes the best of (1: main() alternates rounds of one run).
int g_runs = 1;
template <class F>
double best_cpu_seconds(F&& fn) {
    return bench::best_cpu_seconds(fn, g_runs);
}

struct Result {
    double seconds = 0;
    long long fragments = 0, writes = 0, depth_tests = 0;
};

Result run_reference(const Scene& sc) {
    m4::Frame frame;
    frame.color = raster::Image(kSize, kSize);
    m4::Needs needs;
    needs.depth_test = true;
    needs.shading = m4::Shading::kGouraud;
    needs.cull = true;
    m4::Stats st;
    Result r;
    r.seconds = best_cpu_seconds([&] {
        m4::clear_frame(frame, {0, 0, 0}, true, needs.depth_format);
        st = m4::draw_mesh(frame, sc.mesh, sc.model, sc.view, sc.proj, sc.lighting, sc.material, needs);
    });
    r.fragments = st.fragments;
    r.writes = st.depth_writes;
    r.depth_tests = st.depth_tests;
    return r;
}

// ---- the lean baseline ----
// The same per-pixel idea (barycentric coordinates from scratch at every pixel of the bounding
// box, in floating point) with the rest done as the reference does it: every position lit and
// projected once, back faces culled, no virtual calls.
struct BaseVertex {
    float x, y, z;  // pixels and NDC depth
    float r, g, b;  // Gouraud levels
};

Result run_baseline(const Scene& sc) {
    const m4::Mat4 mvp = sc.proj * (sc.view * sc.model);
    const m4::Mat4 nm = m4::normal_matrix(sc.model);
    raster::Image img(kSize, kSize);
    std::vector<float> zbuffer(std::size_t(kSize) * kSize);
    std::vector<BaseVertex> verts(sc.mesh.positions.size());
    Result r;
    r.seconds = best_cpu_seconds([&] {
        std::fill(zbuffer.begin(), zbuffer.end(), std::numeric_limits<float>::infinity());
        img.fill({0, 0, 0});
        r.fragments = r.writes = 0;
        for (std::size_t i = 0; i < verts.size(); ++i) {
            const raster::Vec4 c = mvp * raster::point(sc.mesh.positions[i]);
            const raster::Vec3 n = raster::normalize(m3::transform_direction(nm, sc.mesh.normals[i]));
            const raster::Vec3 lit =
                m4::shade(sc.lighting, sc.material, m3::transform_point(sc.model, sc.mesh.positions[i]), n);
            verts[i] = {float((c.x / c.w + 1) / 2 * kSize), float((1 - c.y / c.w) / 2 * kSize), float(c.z / c.w),
                        float(lit.x), float(lit.y), float(lit.z)};
        }
        for (const auto& t : sc.mesh.triangles) {
            const BaseVertex &a = verts[t[0]], &b = verts[t[1]], &c = verts[t[2]];
            // Back faces (positive area with y down) are skipped, as the reference culls them.
            if ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) >= 0) continue;
            const int x0 = std::max(0, int(std::floor(std::min({a.x, b.x, c.x}))));
            const int x1 = std::min(kSize - 1, int(std::ceil(std::max({a.x, b.x, c.x}))));
            const int y0 = std::max(0, int(std::floor(std::min({a.y, b.y, c.y}))));
            const int y1 = std::min(kSize - 1, int(std::ceil(std::max({a.y, b.y, c.y}))));
            for (int y = y0; y <= y1; ++y) {
                for (int x = x0; x <= x1; ++x) {
                    // Barycentric coordinates of the pixel center from a cross product.
                    const float px = x + 0.5f, py = y + 0.5f;
                    const float ux = c.x - a.x, vx = b.x - a.x, wx = a.x - px;
                    const float uy = c.y - a.y, vy = b.y - a.y, wy = a.y - py;
                    const float cx = vx * wy - wx * vy, cy = wx * uy - ux * wy, cz = ux * vy - vx * uy;
                    if (std::abs(cz) < 1e-6f) continue;
                    const float l1 = cx / cz, l2 = cy / cz, l0 = 1 - l1 - l2;
                    if (l0 < 0 || l1 < 0 || l2 < 0) continue;
                    ++r.fragments;
                    const float z = l0 * a.z + l1 * c.z + l2 * b.z;
                    float& stored = zbuffer[std::size_t(y) * kSize + x];
                    if (!(z < stored)) continue;
                    stored = z;
                    auto ch = [](float v) { return std::uint8_t(std::clamp(v, 0.0f, 255.0f) + 0.5f); };
                    img.set(x, y, {ch(l0 * a.r + l1 * c.r + l2 * b.r), ch(l0 * a.g + l1 * c.g + l2 * b.g),
                                   ch(l0 * a.b + l1 * c.b + l2 * b.b)});
                    ++r.writes;
                }
            }
        }
    });
    return r;
}

// ---- the tutorial baseline ----
// The structure of the best-known tutorial renderer's final lessons, written afresh: a shader
// object whose virtual vertex() runs for every corner of every triangle (nothing is shared
// between triangles that share a vertex, and nothing is culled: the depth buffer hides the
// back faces), and for every pixel of a triangle's bounding box a 3x3 linear system solved
// for the barycentric coordinates (the inverse of the matrix of the three screen vertices in
// homogeneous form), the weights corrected for perspective and the depth computed, then the
// inside and depth tests and a virtual fragment() for the color.
struct TutorialShader {
    virtual ~TutorialShader() = default;
    virtual raster::Vec4 vertex(int face, int corner) = 0;               // clip position
    virtual bool fragment(const double weights[3], raster::Color& out) = 0;  // true: discard
};

struct GouraudShader final : TutorialShader {
    const Scene* sc = nullptr;
    m4::Mat4 mvp, nm;
    raster::Vec3 levels[3];  // the current triangle's corners, lit
    raster::Vec4 vertex(int face, int corner) override {
        const int i = sc->mesh.triangles[face][corner];
        const raster::Vec3 n = raster::normalize(m3::transform_direction(nm, sc->mesh.normals[i]));
        levels[corner] = m4::shade(sc->lighting, sc->material, m3::transform_point(sc->model, sc->mesh.positions[i]), n);
        return mvp * raster::point(sc->mesh.positions[i]);
    }
    bool fragment(const double weights[3], raster::Color& out) override {
        auto ch = [](double v) { return std::uint8_t(std::clamp(v, 0.0, 255.0) + 0.5); };
        const raster::Vec3 c = levels[0] * weights[0] + levels[1] * weights[1] + levels[2] * weights[2];
        out = {ch(c.x), ch(c.y), ch(c.z)};
        return false;
    }
};

Result run_tutorial(const Scene& sc) {
    GouraudShader shader;
    shader.sc = &sc;
    shader.mvp = sc.proj * (sc.view * sc.model);
    shader.nm = m4::normal_matrix(sc.model);
    raster::Image img(kSize, kSize);
    std::vector<double> zbuffer(std::size_t(kSize) * kSize);
    Result r;
    r.seconds = best_cpu_seconds([&] {
        std::fill(zbuffer.begin(), zbuffer.end(), std::numeric_limits<double>::infinity());
        img.fill({0, 0, 0});
        r.fragments = r.writes = 0;
        for (int face = 0; face < int(sc.mesh.triangles.size()); ++face) {
            raster::Vec4 clip[3];
            double sx[3], sy[3];
            for (int k = 0; k < 3; ++k) {
                clip[k] = shader.vertex(face, k);
                sx[k] = (clip[k].x / clip[k].w + 1) / 2 * kSize;
                sy[k] = (1 - clip[k].y / clip[k].w) / 2 * kSize;
            }
            const int x0 = std::max(0, int(std::floor(std::min({sx[0], sx[1], sx[2]}))));
            const int x1 = std::min(kSize - 1, int(std::ceil(std::max({sx[0], sx[1], sx[2]}))));
            const int y0 = std::max(0, int(std::floor(std::min({sy[0], sy[1], sy[2]}))));
            const int y1 = std::min(kSize - 1, int(std::ceil(std::max({sy[0], sy[1], sy[2]}))));
            for (int x = x0; x <= x1; ++x) {
                for (int y = y0; y <= y1; ++y) {
                    // Solve M b = (px, py, 1) for b, M's columns being the vertices in
                    // homogeneous form (x, y, 1): b = inverse(M) * (px, py, 1), the inverse
                    // from the adjugate (the transposed cofactors) divided by the determinant.
                    const double px = x + 0.5, py = y + 0.5;
                    const double m[3][3] = {{sx[0], sx[1], sx[2]}, {sy[0], sy[1], sy[2]}, {1, 1, 1}};
                    double cof[3][3];
                    for (int i = 0; i < 3; ++i) {
                        for (int j = 0; j < 3; ++j) {
                            const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
                            cof[i][j] = m[i1][j1] * m[i2][j2] - m[i1][j2] * m[i2][j1];
                        }
                    }
                    const double det = m[0][0] * cof[0][0] + m[0][1] * cof[0][1] + m[0][2] * cof[0][2];
                    if (std::abs(det) < 1e-9) continue;
                    double inv[3][3];
                    for (int i = 0; i < 3; ++i) {
                        for (int j = 0; j < 3; ++j) inv[i][j] = cof[j][i] / det;
                    }
                    const double p[3] = {px, py, 1};
                    double b[3];
                    for (int i = 0; i < 3; ++i) b[i] = inv[i][0] * p[0] + inv[i][1] * p[1] + inv[i][2] * p[2];
                    double q[3] = {b[0] / clip[0].w, b[1] / clip[1].w, b[2] / clip[2].w};
                    const double sum = q[0] + q[1] + q[2];
                    for (double& v : q) v /= sum;
                    const double z = q[0] * clip[0].z / clip[0].w + q[1] * clip[1].z / clip[1].w + q[2] * clip[2].z / clip[2].w;
                    double& stored = zbuffer[std::size_t(y) * kSize + x];
                    if (b[0] < 0 || b[1] < 0 || b[2] < 0) continue;
                    ++r.fragments;
                    if (z > stored) continue;
                    raster::Color c;
                    if (shader.fragment(q, c)) continue;
                    stored = z;
                    img.set(x, y, c);
                    ++r.writes;
                }
            }
        }
    });
    return r;
}

// Memory bandwidth: the best of a few copies of a 256 MB buffer (bytes read plus written).
double bandwidth_bytes_per_second() {
    const std::size_t n = std::size_t(256) << 20;
    std::vector<char> a(n, 1), b(n, 2);
    g_runs = 5;
    const double t = best_cpu_seconds([&] { std::memcpy(b.data(), a.data(), n); });
    g_runs = 1;
    if (b[n / 2] != 1) std::puts("(copy failed)");
    return 2.0 * double(n) / t;
}

}  // namespace

int main(int argc, char** argv) {
    std::string lesson;
    if (argc == 3 && std::string(argv[1]) == "--lesson") lesson = argv[2];
    std::printf("Milestone 4, one thread, %dx%d, depth test and Gouraud shading (reference against baseline)\n", kSize,
                kSize);
    std::printf("build %s (%s): the ratios depend on it\n\n", RASTER_BUILD_TYPE, RASTER_BUILD_FLAGS);
    const int rounds = std::getenv("BENCH_M4_ROUNDS") ? std::max(1, std::atoi(std::getenv("BENCH_M4_ROUNDS"))) : 5;
    const double bandwidth = std::getenv("BENCH_M4_SMALL") || std::getenv("BENCH_M4_LARGE") ? 1e10 : bandwidth_bytes_per_second();
    std::printf("memory bandwidth (memcpy of 256 MB, read + write): %.1f GB/s\n\n", bandwidth / 1e9);

    std::ostringstream table;
    table << "Build: " << RASTER_BUILD_TYPE << " (`" << RASTER_BUILD_FLAGS << "`), one thread, CPU time, median of " << rounds
          << " alternating rounds.\n\n"
          << "| mesh | triangles | reference ms per frame | tutorial baseline ms | speedup (median) | speedup, slowest to "
             "fastest round | lean baseline ms | speedup over lean | reference Mtriangles/s | reference Mpixels/s | pixel memory "
             "traffic, share of memory bandwidth |\n"
             "|---|---|---|---|---|---|---|---|---|---|---|\n";
    bool goals = true;
    for (const auto& [name, segments] : {std::pair{"sphere, ~2,600 triangles", 52}, std::pair{"sphere, ~1,000,000 triangles", 1002}}) {
        // (BENCH_M4_SMALL or BENCH_M4_LARGE: one mesh alone; BENCH_M4_REFERENCE_ONLY: no baselines)
        if ((std::getenv("BENCH_M4_SMALL") && segments > 100) || (std::getenv("BENCH_M4_LARGE") && segments < 100)) continue;
        const Scene sc = make_scene(segments);
        if (std::getenv("BENCH_M4_REFERENCE_ONLY")) {  // (for profiling the reference alone)
            g_runs = 5;
            const Result ref = run_reference(sc);
            g_runs = 1;
            std::printf("%-30s reference %.3f ms per frame\n", name, ref.seconds * 1e3);
            continue;
        }
        // Alternating rounds: reference, tutorial, lean; then medians and the spread of the
        // per-round speedups, so a reader can tell 9.3x from 10.3x as noise or not.
        Result ref, tutorial, lean;
        std::vector<double> tr, tt, tl, speedups, over_leans;
        for (int r = 0; r < rounds; ++r) {
            ref = run_reference(sc);
            tutorial = run_tutorial(sc);
            lean = run_baseline(sc);
            tr.push_back(ref.seconds);
            tt.push_back(tutorial.seconds);
            tl.push_back(lean.seconds);
            speedups.push_back(tutorial.seconds / ref.seconds);
            over_leans.push_back(lean.seconds / ref.seconds);
        }
        ref.seconds = bench::median(tr);
        tutorial.seconds = bench::median(tt);
        lean.seconds = bench::median(tl);
        const double tris = double(sc.mesh.triangles.size());
        const double speedup = bench::median(speedups), over_lean = bench::median(over_leans);
        const double lo = *std::min_element(speedups.begin(), speedups.end());
        const double hi = *std::max_element(speedups.begin(), speedups.end());
        // The pixel memory a frame moves: clearing every pixel (3 bytes of color, 4 of depth),
        // reading 4 bytes of depth per test, writing 7 bytes per written fragment. The goal:
        // at least a tenth of the rate at which memcpy moves memory.
        const double pixel_bytes = 7.0 * kSize * kSize + 4.0 * double(ref.depth_tests) + 7.0 * double(ref.writes);
        const double share = pixel_bytes / ref.seconds / bandwidth;
        auto line = [tris](const char* who, const Result& r) {
            std::printf("  %-18s %9.3f ms per frame, %8.1f Mtriangles/s, %8.1f Mpixels/s (%lld covered)\n", who,
                        r.seconds * 1e3, tris / r.seconds / 1e6, double(r.fragments) / r.seconds / 1e6, r.fragments);
        };
        std::printf("%-30s %8.0f triangles\n", name, tris);
        line("reference:", ref);
        line("tutorial baseline:", tutorial);
        line("lean baseline:", lean);
        std::printf("  speedup over the tutorial baseline %.1fx (rounds %.1fx to %.1fx; goal: at least 10x): %s; over the lean "
                    "baseline %.1fx\n",
                    speedup, lo, hi, speedup >= 10 ? "met" : "NOT met", over_lean);
        std::printf("  pixel memory traffic at %.3f of the memory bandwidth (goal: within 10x, i.e. at least 0.1): %s\n\n",
                    share, share >= 0.1 ? "met" : "not met");
        goals &= speedup >= 10;
        char row[400];
        std::snprintf(row, sizeof row, "| %s | %.0f | %.3f | %.3f | %.1fx | %.1fx to %.1fx | %.3f | %.1fx | %.1f | %.1f | %.3f |\n",
                      name, tris, ref.seconds * 1e3, tutorial.seconds * 1e3, speedup, lo, hi, lean.seconds * 1e3, over_lean,
                      tris / ref.seconds / 1e6, double(ref.fragments) / ref.seconds / 1e6, share);
        table << row;
    }
    std::printf("%s\n", goals ? "The speed goal (over the tutorial baseline) is met on both meshes." : "The speed goal (over the tutorial baseline) is NOT met on every mesh.");
    if (lesson.empty()) return 0;

    std::ifstream in(lesson);
    std::stringstream ss;
    ss << in.rdbuf();
    std::string text = ss.str();
    // Each build writes its own table (markers m4-bench-<build type>): the default build and a
    // Release build side by side, because the verdict differs between them.
    const std::string name = std::string("m4-bench-") + RASTER_BUILD_TYPE;
    const std::string begin = "<!-- " + name, end = "<!-- /" + name + " -->";
    const auto b = text.find(begin), e = text.find(end);
    if (!in || b == std::string::npos || e == std::string::npos || e < b) {
        std::cerr << lesson << ": no " << name << " markers; the table was not written\n";
        return 1;
    }
    const auto body = text.find('\n', b) + 1;
    text.replace(body, e - body, table.str());
    std::ofstream(lesson) << text;
    std::printf("wrote the table into %s\n", lesson.c_str());
    return 0;
}
