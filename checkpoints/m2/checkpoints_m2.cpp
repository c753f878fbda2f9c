// The milestone-2 checkpoints: one Catch2 test case per scene in scenes.cpp.
// Run them with `make check-m2`, or run this program with a checkpoint name
// (e.g. `./checkpoints_m2 m2.top_left`) to debug one of them.
#include "harness/checkpoint.h"
#include "m2/functions.h"
#include "m2/judge.h"
#include "m2/render.h"
#include "m2/scenes.h"

namespace {

[[maybe_unused]] const bool registered = cp::register_suite(
    cp::make_suite("m2", m2cp::scenes, m2cp::student::render, m2cp::reference::render, m2cp::judge,
                   m2cp::functions(), {}, m2cp::use_variant));

}  // namespace
