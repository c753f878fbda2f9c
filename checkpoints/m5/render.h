// The render half of the milestone-5 checkpoints, compiled once per flavour (see m1/render.h).
#pragma once

#include <string>

#include "harness/checkpoint.h"

namespace m5cp {
struct Scene;
namespace student {
cp::Artifacts render(const std::string& id);
cp::Artifacts render_scene(const Scene& s);  // a scene that is not in the table (lesson tables)
}  // namespace student
namespace reference {
cp::Artifacts render(const std::string& id);
cp::Artifacts render_scene(const Scene& s);
}  // namespace reference
}  // namespace m5cp
