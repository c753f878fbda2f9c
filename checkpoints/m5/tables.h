// Milestone 5's lesson tables and chart, measured on the reference (reference_tool m5-table
// writes each table between its markers in the lesson, m5-filters, m5-shadows and m5-needs, and
// the chart beside it as error_vs_time.png; the project tests check that the tables' numbers
// other than times are current).
#pragma once

#include <string>

#include "raster/image.h"

namespace m5cp {
std::string filter_table();  // each filter on a receding plane: error against a 16x truth, time
std::string shadow_table();  // shadow-map resolution, without and with PCF: wrong pixels, time
std::string needs_table();   // the Stats counts of one scene as it needs more and more
raster::Image error_time_chart();  // the filter table's error against time
}  // namespace m5cp
