#include "harness/showcase.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "harness/html.h"
#include "raster/compare.h"
#include "raster/io.h"

namespace fs = std::filesystem;

namespace cp {

namespace {

// `text` in lines of at most `width` characters (a longer word gets a line of its own); a
// command in backquotes ("(`make check-m1`,") stays on one line.
std::string wrapped(const std::string& text, std::size_t width) {
    std::istringstream words(text);
    std::string word, line, out, more;
    while (words >> word) {
        while (std::count(word.begin(), word.end(), '`') % 2 == 1 && words >> more) word += " " + more;
        if (!line.empty() && line.size() + 1 + word.size() > width) {
            out += line + "\n";
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
    }
    return out + line + "\n";
}

}  // namespace

std::string demo_note(int milestone, bool earlier) {
    const std::string m = std::to_string(milestone);
    const std::string before = (milestone == 3 ? "1 and " : "1 to ") + std::to_string(milestone - 1);
    if (!earlier) {
        return "This demo draws with your milestone " + m + " code: run `make check-m" + m +
               "`, whose first failing checkpoint says what to fix.";
    }
    std::string checks;  // "`make check-m1`, `make check-m2`"
    for (int k = 1; k < milestone; ++k) {
        checks += (k > 1 ? ", `make check-m" : "`make check-m") + std::to_string(k) + "`";
    }
    return "This demo draws with your own milestones 1 to " + m + ", not only milestone " + m +
           " (the checkpoints of milestone " + m + " use the reference's milestones " + before +
           ", so they can pass while the demo cannot). Make the earlier milestones pass their own "
           "checkpoints first (" + checks + "), then `make check-m" + m + "`.";
}

int showcase(const std::vector<ShowItem>& items, const std::string& out_dir, const std::string& heading,
             const std::string& far_note) {
    fs::create_directories(out_dir);
    std::ofstream html(fs::path(out_dir) / "index.html");
    html << "<!doctype html><meta charset=utf-8><title>" << heading << "</title>\n"
         << "<style>body{font-family:sans-serif;background:#222;color:#eee}"
            "img{image-rendering:pixelated;width:256px;border:1px solid #555}"
            "td{padding:6px;vertical-align:top}</style>\n<h1>"
         << heading << "</h1>\n<table><tr><th>scene<th>rendered<th>expected<th>error<th>time</tr>\n";

    std::cout << heading << "\n"
              << std::left << std::setw(26) << "scene" << std::right << std::setw(12) << "px differ"
              << std::setw(12) << "mean err" << std::setw(10) << "PSNR" << std::setw(12) << "time ms"
              << "  file\n"
              << std::string(100, '-') << "\n";
    int status = 0;
    int far = 0;  // pictures with more than half their pixels off the expected image, or not drawn
    for (const ShowItem& item : items) {
        try {
            Artifacts a;
            const double seconds = time_best_of([&] { a = item.render(item.id); });
            const raster::Image& img = a.images.at("main");
            const fs::path png = fs::path(out_dir) / (item.id + ".png");
            raster::write_png(png.string(), img);
            const std::string expected_path = expected_png_path(item.milestone, item.id);
            std::string psnr = "-", differ = "-", mae = "-";
            if (fs::exists(expected_path)) {
                const raster::Image expected = raster::read_png(expected_path);
                const raster::ImageMetrics m = raster::compare(img, expected);
                // Far: most of it differs, or nothing is drawn where the expected image shows something.
                far += !m.same_size || m.differing_share > 0.5 || (one_color(img) && !one_color(expected));
                differ = std::to_string(m.differing_pixels);
                std::ostringstream s1, s2;
                s1 << std::fixed << std::setprecision(3) << m.mean_abs_error;
                s2 << std::fixed << std::setprecision(1) << m.psnr_db;
                mae = s1.str();
                psnr = std::isinf(m.psnr_db) ? "inf" : s2.str();
            }
            std::cout << std::left << std::setw(26) << item.id << std::right << std::setw(12) << differ
                      << std::setw(12) << mae << std::setw(10) << psnr << std::setw(12) << std::fixed
                      << std::setprecision(3) << seconds * 1e3 << "  " << png.string() << "\n";
            html << "<tr><td><b>" << item.id << "</b><br>" << item.title << "<td><img src=\"" << item.id
                 << ".png\"><td><img src=\"" << fs::absolute(expected_path).string() << "\"><td>" << differ
                 << " px differ<br>mean error " << mae << "<br>PSNR " << psnr << "<td>" << std::fixed << std::setprecision(3)
                 << seconds * 1e3 << " ms</tr>\n";
        } catch (const std::exception& e) {
            std::cout << std::left << std::setw(26) << item.id << " failed: " << e.what() << "\n";
            status = 1;
            ++far;
        }
    }
    html << "</table>\n";
    std::cout << std::string(100, '-') << "\n";
    if (far > 0 && !far_note.empty()) {
        const std::string count = std::to_string(far) + " of " + std::to_string(items.size()) +
                                  " pictures are far from the expected ones: more than half their pixels differ, "
                                  "nothing is drawn, or they could not be drawn.";
        std::cout << wrapped(count + " " + far_note, 100) << std::string(100, '-') << "\n";
        html << "<p>" << html_escape(count + " " + far_note) << "</p>\n";
    }
    std::cout << "Pictures and index.html: " << fs::absolute(out_dir).string() << "\n";
    return status;
}

}  // namespace cp
