#include "raster_catch.h"

#include <cmath>

#include "raster/plot.h"

namespace {

long long count_color(const raster::Image& img, raster::Color c) {
    long long n = 0;
    for (int y = 0; y < img.height(); ++y) {
        for (int x = 0; x < img.width(); ++x) n += img.at(x, y) == c;
    }
    return n;
}

}  // namespace

TEST_CASE("plot draws every series in its color, on log axes too", "[plot]") {
    raster::PlotSpec spec;
    spec.title = "error against time";
    spec.x_label = "ms";
    spec.y_label = "error";
    spec.log_x = true;
    spec.series.push_back({"flat", {200, 40, 40}, {{0.1, 5}, {1, 2}, {10, 1}}, {"8", "16", "32"}});
    spec.series.push_back({"smooth", {40, 40, 200}, {{0.2, 3}, {2, 0.5}}, {}});
    const raster::Image img = raster::plot(spec);
    CHECK(img.width() == spec.width);
    CHECK(img.height() == spec.height);
    CHECK(count_color(img, {200, 40, 40}) > 100);
    CHECK(count_color(img, {40, 40, 200}) > 50);
    CHECK(img.stray_writes() == 0);
}

TEST_CASE("plot leaves out points it cannot place and survives an empty chart", "[plot]") {
    raster::PlotSpec spec;
    spec.log_y = true;
    spec.series.push_back({"bad", {0, 200, 0}, {{NAN, 1}, {1, -3}, {INFINITY, 2}}, {}});
    const raster::Image img = raster::plot(spec);
    CHECK(count_color(img, {0, 200, 0}) < 200);  // the legend's swatch only
    raster::PlotSpec empty;
    CHECK(raster::plot(empty).width() == empty.width);
}

TEST_CASE("draw_text writes pixels and never outside the image", "[plot]") {
    raster::Image img(40, 12, {255, 255, 255});
    raster::draw_text(img, 2, 2, "1e-3 ms", {0, 0, 0});
    raster::draw_text(img, 30, 8, "far outside the right edge", {0, 0, 0}, 2);
    CHECK(count_color(img, {0, 0, 0}) > 10);
    CHECK(img.stray_writes() == 0);
    CHECK(raster::text_width("abc") > raster::text_width("a"));
}

TEST_CASE("draw_text draws every glyph of a long label whole", "[plot]") {
    raster::Image one(20, 12, {255, 255, 255}), many(200, 12, {255, 255, 255});
    raster::draw_text(one, 0, 0, "8", {0, 0, 0});
    raster::draw_text(many, 0, 0, "88888888", {0, 0, 0});
    CHECK(count_color(many, {0, 0, 0}) == 8 * count_color(one, {0, 0, 0}));
}
