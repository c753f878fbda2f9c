// bug_tool: the library of known-bug pictures behind "your picture matches what happens when
// ..." (see harness/diagnosis.h), and the lessons' troubleshooting galleries. For maintainers;
// `make bug-pictures` (part of `make regenerate`) runs `update` for every milestone.
//
//   bug_tool update <m> <repo-root> <lesson.md> <work-dir> <skeleton-program>
//                   (<file.bug> <checkpoint-program>)...
//       Runs the skeleton's and each bug's checkpoint program on every scene, and rewrites checkpoints/bug_pictures/<m>/ (the index
//       bugs.txt, the skeleton's pictures, the pictures of the checkpoints each bug fails where
//       its picture differs from the expected image and from the skeleton's, and the gallery
//       images) and the troubleshooting section of the lesson.
//   bug_tool check <same arguments>
//       The same in <work-dir>; exits 1 when the committed library is not what it makes.
//   bug_tool gallery --update|--check <m> <repo-root> <lesson.md>
//       The lesson's troubleshooting section (between the troubleshooting markers) and the
//       gallery images, from the committed library alone.
//   bug_tool named <m> <work-dir> (<file.bug> <checkpoint-program>)...
//       End to end, as a student runs it: each bug's program on the checkpoint its gallery
//       shows must write a record whose diagnosis names the bug; exits 1 otherwise.
//   bug_tool rates <m> <min-hits-percent> <max-wrong-percent>
//       Measures the diagnosis on the committed library (in-sample and leave-one-out, see
//       DiagnosisRates); exits 1 if that is not what the index says or misses a threshold.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "harness/checkpoint.h"
#include "harness/diagnosis.h"
#include "harness/record.h"
#include "raster/compare.h"
#include "raster/io.h"

namespace fs = std::filesystem;

