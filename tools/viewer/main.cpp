// viewer: the student's own rasterizer in a window (SDL2). Orbit, pan and zoom around a model,
// switch between wireframe, flat, Gouraud, per-pixel, depth and normals (milestones 1 to 4) and
// textured, specular and shadowed (milestone 5), move the light or let it circle. Each
// milestone the student has not finished yet is drawn by the reference, and the screen says so.
//
//   viewer [MODEL] [options]     MODEL: an .obj file, a model of common/models by name (cube,
//                                soccer_ball...), or torus / sphere / big-torus (generated);
//                                default: a generated torus
//   --mode NAME                  start in wireframe, flat, gouraud, perpixel, depth, normals,
//                                textured, specular or shadowed
//   --size WxH                   window size (default 800x600)
//   --spin / --still / --no-help start spinning (the default in a window opened by hand) /
//                                not spinning / with the key help hidden
//   --reference                  draw everything with the reference (skip the probes)
//   --help                       the options and the keys
//   --events "STEPS"             scripted mode (script.h): inject events, take screenshots, exit
//   --script FILE                the same, steps read from FILE
//   --probe                      print which milestones are yours and exit (no window)
//   --gif FILE [FRAMES]          write an animated GIF of the light circling the model once
//                                (default 36 frames; --size sets its size), and exit (no window)
//   --bench [FRAMES]             time the reference on ~100,000 triangles at 800x600 (no window)
//
// Headless: SDL_VIDEODRIVER=dummy works (scripted mode, screenshots), as does xvfb-run -a.
#define SDL_MAIN_HANDLED
#include <SDL.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "app.h"
#include "raster/gif.h"
#include "raster/io.h"
#include "raster/timer.h"
#include "script.h"

namespace {

using viewer::App;
using viewer::Mode;

struct Options {
    std::string model = "torus";
    Mode mode = Mode::kGouraud;
    int width = 800, height = 600;
    bool spin = false, still = false, help = true;
    bool show_help = false;
    bool reference_only = false;
    bool probe_only = false;
    bool bench = false;
    int bench_frames = 60;
    std::string gif;
    int gif_frames = 36;
    bool scripted = false;
    std::vector<viewer::Step> script;
};

constexpr const char* kModeNames[viewer::kModeCount] = {"wireframe", "flat",     "gouraud",  "perpixel", "depth",
                                                         "normals",   "textured", "specular", "shadowed"};

void usage(std::ostream& out, const char* argv0) {
    out << "usage: " << argv0
              << " [MODEL.obj | torus | sphere | big-torus | cube | soccer_ball ...]\n"
                 "  [--mode wireframe|flat|gouraud|perpixel|depth|normals|textured|specular|shadowed] [--size WxH]\n"
                 "  [--spin | --still] [--no-help] [--reference] [--events \"STEPS\" | --script FILE] [--probe]\n"
                 "  [--gif FILE [FRAMES]] [--bench [FRAMES]]\n"
                 "Scripted steps (';' or new lines): key NAME [N]; drag BUTTON X0 Y0 X1 Y1; wheel N; frames N;\n"
                 "  screenshot FILE; quit\n"
                 "Keys: 1-9 mode, drag or arrows orbit, right drag or A D Q E pan, wheel or W S zoom,\n"
                 "  shift+drag or I J K L light, O light circles, space spin, C culling, R reset, H help,\n"
                 "  P screenshot, Esc quit\n";
}

bool parse_options(int argc, char** argv, Options& o) {
    std::string script_text;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const auto value = [&](std::string& out) {
            if (i + 1 >= argc) return false;
            out = argv[++i];
            return true;
        };
        std::string v;
        if (a == "--mode") {
            if (!value(v)) return false;
            bool found = false;
            for (int m = 0; m < viewer::kModeCount; ++m) {
                if (v == kModeNames[m]) {
                    o.mode = static_cast<Mode>(m);
                    found = true;
                }
            }
            if (!found) return false;
        } else if (a == "--size") {
            if (!value(v) || std::sscanf(v.c_str(), "%dx%d", &o.width, &o.height) != 2) return false;
            if (o.width < 64 || o.height < 64 || o.width > 8192 || o.height > 8192) return false;
        } else if (a == "--spin") {
            o.spin = true;
        } else if (a == "--still") {
            o.still = true;
        } else if (a == "--help" || a == "-h") {
            o.show_help = true;
        } else if (a == "--no-help") {
            o.help = false;
        } else if (a == "--reference") {
            o.reference_only = true;
        } else if (a == "--probe") {
            o.probe_only = true;
        } else if (a == "--bench") {
            o.bench = true;
            if (i + 1 < argc && std::atoi(argv[i + 1]) > 0) o.bench_frames = std::atoi(argv[++i]);
        } else if (a == "--gif") {
            if (!value(o.gif) || o.gif.empty()) return false;
            if (i + 1 < argc && std::atoi(argv[i + 1]) > 0) o.gif_frames = std::atoi(argv[++i]);
            if (o.gif_frames < 2 || o.gif_frames > 400) return false;
        } else if (a == "--events") {
            if (!value(script_text)) return false;
            o.scripted = true;
        } else if (a == "--script") {
            if (!value(v)) return false;
            std::ifstream in(v);
            if (!in) {
                std::cerr << "viewer: cannot read the script " << v << "\n";
                return false;
            }
            std::ostringstream text;
            text << in.rdbuf();
            script_text = text.str();
            o.scripted = true;
        } else if (!a.empty() && a[0] == '-') {
            return false;
        } else {
            o.model = a;
        }
    }
    if (o.scripted) {
        std::string error;
        if (!viewer::parse_script(script_text, o.script, error)) {
            std::cerr << "viewer: " << error << "\n";
            return false;
        }
    }
    return true;
}

