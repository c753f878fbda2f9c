// The checkpoints as Catch2 test cases (`make check`): render with the student's code and the
// reference in this process, then the shared judge step (verdict.h) and its reporters.
#include "harness/checkpoint.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "raster_catch.h"

#include "harness/record.h"
#include "harness/verdict.h"

namespace fs = std::filesystem;

namespace cp {

namespace {

Artifacts render_timed(const std::function<Artifacts(const std::string&)>& render,
                       const std::string& id) {
    Artifacts a;
    const double seconds = time_best_of([&] { a = render(id); });
    a.seconds = seconds;
    return a;
}

// Every registered checkpoint, by its test case's name (its id).
std::map<std::string, std::pair<const Suite*, std::string>>& registered() {
    static std::map<std::string, std::pair<const Suite*, std::string>> by_name;
    return by_name;
}

// The body of every checkpoint's test case: REGISTER_TEST_CASE (Catch2 2 and 3 alike) takes a
// plain function, so the checkpoint is found by the name of the test case that is running.
void run_registered_checkpoint() {
    const auto found = registered().find(raster_test::current_test_name());
    if (found == registered().end()) throw std::logic_error("no checkpoint registered under this name");
    run_checkpoint(*found->second.first, found->second.second);
}

}  // namespace

bool register_suite(const Suite& suite) {
    static std::vector<std::unique_ptr<Suite>> suites;  // the registry points into these
    suites.push_back(std::make_unique<Suite>(suite));
    const Suite* kept = suites.back().get();
    const std::string tags = "[" + kept->milestone + "]";
    for (const std::string& id : kept->ids) {
        if (!registered().emplace(id, std::make_pair(kept, id)).second)
            throw std::logic_error("checkpoint " + id + " is registered twice");
        REGISTER_TEST_CASE(run_registered_checkpoint, id, tags);
    }
    return true;
}

void run_checkpoint(const Suite& suite, const std::string& id) {
    // A scene variant (grading's seeds, the project's fairness tests): every scene of the
    // milestone is replaced before anything is drawn, for the reference and the student alike.
    const std::uint64_t seed = scene_seed_from_env();
    if (seed != 0) {
        if (!suite.use_variant) throw std::runtime_error(suite.milestone + " has no scene variants");
        suite.use_variant(seed);
    }
    const std::string output_dir = (fs::path(env_or("RASTER_OUTPUT_DIR", "checkpoint_output")) / id).string();

    // The reference first: its trace says which TODOs the scene needs, which is worth saying
    // even when the code under test then crashes (the record says "crashed" until replaced).
    const Artifacts reference = render_timed(suite.render_reference, id);
    const Expected expected = expected_image(suite, id, seed, reference);
    write_record(checkpoint_record(suite, id, reference));

    // A render that never ends is stopped by the watchdog, which names the function still
    // running. It cannot wait for the stuck code, so it finishes the checkpoint itself.
    Artifacts student;
    {
        const Watchdog watchdog(watchdog_seconds(), [&](const StoppedCall& s) {
            Artifacts stopped;
            stopped.stopped = true;
            stopped.stopped_call = s;
            if (!s.picture.empty()) stopped.images["stopped"] = s.picture;
            Verdict v = judge_checkpoint(suite, id, stopped, reference, expected);
            write_pictures(output_dir, v);
            print_verdict(std::cout, suite, v);
            write_record(v.record);
            std::fflush(nullptr);
            std::_Exit(1);
        });
        student = render_timed(suite.render_student, id);
    }

    // ---- judge: from here on, no code under test runs ----
    Verdict v = judge_checkpoint(suite, id, student, reference, expected);
    write_pictures(output_dir, v);
    print_verdict(std::cout, suite, v);
    write_record(v.record);
    if (!v.findings.empty()) {
        FAIL_CHECK("checkpoint " << id << " failed: " << v.record.findings.front() << " (all findings above)");
    }
    SUCCEED();
}

}  // namespace cp
