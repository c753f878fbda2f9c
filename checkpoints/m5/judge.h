// The judge half of the milestone-5 checkpoints (trusted: it runs no code under test).
#pragma once

#include <string>

#include "harness/checkpoint.h"

namespace m5cp {
cp::Judgement judge(const std::string& id, const cp::Artifacts& artifacts, const cp::Artifacts& reference,
                    const raster::Image& expected);
}  // namespace m5cp
