// The functions a milestone-3 student writes, with their TODO numbers (transforms.cpp,
// lesson): the render half names each call with cp::traced(), and the harness uses this table
// to say which TODOs a checkpoint needs, which TODO drew nothing, and what a stuck function
// means. The operators are traced as "operator*" (Mat4 * Mat4 and Mat4 * Vec4).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "harness/checkpoint.h"

namespace m3cp {

inline std::vector<cp::StudentFunction> functions() {
    return {
        {"operator*", {1}, {}, "matrix", ""},
        {"transpose", {1}, {}, "matrix", ""},
        {"transform_point", {1}, {"operator*"}, "matrix", ""},
        {"transform_direction", {1}, {"operator*"}, "direction", ""},
        {"translate", {2}, {}, "builders", ""},
        {"scale", {2}, {}, "builders", ""},
        {"rotate_x", {2}, {}, "builders", ""},
        {"rotate_y", {2}, {}, "builders", ""},
        {"rotate_z", {2}, {}, "builders", ""},
        {"rotate", {2}, {}, "rotation", ""},
        {"inverse", {3}, {}, "inverse", "each of the four columns needs one pivot step; loops over rows and columns end at 4"},
        {"rigid_inverse", {3}, {}, "inverse", ""},
        {"look_at", {4}, {}, "look at", ""},
        {"perspective", {5}, {}, "projection", ""},
        {"orthographic", {5}, {}, "projection", ""},
        {"to_screen", {6}, {}, "viewport", ""},
        {"clip_polygon", {7}, {}, "clipping",
         "clip against each of the six planes once, walking the current polygon's edges once per plane; a polygon "
         "never grows beyond 9 vertices"},
        {"clip_line", {7}, {}, "clipping", ""},
        {"is_back_facing", {8}, {}, "culling", ""},
        {"bezier", {9}, {}, "bezier", ""},
        {"painter_order", {10}, {}, "painter", ""},
        {"draw_model", {11},
         {"operator*", "transform_point", "clip_polygon", "clip_line", "to_screen", "is_back_facing", "painter_order"},
         "pipeline",
         "loop over the model's triangles and edges once; fan a clipped polygon with i from 1 while i + 1 < size"},
    };
}

// Which TODO a finding's concept points to, and what to do about it.
inline std::map<std::string, cp::TopicAdvice> topics() {
    return {
        {"matrix", {"TODO 1", "entry r of M * v is row r of M dotted with v; (A * B)[i][j] is row i of A times column j of B"}},
        {"storage order", {"TODO 1", "Mat4 is m[row][col] and acts on column vectors: the translation is the last column"}},
        {"multiplication order", {"TODO 1", "A * B applies B first: read a product right to left"}},
        {"direction", {"TODO 1", "a direction has w = 0: the translation column must not move it"}},
        {"composition", {"TODOs 1-2", "translate(t) * rotate(a) turns first, then moves"}},
        {"builders", {"TODO 2", "rotate_z(pi/2) takes +x to +y; the translation goes in the last column"}},
        {"rotation", {"TODO 2", "Rodrigues: normalize the axis; the zero axis gives the identity"}},
        {"precision", {"TODOs 1-2", "compose in double; each product must stay a rotation"}},
        {"inverse", {"TODO 3", "pivot on the largest |entry| of the column; report a zero pivot as singular"}},
        {"look at", {"TODO 4", "rows r, u, -f and the last column -(R * eye)"}},
        {"look at fallback", {"TODO 4", "up parallel to the view: use the world axis transforms.h pins; eye == target: f = -z"}},
        {"handedness", {"TODO 4", "r = cross(f, up), not cross(up, f)"}},
        {"projection", {"TODO 5", "OpenGL's matrices; invalid arguments give the zero matrix"}},
        {"degrees", {"TODO 5", "perspective() takes degrees: convert to radians before std::tan"}},
        {"perspective divide", {"TODO 6", "divide x, y and z by w before the viewport map"}},
        {"viewport", {"TODO 6", "divide by w, then x_pixel = (x_ndc + 1) / 2 * W and y_pixel = (1 - y_ndc) / 2 * H: rows grow downward"}},
        {"clipping", {"TODO 7", "clip against all six planes -w <= x, y, z <= w, in clip space"}},
        {"near plane", {"TODO 7", "clip against z >= -w too: it removes everything at or behind the camera"}},
        {"clip space", {"TODO 11", "clip the clip-space vertices first, then divide what survives"}},
        {"culling", {"TODO 8", "cull when cross(s1 - s0, s2 - s0) >= 0 in pixel coordinates"}},
        {"bezier", {"TODO 9", "three rounds of linear interpolation at t"}},
        {"painter", {"TODO 10", "sort by mean view-space z, most negative first"}},
        {"pipeline", {"TODO 11", "run only the stages in Needs and count each as transforms.h says"}},
        {"face colors", {"TODO 11", "fill triangle i with model.face_colors[i], white where the list is shorter"}},
    };
}

}  // namespace m3cp
