// The functions a milestone-4 student writes, with their TODO numbers (depth_lighting.cpp,
// lesson): the render half names each call with cp::traced(), and the harness uses this table
// to say which TODOs a checkpoint needs, which TODO drew nothing, and what a stuck function
// means.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "harness/checkpoint.h"

namespace m4cp {

inline std::vector<cp::StudentFunction> functions() {
    return {
        {"depth_key", {1}, {}, "depth key", ""},
        {"depth_passes", {2}, {}, "depth test", ""},
        {"clear_frame", {2}, {}, "depth clear", ""},
        {"perspective_weights", {3}, {}, "perspective", ""},
        {"face_normal", {4}, {}, "normals", ""},
        {"vertex_normals", {4}, {}, "normals", ""},
        {"normal_matrix", {4}, {}, "normal matrix", ""},
        {"shade", {5}, {}, "lambert", ""},
        {"to_color", {5}, {}, "clamp", ""},
        {"depth_gray", {6}, {}, "debug view", ""},
        {"normal_color", {6}, {}, "debug view", ""},
        {"lerp", {7}, {}, "clipping", ""},
        {"clip_triangle", {7}, {"lerp"}, "clipping",
         "clip against each of the six planes once, walking the current polygon once per plane"},
        {"fill_triangle", {8},
         {"depth_key", "depth_passes", "perspective_weights", "shade", "to_color", "depth_gray", "normal_color"},
         "rasterizer", "loop over the pixels of the bounding box once; step the edge values by constants"},
        {"draw_mesh", {9},
         {"clip_triangle", "fill_triangle", "vertex_normals", "normal_matrix", "face_normal", "shade", "to_color"},
         "pipeline", "loop over the positions once and the triangles once; fan a polygon with i from 1 while i + 1 < size"},
    };
}

// Which TODO a finding's concept points to, and what to do about it.
inline std::map<std::string, cp::TopicAdvice> topics() {
    return {
        {"depth key", {"TODO 1", "d = (z_ndc + 1) / 2 clamped to [0, 1]; each format's key as depth_lighting.h says"}},
        {"depth format", {"TODO 1", "reversed-Z and 1/w are computed in double and only then rounded to float"}},
        {"depth test", {"TODO 2", "a smaller key is nearer; test first, write color and key only when the test passes"}},
        {"depth clear", {"TODO 2", "clear_frame gives every pixel kClearKey at the start of EVERY frame"}},
        {"tie rule", {"TODO 2", "an exact tie of keys goes to the brighter color (r, then g, then b)"}},
        {"perspective", {"TODO 3", "weights l_i / w_i, normalized to sum 1"}},
        {"extreme w", {"TODO 3", "when sum(l_i / w_i) is not > 0 or not finite, return the screen weights unchanged"}},
        {"interpolation", {"TODO 8", "with perspective_correct false the weights are the screen weights l_i"}},
        {"normals", {"TODO 4", "normalize(cross(p1 - p0, p2 - p0)); vertex normals sum the unnormalized cross products"}},
        {"normal matrix", {"TODO 4", "normals go to world space by the inverse transpose of the model's 3x3, not the model matrix"}},
        {"zero normal", {"TODOs 4-5", "a zero normal stays zero and lights nothing: ambient only, never NaN"}},
        {"lambert", {"TODO 5", "B * (ambient + sum of I * max(0, N . L)) per channel"}},
        {"negative light", {"TODO 5", "max(0, N . L): a light behind the surface adds nothing, it never subtracts"}},
        {"light direction", {"TODO 5", "L points from the surface TOWARD the light: -direction for a directional light"}},
        {"grazing light", {"TODO 5", "N . L = 0 exactly gives no light and no NaN"}},
        {"clamp", {"TODO 5", "clamp each channel to [0, 255] before converting: 300 must become 255, not 44"}},
        {"rounding", {"TODO 5", "after clamping, round each channel to the nearest level: 12.6 becomes 13, not 12"}},
        {"debug view", {"TODO 6", "gray = round(255 * (1 - d)); normal colors round(255 * (n + 1) / 2)"}},
        {"clipping", {"TODO 7", "clip in clip space against all six planes and lerp EVERY attribute with the same t"}},
        {"rasterizer", {"TODO 8", "milestone 2's snapping, edge functions and top-left rule, with depth and attributes"}},
        {"per-pixel normals", {"TODO 8", "interpolate the world normal perspective-correctly and normalize it before "
                                         "lighting (between vertices it is shorter than 1); a world-space normal, not "
                                         "a view-space one"}},
        {"world position", {"TODO 8", "interpolate the world position perspective-correctly, as every attribute: a "
                                      "point light's direction and distance depend on it"}},
        {"flat shading", {"TODO 9", "one light value per triangle: face normal of the world positions, at the centroid"}},
        {"gouraud", {"TODO 9", "light every vertex once, interpolate the lit colors (perspective-correctly, as every attribute)"}},
        {"face color", {"TODO 9", "face_colors[face], face being the triangle's index in mesh.triangles; past the end of face_colors, white"}},
        {"needs", {"TODO 9", "allocate, compute and interpolate only what Needs asks for"}},
        {"pipeline", {"TODO 9", "follow draw_mesh's steps in depth_lighting.h and count each as Stats says"}},
        {"bad input", {"TODO 9", "skip triangles with a non-finite clip coordinate or an index out of range"}},
    };
}

}  // namespace m4cp
