// The checkpoint harness, shared by every milestone.
//
// A checkpoint has two halves:
//  * the RENDER half runs the implementation under test on a scene and returns Artifacts
//    (images and numbers). It is the only part that executes a student's code.
//  * the JUDGE half decides the verdict from the Artifacts, the scene's trusted description
//    and the expected PNG alone.
//
// `make check` runs both halves in one process, so a breakpoint in a student's function is
// hit straight from the checkpoint. For grading, RASTER_CHECKPOINT_MODE=render writes the
// artifacts to RASTER_ARTIFACTS_DIR and stops, and RASTER_CHECKPOINT_MODE=judge reads them
// back without running any student code: the grader runs the first in a sandbox and the
// second in a trusted process, so no verdict depends on code a student wrote.
#pragma once

#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "raster/compare.h"
#include "raster/image.h"

namespace cp {

// What the render half produces.
struct Artifacts {
    std::map<std::string, raster::Image> images;  // "main" is compared with the expected PNG
    std::map<std::string, double> values;         // numbers a scene asks for (clip results...)
    long long stray_writes = 0;  // writes outside any image, summed (see Image::stray_writes)
    double seconds = 0;          // render time of the implementation (best of a few runs)
};

// Render halves give every image this stray-write budget (Image::limit_stray_writes) and,
// when a loop runs past its end and spends it, set values[kRunawayKey] = 1 and keep the
// partial picture; the harness turns that into a finding instead of a hang.
inline constexpr long long kStrayWriteBudget = 1'000'000;
inline constexpr const char* kRunawayKey = "runaway";

// How strictly the main image must match the expected PNG. Pixels outside `lenient` must
// match to within strict_channel_diff levels; pixels inside it may differ, but at most
// max_lenient_diffs of them. `why` says why this policy is fair; it is printed on failure.
struct Tolerance {
    int strict_channel_diff = 0;
    raster::Mask lenient;  // empty mask: every pixel is strict
    long long max_lenient_diffs = 0;
    std::string why;
};

// One thing the judge found wrong, in a student's words. `topic` is a short tag naming the
// idea the student should revisit ("endpoint", "octant", "clipping", ...): the summary table
// shows it, and the project's own tests check that each deliberate bug names its concept.
struct Finding {
    std::string topic;
    std::string message;
};

struct Judgement {
    std::vector<Finding> findings;  // empty: the properties hold
    Tolerance tolerance;            // the policy for comparing "main" with the expected PNG
    // Numbers worth reporting beside the verdict (e.g. the coverage error against the exact
    // area), printed with the checkpoint and kept in its record and the JSON summary.
    std::map<std::string, double> measures;
};

// Everything the harness needs to know about one milestone's checkpoints.
struct Suite {
    std::string milestone;  // "m1"
    std::vector<std::string> ids;
    std::function<std::string(const std::string& id)> title;
    std::function<std::string(const std::string& id)> hint;  // what a failure usually means
    std::function<Artifacts(const std::string& id)> render_student;    // code under test
    std::function<Artifacts(const std::string& id)> render_reference;  // for timing only
    std::function<Judgement(const std::string& id, const Artifacts&)> judge;
};

// Registers one Catch2 test case per checkpoint of the suite (named by its id, tagged with
// the milestone). Call it from a static initializer in the milestone's test file.
bool register_suite(const Suite& suite);

// Runs one checkpoint: render (or read artifacts), judge, compare, report, record.
void run_checkpoint(const Suite& suite, const std::string& id);

// The frame of every render half: makes the main image (with the stray-write budget), runs
// `draw`, turns a spent budget into values[kRunawayKey], sums the stray writes of all images
// and stores the main image as "main". Extra images a scene needs go into out.images.
Artifacts render_guarded(int width, int height,
                         const std::function<void(raster::Image& main, Artifacts& out)>& draw);

// A fresh image for a render half's extra pictures, with the stray-write budget set.
raster::Image guarded_image(int width, int height);

// The judge's first look: the main image if it exists and has the scene's size (otherwise the
// harness reports the problem), and a finding for any stray write.
const raster::Image* main_image_for_judging(const Artifacts& art, int width, int height, Judgement& j,
                                            const std::string& stray_topic, const std::string& stray_advice);

// Finds the scene with the given id in a milestone's list.
template <typename Scene>
const Scene& find_scene(const std::vector<Scene>& all, const std::string& id) {
    for (const Scene& s : all) {
        if (s.id == id) return s;
    }
    throw std::out_of_range("no scene named " + id);
}

// The suite of a milestone whose scenes have id, title and hint: one checkpoint per scene, in
// the scenes' order.
template <typename Scene>
Suite make_suite(std::string milestone, const std::vector<Scene>& (*scenes)(),
                 Artifacts (*render_student)(const std::string&), Artifacts (*render_reference)(const std::string&),
                 Judgement (*judge)(const std::string&, const Artifacts&)) {
    Suite s;
    s.milestone = std::move(milestone);
    for (const Scene& scene : scenes()) s.ids.push_back(scene.id);
    s.title = [scenes](const std::string& id) { return find_scene(scenes(), id).title; };
    s.hint = [scenes](const std::string& id) { return find_scene(scenes(), id).hint; };
    s.render_student = render_student;
    s.render_reference = render_reference;
    s.judge = judge;
    return s;
}

// The value of environment variable `name`, or `fallback` when it is unset or empty.
std::string env_or(const char* name, const std::string& fallback);

// Helpers shared by renderers and judges.
double time_best_of(const std::function<void()>& fn);  // seconds; a few runs for tiny scenes
std::string expected_png_path(const std::string& milestone, const std::string& id);

}  // namespace cp
