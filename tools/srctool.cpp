// srctool: derives files from the reference solutions, so nothing is maintained twice.
//
//   srctool skeleton <solution.cpp> <out.cpp>
//       The student's skeleton: every region from a line `// BEGIN SOLUTION` to a line
//       `// END SOLUTION` is replaced by the region's `// SKELETON: ` lines (prefix removed,
//       indentation kept). Unclosed, nested or stray markers are errors with a line number.
//
//   srctool mutate <source.cpp> <bug-file> <out.cpp>
//       A deliberately buggy implementation (a .bug file) or a correct variant (a .variant
//       file, which may instead give only compiler flags): the source with the file's
//       find/replace blocks applied. Each `find` text must occur exactly once, so a bug whose code has
//       changed in the reference fails loudly instead of silently testing nothing. Solution
//       markers are stripped from the output (their SKELETON lines dropped).
//
//   srctool check <solution.cpp> <skeleton.cpp>
//       Exit 1, with a diff hint, when the committed skeleton is not what `skeleton` makes.
//
// Bug file format (see checkpoints/m1/bugs/*.bug):
//   summary: one line describing the bug
//   must_fail: checkpoint ids that must catch it
//   says: the concept tag the failing checkpoint must name
//   lesson: (optional) the lesson section to reread, as text of its heading ("TODO 3: Bresenham")
//   fix: (optional) one sentence: what the right code does
//   blames: (optional) "TODO <n>: <concept>[, ...]": every finding of every checkpoint it fails
//       names that TODO and one of those concepts (bug_tool blames)
//   grading: (optional) "always": the grader's test grades this bug whatever its sample
//       (tools/grading/tests/grade_test.sh, bugs-mN): a path of the grader that only it takes
//   (summary, lesson and fix feed the known-bug diagnosis and the lesson's troubleshooting
//   gallery: see checkpoints/harness/diagnosis.h and checkpoints/bug_tool.cpp)
//   @@ find
//   ...exact lines from the source...
//   @@ replace
//   ...their replacement (may be empty)...
//   @@ end
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

std::vector<std::string> read_lines(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read " + path);
    std::vector<std::string> lines;
    std::string line;
    while (std::getline(in, line)) lines.push_back(line);
    return lines;
}

std::string join(const std::vector<std::string>& lines) {
    std::string out;
    for (const auto& l : lines) out += l + "\n";
    return out;
}

void write_file(const std::string& path, const std::string& text) {
    std::ofstream out(path);
    if (!out) throw std::runtime_error("cannot write " + path);
    out << text;
}

std::string trim_left(const std::string& s) { return s.substr(std::min(s.find_first_not_of(" \t"), s.size())); }

// keep_skeleton_lines: true for the student's skeleton, false for mutated reference copies.
std::string strip_solutions(const std::vector<std::string>& lines, const std::string& path,
                            bool keep_skeleton_lines) {
    const std::string begin = "// BEGIN SOLUTION", end = "// END SOLUTION", stub = "// SKELETON:";
    std::vector<std::string> out;
    bool in_region = false;
    std::size_t region_start = 0;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string t = trim_left(lines[i]);
        const std::string where = path + ":" + std::to_string(i + 1) + ": ";
        if (t == begin) {
            if (in_region) throw std::runtime_error(where + "nested BEGIN SOLUTION (the region opened at line " + std::to_string(region_start + 1) + " is not closed)");
            in_region = true;
            region_start = i;
        } else if (t == end) {
            if (!in_region) throw std::runtime_error(where + "END SOLUTION without BEGIN SOLUTION");
            in_region = false;
        } else if (in_region) {
            if (t.rfind(stub, 0) == 0) {
                if (!keep_skeleton_lines) continue;
                const std::string indent = lines[i].substr(0, lines[i].size() - t.size());
                std::string body = t.substr(stub.size());
                if (!body.empty() && body[0] == ' ') body.erase(0, 1);
                out.push_back(body.empty() ? "" : indent + body);
            } else if (!keep_skeleton_lines) {
                out.push_back(lines[i]);
            }
        } else {
            if (t.find("BEGIN SOLUTION") != std::string::npos || t.find("END SOLUTION") != std::string::npos ||
                t.rfind(stub, 0) == 0) {
                throw std::runtime_error(where + "marker is not alone on its line or is outside a region");
            }
            // A region that left nothing behind would leave two blank lines where the
            // solution had one on each side of it: the skeleton keeps one.
            if (keep_skeleton_lines && t.empty() && !out.empty() && trim_left(out.back()).empty()) continue;
            out.push_back(lines[i]);
        }
    }
    if (in_region) throw std::runtime_error(path + ":" + std::to_string(region_start + 1) + ": BEGIN SOLUTION is never closed");
    return join(out);
}

