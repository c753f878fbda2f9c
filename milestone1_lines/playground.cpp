// Milestone 1 playground: this file is yours. Draw whatever you want to look at with YOUR
// lines.cpp; `make` rebuilds it with your current code, and the checkpoints never read it.
//
//   ./checkpoints/playground_m1 [output-folder]     (default: playground_out/m1)
//
// Each picture below is written as a PNG into the output folder. Add your own: a line you
// doubt, the same line drawn from both ends, a line from far outside the image, an
// anti-aliased line next to its aliased twin...
#include <filesystem>
#include <iostream>
#include <string>

#include "lines.h"
#include "raster/io.h"

using raster::Color;
using raster::Image;
using raster::Vec2;

int main(int argc, char** argv) {
    const std::filesystem::path out = argc > 1 ? argv[1] : "playground_out/m1";
    std::filesystem::create_directories(out);
    auto save = [&](const std::string& name, const Image& img) {
        const std::string path = (out / (name + ".png")).string();
        raster::write_png(path, img);
        std::cout << "wrote " << path << "\n";
    };

    {
        // A fan of lines from one pixel: every octant, and the axes and diagonals between them.
        Image img(64, 64);
        const Vec2 tips[] = {{60.5, 32.5}, {60.5, 46.5}, {60.5, 60.5}, {46.5, 60.5}, {32.5, 60.5},
                             {18.5, 60.5}, {4.5, 60.5},  {4.5, 46.5},  {4.5, 32.5},  {4.5, 18.5},
                             {4.5, 4.5},   {18.5, 4.5},  {32.5, 4.5},  {46.5, 4.5},  {60.5, 4.5},
                             {60.5, 18.5}};
        int k = 0;
        for (const Vec2 tip : tips) {
            m1::draw_line(img, {32.5, 32.5}, tip, k++ % 2 == 0 ? Color{255, 255, 255} : Color{255, 200, 0});
        }
        save("fan", img);
    }
    {
        // The same line, aliased (top) and anti-aliased (bottom).
        Image img(64, 32);
        m1::draw_line(img, {2.5, 3.2}, {61.5, 12.7}, {255, 255, 255});
        m1::draw_line_aa(img, {2.5, 19.2}, {61.5, 28.7}, {255, 255, 255});
        save("aliased_vs_wu", img);
    }
    {
        // clip_line against a rectangle: gray is the whole segment, green what was kept.
        Image img(64, 64);
        const m1::Rect r{12.5, 16.5, 50.5, 44.5};
        m1::draw_line(img, {r.xmin, r.ymin}, {r.xmax, r.ymin}, {40, 90, 200});
        m1::draw_line(img, {r.xmax, r.ymin}, {r.xmax, r.ymax}, {40, 90, 200});
        m1::draw_line(img, {r.xmax, r.ymax}, {r.xmin, r.ymax}, {40, 90, 200});
        m1::draw_line(img, {r.xmin, r.ymax}, {r.xmin, r.ymin}, {40, 90, 200});
        Vec2 a{2.0, 6.0}, b{61.0, 55.0};
        m1::draw_line(img, a, b, {70, 70, 70});
        if (m1::clip_line(a, b, r)) m1::draw_line(img, a, b, {60, 220, 90});
        save("clipping", img);
    }
    {
        // Endpoints far outside the image: only the visible part is drawn, and quickly.
        Image img(64, 64);
        m1::draw_line(img, {-1e9, 10.5}, {1e9, 50.5}, {255, 255, 255});
        m1::draw_line_aa(img, {1e300, 40.5}, {-1e300, 44.5}, {0, 200, 255});
        save("far_away", img);
    }
    return 0;
}
