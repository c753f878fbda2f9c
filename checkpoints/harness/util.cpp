// The judge side's small helpers: TODO labels, the TODOs a scene needs, expected-image paths,
// the judge's first look at an image. (The render side is in render_side.cpp.)
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <set>

#include "harness/checkpoint.h"
#include "harness/judging.h"

namespace fs = std::filesystem;

namespace cp {

std::string todo_list(std::vector<int> todos) {
    std::sort(todos.begin(), todos.end());
    todos.erase(std::unique(todos.begin(), todos.end()), todos.end());
    std::string out;
    for (std::size_t i = 0; i < todos.size();) {
        std::size_t j = i;
        while (j + 1 < todos.size() && todos[j + 1] == todos[j] + 1) ++j;
        // (Appended piece by piece: GCC 12 at -O3 warns falsely (-Wrestrict) about
        // `"literal" + std::to_string(...)`, an insert at the front of a temporary string.)
        if (!out.empty()) out += ", ";
        out += std::to_string(todos[i]);
        if (j > i) {
            out += '-';
            out += std::to_string(todos[j]);
        }
        i = j + 1;
    }
    return out;
}

bool one_color(const raster::Image& img) {
    if (img.empty()) return false;
    const std::uint8_t* p = img.data();
    for (std::size_t i = 3; i < img.size_bytes(); i += 3) {
        if (p[i] != p[0] || p[i + 1] != p[1] || p[i + 2] != p[2]) return false;
    }
    return true;
}

std::string todo_label(const std::vector<int>& todos) { return todo_label(todo_list(todos)); }

std::string todo_label(const std::string& list) {
    if (list.empty()) return "";
    return (list.find_first_of("-,") == std::string::npos ? "TODO " : "TODOs ") + list;
}

std::vector<int> needed_todos(const Suite& suite, const Artifacts& reference) {
    std::set<std::string> seen;
    std::vector<std::string> queue;
    for (const auto& [name, t] : reference.trace) {
        if (t.calls > 0) queue.push_back(name);
    }
    std::vector<int> todos;
    while (!queue.empty()) {
        const std::string name = queue.back();
        queue.pop_back();
        if (!seen.insert(name).second) continue;
        for (const StudentFunction& f : suite.functions) {
            if (f.name != name) continue;
            todos.insert(todos.end(), f.todos.begin(), f.todos.end());
            queue.insert(queue.end(), f.uses.begin(), f.uses.end());
        }
    }
    std::sort(todos.begin(), todos.end());
    todos.erase(std::unique(todos.begin(), todos.end()), todos.end());
    return todos;
}

std::string expected_png_path(const std::string& milestone, const std::string& id) {
    const fs::path dir = env_or("RASTER_EXPECTED_DIR", RASTER_DEFAULT_EXPECTED_DIR);
    return (dir / milestone / (id + ".png")).string();
}

const raster::Image* main_image_for_judging(const Artifacts& art, int width, int height, Judgement& j) {
    j.tolerance.lenient = raster::Mask(width, height);
    j.tolerance.wrong = raster::Mask(width, height);
    const auto it = art.images.find("main");
    if (it == art.images.end() || it->second.width() != width || it->second.height() != height) return nullptr;
    return &it->second;
}

std::vector<Finding> stray_write_findings(const Artifacts& art, const StrayFinding& per_function,
                                          const Finding& unattributed) {
    std::vector<Finding> out;
    if (art.stray_writes <= 0) return out;
    long long attributed = 0;
    for (const auto& [name, t] : art.trace) {
        if (t.stray_writes <= 0) continue;
        attributed += t.stray_writes;
        out.push_back(per_function(name, t.stray_writes));
    }
    if (attributed < art.stray_writes) {
        Finding f = unattributed;
        f.message = "your code asked to write " + plural(double(art.stray_writes - attributed), "pixel") +
                    " outside the image (Image::stray_writes): " + f.message;
        out.push_back(std::move(f));
    }
    return out;
}

}  // namespace cp
