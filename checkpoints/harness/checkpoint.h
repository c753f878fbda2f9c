// The checkpoint harness, shared by every milestone.
//
// A checkpoint has two halves:
//  * the RENDER half runs the implementation under test on a scene and returns Artifacts
//    (images and numbers). It is the only part that executes a student's code.
//  * the JUDGE half decides the verdict from the Artifacts, the scene's trusted description
//    and the expected PNG alone.
//
// `make check` runs both halves in one process (harness/checkpoint.cpp), so a breakpoint in a
// student's function is hit straight from the checkpoint. The grader runs them apart: a
// render program (harness/render_main.cpp: the student's code, the render half and the render
// side of this harness, nothing else) in a sandbox, one process per checkpoint, and the judge
// (verdict.h) in a trusted process that reads the artifacts as hostile input. Both use the same
// judge step, so no verdict ever depends on code a student wrote.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "raster/compare.h"
#include "raster/image.h"

namespace cp {

// What one function of the code under test did during a render, counted by traced(): how
// often the render half called it, and how many pixels those calls wrote inside the image
// (Image::writes) and tried to write outside it (Image::stray_writes).
struct FunctionTrace {
    long long calls = 0;
    long long writes = 0;
    long long stray_writes = 0;
};

// Set when the watchdog stopped a render that ran too long: the function that was still
// running then (empty when no function of the code under test was running), which of its
// calls that was (1 = the first), and what that call had written so far.
struct StoppedCall {
    std::string function;
    long long call = 0;
    long long writes = 0;
    long long stray_writes = 0;
    double seconds = 0;  // the watchdog's limit, which the render had run past
    raster::Image picture;  // what that call's image held when it was stopped (may be empty)
};

// What the render half produces.
struct Artifacts {
    std::map<std::string, raster::Image> images;  // "main" is compared with the expected PNG
    std::map<std::string, double> values;         // numbers a scene asks for (clip results...)
    long long stray_writes = 0;  // writes outside any image, summed (see Image::stray_writes)
    double seconds = 0;          // render time of the implementation (best of a few runs)
    // Per function of the code under test (by name, e.g. "draw_line"): see traced().
    std::map<std::string, FunctionTrace, std::less<>> trace;
    bool stopped = false;  // the watchdog stopped the render; then stopped_call says where
    StoppedCall stopped_call;
};

// Render halves give every image this stray-write budget (Image::limit_stray_writes) and,
// when a loop runs past its end and spends it, set values[kRunawayKey] = 1 and keep the
// partial picture; the harness turns that into a finding instead of a hang.
inline constexpr long long kStrayWriteBudget = 1'000'000;
inline constexpr const char* kRunawayKey = "runaway";
// values[kRunawayInKey + function] = which call of that function (1 = its first on the scene)
// was running when the budget ran out; set by traced(), innermost call first.
inline constexpr const char* kRunawayInKey = "runaway.in.";

// What a checkpoint that fails only on the counts of the student's own program says (console,
// summary and report): why `make check` fails it though its pictures are right, and what a
// grader does with it.
inline constexpr const char* kCountsOnlyNote =
    "your pictures and answers are right; what fails is numbers your own code counted (how much "
    "work each stage did, memory kept, writes outside the image). They are the lesson's rules, so "
    "make check fails the checkpoint; a grader cannot trust numbers a program reports about "
    "itself, so there these findings are advice and cost no points.";

// Every difference picture of the project (make check's diff.png, the HTML reports, the lessons'
// troubleshooting galleries) uses these colors, and this legend is printed beside each one.
inline constexpr raster::Color kDiffWrong{255, 40, 40};     // differs where it must not
inline constexpr raster::Color kDiffAllowed{70, 150, 255};  // differs where the rule allows it
inline constexpr const char* kDiffLegend =
    "red: differs where it must not; blue: differs, but within what the rule allows; dimmed: as expected";

// How strictly the main image must match the expected PNG. Pixels outside `lenient` must
// match to within strict_channel_diff levels; pixels inside it may differ, but at most
// max_lenient_diffs of them. `why` says why this policy is fair; it is printed on failure.
struct Tolerance {
    int strict_channel_diff = 0;
    raster::Mask lenient;  // empty mask: every pixel is strict
    long long max_lenient_diffs = 0;
    std::string why;
    // Pixels the judge's own pixel rules found wrong (a lenient pixel it judged and rejected):
    // red in diff.png, never counted as tolerated. They fail through the judge's findings.
    raster::Mask wrong;
};

// Whether `actual` fails `expected` under the tolerance: the judge step's own rule, for the
// milestone judges that must know before the verdict whether a picture would fail.
bool exceeds_tolerance(const raster::Image& actual, const raster::Image& expected, const Tolerance& tol);

// The values whose names start with `prefix`, the prefix taken off: the numbers a render half
// stored for one prerequisite (under "pre<group>.").
std::map<std::string, double> values_under(const std::map<std::string, double>& all, const std::string& prefix);

// One thing the judge found wrong, in a student's words. `topic` is a short tag naming the
// idea the student should revisit ("endpoint", "octant", "clipping", ...): the summary table
// shows it, and the project's own tests check that each deliberate bug names its concept.
//
// `hint` and `todo` are optional. A finding that knows what the student should do about it
// (e.g. "this TODO is not written yet") says so in `hint`; one that knows which TODO is at
// fault says so in `todo` ("TODO 5", "TODOs 3-4"). Without them the harness looks the topic
// up in Suite::topics, and only then falls back to the scene's hint.
struct Finding {
    std::string topic;
    std::string message;
    std::string hint = {};
    std::string todo = {};
};

// A prerequisite's own finding, told to the checkpoint that depends on it: "fix TODO N first
// (see <checkpoint>, which tests it alone; <why>): <its message>", with a hint ending in
// `hint_tail`. `alone` false: <checkpoint> is a picture that needs other TODOs too ("which
// checks it").
Finding fix_first(Finding f, const std::string& checkpoint, const std::string& why, const std::string& hint_tail,
                  bool alone = true);

struct Judgement {
    std::vector<Finding> findings;  // empty: the properties hold
    Tolerance tolerance;            // the policy for comparing "main" with the expected PNG
    // Numbers worth reporting beside the verdict (e.g. the coverage error against the exact
    // area), printed with the checkpoint and kept in its record and the JSON summary.
    std::map<std::string, double> measures;
    // Pictures the judge made from the artifacts (e.g. a chart of error against run time),
    // shown beside the checkpoint's own pictures in every report.
    std::map<std::string, raster::Image> pictures;
    // The judge found that a TODO this scene is drawn with fails the checks of its own
    // checkpoint, and said "fix TODO N first (see <checkpoint>)". Every other guess about the
    // picture rests on that TODO, so the harness adds none of its own (no "drew nothing: TODO
    // 11 is not written yet" when the matrices put every vertex off screen).
    bool upstream_failed = false;
    // Functions of the code under test that drew nothing on this scene though the judge knows
    // they ran (the work they counted is not zero: m3's draw_model transformed and clipped,
    // then every edge was clipped away). The harness then does not say "not written yet".
    std::vector<std::string> ran = {};
    // Functions that may draw nothing on this scene though the reference draws with them: the
    // rule does not say which pixels they light here (m1.extreme_far's lines from 1e300 away,
    // which no double arithmetic places to the pixel). No "drew nothing" finding for them.
    std::vector<std::string> may_draw_nothing = {};
};

// One function a student writes, as the checkpoints see it: its name (as the render half
// passes it to traced()), the TODO numbers that implement it, the functions it calls in the
// lesson's design (their TODOs are needed too), and what the watchdog says when this function
// never returns: the concept tag and the usual cause.
struct StudentFunction {
    std::string name;
    std::vector<int> todos;
    std::vector<std::string> uses = {};
    std::string loop_topic = {};   // default: "endless loop"
    std::string loop_advice = {};  // e.g. "check that NaN input returns false"
};

// Advice for every finding with a given topic, when the finding carries none of its own.
struct TopicAdvice {
    std::string todo;  // "TODO 3", or empty
    std::string hint;  // empty: no topic-wide hint
};

// Everything the harness needs to know about one milestone's checkpoints.
struct Suite {
    std::string milestone;  // "m1"
    std::vector<std::string> ids;
    std::function<std::string(const std::string& id)> title;
    std::function<std::string(const std::string& id)> hint;  // what a failure usually means
    std::function<Artifacts(const std::string& id)> render_student;    // code under test
    std::function<Artifacts(const std::string& id)> render_reference;  // for timing only
    // The judge: a pure function of the scene (by id, under the current variant), the student's
    // artifacts, the reference's artifacts on the same scene and the expected image. It runs no
    // code under test and reads no file.
    std::function<Judgement(const std::string& id, const Artifacts& student, const Artifacts& reference,
                            const raster::Image& expected)>
        judge;
    // Scene variants for grading: use_variant(seed) replaces every scene of the milestone by a
    // variant derived from (seed, scene id); seed 0 restores the public scenes. Null: the
    // milestone has no variants. See RASTER_SCENE_SEED.
    std::function<void(std::uint64_t seed)> use_variant;
    std::vector<StudentFunction> functions;    // the milestone's TODO table (see traced())
    std::map<std::string, TopicAdvice> topics;  // per-finding advice, by topic
    // Optional: what the n-th call (from 1) of a function draws on a scene, such as "the line
    // from (2.5, 3.5) to (40.5, 9.5)", for the watchdog's and the runaway's findings; empty
    // when the judge side cannot tell. A pure function of the scene, like the judge.
    std::function<std::string(const std::string& id, const std::string& function, long long call)> describe_call;
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

// Pieces of the render halves that draw panels through a pipeline (milestones 4 and 5).
// The values `numbers` stores, each put into out.values under prefix + its key (a picture's
// prerequisite groups under "pre<group>.").
void record_under(Artifacts& out, const std::string& prefix,
                  const std::function<void(std::map<std::string, double>& values)>& numbers);
// The fill_triangle scene (width x height) that a scene drawn through the pipeline also draws:
// `draw` renders it into a fresh guarded image with artifacts of its own, whose values go into
// out.values under fill_key ("fill_triangle."), whose stray writes add to out's, and whose
// picture becomes the image named fill_key without its final dot.
void record_fill_scene(Artifacts& out, const std::string& fill_key, int width, int height,
                       const std::function<void(raster::Image& img, Artifacts& scratch)>& draw);
// Seconds `draw` takes: best of a few runs when `best_of` (a panel timed on its own), else one.
double seconds_of(const std::function<void()>& draw, bool best_of);
// A panel's frame, drawn to be w x h, into the rectangle (x0, y0, w, h) of img, its stray
// writes counted; a frame of another size (the code under test replaced its image) is not
// copied and sets values[key + ".resized"] = 1.
void place_panel(Artifacts& out, const std::string& key, const raster::Image& frame, raster::Image& img, int x0,
                 int y0, int w, int h);

// ---- attribution: which function of the code under test drew what ----
//
// The render half wraps EVERY call into the code under test:
//     cp::traced(out, "draw_line", img, [&] { m1::draw_line(img, a, b, c); });
//     const bool kept = cp::traced(out, "clip_line", [&] { return m1::clip_line(a, b, r); });
// Each call adds 1 to out.trace[name].calls and the writes it made into `img` (if given) to
// out.trace[name].writes and .stray_writes, also when the call throws (StrayWriteLimit). While
// the call runs, it is "the function currently running" that the watchdog names.
class TracedCall {
public:
    TracedCall(Artifacts& out, std::string_view function, const raster::Image* img);
    ~TracedCall();
    TracedCall(const TracedCall&) = delete;
    TracedCall& operator=(const TracedCall&) = delete;

private:
    Artifacts* out_;
    FunctionTrace* entry_;
    const std::string* name_;
    const raster::Image* img_;
    long long writes0_ = 0, strays0_ = 0;
    int uncaught0_ = 0;  // std::uncaught_exceptions() at the call: more at its end means it threw
};

template <typename Fn>
decltype(auto) traced(Artifacts& out, std::string_view function, const raster::Image& img, Fn&& fn) {
    TracedCall call(out, function, &img);
    return std::forward<Fn>(fn)();
}

template <typename Fn>
decltype(auto) traced(Artifacts& out, std::string_view function, Fn&& fn) {
    TracedCall call(out, function, nullptr);
    return std::forward<Fn>(fn)();
}

// Stops a render that runs too long. While a Watchdog lives, a thread waits `seconds`; if the
// Watchdog is still alive then, it calls on_stop with the function currently running (see
// traced()) and what it has done. on_stop must end the process (std::_Exit): the stuck code
// cannot be interrupted. Seconds come from RASTER_WATCHDOG_SECONDS (default 5), below CTest's
// time-out, so a checkpoint that hangs fails with a message naming the function.
class Watchdog {
public:
    Watchdog(double seconds, std::function<void(const StoppedCall&)> on_stop);
    ~Watchdog();
    Watchdog(const Watchdog&) = delete;
    Watchdog& operator=(const Watchdog&) = delete;

private:
    struct State;
    std::unique_ptr<State> state_;
};
inline constexpr double kDefaultWatchdogSeconds = 5;  // make check's, unless the build sets another
double watchdog_seconds();  // RASTER_WATCHDOG_SECONDS, default kDefaultWatchdogSeconds

// "1-4, 6" for {1, 2, 3, 4, 6}; "TODO 5" / "TODOs 3-4" with todo_label.
std::string todo_list(std::vector<int> todos);
std::string todo_label(const std::vector<int>& todos);
std::string todo_label(const std::string& list);  // "TODO 1" for "1", "TODOs 1-4, 6" for "1-4, 6"

// The TODOs a scene needs: those of every function the reference called on it (calls > 0),
// and of the functions those use, transitively.
std::vector<int> needed_todos(const Suite& suite, const Artifacts& reference);

// True when every pixel of `img` has the color of the first (an empty image is not).
bool one_color(const raster::Image& img);

// A fresh image for a render half's extra pictures, with the stray-write budget set.
raster::Image guarded_image(int width, int height);

// The judge's first look: the main image if it exists and has the scene's size (otherwise the
// harness reports the problem), with the tolerance masks made to that size.
const raster::Image* main_image_for_judging(const Artifacts& art, int width, int height, Judgement& j);

// The findings for writes outside the image (Image::stray_writes): one for each function of the
// trace that made some, as `per_function(name, count)` words it (the judge knows each function's
// usual cause and TODO), and, for writes no traced function made, `unattributed` with "your code
// asked to write N pixels outside the image (Image::stray_writes): " before its message. None
// without stray writes.
using StrayFinding = std::function<Finding(const std::string& function, long long count)>;
std::vector<Finding> stray_write_findings(const Artifacts& art, const StrayFinding& per_function,
                                          const Finding& unattributed);

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
                 Judgement (*judge)(const std::string&, const Artifacts&, const Artifacts&, const raster::Image&),
                 std::vector<StudentFunction> functions = {}, std::map<std::string, TopicAdvice> topics = {},
                 void (*use_variant)(std::uint64_t) = nullptr) {
    Suite s;
    s.milestone = std::move(milestone);
    for (const Scene& scene : scenes()) s.ids.push_back(scene.id);
    s.title = [scenes](const std::string& id) { return find_scene(scenes(), id).title; };
    s.hint = [scenes](const std::string& id) { return find_scene(scenes(), id).hint; };
    s.render_student = render_student;
    s.render_reference = render_reference;
    s.judge = judge;
    s.functions = std::move(functions);
    s.topics = std::move(topics);
    if (use_variant) s.use_variant = use_variant;
    return s;
}

// ---- artifacts on disk: a render program's output, read back by the trusted judge ----
// Writes `a` into `dir`: one PNG per image (<name>.png) and values.txt (numbers, trace,
// stopped call).
void save_artifacts(const std::string& dir, const Artifacts& a);

// What a judge accepts from a render program: these image names at these sizes, each file at
// most max_file_bytes.
struct ArtifactRules {
    std::map<std::string, std::pair<int, int>> images;  // name -> (width, height)
    std::size_t max_file_bytes = 16u << 20;
};
struct ArtifactError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
// Reads artifacts written by a render program, treating everything in `dir` as hostile: only
// the file names the rules know are opened, never through a symbolic link, only if they are
// plain files within the size cap (FIFOs and devices are refused without blocking), and a PNG
// only if its header has the expected size. Other files are ignored. Throws ArtifactError
// saying what was wrong; a missing values.txt is an error, a missing image is not (the judge
// reports it).
Artifacts read_artifacts(const std::string& dir, const ArtifactRules& rules);
// The rules for a scene, from the reference's artifacts on it: its image names and sizes, and
// "stopped" (the watchdog's picture) at the size of any of them.
ArtifactRules rules_from_reference(const Artifacts& reference);

// The value of environment variable `name`, or `fallback` when it is unset or empty.
std::string env_or(const char* name, const std::string& fallback);

// Helpers shared by renderers and judges.
double time_best_of(const std::function<void()>& fn, int min_runs = 1);  // seconds; a few runs for tiny scenes
std::string expected_png_path(const std::string& milestone, const std::string& id);

}  // namespace cp
