// `make bench`, milestone 4: the reference pipeline (depth test, Gouraud shading) against a
// baseline measured in the same run, on a mesh of about 2,600 triangles and one of about a
// million, single-threaded, 800 x 800. Never a timed test: the numbers are printed, and
// `bench_m4 --lesson FILE` writes them into lesson 4's table.
//
// The baseline is the approach of the best-known tutorial renderer: per triangle, every pixel
// of its bounding box solves for its barycentric coordinates from scratch in floating point
// (a cross product per pixel), then tests, interpolates and writes. The reference steps three
// integer edge functions by constants and rejects hidden fragments before shading.
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

struct Result {
    double seconds = 0;
    long long fragments = 0, writes = 0;
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
    r.seconds = cp::time_best_of([&] {
        m4::clear_frame(frame, {0, 0, 0}, true, needs.depth_format);
        st = m4::draw_mesh(frame, sc.mesh, sc.model, sc.view, sc.proj, sc.lighting, sc.material, needs);
    });
    r.fragments = st.fragments;
    r.writes = st.depth_writes;
    return r;
}

// ---- the baseline ----
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
    r.seconds = cp::time_best_of([&] {
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

// Memory bandwidth: the best of a few copies of a 256 MB buffer (bytes read plus written).
double bandwidth_bytes_per_second() {
    const std::size_t n = std::size_t(256) << 20;
    std::vector<char> a(n, 1), b(n, 2);
    const double t = cp::time_best_of([&] { std::memcpy(b.data(), a.data(), n); });
    if (b[n / 2] != 1) std::puts("(copy failed)");
    return 2.0 * double(n) / t;
}

}  // namespace

int main(int argc, char** argv) {
    std::string lesson;
    if (argc == 3 && std::string(argv[1]) == "--lesson") lesson = argv[2];
    std::printf("Milestone 4, one thread, %dx%d, depth test and Gouraud shading (reference against baseline)\n\n", kSize,
                kSize);
    const double bandwidth = bandwidth_bytes_per_second();
    std::printf("memory bandwidth (memcpy of 256 MB, read + write): %.1f GB/s\n\n", bandwidth / 1e9);

    std::ostringstream table;
    table << "| mesh | triangles | reference ms per frame | baseline ms per frame | speedup | reference Mtriangles/s "
             "| reference Mpixels/s | pixel writes, share of memory bandwidth |\n|---|---|---|---|---|---|---|---|\n";
    bool goals = true;
    for (const auto& [name, segments] : {std::pair{"sphere, ~2,600 triangles", 52}, std::pair{"sphere, ~1,000,000 triangles", 1002}}) {
        if (std::getenv("BENCH_M4_SMALL") && segments > 100) continue;  // (for profiling the small mesh alone)
        const Scene sc = make_scene(segments);
        const Result ref = run_reference(sc), base = run_baseline(sc);
        const double tris = double(sc.mesh.triangles.size());
        const double speedup = base.seconds / ref.seconds;
        // Bytes the reference writes for its pixels: 3 of color and 4 of depth per written fragment.
        const double share = 7.0 * double(ref.writes) / ref.seconds / bandwidth;
        std::printf("%-30s %8.0f triangles\n", name, tris);
        std::printf("  reference: %9.3f ms per frame, %8.1f Mtriangles/s, %8.1f Mpixels/s (%lld covered)\n",
                    ref.seconds * 1e3, tris / ref.seconds / 1e6, double(ref.fragments) / ref.seconds / 1e6, ref.fragments);
        std::printf("  baseline:  %9.3f ms per frame, %8.1f Mtriangles/s, %8.1f Mpixels/s (%lld covered)\n",
                    base.seconds * 1e3, tris / base.seconds / 1e6, double(base.fragments) / base.seconds / 1e6,
                    base.fragments);
        std::printf("  speedup %.1fx (goal: at least 10x): %s\n", speedup, speedup >= 10 ? "met" : "NOT met");
        std::printf("  pixel writes at %.4f of the memory bandwidth (goal: within 10x, i.e. at least 0.1): %s\n\n",
                    share, share >= 0.1 ? "met" : "not met");
        goals &= speedup >= 10;
        char row[256];
        std::snprintf(row, sizeof row, "| %s | %.0f | %.3f | %.3f | %.1fx | %.1f | %.1f | %.4f |\n", name, tris,
                      ref.seconds * 1e3, base.seconds * 1e3, speedup, tris / ref.seconds / 1e6,
                      double(ref.fragments) / ref.seconds / 1e6, share);
        table << row;
    }
    std::printf("%s\n", goals ? "The speed goal is met on both meshes." : "The speed goal is NOT met on every mesh.");
    if (lesson.empty()) return 0;

    std::ifstream in(lesson);
    std::stringstream ss;
    ss << in.rdbuf();
    std::string text = ss.str();
    const std::string begin = "<!-- m4-bench", end = "<!-- /m4-bench -->";
    const auto b = text.find(begin), e = text.find(end);
    if (!in || b == std::string::npos || e == std::string::npos || e < b) {
        std::cerr << lesson << ": no m4-bench markers; the table was not written\n";
        return 1;
    }
    const auto body = text.find('\n', b) + 1;
    text.replace(body, e - body, table.str());
    std::ofstream(lesson) << text;
    std::printf("wrote the table into %s\n", lesson.c_str());
    return 0;
}
