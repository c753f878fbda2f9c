// Unit tests of the viewer's parts that need no window: the probes' comparisons, the plan of
// who draws what, the camera's limits, fitting a model, the script parser. The window itself
// is tested by viewer_test.sh.
#include "raster_catch.h"

#include <signal.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

#include "camera.h"
#include "model.h"
#include "plan.h"
#include "probe.h"
#include "script.h"

using viewer::Mode;

TEST_CASE("images match when few pixels differ, never when nothing is drawn", "[viewer]") {
    raster::Image ref(20, 10), student(20, 10);
    for (int x = 0; x < 20; ++x) ref.set(x, 5, {255, 255, 255});
    CHECK_FALSE(viewer::compare_images(student, ref, 0, 0.03).yours);  // a skeleton draws nothing
    CHECK(viewer::compare_images(student, ref, 0, 0.03).detail == "draws nothing yet");
    student = ref;
    CHECK(viewer::compare_images(student, ref, 0, 0.03).yours);
    student.set(3, 5, {0, 0, 0});
    student.set(3, 4, {255, 255, 255});  // a tie broken the other way: 2 pixels differ
    CHECK(viewer::compare_images(student, ref, 0, 0.03).yours);
    for (int x = 0; x < 10; ++x) student.set(x, 5, {0, 0, 0});
    CHECK_FALSE(viewer::compare_images(student, ref, 0, 0.03).yours);
    CHECK_FALSE(viewer::compare_images(raster::Image(5, 5, {1, 1, 1}), ref, 0, 0.03).yours);  // wrong size
}

TEST_CASE("numbers match within 1e-6 relative, and NaN or a wrong count never does", "[viewer]") {
    CHECK(viewer::compare_numbers({1, 2e6, 0}, {1 + 1e-9, 2e6 + 1, 0}).yours);
    CHECK_FALSE(viewer::compare_numbers({1, 2, 0}, {1, 2.01, 0}).yours);
    CHECK_FALSE(viewer::compare_numbers({std::nan("")}, {0}).yours);
    CHECK_FALSE(viewer::compare_numbers({1, 2}, {1, 2, 3}).yours);
}

TEST_CASE("a probe that crashes, hangs or throws only marks its own stage unfinished", "[viewer]") {
    viewer::Flavour student, reference;
    reference.probe_m1 = reference.probe_m2 = reference.probe_m4 = [] { return raster::Image(4, 4, {9, 9, 9}); };
    reference.probe_m3 = [] { return std::vector<double>{1, 2}; };
    student.probe_m1 = []() -> raster::Image {
        raise(SIGKILL);  // a crash no handler can catch (Catch2 handles SIGSEGV and SIGABRT)
        return {};
    };
    student.probe_m2 = []() -> raster::Image {
        std::this_thread::sleep_for(std::chrono::hours(1));  // a loop that never ends
        return {};
    };
    student.probe_m3 = []() -> std::vector<double> { throw std::runtime_error("boom"); };
    student.probe_m4 = reference.probe_m4;
    const viewer::Stages stages = viewer::probe_stages(student, reference, {true, 1.0});
    CHECK_FALSE(stages[0].yours);
    CHECK(stages[0].detail.find("crashed") == 0);
    CHECK_FALSE(stages[1].yours);
    CHECK(stages[1].detail == "did not return within 1 s");
    CHECK_FALSE(stages[2].yours);
    CHECK(stages[2].detail == "threw: boom");
    CHECK(stages[3].yours);
}

