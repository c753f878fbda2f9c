// The functions a milestone-5 student writes, with their TODO numbers (textures_shadows.cpp,
// lesson): the render half names each call with cp::traced(), and the harness uses this table
// to say which TODOs a checkpoint needs, which TODO drew nothing, and what a stuck function
// means.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "harness/checkpoint.h"

namespace m5cp {

inline std::vector<cp::StudentFunction> functions() {
    return {
        {"wrap_index", {1}, {}, "wrap", "use std::fmod on the double index: a loop that adds or subtracts n never ends for 1e300"},
        {"fetch", {1}, {"wrap_index"}, "wrap", ""},
        {"sample_nearest", {2}, {"fetch"}, "nearest", "check for a non-finite u * w before anything else"},
        {"sample_bilinear", {2}, {"fetch"}, "bilinear", "check for a non-finite u * w before anything else"},
        {"build_mipmaps", {3}, {}, "mipmap", "stop at the 1x1 level: each level is max(1, floor(w / 2)) by max(1, floor(h / 2))"},
        {"uv_derivatives", {4}, {}, "level of detail", ""},
        {"level_of_detail", {4}, {}, "level of detail", ""},
        {"sample", {4}, {"sample_nearest", "sample_bilinear", "build_mipmaps"}, "filter",
         "clamp lambda to [0, L - 1] before choosing a level; NaN magnifies"},
        {"blinn_phong", {6}, {}, "specular", ""},
        {"tangent_frame", {7}, {}, "tangent frame", ""},
        {"perturb_normal", {7}, {}, "normal map", ""},
        {"light_view_projection", {8}, {}, "light matrix", ""},
        {"shadow_factor", {8}, {}, "shadow", "a texel outside the map is lit: test the row and column before reading a key"},
        // fill_triangle and draw_scene list no functions they may call: what a scene needs of
        // them (sample() for a texture, blinn_phong for a lit material, ...) the render half
        // calls on its own as the scene's prerequisites (prerequisite_groups), so the trace has
        // exactly those, and a checkpoint's "needs" names only the TODOs its scene uses.
        {"fill_triangle", {5}, {}, "rasterizer", "loop over the pixels of the bounding box once, clamped to the image"},
        {"draw_scene", {9}, {"fill_triangle"}, "pipeline",
         "loop over the lights once, the objects once per pass and each mesh's triangles once"},
    };
}

// Which TODO a finding's concept points to, and what to do about it.
inline std::map<std::string, cp::TopicAdvice> topics() {
    return {
        {"wrap", {"TODO 1", "wrap whole-number indices: repeat i mod n in [0, n), clamp, mirrored m = i mod 2n then m or 2n - 1 - m"}},
        {"nearest", {"TODO 2", "nearest reads texel (floor(u * w), floor(v * h)), wrapped"}},
        {"texel centers", {"TODO 2", "texel centers are at half-integers: bilinear starts from x' = u * w - 0.5"}},
        {"bilinear", {"TODO 2", "weights (1 - a)(1 - b), a(1 - b), (1 - a)b, ab for texels (i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1)"}},
        {"non-finite uv", {"TODO 2", "a NaN or infinite uv, or a u * w that overflows, samples black"}},
        {"mipmap", {"TODO 3", "each level max(1, floor(w / 2)) by max(1, floor(h / 2)), texels the plain average of 2x2, an index past a 1-texel side clamped, odd last row or column dropped"}},
        {"level of detail", {"TODO 4", "exact derivatives of A / B at the pixel center; rho in texel units of level 0; lambda = log2(rho)"}},
        {"filter", {"TODO 4", "lambda <= 0 or NaN: bilinear on level 0; else clamp to [0, L - 1]; nearest-mip level floor(lambda + 0.5)"}},
        {"lambda clamp", {"TODO 4", "clamp lambda to [0, L - 1]: never read past the 1x1 level"}},
        {"trilinear", {"TODO 4", "blend the bilinear samples of levels k = floor(lambda) and k + 1 as (1 - f) level k + f level k + 1, f = lambda - k"}},
        {"mipmap builds", {"TODO 4", "build the pyramid once, the first time a mip filter reads a level above 0; never for lambda <= 0"}},
        {"perspective uv", {"TODO 5", "interpolate u/w, v/w and 1/w on the screen (m4::perspective_weights), in double"}},
        {"rasterizer", {"TODO 5", "milestone 2's snapping, edge functions and top-left rule; depth pre-test before shading"}},
        {"ambient", {"TODO 5", "every fragment gets base times lighting.ambient once, lit or not; a light's intensity scales only its own blinn_phong term"}},
        {"specular", {"TODO 6", "base c I + specular max(0, N.H)^shininess I with H = normalize(L + V)"}},
        {"halfway vector", {"TODO 6", "normalize H = L + V before the dot product"}},
        {"light behind", {"TODO 6", "dot(N, L) <= 0: the light adds nothing, specular included"}},
        {"tangent frame", {"TODO 7", "T = (e1 dv2 - e2 dv1) / r, B = (e2 du1 - e1 du2) / r; no frame when r is 0 or not finite"}},
        {"normal map", {"TODO 7", "texel to 2 t / 255 - 1; T' = T made orthogonal to n, B' = cross(n, T') negated when dot(B', B) < 0; x T' + y B' + z n normalized"}},
        {"light matrix", {"TODO 8", "orthographic(-r, r, -r, r, r, 3r) * look_at(center - 2r dir, center, up)"}},
        {"shadow", {"TODO 8", "shadowed when d - bias / (2r) > the stored depth; outside the map or never drawn is lit"}},
        {"shadow bias", {"TODO 8", "bias = constant + slope * min(tan(theta), 10), in world units, divided by 2r in depth"}},
        {"pcf", {"TODO 8", "the lit fraction of the 3x3 texels around the one the point falls in"}},
        {"needs", {"TODO 9", "run only the passes a scene needs: no sampling without a texture, no shadow pass without a casting light"}},
        {"pipeline", {"TODO 9", "follow draw_scene's steps in textures_shadows.h and count each as Stats says"}},
        {"normals", {"TODOs 5 and 9", "each vertex's world normal is m4::normal_matrix(model) times it, normalized (draw_scene); "
                                      "a fragment's is those interpolated with the perspective-correct weights, normalized (fill_triangle)"}},
        {"bad input", {"TODO 9", "skip triangles with an index out of range or a non-finite clip coordinate"}},
    };
}

}  // namespace m5cp
