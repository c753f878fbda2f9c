// Unit tests of the viewer's parts that need no window: the probes' comparisons, the plan of
// who draws what, the camera's limits, fitting a model, milestone 5's scenes (uv seams, the
// textures, what each mode draws), the circling light, the script parser. The window itself
// is tested by viewer_test.sh.
#include "raster_catch.h"

#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <thread>

#include "app.h"
#include "camera.h"
#include "model.h"
#include "plan.h"
#include "probe.h"
#include "scene.h"
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
    reference.probe_m1 = reference.probe_m2 = reference.probe_m4 = reference.probe_m5 = [] {
        return raster::Image(4, 4, {9, 9, 9});
    };
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
    student.probe_m5 = [] { return raster::Image(4, 4); };  // a skeleton: draws nothing
    const viewer::Stages stages = viewer::probe_stages(student, reference, {true, 1.0});
    CHECK_FALSE(stages[0].yours);
    CHECK(stages[0].detail.find("crashed") == 0);
    CHECK_FALSE(stages[1].yours);
    CHECK(stages[1].detail == "did not return within 1 s");
    CHECK_FALSE(stages[2].yours);
    CHECK(stages[2].detail == "threw: boom");
    CHECK(stages[3].yours);
    CHECK_FALSE(stages[4].yours);
    CHECK(stages[4].detail == "draws nothing yet");
    viewer::Flavour no_probe;  // a table without a milestone's probe never crashes the viewer
    const viewer::Stages missing = viewer::probe_stages(no_probe, reference, {false, 1.0});
    CHECK_FALSE(missing[4].yours);
    CHECK(missing[4].detail == "no probe for this milestone");
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

    stages[2].yours = stages[3].yours = true;  // milestones 1 to 4: the student's draw_mesh
    for (const Mode m : {Mode::kFlat, Mode::kGouraud, Mode::kPerPixel, Mode::kDepth, Mode::kNormals}) {
        plan = viewer::make_plan(m, stages, student, reference);
        CHECK(plan.path == viewer::Plan::Path::kDrawMesh);
        CHECK(plan.mesh == &student);
    }
    for (const Mode m : {Mode::kTextured, Mode::kSpecular, Mode::kShadowed}) {  // milestone 5 not yet
        plan = viewer::make_plan(m, stages, student, reference);
        CHECK(plan.path == viewer::Plan::Path::kScene);
        CHECK(plan.mesh == &reference);
        CHECK(plan.description == "reference m5 draw_scene");
    }
    stages[4].yours = true;
    for (const Mode m : {Mode::kTextured, Mode::kSpecular, Mode::kShadowed}) {
        plan = viewer::make_plan(m, stages, student, reference);
        CHECK(plan.path == viewer::Plan::Path::kScene);
        CHECK(plan.mesh == &student);
        CHECK(plan.description == "your m5 draw_scene (your m1-m4 inside)");
    }
    CHECK(std::string(viewer::stage_title(5)) == "textures");
    CHECK(std::string(viewer::mode_name(Mode::kShadowed)) == "shadowed");
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
    // A scene larger than the model (the shadowed mode's floor): near and far hold it all.
    const viewer::View wide = cam.view(0, 45, 3);
    const double d = raster::length(wide.eye);
    CHECK(wide.near <= d - 3);
    CHECK(wide.far >= d + 3);
    CHECK(wide.near > 0);
    const viewer::View bad = cam.view(0, 45, std::numeric_limits<double>::quiet_NaN());  // as radius 1
    CHECK(bad.near == Approx(cam.view(0).near));
    CHECK(bad.far == Approx(cam.view(0).far));
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

namespace {

// The largest jump of u or v along any edge of any triangle (after scaling by the repeats).
double largest_uv_jump(const viewer::TexturedMesh& m) {
    double jump = 0;
    for (const auto& t : m.triangles)
        for (int k = 0; k < 3; ++k) {
            const raster::Vec2 a = m.uvs[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])];
            const raster::Vec2 b = m.uvs[static_cast<std::size_t>(t[static_cast<std::size_t>((k + 1) % 3)])];
            jump = std::max({jump, std::abs(a.x - b.x), std::abs(a.y - b.y)});
        }
    return jump;
}

}  // namespace

