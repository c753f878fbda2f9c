// Renders a list of scenes into a folder and prints, per scene, its error against the
// expected image and its render time. The demo programs (student code) and the reference
// gallery use it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "harness/checkpoint.h"

namespace cp {

struct ShowItem {
    std::string milestone, id, title;
    std::function<Artifacts(const std::string& id)> render;
};

// Writes <out_dir>/<id>.png for each item and an index.html showing them beside their
// expected images. Returns 0, or 1 if a scene could not be rendered or written. When a picture
// is far from its expected image (more than half of its pixels differ, or it is blank where the
// expected image is not) or could not be drawn, prints how many and `far_note` (see demo_note)
// under the table and on the page.
int showcase(const std::vector<ShowItem>& items, const std::string& out_dir, const std::string& heading,
             const std::string& far_note = "");

// The far_note of the demo of milestone `milestone`: which of the student's milestones it draws
// with (1 to `milestone` when `earlier`, else that one alone) and which `make check-mN` must pass
// before its pictures can match.
std::string demo_note(int milestone, bool earlier);

}  // namespace cp