std::string skeleton_of(const std::string& solution) {
    return "// GENERATED from " + std::string("solutions/") + solution.substr(solution.rfind("solutions/") == std::string::npos ? 0 : solution.rfind("solutions/") + 10) +
           " by `make skeletons`. Fill in the TODOs; do not edit the rest.\n" +
           strip_solutions(read_lines(solution), solution, true);
}

std::string mutate(const std::string& source, const std::string& bug_path) {
    std::string text = strip_solutions(read_lines(source), source, false);
    const auto bug = read_lines(bug_path);
    enum { kHeader, kFind, kReplace } state = kHeader;
    std::vector<std::string> find, replace;
    int blocks = 0;
    for (std::size_t i = 0; i < bug.size(); ++i) {
        const std::string& l = bug[i];
        auto misplaced = [&](const char* what) {
            return std::runtime_error(bug_path + ":" + std::to_string(i + 1) + ": " + what +
                                      " (each block is @@ find, its text, @@ replace, its text, @@ end)");
        };
        if (l == "@@ find") {
            if (state != kHeader) throw misplaced("@@ find inside a block that no @@ end closed");
            state = kFind;
            find.clear();
            replace.clear();
        } else if (l == "@@ replace") {
            if (state != kFind) throw misplaced("@@ replace without its @@ find");
            state = kReplace;
        } else if (l == "@@ end") {
            if (state != kReplace) throw misplaced("@@ end without its @@ replace");
            const std::string f = join(find), r = join(replace);
            const auto at = text.find(f);
            if (find.empty() || at == std::string::npos || text.find(f, at + 1) != std::string::npos) {
                throw std::runtime_error(bug_path + ":" + std::to_string(i + 1) +
                                         ": the find block must occur exactly once in " + source +
                                         " (has the reference changed? update the bug)");
            }
            text.replace(at, f.size(), r);
            state = kHeader;
            ++blocks;
        } else if (state == kFind) {
            find.push_back(l);
        } else if (state == kReplace) {
            replace.push_back(l);
        }
    }
    if (state != kHeader) throw std::runtime_error(bug_path + ": the last block has no @@ end");
    bool has_flags = false;
    for (const auto& l : bug) has_flags |= l.rfind("flags:", 0) == 0;
    if (blocks == 0 && !has_flags) {
        throw std::runtime_error(bug_path + ": no @@ find / @@ replace / @@ end block (and no flags: line)");
    }
    return "// GENERATED: " + source + " with the bug " + bug_path + " applied.\n" + text;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const std::vector<std::string> args(argv + 1, argv + argc);
        if (args.size() == 3 && args[0] == "skeleton") {
            write_file(args[2], skeleton_of(args[1]));
            return 0;
        }
        if (args.size() == 4 && args[0] == "mutate") {
            write_file(args[3], mutate(args[1], args[2]));
            return 0;
        }
        if (args.size() == 3 && args[0] == "check") {
            std::ifstream in(args[2]);
            std::stringstream committed;
            committed << in.rdbuf();
            if (committed.str() != skeleton_of(args[1])) {
                std::cerr << args[2] << " is not the skeleton generated from " << args[1]
                          << ".\nRegenerate it with `make skeletons` (never edit a skeleton by hand).\n";
                return 1;
            }
            std::cout << args[2] << " matches " << args[1] << "\n";
            return 0;
        }
        std::cerr << "usage: srctool skeleton <solution> <out> | mutate <source> <bug> <out> | check <solution> <skeleton>\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "srctool: " << e.what() << "\n";
        return 1;
    }
}
