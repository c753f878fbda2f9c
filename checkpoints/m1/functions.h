// The functions a milestone-1 student writes, with their TODO numbers (lines.cpp, lesson):
// the render half names each call with cp::traced(), and the harness uses this table to say
// which TODOs a checkpoint needs, which TODO drew nothing, and what a stuck function means.
#pragma once

#include <vector>

#include "harness/checkpoint.h"

namespace m1cp {

inline std::vector<cp::StudentFunction> functions() {
    return {
        {"outcode", {1}, {}, "outcode", ""},
        {"clip_line", {2}, {"outcode"}, "clipping",
         "check for NaN and infinity before the loop and return false: NaN compares false with everything, so "
         "a NaN endpoint's outcode never changes and the loop never ends. Each pass must move one endpoint onto "
         "an edge; a few passes are always enough"},
        // TODO 3 is bresenham(), which draw_line calls; in the lesson's design draw_line clips
        // with clip_line first.
        {"draw_line", {3, 4}, {"clip_line"}, "clipping",
         "reject NaN and infinite endpoints first (NaN compares false with everything, so a clipping loop "
         "fed NaN may never end), clip the segment to the image (in double) before the loop, so it walks only "
         "the visible pixels (a line to 1e9 walked pixel by pixel takes billions of steps), and check that the "
         "loop stops exactly at the end pixel"},
        {"draw_line_aa", {5}, {}, "clipping",
         "limit the columns to the image before the loop, so it walks only the visible ones, and skip lines "
         "whose slope is not finite"},
    };
}

}  // namespace m1cp
