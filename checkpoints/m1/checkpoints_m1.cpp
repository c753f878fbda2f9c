// The milestone-1 checkpoints: one Catch2 test case per scene in scenes.cpp.
// Run them with `make check-m1`, or run this program with a checkpoint name
// (e.g. `./checkpoints_m1 m1.octant_3`) to debug one of them.
#include "harness/checkpoint.h"
#include "m1/functions.h"
#include "m1/judge.h"
#include "m1/render.h"
#include "m1/scenes.h"

namespace {

cp::Suite suite() {
    cp::Suite s = cp::make_suite("m1", m1cp::scenes, m1cp::student::render, m1cp::reference::render, m1cp::judge,
                                 m1cp::functions(), {}, m1cp::use_variant);
    s.describe_call = m1cp::describe_call;
    return s;
}

[[maybe_unused]] const bool registered = cp::register_suite(suite());

}  // namespace
