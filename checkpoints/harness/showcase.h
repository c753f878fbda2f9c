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
// expected images. Returns 0, or 1 if a scene could not be rendered or written.
int showcase(const std::vector<ShowItem>& items, const std::string& out_dir, const std::string& heading);

}  // namespace cp
