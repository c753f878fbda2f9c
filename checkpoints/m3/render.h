// The render half of the milestone-3 checkpoints, compiled once per flavour (see m1/render.h).
#pragma once

#include <string>
#include <vector>

#include "harness/checkpoint.h"

namespace m3cp {
namespace student {
cp::Artifacts render(const std::string& id);
// The demo's animation: a spinning wireframe cube and soccer ball, the camera flying along a
// cubic Bezier path (36 frames of 160 x 120).
std::vector<raster::Image> animation();
}
namespace reference {
cp::Artifacts render(const std::string& id);
std::vector<raster::Image> animation();
}
}  // namespace m3cp
