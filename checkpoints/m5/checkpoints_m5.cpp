// The milestone-5 checkpoints: one Catch2 test case per scene in scenes.cpp.
// Run them with `make check-m5`, or run this program with a checkpoint name
// (e.g. `./checkpoints_m5 m5.sampling`) to debug one of them.
//
// This program links YOUR textures_shadows.cpp with the REFERENCE milestones 1 to 4 (compiled
// like yours), so that every verdict here is about textures, specular light and shadows: a bug
// left in your triangles, transforms or depth buffer cannot fail a checkpoint of milestone 5.
// demo_m5 uses your own code throughout.
#include "harness/checkpoint.h"
#include "m5/functions.h"
#include "m5/judge.h"
#include "m5/render.h"
#include "m5/scenes.h"

namespace {

[[maybe_unused]] const bool registered = cp::register_suite(
    cp::make_suite("m5", m5cp::scenes, m5cp::student::render, m5cp::reference::render, m5cp::judge,
                   m5cp::functions(), m5cp::topics(), m5cp::use_variant));

}  // namespace
