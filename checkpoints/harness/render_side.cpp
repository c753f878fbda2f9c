// The render side of the harness: what a render program needs around the code under test
// (attribution, the watchdog, timing, the guarded images, writing artifacts). It holds no
// judge, no reference and no expected image: the grader links it into the one program that
// runs a student's code.
#include <algorithm>
#include <chrono>
#include <exception>
#include <condition_variable>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <locale>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "harness/checkpoint.h"
#include "raster/io.h"
#include "raster/timer.h"

namespace fs = std::filesystem;

namespace cp {
namespace {

// The call of the code under test that is running now, for the watchdog. Guarded by a mutex:
// the watchdog holds it while it reports, so the call (and the image it draws into) cannot
// end under its feet.
struct Running {
    std::mutex mutex;
    const std::string* function = nullptr;  // a key of the running call's trace; null: none
    long long call = 0;
    const raster::Image* img = nullptr;
    long long writes0 = 0, strays0 = 0;
};

Running& running() {
    static Running r;
    return r;
}

}  // namespace

TracedCall::TracedCall(Artifacts& out, std::string_view function, const raster::Image* img)
    : out_(&out), img_(img), uncaught0_(std::uncaught_exceptions()) {
    auto it = out.trace.find(function);
    if (it == out.trace.end()) it = out.trace.emplace(std::string(function), FunctionTrace{}).first;
    entry_ = &it->second;
    name_ = &it->first;
    if (img_ != nullptr) {
        writes0_ = img_->writes();
        strays0_ = img_->stray_writes();
    }
    Running& r = running();
    const std::lock_guard<std::mutex> lock(r.mutex);
    r.function = &it->first;
    r.call = entry_->calls + 1;
    r.img = img_;
    r.writes0 = writes0_;
    r.strays0 = strays0_;
}

TracedCall::~TracedCall() {
    Running& r = running();
    const std::lock_guard<std::mutex> lock(r.mutex);
    r.function = nullptr;
    r.img = nullptr;
    entry_->calls += 1;
    if (img_ != nullptr) {
        entry_->writes += img_->writes() - writes0_;
        entry_->stray_writes += img_->stray_writes() - strays0_;
    }
    // Left by an exception (the stray-write budget spent, see render_guarded): remember which
    // call it was, unless a call inside this one already did.
    if (std::uncaught_exceptions() > uncaught0_) {
        const auto& values = out_->values;
        const auto it = values.lower_bound(kRunawayInKey);
        if (it == values.end() || it->first.rfind(kRunawayInKey, 0) != 0) {
            out_->values[kRunawayInKey + *name_] = double(entry_->calls);
        }
    }
}

struct Watchdog::State {
    std::mutex mutex;
    std::condition_variable cv;
    bool done = false;
    std::thread thread;
};

Watchdog::Watchdog(double seconds, std::function<void(const StoppedCall&)> on_stop)
    : state_(std::make_unique<State>()) {
    State* st = state_.get();
    st->thread = std::thread([st, seconds, on_stop = std::move(on_stop)] {
        {
            std::unique_lock<std::mutex> lock(st->mutex);
            if (st->cv.wait_for(lock, std::chrono::duration<double>(seconds), [st] { return st->done; })) return;
        }
        Running& r = running();
        const std::lock_guard<std::mutex> lock(r.mutex);  // held until on_stop ends the process
        StoppedCall s;
        if (r.function != nullptr) {
            s.function = *r.function;
            s.call = r.call;
        }
        if (r.function != nullptr && r.img != nullptr) {
            s.writes = r.img->writes() - r.writes0;
            s.stray_writes = r.img->stray_writes() - r.strays0;
            // The stuck call may still be writing pixels while they are copied: at worst a
            // pixel of the picture is one write behind. The image's size never changes.
            s.picture = *r.img;
        }
        s.seconds = seconds;  // the limit, not the clock: the message must not depend on the machine's load
        on_stop(s);
        std::_Exit(1);  // on_stop should not return; if it does, still stop
    });
}

Watchdog::~Watchdog() {
    {
        const std::lock_guard<std::mutex> lock(state_->mutex);
        state_->done = true;
    }
    state_->cv.notify_all();
    state_->thread.join();
}

double watchdog_seconds() {
    const double s = std::strtod(env_or("RASTER_WATCHDOG_SECONDS", "").c_str(), nullptr);
    return s > 0 ? s : kDefaultWatchdogSeconds;
}

std::string env_or(const char* name, const std::string& fallback) {
    const char* v = std::getenv(name);
    return v && *v ? std::string(v) : fallback;
}

double time_best_of(const std::function<void()>& fn, int min_runs) {
    // One run is enough for anything slow; tiny scenes are repeated (up to 5 runs or about
    // 50 ms) and the fastest run is kept, which is the figure least disturbed by the machine.
    double best = 0, total = 0;
    for (int run = 0; run < 5; ++run) {
        raster::Stopwatch sw;
        fn();
        const double t = sw.seconds();
        best = run == 0 ? t : std::min(best, t);
        total += t;
        if (run + 1 >= min_runs && total > 0.05) break;
    }
    return best;
}

Artifacts render_guarded(int width, int height,
                         const std::function<void(raster::Image& main, Artifacts& out)>& draw) {
    Artifacts out;
    const long long strays_before = raster::Image::total_stray_writes();
    raster::Image img = guarded_image(width, height);
    try {
        draw(img, out);
    } catch (const raster::StrayWriteLimit&) {
        out.values[kRunawayKey] = 1;  // keep what was drawn: the picture shows where
    }
    for (const auto& [name, extra] : out.images) out.stray_writes += extra.stray_writes();
    out.stray_writes += img.stray_writes();
    // The process-wide count cannot be reset by assigning a fresh Image over a guarded one.
    out.stray_writes = std::max(out.stray_writes, raster::Image::total_stray_writes() - strays_before);
    out.images["main"] = std::move(img);
    return out;
}

raster::Image guarded_image(int width, int height) {
    raster::Image img(width, height);
    img.limit_stray_writes(kStrayWriteBudget);
    return img;
}

void record_under(Artifacts& out, const std::string& prefix,
                  const std::function<void(std::map<std::string, double>& values)>& numbers) {
    std::map<std::string, double> values;
    numbers(values);
    for (const auto& [key, value] : values) out.values[prefix + key] = value;
}

void record_fill_scene(Artifacts& out, const std::string& fill_key, int width, int height,
                       const std::function<void(raster::Image& img, Artifacts& scratch)>& draw) {
    Artifacts scratch;
    raster::Image img = guarded_image(width, height);
    draw(img, scratch);
    for (const auto& [key, value] : scratch.values) out.values[fill_key + key] = value;
    out.stray_writes += scratch.stray_writes;
    out.images[fill_key.substr(0, fill_key.size() - 1)] = std::move(img);
}

double seconds_of(const std::function<void()>& draw, bool best_of) {
    // At least two runs: memory a renderer keeps between frames (a shadow map of 4096^2 keys)
    // costs its first touch in the first run only, and a lesson's table compares frames.
    if (best_of) return time_best_of(draw, 2);
    const raster::Stopwatch watch;
    draw();
    return watch.seconds();
}

void place_panel(Artifacts& out, const std::string& key, const raster::Image& frame, raster::Image& img, int x0,
                 int y0, int w, int h) {
    out.stray_writes += frame.stray_writes();
    if (frame.width() != w || frame.height() != h) {
        out.values[key + ".resized"] = 1;
        return;
    }
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) img.set(x0 + x, y0 + y, frame.at(x, y));
    }
}

