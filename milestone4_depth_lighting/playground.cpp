// Milestone 4 playground: this file is yours. Draw whatever you want to look at with YOUR
// depth_lighting.cpp (and your own milestones 1 to 3); `make` rebuilds it with your current
// code, and the checkpoints never read it.
//
//   ./checkpoints/playground_m4 [output-folder]     (default: playground_out/m4)
//
// Try: turn the depth test off, move the point light behind the cube, switch a mode to
// kNormalView or kDepthView, set near to 1e-4, scale the cube by (3, 0.2, 1).
#include <filesystem>
#include <iostream>
#include <string>

#include "depth_lighting.h"
#include "raster/io.h"

int main(int argc, char** argv) {
    const std::filesystem::path out = argc > 1 ? argv[1] : "playground_out/m4";
    std::filesystem::create_directories(out);

    // A cube from its 8 corners, as 12 triangles counter-clockwise from outside.
    m4::Mesh cube;
    for (int i = 0; i < 8; ++i) cube.positions.push_back({i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0});
    cube.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 4, 6}, {0, 6, 2},
                      {1, 3, 7}, {1, 7, 5}, {0, 1, 5}, {0, 5, 4}, {2, 6, 7}, {2, 7, 3}};
    cube.face_colors.assign(12, {230, 80, 60});

    const m4::Mat4 view = m3::look_at({3, 2, 4}, {0, 0, 0}, {0, 1, 0});
    // Near and far hug the cube (it lies 3.6 to 7.2 from the eye), so the depth view spreads
    // its grays; with near 0.1 and far 100 the whole cube would be nearly black (lesson 7).
    const m4::Mat4 proj = m3::perspective(50, 1, 3, 8);
    m4::Lighting lighting;
    lighting.lights.push_back({m4::Light::Kind::kDirectional, {-0.5, -1, -0.3}, {0.8, 0.8, 0.8}});
    lighting.lights.push_back({m4::Light::Kind::kPoint, {2, 3, 3}, {0.3, 0.3, 0.3}});

    const m4::Shading modes[] = {m4::Shading::kFaceColor, m4::Shading::kFlat, m4::Shading::kDepthView};
    const char* names[] = {"unlit", "flat", "depth"};
    for (int k = 0; k < 3; ++k) {
        m4::Frame frame;
        frame.color = raster::Image(128, 128);
        m4::Needs needs;
        needs.depth_test = true;
        needs.shading = modes[k];
        m4::clear_frame(frame, {20, 22, 30}, needs.depth_test, needs.depth_format);
        const m4::Stats st = m4::draw_mesh(frame, cube, m3::rotate({0, 1, 0}, 0.5), view, proj, lighting,
                                           {200, 180, 150}, needs);
        const std::string path = (out / (std::string(names[k]) + ".png")).string();
        raster::write_png(path, frame.color);
        std::cout << "wrote " << path << ": " << st.triangles_drawn << " triangles, " << st.fragments << " fragments, "
                  << st.depth_writes << " depth writes\n";
    }
    return 0;
}