void print_stages(const viewer::Stages& stages) {
    for (int s = 1; s <= viewer::kStages; ++s) {
        const viewer::StageResult& r = stages[static_cast<std::size_t>(s - 1)];
        std::cout << "m" << s << " " << viewer::stage_title(s) << ": " << (r.yours ? "yours" : "reference")
                  << " (your code: " << r.detail << ")\n";
    }
}

// ---- the benchmark: the reference pipeline alone, no window ----

int run_bench(int frames) {
    viewer::Model model;
    viewer::make_named("big-torus", model);
    const viewer::Flavour& ref = viewer::reference::flavour();
    const auto prepared = ref.prepare(model.mesh);
    viewer::Target target{raster::Image(800, 600), {}};
    const viewer::OrbitCamera camera;
    const viewer::LightSetup light;
    const long long triangles = static_cast<long long>(model.mesh.triangles.size());
    std::cout << "viewer --bench: the reference m4::draw_mesh, " << triangles << " triangles (" << model.name
              << "), 800x600, depth test, back-face culling, one thread, " << frames << " frames per mode\n";
    bool all_met = true;
    for (const Mode mode : {Mode::kFlat, Mode::kGouraud, Mode::kPerPixel}) {
        for (int i = 0; i < 3; ++i) ref.draw_mesh(target, *prepared, camera.view(0), light, mode, true, {0, 0, 0});
        const raster::Stopwatch clock;
        for (int i = 0; i < frames; ++i) {  // the model turns, as in the viewer
            ref.draw_mesh(target, *prepared, camera.view(0.01 * i), light, mode, true, {0, 0, 0});
        }
        const double ms = clock.milliseconds() / frames;
        const bool met = ms <= 1000.0 / 60.0;
        all_met = all_met && met;
        std::printf("  %-10s %7.2f ms per frame  %6.1f fps  %6.2f M triangles/s  60 fps goal: %s\n",
                    viewer::mode_name(mode), ms, 1000 / ms, triangles / ms / 1000, met ? "met" : "NOT met");
    }
    std::printf("60 fps goal (16.7 ms per frame): %s\n", all_met ? "met in every mode" : "not met in every mode");
    return 0;
}

