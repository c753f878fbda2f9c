// Measures, for lesson 5 (`make lesson-tables`; the tests check everything but the times):
// (1) each filter on a receding textured plane against a 16x supersampled bilinear truth, and
// its time per frame, also as a chart (error_vs_time.png beside the lesson); (2) shadow maps of
// 256 to 4096 texels, without and with PCF, against the exact light state of every pixel (a ray
// cast to the light); (3) the Stats counts of one scene as it needs more and more. Every number
// comes from the reference rendering scenes of checkpoints/m5/scenes.h; the truths are the
// judge's (m5/judge.h).
#include "m5/tables.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "harness/checkpoint.h"
#include "harness/scene_builders.h"
#include "m5/judge.h"
#include "m5/render.h"
#include "m5/scenes.h"
#include "raster/plot.h"
#include "raster/timer.h"

namespace m5cp {

namespace {

std::string fixed(double v, int digits) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

constexpr auto camera = &cp::camera_at<Camera>;

// One panel filling a scene of its size, rendered by the reference (timed: best of a few runs).
cp::Artifacts render_panel(Panel p, const std::string& id) {
    p.x0 = p.y0 = 0;
    p.timed = true;
    Scene s;
    s.id = id;
    s.width = p.w;
    s.height = p.h;
    s.panels = {p};
    return reference::render_scene(s);
}

// ---- (1) filters on a receding plane ----

constexpr int kPlaneW = 256, kPlaneH = 160;

const char* filter_name(Filter f) {
    switch (f) {
        case Filter::kNearest: return "nearest";
        case Filter::kBilinear: return "bilinear";
        case Filter::kNearestMip: return "nearest-mip";
        default: return "trilinear";
    }
}

// An unlit floor 62 units deep under a camera 1.6 units above it, a checker of 2 x 2 texel
// squares (32 x 32 texels) repeated 6 times across and 31 times along it, width x height pixels.
Panel receding_plane(Filter f, int width, int height) {
    TextureSpec t;
    t.pattern = Pattern::kFine;
    t.width = t.height = 32;
    t.a = {235, 225, 200};
    t.b = {50, 70, 120};
    Item floor;
    floor.mesh = quad({-6, -1, 2}, {6, -1, 2}, {6, -1, -60}, {-6, -1, -60}, {0, 0}, {6, 31});
    floor.material.texture = 0;
    floor.material.filter = f;
    floor.material.lit = false;
    Panel p;
    p.camera = camera({0.04, 0.6, 4}, {0.01, -0.6, -6}, 0.5, 100);
    p.items = {floor};
    p.textures = {t};
    p.w = width;
    p.h = height;
    return p;
}

struct FilterRow {
    std::string name;
    int samples;  // per pixel
    double error, ms;
};

// The plane drawn bilinearly at k x k times the pixels, each pixel the mean of its k x k.
FilterRow supersampled(int k, const Truth& truth) {
    const cp::Artifacts a = render_panel(receding_plane(Filter::kBilinear, k * kPlaneW, k * kPlaneH), "lesson.filters");
    const raster::Image& big = a.images.at("main");
    const raster::Stopwatch watch;
    raster::Image img(kPlaneW, kPlaneH);
    for (int y = 0; y < kPlaneH; ++y) {
        for (int x = 0; x < kPlaneW; ++x) {
            long r = 0, g = 0, b = 0;
            for (int sy = 0; sy < k; ++sy) {
                for (int sx = 0; sx < k; ++sx) {
                    const Color c = big.at(k * x + sx, k * y + sy);
                    r += c.r;
                    g += c.g;
                    b += c.b;
                }
            }
            const double n = k * k;
            img.set(x, y, {std::uint8_t(std::lround(r / n)), std::uint8_t(std::lround(g / n)), std::uint8_t(std::lround(b / n))});
        }
    }
    const double seconds = a.values.at("panel0.seconds") + watch.seconds();
    const std::string name = std::to_string(k * k) + "x supersampled bilinear";
    return {name, k * k, truth_error(img, receding_plane(Filter::kBilinear, kPlaneW, kPlaneH), truth), 1e3 * seconds};
}

std::vector<FilterRow> measure_filters() {
    const Truth truth = bilinear_truth(receding_plane(Filter::kBilinear, kPlaneW, kPlaneH));
    std::vector<FilterRow> out;
    for (Filter f : {Filter::kNearest, Filter::kBilinear, Filter::kNearestMip, Filter::kTrilinear}) {
        const Panel p = receding_plane(f, kPlaneW, kPlaneH);
        const cp::Artifacts a = render_panel(p, "lesson.filters");
        out.push_back({filter_name(f), 1, truth_error(a.images.at("main"), p, truth), 1e3 * a.values.at("panel0.seconds")});
    }
    out.push_back(supersampled(2, truth));
    out.push_back(supersampled(4, truth));
    return out;
}

// ---- (2) shadow-map resolution and PCF ----

constexpr int kShadowW = 384, kShadowH = 288;
constexpr double kShadowRadius = 4;

Item solid(Mesh mesh, Color color, Vec3 at = {}, double half = 1, double turn = 0) {
    Item it;
    it.mesh = std::move(mesh);
    it.material.color = color;
    it.position = at;
    it.size = {half, half, half};
    it.angle = turn;
    return it;
}

// A box standing on a floor, a post beside it and a small box floating above the floor, a sun
// from the upper right that casts shadows.
Panel box_on_floor(int resolution, bool pcf) {
    Panel p;
    p.camera = camera({0.3, 4.0, 3.6}, {-0.4, 0.01, -0.1}, 0.5, 50);
    Item post = solid(box_mesh(), {120, 190, 110}, {-1.0, 0.9, 0.8});
    post.size = {0.12, 0.9, 0.12};
    p.items = {solid(quad({-2.2, 0, 2.2}, {2.2, 0, 2.2}, {2.2, 0, -2.2}, {-2.2, 0, -2.2}), {200, 200, 190}),
               solid(box_mesh(), {210, 120, 80}, {0.5, 0.5, -0.6}, 0.5, 0.4), post,
               solid(box_mesh(), {90, 160, 210}, {0.5, 1.4, 1.4}, 0.25, 0.7)};
    p.lights = {{{-0.5, -1, -0.35}, {0.85, 0.85, 0.85}, true}};
    p.shadows.resolution = resolution;
    p.shadows.center = {0, 0.5, 0};
    p.shadows.radius = kShadowRadius;
    p.shadows.pcf = pcf;
    p.w = kShadowW;
    p.h = kShadowH;
    return p;
}

// ---- (3) only what a scene needs ----

// A sphere on a receding floor, one sun; `step` adds one need after another.
Panel needs_scene(int step) {
    TextureSpec sphere_tex;
    sphere_tex.pattern = Pattern::kChecker;
    sphere_tex.width = 32;
    sphere_tex.height = 16;
    sphere_tex.cells = 8;
    TextureSpec floor_tex;
    floor_tex.pattern = Pattern::kFine;
    floor_tex.width = floor_tex.height = 64;
    TextureSpec bumps;
    bumps.pattern = Pattern::kBumps;
    bumps.width = bumps.height = 32;
    bumps.cells = 4;
    Panel p;
    p.camera = camera({0.03, 1.6, 5.5}, {0.01, 0.4, -1}, 0.5, 50);
    p.textures = {sphere_tex, floor_tex, bumps};
    Item floor = solid(quad({-3, 0, 3}, {3, 0, 3}, {3, 0, -12}, {-3, 0, -12}, {0, 0}, {4, 10}), {200, 200, 190});
    Item ball = solid(uv_sphere(32), {220, 70, 60}, {0, 1, 0}, 1);
    if (step >= 1) {
        ball.material.specular = {200, 200, 200};
        ball.material.shininess = 32;
    }
    if (step >= 2) {
        ball.material.texture = 0;
        ball.material.filter = Filter::kBilinear;
    }
    if (step >= 3) {
        floor.material.texture = 1;
        floor.material.filter = Filter::kTrilinear;
    }
    if (step >= 4) ball.material.normal_map = 2;
    p.items = {floor, ball};
    p.lights = {{{-0.6, -1, -0.45}, {0.85, 0.85, 0.85}, step >= 5}};
    p.shadows.resolution = 1024;
    p.shadows.center = {0, 0.5, -2};
    p.shadows.radius = 7;
    p.shadows.pcf = step >= 6;
    p.w = 192;
    p.h = 144;
    return p;
}

}  // namespace

std::string filter_table() {
    std::ostringstream t;
    t << "| filter (" << kPlaneW << " x " << kPlaneH
      << " pixels) | mean error vs 16x supersampled bilinear (levels) | time per frame (ms) |\n|---|---|---|\n";
    for (const FilterRow& r : measure_filters()) t << "| " << r.name << " | " << fixed(r.error, 2) << " | " << fixed(r.ms, 3) << " |\n";
    return t.str();
}

std::string shadow_table() {
    std::ostringstream rows;
    long long compared = 0;
    for (int resolution : {256, 512, 1024, 2048, 4096}) {
        for (bool pcf : {false, true}) {
            const Panel p = box_on_floor(resolution, pcf);
            const cp::Artifacts a = render_panel(p, "lesson.shadows");
            const LightState state = wrong_light_state(a.images.at("main"), p);
            const long long wrong = state.wrong(), counted = state.counted;
            compared = counted;
            rows << "| " << resolution << " | " << (pcf ? "3x3" : "off") << " | " << fixed(2 * kShadowRadius / resolution, 4)
                 << " | " << wrong << " | " << fixed(100.0 * double(wrong) / double(std::max(1LL, counted)), 2) << "% | "
                 << fixed(1e3 * a.values.at("panel0.seconds"), 3) << " |\n";
        }
    }
    std::ostringstream t;
    t << "| shadow map (texels per side) | PCF | texel (world units) | pixels in the wrong light state (of " << compared
      << ") | share | time per frame (ms) |\n|---|---|---|---|---|---|\n"
      << rows.str();
    return t.str();
}

std::string needs_table() {
    std::ostringstream t;
    t << "| needs (a sphere on a floor, 192 x 144) | shaded | texture samples | lod computed | mipmap builds | "
         "normal-map samples | tangent frames | specular terms | shadow passes | shadow texels | shadow lookups | "
         "time per frame (ms) |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    const char* what[] = {"colors, diffuse light",
                          "+ specular on the sphere",
                          "+ a texture on the sphere (bilinear, magnified)",
                          "+ a texture on the floor (trilinear, minified)",
                          "+ a normal map on the sphere",
                          "+ the light casts shadows (1024 texels)",
                          "+ 3x3 PCF"};
    for (int step = 0; step < 7; ++step) {
        const cp::Artifacts a = render_panel(needs_scene(step), "lesson.needs");
        t << "| " << what[step];
        for (const char* k : {"shaded", "texture_samples", "lod_computed", "mipmap_builds", "normal_map_samples", "tangent_frames",
                              "specular_terms", "shadow_passes", "shadow_texels", "shadow_lookups"}) {
            t << " | " << static_cast<long long>(a.values.at(std::string("panel0.stats.") + k));
        }
        t << " | " << fixed(1e3 * a.values.at("panel0.seconds"), 3) << " |\n";
    }
    return t.str();
}

raster::Image error_time_chart() {
    raster::PlotSpec chart;
    chart.title = "texture filters: error against run time";
    chart.x_label = "milliseconds per frame (" + std::to_string(kPlaneW) + " x " + std::to_string(kPlaneH) + " pixels), log scale";
    chart.y_label = "mean error vs 16x supersampled bilinear (levels)";
    chart.log_x = true;
    const Color colors[4] = {{210, 60, 50}, {40, 150, 60}, {50, 90, 210}, {120, 60, 160}};
    // Bilinear is one line: 1 sample per pixel, then 4 and 16 (supersampled, the last the truth).
    raster::PlotSeries bilinear{"bilinear, 1, 4 and 16 samples", colors[3], {}, {}};
    int k = 0;
    for (const FilterRow& r : measure_filters()) {
        if (r.name == "bilinear" || r.samples > 1) {
            bilinear.points.push_back({r.ms, r.error});
            bilinear.labels.push_back(std::to_string(r.samples) + "x");
        } else {
            chart.series.push_back({r.name, colors[k++], {{r.ms, r.error}}, {}});
        }
    }
    chart.series.push_back(bilinear);
    return raster::plot(chart);
}

}  // namespace m5cp