namespace {

struct BugSource {
    std::string name, summary, lesson, fix, says;
    std::string blames;  // "TODO 1: multiplication order, matrix": what every failing checkpoint must name
    std::vector<std::string> must_fail;
    fs::path file, program;
};

std::string read_text(const fs::path& p) {
    std::ifstream in(p);
    if (!in) throw std::runtime_error("cannot read " + p.string());
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

void write_text(const fs::path& p, const std::string& text) {
    std::ofstream out(p);
    if (!out) throw std::runtime_error("cannot write " + p.string());
    out << text;
}

std::string shell_quote(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r"), e = s.find_last_not_of(" \t\r");
    return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

// The header lines of a .bug file (the find/replace blocks are srctool's business).
BugSource read_bug(const fs::path& file, const fs::path& program) {
    BugSource b;
    b.name = file.stem().string();
    b.file = file;
    b.program = program;
    std::istringstream in(read_text(file));
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("@@", 0) == 0) break;
        const auto colon = line.find(':');
        if (colon == std::string::npos) continue;
        const std::string key = line.substr(0, colon), v = trim(line.substr(colon + 1));
        if (key == "summary") b.summary = v;
        if (key == "lesson") b.lesson = v;
        if (key == "fix") b.fix = v;
        if (key == "says") b.says = v;
        if (key == "blames") b.blames = v;
        if (key == "must_fail") {
            std::istringstream w(v);
            for (std::string id; w >> id;) b.must_fail.push_back(id);
        }
    }
    return b;
}

// ---- the lesson ----

struct Heading {
    std::string text;  // without the leading #s
    std::size_t line = 0;
};

std::vector<Heading> headings(const std::string& lesson) {
    std::vector<Heading> out;
    std::istringstream in(lesson);
    std::size_t n = 0;
    bool fenced = false;
    for (std::string line; std::getline(in, line); ++n) {
        if (line.rfind("```", 0) == 0) fenced = !fenced;
        if (fenced || line.rfind("##", 0) != 0) continue;
        out.push_back({trim(line.substr(line.find_first_not_of('#'))), n});
    }
    return out;
}

// GitHub's anchor for a heading: lower case, punctuation other than - and _ dropped, spaces
// turned into hyphens.
// A symptom as the student's `make check` prints it: the bugs' pictures are made with a watchdog
// of 1 s (RASTER_WATCHDOG_SECONDS=1 above, to be quick), make check stops a render after
// kDefaultWatchdogSeconds.
std::string as_make_check_says(std::string symptom) {
    const std::string quick = "was still running after 1 s", slow = "was still running after ";
    std::ostringstream usual;
    usual << slow << cp::kDefaultWatchdogSeconds << " s";
    for (std::size_t at = symptom.find(quick); at != std::string::npos; at = symptom.find(quick, at)) {
        symptom.replace(at, quick.size(), usual.str());
        at += usual.str().size();
    }
    return symptom;
}

std::string anchor(const std::string& heading) {
    std::string out;
    for (char c : heading) {
        const unsigned char u = static_cast<unsigned char>(c);
        if (std::isalnum(u) || c == '-' || c == '_') out += static_cast<char>(std::tolower(u));
        else if (c == ' ') out += '-';
    }
    return out;
}

// ---- running the bug programs ----

int run(const std::string& command) {
    const int status = std::system(command.c_str());
    return status;
}

std::vector<std::string> checkpoint_ids(const fs::path& program, const fs::path& work) {
    const fs::path list = work / "ids.txt";
    run(shell_quote(program.string()) + " --list-test-names-only > " + shell_quote(list.string()) + " 2>/dev/null");
    std::vector<std::string> ids;
    std::istringstream in(read_text(list));
    for (std::string line; std::getline(in, line);) {
        line = trim(line);
        if (!line.empty() && line.find(' ') == std::string::npos) ids.push_back(line);
    }
    if (ids.empty()) throw std::runtime_error(program.string() + " lists no checkpoints");
    return ids;
}

struct BugRun {
    std::vector<std::string> ids;               // every checkpoint, in the suite's order
    std::map<std::string, cp::Record> records;  // by id, from the judge half
    fs::path artifacts;
};

// Runs one bug's checkpoint program on every checkpoint, with its own folders. A checkpoint
// that crashes the program takes the rest with it, so checkpoints without a verdict are run
// again one by one; one that still has none keeps the record "crashed".
BugRun run_bug(const BugSource& bug, const fs::path& work) {
    const fs::path dir = work / bug.name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    BugRun r;
    r.ids = checkpoint_ids(bug.program, dir);
    r.artifacts = dir / "output";  // <id>/actual.png: the main image as drawn
    const fs::path results = dir / "results";
    const std::string run_all = "cd " + shell_quote(dir.string()) +
                                " && RASTER_WATCHDOG_SECONDS=1 RASTER_RESULTS_DIR=" + shell_quote(results.string()) +
                                " RASTER_OUTPUT_DIR=" + shell_quote(r.artifacts.string()) + " timeout 120 " +
                                shell_quote(bug.program.string());
    run(run_all + " > run.log 2>&1");
    auto verdicts = [&] {
        std::map<std::string, cp::Record> by_id;
        for (cp::Record& rec : cp::read_records(results.string())) by_id[rec.id] = std::move(rec);
        return by_id;
    };
    r.records = verdicts();
    bool again = false;
    for (const std::string& id : r.ids) {
        const auto it = r.records.find(id);
        if (it == r.records.end() || it->second.status == "crashed") {
            run(run_all + " " + shell_quote(id) + " >> run.log 2>&1");
            again = true;
        }
    }
    if (again) r.records = verdicts();
    return r;
}

// ---- the library ----

struct Built {
    cp::BugLibrary lib;
    std::map<std::string, raster::Image> expected;  // by scene
};

raster::Image expected_image(Built& b, const std::string& scene) {
    auto it = b.expected.find(scene);
    if (it == b.expected.end()) {
        it = b.expected.emplace(scene, raster::read_png(cp::expected_png_path(b.lib.milestone, scene))).first;
    }
    return it->second;
}

std::vector<raster::Image> expected_per_picture(Built& b) {
    std::vector<raster::Image> out;
    for (const cp::BugPicture& p : b.lib.pictures) out.push_back(expected_image(b, p.scene));
    return out;
}

std::string resolve_lesson(const BugSource& bug, const std::vector<Heading>& hs, const fs::path& lesson_path) {
    if (bug.lesson.empty()) {
        std::cerr << "warning: " << bug.file.string() << " has no lesson: line (the section of "
                  << lesson_path.string() << " to reread)\n";
        return {};
    }
    for (const Heading& h : hs) {
        if (h.text.find(bug.lesson) != std::string::npos) return h.text;
    }
    throw std::runtime_error(bug.file.string() + ": 'lesson: " + bug.lesson + "' names no section of " +
                             lesson_path.string());
}

Built build_library(const std::string& m, const fs::path& root, const fs::path& lesson, const fs::path& work,
                    const fs::path& skeleton, const std::vector<BugSource>& bugs) {
    Built b;
    b.lib.milestone = m;
    b.lib.lesson_file = fs::relative(lesson, root).generic_string();
    const auto hs = headings(read_text(lesson));
    {
        BugSource untouched;
        untouched.name = "skeleton";
        untouched.program = skeleton;
        const BugRun run = run_bug(untouched, work);
        for (const std::string& id : run.ids) {
            const fs::path main = run.artifacts / id / "actual.png";
            if (!fs::exists(main)) continue;
            const raster::Image img = raster::read_png(main.string());
            const raster::Image expected = expected_image(b, id);
            const auto d = cp::differing_pixels(img, expected);
            const long long n = std::count(d.begin(), d.end(), 1);
            if (n > 0 && img.width() == expected.width() && img.height() == expected.height()) {
                b.lib.skeleton.push_back({"", id, n, img, {}});
            }
        }
    }
    auto like_skeleton = [&](const std::string& id, const raster::Image& img) {
        for (const cp::BugPicture& p : b.lib.skeleton) {
            if (p.scene == id && cp::same_symptom(p.image, img, expected_image(b, id))) return true;
        }
        return false;
    };
    for (const BugSource& src : bugs) {
        const BugRun run = run_bug(src, work);
        cp::KnownBug k;
        k.name = src.name;
        k.summary = src.summary;
        k.lesson = resolve_lesson(src, hs, lesson);
        k.fix = src.fix;
        k.says = src.says;
        k.todo = src.blames.substr(0, src.blames.find(':'));  // "TODO 8", or empty
        std::vector<cp::BugPicture> pictures;
        for (const std::string& id : run.ids) {
            const auto rec = run.records.find(id);
            if (rec == run.records.end() || rec->second.status == "pass") continue;
            k.fails.push_back(id);
            const fs::path main = run.artifacts / id / "actual.png";
            if (rec->second.status != "fail" || !fs::exists(main)) continue;
            const raster::Image img = raster::read_png(main.string());
            const raster::Image expected = expected_image(b, id);
            const auto d = cp::differing_pixels(img, expected);
            const long long n = std::count(d.begin(), d.end(), 1);
            if (n > 0 && img.width() == expected.width() && img.height() == expected.height() && !like_skeleton(id, img)) {
                std::vector<std::string> clues;
                for (const std::string& f : rec->second.findings) {
                    if (cp::steers_diagnosis(f)) clues.push_back(f);
                }
                pictures.push_back({src.name, id, n, img, clues});
            }
        }
        // The gallery shows the first checkpoint the bug file names that has a picture (else
        // any with a picture, else the first named one it fails), with that checkpoint's
        // finding on the bug's concept (else its first finding).
        std::string shown;
        for (const std::string& id : src.must_fail) {
            for (const cp::BugPicture& p : pictures) {
                if (shown.empty() && p.scene == id) shown = id;
            }
        }
        if (shown.empty() && !pictures.empty()) shown = pictures.front().scene;
        for (const std::string& id : src.must_fail) {
            if (shown.empty() && std::find(k.fails.begin(), k.fails.end(), id) != k.fails.end()) shown = id;
        }
        if (shown.empty() && !k.fails.empty()) shown = k.fails.front();
        if (!shown.empty()) {
            const cp::Record& rec = run.records.at(shown);
            k.symptom_scene = shown;
            // The finding that names the bug's concept says most about it; else the first.
            k.symptom = rec.findings.empty() ? "the checkpoint " + rec.status : rec.findings.front();
            for (const std::string& f : rec.findings) {
                if (f.rfind("[" + src.says + "]", 0) == 0) {
                    k.symptom = f;
                    break;
                }
            }
        }
        b.lib.bugs.push_back(k);
        for (cp::BugPicture& p : pictures) b.lib.pictures.push_back(std::move(p));
    }
    b.lib.rates = cp::measure_rates(b.lib, expected_per_picture(b));
    return b;
}

// The gallery picture of a bug: expected | with the bug | where they differ, in the colors of
// make check's diff.png (cp::kDiffLegend: red where the bug's pixel differs by more than
// kPixelNoise levels, blue where it differs by less, on the expected picture dimmed), each
// magnified with sharp pixels. Wide scenes stack the three vertically.
raster::Image gallery_picture(const raster::Image& expected, const raster::Image& bug) {
    const int w = expected.width(), h = expected.height();
    const int k = std::max(1, 192 / std::max(w, h));
    const bool vertical = w > 2 * h;
    const int gap = 6;
    const int W = vertical ? w * k : 3 * w * k + 2 * gap, H = vertical ? 3 * h * k + 2 * gap : h * k;
    raster::Image out(W, H, raster::Color{90, 90, 90});
    for (int panel = 0; panel < 3; ++panel) {
        const int ox = vertical ? 0 : panel * (w * k + gap), oy = vertical ? panel * (h * k + gap) : 0;
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const raster::Color e = expected.at(x, y), g = bug.at(x, y);
                raster::Color c = panel == 0 ? e : g;
                if (panel == 2) {
                    const int d = std::max({std::abs(e.r - g.r), std::abs(e.g - g.g), std::abs(e.b - g.b)});
                    if (d > cp::kPixelNoise) {
                        c = cp::kDiffWrong;
                    } else if (d > 0) {
                        c = cp::kDiffAllowed;
                    } else {
                        c = {static_cast<std::uint8_t>(e.r / 4), static_cast<std::uint8_t>(e.g / 4),
                             static_cast<std::uint8_t>(e.b / 4)};
                    }
                }
                for (int j = 0; j < k; ++j) {
                    for (int i = 0; i < k; ++i) out.set(ox + x * k + i, oy + y * k + j, c);
                }
            }
        }
    }
    return out;
}

