// The error-against-run-time table of lesson 1 (`reference_tool m1-table`).
#pragma once

#include <string>

namespace m1cp {

// Bresenham, Wu and supersampled lines against the exact coverage of the ideal line one pixel
// wide: mean and largest intensity error, then the time per line (the last column).
std::string error_time_table();

}  // namespace m1cp
