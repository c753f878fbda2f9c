// Milestone 4 demo: your whole renderer. Draws the demo scenes with YOUR depth_lighting.cpp AND
// your own lines.cpp, triangles.cpp and transforms.cpp (the checkpoints use the reference of
// milestones 1 to 3 instead), and prints how far each picture is from the reference's.
//
// Its source lives with the checkpoints (it compares with their expected images); the
// student's folder, milestone4_depth_lighting/, holds only what the student writes.
//
//   ./demo_m4 [output-folder]     (default: demo_out/m4; open index.html in a browser)
#include <string>
#include <vector>

#include "harness/showcase.h"
#include "m4/render.h"
#include "m4/scenes.h"

int main(int argc, char** argv) {
    const std::string out = argc > 1 ? argv[1] : "demo_out/m4";
    std::vector<cp::ShowItem> items;
    for (const m4cp::Scene& s : m4cp::scenes()) {
        if (s.demo) items.push_back({"m4", s.id, s.title, m4cp::student::render});
    }
    return cp::showcase(items, out, "Milestone 4 demo: your whole renderer, lit and depth-tested",
                        cp::demo_note(4, true));
}