// The bugs in the order of the lesson sections they send the student to, then by name.
std::vector<const cp::KnownBug*> in_lesson_order(const cp::BugLibrary& lib, const std::vector<Heading>& hs) {
    std::vector<const cp::KnownBug*> out;
    for (const cp::KnownBug& b : lib.bugs) out.push_back(&b);
    auto pos = [&](const cp::KnownBug* b) {
        for (const Heading& h : hs) {
            if (h.text == b->lesson) return h.line;
        }
        return std::string::npos;
    };
    std::stable_sort(out.begin(), out.end(), [&](const cp::KnownBug* a, const cp::KnownBug* b) {
        return pos(a) != pos(b) ? pos(a) < pos(b) : a->name < b->name;
    });
    return out;
}

const char* kBegin = "<!-- troubleshooting";
const char* kEnd = "<!-- /troubleshooting -->";

std::string gallery_text(const cp::BugLibrary& lib, const fs::path& root, const fs::path& lesson) {
    const auto hs = headings(read_text(lesson));
    const std::string pics =
        fs::relative(fs::path(cp::bug_pictures_dir()) / lib.milestone / "gallery", lesson.parent_path()).generic_string();
    std::ostringstream out;
    out << kBegin << ": written by `make bug-pictures` from checkpoints/" << lib.milestone
        << "/bugs/*.bug; the project tests check it -->\n"
        << "Each mistake below is one of the deliberate bugs the project tests its checkpoints with. The picture "
           "shows the checkpoint that catches it: the expected image, the image with the bug, and where they differ, "
           "in the colors of `make check`'s diff.png ("
        << cp::kDiffLegend << "; here blue marks differences of at most " << cp::kPixelNoise
        << " levels). When a "
           "checkpoint of yours fails with a picture that matches one of these closely, `make check` names the bug "
           "and the section to reread.\n\n"
        << "How often that diagnosis is right, measured on the bugs themselves: " << cp::rates_text(lib.rates)
        << ".\n";
    (void)root;
    int n = 0;
    for (const cp::KnownBug* b : in_lesson_order(lib, hs)) {
        out << "\n### " << lib.milestone << "." << ++n << " " << b->name << "\n\n";
        const bool has_picture = std::any_of(lib.pictures.begin(), lib.pictures.end(), [&](const cp::BugPicture& p) {
            return p.bug == b->name && p.scene == b->symptom_scene;
        });
        if (has_picture) {
            out << "![" << b->symptom_scene << ": expected, with the bug, where they differ](" << pics << "/" << b->name
                << ".png)\n\n";
        }
        out << "- **Symptom**";
        if (!b->symptom_scene.empty()) out << " (`" << b->symptom_scene << "`)";
        out << ": " << (b->symptom.empty() ? "no checkpoint fails" : as_make_check_says(b->symptom)) << "\n";
        if (!has_picture && !b->symptom_scene.empty()) {
            out << "  No picture: here the bug changes no pixel by more than " << cp::kPixelNoise
                << " levels, or draws what an untouched TODO draws; the checkpoint catches it by exact values or by "
                   "the numbers your functions return.\n";
        }
        out << "- **Cause**: " << b->summary << "\n";
        if (!b->fix.empty()) out << "- **Fix**: " << b->fix << "\n";
        if (!b->lesson.empty()) out << "- **Reread**: [" << b->lesson << "](#" << anchor(b->lesson) << ")\n";
        out << "- **Caught by**: ";
        for (std::size_t i = 0; i < b->fails.size(); ++i) out << (i ? ", " : "") << "`" << b->fails[i] << "`";
        out << "\n";
    }
    out << kEnd;
    return out.str();
}

