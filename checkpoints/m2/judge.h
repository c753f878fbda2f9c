// The judge half of the milestone-2 checkpoints (trusted: it runs no code under test).
#pragma once

#include <string>

#include "harness/checkpoint.h"

namespace m2cp {
cp::Judgement judge(const std::string& id, const cp::Artifacts& artifacts, const cp::Artifacts& reference,
                    const raster::Image& expected);
}
