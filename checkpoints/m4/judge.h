// The judge half of the milestone-4 checkpoints (trusted: it runs no code under test).
#pragma once

#include <string>

#include "harness/checkpoint.h"

namespace m4cp {
cp::Judgement judge(const std::string& id, const cp::Artifacts& artifacts, const cp::Artifacts& reference,
                    const raster::Image& expected);
}

namespace m4cp {
struct Panel;
// Analytic pictures of a panel, computed from the scene alone: the checkerboard floor (item 0,
// a rectangle) by ray casting, and the perfect sphere (item 0, uniform scale) lit exactly.
raster::Image analytic_checker(const Panel& p);
raster::Image analytic_sphere(const Panel& p);
// The mean absolute channel difference between panel p of `img` and `truth`, in levels.
double panel_error(const raster::Image& img, const Panel& p, const raster::Image& truth);
}  // namespace m4cp