TEST_CASE("texture coordinates: no triangle runs backwards across a seam", "[viewer]") {
    SECTION("the torus by its own angles, split along both seams") {
        viewer::Model torus = viewer::default_model();
        REQUIRE(torus.uv_mapping == viewer::UvMapping::kTorus);
        const viewer::UvRepeats r = viewer::uv_repeats(torus.uv_mapping);
        const viewer::TexturedMesh m = viewer::with_uvs(torus.mesh, torus.uv_mapping, torus.ring_radius, r);
        REQUIRE(m.positions.size() == m.uvs.size());
        REQUIRE(m.positions.size() == m.normals.size());
        CHECK(m.triangles.size() == torus.mesh.triangles.size());
        // 48 rings x 24 sides: one more ring and one more side where the seams are.
        CHECK(m.positions.size() == 49u * 25u);
        // Neighbours are one ring (12 / 48 of a repeat) or one side (4 / 24) apart, never a turn.
        CHECK(largest_uv_jump(m) <= 0.26);
        // u runs over the 12 repeats once around the ring, v over the 4 around the tube.
        double u_min = 1e9, u_max = -1e9, v_min = 1e9, v_max = -1e9;
        for (const raster::Vec2 uv : m.uvs) {
            u_min = std::min(u_min, uv.x);
            u_max = std::max(u_max, uv.x);
            v_min = std::min(v_min, uv.y);
            v_max = std::max(v_max, uv.y);
        }
        CHECK(u_min == Approx(0).margin(1e-9));
        CHECK(u_max == Approx(12));
        CHECK(v_min == Approx(0).margin(1e-9));
        CHECK(v_max == Approx(4));
        for (std::size_t i = 0; i < m.normals.size(); ++i) CHECK(raster::length(m.normals[i]) == Approx(1));
    }
    SECTION("the sphere, its poles and a model without normals") {
        raster::Mesh sphere = raster::make_uv_sphere(8, 12);
        sphere.normals.clear();  // the viewer computes them, before splitting
        const viewer::TexturedMesh m = viewer::with_uvs(sphere, viewer::UvMapping::kSpherical, 0, {8, 4});
        CHECK(m.triangles.size() == sphere.triangles.size());
        CHECK(largest_uv_jump(m) <= 8.0 / 12 + 1e-9);  // one meridian apart at most (a pole's mean: half)
        for (std::size_t i = 0; i < m.positions.size(); ++i) {
            // The normal of a unit sphere is its position: the same on both sides of a seam.
            CHECK(raster::length(m.normals[i] - m.positions[i]) < 0.2);
            CHECK(m.uvs[i].y >= 0);
            CHECK(m.uvs[i].y <= 4 + 1e-12);
        }
    }
    SECTION("bad indices are dropped, not read") {
        raster::Mesh bad;
        bad.positions = {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}};
        bad.triangles = {{0, 1, 2}, {0, 1, 7}, {-1, 1, 2}};
        const viewer::TexturedMesh m = viewer::with_uvs(bad, viewer::UvMapping::kSpherical, 0, {8, 4});
        CHECK(m.triangles.size() == 1);
        CHECK(m.positions.size() == 3);
    }
}

TEST_CASE("milestone 5's scenes: textures, floor, and what each mode draws", "[viewer]") {
    const raster::Image bricks = viewer::brick_texture(), checker = viewer::checker_texture();
    CHECK(bricks.width() == 128);
    CHECK(bricks.height() == 128);
    CHECK(checker.width() == 64);
    const auto gray = [](raster::Color c) { return std::abs(c.r - c.b) < 30 && c.g > 170; };
    CHECK(gray(bricks.at(10, 1)));  // mortar on top of every course...
    CHECK(gray(bricks.at(70, 34)));
    CHECK(gray(bricks.at(33, 40)));  // ...between the bricks, the odd courses offset by half a brick
    CHECK(bricks.at(10, 10).r > bricks.at(10, 10).g + 40);  // ...and red bricks
    CHECK(checker.at(0, 0) != checker.at(32, 0));
    CHECK(checker.at(0, 0) == checker.at(32, 32));

    const viewer::Model torus = viewer::default_model();
    const viewer::SceneAssets a = viewer::make_scene_assets(torus);
    double lowest = 0;
    for (const raster::Vec3 p : torus.mesh.positions) lowest = std::min(lowest, p.y);
    CHECK(a.floor_y < lowest);
    CHECK(a.floor_y > lowest - 0.5);
    REQUIRE(a.floor.triangles.size() == 2);
    for (const auto& t : a.floor.triangles) {  // facing up: lit from above
        const raster::Vec3 n = raster::cross(a.floor.positions[t[1]] - a.floor.positions[t[0]],
                                             a.floor.positions[t[2]] - a.floor.positions[t[0]]);
        CHECK(n.y > 0);
    }
    for (const raster::Vec3 p : a.floor.positions) CHECK(raster::length(p) <= a.scene_radius + 1e-9);

    const viewer::SceneSetup textured = viewer::scene_setup(Mode::kTextured, a);
    CHECK(textured.model.textured);
    CHECK(textured.model.specular == 0);
    CHECK_FALSE(textured.floor);
    CHECK_FALSE(textured.shadows);
    const viewer::SceneSetup specular = viewer::scene_setup(Mode::kSpecular, a);
    CHECK_FALSE(specular.model.textured);
    CHECK(specular.model.specular > 0);
    CHECK_FALSE(specular.shadows);
    const viewer::SceneSetup shadowed = viewer::scene_setup(Mode::kShadowed, a);
    CHECK(shadowed.floor);
    CHECK(shadowed.floor_surface.textured);
    CHECK(shadowed.shadows);
    // The light's box holds the floor's corners and the model's unit sphere.
    for (const raster::Vec3 p : a.floor.positions) CHECK(raster::length(p - shadowed.shadow_center) <= shadowed.shadow_radius);
    CHECK(raster::length(shadowed.shadow_center) + 1 <= shadowed.shadow_radius);
}

TEST_CASE("the light circles the model once in kLightTurnSeconds, and O stops it", "[viewer]") {
    const viewer::Flavour student, reference;  // never drawn with here
    viewer::App app(student, reference, viewer::all_reference("test"));
    const double start = app.light_azimuth(), elevation = app.light_elevation();
    CHECK_FALSE(app.animating());
    app.toggle_light_circle();
    CHECK(app.animating());
    app.advance(viewer::App::kLightTurnSeconds / 4);
    CHECK(std::remainder(app.light_azimuth() - start - std::numbers::pi / 2, 2 * std::numbers::pi) == Approx(0).margin(1e-9));
    CHECK(app.light_elevation() == elevation);
    app.toggle_light_circle();
    const double stopped = app.light_azimuth();
    app.advance(1);
    CHECK(app.light_azimuth() == stopped);
    app.set_light(1e300, std::numeric_limits<double>::infinity());  // ignored
    CHECK(app.light_azimuth() == stopped);
    app.set_light(0.5, 9);  // the elevation is clamped
    CHECK(app.light_elevation() == 1.5);
}