// The lesson with its troubleshooting section replaced; a lesson without one gets it at the end.
std::string lesson_with_gallery(const std::string& text, const std::string& gallery) {
    const auto b = text.find(kBegin), e = text.find(kEnd);
    if (b == std::string::npos || e == std::string::npos || e < b) {
        return text + (text.empty() || text.back() == '\n' ? "" : "\n") +
               "\n## Troubleshooting: pictures of known bugs\n\n" + gallery + "\n";
    }
    return text.substr(0, b) + gallery + text.substr(e + std::string(kEnd).size());
}

std::map<std::string, raster::Image> gallery_pictures(Built& b) {
    std::map<std::string, raster::Image> out;
    for (const cp::KnownBug& k : b.lib.bugs) {
        for (const cp::BugPicture& p : b.lib.pictures) {
            if (p.bug == k.name && p.scene == k.symptom_scene) {
                out[k.name + ".png"] = gallery_picture(expected_image(b, p.scene), p.image);
            }
        }
    }
    return out;
}

void write_library(Built& b, const fs::path& dir) {
    fs::remove_all(dir);
    fs::create_directories(dir / "gallery");
    write_text(dir / "bugs.txt", cp::bug_library_index(b.lib));
    if (!b.lib.skeleton.empty()) fs::create_directories(dir / "skeleton");
    for (const cp::BugPicture& p : b.lib.skeleton) raster::write_png((dir / "skeleton" / (p.scene + ".png")).string(), p.image);
    for (const cp::BugPicture& p : b.lib.pictures) {
        fs::create_directories(dir / p.bug);
        raster::write_png((dir / p.bug / (p.scene + ".png")).string(), p.image);
    }
    for (const auto& [name, img] : gallery_pictures(b)) raster::write_png((dir / "gallery" / name).string(), img);
}

