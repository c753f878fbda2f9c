// The render half of the milestone-3 checkpoints, compiled once per flavour (see m1/render.h).
#pragma once

#include <string>

#include "harness/checkpoint.h"

namespace m3cp {
namespace student {
cp::Artifacts render(const std::string& id);
}
namespace reference {
cp::Artifacts render(const std::string& id);
}
}  // namespace m3cp
