// Milestone 5 demo: your whole renderer. Draws the demo scenes with YOUR textures_shadows.cpp
// AND your own lines.cpp, triangles.cpp, transforms.cpp and depth_lighting.cpp (the checkpoints
// use the reference of milestones 1 to 4 instead), and prints how far each picture is from the
// reference's.
//
// Its source lives with the checkpoints (it compares with their expected images); the
// student's folder, milestone5_textures_shadows/, holds only what the student writes.
//
//   ./demo_m5 [output-folder]     (default: demo_out/m5; open index.html in a browser)
#include <string>
#include <vector>

#include "harness/showcase.h"
#include "m5/render.h"
#include "m5/scenes.h"

int main(int argc, char** argv) {
    const std::string out = argc > 1 ? argv[1] : "demo_out/m5";
    std::vector<cp::ShowItem> items;
    for (const m5cp::Scene& s : m5cp::scenes()) {
        if (s.demo) items.push_back({"m5", s.id, s.title, m5cp::student::render});
    }
    return cp::showcase(items, out, "Milestone 5 demo: your whole renderer, textured, lit and shadowed",
                        cp::demo_note(5, true));
}
