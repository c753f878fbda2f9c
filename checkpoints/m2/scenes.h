// Milestone 2 scenes: the trusted description of every triangle checkpoint and demo picture.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "raster/color.h"
#include "raster/vec.h"

namespace m2cp {

using raster::Color;
using raster::Vec2;

struct Tri {
    Vec2 v[3];
    Color c[3];             // c[0] for solid fills; all three for gradients
    bool gradient = false;  // fill_triangle_gradient
    int aa = 0;             // > 0: fill_triangle_aa with this many samples per axis
};

// Inputs for the numeric checks of snap(), edge() and bounding_box().
struct NumberCases {
    std::vector<Vec2> snaps;
    std::vector<std::vector<Vec2>> boxes;  // three vertices each; also used for edge()
};

struct Scene {
    std::string id;
    std::string title;
    std::string hint;
    int width = 64, height = 64;
    std::vector<Tri> tris;
    bool check_winding = false;  // also draw every triangle with the other winding: same image
    bool watertight = false;     // the triangles tile a region: every pixel covered exactly once
    NumberCases numbers;         // m2.edge_and_box only
    bool demo = false;
};

const std::vector<Scene>& scenes();
// Grading's scene variants: replaces every scene by a variant derived from (seed, scene id);
// seed 0 restores the public scenes. scenes() and scene() return the current ones.
void use_variant(std::uint64_t seed);
const Scene& scene(const std::string& id);

}  // namespace m2cp