// ---- the GIF: the light circling once, no window ----

int run_gif(App& app, const Options& o) {
    std::vector<raster::Image> frames;
    viewer::Target target;
    // The light a little lower than the window's first one: longer shadows, past the model.
    const double start = app.light_azimuth(), elevation = app.light_elevation() - 0.15;
    for (int i = 0; i < o.gif_frames; ++i) {
        app.set_light(start + 2 * std::numbers::pi * i / o.gif_frames, elevation);
        target.color = raster::Image(o.width, o.height);
        const viewer::FrameInfo info = app.render(target);
        if (!info.failure.empty()) {
            std::cerr << "viewer: " << info.failure << "\n";
            return 1;
        }
        frames.push_back(target.color);
    }
    try {
        raster::write_gif(o.gif, frames, 8);
    } catch (const std::exception& e) {
        std::cerr << "viewer: " << e.what() << "\n";
        return 1;
    }
    std::cout << "viewer: " << viewer::mode_name(app.mode()) << ", drawn by " << app.plan().description << ": "
              << o.gif_frames << " frames of " << o.width << "x" << o.height << " written to " << o.gif << "\n";
    return 0;
}

// ---- the window ----

// Turns a scripted step into real SDL events on the queue (the loop then handles them as it
// handles a person's input). Returns false for a key SDL does not know.
bool push_step(const viewer::Step& step, Uint32 window_id) {
    const auto push = [](SDL_Event e) { return SDL_PushEvent(&e) == 1; };
    const auto key_event = [&](Uint32 type, SDL_Keycode key, Uint16 mod) {
        SDL_Event e{};
        e.type = type;
        e.key.windowID = window_id;
        e.key.state = type == SDL_KEYDOWN ? SDL_PRESSED : SDL_RELEASED;
        e.key.keysym.sym = key;
        e.key.keysym.scancode = SDL_GetScancodeFromKey(key);
        e.key.keysym.mod = mod;
        return push(e);
    };
    const Uint16 mod = step.shift ? KMOD_LSHIFT : KMOD_NONE;
    if (step.shift) key_event(SDL_KEYDOWN, SDLK_LSHIFT, mod);
    bool ok = true;
    if (step.kind == viewer::Step::Kind::kKey) {
        const SDL_Keycode key = SDL_GetKeyFromName(step.name.c_str());
        if (key == SDLK_UNKNOWN) {
            ok = false;
        } else {
            for (int i = 0; i < step.count; ++i) ok = key_event(SDL_KEYDOWN, key, mod) && key_event(SDL_KEYUP, key, mod) && ok;
        }
    } else if (step.kind == viewer::Step::Kind::kDrag) {
        const Uint8 button = step.name == "right" ? SDL_BUTTON_RIGHT : step.name == "middle" ? SDL_BUTTON_MIDDLE : SDL_BUTTON_LEFT;
        SDL_Event e{};
        e.type = SDL_MOUSEBUTTONDOWN;
        e.button.windowID = window_id;
        e.button.button = button;
        e.button.state = SDL_PRESSED;
        e.button.clicks = 1;
        e.button.x = step.x0;
        e.button.y = step.y0;
        push(e);
        constexpr int kMoves = 10;
        int x = step.x0, y = step.y0;
        for (int i = 1; i <= kMoves; ++i) {
            const int nx = step.x0 + (step.x1 - step.x0) * i / kMoves, ny = step.y0 + (step.y1 - step.y0) * i / kMoves;
            SDL_Event m{};
            m.type = SDL_MOUSEMOTION;
            m.motion.windowID = window_id;
            m.motion.state = SDL_BUTTON(button);
            m.motion.x = nx;
            m.motion.y = ny;
            m.motion.xrel = nx - x;
            m.motion.yrel = ny - y;
            push(m);
            x = nx;
            y = ny;
        }
        e.type = SDL_MOUSEBUTTONUP;
        e.button.state = SDL_RELEASED;
        e.button.x = step.x1;
        e.button.y = step.y1;
        push(e);
    } else if (step.kind == viewer::Step::Kind::kWheel) {
        SDL_Event e{};
        e.type = SDL_MOUSEWHEEL;
        e.wheel.windowID = window_id;
        e.wheel.y = step.count;
        e.wheel.direction = SDL_MOUSEWHEEL_NORMAL;
        push(e);
    }
    if (step.shift) key_event(SDL_KEYUP, SDLK_LSHIFT, KMOD_NONE);
    return ok;
}

