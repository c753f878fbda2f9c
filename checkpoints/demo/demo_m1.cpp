// Milestone 1 demo: draws the demo scenes (clock face, eight-octant star, lines clipped
// against a viewport) with YOUR lines.cpp, and prints how far each is from the reference
// picture and how long it took.
//
// Its source lives with the checkpoints (it compares with their expected images); the
// student's folder, milestone1_lines/, holds only what the student writes.
//
//   ./demo_m1 [output-folder]     (default: demo_out/m1; open index.html in a browser)
#include "harness/showcase.h"
#include "m1/render.h"
#include "m1/scenes.h"

int main(int argc, char** argv) {
    std::vector<cp::ShowItem> items;
    for (const m1cp::Scene& s : m1cp::scenes()) {
        if (s.demo) items.push_back({"m1", s.id, s.title, m1cp::student::render});
    }
    return cp::showcase(items, argc > 1 ? argv[1] : "demo_out/m1", "Milestone 1 demo: your lines",
                        cp::demo_note(1, false));
}
