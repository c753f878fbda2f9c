// The milestone-2 checkpoints: one Catch2 test case per scene in scenes.cpp.
// Run them with `make check-m2`, or run this program with a checkpoint name
// (e.g. `./checkpoints_m2 m2.top_left`) to debug one of them.
#include "harness/checkpoint.h"
#include "m2/judge.h"
#include "m2/render.h"
#include "m2/scenes.h"

namespace {

cp::Suite make_suite() {
    cp::Suite s;
    s.milestone = "m2";
    for (const m2cp::Scene& scene : m2cp::scenes()) s.ids.push_back(scene.id);
    s.title = [](const std::string& id) { return m2cp::scene(id).title; };
    s.hint = [](const std::string& id) { return m2cp::scene(id).hint; };
    s.render_student = m2cp::student::render;
    s.render_reference = m2cp::reference::render;
    s.judge = m2cp::judge;
    return s;
}

[[maybe_unused]] const bool registered = cp::register_suite(make_suite());

}  // namespace