TEST_CASE("the plan: the student's code wherever the stage is finished, else the reference", "[viewer]") {
    const viewer::Flavour student, reference;  // empty tables: only their addresses matter here
    viewer::Stages stages = viewer::all_reference("test");
    auto plan = viewer::make_plan(Mode::kWireframe, stages, student, reference);
    CHECK(plan.path == viewer::Plan::Path::kWireframe);
    CHECK(plan.primitive == &reference);
    CHECK(plan.transforms == &reference);

    stages[0].yours = true;  // only milestone 1: the student's lines, the reference's transforms
    plan = viewer::make_plan(Mode::kWireframe, stages, student, reference);
    CHECK(plan.primitive == &student);
    CHECK(plan.transforms == &reference);
    CHECK(plan.description == "your m1 lines, reference m3 transforms");
    CHECK(viewer::make_plan(Mode::kFlat, stages, student, reference).mesh == &reference);

    stages[1].yours = true;  // and milestone 2: flat is the student's triangles, painter's order
    plan = viewer::make_plan(Mode::kFlat, stages, student, reference);
    CHECK(plan.path == viewer::Plan::Path::kPainter);
    CHECK(plan.primitive == &student);
    CHECK(plan.transforms == &reference);
    CHECK(plan.lighting == &reference);
    CHECK(viewer::make_plan(Mode::kGouraud, stages, student, reference).mesh == &reference);

    stages[2].yours = stages[3].yours = true;  // everything: the student's draw_mesh
    for (const Mode m : {Mode::kFlat, Mode::kGouraud, Mode::kPerPixel, Mode::kDepth, Mode::kNormals}) {
        plan = viewer::make_plan(m, stages, student, reference);
        CHECK(plan.path == viewer::Plan::Path::kDrawMesh);
        CHECK(plan.mesh == &student);
    }
}

TEST_CASE("the camera stays finite with 0 < near < far wherever it goes", "[viewer]") {
    viewer::OrbitCamera cam;
    const auto check = [&] {
        const viewer::View v = cam.view(0);
        CHECK(raster::is_finite(v.eye));
        CHECK(v.near > 0);
        CHECK(v.far > v.near);
        CHECK(std::isfinite(v.far));
    };
    check();
    CHECK(cam.warning().empty());
    cam.zoom(1e-30);  // inside the model
    check();
    CHECK(cam.warning().find("inside") != std::string::npos);
    cam.zoom(1e300);  // far away
    check();
    CHECK(cam.warning().find("far away") != std::string::npos);
    cam.zoom(std::numeric_limits<double>::quiet_NaN());
    cam.orbit(1e9, -1e9);
    cam.orbit(std::numeric_limits<double>::infinity(), 0);
    cam.pan(1e300, -1e300);
    check();
    cam.reset();
    CHECK(cam.warning().empty());
}

TEST_CASE("models are fitted into the unit sphere without overflow, and no size is refused", "[viewer]") {
    raster::Mesh m;
    m.positions = {{-1e308, 0, 0}, {1e308, 0, 0}, {0, 1e308, 5}};
    REQUIRE(viewer::fit_unit_sphere(m));
    double farthest = 0;
    for (const raster::Vec3 p : m.positions) farthest = std::max(farthest, raster::length(p));
    CHECK(farthest == Approx(1.0));
    m.positions = {{2, 2, 2}, {2, 2, 2}};
    CHECK_FALSE(viewer::fit_unit_sphere(m));
    std::string error;
    const viewer::Model fallback = viewer::load_model("/nonexistent/file.obj", error);
    CHECK(error.find("cannot load") != std::string::npos);
    CHECK_FALSE(fallback.mesh.triangles.empty());
    viewer::Model big;
    REQUIRE(viewer::make_named("big-torus", big));
    CHECK(big.mesh.triangles.size() == 100000);
}

TEST_CASE("scripts parse into steps, and a bad step is named", "[viewer]") {
    std::vector<viewer::Step> steps;
    std::string error;
    REQUIRE(viewer::parse_script("key w 3; drag shift+left 1 2 3 4\n# a comment; still one\nwheel -2;screenshot a.png;quit",
                                 steps, error));
    REQUIRE(steps.size() == 5);
    CHECK(steps[0].kind == viewer::Step::Kind::kKey);
    CHECK(steps[0].name == "w");
    CHECK(steps[0].count == 3);
    CHECK(steps[1].kind == viewer::Step::Kind::kDrag);
    CHECK(steps[1].shift);
    CHECK(steps[1].name == "left");
    CHECK(steps[1].y1 == 4);
    CHECK(steps[2].count == -2);
    CHECK(steps[3].name == "a.png");
    CHECK(steps[4].kind == viewer::Step::Kind::kQuit);
    CHECK_FALSE(viewer::parse_script("key w; jump 3", steps, error));
    CHECK(error.find("jump 3") != std::string::npos);
    CHECK_FALSE(viewer::parse_script("drag left 1 2", steps, error));
    CHECK_FALSE(viewer::parse_script("key w x", steps, error));
}
