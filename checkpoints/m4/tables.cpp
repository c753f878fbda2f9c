// Measures, for lesson 4 (`make lesson-tables`; the tests check everything but the times):
// (1) the error of flat, Gouraud and per-pixel shading against a perfect sphere, for spheres of
// several tessellations, against run time, also as a chart (error_vs_time.png beside the
// lesson); (2) what each stage costs on one scene; (3) z-fighting in the four depth formats.
// Every number comes from the reference rendering the scenes of checkpoints/m4/scenes.cpp.
#include "m4/tables.h"

#include <cstdio>
#include <sstream>

#include "harness/checkpoint.h"
#include "m4/judge.h"
#include "m4/render.h"
#include "m4/scenes.h"
#include "raster/plot.h"

namespace m4cp {

namespace {

constexpr int kSize = 160;  // pixels per sphere in the lesson's measurements

std::string fixed(double v, int digits) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

const char* name_of(Shade s) {
    switch (s) {
        case Shade::kFlat: return "flat";
        case Shade::kGouraud: return "Gouraud";
        case Shade::kPerPixel: return "per-pixel";
        default: return "unlit";
    }
}

struct Measured {
    Shade shading;
    std::size_t triangles;
    double error, ms;
};

std::vector<Measured> measure_shading() {
    std::vector<Measured> out;
    for (Shade mode : {Shade::kFlat, Shade::kGouraud, Shade::kPerPixel}) {
        for (int segments : kChartSegments) {
            Scene s;
            s.id = "lesson.shading";
            s.width = s.height = kSize;
            s.panels = {shading_panel(mode, segments, 0, 0, kSize)};
            const cp::Artifacts a = reference::render_scene(s);
            const Panel& p = s.panels[0];
            out.push_back({mode, p.items[0].mesh.triangles.size(), panel_error(a.images.at("main"), p, analytic_sphere(p)),
                           1e3 * a.values.at("panel0.seconds")});
        }
    }
    return out;
}

}  // namespace

std::string error_time_tables() {
    std::ostringstream t;
    // (1) shading error against time
    t << "| shading | triangles | mean error vs the perfect sphere (levels) | time per sphere (ms) |\n|---|---|---|---|\n";
    for (const Measured& m : measure_shading()) {
        t << "| " << name_of(m.shading) << " | " << m.triangles << " | " << fixed(m.error, 2) << " | " << fixed(m.ms, 3) << " |\n";
    }

    // (2) what each stage costs: one sphere, more and more needs
    t << "\n| needs (one sphere of 2208 triangles, " << kSize << " x " << kSize
      << ") | depth keys allocated | vertex normals | shade() calls | values interpolated | time (ms) |\n|---|---|---|---|---|---|\n";
    struct Step {
        const char* what;
        bool depth;
        Shade shading;
        bool point;
    };
    const Step steps[] = {{"face colors, no depth test", false, Shade::kFaceColor, false},
                          {"face colors, depth test", true, Shade::kFaceColor, false},
                          {"flat lighting, depth test", true, Shade::kFlat, false},
                          {"Gouraud, depth test", true, Shade::kGouraud, false},
                          {"per-pixel, directional light", true, Shade::kPerPixel, false},
                          {"per-pixel, directional and point light", true, Shade::kPerPixel, true}};
    for (const Step& st : steps) {
        Scene s;
        s.id = "lesson.costs";
        s.width = s.height = kSize;
        Panel p = shading_panel(st.shading, 48, 0, 0, kSize);
        p.items[0].mesh.normals.clear();  // computed by the pipeline, where a mode needs them
        p.depth_test = st.depth;
        if (!st.point) p.lights.resize(1);
        s.panels = {p};
        const cp::Artifacts a = reference::render_scene(s);
        auto v = [&](const char* k) { return static_cast<long long>(a.values.at(std::string("panel0.") + k)); };
        t << "| " << st.what << " | " << v("depth_capacity") << " | " << v("stats.vertex_normals") << " | "
          << v("stats.shade_calls") << " | " << v("stats.interpolated") << " | "
          << fixed(1e3 * a.values.at("panel0.seconds"), 3) << " |\n";
    }

    // (3) z-fighting: the checkpoint's scene, per format and per distance
    t << "\n| depth format (near 0.001, far 100000) | far surface showing at distance 5 | 50 | 500 | 5000 | time (ms) "
         "|\n|---|---|---|---|---|---|\n";
    const std::string zfight_id = "m4.zfight_formats";  // a named string: GCC 14 would suspect a
    const Scene& z = scene(zfight_id);                  // reference into a temporary otherwise
    const cp::Artifacts a = reference::render_scene(z);
    const raster::Image& img = a.images.at("main");
    const char* names[4] = {"float z in [0, 1]", "reversed-Z float", "24-bit fixed point", "1/w float"};
    for (std::size_t p = 0; p < z.panels.size() && p < 4; ++p) {
        const Panel& panel = z.panels[p];
        long long band[4] = {};
        for (int y = 0; y < panel.h; ++y) {
            for (int x = 0; x < panel.w; ++x) {
                band[std::min(3, 4 * y / panel.h)] += img.at(panel.x0 + x, panel.y0 + y) == Color{250, 220, 80};
            }
        }
        t << "| " << names[p];
        for (long long b : band) t << " | " << b << " px";
        t << " | " << fixed(1e3 * a.values.at("panel" + std::to_string(p) + ".seconds"), 3) << " |\n";
    }
    return t.str();
}

raster::Image error_time_chart() {
    raster::PlotSpec chart;
    chart.title = "error against run time";
    chart.x_label = "milliseconds per sphere (" + std::to_string(kSize) + " x " + std::to_string(kSize) + " pixels), log scale";
    chart.y_label = "mean error vs the perfect sphere (levels)";
    chart.log_x = true;
    const Color colors[3] = {{210, 60, 50}, {40, 150, 60}, {50, 90, 210}};
    const std::vector<Measured> all = measure_shading();
    int k = 0;
    for (Shade mode : {Shade::kFlat, Shade::kGouraud, Shade::kPerPixel}) {
        raster::PlotSeries s{name_of(mode), colors[k++], {}, {}};
        for (const Measured& m : all) {
            if (m.shading != mode) continue;
            s.points.push_back({m.ms, m.error});
            s.labels.push_back(std::to_string(m.triangles));
        }
        chart.series.push_back(s);
    }
    return raster::plot(chart);
}

}  // namespace m4cp