std::set<std::string> files_under(const fs::path& dir) {
    std::set<std::string> out;
    if (!fs::is_directory(dir)) return out;
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
        if (e.is_regular_file()) out.insert(fs::relative(e.path(), dir).generic_string());
    }
    return out;
}

// Problems between a freshly made library folder and the committed one (PNG files may differ by
// one level, as expected images may between compilers).
std::vector<std::string> compare_folders(const fs::path& fresh, const fs::path& committed) {
    std::vector<std::string> problems;
    const auto a = files_under(fresh), b = files_under(committed);
    for (const std::string& f : a) {
        if (!b.count(f)) {
            problems.push_back("missing: " + (committed / f).string());
        } else if (fs::path(f).extension() == ".png") {
            const raster::ImageMetrics m =
                raster::compare(raster::read_png((fresh / f).string()), raster::read_png((committed / f).string()));
            if (!m.same_size || m.max_channel_diff > 1) problems.push_back("differs: " + (committed / f).string());
        } else if (read_text(fresh / f) != read_text(committed / f)) {
            problems.push_back("differs: " + (committed / f).string());
        }
    }
    for (const std::string& f : b) {
        if (!a.count(f)) problems.push_back("stale: " + (committed / f).string());
    }
    return problems;
}

int update_or_check(bool update, const std::vector<std::string>& args) {
    if (args.size() < 6 || (args.size() - 6) % 2 != 0) throw std::runtime_error("update/check: bad arguments");
    const std::string m = args[1];
    const fs::path root = args[2], lesson = args[3], work = fs::absolute(fs::path(args[4]) / m), skeleton = args[5];
    std::vector<BugSource> bugs;
    for (std::size_t i = 6; i + 1 < args.size(); i += 2) bugs.push_back(read_bug(args[i], args[i + 1]));
    std::sort(bugs.begin(), bugs.end(), [](const BugSource& a, const BugSource& b) { return a.name < b.name; });
    Built b = build_library(m, root, lesson, work / "runs", skeleton, bugs);
    const fs::path committed = fs::path(cp::bug_pictures_dir()) / m;
    const std::string text = read_text(lesson);
    const std::string with_gallery = lesson_with_gallery(text, gallery_text(b.lib, root, lesson));
    if (update) {
        write_library(b, committed);
        if (with_gallery != text) write_text(lesson, with_gallery);
        std::cout << m << ": " << b.lib.pictures.size() << " bug pictures of " << b.lib.bugs.size() << " bugs in "
                  << committed.string() << "\n  " << cp::rates_text(b.lib.rates) << "\n";
        return 0;
    }
    write_library(b, work / "library");
    auto problems = compare_folders(work / "library", committed);
    if (with_gallery != text) problems.push_back(lesson.string() + ": the troubleshooting gallery is out of date");
    for (const std::string& p : problems) std::cout << p << "\n";
    if (!problems.empty()) {
        std::cout << "The known-bug pictures of " << m
                  << " are out of date (a bug, a scene, the reference or a message changed): run `make bug-pictures` "
                     "(or `make regenerate`) in the build folder and commit the result.\n";
        return 1;
    }
    std::cout << m << ": the " << b.lib.pictures.size() << " known-bug pictures are current\n";
    return 0;
}

