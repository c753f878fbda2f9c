// Which milestones has the student finished? The viewer decides it by experiment, once at start:
// per milestone, a small fixed test (flavour.cpp's probe_m1 ... probe_m5) is drawn by the
// student's code and by the reference, and the stage counts as the student's when the results
// match, or nearly match (lines may break ties differently, lit pixels may differ by a few
// levels). The untouched skeletons draw nothing or return zeros, so they never match.
//
// A half-written milestone may crash or loop forever. So each probe runs in a child process
// (fork) with a time limit: a crash, a hang or an exception only marks that stage unfinished,
// with the reason, and the viewer falls back to the reference for it.
#pragma once

#include <array>
#include <string>

#include "flavour_api.h"

namespace viewer {

inline constexpr int kStages = 5;  // milestones 1 to 5; index 0 is milestone 1

struct StageResult {
    bool yours = false;  // the student's code matched the reference: the viewer uses it
    std::string detail;  // why, in a few words: "3 of 412 pixels differ", "draws nothing yet", "crashed (...)"
};
using Stages = std::array<StageResult, kStages>;

// What milestone `stage` (1..5) is called on screen: "lines", "triangles", ...
const char* stage_title(int stage);

struct ProbeOptions {
    bool isolate = true;           // run each probe in a child process (false: in this one)
    double timeout_seconds = 5.0;  // per probe, when isolated
};

// Probes the five milestones of `student` against `reference`.
Stages probe_stages(const Flavour& student, const Flavour& reference, const ProbeOptions& options = {});

// Every stage the reference's, with `why` as the detail (the --reference option).
Stages all_reference(const std::string& why);

// The comparisons, exposed for the tests. Images: a pixel differs when a channel differs by
// more than `levels`; the stage matches when no more than `fraction` of the pixels drawn in
// either image differ (and at least 2 may). Numbers: each within 1e-6, relative.
StageResult compare_images(const raster::Image& student, const raster::Image& reference, int levels, double fraction);
StageResult compare_numbers(const std::vector<double>& student, const std::vector<double>& reference);

}  // namespace viewer
