// The viewer without its window: the state that input changes (mode, camera, light, spin),
// the frame drawn by whichever code the plan picks, and the text drawn over it. main.cpp feeds
// it SDL's events and shows its image; the benchmark and the tests use it without any window.
#pragma once

#include <array>
#include <memory>
#include <string>

#include "camera.h"
#include "flavour_api.h"
#include "model.h"
#include "plan.h"
#include "probe.h"
#include "scene.h"

namespace viewer {

struct FrameInfo {
    DrawCounts counts;
    double render_ms = 0;  // the pipeline alone (not the text, not the upload to the window)
    std::string failure;   // an exception the drawing code threw, if any
};

class App {
public:
    App(const Flavour& student, const Flavour& reference, const Stages& stages);

    // A new model; `error` (may be empty) says why it is not the one asked for.
    void set_model(Model model, const std::string& error = "");
    const Model& model() const { return model_; }

    // ---- what input changes ----
    void set_mode(Mode mode);
    Mode mode() const { return mode_; }
    OrbitCamera& camera() { return camera_; }
    const OrbitCamera& camera() const { return camera_; }
    // Turns the light around the model (radians): azimuth about y, elevation up and down.
    void move_light(double azimuth, double elevation);
    // Puts the light at (azimuth, elevation) (radians; the elevation clamped as move_light's).
    void set_light(double azimuth, double elevation);
    double light_azimuth() const { return light_azimuth_; }
    double light_elevation() const { return light_elevation_; }
    // The light circles the model (one turn in kLightTurnSeconds of animation) or stops.
    void toggle_light_circle() { light_circling_ = !light_circling_; }
    bool light_circling() const { return light_circling_; }
    static constexpr double kLightTurnSeconds = 8;
    void toggle_cull() { cull_ = !cull_; }
    void toggle_spin() { spin_ = !spin_; }
    void toggle_help() { help_ = !help_; }
    bool spinning() const { return spin_; }
    // Something moves by itself (the spin or the circling light): the window keeps drawing.
    bool animating() const { return spin_ || light_circling_; }
    // Advances the spin and the circling light by `seconds` of animation.
    void advance(double seconds);

    // ---- a frame ----
    // Draws the model into target.color (its size is the frame's) with the plan's code.
    FrameInfo render(Target& target);
    // The text over the frame: mode, frame time, who draws what, the warning, the keys.
    void draw_overlay(raster::Image& img, const FrameInfo& info) const;
    // The warning for this frame, or "" (a bad model, an extreme camera, nothing in view).
    std::string warning(const FrameInfo& info) const;

    const Plan& plan() const { return plan_; }
    const Stages& stages() const { return stages_; }

    // What the scene modes draw for this model (made when first needed).
    const SceneAssets& scene_assets();

private:
    const PreparedMesh& prepared(const Flavour& flavour);
    PreparedScene& prepared_scene(const Flavour& flavour);
    View view();

    const Flavour& student_;
    const Flavour& reference_;
    Stages stages_;
    Model model_;
    std::string model_error_;
    std::array<std::unique_ptr<PreparedMesh>, 2> prepared_;  // per flavour, made when first drawn
    std::unique_ptr<SceneAssets> scene_assets_;               // made when a scene mode first draws
    std::array<std::unique_ptr<PreparedScene>, 2> prepared_scene_;

    Mode mode_ = Mode::kGouraud;
    Plan plan_;
    OrbitCamera camera_;
    LightSetup light_;
    double light_azimuth_ = -0.7, light_elevation_ = 0.6;
    bool cull_ = true;
    bool spin_ = false;
    bool light_circling_ = false;
    bool help_ = true;
    double model_yaw_ = 0;
    double smoothed_ms_ = 0;  // the render time, averaged over the last frames, for the screen
};

}  // namespace viewer