int gallery(const std::vector<std::string>& args) {
    if (args.size() != 5 || (args[1] != "--update" && args[1] != "--check")) throw std::runtime_error("gallery: bad arguments");
    const std::string m = args[2];
    const fs::path root = args[3], lesson = args[4];
    Built b;
    b.lib = cp::read_bug_library(cp::bug_pictures_dir(), m, "*");
    const fs::path dir = fs::path(cp::bug_pictures_dir()) / m;
    const std::string text = read_text(lesson);
    const std::string with_gallery = lesson_with_gallery(text, gallery_text(b.lib, root, lesson));
    const auto pictures = gallery_pictures(b);
    if (args[1] == "--update") {
        fs::remove_all(dir / "gallery");
        fs::create_directories(dir / "gallery");
        for (const auto& [name, img] : pictures) raster::write_png((dir / "gallery" / name).string(), img);
        if (with_gallery != text) write_text(lesson, with_gallery);
        return 0;
    }
    int bad = 0;
    if (text.find(kBegin) == std::string::npos) {
        std::cout << lesson.string() << ": no troubleshooting markers\n";
        ++bad;
    } else if (with_gallery != text) {
        std::cout << lesson.string() << ": the troubleshooting gallery is out of date\n";
        ++bad;
    }
    std::set<std::string> names;
    for (const auto& [name, img] : pictures) {
        names.insert(name);
        const fs::path p = dir / "gallery" / name;
        if (!fs::exists(p) || !(raster::read_png(p.string()) == img)) {
            std::cout << "differs or missing: " << p.string() << "\n";
            ++bad;
        }
    }
    for (const std::string& f : files_under(dir / "gallery")) {
        if (!names.count(f)) {
            std::cout << "stale: " << (dir / "gallery" / f).string() << "\n";
            ++bad;
        }
    }
    if (bad) {
        std::cout << "run `make bug-pictures` (or `make regenerate`) in the build folder\n";
        return 1;
    }
    std::cout << lesson.string() << ": the troubleshooting gallery is current\n";
    return 0;
}