// The window's pixels as the renderer shows them, as a PNG through the project's writer.
bool save_screenshot(SDL_Renderer* renderer, int width, int height, const std::string& path) {
    raster::Image shot(width, height);
    if (SDL_RenderReadPixels(renderer, nullptr, SDL_PIXELFORMAT_RGB24, shot.data(), width * 3) != 0) {
        std::cerr << "viewer: cannot read the window's pixels: " << SDL_GetError() << "\n";
        return false;
    }
    try {
        raster::write_png(path, shot);
    } catch (const std::exception& e) {
        std::cerr << "viewer: " << e.what() << "\n";
        return false;
    }
    std::cout << "viewer: screenshot " << path << "\n" << std::flush;
    return true;
}

// What the person (or the script) does, as SDL events.
class Input {
public:
    explicit Input(App& app) : app_(app) {}
    bool quit() const { return quit_; }
    bool screenshot_requested() {
        const bool r = screenshot_;
        screenshot_ = false;
        return r;
    }

    void handle(const SDL_Event& e, int height) {
        switch (e.type) {
            case SDL_QUIT: quit_ = true; break;
            case SDL_KEYDOWN: key(e.key.keysym.sym); break;
            case SDL_KEYUP:
                if (e.key.keysym.sym == SDLK_LSHIFT || e.key.keysym.sym == SDLK_RSHIFT) shift_ = false;
                break;
            case SDL_MOUSEBUTTONDOWN:
                dragging_ = e.button.button;
                light_drag_ = dragging_ == SDL_BUTTON_LEFT && shift_;
                break;
            case SDL_MOUSEBUTTONUP:
                if (e.button.button == dragging_) dragging_ = 0;
                break;
            case SDL_MOUSEMOTION: motion(e.motion.xrel, e.motion.yrel, height); break;
            case SDL_MOUSEWHEEL: {
                const int notches = e.wheel.direction == SDL_MOUSEWHEEL_FLIPPED ? -e.wheel.y : e.wheel.y;
                app_.camera().zoom(std::pow(0.9, notches));
                break;
            }
        }
    }

private:
    void key(SDL_Keycode k) {
        constexpr double kTurn = 0.1, kPan = 0.05, kZoom = 0.9;
        auto& cam = app_.camera();
        if (k >= SDLK_1 && k < SDLK_1 + viewer::kModeCount) app_.set_mode(static_cast<Mode>(k - SDLK_1));
        switch (k) {
            case SDLK_ESCAPE: quit_ = true; break;
            case SDLK_LSHIFT:
            case SDLK_RSHIFT: shift_ = true; break;
            case SDLK_TAB:
            case SDLK_m: app_.set_mode(static_cast<Mode>((static_cast<int>(app_.mode()) + 1) % viewer::kModeCount)); break;
            case SDLK_LEFT: cam.orbit(kTurn, 0); break;
            case SDLK_RIGHT: cam.orbit(-kTurn, 0); break;
            case SDLK_UP: cam.orbit(0, kTurn); break;
            case SDLK_DOWN: cam.orbit(0, -kTurn); break;
            case SDLK_w:
            case SDLK_PLUS:
            case SDLK_EQUALS:
            case SDLK_KP_PLUS: cam.zoom(kZoom); break;
            case SDLK_s:
            case SDLK_MINUS:
            case SDLK_KP_MINUS: cam.zoom(1 / kZoom); break;
            case SDLK_a: cam.pan(kPan, 0); break;   // the camera left: the model moves right
            case SDLK_d: cam.pan(-kPan, 0); break;
            case SDLK_q: cam.pan(0, -kPan); break;  // the camera down
            case SDLK_e: cam.pan(0, kPan); break;
            case SDLK_j: app_.move_light(-kTurn, 0); break;
            case SDLK_l: app_.move_light(kTurn, 0); break;
            case SDLK_i: app_.move_light(0, kTurn); break;
            case SDLK_k: app_.move_light(0, -kTurn); break;
            case SDLK_o: app_.toggle_light_circle(); break;
            case SDLK_SPACE: app_.toggle_spin(); break;
            case SDLK_c: app_.toggle_cull(); break;
            case SDLK_r: cam.reset(); break;
            case SDLK_h:
            case SDLK_F1: app_.toggle_help(); break;
            case SDLK_p: screenshot_ = true; break;
            default: break;
        }
    }

