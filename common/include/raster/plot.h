// Charts as images, for the lessons' error-against-run-time plots and the reports: points of
// several series, joined by lines, on linear or logarithmic axes, with tick labels, axis names,
// a title and a legend (text drawn with stb_easy_font). Knows nothing about any milestone.
#pragma once

#include <string>
#include <vector>

#include "raster/color.h"
#include "raster/image.h"
#include "raster/vec.h"

namespace raster {

struct PlotSeries {
    std::string name;                 // in the legend
    Color color;
    std::vector<Vec2> points;         // (x, y), joined in this order
    std::vector<std::string> labels;  // optional, one per point, written beside it
};

struct PlotSpec {
    std::string title, x_label, y_label;
    bool log_x = false, log_y = false;  // logarithmic axes ignore points <= 0
    int width = 560, height = 360;
    std::vector<PlotSeries> series;
};

// The chart on a white background. Non-finite points (and non-positive ones on a log axis) are
// left out; with no point at all the chart has empty axes.
Image plot(const PlotSpec& spec);

// Writes `text` with its top-left corner at (x, y), `scale` pixels per font unit (the font is
// about 7 units tall). Pixels outside the image are skipped.
void draw_text(Image& img, int x, int y, const std::string& text, Color color, int scale = 1);
int text_width(const std::string& text, int scale = 1);

}  // namespace raster
