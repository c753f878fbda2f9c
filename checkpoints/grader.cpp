// raster_grade: the trusted half of grading. It links the scenes, the reference and the judges
// of every milestone, and never a student's code. tools/grading/grade drives it; see the
// instructor section of README.md.
//
//   raster_grade ids <m>
//       The checkpoint ids of milestone <m>, one per line, from the trusted scene table (the
//       grader and `make check`'s test discovery use this; no student code runs for it).
//   raster_grade judge <m> <scene-id> <seed> <artifacts-dir> <out-dir> [--status FILE]
//                      [--name NAME] [--title TITLE]
//       Renders the reference on the scene (variant <seed>; 0 = public), reads the render
//       program's artifacts from <artifacts-dir> as hostile input, judges them with the same
//       judge step as `make check`, and writes <out-dir>/verdict.json and the pictures.
//       --status is sandbox-run's status file of the render: a render that crashed, timed out
//       or exited non-zero fails with that said. --name is the checkpoint's name in the
//       results (hidden checkpoints have their own); --title replaces the scene's title.
//   raster_grade rubric-files <rubric.json>
//       Per milestone: its folder and the files students edit, which the grader takes.
//   raster_grade plan <rubric.json> <m> <seed> [hidden.json]
//       The checkpoints to grade (public and hidden) with their scenes, seeds and points.
//   raster_grade report <grading-dir> <rubric.json> <out-dir> [--name NAME]
//       From the verdicts under <grading-dir> (<m>/verdicts/<name>/verdict.json, and
//       <m>/compile.status and compile.log) writes <out-dir>/results.json (Gradescope's
//       format) and <out-dir>/report.html (self-contained: pictures inline).
//   raster_grade class <out-dir> <results.json>...
//       The class view of many gradings: <out-dir>/class.csv (points per milestone and per
//       checkpoint: a row "(maximum)", then a row per submission) and <out-dir>/class.html
//       (which checkpoints the class fails most, with the concept named; unbuilt milestones
//       left out).
#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/checkpoint.h"
#include "harness/html.h"
#include "harness/verdict.h"
#include "m1/functions.h"
#include "m1/judge.h"
#include "m1/render.h"
#include "m1/scenes.h"
#include "m2/functions.h"
#include "m2/judge.h"
#include "m2/render.h"
#include "m2/scenes.h"
#include "m3/functions.h"
#include "m3/judge.h"
#include "m3/render.h"
#include "m3/scenes.h"
#include "m4/functions.h"
#include "m4/judge.h"
#include "m4/render.h"
#include "m4/scenes.h"
#include "m5/functions.h"
#include "m5/judge.h"
#include "m5/render.h"
#include "m5/scenes.h"
#include "raster/io.h"

namespace fs = std::filesystem;
using cp::html_escape;
using nlohmann::json;

