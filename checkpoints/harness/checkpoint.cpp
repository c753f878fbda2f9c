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
    for (const auto& [name, t] : a.trace) {
        out << "trace " << name << " " << t.calls << " " << t.writes << " " << t.stray_writes << "\n";
    }
    if (a.stopped) {
        const StoppedCall& s = a.stopped_call;
        out << "stopped " << (s.function.empty() ? "-" : s.function) << " " << s.call << " " << s.writes << " "
            << s.stray_writes << " " << s.seconds << "\n";
    }
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
        if (key == "trace") {
            FunctionTrace t;
            words >> name >> t.calls >> t.writes >> t.stray_writes;
            a.trace[name] = t;
            continue;
        }
        if (key == "stopped") {
            StoppedCall& s = a.stopped_call;
            words >> s.function >> s.call >> s.writes >> s.stray_writes >> number;
            if (s.function == "-") s.function.clear();
            s.seconds = std::strtod(number.c_str(), nullptr);
            a.stopped = true;
            continue;
        }
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
    long long small_diffs = 0;  // outside the lenient mask, within strict_channel_diff levels
    int first_x = -1, first_y = -1;  // first strict difference, for the message
    raster::Image diff;  // expected dimmed; errors bright red, tolerated differences blue
};

inline constexpr raster::Color kErrorMark{255, 40, 40};
inline constexpr raster::Color kToleratedMark{70, 150, 255};

