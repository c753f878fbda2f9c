// One checkpoint's result as the summary sees it: written by every checkpoint process into
// RASTER_RESULTS_DIR (one small file per checkpoint, so parallel ctest runs never share a
// file), read back by the summary tool that prints the error-against-time table.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "raster/compare.h"

namespace cp {

struct Record {
    std::string id, milestone, title;
    int order = 0;  // position in its milestone's list: the order of the lesson
    std::string status;    // pass, fail, or crashed (the process never finished the checkpoint)
    std::string concepts;  // comma-separated concept tags of the findings
    bool has_metrics = false;
    bool numbers_only = false;  // a checkpoint of numbers: no picture to show (see Verdict)
    raster::ImageMetrics student, reference;  // each against the expected image
    double student_ms = 0, reference_ms = 0;
    std::string output_dir;  // where the failure pictures are
    std::map<std::string, double> measures;  // see Judgement::measures
    std::vector<std::string> findings;       // "[topic] message", as printed
    std::string hint;
    long long tolerated = 0;    // pixels that differ from the expected image where the rule allows it
    std::string tolerated_why;  // how many of which kind, and why that is fair
    std::string diagnosis;  // "your picture matches what happens ..." (see diagnosis.h), or empty
    std::string todos;  // the TODOs the scene needs, e.g. "1-4, 6" (see cp::needed_todos)
    // A failing checkpoint whose pictures and answers are right: only numbers the student's own
    // program counted (stage counts, buffer capacities, writes outside the image) made it fail.
    // `make check` fails it; a grader shows those findings as advice (see verifiable_part).
    bool counts_only = false;
};

void write_record(const Record& r);  // into $RASTER_RESULTS_DIR (default: checkpoint_results)
std::vector<Record> read_records(const std::string& dir);  // sorted by milestone, then order

}  // namespace cp
