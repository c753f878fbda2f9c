// The render half of the milestone-4 checkpoints, compiled once per flavour (see m1/render.h).
#pragma once

#include <string>

#include "harness/checkpoint.h"

namespace m4cp {
namespace student {
cp::Artifacts render(const std::string& id);
}
namespace reference {
cp::Artifacts render(const std::string& id);
}
}  // namespace m4cp
