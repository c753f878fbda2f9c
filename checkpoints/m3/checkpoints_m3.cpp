// The milestone-3 checkpoints: one Catch2 test case per scene in scenes.cpp.
// Run them with `make check-m3`, or run this program with a checkpoint name
// (e.g. `./checkpoints_m3 m3.look_at`) to debug one of them.
//
// This program links YOUR transforms.cpp with the REFERENCE milestones 1 and 2 (compiled
// like yours), so that every verdict here is about transforms: a bug left in your lines or
// triangles cannot fail a checkpoint of milestone 3. demo_m3 uses your own code throughout.
#include "harness/checkpoint.h"
#include "m3/functions.h"
#include "m3/judge.h"
#include "m3/render.h"
#include "m3/scenes.h"

namespace {

[[maybe_unused]] const bool registered = cp::register_suite(
    cp::make_suite("m3", m3cp::scenes, m3cp::student::render, m3cp::reference::render, m3cp::judge,
                   m3cp::functions(), m3cp::topics(), m3cp::use_variant));

}  // namespace
