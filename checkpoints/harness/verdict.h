// The judge step and its reporters.
//
// judge_checkpoint() is THE judge of every checkpoint: a pure function from the scene (by id,
// under the current scene variant), the student's artifacts, the reference's artifacts on the
// same scene and the expected image, to a Verdict. It runs no code under test, reads and
// writes no file and prints nothing. `make check` (one process, harness/checkpoint.cpp) and the
// grader (a trusted process fed with artifacts from a sandbox, checkpoints/grader.cpp) both
// call it, so a student sees locally exactly the verdict a grader would give on those pictures.
//
// The reporters turn a Verdict into the console text, the pictures of the HTML report and the
// record the summary reads; the grader adds its own (results.json, its HTML page).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "harness/checkpoint.h"
#include "harness/record.h"
#include "raster/image.h"

namespace cp {

struct Verdict {
    Record record;                  // status "pass"/"fail", concepts, finding lines, metrics, times...
    std::vector<Finding> findings;  // empty: pass
    std::string image_report;       // the "image error ..." and "tolerated: ..." lines, for the console
    std::string needs;              // " (needs TODOs 1-4)", or empty
    // A checkpoint of numbers: its expected picture is one flat color, and the reference's and
    // the student's main images match it exactly. The console then shows no image lines and
    // no blank pictures (the findings are the whole verdict).
    bool numbers_only = false;
    // The pictures worth keeping, by file stem: "actual" (the main image), each extra image
    // under its own name ("reversed", "stopped"...), "expected" and "diff".
    std::map<std::string, raster::Image> pictures;
};

// The expected image of a checkpoint: the committed PNG for the public scenes (seed 0); for a
// scene variant (seed != 0) the reference's own main image, rendered on the trusted side.
// `problem` says why there is none (empty image).
struct Expected {
    raster::Image image;
    std::string problem;
};
Expected expected_image(const Suite& suite, const std::string& id, std::uint64_t seed, const Artifacts& reference);

// A failing verdict whose findings all come from numbers only the render process counts about
// itself has record.counts_only set (the judge runs again on verifiable_part to know).
Verdict judge_checkpoint(const Suite& suite, const std::string& id, const Artifacts& student,
                         const Artifacts& reference, const Expected& expected);

// The grader's two verdicts from one call: `whole` is judge_checkpoint's; `graded` is the verdict,
// with its diagnosis, on verifiable_part, judged only when `whole` fails (when it passes there is
// nothing the counts alone could have failed, and `graded` is empty: grade `whole`).
struct GradedVerdict {
    Verdict whole;
    std::optional<Verdict> graded;
};
GradedVerdict judge_for_grading(const Suite& suite, const std::string& id, const Artifacts& student,
                                const Artifacts& reference, const Expected& expected);

// What of the student's artifacts the trusted side can check (tools/grading/README.md, "What the
// render reports about itself"): the pictures and the answers, not the numbers that only the
// render process itself measures. Those (writes outside the image, the runaway flag, milestones
// 4 and 5's stage counts, the pyramid builds milestone 5's sample() counts through its pointer,
// milestone 4's buffer capacities) are replaced by the reference's. The grader grades this part;
// what only the whole artifacts' verdict said is advice there, for no points.
Artifacts verifiable_part(const Artifacts& student, const Artifacts& reference);

// A checkpoint's record before any verdict: id, milestone, title, order, the TODOs the scene
// needs (from the reference's trace), status "crashed".
Record checkpoint_record(const Suite& suite, const std::string& id, const Artifacts& reference);

// The finding for artifacts that could not be read (see read_artifacts): the checkpoint fails.
Finding unreadable_artifacts_finding(const std::string& why);

// ---- reporters ----
// The console text of a checkpoint, ending with the line tools match:
// "VERDICT <id> PASS|FAIL concepts=<topics>". Picture paths are printed for a failure when the
// pictures were written (record.output_dir set).
void print_verdict(std::ostream& out, const Suite& suite, const Verdict& v);
// The caption of a picture in the HTML reports, by file stem, for a checkpoint of `milestone`
// ("m5"): what the picture is when its name does not say ("diff" with its legend, the
// "fill_triangle" that a pipeline scene also draws, the "error_vs_time" chart), else the name.
std::string picture_caption(const std::string& milestone, const std::string& name);
// Writes every picture into `dir` (created) and sets v.record.output_dir to its absolute path.
void write_pictures(const std::string& dir, Verdict& v);

// The scene seed of this process: RASTER_SCENE_SEED, 0 (the public scenes) when unset.
std::uint64_t scene_seed_from_env();

}  // namespace cp
