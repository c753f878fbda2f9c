// The parts of the harness that need no test framework (used by the demos and tools too).
#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "harness/checkpoint.h"
#include "raster/timer.h"

namespace fs = std::filesystem;

namespace cp {

std::string env_or(const char* name, const std::string& fallback) {
    const char* v = std::getenv(name);
    return v && *v ? std::string(v) : fallback;
}

double time_best_of(const std::function<void()>& fn) {
    // One run is enough for anything slow; tiny scenes are repeated (up to 5 runs or about
    // 50 ms) and the fastest run is kept, which is the figure least disturbed by the machine.
    double best = 0, total = 0;
    for (int run = 0; run < 5; ++run) {
        raster::Stopwatch sw;
        fn();
        const double t = sw.seconds();
        best = run == 0 ? t : std::min(best, t);
        total += t;
        if (total > 0.05) break;
    }
    return best;
}

std::string expected_png_path(const std::string& milestone, const std::string& id) {
    const fs::path dir = env_or("RASTER_EXPECTED_DIR", RASTER_DEFAULT_EXPECTED_DIR);
    return (dir / milestone / (id + ".png")).string();
}

Artifacts render_guarded(int width, int height,
                         const std::function<void(raster::Image& main, Artifacts& out)>& draw) {
    Artifacts out;
    raster::Image img = guarded_image(width, height);
    try {
        draw(img, out);
    } catch (const raster::StrayWriteLimit&) {
        out.values[kRunawayKey] = 1;  // keep what was drawn: the picture shows where
    }
    for (const auto& [name, extra] : out.images) out.stray_writes += extra.stray_writes();
    out.stray_writes += img.stray_writes();
    out.images["main"] = std::move(img);
    return out;
}

raster::Image guarded_image(int width, int height) {
    raster::Image img(width, height);
    img.limit_stray_writes(kStrayWriteBudget);
    return img;
}

const raster::Image* main_image_for_judging(const Artifacts& art, int width, int height, Judgement& j,
                                            const std::string& stray_topic, const std::string& stray_advice) {
    j.tolerance.lenient = raster::Mask(width, height);
    const auto it = art.images.find("main");
    if (it == art.images.end() || it->second.width() != width || it->second.height() != height) return nullptr;
    if (art.stray_writes > 0) {
        j.findings.push_back({stray_topic, "your code asked to write " + std::to_string(art.stray_writes) +
                                               " pixel(s) outside the image (Image::stray_writes): " + stray_advice});
    }
    return &it->second;
}

}  // namespace cp
