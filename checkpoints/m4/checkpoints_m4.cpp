// The milestone-4 checkpoints: one Catch2 test case per scene in scenes.cpp.
// Run them with `make check-m4`, or run this program with a checkpoint name
// (e.g. `./checkpoints_m4 m4.occlusion_order`) to debug one of them.
//
// This program links YOUR depth_lighting.cpp with the REFERENCE milestones 1 to 3 (compiled
// like yours), so that every verdict here is about depth and lighting: a bug left in your
// triangles or transforms cannot fail a checkpoint of milestone 4. demo_m4 uses your own code
// throughout.
#include "harness/checkpoint.h"
#include "m4/functions.h"
#include "m4/judge.h"
#include "m4/render.h"
#include "m4/scenes.h"

namespace {

[[maybe_unused]] const bool registered = cp::register_suite(
    cp::make_suite("m4", m4cp::scenes, m4cp::student::render, m4cp::reference::render, m4cp::judge,
                   m4cp::functions(), m4cp::topics(), m4cp::use_variant));

}  // namespace
