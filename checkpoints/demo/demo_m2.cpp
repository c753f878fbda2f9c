// Milestone 2 demo: draws the demo scenes (a flat-colored cube, the gradient triangle, the
// watertight fan, the cube without and with anti-aliasing) with YOUR triangles.cpp, and
// prints how far each is from the reference picture and how long it took.
//
// Its source lives with the checkpoints (it compares with their expected images); the
// student's folder, milestone2_triangles/, holds only what the student writes.
//
//   ./demo_m2 [output-folder]     (default: demo_out/m2; open index.html in a browser)
#include "harness/showcase.h"
#include "m2/render.h"
#include "m2/scenes.h"

int main(int argc, char** argv) {
    std::vector<cp::ShowItem> items;
    for (const m2cp::Scene& s : m2cp::scenes()) {
        if (s.demo) items.push_back({"m2", s.id, s.title, m2cp::student::render});
    }
    return cp::showcase(items, argc > 1 ? argv[1] : "demo_out/m2", "Milestone 2 demo: your triangles",
                        cp::demo_note(2, false));
}