void save_artifacts(const std::string& dir, const Artifacts& a) {
    // values.txt is "key name number" per line: a name with white space would be misread.
    for (const auto& [name, v] : a.values) {
        if (name.empty() || name.find_first_of(" \t\n\r") != std::string::npos) {
            throw std::logic_error("value name '" + name + "' is empty or holds white space");
        }
    }
    fs::create_directories(dir);
    for (const auto& [name, img] : a.images) raster::write_png((fs::path(dir) / (name + ".png")).string(), img);
    std::ofstream out(fs::path(dir) / "values.txt");
    // The classic locale, whatever the global one is now: student code may have replaced it
    // (std::locale::global with its own number facet), and the numbers must be the program's.
    out.imbue(std::locale::classic());
    out << std::setprecision(17);
    out << "seconds " << a.seconds << "\nstray_writes " << a.stray_writes << "\n";
    for (const auto& [name, v] : a.values) out << "value " << name << " " << v << "\n";
    for (const auto& [name, t] : a.trace) {
        out << "trace " << name << " " << t.calls << " " << t.writes << " " << t.stray_writes << "\n";
    }
    if (a.stopped) {
        const StoppedCall& s = a.stopped_call;
        out << "stopped " << (s.function.empty() ? "-" : s.function) << " " << s.call << " " << s.writes << " "
            << s.stray_writes << " " << s.seconds << "\n";
    }
}

}  // namespace cp
