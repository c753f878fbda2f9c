#include "app.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <numbers>

#include "raster/plot.h"
#include "raster/timer.h"

namespace viewer {

using raster::Color;
using raster::Image;

namespace {

constexpr Color kBackground{28, 32, 40};
constexpr Color kWireColor{225, 230, 240};
constexpr Color kText{235, 235, 235};
constexpr Color kDim{170, 178, 190};
constexpr Color kYours{120, 230, 120};
constexpr Color kReference{255, 170, 80};
constexpr Color kWarning{255, 225, 60};
constexpr double kSpinPerSecond = 0.6;  // radians

std::string fixed(double v, int decimals) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
    return buffer;
}

// 1234567 -> "1,234,567"
std::string grouped(long long n) {
    std::string digits = std::to_string(n), out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

// ---- text on the frame: stb_easy_font through raster::draw_text, on a darkened band ----

constexpr int kGlyphHeight = 8;  // font units, descenders included

void darken(Image& img, int x0, int y0, int x1, int y1) {
    x0 = std::max(x0, 0);
    y0 = std::max(y0, 0);
    x1 = std::min(x1, img.width());
    y1 = std::min(y1, img.height());
    for (int y = y0; y < y1; ++y) {
        std::uint8_t* row = img.data() + 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width()));
        for (int x = 3 * x0; x < 3 * x1; ++x) row[x] = static_cast<std::uint8_t>(row[x] * 2 / 5);
    }
}

// Lines of text, each made of colored pieces.
struct Piece {
    std::string text;
    Color color;
};
using Line = std::vector<Piece>;

int width_of(const Line& line) {
    int width = 0;
    for (const Piece& p : line) width += raster::text_width(p.text);
    return width;
}

// A line of one piece too wide for `room` pixels at scale 2 becomes several, broken at spaces.
std::vector<Line> wrap(const Line& line, int room) {
    if (line.size() != 1 || 2 * width_of(line) <= room) return {line};
    std::vector<Line> out;
    std::string current;
    std::size_t start = 0;
    const std::string& text = line[0].text;
    while (start < text.size()) {
        std::size_t end = text.find(' ', start);
        if (end == std::string::npos) end = text.size();
        const std::string word = text.substr(start, end - start);
        const std::string longer = current.empty() ? word : current + " " + word;
        if (!current.empty() && 2 * raster::text_width(longer) > room) {
            out.push_back({{current, line[0].color}});
            current = "  " + word;  // continued lines are indented
        } else {
            current = longer;
        }
        start = end + 1;
    }
    if (!current.empty()) out.push_back({{current, line[0].color}});
    return out;
}

// Writes the lines downward from (x, y), on darkened bands: at scale 2 when a line fits the
// image's width (long single-color lines are wrapped first), else at scale 1. Returns the y
// below the last line.
int write_lines(Image& img, int x, int y, const std::vector<Line>& lines) {
    const int room = img.width() - 2 * x;
    for (const Line& unwrapped : lines) {
        for (const Line& line : wrap(unwrapped, room)) {
            const int width = width_of(line);
            const int scale = (2 * width <= room) ? 2 : 1;
            const int height = kGlyphHeight * scale;
            darken(img, x - 4, y - 3, x + width * scale + 4, y + height + 2);
            int cx = x;
            for (const Piece& p : line) {
                raster::draw_text(img, cx, y, p.text, p.color, scale);
                cx += raster::text_width(p.text, scale);
            }
            y += height + 6;
        }
    }
    return y;
}

// The height write_lines will take for `lines`.
int height_of(const Image& img, int x, const std::vector<Line>& lines) {
    const int room = img.width() - 2 * x;
    int h = 0;
    for (const Line& unwrapped : lines) {
        for (const Line& line : wrap(unwrapped, room)) h += kGlyphHeight * (2 * width_of(line) <= room ? 2 : 1) + 6;
    }
    return h;
}

}  // namespace

App::App(const Flavour& student, const Flavour& reference, const Stages& stages)
    : student_(student), reference_(reference), stages_(stages) {
    set_model(default_model());
    set_mode(Mode::kGouraud);
    move_light(0, 0);
}

void App::set_model(Model model, const std::string& error) {
    model_ = std::move(model);
    model_error_ = error;
    for (auto& p : prepared_) p.reset();
    scene_assets_.reset();
    for (auto& p : prepared_scene_) p.reset();
}

void App::set_mode(Mode mode) {
    mode_ = mode;
    plan_ = make_plan(mode, stages_, student_, reference_);
}

void App::move_light(double azimuth, double elevation) { set_light(light_azimuth_ + azimuth, light_elevation_ + elevation); }

void App::set_light(double azimuth, double elevation) {
    if (!std::isfinite(azimuth) || !std::isfinite(elevation)) return;
    light_azimuth_ = std::remainder(azimuth, 2 * std::numbers::pi);
    light_elevation_ = std::clamp(elevation, -1.5, 1.5);
    // The light sits in the direction (azimuth, elevation) from the model; its rays travel back.
    const double c = std::cos(light_elevation_);
    light_.direction = {-c * std::sin(light_azimuth_), -std::sin(light_elevation_), -c * std::cos(light_azimuth_)};
}

void App::advance(double seconds) {
    if (spin_) model_yaw_ = std::remainder(model_yaw_ + kSpinPerSecond * seconds, 2 * std::numbers::pi);
    if (light_circling_) move_light(2 * std::numbers::pi * seconds / kLightTurnSeconds, 0);
}