namespace {

// Writes a whole file, or throws: a disk that is full (or any write error of the grader's own)
// must end the grading as a failure to retry, never leave a truncated verdict or results.json.
// The file is written next to its place and renamed over it only when complete.
void write_file_checked(const fs::path& path, const std::string& text) {
    const fs::path tmp = path.string() + ".part";
    {
        std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
        f << text;
        f.flush();
        if (!f) {
            std::error_code ignored;
            fs::remove(tmp, ignored);
            throw std::runtime_error("cannot write " + path.string() + " (is the disk full?)");
        }
    }
    fs::rename(tmp, path);
}

// The milestones as the judge sees them: no render_student (no student code is linked here).
const std::vector<cp::Suite>& suites() {
    static const std::vector<cp::Suite> all = {
        [] {
            cp::Suite m1 = cp::make_suite("m1", m1cp::scenes, nullptr, m1cp::reference::render, m1cp::judge,
                                          m1cp::functions(), {}, m1cp::use_variant);
            m1.describe_call = m1cp::describe_call;  // as checkpoints_m1.cpp: the same findings
            return m1;
        }(),
        cp::make_suite("m2", m2cp::scenes, nullptr, m2cp::reference::render, m2cp::judge, m2cp::functions(), {},
                       m2cp::use_variant),
        cp::make_suite("m3", m3cp::scenes, nullptr, m3cp::reference::render, m3cp::judge, m3cp::functions(),
                       m3cp::topics(), m3cp::use_variant),
        cp::make_suite("m4", m4cp::scenes, nullptr, m4cp::reference::render, m4cp::judge, m4cp::functions(),
                       m4cp::topics(), m4cp::use_variant),
        cp::make_suite("m5", m5cp::scenes, nullptr, m5cp::reference::render, m5cp::judge, m5cp::functions(),
                       m5cp::topics(), m5cp::use_variant),
    };
    return all;
}

const cp::Suite& suite(const std::string& m) {
    for (const cp::Suite& s : suites()) {
        if (s.milestone == m) return s;
    }
    throw std::invalid_argument("no milestone " + m);
}

std::string read_text(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// sandbox-run's status file: key=value lines.
std::map<std::string, std::string> read_status(const fs::path& p) {
    std::map<std::string, std::string> kv;
    std::istringstream in(read_text(p));
    std::string line;
    while (std::getline(in, line)) {
        const auto eq = line.find('=');
        if (eq != std::string::npos) kv[line.substr(0, eq)] = line.substr(eq + 1);
    }
    return kv;
}

std::string signal_name(int sig) {
    switch (sig) {
        case 4: return "SIGILL (illegal instruction)";
        case 6: return "SIGABRT (abort: a failed assertion or an uncaught exception)";
        case 8: return "SIGFPE (integer division by zero)";
        case 9: return "SIGKILL (a hard limit: CPU time or memory)";
        case 11: return "SIGSEGV (segmentation fault: a bad pointer or an index out of range)";
        case 24: return "SIGXCPU (the CPU-time limit)";
        case 25: return "SIGXFSZ (the file-size limit)";
        default: return "signal " + std::to_string(sig);
    }
}

// The finding for a render that did not end normally, or none.
std::optional<cp::Finding> render_status_finding(const std::map<std::string, std::string>& st) {
    const std::string result = st.count("result") ? st.at("result") : "missing";
    const int exit = st.count("exit") ? std::atoi(st.at("exit").c_str()) : -1;
    if (result == "exited" && exit == 0) return std::nullopt;
    if (result == "timeout") {
        return cp::Finding{"time limit", "the render did not finish within the time limit and was killed",
                           "an endless loop that the checkpoint's watchdog could not stop: does a loop of yours "
                           "depend on input that never changes (NaN, a step of 0)?"};
    }
    if (result == "exited" && exit > 128) {
        return cp::Finding{"crash", "the render program was ended by " + signal_name(exit - 128),
                           "run this checkpoint with `make check` on your machine, under a debugger or with the "
                           "sanitizers (cmake -DRASTER_SANITIZE=ON), to see where"};
    }
    if (result == "exited") {
        return cp::Finding{"crash", "the render program exited with status " + std::to_string(exit) +
                                        " instead of finishing the scene",
                           "your code must not end the program (exit(), abort(), an uncaught exception)"};
    }
    return cp::Finding{"crash", "the render program could not be run (" + result + ")", ""};
}

json metrics_json(const raster::ImageMetrics& m) {
    return {{"differing_pixels", m.differing_pixels},
            {"differing_share", m.differing_share},
            {"max_channel_diff", m.max_channel_diff},
            {"mean_abs_error", m.mean_abs_error},
            {"psnr_db", std::isfinite(m.psnr_db) ? json(m.psnr_db) : json(nullptr)}};
}

int cmd_ids(const std::string& m) {
    for (const std::string& id : suite(m).ids) std::cout << id << "\n";
    return 0;
}

int cmd_judge(const std::vector<std::string>& args) {
    if (args.size() < 5) throw std::invalid_argument("judge needs <m> <scene-id> <seed> <artifacts-dir> <out-dir>");
    const std::string m = args[0], id = args[1];
    const std::uint64_t seed = std::stoull(args[2]);
    const fs::path artifacts_dir = args[3], out = args[4];
    std::string status_file, name = id, title;
    for (std::size_t i = 5; i + 1 < args.size(); i += 2) {
        if (args[i] == "--status") status_file = args[i + 1];
        else if (args[i] == "--name") name = args[i + 1];
        else if (args[i] == "--title") title = args[i + 1];
        else throw std::invalid_argument("unknown option " + args[i]);
    }
    const cp::Suite& s = suite(m);
    if (seed != 0) s.use_variant(seed);
    if (std::find(s.ids.begin(), s.ids.end(), id) == s.ids.end()) throw std::invalid_argument("no checkpoint " + id);
    fs::remove_all(out);
    fs::create_directories(out);

    cp::Artifacts reference;
    const double ref_seconds = cp::time_best_of([&] { reference = s.render_reference(id); });
    reference.seconds = ref_seconds;
    const cp::Expected expected = cp::expected_image(s, id, seed, reference);

    // The student's artifacts: only what the scene can produce, as hostile input.
    std::vector<cp::Finding> early;
    bool unreadable = false;  // then judging the empty artifacts adds nothing but echoes of it
    cp::Artifacts student;
    std::map<std::string, std::string> status;
    if (!status_file.empty()) {
        status = read_status(status_file);
        if (auto f = render_status_finding(status)) early.push_back(*f);
    }
    try {
        student = cp::read_artifacts(artifacts_dir.string(), cp::rules_from_reference(reference));
    } catch (const cp::ArtifactError& e) {
        // Told once: after a crash or a timeout the missing output is that failure's echo, and
        // judging none would only report every value the program never wrote ("gave nan").
        if (early.empty()) early.push_back(cp::unreadable_artifacts_finding(e.what()));
        unreadable = true;
        student = cp::Artifacts{};
    }
    // Nothing was timed where the render failed or the watchdog stopped it.
    const bool render_failed = !early.empty() || student.stopped;
    // Graded: the verdict on what the trusted side can check; what only the counts said is advice.
    // (When the render itself failed, that is the verdict and the whole one is kept below.)
    cp::GradedVerdict judged = cp::judge_for_grading(s, id, student, reference, expected);
    cp::Verdict v = std::move(judged.whole);
    std::vector<std::string> advice;
    if (early.empty() && judged.graded) {
        const auto& kept = judged.graded->record.findings;
        for (const std::string& f : v.record.findings) {
            if (std::find(kept.begin(), kept.end(), f) == kept.end()) advice.push_back(f);
        }
        v = std::move(*judged.graded);
    }
    if (!early.empty()) {
        // The render itself failed: that is the verdict, whatever its output looks like. Output
        // that could not be read is judged as none, and what that judgement says ("the render
        // produced no main image") is the same cause again: only the reason it was unreadable stays.
        if (unreadable) {
            v.findings.clear();
            v.record.findings.clear();
            v.record.concepts.clear();
        }
        v.findings.insert(v.findings.begin(), early.begin(), early.end());
        std::vector<std::string> lines;
        for (const cp::Finding& f : early) lines.push_back("[" + f.topic + "] " + f.message);
        v.record.findings.insert(v.record.findings.begin(), lines.begin(), lines.end());
        v.record.status = "fail";
        std::string concepts;
        for (const cp::Finding& f : early) concepts += (concepts.empty() ? "" : ",") + f.topic;
        v.record.concepts = concepts + (v.record.concepts.empty() ? "" : "," + v.record.concepts);
        if (!early.front().hint.empty()) v.record.hint = early.front().hint;
    }
    cp::write_pictures(out.string(), v);
    const cp::Record& r = v.record;
    std::vector<std::string> concepts;
    std::istringstream cs(r.concepts);
    for (std::string c; std::getline(cs, c, ',');) {
        if (!c.empty()) concepts.push_back(c);
    }
    json j = {{"milestone", m},
              {"name", name},
              {"scene", id},
              {"seed", seed},
              {"title", title.empty() ? r.title : title},
              {"order", r.order},
              {"status", r.status},
              {"concepts", concepts},
              {"findings", r.findings},
              {"hint", r.hint},
              {"diagnosis", r.diagnosis},
              {"todos", r.todos},
              {"student_ms", r.student_ms},
              {"render_failed", render_failed},  // then student_ms timed nothing
              {"reference_ms", r.reference_ms},
              {"tolerated", r.tolerated},
              {"tolerated_why", r.tolerated_why},
              {"has_metrics", r.has_metrics},
              {"numbers_only", r.numbers_only},
              {"student", metrics_json(r.student)},
              {"reference", metrics_json(r.reference)},
              {"measures", r.measures},
              {"render", status},
              {"advice", advice}};
    std::vector<std::string> pictures;
    for (const auto& [pname, img] : v.pictures) pictures.push_back(pname);
    j["pictures"] = pictures;
    write_file_checked(out / "verdict.json", j.dump(1) + "\n");
    std::cout << "VERDICT " << name << " " << (r.status == "pass" ? "PASS" : "FAIL") << " concepts=" << r.concepts
              << "\n";
    return 0;
}

// ---- the rubric ----

struct Part {
    std::vector<std::string> topics;
    double points = 0;
    std::string what;
};

struct MilestoneRubric {
    std::string folder;
    std::vector<std::string> files;
    double default_points = 1;
    std::map<std::string, double> points;
    std::vector<Part> parts;
};

std::map<std::string, MilestoneRubric> read_rubric(const fs::path& p) {
    const json j = json::parse(read_text(p));
    std::map<std::string, MilestoneRubric> out;
    for (const auto& [m, jm] : j.at("milestones").items()) {
        MilestoneRubric r;
        r.folder = jm.at("folder").get<std::string>();
        r.files = jm.at("files").get<std::vector<std::string>>();
        r.default_points = jm.value("default_points", 1.0);
        if (jm.contains("points")) r.points = jm.at("points").get<std::map<std::string, double>>();
        if (jm.contains("partial")) {
            for (const json& jp : jm.at("partial")) {
                r.parts.push_back({jp.at("topics").get<std::vector<std::string>>(), jp.at("points").get<double>(),
                                   jp.value("what", std::string())});
            }
        }
        out[m] = r;
    }
    return out;
}

double max_points(const MilestoneRubric& r, const std::string& name, const json& verdict) {
    if (verdict.contains("points")) return verdict.at("points").get<double>();
    const auto it = r.points.find(name);
    return it == r.points.end() ? r.default_points : it->second;
}

std::string points_text(double p) {
    std::ostringstream s;
    s << std::setprecision(4) << p << (p == 1 ? " point" : " points");
    return s.str();
}

// Points earned: all on a pass; on a failure, when every concept that failed belongs to a
// partial-credit part (an independent property of the checkpoint), the maximum less those
// parts' points; otherwise 0. No verdict at all: 0.
double earned(const MilestoneRubric& r, double max, const json& verdict, std::string& why) {
    if (verdict.value("status", std::string()) == "pass") return max;
    const auto concepts = verdict.value("concepts", std::vector<std::string>{});
    if (concepts.empty()) return 0;
    double lost = 0;
    std::set<const Part*> used;
    for (const std::string& c : concepts) {
        const Part* part = nullptr;
        for (const Part& p : r.parts) {
            if (std::find(p.topics.begin(), p.topics.end(), c) != p.topics.end()) part = &p;
        }
        if (part == nullptr) return 0;
        if (used.insert(part).second) {
            lost += part->points;
            why += (why.empty() ? "" : "; ") + std::string("partial credit: lost ") + points_text(part->points) +
                   " for " + (part->what.empty() ? c : part->what);
        }
    }
    return std::max(0.0, max - lost);
}

std::string fmt_points(double p) {
    std::ostringstream s;
    s << std::setprecision(4) << p;
    return s.str();
}


std::string join(const std::vector<std::string>& parts, const std::string& sep) {
    std::string out;
    for (const std::string& p : parts) out += (out.empty() ? "" : sep) + p;
    return out;
}

std::string base64(const std::string& bytes) {
    static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const unsigned n = (static_cast<unsigned char>(bytes[i]) << 16) |
                           (static_cast<unsigned char>(bytes[i + 1]) << 8) | static_cast<unsigned char>(bytes[i + 2]);
        out += {k[n >> 18], k[(n >> 12) & 63], k[(n >> 6) & 63], k[n & 63]};
    }
    if (i + 1 == bytes.size()) {
        const unsigned n = static_cast<unsigned char>(bytes[i]) << 16;
        out += {k[n >> 18], k[(n >> 12) & 63], '=', '='};
    } else if (i + 2 == bytes.size()) {
        const unsigned n = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8);
        out += {k[n >> 18], k[(n >> 12) & 63], k[(n >> 6) & 63], '='};
    }
    return out;
}

