#include "harness/checkpoint.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include <catch2/catch.hpp>

#include "harness/diagnosis.h"
#include "harness/record.h"
#include "raster/io.h"
#include "raster/timer.h"

namespace fs = std::filesystem;

namespace cp {

namespace {

enum class Mode { kAll, kRender, kJudge };

Mode mode_from_env() {
    const std::string m = env_or("RASTER_CHECKPOINT_MODE", "all");
    if (m == "render") return Mode::kRender;
    if (m == "judge") return Mode::kJudge;
    if (m != "all") {
        std::cerr << "RASTER_CHECKPOINT_MODE='" << m << "' is not one of all, render, judge\n";
        std::exit(2);
    }
    return Mode::kAll;
}

// ---- artifacts on disk (render half -> judge half) ----

fs::path artifacts_dir(const std::string& id) {
    return fs::path(env_or("RASTER_ARTIFACTS_DIR", "checkpoint_artifacts")) / id;
}

void save_artifacts(const std::string& id, const Artifacts& a) {
    const fs::path dir = artifacts_dir(id);
    fs::create_directories(dir);
    for (const auto& [name, img] : a.images) raster::write_png((dir / (name + ".png")).string(), img);
    std::ofstream out(dir / "values.txt");
    out << std::setprecision(17);
    out << "seconds " << a.seconds << "\nstray_writes " << a.stray_writes << "\n";
    for (const auto& [name, v] : a.values) out << "value " << name << " " << v << "\n";
}

Artifacts load_artifacts(const std::string& id) {
    const fs::path dir = artifacts_dir(id);
    Artifacts a;
    std::ifstream in(dir / "values.txt");
    if (!in) throw std::runtime_error("no artifacts for " + id + " in " + dir.string());
    // Line by line, numbers through strtod: a student's code may well produce NaN or
    // infinity, which operator>> refuses (and would end the reading there).
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string key, name, number;
        words >> key;
        if (key == "value") words >> name;
        words >> number;
        const double v = std::strtod(number.c_str(), nullptr);
        if (key == "seconds") {
            a.seconds = v;
        } else if (key == "stray_writes") {
            a.stray_writes = static_cast<long long>(v);
        } else if (key == "value") {
            a.values[name] = v;
        }
    }
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().extension() == ".png") {
            a.images[entry.path().stem().string()] = raster::read_png(entry.path().string());
        }
    }
    return a;
}

Artifacts render_timed(const std::function<Artifacts(const std::string&)>& render,
                       const std::string& id) {
    Artifacts a;
    const double seconds = time_best_of([&] { a = render(id); });
    a.seconds = seconds;
    return a;
}

// ---- image comparison under a tolerance policy ----

struct PolicyCount {
    long long strict_diffs = 0;
    long long lenient_diffs = 0;
    int first_x = -1, first_y = -1;  // first strict difference, for the message
};

PolicyCount count_under_policy(const raster::Image& actual, const raster::Image& expected,
                               const Tolerance& tol) {
    PolicyCount pc;
    for (int y = 0; y < expected.height(); ++y) {
        for (int x = 0; x < expected.width(); ++x) {
            const raster::Color a = actual.at(x, y);
            const raster::Color e = expected.at(x, y);
            const int d = std::max({std::abs(a.r - e.r), std::abs(a.g - e.g), std::abs(a.b - e.b)});
            if (tol.lenient.get(x, y)) {
                pc.lenient_diffs += d > 0;
            } else if (d > tol.strict_channel_diff) {
                if (pc.strict_diffs++ == 0) {
                    pc.first_x = x;
                    pc.first_y = y;
                }
            }
        }
    }
    return pc;
}

std::string fmt_metrics(const raster::ImageMetrics& m) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(3) << m.differing_pixels << " pixels differ ("
      << 100 * m.differing_share << "%), max channel diff " << m.max_channel_diff
      << ", mean abs error " << m.mean_abs_error << ", PSNR ";
    if (std::isinf(m.psnr_db)) {
        s << "inf";
    } else {
        s << std::setprecision(1) << m.psnr_db << " dB";
    }
    return s.str();
}

