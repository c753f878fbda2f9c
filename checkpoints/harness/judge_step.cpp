// The judge step (see verdict.h): pure, shared by `make check` and the grader.
#include "harness/verdict.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <sstream>

#include "harness/diagnosis.h"
#include "harness/judging.h"
#include "raster/io.h"

namespace fs = std::filesystem;

namespace cp {

namespace {

// ---- image comparison under a tolerance policy ----

struct PolicyCount {
    long long strict_diffs = 0;
    long long lenient_diffs = 0;
    long long judged_wrong = 0;  // differing pixels in Tolerance::wrong
    long long small_diffs = 0;  // outside the lenient mask, within strict_channel_diff levels
    int first_x = -1, first_y = -1;  // first strict difference, for the message
    raster::Image diff;  // expected dimmed; errors bright red, tolerated differences blue
    bool over_limit = false;  // more lenient differences than allowed: painted red, not blue
};

inline constexpr raster::Color kErrorMark{255, 40, 40};
inline constexpr raster::Color kToleratedMark{70, 150, 255};

PolicyCount count_under_policy(const raster::Image& actual, const raster::Image& expected,
                               const Tolerance& tol) {
    PolicyCount pc;
    pc.diff = raster::Image(expected.width(), expected.height());
    std::vector<std::size_t> lenient_at;  // where the band's differences are, to repaint them
    for (int y = 0; y < expected.height(); ++y) {
        for (int x = 0; x < expected.width(); ++x) {
            const raster::Color a = actual.at(x, y);
            const raster::Color e = expected.at(x, y);
            const int d = std::max({std::abs(a.r - e.r), std::abs(a.g - e.g), std::abs(a.b - e.b)});
            raster::Color mark{static_cast<std::uint8_t>(e.r / 4), static_cast<std::uint8_t>(e.g / 4),
                               static_cast<std::uint8_t>(e.b / 4)};
            // One rule for every pixel: a difference of at most strict_channel_diff levels is
            // rounding wherever it is; a larger one is allowed only in the lenient band, and
            // only up to max_lenient_diffs of them.
            if (d > 0 && tol.wrong.get(x, y)) {
                ++pc.judged_wrong;  // the judge's findings say why
                mark = kErrorMark;
            } else if (d > tol.strict_channel_diff && tol.lenient.get(x, y)) {
                ++pc.lenient_diffs;
                mark = kToleratedMark;
                lenient_at.push_back(std::size_t(y) * expected.width() + x);
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
    // Over the limit, the band's differences are errors too: red, not "allowed".
    pc.over_limit = pc.lenient_diffs > tol.max_lenient_diffs;
    if (pc.over_limit) {
        for (const std::size_t at : lenient_at) {
            pc.diff.set(int(at % expected.width()), int(at / expected.width()), kErrorMark);
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

// "first call on this scene", "call number 3 on this scene (2 earlier calls returned)".
std::string which_call(long long call) {
    if (call <= 1) return "first call on this scene";
    return "call number " + std::to_string(call) + " on this scene (" + plural(double(call - 1), "earlier call") + " returned)";
}

// The finding for a render the watchdog stopped.
// ", drawing the line from (..) to (..)" when the suite can tell what that call draws.
std::string call_subject(const Suite& suite, const std::string& id, const std::string& function, long long call) {
    if (!suite.describe_call || function.empty()) return "";
    const std::string what = suite.describe_call(id, function, call);
    return what.empty() ? "" : " (drawing " + what + ")";
}

Finding stopped_finding(const Suite& suite, const std::string& id, const StoppedCall& s) {
    std::ostringstream msg;
    if (s.function.empty()) {
        msg << "the render did not finish within " << s.seconds
            << " s, and none of your functions was running: a loop outside them (report this to your teacher)";
        return {"endless loop", msg.str()};
    }
    const StudentFunction* f = find_function(suite, s.function);
    msg << function_label(suite, s.function) << " was still running after " << s.seconds << " s, in its "
        << which_call(s.call) << call_subject(suite, id, s.function, s.call) << ", having written " << plural(double(s.writes), "pixel") << " in that call";
    if (s.stray_writes > 0) msg << " and " << s.stray_writes << " outside the image";
    msg << ": most likely an endless loop, so the watchdog stopped it";
    Finding out{f && !f->loop_topic.empty() ? f->loop_topic : "endless loop", msg.str()};
    out.todo = f ? todo_label(f->todos) : "";
    out.hint = f ? f->loop_advice : "";
    return out;
}

// One finding per function that the reference drew with on this scene and the code under test
// called without drawing anything: most often a TODO not written yet.
// A function in `ran` (Judgement::ran), or one that wrote only outside the image, is said to have
// drawn nothing though it ran, without the "not written yet" hint, in `after`: the judge's own
// findings (the stray writes, the wrong numbers), which say why, come first. The
// functions in `skip` are left out: the one a runaway loop stopped (the runaway finding
// explains it) and those the judge allows to draw nothing (Judgement::may_draw_nothing).
// The lowest TODO number a label names ("TODO 4", "TODOs 2, 4"); 1000 for none.
int lowest_todo(const std::string& label) {
    const std::set<int> todos = todo_numbers(label);
    return todos.empty() ? 1000 : *todos.begin();
}

struct NothingDrawn {
    std::vector<Finding> before, after;
};
NothingDrawn nothing_drawn_findings(const Suite& suite, const Artifacts& student, const Artifacts& reference,
                                    const std::vector<std::string>& ran, const std::vector<std::string>& skip) {
    std::vector<std::string> names;  // the milestone's TODO order first, then any other
    for (const StudentFunction& f : suite.functions) names.push_back(f.name);
    for (const auto& [name, t] : reference.trace) {
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
    NothingDrawn out;
    for (const std::string& name : names) {
        const auto ref_it = reference.trace.find(name);
        if (ref_it == reference.trace.end()) continue;
        const FunctionTrace& ref = ref_it->second;
        const auto it = student.trace.find(name);
        if (ref.writes == 0 || it == student.trace.end() || it->second.calls == 0 || it->second.writes > 0) continue;
        if (std::find(skip.begin(), skip.end(), name) != skip.end()) continue;
        const bool did_run = std::find(ran.begin(), ran.end(), name) != ran.end();
        // Writes outside the image show the code is written too: it computed pixels, all off
        // the image (the judge's stray-write finding says why).
        const bool wrote_outside = it->second.stray_writes > 0;
        const StudentFunction* f = find_function(suite, name);
        std::string msg = function_label(suite, name) + (did_run ? " ran (the work it counted is not zero) but" : "") +
                          " drew nothing" + (wrote_outside ? " inside the image" : "") + " in " +
                          plural(double(it->second.calls), "call") + "; the reference draws " +
                          plural(double(ref.writes), "pixel") + " with it on this scene";
        if (did_run) {
            msg += ", so its TODO is written but what it computed put nothing on screen";
        } else if (wrote_outside) {
            msg += ", and every pixel it asked for (" + plural(double(it->second.stray_writes), "write") +
                   ") was outside the image, so its TODO is written but computes the wrong pixels";
        }
        Finding finding{"nothing drawn", msg};
        finding.todo = f ? todo_label(f->todos) : "";
        if (did_run || wrote_outside) {
            out.after.push_back(finding);
            continue;
        }
        const bool several = finding.todo.rfind("TODOs", 0) == 0;
        finding.hint = (finding.todo.empty() ? "this TODO" : finding.todo) + (several ? " are" : " is") +
                       " not written yet, or `" + name + "` returns before drawing anything (on this scene the "
                       "reference draws at least one pixel with it): fill it in, following its section in the lesson";
        out.before.push_back(finding);
    }
    return out;
}


}  // namespace

bool exceeds_tolerance(const raster::Image& actual, const raster::Image& expected, const Tolerance& tol) {
    if (actual.width() != expected.width() || actual.height() != expected.height()) return true;
    const PolicyCount pc = count_under_policy(actual, expected, tol);
    return pc.strict_diffs > 0 || pc.over_limit;
}

std::map<std::string, double> values_under(const std::map<std::string, double>& all, const std::string& prefix) {
    std::map<std::string, double> out;
    for (auto it = all.lower_bound(prefix); it != all.end() && it->first.rfind(prefix, 0) == 0; ++it) {
        out[it->first.substr(prefix.size())] = it->second;
    }
    return out;
}

Finding fix_first(Finding f, const std::string& checkpoint, const std::string& why, const std::string& hint_tail,
                  bool alone_) {
    const std::string todo = f.todo.empty() ? "that TODO" : f.todo;
    // A numbers checkpoint (m3.matrix_ops) tests its TODO alone; a picture (m3.solid_cube) needs others too.
    const std::string alone = alone_ ? ", which tests it alone; " : ", which checks it; ";
    f.message = "fix " + todo + " first (see " + checkpoint + alone + why + "): " + f.message;
    f.hint = "fix " + todo + " first: " + checkpoint + (alone_ ? " checks it on its own, and " : " checks it, and ") + hint_tail;
    return f;
}

std::uint64_t scene_seed_from_env() {
    const std::string s = env_or("RASTER_SCENE_SEED", "0");
    char* end = nullptr;
    const unsigned long long v = std::strtoull(s.c_str(), &end, 10);
    if (end == s.c_str() || *end != '\0') throw std::invalid_argument("RASTER_SCENE_SEED='" + s + "' is not a number");
    return v;
}

Expected expected_image(const Suite& suite, const std::string& id, std::uint64_t seed, const Artifacts& reference) {
    Expected e;
    if (seed != 0) {
        const auto it = reference.images.find("main");
        if (it != reference.images.end()) {
            e.image = it->second;
        } else {
            e.problem = "the reference drew no main image on this scene variant";
        }
        return e;
    }
    try {
        e.image = raster::read_png(expected_png_path(suite.milestone, id));
    } catch (const raster::ImageIoError& err) {
        e.problem = std::string(err.what()) + " (maintainers: run `make expected` to regenerate it)";
    }
    return e;
}

Record checkpoint_record(const Suite& suite, const std::string& id, const Artifacts& reference) {
    Record rec;
    rec.id = id;
    rec.milestone = suite.milestone;
    rec.title = suite.title(id);
    rec.order = static_cast<int>(std::find(suite.ids.begin(), suite.ids.end(), id) - suite.ids.begin());
    rec.todos = todo_list(needed_todos(suite, reference));
    rec.status = "crashed";  // until a verdict replaces it
    return rec;
}

Finding unreadable_artifacts_finding(const std::string& why) {
    return {"artifacts", "the render's output could not be used: " + why,
            "the render program wrote something other than the pictures and numbers of this scene "
            "(or nothing at all): did your code end the program, print to a file, or crash?"};
}

Artifacts verifiable_part(const Artifacts& student, const Artifacts& reference) {
    Artifacts a = student;
    a.stray_writes = reference.stray_writes;
    for (auto& [name, t] : a.trace) {
        const auto it = reference.trace.find(name);
        t.stray_writes = it == reference.trace.end() ? 0 : it->second.stray_writes;
    }
    a.stopped_call.stray_writes = 0;
    std::erase_if(a.values, [](const auto& kv) { return kv.first == kRunawayKey || kv.first.rfind(kRunawayInKey, 0) == 0; });
    for (auto& [key, value] : a.values) {
        const bool counted = key.find(".stats.") != std::string::npos || key.find("capacity") != std::string::npos ||
                             key.ends_with(".builds");  // milestone 5's sample() counts its own pyramid builds
        if (!counted) continue;
        const auto it = reference.values.find(key);
        if (it != reference.values.end()) value = it->second;
    }
    return a;
}

namespace {

// The judge proper; `diagnose` false skips the known-bug diagnosis (judge_checkpoint's second
// look, which only asks whether anything but the counts fails).
Verdict judge_once(const Suite& suite, const std::string& id, const Artifacts& student, const Artifacts& reference,
                   const Expected& expected_in, bool diagnose) {
    Verdict v;
    Record& rec = v.record;
    rec = checkpoint_record(suite, id, reference);
    if (!rec.todos.empty()) v.needs = " (needs " + todo_label(needed_todos(suite, reference)) + ")";
    const raster::Image& expected = expected_in.image;

    Judgement judgement;
    if (student.stopped) {
        judgement.findings.push_back(stopped_finding(suite, id, student.stopped_call));
    } else {
        judgement = suite.judge(id, student, reference, expected);
    }
    std::vector<Finding>& findings = judgement.findings;
    std::string stopped_function;  // the function the runaway stopped: it drew nothing because it was stopped
    if (student.values.count(kRunawayKey)) {
        std::string where = "your code";
        const auto in = student.values.lower_bound(kRunawayInKey);
        Finding runaway{"runaway loop", ""};
        if (in != student.values.end() && in->first.rfind(kRunawayInKey, 0) == 0) {
            const std::string name = in->first.substr(std::string(kRunawayInKey).size());
            stopped_function = name;
            const long long call = static_cast<long long>(in->second);
            where = function_label(suite, name) + ", in its " + which_call(call) + call_subject(suite, id, name, call) + ",";
            const StudentFunction* f = find_function(suite, name);
            runaway.todo = f ? todo_label(f->todos) : "";
        }
        // A line's loop runs away by stepping the wrong way; a fill's, by an unclamped box.
        const bool line = stopped_function.find("line") != std::string::npos;
        const std::string check = stopped_function.empty() ? "its stop condition (for a line, the step signs; for a fill, the box's "
                                                             "clamping)"
                                  : line ? "its stop condition (the step signs; and an endpoint that is NaN or "
                                           "infinite, which must be rejected before the loop)"
                                         : "(for a fill) whether the box it loops over is clamped to the image";
        runaway.message = where + " was stopped after " + std::to_string(kStrayWriteBudget) +
                          " writes outside the image: a loop runs past its end point. Check the loop's bounds and " + check +
                          ". The calls after that write never ran: a finding below about "
                          "what they compute (nan, \"not drawn\", \"not written yet\") is about code that was not reached";
        findings.insert(findings.begin(), runaway);
    }
    if (!judgement.upstream_failed) {
        std::vector<std::string> skip = judgement.may_draw_nothing;
        if (!stopped_function.empty()) skip.push_back(stopped_function);
        const NothingDrawn nothing = nothing_drawn_findings(suite, student, reference, judgement.ran, skip);
        // The runaway, if any, stays first: it is why the rest of the scene was not drawn. So do
        // the judge's findings that name an earlier TODO than the functions that drew nothing
        // (the skeleton's m2.edge_and_box: snap's TODO 1 before fill_triangle's TODO 4).
        std::size_t at = student.values.count(kRunawayKey) ? 1 : 0;
        int nothing_todo = 1000;
        for (const Finding& f : nothing.before) nothing_todo = std::min(nothing_todo, lowest_todo(f.todo));
        while (at < findings.size() && lowest_todo(findings[at].todo) < nothing_todo) ++at;
        findings.insert(findings.begin() + std::ptrdiff_t(at), nothing.before.begin(), nothing.before.end());
        findings.insert(findings.end(), nothing.after.begin(), nothing.after.end());
    }
    if (!expected_in.problem.empty()) findings.push_back({"setup", expected_in.problem});

    const auto main_it = student.images.find("main");
    std::ostringstream report;
    raster::Image policy_diff;  // see count_under_policy
    if (!expected.empty() && main_it != student.images.end()) {
        const raster::Image& actual = main_it->second;
        const raster::ImageMetrics m = raster::compare(actual, expected);
        rec.student = m;
        rec.has_metrics = true;
        const auto ref_it = reference.images.find("main");
        if (ref_it != reference.images.end()) rec.reference = raster::compare(ref_it->second, expected);
        v.numbers_only = ref_it != reference.images.end() && rec.reference.same_size &&
                         rec.reference.differing_pixels == 0 && m.same_size && m.differing_pixels == 0 &&
                         one_color(expected);
        rec.numbers_only = v.numbers_only;
        if (v.numbers_only) {
            report << "  no picture to compare: this checkpoint judges numbers\n";
        } else {
            report << "  image error (yours vs expected):     " << fmt_metrics(m) << "\n";
            if (ref_it != reference.images.end()) {
                report << "  image error (reference vs expected): " << fmt_metrics(rec.reference) << "\n";
            }
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
            // Differences in the band count as tolerated only while they stay within the limit.
            const long long band = pc.over_limit ? 0 : pc.lenient_diffs;
            rec.tolerated = band + pc.small_diffs;
            if (rec.tolerated > 0) {
                std::ostringstream t;
                t << plural(double(rec.tolerated), "pixel") << (rec.tolerated == 1 ? " differs" : " differ")
                  << " where the rule allows it (blue in diff.png): ";
                if (pc.small_diffs > 0) {
                    t << pc.small_diffs << " by at most " << plural(double(tol.strict_channel_diff), "level")
                      << " (rounding and FMA differences)";
                }
                if (band > 0) {
                    t << (pc.small_diffs > 0 ? "; " : "") << pc.lenient_diffs << " of at most "
                      << tol.max_lenient_diffs << " in the ambiguous band"
                      << (tol.why.empty() ? std::string() : ", because " + tol.why);
                }
                rec.tolerated_why = t.str();
                report << "  tolerated: " << rec.tolerated_why << "\n";
            }
            if (pc.judged_wrong > 0) {
                report << "  judged wrong: " << plural(double(pc.judged_wrong), "pixel")
                       << " where the pixel rules below decide (red in diff.png)\n";
            }
            // An empty picture (one color, where the expected one has more): say so, rather
            // than count its pixels as a rounding question in the ambiguous band.
            const bool empty = one_color(actual) && !one_color(expected) && (pc.strict_diffs > 0 || pc.over_limit);
            if (empty) {
                findings.push_back({"image", "nothing is drawn: the picture is one color, and " +
                                                 plural(double(m.differing_pixels), "pixel") +
                                                 " of the expected image differ from it" +
                                                 (pc.over_limit ? "; none is tolerated: all are red in diff.png" : "")});
            }
            if (pc.strict_diffs > 0 && !empty) {
                findings.push_back(
                    {"image", plural(double(pc.strict_diffs), "pixel") + (pc.strict_diffs == 1 ? " differs" : " differ") +
                                  " from the expected image where every correct "
                                  "implementation agrees; the first is (" +
                                  std::to_string(pc.first_x) + ", " + std::to_string(pc.first_y) +
                                  "). Bright red pixels in diff.png show them all."});
            }
            if (pc.lenient_diffs > tol.max_lenient_diffs && !empty) {
                const std::string by = tol.strict_channel_diff > 0
                                           ? " by more than " + plural(double(tol.strict_channel_diff), "level")
                                           : "";
                findings.push_back({"image", std::to_string(pc.lenient_diffs) +
                                                 " pixels in the ambiguous band differ from the expected image" + by + "; up to " +
                                                 std::to_string(tol.max_lenient_diffs) + " may, because " + tol.why +
                                                 ". Over that limit none is tolerated: all are red in diff.png."});
            }
        }
    } else if (main_it == student.images.end() && !student.stopped) {
        findings.push_back({"setup", "the render produced no main image"});
    }
    v.image_report = report.str();

    rec.student_ms = student.seconds * 1e3;
    rec.reference_ms = reference.seconds * 1e3;
    rec.measures = judgement.measures;
    rec.status = findings.empty() ? "pass" : "fail";
    std::vector<std::string> topics;  // each finding's topic once, in order of appearance
    for (const Finding& f : findings) {
        if (std::find(topics.begin(), topics.end(), f.topic) == topics.end()) {
            topics.push_back(f.topic);
            rec.concepts += (rec.concepts.empty() ? "" : ",") + f.topic;
        }
        rec.findings.push_back(finding_line(suite, f));
    }
    if (!findings.empty()) {
        // The hint follows the first finding (the likeliest cause), not the scene: a scene that
        // fails because a TODO it also needs is empty should say so, not hint at its own topic.
        std::string own = finding_hint(suite, findings.front());
        // "Not written yet" (the only "nothing drawn" finding with a hint of its own) is wrong
        // for a function that is written but returns early on this scene's input, such as a
        // zero-length line: the scene's hint follows, for that case.
        const std::string scene_hint = suite.hint(id);
        if (findings.front().topic == "nothing drawn" && !findings.front().hint.empty() && !scene_hint.empty()) {
            own += ". If that code is written already: " + scene_hint;
        }
        rec.hint = own.empty() ? scene_hint : own;
        if (diagnose && !expected.empty() && main_it != student.images.end()) {
            rec.diagnosis = diagnosis_for(suite.milestone, id, main_it->second, expected, rec.findings);
        }
    }

    // Every checkpoint keeps its pictures (the HTML report shows passing ones too).
    for (const auto& [name, img] : student.images) v.pictures[name == "main" ? "actual" : name] = img;
    for (const auto& [name, img] : judgement.pictures) v.pictures[name] = img;
    if (!expected.empty()) {
        v.pictures["expected"] = expected;
        if (main_it != student.images.end()) {
            v.pictures["diff"] = policy_diff.empty() ? raster::diff_image(main_it->second, expected) : policy_diff;
        }
    }
    v.findings = std::move(findings);
    return v;
}

}  // namespace

Verdict judge_checkpoint(const Suite& suite, const std::string& id, const Artifacts& student,
                         const Artifacts& reference, const Expected& expected) {
    Verdict v = judge_once(suite, id, student, reference, expected, true);
    if (!v.findings.empty() && !student.stopped) {
        v.record.counts_only =
            judge_once(suite, id, verifiable_part(student, reference), reference, expected, false).findings.empty();
    }
    return v;
}

GradedVerdict judge_for_grading(const Suite& suite, const std::string& id, const Artifacts& student,
                                const Artifacts& reference, const Expected& expected) {
    GradedVerdict g{judge_once(suite, id, student, reference, expected, true), std::nullopt};
    if (g.whole.findings.empty()) return g;
    g.graded = judge_once(suite, id, verifiable_part(student, reference), reference, expected, true);
    if (!student.stopped) g.whole.record.counts_only = g.graded->findings.empty();
    return g;
}

std::string picture_caption(const std::string& milestone, const std::string& name) {
    if (name == "diff") return std::string("diff (") + kDiffLegend + ")";
    if (name == "fill_triangle") {
        return "fill_triangle: the " + milestone + ".fill_triangle scene, drawn in this run by your fill_triangle "
               "alone; if it differs from that checkpoint's expected picture, fix fill_triangle first";
    }
    if (name == "error_vs_time") return "error_vs_time: error against run time, yours beside the reference's";
    if (name == "other_winding") {
        return "other_winding: the same triangles, each with its vertices in the other order (the other winding); "
               "it must have the same pixels as your main picture";
    }
    if (name == "count") {
        return "count: how many of your triangles cover each pixel (black none, gray one, red two or more: "
               "a pixel two triangles both take, on a shared edge)";
    }
    return name;
}

void write_pictures(const std::string& dir, Verdict& v) {
    const fs::path out = dir;
    fs::create_directories(out);
    for (const auto& [name, img] : v.pictures) raster::write_png((out / (name + ".png")).string(), img);
    v.record.output_dir = fs::absolute(out).string();
}

void print_verdict(std::ostream& out, const Suite& suite, const Verdict& v) {
    const Record& rec = v.record;
    out << "checkpoint " << rec.id << ": " << rec.title << v.needs << "\n" << v.image_report;
    for (const auto& [name, value] : rec.measures) {
        std::ostringstream text;  // a count as "84", anything else with six significant digits
        if (std::isfinite(value) && value == std::round(value) && std::abs(value) < 1e15) {
            text << static_cast<long long>(value);
        } else {
            text << std::setprecision(6) << value;
        }
        out << "  " << name << ": " << text.str() << "\n";
    }
    out << "  render time: yours " << std::fixed << std::setprecision(3) << rec.student_ms << " ms, reference "
        << rec.reference_ms << " ms\n";
    out.unsetf(std::ios::fixed);
    const bool failing = !v.findings.empty();
    if (failing && !rec.output_dir.empty() && !v.pictures.empty()) {
        // The student's own pictures first, then the expected image and the difference.
        std::vector<std::string> names;
        for (const auto& [name, img] : v.pictures) {
            if (name != "expected" && name != "diff" && !(v.numbers_only && name == "actual")) names.push_back(name);
        }
        for (const char* name : {"expected", "diff"}) {
            if (v.pictures.count(name) && !v.numbers_only) names.push_back(name);
        }
        if (!names.empty()) out << "  pictures:\n";
        for (const std::string& name : names) {
            // fill_triangle.png, beside a picture drawn through the pipeline: say what it is for.
            const std::string note = name == "diff" ? std::string("  (") + kDiffLegend + ")"
                                     : name == "fill_triangle"
                                         ? "  (the " + suite.milestone + ".fill_triangle scene by your fill_triangle alone: if it differs from "
                                           "that checkpoint's expected picture, fix fill_triangle first)"
                                         : std::string();
            out << "    " << (fs::path(rec.output_dir) / (name + ".png")).string() << note << "\n";
        }
    }
    if (failing) {
        out << "  what is wrong:\n";
        const std::size_t shown = std::min<std::size_t>(v.findings.size(), 8);
        for (std::size_t i = 0; i < shown; ++i) out << "    " << finding_line(suite, v.findings[i]) << "\n";
        if (v.findings.size() > shown) out << "    ... and " << v.findings.size() - shown << " more\n";
        out << "  hint: " << rec.hint << "\n";
        if (!rec.diagnosis.empty()) out << "  known bug: " << rec.diagnosis << "\n";
        if (rec.counts_only) out << "  counts only: " << kCountsOnlyNote << "\n";
    }
    // One line that tools (and the project's own tests) can match.
    out << "VERDICT " << rec.id << " " << (failing ? "FAIL" : "PASS") << " concepts=" << rec.concepts << "\n"
        << std::flush;
}

}  // namespace cp
