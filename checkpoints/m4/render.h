// The render half of the milestone-4 checkpoints, compiled once per flavour (see m1/render.h).
#pragma once

#include <string>

#include "harness/checkpoint.h"

namespace m4cp {
struct Scene;
namespace student {
cp::Artifacts render(const std::string& id);
cp::Artifacts render_scene(const Scene& s);  // a scene that is not in the table (lesson tables)
}
namespace reference {
cp::Artifacts render(const std::string& id);
cp::Artifacts render_scene(const Scene& s);
}
}  // namespace m4cp
