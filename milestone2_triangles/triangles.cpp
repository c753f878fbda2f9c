// GENERATED from solutions/milestone2_triangles/triangles.cpp by `make skeletons`. Fill in the TODOs; do not edit the rest.
// Milestone 2: triangles. Fill in the numbered TODOs; triangles.h says exactly what
// each function must do, and README.md walks through them in the same order.
// Run `make check-m2` in your build folder to see which checkpoints pass.
#include "triangles.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>

namespace m2 {
inline namespace RASTER_FLAVOUR {

bool snap(Vec2 p, Fixed& out) {
    // TODO 1: reject non-finite points and points beyond kMaxCoordinate, then round each
    // coordinate times kSubpixelSteps to the nearest integer (std::llround).
    return false;
}

std::int64_t edge(Fixed a, Fixed b, Fixed p) {
    // TODO 2: cross(b - a, p - a). With |coordinates| <= 2^28 sixteenths, every product fits
    // in 64 bits, so the result is exact: no rounding can put a sample on the wrong side.
    return 0;
}

PixelRect bounding_box(Fixed v0, Fixed v1, Fixed v2, int width, int height) {
    // TODO 3: pixel x is a candidate when its center 16x + 8 (in sixteenths) lies between the
    // smallest and largest vertex x. Round with floor/ceil division (careful: negative
    // numbers), then clamp to the image.
    return {};
}

namespace {

// A triangle ready for rasterizing: snapped, with positive area.
struct Setup {
    Fixed v[3];
    std::int64_t area2 = 0;     // twice the area, in (1/16 pixel)^2; > 0
    bool top_left[3] = {};      // edge i runs from v[i] to v[(i + 1) % 3]
    bool swapped = false;       // v[1] and v[2] were exchanged to make the area positive
};

// TODO 4a: snap the three vertices, compute the signed area, reject zero area, swap two
// vertices when it is negative, and mark which edges are top or left edges.
[[maybe_unused]] bool set_up(Vec2 v0, Vec2 v1, Vec2 v2, Setup& t) {
    return false;
}

// TODO 4b: is sample p covered? Fill e[] with the three edge values (e[i] for the edge
// from v[i] to v[i+1], which is 0 on that edge), then apply the top-left rule to zeros.
[[maybe_unused]] bool covers(const Setup& t, Fixed p, std::int64_t e[3]) {
    return false;
}

}  // namespace

void fill_triangle(Image& img, Vec2 v0, Vec2 v1, Vec2 v2, Color c) {
    // TODO 4c: set up the triangle, then test the center of every pixel in its bounding box.
}

void fill_triangle_gradient(Image& img, Vec2 v0, Vec2 v1, Vec2 v2, Color c0, Color c1, Color c2) {
    // TODO 5: as fill_triangle; for a covered pixel, the weight of vertex k is the edge value
    // of the edge opposite it divided by area2 (in floating point: integer division gives 0).
    // Remember which vertices set_up swapped. Round each channel to nearest (raster::to_channel).
}

void fill_triangle_aa(Image& img, Vec2 v0, Vec2 v1, Vec2 v2, Color c, int n) {
    // TODO 6: n * n samples per pixel at (x + (i + 0.5) / n, y + (j + 0.5) / n), which are
    // exact points of the 1/16 grid for n = 1, 2, 4, 8. Count the covered samples (same test,
    // same fill rule) and blend. Loop over every pixel the vertices' box overlaps, not over
    // bounding_box(): that one holds only the pixels whose CENTERS can be inside.
}

}  // namespace RASTER_FLAVOUR
}  // namespace m2
