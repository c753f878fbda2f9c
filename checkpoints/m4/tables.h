// Milestone 4's lesson tables and chart, measured on the reference (reference_tool m4-table
// writes them into the lesson, and the chart beside it as error_vs_time.png; the project tests
// check that the tables' numbers other than times are current).
#pragma once

#include <string>

#include "raster/image.h"

namespace m4cp {
std::string error_time_tables();
raster::Image error_time_chart();  // error against time of flat, Gouraud and per-pixel shading
}
