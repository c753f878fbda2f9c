// Milestone 3 demo: your whole renderer. Draws the demo scenes with YOUR transforms.cpp AND your
// own lines.cpp and triangles.cpp (the checkpoints use the reference of milestones 1 and 2
// instead), prints how far each is from the reference picture, and renders an animation: a
// spinning wireframe cube and soccer ball, the camera flying along a cubic Bezier path.
//
// Its source lives with the checkpoints (it compares with their expected images); the
// student's folder, milestone3_transforms/, holds only what the student writes.
//
//   ./demo_m3 [output-folder]     (default: demo_out/m3; open index.html in a browser;
//                                  the animation is frames/animation.gif, and its frames)
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "harness/showcase.h"
#include "m3/render.h"
#include "m3/scenes.h"
#include "raster/gif.h"
#include "raster/io.h"

namespace {

// The animation (drawn by m3cp::student::animation, in checkpoints/m3/render.cpp), written
// as frames/frame_NN.png and as one animated GIF, frames/animation.gif.
int animate(const std::filesystem::path& dir) {
    std::filesystem::create_directories(dir);
    const std::vector<raster::Image> frames = m3cp::student::animation();
    for (std::size_t f = 0; f < frames.size(); ++f) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%02zu.png", f);
        raster::write_png((dir / name).string(), frames[f]);
    }
    raster::write_gif((dir / "animation.gif").string(), frames, 6);
    std::cout << "wrote " << frames.size() << " animation frames and animation.gif to " << dir.string() << "\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string out = argc > 1 ? argv[1] : "demo_out/m3";
    std::vector<cp::ShowItem> items;
    for (const m3cp::Scene& s : m3cp::scenes()) {
        if (s.demo) items.push_back({"m3", s.id, s.title, m3cp::student::render});
    }
    const int shown = cp::showcase(items, out, "Milestone 3 demo: your whole renderer", cp::demo_note(3, true));
    try {
        return animate(std::filesystem::path(out) / "frames") | shown;
    } catch (const std::exception& e) {
        std::cerr << "demo_m3: " << e.what() << "\n";
        return 1;
    }
}
