// The milestone-1 checkpoints: one Catch2 test case per scene in scenes.cpp.
// Run them with `make check-m1`, or run this program with a checkpoint name
// (e.g. `./checkpoints_m1 m1.octant_3`) to debug one of them.
#include "harness/checkpoint.h"
#include "m1/judge.h"
#include "m1/render.h"
#include "m1/scenes.h"

namespace {

cp::Suite make_suite() {
    cp::Suite s;
    s.milestone = "m1";
    for (const m1cp::Scene& scene : m1cp::scenes()) s.ids.push_back(scene.id);
    s.title = [](const std::string& id) { return m1cp::scene(id).title; };
    s.hint = [](const std::string& id) { return m1cp::scene(id).hint; };
    s.render_student = m1cp::student::render;
    s.render_reference = m1cp::reference::render;
    s.judge = m1cp::judge;
    return s;
}

[[maybe_unused]] const bool registered = cp::register_suite(make_suite());

}  // namespace
