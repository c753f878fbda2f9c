// The render half of the milestone-1 checkpoints. render.cpp is compiled once per flavour
// (see raster/flavour.h), so a checkpoint program holds both the code under test
// (m1cp::student::render) and the reference (m1cp::reference::render).
#pragma once

#include <string>

#include "harness/checkpoint.h"

namespace m1cp {
namespace student {
cp::Artifacts render(const std::string& id);
}
namespace reference {
cp::Artifacts render(const std::string& id);
}
}  // namespace m1cp
