// Milestone 2 playground: this file is yours. Draw whatever you want to look at with YOUR
// triangles.cpp; `make` rebuilds it with your current code, and the checkpoints never read it.
//
//   ./checkpoints/playground_m2 [output-folder]     (default: playground_out/m2)
//
// Each picture below is written as a PNG into the output folder. Add your own: a triangle
// with an edge through pixel centers, two triangles sharing an edge, a needle, a vertex far
// outside the image...
#include <filesystem>
#include <iostream>
#include <string>

#include "raster/io.h"
#include "triangles.h"

using raster::Color;
using raster::Image;
using raster::Vec2;

int main(int argc, char** argv) {
    const std::filesystem::path out = argc > 1 ? argv[1] : "playground_out/m2";
    std::filesystem::create_directories(out);
    auto save = [&](const std::string& name, const Image& img) {
        const std::string path = (out / (name + ".png")).string();
        raster::write_png(path, img);
        std::cout << "wrote " << path << "\n";
    };

    {
        // One solid triangle and one with per-vertex colors.
        Image img(96, 64);
        m2::fill_triangle(img, {4.5, 6.0}, {44.0, 14.5}, {12.25, 58.0}, {230, 80, 60});
        m2::fill_triangle_gradient(img, {60.0, 4.0}, {92.0, 58.0}, {50.0, 50.0}, {255, 0, 0}, {0, 255, 0},
                                   {0, 0, 255});
        save("triangles", img);
    }
    {
        // A square split along its diagonal: the two halves share an edge through pixel
        // centers. Each center on it must be drawn exactly once (top-left rule).
        Image img(32, 32);
        m2::fill_triangle(img, {4.5, 4.5}, {27.5, 4.5}, {4.5, 27.5}, {60, 170, 90});
        m2::fill_triangle(img, {27.5, 4.5}, {27.5, 27.5}, {4.5, 27.5}, {70, 110, 230});
        save("shared_edge", img);
    }
    {
        // The same triangle with 1, 4, 16 and 64 samples per pixel, side by side.
        Image img(128, 40);
        for (int k = 0; k < 4; ++k) {
            const double x = 32.0 * k;
            m2::fill_triangle_aa(img, {x + 3.3, 4.7}, {x + 29.6, 12.2}, {x + 9.1, 36.4}, {255, 255, 255}, 1 << k);
        }
        save("antialiasing", img);
    }
    return 0;
}
