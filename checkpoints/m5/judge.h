// The judge half of the milestone-5 checkpoints (trusted: it runs no code under test).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "harness/checkpoint.h"

namespace m5cp {
cp::Judgement judge(const std::string& id, const cp::Artifacts& artifacts, const cp::Artifacts& reference,
                    const raster::Image& expected);
}  // namespace m5cp

namespace m5cp {
struct Panel;
// Exact pictures of a panel, computed from the scene alone (the lesson's tables use them too).
// The 16x supersampled bilinear truth of item 0 (an unlit textured quad), panel-sized; `valid`
// marks the pixels wholly on the quad (row-major), the only ones truth_error counts.
struct Truth {
    raster::Image img;
    std::vector<char> valid;
};
Truth bilinear_truth(const Panel& p);
// The mean absolute channel difference between panel p of `img` and the truth, in levels.
double truth_error(const raster::Image& img, const Panel& p, const Truth& t);
// Pixels of panel p of `img` in the wrong light state against a ray cast to the light (the
// panel's light that casts shadows), split by which way they are wrong, and the pixels counted.
struct LightState {
    long long missing = 0;        // the ray to the light is blocked, but the pixel looks lit
    long long spurious = 0;       // the ray reaches the light, but the pixel looks shadowed
    long long counted = 0;        // pixels that face the light where lit and shadowed differ visibly
    long long in_shadow = 0;      // of them, where the ray to the light is blocked and ambient shows
    long long too_dark = 0;       // of those, nearer black than ambient alone: ambient shadowed too
    long long facing_away = 0;    // pixels clearly facing away from the panel's only light
    long long lit_from_behind = 0;  // of them, lit as if L were +direction
    long long wrong() const { return missing + spurious; }
};
LightState wrong_light_state(const raster::Image& img, const Panel& p);
}  // namespace m5cp