class CheckpointInvoker : public Catch::ITestInvoker {
public:
    CheckpointInvoker(const Suite* suite, std::string id) : suite_(suite), id_(std::move(id)) {}
    void invoke() const override { run_checkpoint(*suite_, id_); }

private:
    const Suite* suite_;
    std::string id_;
};

}  // namespace

bool register_suite(const Suite& suite) {
    static std::vector<std::unique_ptr<Suite>> suites;  // test cases point into these
    suites.push_back(std::make_unique<Suite>(suite));
    const Suite* kept = suites.back().get();
    const std::string tags = "[" + kept->milestone + "]";
    for (const std::string& id : kept->ids) {
        Catch::getMutableRegistryHub().registerTest(Catch::makeTestCase(
            new CheckpointInvoker(kept, id), "", Catch::NameAndTags{id, tags}, CATCH_INTERNAL_LINEINFO));
    }
    return true;
}

void run_checkpoint(const Suite& suite, const std::string& id) {
    const Mode mode = mode_from_env();
    Record rec;
    rec.id = id;
    rec.milestone = suite.milestone;
    rec.title = suite.title(id);
    rec.order = static_cast<int>(std::find(suite.ids.begin(), suite.ids.end(), id) - suite.ids.begin());
    rec.status = "crashed";  // overwritten below unless the code under test never returns
    if (mode != Mode::kRender) write_record(rec);

    // ---- render half ----
    Artifacts student;
    if (mode == Mode::kJudge) {
        student = load_artifacts(id);
    } else {
        student = render_timed(suite.render_student, id);
    }
    if (mode == Mode::kRender) {
        save_artifacts(id, student);
        return;
    }

    // ---- judge half: from here on, no code under test runs ----
    const Artifacts reference = render_timed(suite.render_reference, id);
    Judgement judgement = suite.judge(id, student);
    std::vector<Finding>& findings = judgement.findings;
    if (student.values.count(kRunawayKey)) {
        findings.insert(findings.begin(),
                        {"runaway loop", "your code was stopped after " + std::to_string(kStrayWriteBudget) +
                                             " writes outside the image: a loop runs past its end point. "
                                             "Check the step signs and the loop's stop condition"});
    }

    const auto main_it = student.images.find("main");
    const std::string expected_path = expected_png_path(suite.milestone, id);
    raster::Image expected;
    try {
        expected = raster::read_png(expected_path);
    } catch (const raster::ImageIoError& e) {
        findings.push_back({"setup", std::string(e.what()) +
                                         " (maintainers: run `make expected` to regenerate it)"});
    }

    std::ostringstream report;
    if (!expected.empty() && main_it != student.images.end()) {
        const raster::Image& actual = main_it->second;
        const raster::ImageMetrics m = raster::compare(actual, expected);
        rec.student = m;
        rec.has_metrics = true;
        report << "  image error (yours vs expected):     " << fmt_metrics(m) << "\n";
        const auto ref_it = reference.images.find("main");
        if (ref_it != reference.images.end()) {
            rec.reference = raster::compare(ref_it->second, expected);
            report << "  image error (reference vs expected): " << fmt_metrics(rec.reference) << "\n";
        }
        if (!m.same_size) {
            findings.push_back({"image", "the image is " + std::to_string(actual.width()) + "x" +
                                             std::to_string(actual.height()) + ", expected " +
                                             std::to_string(expected.width()) + "x" +
                                             std::to_string(expected.height())});
        } else {
            const PolicyCount pc = count_under_policy(actual, expected, judgement.tolerance);
            if (pc.strict_diffs > 0) {
                findings.push_back(
                    {"image", std::to_string(pc.strict_diffs) +
                                  " pixel(s) differ from the expected image where every correct "
                                  "implementation agrees; the first is (" +
                                  std::to_string(pc.first_x) + ", " + std::to_string(pc.first_y) +
                                  "). Red pixels in diff.png show them all."});
            }
            if (pc.lenient_diffs > judgement.tolerance.max_lenient_diffs) {
                findings.push_back(
                    {"image", std::to_string(pc.lenient_diffs) +
                                  " pixels near edges differ from the expected image; up to " +
                                  std::to_string(judgement.tolerance.max_lenient_diffs) +
                                  " may, because " + judgement.tolerance.why});
            }
        }
    } else if (main_it == student.images.end()) {
        findings.push_back({"setup", "the render produced no main image"});
    }

    rec.student_ms = student.seconds * 1e3;
    rec.reference_ms = reference.seconds * 1e3;
    rec.status = findings.empty() ? "pass" : "fail";
    std::vector<std::string> topics;  // each finding's topic once, in order of appearance
    for (const Finding& f : findings) {
        if (std::find(topics.begin(), topics.end(), f.topic) == topics.end()) {
            topics.push_back(f.topic);
            rec.concepts += (rec.concepts.empty() ? "" : ",") + f.topic;
        }
    }

    std::cout << "checkpoint " << id << ": " << rec.title << "\n" << report.str();
    rec.measures = judgement.measures;
    for (const auto& [name, v] : judgement.measures) std::cout << "  " << name << ": " << v << "\n";
    std::cout << "  render time: yours " << std::fixed << std::setprecision(3) << rec.student_ms
              << " ms, reference " << rec.reference_ms << " ms\n";
    if (!findings.empty()) {
        const fs::path out = fs::path(env_or("RASTER_OUTPUT_DIR", "checkpoint_output")) / id;
        fs::create_directories(out);
        std::cout << "  pictures:\n";
        for (const auto& [name, img] : student.images) {
            const fs::path p = out / ((name == "main" ? std::string("actual") : name) + ".png");
            raster::write_png(p.string(), img);
            std::cout << "    " << fs::absolute(p).string() << "\n";
        }
        if (!expected.empty()) {
            raster::write_png((out / "expected.png").string(), expected);
            std::cout << "    " << fs::absolute(out / "expected.png").string() << "\n";
            if (main_it != student.images.end()) {
                raster::write_png((out / "diff.png").string(), raster::diff_image(main_it->second, expected));
                std::cout << "    " << fs::absolute(out / "diff.png").string()
                          << "  (red: differs from expected)\n";
            }
        }
        rec.output_dir = fs::absolute(out).string();
        std::cout << "  what is wrong:\n";
        const std::size_t shown = std::min<std::size_t>(findings.size(), 8);
        for (std::size_t i = 0; i < shown; ++i) {
            std::cout << "    [" << findings[i].topic << "] " << findings[i].message << "\n";
        }
        if (findings.size() > shown) {
            std::cout << "    ... and " << findings.size() - shown << " more\n";
        }
        std::cout << "  hint: " << suite.hint(id) << "\n";
        if (!expected.empty() && main_it != student.images.end()) {
            rec.diagnosis = diagnosis_for(suite.milestone, id, main_it->second, expected);
            if (!rec.diagnosis.empty()) std::cout << "  known bug: " << rec.diagnosis << "\n";
        }
        rec.hint = suite.hint(id);
        for (const Finding& f : findings) rec.findings.push_back("[" + f.topic + "] " + f.message);
    }
    // One line that tools (and the project's own tests) can match.
    std::cout << "VERDICT " << id << " " << (findings.empty() ? "PASS" : "FAIL")
              << " concepts=" << rec.concepts << "\n"
              << std::flush;
    write_record(rec);

    if (!findings.empty()) {
        FAIL_CHECK("checkpoint " << id << " failed: [" << findings.front().topic << "] "
                                 << findings.front().message << " (all findings above)");
    }
    SUCCEED();
}

}  // namespace cp
