// The build a benchmark was compiled with, for `make bench` to print beside its numbers: the
// ratios depend on the optimisation level. CMake defines both (checkpoints/CMakeLists.txt);
// a compile without them says "unknown".
#pragma once

#ifndef RASTER_BUILD_TYPE
#define RASTER_BUILD_TYPE "unknown"
#endif
#ifndef RASTER_BUILD_FLAGS
#define RASTER_BUILD_FLAGS ""
#endif