PolicyCount count_under_policy(const raster::Image& actual, const raster::Image& expected,
                               const Tolerance& tol) {
    PolicyCount pc;
    pc.diff = raster::Image(expected.width(), expected.height());
    for (int y = 0; y < expected.height(); ++y) {
        for (int x = 0; x < expected.width(); ++x) {
            const raster::Color a = actual.at(x, y);
            const raster::Color e = expected.at(x, y);
            const int d = std::max({std::abs(a.r - e.r), std::abs(a.g - e.g), std::abs(a.b - e.b)});
            raster::Color mark{static_cast<std::uint8_t>(e.r / 4), static_cast<std::uint8_t>(e.g / 4),
                               static_cast<std::uint8_t>(e.b / 4)};
            if (d > 0 && tol.lenient.get(x, y)) {
                ++pc.lenient_diffs;
                mark = kToleratedMark;
            } else if (d > tol.strict_channel_diff) {
                if (pc.strict_diffs++ == 0) {
                    pc.first_x = x;
                    pc.first_y = y;
                }
                mark = kErrorMark;
            } else if (d > 0) {
                ++pc.small_diffs;
                mark = kToleratedMark;
            }
            pc.diff.set(x, y, mark);
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

namespace {

const StudentFunction* find_function(const Suite& suite, const std::string& name) {
    for (const StudentFunction& f : suite.functions) {
        if (f.name == name) return &f;
    }
    return nullptr;
}

// "`draw_line` (TODOs 3-4)", or "`draw_line`" when the milestone's table does not name it.
std::string function_label(const Suite& suite, const std::string& name) {
    const StudentFunction* f = find_function(suite, name);
    const std::string todo = f ? todo_label(f->todos) : "";
    return "`" + name + "`" + (todo.empty() ? "" : " (" + todo + ")");
}

std::string finding_todo(const Suite& suite, const Finding& f) {
    if (!f.todo.empty()) return f.todo;
    const auto it = suite.topics.find(f.topic);
    return it == suite.topics.end() ? "" : it->second.todo;
}

std::string finding_hint(const Suite& suite, const Finding& f) {
    if (!f.hint.empty()) return f.hint;
    const auto it = suite.topics.find(f.topic);
    return it == suite.topics.end() ? "" : it->second.hint;
}

// "[topic] (TODO 5) message": how a finding is printed and recorded.
std::string finding_line(const Suite& suite, const Finding& f) {
    const std::string todo = finding_todo(suite, f);
    const bool named = todo.empty() || f.message.find("(" + todo + ")") != std::string::npos;
    return "[" + f.topic + "] " + (named ? "" : "(" + todo + ") ") + f.message;
}

// The finding for a render the watchdog stopped.
Finding stopped_finding(const Suite& suite, const StoppedCall& s) {
    std::ostringstream msg;
    if (s.function.empty()) {
        msg << "the render did not finish within " << s.seconds
            << " s, and none of your functions was running: a loop outside them (report this to your teacher)";
        return {"endless loop", msg.str()};
    }
    const StudentFunction* f = find_function(suite, s.function);
    msg << function_label(suite, s.function) << " was still running after " << s.seconds << " s, in its ";
    if (s.call <= 1) {
        msg << "first call on this scene";
    } else {
        msg << "call number " << s.call << " on this scene (" << s.call - 1 << " earlier call(s) returned)";
    }
    msg << ", having written " << s.writes << " pixel(s) in that call";
    if (s.stray_writes > 0) msg << " and " << s.stray_writes << " outside the image";
    msg << ": most likely an endless loop, so the watchdog stopped it";
    Finding out{f && !f->loop_topic.empty() ? f->loop_topic : "endless loop", msg.str()};
    out.todo = f ? todo_label(f->todos) : "";
    out.hint = f ? f->loop_advice : "";
    return out;
}

// One finding per function that the reference drew with on this scene and the code under test
// called without drawing anything: most often a TODO not written yet.
std::vector<Finding> nothing_drawn_findings(const Suite& suite, const Artifacts& student, const Artifacts& reference) {
    std::vector<std::string> names;  // the milestone's TODO order first, then any other
    for (const StudentFunction& f : suite.functions) names.push_back(f.name);
    for (const auto& [name, t] : reference.trace) {
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
    std::vector<Finding> out;
    for (const std::string& name : names) {
        const auto ref_it = reference.trace.find(name);
        if (ref_it == reference.trace.end()) continue;
        const FunctionTrace& ref = ref_it->second;
        const auto it = student.trace.find(name);
        if (ref.writes == 0 || it == student.trace.end() || it->second.calls == 0 || it->second.writes > 0) continue;
        const StudentFunction* f = find_function(suite, name);
        std::string msg = function_label(suite, name) + " drew nothing" +
                          (it->second.stray_writes > 0 ? " inside the image" : "") + " in " +
                          std::to_string(it->second.calls) + " call(s); the reference draws " +
                          std::to_string(ref.writes) + " pixel(s) with it on this scene";
        Finding finding{"nothing drawn", msg};
        finding.todo = f ? todo_label(f->todos) : "";
        finding.hint = (finding.todo.empty() ? "this TODO" : finding.todo) + " is not written yet (or `" + name +
                       "` returns before drawing anything): fill it in, following its section in the lesson";
        out.push_back(finding);
    }
    return out;
}

}  // namespace

void run_checkpoint(const Suite& suite, const std::string& id) {
    const Mode mode = mode_from_env();
    Record rec;
    rec.id = id;
    rec.milestone = suite.milestone;
    rec.title = suite.title(id);
    rec.order = static_cast<int>(std::find(suite.ids.begin(), suite.ids.end(), id) - suite.ids.begin());
    rec.status = "crashed";  // overwritten below unless the code under test never returns

    // The reference first: its trace says which TODOs the scene needs, which is worth saying
    // even when the code under test then crashes.
    Artifacts reference;
    std::string needs;
    if (mode != Mode::kRender) {
        reference = render_timed(suite.render_reference, id);
        const std::vector<int> todos = needed_todos(suite, reference);
        rec.todos = todo_list(todos);
        if (!todos.empty()) needs = " (needs " + todo_label(todos) + ")";
        write_record(rec);
    }

    // ---- render half ----
    Artifacts student;
    if (mode == Mode::kJudge) {
        student = load_artifacts(id);
    } else {
        // A render that never ends is stopped by the watchdog, which names the function still
        // running. It cannot wait for the stuck code, so it finishes the checkpoint itself.
        const Watchdog watchdog(watchdog_seconds(), [&](const StoppedCall& s) {
            Artifacts stopped;
            stopped.stopped = true;
            stopped.stopped_call = s;
            if (!s.picture.empty()) stopped.images["stopped"] = s.picture;
            if (mode == Mode::kRender) {
                save_artifacts(id, stopped);
            } else {
                Record r = rec;
                const Finding f = stopped_finding(suite, s);
                r.status = "fail";
                r.concepts = f.topic;
                r.findings.push_back(finding_line(suite, f));
                r.hint = f.hint.empty() ? suite.hint(id) : f.hint;
                std::cout << "checkpoint " << id << ": " << rec.title << needs << "\n  what is wrong:\n    "
                          << r.findings.front() << "\n  hint: " << r.hint << "\n";
                if (!s.picture.empty()) {
                    const fs::path out = fs::path(env_or("RASTER_OUTPUT_DIR", "checkpoint_output")) / id;
                    fs::create_directories(out);
                    raster::write_png((out / "stopped.png").string(), s.picture);
                    r.output_dir = fs::absolute(out).string();
                    std::cout << "  picture when stopped: " << fs::absolute(out / "stopped.png").string() << "\n";
                }
                std::cout << "VERDICT " << id << " FAIL concepts=" << r.concepts << "\n";
                write_record(r);
            }
            std::cout << std::flush;
            std::fflush(nullptr);
            std::_Exit(1);
        });
        student = render_timed(suite.render_student, id);
    }
    if (mode == Mode::kRender) {
        save_artifacts(id, student);
        return;
    }

    // ---- judge half: from here on, no code under test runs ----
    Judgement judgement;
    if (student.stopped) {
        judgement.findings.push_back(stopped_finding(suite, student.stopped_call));
    } else {
        judgement = suite.judge(id, student);
    }
    std::vector<Finding>& findings = judgement.findings;
    if (student.values.count(kRunawayKey)) {
        findings.insert(findings.begin(),
                        {"runaway loop", "your code was stopped after " + std::to_string(kStrayWriteBudget) +
                                             " writes outside the image: a loop runs past its end point. "
                                             "Check the step signs and the loop's stop condition"});
    }
    const std::vector<Finding> nothing = nothing_drawn_findings(suite, student, reference);
    findings.insert(findings.begin(), nothing.begin(), nothing.end());

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
    raster::Image policy_diff;  // see count_under_policy
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
            PolicyCount pc = count_under_policy(actual, expected, judgement.tolerance);
            policy_diff = std::move(pc.diff);
            const Tolerance& tol = judgement.tolerance;
            rec.tolerated = pc.lenient_diffs + pc.small_diffs;
            if (rec.tolerated > 0) {
                std::ostringstream t;
                t << rec.tolerated << " pixel(s) differ where the rule allows it (blue in diff.png): ";
                if (pc.small_diffs > 0) {
                    t << pc.small_diffs << " by at most " << tol.strict_channel_diff
                      << " level(s) (rounding and FMA differences)";
                }
                if (pc.lenient_diffs > 0) {
                    t << (pc.small_diffs > 0 ? "; " : "") << pc.lenient_diffs << " of at most "
                      << tol.max_lenient_diffs << " in the ambiguous band"
                      << (tol.why.empty() ? std::string() : ", because " + tol.why);
                }
                rec.tolerated_why = t.str();
                report << "  tolerated: " << rec.tolerated_why << "\n";
            }
            if (pc.strict_diffs > 0) {
                findings.push_back(
                    {"image", std::to_string(pc.strict_diffs) +
                                  " pixel(s) differ from the expected image where every correct "
                                  "implementation agrees; the first is (" +
                                  std::to_string(pc.first_x) + ", " + std::to_string(pc.first_y) +
                                  "). Bright red pixels in diff.png show them all."});
            }
            if (pc.lenient_diffs > judgement.tolerance.max_lenient_diffs) {
                findings.push_back(
                    {"image", std::to_string(pc.lenient_diffs) +
                                  " pixels near edges differ from the expected image; up to " +
                                  std::to_string(judgement.tolerance.max_lenient_diffs) +
                                  " may, because " + judgement.tolerance.why});
            }
        }
    } else if (main_it == student.images.end() && !student.stopped) {
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

    std::cout << "checkpoint " << id << ": " << rec.title << needs << "\n" << report.str();
    rec.measures = judgement.measures;
    for (const auto& [name, v] : judgement.measures) std::cout << "  " << name << ": " << v << "\n";
    std::cout << "  render time: yours " << std::fixed << std::setprecision(3) << rec.student_ms
              << " ms, reference " << rec.reference_ms << " ms\n";
    // Every checkpoint keeps its pictures (the HTML report shows passing ones too); the paths
    // are printed only for a failure.
    const bool failing = !findings.empty();
    {
        const fs::path out = fs::path(env_or("RASTER_OUTPUT_DIR", "checkpoint_output")) / id;
        fs::create_directories(out);
        if (failing) std::cout << "  pictures:\n";
        for (const auto& [name, img] : student.images) {
            const fs::path p = out / ((name == "main" ? std::string("actual") : name) + ".png");
            raster::write_png(p.string(), img);
            if (failing) std::cout << "    " << fs::absolute(p).string() << "\n";
        }
        if (!expected.empty()) {
            raster::write_png((out / "expected.png").string(), expected);
            if (failing) std::cout << "    " << fs::absolute(out / "expected.png").string() << "\n";
            if (main_it != student.images.end()) {
                raster::write_png((out / "diff.png").string(), policy_diff.empty()
                                                                 ? raster::diff_image(main_it->second, expected)
                                                                 : policy_diff);
                if (failing) {
                    std::cout << "    " << fs::absolute(out / "diff.png").string()
                              << "  (red: wrong; blue: differs, but allowed)\n";
                }
            }
        }
        rec.output_dir = fs::absolute(out).string();
    }
    if (failing) {
        std::cout << "  what is wrong:\n";
        const std::size_t shown = std::min<std::size_t>(findings.size(), 8);
        for (std::size_t i = 0; i < shown; ++i) {
            std::cout << "    " << finding_line(suite, findings[i]) << "\n";
        }
        if (findings.size() > shown) {
            std::cout << "    ... and " << findings.size() - shown << " more\n";
        }
        // The hint follows the first finding (the likeliest cause), not the scene: a scene that
        // fails because a TODO it also needs is empty should say so, not hint at its own topic.
        const std::string own = finding_hint(suite, findings.front());
        rec.hint = own.empty() ? suite.hint(id) : own;
        std::cout << "  hint: " << rec.hint << "\n";
        if (!expected.empty() && main_it != student.images.end()) {
            rec.diagnosis = diagnosis_for(suite.milestone, id, main_it->second, expected);
            if (!rec.diagnosis.empty()) std::cout << "  known bug: " << rec.diagnosis << "\n";
        }
        for (const Finding& f : findings) rec.findings.push_back(finding_line(suite, f));
    }
    // One line that tools (and the project's own tests) can match.
    std::cout << "VERDICT " << id << " " << (findings.empty() ? "PASS" : "FAIL")
              << " concepts=" << rec.concepts << "\n"
              << std::flush;
    write_record(rec);

    if (!findings.empty()) {
        FAIL_CHECK("checkpoint " << id << " failed: " << finding_line(suite, findings.front())
                                 << " (all findings above)");
    }
    SUCCEED();
}

}  // namespace cp
