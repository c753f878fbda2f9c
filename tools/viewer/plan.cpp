#include "plan.h"

namespace viewer {

const char* mode_name(Mode mode) {
    switch (mode) {
        case Mode::kWireframe: return "wireframe";
        case Mode::kFlat: return "flat";
        case Mode::kGouraud: return "Gouraud";
        case Mode::kPerPixel: return "per-pixel";
        case Mode::kDepth: return "depth view";
        case Mode::kNormals: return "normals view";
        case Mode::kTextured: return "textured";
        case Mode::kSpecular: return "specular";
        case Mode::kShadowed: return "shadowed";
    }
    return "?";
}

Plan make_plan(Mode mode, const Stages& stages, const Flavour& student, const Flavour& reference) {
    const auto yours = [&](int stage) { return stages[static_cast<std::size_t>(stage - 1)].yours; };
    const auto pick = [&](int stage) { return yours(stage) ? &student : &reference; };
    const auto whose = [&](int stage) { return std::string(yours(stage) ? "your" : "reference"); };

    Plan plan;
    if (is_scene_mode(mode)) {
        plan.path = Plan::Path::kScene;
        plan.mesh = pick(5);
        plan.description = yours(5) ? "your m5 draw_scene (your m1-m4 inside)" : "reference m5 draw_scene";
    } else if (mode == Mode::kWireframe) {
        plan.path = Plan::Path::kWireframe;
        plan.transforms = pick(3);
        plan.primitive = pick(1);
        plan.description = whose(1) + " m1 lines, " + whose(3) + " m3 transforms";
    } else if (mode == Mode::kFlat && !yours(4) && yours(2)) {
        plan.path = Plan::Path::kPainter;
        plan.transforms = pick(3);
        plan.primitive = &student;
        plan.lighting = &reference;
        plan.description = "your m2 triangles in " + whose(3) + " m3 painter's order (no depth buffer before m4), reference m4 light";
    } else {
        plan.path = Plan::Path::kDrawMesh;
        plan.mesh = pick(4);
        plan.description = yours(4) ? "your m4 draw_mesh (your m1-m3 inside)" : "reference m4 draw_mesh";
    }
    return plan;
}

}  // namespace viewer
