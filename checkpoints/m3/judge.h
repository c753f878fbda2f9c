// The judge half of the milestone-3 checkpoints (trusted: it runs no code under test).
#pragma once

#include <string>

#include "harness/checkpoint.h"

namespace m3cp {
cp::Judgement judge(const std::string& id, const cp::Artifacts& artifacts, const cp::Artifacts& reference,
                    const raster::Image& expected);
}
