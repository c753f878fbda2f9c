// Milestone 3's error-against-run-time tables, measured on the reference (reference_tool
// m3-table writes them into the lesson; the project tests check that their errors are current).
#pragma once

#include <string>

namespace m3cp {
std::string error_time_tables();
}
