// The functions a milestone-2 student writes, with their TODO numbers (triangles.cpp,
// lesson): see m1/functions.h for how the harness uses this table.
#pragma once

#include <string>
#include <vector>

#include "harness/checkpoint.h"

namespace m2cp {

inline std::vector<cp::StudentFunction> functions() {
    const std::string box_loop =
        "clamp the bounding box to the image before looping over it (a triangle with a vertex at 1e7 has a box "
        "of 1e14 pixels), and reject non-finite vertices first (snap returns false)";
    return {
        {"snap", {1}, {}, "snap", ""},
        {"edge", {2}, {}, "edge function", ""},
        {"bounding_box", {3}, {}, "bounding box", box_loop},
        // TODO 4 sets up a triangle (4a), tests a sample (4b) and fills (4c); 5 and 6 reuse 4a and 4b.
        {"fill_triangle", {4}, {"snap", "edge", "bounding_box"}, "bounding box", box_loop},
        {"fill_triangle_gradient", {5}, {"fill_triangle"}, "bounding box", box_loop},
        {"fill_triangle_aa", {6}, {"fill_triangle"}, "bounding box",
         box_loop + "; with n * n samples per pixel, check that the sample loops count up to n"},
    };
}

}  // namespace m2cp