const char* kStyle = R"(<style>
body{font-family:system-ui,sans-serif;margin:1.5em;max-width:70em;color:#222}
table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:.25em .5em;text-align:left}
.pass{color:#186a1e}.fail{color:#a51d1d}.error{color:#a51d1d;font-weight:bold}
section{border-top:1px solid #ddd;margin-top:1.2em;padding-top:.6em}
figure{display:inline-block;margin:.3em .6em .3em 0;vertical-align:top}figcaption{font-size:.85em;color:#555}
img{image-rendering:pixelated;border:1px solid #999}
pre{background:#f5f5f5;padding:.6em;white-space:pre-wrap;max-height:24em;overflow:auto}
</style>)";


// One checkpoint's text for Gradescope's `output` and the HTML page.
std::string checkpoint_output(const json& v, const std::string& why) {
    std::ostringstream o;
    o << v.value("title", std::string()) << "\n";
    if (v.value("status", std::string()) == "pass") {
        o << "passed";
    } else {
        o << "what is wrong:\n";
        for (const std::string& f : v.value("findings", std::vector<std::string>{})) o << "  " << f << "\n";
        const std::string hint = v.value("hint", std::string());
        if (!hint.empty()) o << "hint: " << hint << "\n";
        const std::string diag = v.value("diagnosis", std::string());
        if (!diag.empty()) o << "known bug: " << diag << "\n";
    }
    const auto advice = v.value("advice", std::vector<std::string>{});
    if (!advice.empty()) {
        o << "\nadvice (not graded: counted inside your own program, which the grader cannot check):\n";
        for (const std::string& a : advice) o << "  " << a << "\n";
    }
    if (!why.empty()) o << "\n" << why;
    if (v.contains("student_ms")) {  // (nothing was timed where nothing was built)
        o << std::fixed << std::setprecision(3) << "\nrender time: yours ";
        if (v.value("render_failed", false)) {
            o << "none (the render did not finish)";
        } else {
            o << v.value("student_ms", 0.0) << " ms";
        }
        o << ", reference " << v.value("reference_ms", 0.0) << " ms";
    }
    if (v.value("numbers_only", false)) {
        o << "\nno picture to compare: this checkpoint judges numbers";
    } else if (v.value("has_metrics", false)) {
        const long long differing = v["student"].value("differing_pixels", 0LL);
        o << "\nimage error: " << differing << (differing == 1 ? " pixel differs" : " pixels differ") << ", mean abs error "
          << v["student"].value("mean_abs_error", 0.0);
    }
    return o.str();
}

int cmd_report(const std::vector<std::string>& args) {
    if (args.size() < 3) throw std::invalid_argument("report needs <grading-dir> <rubric.json> <out-dir>");
    const fs::path dir = args[0], out = args[2];
    const auto rubric = read_rubric(args[1]);
    std::string name = "submission", seed;
    for (std::size_t i = 3; i + 1 < args.size(); i += 2) {
        if (args[i] == "--name") name = args[i + 1];
        else if (args[i] == "--seed") seed = args[i + 1];
        else throw std::invalid_argument("unknown option " + args[i]);
    }
    fs::create_directories(out);
    json tests = json::array();
    double score = 0, total = 0;
    std::ostringstream html, rows, sections, passing, notes;
    std::map<std::string, std::pair<double, double>> per_milestone;  // earned, max (visible only)
    int hidden_count = 0;
    for (const auto& [m, r] : rubric) {
        const fs::path mdir = dir / m;
        if (!fs::is_directory(mdir)) continue;
        const auto compile = read_status(mdir / "compile.status");
        const bool compiled = compile.count("result") && compile.at("result") == "exited" && compile.at("exit") == "0";
        std::string compile_log = read_text(mdir / "compile.log");
        // A file the grader could not find is not the compiler's verdict: say which it is.
        const std::string not_built = compile_log.rfind("The submission has no", 0) == 0     ? "missing file"
                                      : compile_log.rfind("Refused before linking", 0) == 0 ? "code refused"
                                                                                            : "compile error";
        if (compile_log.size() > 20000) compile_log = compile_log.substr(0, 20000) + "\n[... cut]";
        // Which file was graded where the submission has several of its name (the grader's own
        // words, from its private folder).
        std::string layout = read_text(mdir / "layout.txt");
        if (layout.size() > 4000) layout = layout.substr(0, 4000) + "\n[... cut]\n";
        // The trusted list of checkpoints this milestone was graded on (written by the grader
        // from `raster_grade ids` and the hidden ones): a missing verdict scores 0.
        std::istringstream list(read_text(mdir / "checkpoints.txt"));
        std::string line;
        while (std::getline(list, line)) {
            std::istringstream words(line);
            std::string cname, visibility;
            double listed_points = -1;
            words >> cname >> visibility >> listed_points;
            if (cname.empty()) continue;
            json v;
            const fs::path vf = mdir / "verdicts" / cname / "verdict.json";
            try {
                if (fs::is_regular_file(vf)) v = json::parse(read_text(vf));
            } catch (const json::exception&) {
                v = json{};
            }
            if (!v.is_object() || !v.contains("status")) {
                v = {{"status", "error"},
                     {"title", cname},
                     {"findings", {compiled ? "[grader] no verdict for this checkpoint" :
                                              not_built == "missing file"
                                              ? "[missing file] the grader found no file of this milestone to build: see the test \"" + m + " compiles\""
                                              : "[compile] your code did not compile: see the compile log"}}};
            }
            const double max = listed_points >= 0 ? listed_points : max_points(r, cname, v);
            std::string why;
            const double got = earned(r, max, v, why);
            score += got;
            total += max;
            const bool is_hidden = visibility == "after_published";
            if (is_hidden) {
                hidden_count += 1;
            } else {  // the visible summary says nothing about hidden checkpoints
                per_milestone[m].first += got;
                per_milestone[m].second += max;
            }
            std::string output = checkpoint_output(v, why);
            // The same name as the test that holds the reason, and as its section in report.html.
            if (!compiled) output = not_built + ": the reason is in \"" + m + " compiles\"\n" + output;
            const bool hidden = is_hidden;
            tests.push_back({{"name", m + " " + cname},
                             {"score", got},
                             {"max_score", max},
                             {"status", got >= max ? "passed" : "failed"},
                             {"output", output},
                             {"visibility", hidden ? "after_published" : "visible"}});
            const std::string status = v.value("status", std::string("error"));
            // A milestone that was not built has one section, its reason (below), which its
            // checkpoints' rows link to: not a box per checkpoint repeating it.
            rows << "<tr><td><a href=\"#" << html_escape(compiled ? m + "-" + cname : m + "-compile") << "\">" << html_escape(cname)
                 << (hidden ? " (hidden)" : "") << "</a></td><td class=\"" << (status == "pass" ? "pass" : "fail") << "\">" << html_escape(status)
                 << "</td><td>" << fmt_points(got) << " / " << fmt_points(max) << "</td><td>"
                 << html_escape(join(v.value("concepts", std::vector<std::string>{}), ", ")) << "</td><td>"
                 << std::fixed << std::setprecision(3);
            if (!compiled) {
                rows << "&mdash;</td><td>&mdash;";  // nothing of this milestone ran
            } else {
                if (v.value("render_failed", false)) {
                    rows << "&mdash;";  // the render did not finish: nothing was timed
                } else {
                    rows << v.value("student_ms", 0.0);
                }
                rows << "</td><td>" << v.value("reference_ms", 0.0);
            }
            rows << "</td><td>"
                 << (v.value("has_metrics", false) && !v.value("numbers_only", false)
                         ? std::to_string(v["student"].value("differing_pixels", 0LL)) +
                               // a passing picture's differences are all within the rule's tolerance
                               (status == "pass" && v["student"].value("differing_pixels", 0LL) > 0 ? " (allowed)" : "")
                         : "")
                 << "</td></tr>\n";
            rows.unsetf(std::ios::fixed);
            if (!compiled) continue;
            // Sections of checkpoints that lost points first, then the full-marks ones.
            std::ostringstream& sec = got >= max ? passing : sections;
            sec << "<section id=\"" << html_escape(m + "-" + cname) << "\"><h3>" << html_escape(m + " " + cname)
                     << (hidden ? " (hidden)" : "") << ": " << fmt_points(got) << " / " << fmt_points(max)
                     << "</h3><pre>" << html_escape(output) << "</pre>\n";
            // The student's main picture first, then its other pictures, the expected image and
            // the difference. A checkpoint of numbers has no picture of its own: its blank canvas,
            // expected image and diff are left out, and a note says why.
            const bool numbers_only = v.value("numbers_only", false);
            if (numbers_only) sec << cp::kNumbersOnlyNote;
            const auto listed = v.value("pictures", std::vector<std::string>{});
            std::vector<std::string> pics;
            auto take = [&](auto keep) {
                for (const std::string& p : listed) {
                    if (keep(p)) pics.push_back(p);
                }
            };
            if (!numbers_only) take([](const std::string& p) { return p == "actual"; });
            // A picture of another checkpoint's scene drawn by the student's fill_triangle alone
            // ("fill_triangle", milestone 4's "shared_edges") tells a wrong fill_triangle from a
            // wrong caller: of no use where this scene passes or where that checkpoint passed.
            auto other_scene_passed = [&](const std::string& p) {
                json o;
                try {
                    const fs::path of = mdir / "verdicts" / p / "verdict.json";
                    if (fs::is_regular_file(of)) o = json::parse(read_text(of));
                } catch (const json::exception&) {
                    return false;
                }
                return o.is_object() && o.value("status", std::string()) == "pass";
            };
            take([&](const std::string& p) {
                const bool other_scene = p == "fill_triangle" || p == "shared_edges";
                return p != "actual" && p != "expected" && p != "diff" &&
                       !(other_scene && (status == "pass" || other_scene_passed(p)));
            });
            if (!numbers_only) {
                take([](const std::string& p) { return p == "expected"; });
                take([](const std::string& p) { return p == "diff"; });
            }
            for (const std::string& pic : pics) {
                // Only names the judge wrote, from its own folder.
                const fs::path pf = mdir / "verdicts" / cname / (pic + ".png");
                if (pic.find('/') != std::string::npos || !fs::is_regular_file(pf)) continue;
                // Pictures a whole multiple of their size (so no pixel is dropped), at least 128 high,
                // the diff at least twice its size, charts as they are.
                const std::string png = read_text(pf);
                const int natural = cp::png_width(png);
                const int width = pic == "error_vs_time"
                                      ? (natural > 0 ? natural : 480)
                                      : cp::shown_width(natural, 192, pic == "diff" ? 2 : 1, cp::png_height(png), 128);
                sec << "<figure style=\"width:" << width + 2 << "px\"><img alt=\"" << html_escape(pic)
                         << "\" width=\"" << width << "\" src=\"data:image/png;base64," << base64(png)
                         << "\"><figcaption>" << html_escape(cp::picture_caption(m, pic)) << "</figcaption></figure>";
            }
            sec << "</section>\n";
        }
        tests.push_back({{"name", m + " compiles"},
                         {"score", 0},
                         {"max_score", 0},
                         {"status", compiled ? "passed" : "failed"},
                         {"output", (compiled ? std::string("compiled") : not_built + ":\n" + compile_log) +
                                        (layout.empty() ? "" : "\n" + layout)},
                         {"visibility", "visible"}});
        if (!layout.empty()) {
            notes << "<section id=\"" << m << "-files\"><h3>" << m << " compiles: which file was graded</h3><pre>"
                  << html_escape(layout) << "</pre></section>\n";
        }
        if (!compiled) {
            sections << "<section id=\"" << m << "-compile\"><h3>" << m
                     << " compiles: " << not_built << "</h3><pre>" << html_escape(compile_log) << "</pre></section>\n";
        }
    }
    std::ostringstream summary;
    if (hidden_count == 0) {
        summary << "Score " << fmt_points(score) << " / " << fmt_points(total) << ".";
    } else {
        summary << "Visible checkpoints:";
    }
    for (const auto& [m, p] : per_milestone) summary << " " << m << ": " << fmt_points(p.first) << "/" << fmt_points(p.second) << ".";
    if (hidden_count > 0) summary << " More checkpoints are shown when the grades are published.";
    if (!seed.empty()) summary << " Scene seed " << seed << ".";
    json results = {{"score", score},
                    {"output", summary.str()},
                    {"tests", tests},
                    {"visibility", "visible"},
                    {"stdout_visibility", "hidden"}};
    if (fs::exists(dir / "execution_time")) results["execution_time"] = std::stod(read_text(dir / "execution_time"));
    write_file_checked(out / "results.json", results.dump(2) + "\n");

    html << "<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>Grade: " << html_escape(name)
         << "</title>" << kStyle << "</head><body><h1>Grade: " << html_escape(name) << "</h1><p>"
         << html_escape(summary.str()) << "</p>";
    if (hidden_count > 0) {  // the instructor's page: the grade, which results.json's summary keeps back
        html << "<p><b>With the " << hidden_count << " hidden checkpoint" << (hidden_count == 1 ? "" : "s")
             << ": " << fmt_points(score) << " / " << fmt_points(total)
             << "</b> (the grade; students see it when the grades are published)</p>";
    }
    html << "<table><tr><th>checkpoint</th><th>status</th><th>points</th>"
         << "<th>concepts</th><th>your ms</th><th>reference ms</th><th>pixels differ</th></tr>\n"
         << rows.str() << "</table>\n" << notes.str() << sections.str()
         << (!sections.str().empty() && !passing.str().empty()
                 ? "<p id=\"full-marks\"><b>Checkpoints with full marks</b> (those that lost points are above)</p>\n"
                 : "")
         << passing.str() << cp::kPictureLoadMarker << "</body></html>\n";
    write_file_checked(out / "report.html", html.str());
    std::cout << summary.str() << "\n";
    // For the instructor's console only (results.json's output is the students'): the grade.
    if (hidden_count > 0) {
        std::cout << "Score " << fmt_points(score) << " / " << fmt_points(total) << " with the " << hidden_count
                  << " hidden checkpoint" << (hidden_count == 1 ? "" : "s")
                  << ": the grade, which students see when the grades are published.\n";
    }
    return 0;
}

// ---- the class ----

// A CSV field: quoted where it holds a comma, a quote or a line break; and a text a spreadsheet
// would take for a formula (=, +, -, @, a tab or a carriage return first: a submission's name
// is the student's to choose) starts with an apostrophe, which the spreadsheet shows as text.
std::string csv_field(std::string s) {
    if (!s.empty() && std::string_view("=+-@\t\r").find(s[0]) != std::string_view::npos) s = "'" + s;
    if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
    std::string out = "\"";
    for (char c : s) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + "\"";
}

// A submission's name as a relative link: "./" first (a name like "javascript:..." is then no
// scheme) and every byte but letters, digits and -._~ percent-encoded.
std::string relative_link(const std::string& name, const std::string& rest) {
    static const char* hex = "0123456789ABCDEF";
    std::string out = "./";
    for (unsigned char c : name) {
        if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~') {
            out += char(c);
        } else {
            out += '%';
            out += hex[c >> 4];
            out += hex[c & 15];
        }
    }
    return out + rest;
}

int cmd_class(const std::vector<std::string>& args) {
    if (args.size() < 2) throw std::invalid_argument("class needs <out-dir> <results.json>...");
    const fs::path out = args[0];
    fs::create_directories(out);
    struct Row {
        std::string who;
        double score = 0;
        std::map<std::string, double> points, milestone;
        std::string unbuilt;  // "m2: compile error, m4: missing file"
    };
    std::vector<Row> rows;
    std::vector<std::string> columns;  // checkpoint names, in first-seen order
    std::map<std::string, double> max_of;
    std::map<std::string, int> fails, graded;  // checkpoint -> submissions that failed it, that built its milestone
    std::map<std::string, std::map<std::string, int>> concepts_of;  // checkpoint -> concept -> count
    for (std::size_t i = 1; i < args.size(); ++i) {
        const fs::path p = args[i];
        Row row;
        row.who = p.parent_path().filename().string();
        json j;
        try {
            j = json::parse(read_text(p));
        } catch (const json::exception&) {
            std::cerr << "skipping unreadable " << p << "\n";
            continue;
        }
        row.score = j.value("score", 0.0);
        // The milestones not built (compile error, missing file, code refused): their checkpoints'
        // failures say nothing about the checkpoints, so they are left out of the list of the
        // checkpoints the class fails (the "not built" column shows them).
        std::set<std::string> unbuilt;
        for (const json& t : j.value("tests", json::array())) {
            const std::string name = t.value("name", std::string());
            if (name.size() > 9 && name.ends_with(" compiles") && t.value("status", std::string()) == "failed") {
                const std::string output = t.value("output", std::string());
                unbuilt.insert(name.substr(0, name.find(' ')));
                row.unbuilt += (row.unbuilt.empty() ? "" : ", ") + name.substr(0, name.find(' ')) + ": " +
                               output.substr(0, std::min(output.find(':'), output.find('\n')));
            }
        }
        for (const json& t : j.value("tests", json::array())) {
            const std::string name = t.value("name", std::string());
            if (t.value("max_score", 0.0) <= 0) continue;
            if (!max_of.count(name)) columns.push_back(name);
            max_of[name] = t.value("max_score", 0.0);
            row.points[name] = t.value("score", 0.0);
            row.milestone[name.substr(0, name.find(' '))] += t.value("score", 0.0);
            if (unbuilt.count(name.substr(0, name.find(' ')))) continue;
            ++graded[name];
            if (t.value("score", 0.0) < t.value("max_score", 0.0)) {
                ++fails[name];
                const std::string output = t.value("output", std::string());
                // The concept of the first finding: "  [topic] ..." on the line after "what is wrong:".
                const auto at = output.find("\n  [");
                if (at != std::string::npos) {
                    const auto end = output.find(']', at);
                    concepts_of[name][output.substr(at + 4, end - at - 4)]++;
                }
            }
        }
        rows.push_back(row);
    }
    std::set<std::string> milestones;
    std::map<std::string, double> milestone_max;
    double total_max = 0;
    for (const std::string& c : columns) {
        milestones.insert(c.substr(0, c.find(' ')));
        milestone_max[c.substr(0, c.find(' '))] += max_of[c];
        total_max += max_of[c];
    }
    // The header, then a row "(maximum)" of the points each column can have (so that a
    // spreadsheet keeps plain column names and can divide by that row), then a row each.
    std::ostringstream csv;
    csv << "submission,score";
    for (const std::string& m : milestones) csv << "," << csv_field(m);
    for (const std::string& c : columns) csv << "," << csv_field(c);
    csv << "\n(maximum)," << fmt_points(total_max);
    for (const std::string& m : milestones) csv << "," << fmt_points(milestone_max[m]);
    for (const std::string& c : columns) csv << "," << fmt_points(max_of[c]);
    csv << "\n";
    for (const Row& r : rows) {
        csv << csv_field(r.who) << "," << fmt_points(r.score);
        for (const std::string& m : milestones) csv << "," << fmt_points(r.milestone.count(m) ? r.milestone.at(m) : 0);
        for (const std::string& c : columns) csv << "," << fmt_points(r.points.count(c) ? r.points.at(c) : 0);
        csv << "\n";
    }
    std::vector<std::string> order = columns;
    std::stable_sort(order.begin(), order.end(), [&](const std::string& a, const std::string& b) { return fails[a] > fails[b]; });
    std::ostringstream html;
    html << "<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>Class results</title>" << kStyle
         << "</head><body><h1>Class results</h1><p>" << rows.size()
         << " submission(s): their points first (a column's maximum in its heading), then the checkpoints the class "
            "fails most, with the concept their first finding names; a milestone that was not built (compile error, "
            "missing file, code refused) is left out of that list, as its checkpoints were not tried (the \"not "
            "built\" column shows it).</p><h2>Submissions</h2><table><tr><th>submission</th><th>score ("
         << fmt_points(total_max) << ")</th>";
    for (const std::string& m : milestones) html << "<th>" << html_escape(m) << " (" << fmt_points(milestone_max[m]) << ")</th>";
    html << "<th>not built</th></tr>\n";
    for (const Row& r : rows) {
        html << "<tr><td><a href=\"" << html_escape(relative_link(r.who, "/report.html")) << "\">" << html_escape(r.who) << "</a></td><td>"
             << fmt_points(r.score) << "</td>";
        for (const std::string& m : milestones) html << "<td>" << fmt_points(r.milestone.count(m) ? r.milestone.at(m) : 0) << "</td>";
        html << "<td>" << html_escape(r.unbuilt) << "</td></tr>\n";
    }
    html << "</table><h2>Checkpoints</h2><table><tr><th>checkpoint</th><th>failed by (of those that built its milestone)</th>"
            "<th>concepts</th></tr>\n";
    for (const std::string& c : order) {
        if (graded[c] == 0 || fails[c] == 0) continue;  // no submission built its milestone, or none failed it
        std::string concepts;
        std::vector<std::pair<int, std::string>> byc;
        for (const auto& [k, n] : concepts_of[c]) byc.push_back({-n, k});
        std::sort(byc.begin(), byc.end());
        for (const auto& [n, k] : byc) concepts += (concepts.empty() ? "" : ", ") + k + " (" + std::to_string(-n) + ")";
        html << "<tr><td>" << html_escape(c) << "</td><td>" << fails[c] << " of " << graded[c] << "</td><td>"
             << html_escape(concepts) << "</td></tr>\n";
    }
    html << "</table>" << cp::kPictureLoadMarker << "</body></html>\n";
    write_file_checked(out / "class.csv", csv.str());
    write_file_checked(out / "class.html", html.str());
    std::cout << "class results: " << (out / "class.csv").string() << ", " << (out / "class.html").string() << "\n";
    return 0;
}

// ---- what to grade ----

// SplitMix64's finalizer: a hidden checkpoint's seed for one submission.
std::uint64_t mix(std::uint64_t a, std::uint64_t b) {
    std::uint64_t z = a ^ (b + 0x9e3779b97f4a7c15ULL + (a << 6) + (a >> 2));
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return (z ^ (z >> 31)) & ((1ULL << 53) - 1);  // exact in a JSON number
}

// "m1 milestone1_lines lines.cpp [more files]" per milestone of the rubric.
int cmd_rubric_files(const std::string& rubric_file) {
    for (const auto& [m, r] : read_rubric(rubric_file)) {
        std::cout << m << " " << r.folder;
        for (const std::string& f : r.files) std::cout << " " << f;
        std::cout << "\n";
    }
    return 0;
}

// The checkpoints of milestone <m> to grade, one per line:
//   <name> <scene-id> <seed> <visibility> <points> <title...>
// every public checkpoint (on the submission's seed), then the hidden ones of hidden.json:
//   {"checkpoints": [{"name": "hidden.steep", "milestone": "m1", "scene": "m1.octant_2",
//                     "seed": 912, "points": 2, "title": "..."}]}
// A hidden checkpoint is a scene variant nobody outside the course staff has seen: its seed is
// mixed with the submission's, and its results are shown after the grades are published.
int cmd_plan(const std::vector<std::string>& args) {
    if (args.size() < 3) throw std::invalid_argument("plan needs <rubric.json> <m> <seed> [hidden.json]");
    const auto rubric = read_rubric(args[0]);
    const std::string m = args[1];
    const std::uint64_t seed = std::stoull(args[2]);
    const MilestoneRubric& r = rubric.at(m);
    const cp::Suite& s = suite(m);
    for (const auto& [id, points] : r.points) {
        if (std::find(s.ids.begin(), s.ids.end(), id) == s.ids.end()) {
            throw std::invalid_argument("the rubric gives points to " + id + ", which is no checkpoint of " + m);
        }
    }
    auto clean = [](std::string t) {
        std::replace(t.begin(), t.end(), '\n', ' ');
        std::replace(t.begin(), t.end(), '\r', ' ');
        return t;
    };
    std::ostringstream lines;  // printed only when hidden.json is right too
    for (const std::string& id : s.ids) {
        const auto it = r.points.find(id);
        lines << id << " " << id << " " << seed << " visible "
                  << fmt_points(it == r.points.end() ? r.default_points : it->second) << " " << clean(s.title(id)) << "\n";
    }
    if (args.size() >= 4 && !args[3].empty()) try {
        const json h = json::parse(read_text(args[3]));
        if (!h.is_object() || !h.contains("checkpoints") || !h.at("checkpoints").is_array()) {
            throw std::invalid_argument("the file must be {\"checkpoints\": [ ... ]}, a list of entries");
        }
        // Every entry is checked on every call, whichever milestone it belongs to, so that the
        // first plan the grader makes refuses a wrong entry before anything is graded. Names are
        // unique among all checkpoints: the public ones of every milestone and the hidden ones.
        std::map<std::string, std::string> milestone_of;  // public checkpoint (= scene) -> milestone
        for (const auto& [rm, rr] : rubric) {
            for (const std::string& id : suite(rm).ids) milestone_of[id] = rm;
        }
        std::map<std::string, int> hidden_names;  // name -> entry
        // Every wrong entry is told in one run (a file with three mistakes needs one fix, not three
        // runs); the plan is printed only when all of them are right.
        std::vector<std::string> errors;
        int entry = 0;
        for (const json& c : h.at("checkpoints")) try {
            ++entry;
            std::string label = "entry " + std::to_string(entry);
            if (!c.is_object() || !c.contains("name") || !c.contains("milestone") || !c.contains("scene") ||
                !c.contains("seed")) {
                throw std::invalid_argument(label + " needs name, milestone, scene and seed (points and title are optional)");
            }
            // A field's value as it is written, to quote in a message.
            auto written = [](const json& f) {
                std::string d = f.dump();
                return d.size() > 40 ? d.substr(0, 40) + "..." : d;
            };
            auto text = [&](const char* field) {
                const json& f = c.at(field);
                if (!f.is_string()) {
                    throw std::invalid_argument(label + ": \"" + field + "\" must be a string (in quotes), not " +
                                                written(f) + " (a " + f.type_name() + ")");
                }
                return f.get<std::string>();
            };
            const std::string name = text("name");
            label += " (" + name + ")";
            const bool plain = !name.empty() && std::all_of(name.begin(), name.end(), [](char ch) {
                return std::isalnum(static_cast<unsigned char>(ch)) || ch == '.' || ch == '_' || ch == '-';
            });
            if (!plain) throw std::invalid_argument(label + ": a name is letters, digits, '.', '_' and '-' only");
            if (milestone_of.count(name)) {
                throw std::invalid_argument(label + ": " + name + " is the name of a public checkpoint of " +
                                            milestone_of.at(name) +
                                            "; a hidden checkpoint needs a name of its own (such as hidden." +
                                            name.substr(name.find('.') + 1) + ")");
            }
            if (!hidden_names.emplace(name, entry).second) {
                throw std::invalid_argument(label + ": entry " + std::to_string(hidden_names.at(name)) +
                                            " has the same name; each hidden checkpoint needs a name of its own");
            }
            const std::string hm = text("milestone"), scene = text("scene");
            if (!rubric.count(hm)) {
                std::string known;
                for (const auto& [rm, rr] : rubric) known += (known.empty() ? "" : ", ") + rm;
                throw std::invalid_argument(label + ": milestone " + hm + " is not in the rubric (" + known + ")");
            }
            if (!milestone_of.count(scene) || milestone_of.at(scene) != hm) {
                throw std::invalid_argument(
                    label + ": " +
                    (milestone_of.count(scene)
                         ? "scene " + scene + " belongs to milestone " + milestone_of.at(scene) + ", not " + hm +
                               ": give \"milestone\": \"" + milestone_of.at(scene) + "\", or a scene of " + hm
                         : "no scene " + scene + " in milestone " + hm + " (`raster_grade ids " + hm + "` lists them)"));
            }
            const json& js = c.at("seed");
            if (!js.is_number_unsigned()) {
                throw std::invalid_argument(label + ": \"seed\" must be a whole number of 0 or more (such as 9127, no quotes), not " +
                                            written(js) + " (a " + js.type_name() + ")");
            }
            double points = r.default_points;
            if (c.contains("points")) {
                const json& jp = c.at("points");
                if (!jp.is_number() || !(jp.get<double>() > 0) || jp.get<double>() != std::floor(jp.get<double>()) ||
                    jp.get<double>() > 1000) {
                    throw std::invalid_argument(label + ": \"points\" must be a whole number from 1 to 1000 (such as 3, no quotes), not " +
                                                written(jp));
                }
                points = jp.get<double>();
            }
            std::string title;
            if (c.contains("title")) title = text("title");
            if (hm != m) continue;
            const std::uint64_t hseed = js.get<std::uint64_t>();
            lines << name << " " << scene << " " << (seed == 0 ? hseed : mix(seed, hseed)) << " after_published "
                  << fmt_points(points) << " " << clean(title.empty() ? s.title(scene) : title) << "\n";
        } catch (const std::invalid_argument& e) {
            errors.push_back(e.what());
        }
        if (errors.size() == 1) throw std::invalid_argument(errors.front());
        if (!errors.empty()) {
            std::string all = std::to_string(errors.size()) + " entries need a fix:";
            for (const std::string& e : errors) all += "\n  " + e;
            throw std::invalid_argument(all);
        }
    } catch (const std::exception& e) {
        throw std::invalid_argument(args[3] + ": " + e.what());
    }
    std::cout << lines.str();
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> args(argv + 1, argv + argc);
    try {
        if (args.size() >= 2 && args[0] == "ids") return cmd_ids(args[1]);
        if (!args.empty() && args[0] == "judge") return cmd_judge({args.begin() + 1, args.end()});
        if (!args.empty() && args[0] == "report") return cmd_report({args.begin() + 1, args.end()});
        if (!args.empty() && args[0] == "class") return cmd_class({args.begin() + 1, args.end()});
        if (args.size() >= 2 && args[0] == "rubric-files") return cmd_rubric_files(args[1]);
        if (!args.empty() && args[0] == "plan") return cmd_plan({args.begin() + 1, args.end()});
    } catch (const std::exception& e) {
        std::cerr << "raster_grade: " << e.what() << "\n";
        return 2;
    }
    std::cerr << "usage: raster_grade ids <m> | judge ... | report ... | class ... (see grader.cpp)\n";
    return 2;
}