    void motion(int dx, int dy, int height) {
        constexpr double kRadiansPerPixel = 0.01;
        if (dragging_ == SDL_BUTTON_LEFT && light_drag_) {
            app_.move_light(dx * kRadiansPerPixel, -dy * kRadiansPerPixel);
        } else if (dragging_ == SDL_BUTTON_LEFT) {
            app_.camera().orbit(-dx * kRadiansPerPixel, dy * kRadiansPerPixel);
        } else if (dragging_ == SDL_BUTTON_RIGHT || dragging_ == SDL_BUTTON_MIDDLE) {
            app_.camera().pan(static_cast<double>(dx) / height, static_cast<double>(dy) / height);
        }
    }

    App& app_;
    bool quit_ = false, shift_ = false, light_drag_ = false, screenshot_ = false;
    Uint8 dragging_ = 0;  // the button held, 0 for none
};

int run_window(App& app, const Options& o) {
    SDL_SetMainReady();
    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        std::cerr << "viewer: cannot open a window: " << SDL_GetError()
                  << "\n(no display? run it under `xvfb-run -a`, or headless with SDL_VIDEODRIVER=dummy and --events)\n";
        return 1;
    }
    SDL_SetHint(SDL_HINT_RENDER_SCALE_QUALITY, "0");  // the frame is shown pixel for pixel
    SDL_Window* window = SDL_CreateWindow("raster viewer: your rasterizer", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                                          o.width, o.height, o.scripted ? 0 : SDL_WINDOW_RESIZABLE);
    SDL_Renderer* renderer = window ? SDL_CreateRenderer(window, -1, 0) : nullptr;
    if (window && !renderer) renderer = SDL_CreateRenderer(window, -1, SDL_RENDERER_SOFTWARE);
    if (!renderer) {
        std::cerr << "viewer: cannot create a window and renderer: " << SDL_GetError() << "\n";
        if (window) SDL_DestroyWindow(window);
        SDL_Quit();
        return 1;
    }
    const Uint32 window_id = SDL_GetWindowID(window);

    Input input(app);
    viewer::Target target;
    SDL_Texture* texture = nullptr;
    std::size_t next_step = 0;
    int frames_to_wait = 0;
    int exit_code = 0;
    std::string last_warning, last_drawn_by;
    Uint64 last_tick = SDL_GetPerformanceCounter();
    bool idle = false;

    while (!input.quit()) {
        // 1. Scripted mode: one step per frame, as events pushed onto SDL's own queue.
        std::string screenshot_path;
        if (o.scripted && frames_to_wait > 0) {
            --frames_to_wait;
        } else if (o.scripted) {
            if (next_step == o.script.size()) break;  // the script is over
            const viewer::Step& step = o.script[next_step++];
            switch (step.kind) {
                case viewer::Step::Kind::kQuit: frames_to_wait = -1; break;
                case viewer::Step::Kind::kFrames: frames_to_wait = step.count - 1; break;
                case viewer::Step::Kind::kScreenshot: screenshot_path = step.name; break;
                default:
                    if (!push_step(step, window_id)) {
                        std::cerr << "viewer: unknown key \"" << step.name << "\" in the script\n";
                        exit_code = 1;
                    }
            }
            if (frames_to_wait < 0) break;
        }

        // 2. Events: a person's, or the script's. Idle and not animating: wait for one.
        if (!o.scripted && idle && !app.animating()) SDL_WaitEventTimeout(nullptr, 250);
        SDL_Event e;
        int w = 0, h = 0;
        SDL_GetRendererOutputSize(renderer, &w, &h);
        idle = true;
        while (SDL_PollEvent(&e)) {
            input.handle(e, h > 0 ? h : o.height);
            idle = false;
        }
        if (input.screenshot_requested()) screenshot_path = "viewer-screenshot.png";

        // 3. The frame's size follows the window's.
        if (w <= 0 || h <= 0) continue;  // minimized
        if (!texture || target.color.width() != w || target.color.height() != h) {
            if (texture) SDL_DestroyTexture(texture);
            texture = SDL_CreateTexture(renderer, SDL_PIXELFORMAT_RGB24, SDL_TEXTUREACCESS_STREAMING, w, h);
            if (!texture) {
                std::cerr << "viewer: cannot create a texture: " << SDL_GetError() << "\n";
                exit_code = 1;
                break;
            }
            target.color = raster::Image(w, h);
            target.depth.clear();
        }

        // 4. Draw: the model with the plan's code, then the text.
        const Uint64 now = SDL_GetPerformanceCounter();
        app.advance(o.scripted ? 1.0 / 30 : static_cast<double>(now - last_tick) / SDL_GetPerformanceFrequency());
        last_tick = now;
        const viewer::FrameInfo info = app.render(target);
        app.draw_overlay(target.color, info);
        const std::string drawn_by = std::string(viewer::mode_name(app.mode())) + ": drawn by " + app.plan().description;
        if (drawn_by != last_drawn_by) {
            std::cout << "viewer: " << drawn_by << "\n" << std::flush;
            last_drawn_by = drawn_by;
        }
        const std::string warning = app.warning(info);
        if (warning != last_warning) {
            if (!warning.empty()) std::cout << "viewer: " << warning << "\n" << std::flush;
            last_warning = warning;
        }

        // 5. Show it: the RGB image becomes the texture, pixel for pixel.
        SDL_UpdateTexture(texture, nullptr, target.color.data(), w * 3);
        SDL_RenderClear(renderer);
        SDL_RenderCopy(renderer, texture, nullptr, nullptr);
        if (!screenshot_path.empty() && !save_screenshot(renderer, w, h, screenshot_path)) exit_code = 1;
        SDL_RenderPresent(renderer);
    }
    if (texture) SDL_DestroyTexture(texture);
    SDL_DestroyRenderer(renderer);
    SDL_DestroyWindow(window);
    SDL_Quit();
    return exit_code;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    if (!parse_options(argc, argv, o)) {
        usage(std::cerr, argv[0]);
        return 2;
    }
    if (o.show_help) {
        usage(std::cout, argv[0]);
        return 0;
    }
    if (o.bench) return run_bench(o.bench_frames);

    // Which milestones are the student's: probed before any window exists (the probes fork).
    const viewer::Flavour& student = viewer::student::flavour();
    const viewer::Flavour& reference = viewer::reference::flavour();
    const viewer::Stages stages = o.reference_only ? viewer::all_reference("not probed, --reference given")
                                                   : viewer::probe_stages(student, reference);
    print_stages(stages);
    if (o.probe_only) return 0;

    App app(student, reference, stages);
    std::string error;
    viewer::Model model = viewer::load_model(o.model, error);
    if (!error.empty()) std::cout << "viewer: " << error << "\n";
    app.set_model(std::move(model), error);
    app.set_mode(o.mode);
    if (!o.gif.empty()) return run_gif(app, o);
    // A window opened by hand starts turning (space stops it); a script starts still, so that
    // each of its screenshots shows only what its steps did.
    if (o.spin || (!o.scripted && !o.still)) app.toggle_spin();
    if (!o.help) app.toggle_help();
    return run_window(app, o);
}
