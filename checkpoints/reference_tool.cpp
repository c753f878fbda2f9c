// The reference tool, for maintainers (and the README's first command):
//
//   reference_tool expected       render every checkpoint scene with the reference solution
//                                 and write checkpoints/expected/<milestone>/<id>.png
//   reference_tool verify         check the stored expected images against a fresh render
//   reference_tool gallery <dir>  render every milestone's demo scenes into <dir>, printing
//                                 each scene's error against its expected image and its time
//   reference_tool aa-table [--update FILE | --check FILE]
//                                 milestone 2's anti-aliasing table: coverage error against the
//                                 exact area, and render time, for 1, 4 and 16 samples. --update
//                                 rewrites the table between the aa-table markers in FILE (the
//                                 lesson); --check fails if the errors there are not current.
//   reference_tool todo-table <m> [--update FILE | --check FILE]
//                                 the table of which TODOs each checkpoint of milestone <m> needs
//   reference_tool m3-table [...]  likewise, milestone 3's error-against-run-time tables (inverses,
//                                 rotation drift, a far-away model in float and double)
//   reference_tool m5-table [...]  milestone 5's tables (filters, shadow maps, needs), each between
//                                 its markers (m5-filters, m5-shadows, m5-needs), and the chart
//
// Expected images come only from here: never edit them by hand.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/checkpoint.h"
#include "harness/showcase.h"
#include "m1/render.h"
#include "m1/scenes.h"
#include "m2/judge.h"
#include "m2/render.h"
#include "m2/scenes.h"
#include "m3/render.h"
#include "m3/scenes.h"
#include "m1/tables.h"
#include "m3/tables.h"
#include "m4/render.h"
#include "m4/tables.h"
#include "m4/scenes.h"
#include "m4/functions.h"
#include "m5/functions.h"
#include "m5/render.h"
#include "m5/scenes.h"
#include "m5/tables.h"
#include "m1/functions.h"
#include "m2/functions.h"
#include "m3/functions.h"
#include "raster/compare.h"
#include "raster/gif.h"
#include "raster/io.h"
#include "raster/plot.h"

namespace fs = std::filesystem;

