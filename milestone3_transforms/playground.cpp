// Milestone 3 playground: this file is yours. Draw whatever you want to look at with YOUR
// transforms.cpp (and your own milestones 1 and 2); `make` rebuilds it with your current code,
// and the checkpoints never read it.
//
//   ./checkpoints/playground_m3 [output-folder]     (default: playground_out/m3)
//
// Try: move the camera behind the cube, set the field of view to 170 degrees, put the near
// plane through the cube, turn culling off and on, draw a triangle reaching behind the camera.
#include <filesystem>
#include <iostream>
#include <string>

#include "raster/io.h"
#include "transforms.h"

using raster::Image;
using raster::Vec3;

int main(int argc, char** argv) {
    const std::filesystem::path out = argc > 1 ? argv[1] : "playground_out/m3";
    std::filesystem::create_directories(out);
    auto save = [&](const std::string& name, const Image& img) {
        const std::string path = (out / (name + ".png")).string();
        raster::write_png(path, img);
        std::cout << "wrote " << path << "\n";
    };

    // A cube from its 8 corners, as 12 triangles counter-clockwise from outside, and 12 edges.
    m3::Model cube;
    for (int i = 0; i < 8; ++i) cube.positions.push_back({i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0});
    cube.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 4, 6}, {0, 6, 2},
                      {1, 3, 7}, {1, 7, 5}, {0, 1, 5}, {0, 5, 4}, {2, 6, 7}, {2, 7, 3}};
    cube.edges = {{0, 1}, {1, 3}, {3, 2}, {2, 0}, {4, 5}, {5, 7}, {7, 6}, {6, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    cube.face_colors = {{230, 80, 60},  {230, 80, 60},  {60, 170, 90}, {60, 170, 90}, {70, 110, 230}, {70, 110, 230},
                        {230, 200, 60}, {230, 200, 60}, {170, 80, 200}, {170, 80, 200}, {60, 190, 200}, {60, 190, 200}};

    const m3::Mat4 view = m3::look_at({3, 2, 4}, {0, 0, 0}, {0, 1, 0});
    const m3::Mat4 proj = m3::perspective(50, 1, 0.1, 100);
    {
        Image img(128, 128);
        m3::draw_model(img, cube, m3::identity(), view, proj, {false, true, false, true, false}, {255, 255, 255});
        save("wireframe", img);
    }
    {
        Image img(128, 128);
        const m3::Stats st = m3::draw_model(img, cube, m3::rotate({0, 1, 0}, 0.5), view, proj,
                                            {true, false, true, true, false}, {255, 255, 255});
        std::cout << "solid cube: " << st.triangles_filled << " triangles filled, " << st.triangles_culled << " culled\n";
        save("solid", img);
    }
    return 0;
}
