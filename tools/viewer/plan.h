// Who draws what: for a display mode and the stages the student has finished, which flavour's
// code draws the frame. The rule is simple, so that the screen can say it honestly:
//
//   wireframe   the viewer's wireframe loop with the transforms of milestone 3 (the student's
//               when finished, else the reference's) and the lines of milestone 1 (likewise):
//               with only milestone 1 done, the student's lines draw the wireframe.
//   flat        milestone 4 finished: the student's m4::draw_mesh. Else, milestone 2 finished:
//               the student's triangles in the painter's order of milestone 3 (no depth buffer
//               before milestone 4; reference lighting). Else the reference's draw_mesh.
//   Gouraud, per-pixel, depth, normals
//               the student's m4::draw_mesh when milestone 4 is finished, else the reference's.
//   textured, specular, shadowed
//               the student's m5::draw_scene when milestone 5 is finished, else the reference's.
//
// The student's draw_mesh runs the student's milestones 1 to 3 inside it (it was compiled
// against them), and its probe checks that whole chain; likewise draw_scene runs the student's
// milestones 1 to 4.
#pragma once

#include <string>

#include "flavour_api.h"
#include "probe.h"

namespace viewer {

struct Plan {
    enum class Path { kDrawMesh, kPainter, kWireframe, kScene };
    Path path = Path::kDrawMesh;
    const Flavour* mesh = nullptr;        // kDrawMesh: whose m4::draw_mesh; kScene: whose m5::draw_scene
    const Flavour* transforms = nullptr;  // kPainter, kWireframe: whose milestone-3 loop
    const Flavour* primitive = nullptr;   // kPainter: whose m2 triangles; kWireframe: whose m1 lines
    const Flavour* lighting = nullptr;    // kPainter: whose m4 lighting
    std::string description;              // for the screen: "your m1 lines, reference m3 transforms"
};

Plan make_plan(Mode mode, const Stages& stages, const Flavour& student, const Flavour& reference);

}  // namespace viewer