int named(const std::vector<std::string>& args) {
    if (args.size() < 3 || (args.size() - 3) % 2 != 0) throw std::runtime_error("named: bad arguments");
    const std::string m = args[1];
    const fs::path work = fs::absolute(fs::path(args[2]) / m);
    const cp::BugLibrary lib = cp::read_bug_library(cp::bug_pictures_dir(), m, "");
    int checked = 0, bad = 0;
    for (std::size_t i = 3; i + 1 < args.size(); i += 2) {
        const BugSource src = read_bug(args[i], args[i + 1]);
        const cp::KnownBug* k = lib.bug(src.name);
        if (!k) {
            std::cout << src.name << ": not in the library; run `make bug-pictures`\n";
            ++bad;
            continue;
        }
        const bool has_picture = std::any_of(lib.pictures.begin(), lib.pictures.end(), [&](const cp::BugPicture& p) {
            return p.bug == k->name && p.scene == k->symptom_scene;
        });
        if (!has_picture) continue;
        const fs::path dir = work / src.name;
        fs::remove_all(dir);
        fs::create_directories(dir);
        run("cd " + shell_quote(dir.string()) + " && RASTER_RESULTS_DIR=results RASTER_OUTPUT_DIR=output timeout 60 " +
            shell_quote(src.program.string()) + " " + shell_quote(k->symptom_scene) + " > out.log 2>&1");
        const auto records = cp::read_records((dir / "results").string());
        const bool ok = records.size() == 1 && records[0].diagnosis.find("(" + src.name + ")") != std::string::npos;
        ++checked;
        if (!ok) {
            std::cout << src.name << " on " << k->symptom_scene << ": the record's diagnosis is '"
                      << (records.empty() ? std::string("(no record)") : records[0].diagnosis) << "'\n";
            ++bad;
        }
    }
    std::cout << m << ": " << checked - bad << " of " << checked << " bugs named by the diagnosis on their gallery checkpoint\n";
    return bad ? 1 : 0;
}

// The TODO numbers of every "(TODO 4)", "(TODOs 1-2)" or "(TODOs 5, 6)" in a finding line.
std::vector<std::set<int>> todo_labels(const std::string& line) {
    std::vector<std::set<int>> out;
    for (std::size_t at = line.find("(TODO"); at != std::string::npos; at = line.find("(TODO", at + 1)) {
        const std::size_t end = line.find(')', at);
        if (end == std::string::npos) break;
        std::string list = line.substr(at + 5, end - at - 5);
        if (!list.empty() && list[0] == 's') list.erase(0, 1);
        std::set<int> todos;
        std::istringstream in(list);
        for (std::string part; std::getline(in, part, ',');) {
            int lo = 0, hi = 0;
            char dash = 0;
            std::istringstream p(part);
            if (!(p >> lo)) continue;
            hi = lo;
            if (p >> dash >> hi && dash != '-') hi = lo;
            for (int t = lo; t <= hi && t - lo < 100; ++t) todos.insert(t);
        }
        if (!todos.empty()) out.push_back(todos);
    }
    return out;
}