namespace {

struct Entry {
    std::string milestone, id, title;
    bool demo;
    cp::Artifacts (*render)(const std::string&);
};

// Every milestone's scenes. Add a milestone here when its scenes exist.
std::vector<Entry> all_scenes() {
    std::vector<Entry> out;
    for (const m1cp::Scene& s : m1cp::scenes()) out.push_back({"m1", s.id, s.title, s.demo, m1cp::reference::render});
    for (const m2cp::Scene& s : m2cp::scenes()) out.push_back({"m2", s.id, s.title, s.demo, m2cp::reference::render});
    for (const m3cp::Scene& s : m3cp::scenes()) out.push_back({"m3", s.id, s.title, s.demo, m3cp::reference::render});
    for (const m4cp::Scene& s : m4cp::scenes()) out.push_back({"m4", s.id, s.title, s.demo, m4cp::reference::render});
    for (const m5cp::Scene& s : m5cp::scenes()) out.push_back({"m5", s.id, s.title, s.demo, m5cp::reference::render});
    return out;
}

// Milestone 3's animation as its lesson shows it (the demo's spinning cube and soccer ball on
// a Bezier camera path): written beside the lesson by `make expected`, checked by verify.
fs::path lesson_animation_path() {
    return fs::path(cp::expected_png_path("m1", "x")).parent_path().parent_path().parent_path().parent_path() /
           "milestone3_transforms" / "animation.gif";
}
constexpr int kAnimationDelay = 6;  // centiseconds per frame

int write_expected() {
    raster::write_gif(lesson_animation_path().string(), m3cp::reference::animation(), kAnimationDelay);
    std::cout << "wrote " << lesson_animation_path().string() << "\n";
    int written = 0;
    for (const Entry& e : all_scenes()) {
        const std::string path = cp::expected_png_path(e.milestone, e.id);
        fs::create_directories(fs::path(path).parent_path());
        raster::write_png(path, e.render(e.id).images.at("main"));
        ++written;
    }
    std::cout << "wrote " << written << " expected images\n";
    return 0;
}

int verify() {
    // The reference must reproduce every stored image. Aliased scenes use integer arithmetic
    // and match exactly; anti-aliased ones may move a channel by one level between compilers
    // (FMA contraction, -O0 vs -O3), which is allowed here and nowhere else.
    int bad = 0;
    for (const Entry& e : all_scenes()) {
        const std::string path = cp::expected_png_path(e.milestone, e.id);
        try {
            const raster::ImageMetrics m = raster::compare(e.render(e.id).images.at("main"), raster::read_png(path));
            if (!m.same_size || m.max_channel_diff > 1) {
                std::cout << "MISMATCH " << e.id << ": " << m.differing_pixels << " pixels differ, max "
                          << m.max_channel_diff << "\n";
                ++bad;
            }
        } catch (const std::exception& ex) {
            std::cout << "MISSING " << e.id << ": " << ex.what() << "\n";
            ++bad;
        }
    }
    // Stale files: an expected image whose scene no longer exists.
    for (const auto& dir : fs::directory_iterator(fs::path(cp::expected_png_path("m1", "x")).parent_path().parent_path())) {
        for (const auto& f : fs::directory_iterator(dir)) {
            bool known = false;
            for (const Entry& e : all_scenes()) known |= fs::equivalent(f.path(), cp::expected_png_path(e.milestone, e.id));
            if (!known) {
                std::cout << "STALE " << f.path().string() << ": no scene renders it\n";
                ++bad;
            }
        }
    }
    // The lesson's animation: same frames as a fresh render, up to the palette's rounding.
    try {
        const raster::GifInfo gif = raster::read_gif(lesson_animation_path().string());
        const std::vector<raster::Image> frames = m3cp::reference::animation();
        bool same = gif.frames.size() == frames.size();
        for (std::size_t i = 0; same && i < frames.size(); ++i) {
            const raster::ImageMetrics m = raster::compare(gif.frames[i], frames[i]);
            same = m.same_size && m.mean_abs_error < 2.0;
        }
        if (!same) {
            std::cout << "MISMATCH " << lesson_animation_path().string() << ": not the reference's animation\n";
            ++bad;
        }
    } catch (const std::exception& ex) {
        std::cout << "MISSING " << lesson_animation_path().string() << ": " << ex.what() << "\n";
        ++bad;
    }
    if (bad > 0) {
        std::cout << bad << " problem(s); if the reference changed on purpose, run `make expected`\n";
        return 1;
    }
    std::cout << "all " << all_scenes().size() << " expected images reproduced\n";
    return 0;
}

int gallery(const std::string& dir) {
    std::vector<cp::ShowItem> items;
    for (const Entry& e : all_scenes()) {
        if (e.demo) items.push_back({e.milestone, e.id, e.title, e.render});
    }
    const int shown = cp::showcase(items, dir, "Reference gallery: every milestone's demo scenes");
    // Milestone 3's animation (the demo's spinning cube and soccer ball on a Bezier camera path).
    raster::write_gif((fs::path(dir) / "m3_animation.gif").string(), m3cp::reference::animation(), kAnimationDelay);
    std::cout << "wrote " << (fs::path(dir) / "m3_animation.gif").string() << "\n";
    return shown;
}

std::string aa_table_text() {
    std::ostringstream out;
    out << "| samples per pixel | mean coverage error vs exact area | render time (ms) |\n"
        << "|---|---|---|\n";
    for (const char* id : {"m2.aa_1", "m2.aa_4", "m2.aa_16"}) {
        cp::Artifacts a;
        const double seconds = cp::time_best_of([&] { a = m2cp::reference::render(id); });
        const cp::Judgement j = m2cp::judge(id, a, a, raster::Image());
        const auto error = j.measures.begin();
        out << "| " << std::string(id).substr(6) << " | " << std::fixed << std::setprecision(4)
            << (error != j.measures.end() ? error->second : -1) << " | " << std::setprecision(3) << seconds * 1e3
            << " |\n";
    }
    return out.str();
}

// The table's rows without the time column, which depends on the machine.
std::string without_times(const std::string& table) {
    std::istringstream in(table);
    std::string line, out;
    while (std::getline(in, line)) out += line.substr(0, line.rfind('|', line.size() - 2)) + "\n";
    return out;
}

// A table between the markers `<!-- NAME ...` and `<!-- /NAME -->` of a lesson: printed,
// rewritten (--update FILE), or checked for drift (--check) in everything but its last column
// when that is a time (`timed`), which depends on the machine; a table without times, whole.
int marked_table(const std::string& name, const std::string& table, const std::vector<std::string>& args,
                 bool timed = true) {
    if (args.size() == 1) {
        std::cout << table;
        return 0;
    }
    const std::string begin = "<!-- " + name, end = "<!-- /" + name + " -->";
    std::ifstream in(args[2]);
    std::stringstream ss;
    ss << in.rdbuf();
    std::string text = ss.str();
    const auto b = text.find(begin), e = text.find(end);
    if (b == std::string::npos || e == std::string::npos || e < b) {
        std::cerr << args[2] << ": no " << name << " markers\n";
        return 1;
    }
    const auto body = text.find('\n', b) + 1;
    if (args[1] == "--check") {
        const std::string written = text.substr(body, e - body);
        if (timed ? without_times(written) != without_times(table) : written != table) {
            std::cerr << args[2] << ": the " << name << " is out of date; run `make regenerate`\n";
            return 1;
        }
        std::cout << args[2] << ": the " << name << (timed ? "'s errors are" : " is") << " current\n";
        return 0;
    }
    text.replace(body, e - body, table);
    std::ofstream(args[2]) << text;
    return 0;
}

// A milestone's checkpoints with the TODOs each needs (the TODOs of every function the
// reference calls on the scene, and of the functions those use, as `make check` prints them)
// and the points each is worth when graded (checkpoints/rubric.json, and its partial credit).
std::string todo_table_text(const std::string& milestone) {
    cp::Suite suite;
    if (milestone == "m1") suite.functions = m1cp::functions();
    if (milestone == "m2") suite.functions = m2cp::functions();
    if (milestone == "m3") suite.functions = m3cp::functions();
    if (milestone == "m4") suite.functions = m4cp::functions();
    if (milestone == "m5") suite.functions = m5cp::functions();
    if (suite.functions.empty()) throw std::runtime_error("no milestone named " + milestone);
    std::ifstream rubric_file(RASTER_RUBRIC);
    if (!rubric_file) throw std::runtime_error(std::string("cannot read the rubric ") + RASTER_RUBRIC);
    const nlohmann::json rubric = nlohmann::json::parse(rubric_file).at("milestones").at(milestone);
    const double default_points = rubric.value("default_points", 1.0);
    const auto points = rubric.value("points", std::map<std::string, double>{});
    auto fmt = [](double p) {
        std::ostringstream s;
        s << p;
        return s.str();
    };
    std::ostringstream out;
    double total = 0;
    out << "| needs TODOs | checkpoint | points | what it checks |\n|---|---|---|---|\n";
    for (const Entry& e : all_scenes()) {
        if (e.milestone != milestone) continue;
        const auto it = points.find(e.id);
        const double p = it == points.end() ? default_points : it->second;
        total += p;
        out << "| " << cp::todo_list(cp::needed_todos(suite, e.render(e.id))) << " | `" << e.id << "` | " << fmt(p)
            << " | " << e.title << " |\n";
    }
    out << "\nGraded, the milestone is worth " << fmt(total) << " points (checkpoints/rubric.json). A failed "
        << "checkpoint scores 0";
    const nlohmann::json partial = rubric.value("partial", nlohmann::json::array());
    for (const nlohmann::json& part : partial) {
        const double lost = part.value("points", 0.0);
        out << "; one whose only failure is " << part.value("what", std::string("one independent property"))
            << " loses " << fmt(lost) << (lost == 1 ? " point" : " points") << ", not all of them";
    }
    out << ".\n";
    return out.str();
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> args(argv + 1, argv + argc);
    try {
        if (args.size() == 1 && args[0] == "expected") return write_expected();
        if (args.size() == 1 && args[0] == "verify") return verify();
        if (args.size() == 2 && args[0] == "gallery") return gallery(args[1]);
        const bool table_args = args.size() == 1 || (args.size() == 3 && (args[1] == "--update" || args[1] == "--check"));
        if (!args.empty() && args[0] == "aa-table" && table_args) return marked_table("aa-table", aa_table_text(), args);
        if (!args.empty() && args[0] == "m1-table" && table_args) return marked_table("m1-table", m1cp::error_time_table(), args);
        if (!args.empty() && args[0] == "m3-table" && table_args) return marked_table("m3-table", m3cp::error_time_tables(), args);
        if (!args.empty() && args[0] == "m4-table" && table_args) {
            const int rc = marked_table("m4-table", m4cp::error_time_tables(), args);
            // The chart beside the lesson: written with --update; with --check it must exist
            // (its times are this machine's, so only its size is checked).
            if (rc != 0 || args.size() != 3) return rc;
            const fs::path chart = fs::path(args[2]).parent_path() / "error_vs_time.png";
            if (args[1] == "--update") {
                raster::write_png(chart.string(), m4cp::error_time_chart());
                std::cout << "wrote " << chart.string() << "\n";
                return 0;
            }
            const raster::Image img = raster::read_png(chart.string());
            if (img.width() != raster::PlotSpec{}.width) {
                std::cerr << chart.string() << " is missing or not the chart; run `make lesson-tables`\n";
                return 1;
            }
            return 0;
        }
        if (!args.empty() && args[0] == "m5-table" && table_args) {
            // Lesson 5's three tables, each between its own markers, and the filters' chart
            // beside the lesson (written with --update; with --check it must exist).
            int rc = marked_table("m5-filters", m5cp::filter_table(), args);
            if (rc == 0) rc = marked_table("m5-shadows", m5cp::shadow_table(), args);
            if (rc == 0) rc = marked_table("m5-needs", m5cp::needs_table(), args);
            if (rc != 0 || args.size() != 3) return rc;
            const fs::path chart = fs::path(args[2]).parent_path() / "error_vs_time.png";
            if (args[1] == "--update") {
                raster::write_png(chart.string(), m5cp::error_time_chart());
                std::cout << "wrote " << chart.string() << "\n";
                return 0;
            }
            if (raster::read_png(chart.string()).width() != raster::PlotSpec{}.width) {
                std::cerr << chart.string() << " is missing or not the chart; run `make lesson-tables`\n";
                return 1;
            }
            return 0;
        }
        if (args.size() >= 2 && args[0] == "todo-table" &&
            (args.size() == 2 || (args.size() == 4 && (args[2] == "--update" || args[2] == "--check")))) {
            std::vector<std::string> rest = {args[0]};
            rest.insert(rest.end(), args.begin() + 2, args.end());
            return marked_table("todo-table", todo_table_text(args[1]), rest, false);
        }
    } catch (const std::exception& e) {
        std::cerr << "reference_tool: " << e.what() << "\n";
        return 1;
    }
    std::cerr << "usage: reference_tool expected | verify | gallery <dir> | aa-table|m1-table|m3-table|m4-table|m5-table [--update|--check FILE]\n"
                 "       reference_tool todo-table m1|m2|m3|m4|m5 [--update|--check FILE]\n";
    return 2;
}