const SceneAssets& App::scene_assets() {
    if (!scene_assets_) scene_assets_ = std::make_unique<SceneAssets>(make_scene_assets(model_));
    return *scene_assets_;
}

PreparedScene& App::prepared_scene(const Flavour& flavour) {
    std::unique_ptr<PreparedScene>& slot = prepared_scene_[&flavour == &student_ ? 0 : 1];
    if (!slot) slot = flavour.prepare_scene(scene_assets());
    return *slot;
}

View App::view() {
    // The shadowed mode's floor reaches past the model's unit sphere: near and far hold it too.
    const double radius = mode_ == Mode::kShadowed ? scene_assets().scene_radius : 1.0;
    return camera_.view(model_yaw_, 45, radius);
}

const PreparedMesh& App::prepared(const Flavour& flavour) {
    std::unique_ptr<PreparedMesh>& slot = prepared_[&flavour == &student_ ? 0 : 1];
    if (!slot) slot = flavour.prepare(model_.mesh);
    return *slot;
}

FrameInfo App::render(Target& target) {
    FrameInfo info;
    const raster::Stopwatch clock;
    try {
        const View v = view();
        const Geometry geometry{&model_.mesh, &model_.edges};
        switch (plan_.path) {
            case Plan::Path::kDrawMesh:
                info.counts = plan_.mesh->draw_mesh(target, prepared(*plan_.mesh), v, light_, mode_, cull_, kBackground);
                break;
            case Plan::Path::kPainter:
                target.color.fill(kBackground);
                info.counts = plan_.transforms->painter(target.color, geometry, v, light_, plan_.primitive->fill_triangle,
                                                        plan_.lighting->shade_face);
                break;
            case Plan::Path::kWireframe:
                target.color.fill(kBackground);
                info.counts = plan_.transforms->wireframe(target.color, geometry, v, plan_.primitive->draw_line, kWireColor);
                break;
            case Plan::Path::kScene:
                info.counts = plan_.mesh->draw_scene(target, prepared_scene(*plan_.mesh), v, light_,
                                                     scene_setup(mode_, scene_assets()), kBackground);
                break;
        }
    } catch (const std::exception& e) {
        info.failure = std::string("drawing failed: ") + e.what();
    }
    info.render_ms = clock.milliseconds();
    smoothed_ms_ = smoothed_ms_ == 0 ? info.render_ms : 0.9 * smoothed_ms_ + 0.1 * info.render_ms;
    return info;
}

std::string App::warning(const FrameInfo& info) const {
    if (!info.failure.empty()) return info.failure;
    if (!model_error_.empty()) return model_error_ + "; showing " + model_.name;
    const std::string camera = camera_.warning();
    if (!camera.empty()) return camera;
    if (info.counts.triangles == 0 && info.counts.lines == 0) {
        return "nothing in view: the model is behind the camera or off the screen (R resets)";
    }
    return "";
}

void App::draw_overlay(Image& img, const FrameInfo& info) const {
    if (img.empty()) return;
    const long long triangles = static_cast<long long>(model_.mesh.triangles.size());
    const double ms = std::max(smoothed_ms_, 1e-3);
    std::vector<Line> top;
    top.push_back({{std::string(mode_name(mode_)) + "   " + fixed(ms, 1) + " ms/frame   " + fixed(1000 / ms, 0) +
                        " fps   " + fixed(triangles / ms / 1000, 2) + " M triangles/s",
                    kText}});
    top.push_back({{"drawn by: " + plan_.description, kDim}});
    if (help_) {
        for (int s = 1; s <= kStages; ++s) {
            const StageResult& r = stages_[static_cast<std::size_t>(s - 1)];
            top.push_back({{"m" + std::to_string(s) + " " + stage_title(s) + ": ", kDim},
                           {r.yours ? "YOURS" : "reference", r.yours ? kYours : kReference},
                           {r.yours ? "" : "  (yours: " + r.detail + ")", kDim}});
        }
    } else {
        Line compact;
        for (int s = 1; s <= kStages; ++s) {
            const bool yours = stages_[static_cast<std::size_t>(s - 1)].yours;
            compact.push_back({"m" + std::to_string(s) + (yours ? " yours   " : " reference   "), yours ? kYours : kReference});
        }
        top.push_back(compact);
    }
    const std::string w = warning(info);
    if (!w.empty()) top.push_back({{w, kWarning}});
    write_lines(img, 10, 10, top);

    std::vector<Line> bottom;
    const std::string culling = is_scene_mode(mode_) ? "no culling (m5 draws both faces)"
                                                     : std::string("culling ") + (cull_ ? "on" : "off");
    bottom.push_back({{model_.name + ": " + grouped(triangles) + " triangles, " + culling + (spin_ ? ", spinning" : "") +
                           (light_circling_ ? ", light circling" : ""),
                       kDim}});
    if (help_) {
        bottom.push_back({{"1-6 wireframe flat Gouraud per-pixel depth normals", kText}});
        bottom.push_back({{"7-9 textured specular shadowed (milestone 5)", kText}});
        bottom.push_back({{"drag/arrows orbit   right drag/ADQE pan   wheel/WS zoom", kText}});
        bottom.push_back({{"shift+drag/IJKL light  O circle it  space spin  C cull  R reset", kText}});
        bottom.push_back({{"H hide help   P screenshot   Esc quit", kText}});
    } else {
        bottom.push_back({{"H: help", kText}});
    }
    write_lines(img, 10, img.height() - 4 - height_of(img, 10, bottom), bottom);
}

}  // namespace viewer
