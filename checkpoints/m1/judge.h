// The judge half of the milestone-1 checkpoints (trusted: it runs no code under test).
#pragma once

#include <string>

#include "harness/checkpoint.h"

namespace m1cp {
cp::Judgement judge(const std::string& id, const cp::Artifacts& artifacts, const cp::Artifacts& reference,
                    const raster::Image& expected);
// Suite::describe_call: which line the n-th call of draw_line or draw_line_aa draws (render.cpp's
// order), or "" where that is not known (clip scenes' clipped parts).
std::string describe_call(const std::string& id, const std::string& function, long long call);
}
