// `make check` and `make check-mN`: runs the student's checkpoints with CTest, then prints the
// table that ends the run (every checkpoint's verdict, image error and render time, yours
// against the reference) and writes the same data as JSON and as an HTML page with every
// failure's findings and pictures.
//
//   checkpoint_summary <ctest> <build-dir> <label-regex>
//
// Exit status: 0 when every checkpoint passed, 1 otherwise.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "harness/checkpoint.h"
#include "harness/diagnosis.h"
#include "harness/html.h"
#include "harness/record.h"
#include "harness/verdict.h"

namespace {

// A measure as a reader expects it: a count as a whole number ("84", not "84.0000"), any other
// value with four significant digits, whatever the stream's flags are.
std::string measure_text(double v) {
    std::ostringstream s;
    if (std::isfinite(v) && v == std::round(v) && std::abs(v) < 1e15) {
        s << static_cast<long long>(v);
    } else {
        s << std::setprecision(4) << v;
    }
    return s.str();
}

using cp::html_escape;

// The first 24 bytes of the PNG at `path` (its width and height), empty when it cannot be read.
std::string png_head_of(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::string head(24, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    return in ? head : std::string();
}

nlohmann::json json_number(double v) {
    if (!std::isfinite(v)) return nullptr;  // JSON has no infinity (PSNR of identical images)
    return v;
}

nlohmann::json json_metrics(const raster::ImageMetrics& m) {
    return {{"differing_pixels", m.differing_pixels},
            {"differing_share", json_number(m.differing_share)},
            {"max_channel_diff", m.max_channel_diff},
            {"mean_abs_error", json_number(m.mean_abs_error)},
            {"psnr_db", json_number(m.psnr_db)}};
}


// `p` as a link from a page in `page_dir`: relative to it, so that the page and its pictures can
// move together (the build folder copied or mounted elsewhere); `p` itself when no relative path
// leads there (another drive).
std::string page_relative(const std::filesystem::path& p, const std::filesystem::path& page_dir) {
    std::error_code ec;
    const std::filesystem::path rel = std::filesystem::relative(p, page_dir, ec);
    return ec || rel.empty() ? p.generic_string() : rel.generic_string();
}

void write_html(const std::vector<cp::Record>& records, const std::string& path, const std::string& refusals) {
    std::ofstream html(path);
    const std::filesystem::path page_dir = std::filesystem::absolute(std::filesystem::path(path)).parent_path();
    html << "<!doctype html><meta charset=utf-8><title>Checkpoints</title>\n"
            "<style>body{font-family:sans-serif;background:#1e1e1e;color:#ddd;margin:2em}"
            "a{color:#8cf}table{border-collapse:collapse}td,th{padding:4px 10px;border-bottom:1px solid #444;text-align:left}"
            ".pass{color:#6c6}.fail{color:#f66}.crashed{color:#fa0}"
            "figure{display:inline-block;margin:0 10px 10px 0;vertical-align:top}"
            "figcaption{font-size:85%;color:#aaa}"
            "img{image-rendering:pixelated;image-rendering:crisp-edges;border:1px solid #555}</style>\n"
            "<h1>Checkpoints</h1>\n";
    if (!refusals.empty()) html << "<pre class=\"fail\">" << html_escape(refusals) << "</pre>\n";
    html << "<table><tr><th>checkpoint<th>result<th>pixels differ<th>mean error"
            "<th>your ms<th>reference ms<th>needs TODOs<th>concepts</tr>\n";
    for (const cp::Record& r : records) {
        html << "<tr><td><a href=\"#" << html_escape(r.id) << "\">" << html_escape(r.id) << "</a><td class=\"" << html_escape(r.status)
             << "\">" << html_escape(r.status);
        if (r.has_metrics) {
            // A checkpoint of numbers has no picture: no pixel can differ, so none is counted.
            html << std::fixed << std::setprecision(3);
            if (r.numbers_only) {
                html << "<td>-<td>-";
            } else {
                html << "<td>" << r.student.differing_pixels << "<td>" << r.student.mean_abs_error;
            }
            html << "<td>" << r.student_ms << "<td>" << r.reference_ms;
        } else {
            html << "<td>-<td>-<td>-<td>-";
        }
        html << "<td>" << html_escape(r.todos) << "<td>" << html_escape(r.concepts) << "</tr>\n";
    }
    html << "</table>\n";
    // The measures (a row per checkpoint and measure, over a hundred for a whole run) come after
    // every checkpoint's section, so that the first screens show the table and the failures.
    const bool any_measure = std::any_of(records.begin(), records.end(),
                                         [](const cp::Record& r) { return !r.measures.empty(); });
    if (any_measure) {
        html << "<p>Each checkpoint's findings and pictures follow, the failing ones first; the <a href=\"#measures\">"
                "measured error against run time</a> is at the end of the page.</p>\n";
    }
    // The sections of failing checkpoints first (in the table's order), then the passing ones:
    // the first screen below the table is what needs work.
    std::vector<const cp::Record*> sections;
    for (const cp::Record& r : records) {
        if (r.status != "pass") sections.push_back(&r);
    }
    const std::size_t failing = sections.size();
    for (const cp::Record& r : records) {
        if (r.status == "pass") sections.push_back(&r);
    }
    std::set<std::string> passed;
    for (const cp::Record& r : records) {
        if (r.status == "pass") passed.insert(r.id);
    }
    for (std::size_t i = 0; i < sections.size(); ++i) {
        const cp::Record& r = *sections[i];
        if (i == failing && failing > 0) {
            html << "<p class=\"pass\" id=\"passing\"><b>Passing checkpoints</b> (the failing ones are above)</p>\n";
        }
        html << "<h2 id=\"" << html_escape(r.id) << "\">" << html_escape(r.id) << ": " << html_escape(r.title)
             << "</h2>\n<p class=\"" << html_escape(r.status) << "\">" << html_escape(r.status) << " "
             << html_escape(r.concepts) << "</p>\n";
        if (!r.todos.empty()) html << "<p>needs " << html_escape(cp::todo_label(r.todos)) << "</p>\n";
        if (!r.findings.empty()) {
            html << "<ul>";
            for (const std::string& f : r.findings) html << "<li>" << html_escape(f) << "</li>";
            html << "</ul>\n";
        }
        if (!r.hint.empty()) html << "<p><b>hint:</b> " << html_escape(r.hint) << "</p>\n";
        if (!r.diagnosis.empty()) html << "<p><b>known bug:</b> " << html_escape(r.diagnosis) << "</p>\n";
        if (r.counts_only) html << "<p><b>counts only:</b> " << html_escape(cp::kCountsOnlyNote) << "</p>\n";
        if (r.tolerated > 0) html << "<p><b>tolerated:</b> " << html_escape(r.tolerated_why) << "</p>\n";
        if (r.output_dir.empty()) {
            html << "<p>No pictures: the checkpoint crashed or ran out of time. Run it alone to see why.</p>\n";
            continue;
        }
        // actual, expected and diff first, then every other picture the scene made. A checkpoint
        // of numbers has no picture of its own: its blank canvas and expected image are left out.
        std::vector<std::string> names;
        if (r.numbers_only) {
            html << cp::kNumbersOnlyNote;
        } else {
            names = {"actual", "expected", "diff"};
        }
        std::vector<std::string> others;
        std::error_code ec;
        for (const auto& entry : std::filesystem::directory_iterator(r.output_dir, ec)) {
            const std::string stem = entry.path().stem().string();
            // A picture of another checkpoint's scene drawn by this run's fill_triangle alone
            // ("fill_triangle", milestone 4's "shared_edges") tells a wrong fill_triangle from a
            // wrong caller: of no use where this scene passes, or where that checkpoint passed in
            // this run (then fill_triangle draws it right, and the picture shows nothing new).
            const bool other_scene = stem == "fill_triangle" || stem == "shared_edges";
            const bool unhelpful = other_scene && (r.status == "pass" || passed.count(r.milestone + "." + stem) > 0);
            if (entry.path().extension() == ".png" && stem != "actual" && stem != "expected" && stem != "diff" &&
                !unhelpful) {
                others.push_back(stem);
            }
        }
        std::sort(others.begin(), others.end());
        names.insert(names.end(), others.begin(), others.end());
        if (names.empty()) continue;
        html << "<p>";
        for (const std::string& name : names) {
            const std::filesystem::path p = std::filesystem::path(r.output_dir) / (name + ".png");
            if (!std::filesystem::exists(p)) continue;
            // Scene pictures about 320 px wide and at least 192 high, each a whole multiple of its
            // own size, the diff at least twice its size (so a single pixel of it shows); charts as
            // they are.
            const std::string head = png_head_of(p);
            const int natural = cp::png_width(head);
            const int width = name == "error_vs_time"
                                  ? (natural > 0 ? natural : 640)
                                  : cp::shown_width(natural, 320, name == "diff" ? 2 : 1, cp::png_height(head), 192);
            const std::string src = html_escape(page_relative(p, page_dir));
            html << "<figure style=\"width:" << width + 2 << "px\"><a href=\"" << src << "\"><img alt=\""
                 << html_escape(r.id + " " + name) << "\" width=\"" << width << "\" src=\"" << src
                 << "\"></a><figcaption>"
                 << html_escape(cp::picture_caption(r.milestone, name)) << "</figcaption></figure>";
        }
        html << "</p>\n";
    }
    if (any_measure) {
        // Not an <h2 id=...>: those are the checkpoints' sections.
        html << "<section id=\"measures\"><h2>Measured error against run time</h2>\n<table><tr><th>checkpoint"
                "<th>measure<th>value<th>your ms<th>reference ms</tr>\n";
        for (const cp::Record& r : records) {
            for (const auto& [name, v] : r.measures) {
                html << "<tr><td>" << html_escape(r.id) << "<td>" << html_escape(name) << "<td>" << measure_text(v)
                     << "<td>" << std::setprecision(3) << r.student_ms << "<td>" << r.reference_ms << "</tr>\n";
            }
        }
        html << "</table></section>\n";
    }
    html << cp::diagnosis_footer_html(records);
    html << cp::kPictureLoadMarker;
}

// One checkpoint's report as its process printed it: from "checkpoint <id>: " to its
// "VERDICT <id> " line (or, for a run that never got there, to where CTest's next line starts).
std::string report_block(const std::filesystem::path& log_path, const std::string& id) {
    std::ifstream log(log_path);
    std::string line, block;
    bool inside = false;
    int lines = 0;
    while (std::getline(log, line)) {
        if (!inside) {
            inside = line.rfind("checkpoint " + id + ": ", 0) == 0;
            if (!inside) continue;
        } else if (line.find("Test #") != std::string::npos || line.find(" Start ") != std::string::npos) {
            break;
        }
        block += line + "\n";
        if (line.rfind("VERDICT " + id + " ", 0) == 0 || ++lines > 120) break;
    }
    return block;
}

// The TODO to fix first by these findings: the one the first finding that names any sends the
// student to ("[snap] (TODO 1) ...", "fix TODO 3 first"); the first finding is the judge's
// likeliest cause, later ones may be its consequences. A finding that names several ("(TODOs 2,
// 4)", "(TODO 4b or 6)", "(TODOs 3-4)") counts as the last of them: it does not know that the
// earlier ones are wrong, so a checkpoint that does know comes first. A large number when no
// finding names a TODO.
int first_todo(const std::vector<std::string>& findings) {
    for (const std::string& f : findings) {
        // The first TODO label of the line: "[topic] (TODOs 2, 4) ...", "[nothing drawn]
        // `draw_line` (TODOs 3-4) drew nothing ...", "fix TODO 3 first (see ...)".
        const std::size_t at = f.find("TODO");
        if (at == std::string::npos) continue;
        std::string label = f.substr(at, f.find_first_of("):;", at) - at);
        if (const std::size_t first = label.find(" first"); first != std::string::npos) label.resize(first);
        if (const std::size_t alternative = label.find(" or "); alternative != std::string::npos) {
            label.replace(alternative, 4, ", ");
        }
        const std::set<int> todos = cp::todo_numbers(label);
        if (!todos.empty()) return *todos.rbegin();
    }
    return 1000;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::cerr << "usage: checkpoint_summary <ctest> <build-dir> <label-regex>\n";
        return 2;
    }
    const std::filesystem::path build = argv[2];
    // Each milestone's student checkpoints run in their own folder and leave one record each.
    std::vector<std::filesystem::path> run_dirs;
    for (const auto& entry : std::filesystem::directory_iterator(build / "checkpoints" / "run")) {
        const std::string name = entry.path().filename().string();
        if (entry.is_directory() && name.size() > 8 && name.substr(name.size() - 8) == "_student") {
            run_dirs.push_back(entry.path());
        }
    }
    for (const auto& dir : run_dirs) {  // forget the previous run: its records and pictures
        std::filesystem::remove_all(dir / "checkpoint_results");
        std::filesystem::remove_all(dir / "checkpoint_output");
    }
    // CTest's own output (every checkpoint's full report) goes to a log file; the terminal gets
    // the first failing checkpoint in full and one line for each of the others (the table).
    // CTest runs in the checkpoints' own folder (where the student checkpoints are declared), so
    // its Testing/ logs stay there: a `make check` started from the project's test suite (which
    // runs in the build folder) leaves that suite's Testing/Temporary/LastTest.log alone.
    const std::filesystem::path log_path = build / "check_log.txt";
    const std::string command = std::string("\"") + argv[1] + "\" --test-dir \"" +
                                (build / "checkpoints").string() + "\" -L '" +
                                argv[3] + "' --output-on-failure --parallel 2 > \"" + log_path.string() + "\" 2>&1";
    std::cout << "Running the checkpoints (full output: " << log_path.string() << ") ..." << std::endl;
    const int ctest_status = std::system(command.c_str());

    std::vector<cp::Record> records;
    for (const auto& dir : run_dirs) {
        for (cp::Record& r : cp::read_records((dir / "checkpoint_results").string())) records.push_back(std::move(r));
    }
    std::sort(records.begin(), records.end(), [](const cp::Record& a, const cp::Record& b) {
        return a.milestone != b.milestone ? a.milestone < b.milestone : a.order < b.order;
    });
    const std::string json_path = (build / "check_results.json").string();

    int passed = 0, failed = 0, crashed = 0;

    // The first to fix: in the first milestone with a failure, the failing checkpoint whose
    // findings send the student to the lowest TODO (the lesson's order of work: the skeleton's
    // m2.edge_and_box, which says what snap() returns, before m2.solid, which says that nothing
    // is drawn); at a tie, or without a TODO named, the first in the lesson's order.
    const cp::Record* first = nullptr;
    int lowest = 0;
    for (const cp::Record& r : records) {
        if (r.status == "pass") continue;
        if (first != nullptr && r.milestone != first->milestone) break;
        const int todo = first_todo(r.findings);
        if (first == nullptr || todo < lowest) {
            first = &r;
            lowest = todo;
        }
    }
    if (first != nullptr) {
        const std::string block = report_block(log_path, first->id);
        if (!block.empty()) {
            std::cout << "\nThe first checkpoint to fix, in full (the others are one line each below):\n\n" << block;
        }
    }

    std::cout << "\n"
              << std::left << std::setw(28) << "checkpoint" << std::setw(8) << "result"
              << std::right << std::setw(12) << "px differ" << std::setw(10) << "mean err"
              << std::setw(11) << "your ms" << std::setw(11) << "ref ms" << "  concept\n"
              << std::string(100, '-') << "\n";
    nlohmann::json checkpoints = nlohmann::json::array();
    for (const cp::Record& r : records) {
        std::string result = r.status == "pass" ? "PASS" : r.status == "fail" ? "FAIL" : "CRASH";
        passed += r.status == "pass";
        failed += r.status == "fail";
        crashed += r.status != "pass" && r.status != "fail";
        std::cout << std::left << std::setw(28) << r.id << std::setw(8) << result << std::right;
        if (r.has_metrics && r.numbers_only) {
            std::cout << std::setw(12) << "-" << std::setw(10) << "-" << std::fixed << std::setprecision(3)
                      << std::setw(11) << r.student_ms << std::setw(11) << r.reference_ms;
        } else if (r.has_metrics) {
            std::cout << std::setw(12) << r.student.differing_pixels << std::setw(10) << std::fixed
                      << std::setprecision(3) << r.student.mean_abs_error << std::setw(11)
                      << r.student_ms << std::setw(11) << r.reference_ms;
        } else {
            std::cout << std::setw(12) << "-" << std::setw(10) << "-" << std::setw(11) << "-"
                      << std::setw(11) << "-";
        }
        std::cout << "  "
                  << (r.status == "crashed" ? "crashed or timed out (see below)"
                                            : (r.counts_only ? "counts only: " : "") + r.concepts)
                  << "\n";
        nlohmann::json measures = nlohmann::json::object();
        for (const auto& [name, v] : r.measures) measures[name] = json_number(v);
        checkpoints.push_back({{"id", r.id},
                               {"milestone", r.milestone},
                               {"title", r.title},
                               {"status", r.status},
                               {"concepts", r.concepts},
                               {"student_ms", json_number(r.student_ms)},
                               {"reference_ms", json_number(r.reference_ms)},
                               {"student_error", r.has_metrics ? json_metrics(r.student) : nlohmann::json()},
                               {"reference_error", r.has_metrics ? json_metrics(r.reference) : nlohmann::json()},
                               {"measures", measures},
                               {"findings", r.findings},
                               {"hint", r.hint},
                               {"diagnosis", r.diagnosis},
                               {"todos", r.todos},
                               {"counts_only", r.counts_only},
                               {"pictures", r.output_dir}});
    }
    std::ofstream(json_path) << nlohmann::json{{"checkpoints", checkpoints},
                                               {"passed", passed},
                                               {"failed", failed},
                                               {"crashed", crashed}}
                                    .dump(2)
                             << "\n";

    std::cout << std::string(100, '-') << "\n";
    if (std::any_of(records.begin(), records.end(), [](const cp::Record& r) { return r.counts_only; })) {
        std::cout << "counts only: " << cp::kCountsOnlyNote << "\n" << std::string(100, '-') << "\n";
    }
    // Numbers some checkpoints measure beside their verdict, against the render time: for
    // anti-aliasing, the coverage error against the exact area for each sample count. The
    // pipeline's counts beside the reference's ("... (reference N)") are in the HTML report
    // and in a failing checkpoint's findings; here they would bury the errors.
    // Each checkpoint once, with its render times, and its measures beneath it: a measure's
    // unit is in its name (pixels, ms of one panel), so no line mixes two units.
    bool any_measure = false;
    for (const cp::Record& r : records) {
        std::size_t width = 0;
        for (const auto& m : r.measures)
            if (m.first.find("(reference ") == std::string::npos) width = std::max(width, m.first.size());
        if (width == 0) continue;
        if (!any_measure) std::cout << "measured error against run time:\n";
        any_measure = true;
        std::cout << "  " << r.id << " (the whole checkpoint rendered in " << std::fixed << std::setprecision(3)
                  << r.student_ms << " ms, the reference in " << r.reference_ms << " ms)\n";
        std::cout.unsetf(std::ios::floatfield);
        for (const auto& [name, v] : r.measures) {
            if (name.find("(reference ") != std::string::npos) continue;
            std::cout << "    " << std::left << std::setw(static_cast<int>(width)) << name << std::right << "  "
                      << measure_text(v) << "\n";
        }
    }
    if (any_measure) std::cout << std::string(100, '-') << "\n";
    std::cout << passed << " passed, " << failed + crashed << " failed" << "\n";
    for (const cp::Record& r : records) {
        if (r.status != "crashed") continue;
        std::cout << r.id << " crashed or ran out of time before finishing. To see why, run it alone\n"
                  << "  (in a debugger if you like), from the build folder:\n"
                  << "    cd checkpoints/run/" << r.milestone << "_student && ../../checkpoints_" << r.milestone << " "
                  << r.id << "\n";
    }
    // Variants asked for (RASTER_SCENE_SEED): say so, so a table of other pictures is not a surprise.
    try {
        if (const std::uint64_t seed = cp::scene_seed_from_env(); seed != 0) {
            std::cout << "Scenes: the variants of seed " << seed << " (RASTER_SCENE_SEED), not the public ones; each "
                      << "expected picture is the reference's of that variant.\n";
        }
    } catch (const std::invalid_argument&) {
        // Not a number: the checkpoints themselves refused it, and their output says so.
    }
    // The grader's code check (tools/code-check, run by make check before this): a note for each
    // milestone checked here whose file it would refuse, last, where it is read.
    std::string refusals;
    std::set<std::string> milestones;
    for (const cp::Record& r : records) milestones.insert(r.milestone);
    for (const std::string& m : milestones) {
        std::ifstream note(build / ("code_check_" + m + ".txt"));
        std::stringstream text;
        text << note.rdbuf();
        if (note && !text.str().empty()) refusals += "\n" + text.str();
    }
    std::cout << refusals;
    const std::string html = (build / "check_results.html").string();
    write_html(records, html, refusals);
    std::cout << "This table is also in " << json_path << ",\nand with every failure's findings and pictures in " << html
              << "\n";
    if (records.empty()) {
        std::cout << "No checkpoint left a result: did the build fail? (CTest said " << ctest_status << ")\n";
        return 1;
    }
    if (failed + crashed > 0 || ctest_status != 0) {
        std::cout << "\n" << failed + crashed << (failed + crashed == 1 ? " checkpoint" : " checkpoints") << " to fix";
        if (first != nullptr) std::cout << ": start with " << first->id << ", the one shown in full above";
        std::cout << ".\n";
        return 1;
    }
    std::cout << (refusals.empty() ? "\nAll checkpoints pass.\n"
                                   : "\nAll checkpoints pass, but the grader would refuse code of yours (the note above).\n");
    return 0;
}
