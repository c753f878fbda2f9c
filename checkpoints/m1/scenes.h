// Milestone 1 scenes: the trusted description of every checkpoint and demo picture.
//
// A scene is plain data. The render half (render.cpp) turns it into calls to the code under
// test; the judge (judge.cpp) derives from the same data what a correct image must contain.
// The demo program and the gallery draw the scenes marked `demo`.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "raster/color.h"
#include "raster/vec.h"

namespace m1cp {

using raster::Color;
using raster::Vec2;

struct Segment {
    Vec2 a, b;
    Color color = raster::colors::white;
    bool aa = false;  // draw with draw_line_aa instead of draw_line
};

struct Box {  // a clip rectangle, border included
    double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
};

enum class Kind {
    kLines,     // draw every segment; judge pixels against the ideal lines
    kOutcodes,  // color every pixel by outcode(pixel center, viewport)
    kClip,      // clip every segment to the viewport with clip_line, then draw the result
};

struct Scene {
    std::string id;
    std::string title;
    std::string hint;  // the most likely reason for a failure, in a student's words
    int width = 64, height = 64;
    Kind kind = Kind::kLines;
    std::vector<Segment> lines;
    bool check_reversed = false;  // also draw each line from b to a: the image must not change
    bool disjoint = false;        // no two lines share a pixel: exact per-line checks apply
    Box viewport;                 // kOutcodes and kClip
    bool demo = false;            // shown in the gallery and drawn by the demo program
    // kLines: also call clip_line on each aliased line with a NaN or infinite endpoint
    // (against the image's rectangle of pixel centers): it must return false.
    bool clip_nonfinite = false;
};

const std::vector<Scene>& scenes();
// Grading's scene variants: replaces every scene by a variant derived from (seed, scene id);
// seed 0 restores the public scenes. scenes() and scene() return the current ones.
void use_variant(std::uint64_t seed);
const Scene& scene(const std::string& id);  // throws std::out_of_range for an unknown id

// Points on a rectangle's border: its corners and the middles of its sides. The border is inside,
// so outcode() must give each of them 0. Render halves ask the code under test for their
// outcodes in the rectangle of pixel centers that draw_line clips every line to (values
// "border_outcode.<k>") and, in clip scenes, in the viewport ("viewport_outcode.<k>"): an outcode
// that puts the border outside explains gaps that neither the drawing nor clip_line's numbers do.
std::vector<Vec2> border_probes(const Box& r);
inline Box pixel_center_box(int width, int height) { return {0.5, 0.5, width - 0.5, height - 0.5}; }

// Colors of the outcode picture, indexed by outcode (0..10; unused codes are black).
Color outcode_color(int code);

// In clip scenes: each whole segment is drawn in this color first, then the viewport's
// border, then the clipped part in the segment's own color on top.
inline constexpr Color kUnclippedColor{70, 70, 70};
inline constexpr Color kViewportColor{40, 90, 200};

}  // namespace m1cp