// bug_tool blames <work-dir> <file.bug> <program>: runs the bug on every checkpoint; each one
// that fails must tag one of the concepts of the bug's "blames:" line, and no finding of it may
// name a TODO other than the bug's (a later checkpoint sending the student to the wrong TODO).
int blames(const std::vector<std::string>& args) {
    if (args.size() != 4) throw std::runtime_error("blames: bad arguments");
    const BugSource src = read_bug(args[2], fs::absolute(args[3]));  // run from its own folder
    const auto colon = src.blames.find(':');
    if (src.blames.rfind("TODO ", 0) != 0 || colon == std::string::npos) {
        throw std::runtime_error(src.file.string() + ": blames: must read 'TODO <n>: <concept>[, <concept>...]'");
    }
    const std::set<int> allowed = todo_labels("(" + src.blames.substr(0, colon) + ")").at(0);
    std::vector<std::string> concepts;
    std::istringstream in(src.blames.substr(colon + 1));
    for (std::string c; std::getline(in, c, ',');) concepts.push_back(trim(c));
    const BugRun r = run_bug(src, fs::absolute(args[1]));
    int failing = 0, bad = 0;
    for (const std::string& id : r.ids) {
        const auto it = r.records.find(id);
        if (it == r.records.end() || it->second.status == "crashed") {
            std::cout << id << ": no verdict (crashed)\n";
            ++bad;
            continue;
        }
        const cp::Record& rec = it->second;
        if (rec.status != "fail") continue;
        ++failing;
        std::vector<std::string> problems;
        const std::string tags = "," + rec.concepts + ",";
        if (std::none_of(concepts.begin(), concepts.end(), [&](const std::string& c) { return tags.find("," + c + ",") != std::string::npos; })) {
            problems.push_back("its concepts are '" + rec.concepts + "', none of '" + src.blames.substr(colon + 1) + "'");
        }
        for (const std::string& line : rec.findings) {
            for (const std::set<int>& label : todo_labels(line)) {
                if (std::none_of(label.begin(), label.end(), [&](int t) { return allowed.count(t) > 0; })) {
                    problems.push_back("it blames another TODO: " + line);
                    break;
                }
            }
        }
        std::cout << id << ": " << (problems.empty() ? "names " + src.blames : "WRONG") << "\n";
        for (const std::string& p : problems) std::cout << "    " << p << "\n";
        for (const std::string& line : rec.findings) std::cout << "      " << line << "\n";
        bad += problems.empty() ? 0 : 1;
    }
    std::cout << src.name << ": " << failing - bad << " of " << failing << " failing checkpoints name " << src.blames << "\n";
    return bad ? 1 : 0;
}

int rates(const std::vector<std::string>& args) {
    if (args.size() != 4) throw std::runtime_error("rates: bad arguments");
    const std::string m = args[1];
    const double min_hits = std::stod(args[2]), max_wrong = std::stod(args[3]);
    Built b;
    b.lib = cp::read_bug_library(cp::bug_pictures_dir(), m, "*");
    std::ostringstream details;
    const cp::DiagnosisRates r = cp::measure_rates(b.lib, expected_per_picture(b), &details);
    std::cout << m << ": " << cp::rates_text(r) << "\n" << details.str();
    int bad = 0;
    if (r.in_sample_hits != b.lib.rates.in_sample_hits || r.in_sample_total != b.lib.rates.in_sample_total ||
        r.loo_wrong != b.lib.rates.loo_wrong || r.loo_total != b.lib.rates.loo_total) {
        std::cout << "the index says otherwise: " << cp::rates_text(b.lib.rates) << "; run `make bug-pictures`\n";
        ++bad;
    }
    if (r.in_sample_total > 0 && 100.0 * r.in_sample_hits < min_hits * r.in_sample_total) {
        std::cout << "in-sample hit rate below " << min_hits << "%\n";
        ++bad;
    }
    if (r.loo_total > 0 && 100.0 * r.loo_wrong > max_wrong * r.loo_total) {
        std::cout << "leave-one-out wrong claims above " << max_wrong << "%\n";
        ++bad;
    }
    return bad ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> args(argv + 1, argv + argc);
    try {
        if (!args.empty() && (args[0] == "update" || args[0] == "check")) return update_or_check(args[0] == "update", args);
        if (!args.empty() && args[0] == "gallery") return gallery(args);
        if (!args.empty() && args[0] == "rates") return rates(args);
        if (!args.empty() && args[0] == "named") return named(args);
        if (!args.empty() && args[0] == "blames") return blames(args);
    } catch (const std::exception& e) {
        std::cerr << "bug_tool: " << e.what() << "\n";
        return 1;
    }
    std::cerr << "usage: bug_tool update|check <m> <repo-root> <lesson.md> <work-dir> <skeleton-program> (<file.bug> <program>)...\n"
                 "       bug_tool gallery --update|--check <m> <repo-root> <lesson.md>\n"
                 "       bug_tool named <m> <work-dir> (<file.bug> <program>)...\n"
                 "       bug_tool rates <m> <min-hits-percent> <max-wrong-percent>\n"
                 "       bug_tool blames <work-dir> <file.bug> <program>\n";
    return 2;
}
