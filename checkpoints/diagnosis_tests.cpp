// The known-bug diagnosis (harness/diagnosis.cpp) on pictures from the committed library: it
// names the bug a picture matches, and never one the findings rule out.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "raster_catch.h"

#include "harness/diagnosis.h"
#include "raster/io.h"

namespace {

const std::string kRoot = RASTER_TEST_SOURCE_DIR;

raster::Image picture(const std::string& path) { return raster::read_png(kRoot + "/" + path); }

}  // namespace

TEST_CASE("a picture two bugs draw alike names both when nothing rules one out") {
    const raster::Image culled = picture("checkpoints/bug_pictures/m5/shadow_pass_culls_back_faces/m5.light_behind.png");
    const raster::Image expected = picture("checkpoints/expected/m5/m5.light_behind.png");
    const std::string said = cp::diagnosis_for("m5", "m5.light_behind", culled, expected, {});
    CHECK(said.find("(shadow_pass_culls_back_faces)") != std::string::npos);
}

TEST_CASE("a known bug that fails a checkpoint the findings say passes is not named") {
    // Culling in the depth pass draws on m5.light_behind what reversing the shadow comparison
    // draws; but a reversed comparison fails m5.shadow_lookup, which this student passes.
    const raster::Image culled = picture("checkpoints/bug_pictures/m5/shadow_pass_culls_back_faces/m5.light_behind.png");
    const raster::Image expected = picture("checkpoints/expected/m5/m5.light_behind.png");
    const std::vector<std::string> findings = {
        "[light behind] (TODOs 5 and 9) the picture differs from the expected one beyond the tolerance (see "
        "diff.png), though the functions it is drawn with pass their own checks (m5.blinn_phong, m5.shadow_lookup), "
        "so look at how they are called"};
    const std::string said = cp::diagnosis_for("m5", "m5.light_behind", culled, expected, findings);
    CHECK(said.find("(shadow_pass_culls_back_faces)") != std::string::npos);
    CHECK(said.find("shadow_compare_reversed") == std::string::npos);
}

TEST_CASE("a prerequisite's 'fix TODO N first' keeps only that TODO's bugs of that concept") {
    const raster::Image culled = picture("checkpoints/bug_pictures/m5/shadow_pass_culls_back_faces/m5.light_behind.png");
    const raster::Image expected = picture("checkpoints/expected/m5/m5.light_behind.png");
    const std::vector<std::string> findings = {
        "[shadow] (TODO 8) fix TODO 8 first (see m5.shadow_lookup, which tests it alone; this picture is drawn with "
        "it): shadow_factor(...) gave 1, expected 0"};
    const std::string said = cp::diagnosis_for("m5", "m5.light_behind", culled, expected, findings);
    CHECK(said.find("shadow_pass_culls_back_faces") == std::string::npos);  // a TODO 9 bug
}

TEST_CASE("the rates measure the line the student reads: a picture's clues rule out what its findings would") {
    // Taking a light's direction as L and reversing the shadow comparison draw m5.shadow_box
    // alike; only the second fails m5.shadow_lookup. Each picture, with its own bug left out of
    // the library, matches the other's; but the first one's checkpoint says m5.shadow_lookup
    // passes, and the second one's sends the student to TODO 8 first, which the first bug is not:
    // diagnosis_for names nothing, and so must the leave-one-out count.
    const raster::Image expected = picture("checkpoints/expected/m5/m5.shadow_box.png");
    cp::BugLibrary lib;
    lib.milestone = "m5";
    lib.bugs = {{"to_light", "takes the direction as L", "", "", "specular", "TODO 5, 9", {"m5.shadow_box"}, "", ""},
                {"reversed", "reverses the comparison", "", "", "shadow", "TODO 8", {"m5.shadow_lookup", "m5.shadow_box"}, "", ""}};
    const std::string passes =
        "[shadow] (TODOs 5 and 9) the picture differs from the expected one beyond the tolerance (see diff.png), "
        "though the functions it is drawn with pass their own checks (m5.blinn_phong, m5.shadow_lookup), so look at "
        "how they are called";
    const std::string first = "[shadow] (TODO 8) fix TODO 8 first (see m5.shadow_lookup, which tests it alone)";
    CHECK(cp::steers_diagnosis(passes));
    CHECK(cp::steers_diagnosis(first));
    CHECK_FALSE(cp::steers_diagnosis("[image] 12 pixels differ from the expected image"));
    lib.pictures = {{"to_light", "m5.shadow_box", 1, picture("checkpoints/bug_pictures/m5/light_direction_as_to_light/m5.shadow_box.png"), {}},
                    {"reversed", "m5.shadow_box", 1, picture("checkpoints/bug_pictures/m5/shadow_compare_reversed/m5.shadow_box.png"), {}}};
    const std::vector<raster::Image> expected_each = {expected, expected};
    // Without clues the alike pictures name each other.
    const cp::DiagnosisRates blind = cp::measure_rates(lib, expected_each);
    CHECK(blind.in_sample_hits == 2);
    CHECK(blind.loo_wrong == 2);
    // With them, neither does.
    lib.pictures[0].clues = {passes};
    lib.pictures[1].clues = {first};
    const cp::DiagnosisRates told = cp::measure_rates(lib, expected_each);
    CHECK(told.in_sample_hits == 2);
    CHECK(told.loo_wrong == 0);
    CHECK_FALSE(cp::findings_admit(lib.bugs[1], {passes}));
    CHECK(cp::findings_admit(lib.bugs[0], {passes}));
    CHECK_FALSE(cp::findings_admit(lib.bugs[0], {first}));
    CHECK(cp::findings_admit(lib.bugs[1], {first}));
}

TEST_CASE("a library's clues survive its index") {
    cp::BugLibrary lib;
    lib.milestone = "m9";
    lib.lesson_file = "lesson.md";
    lib.bugs = {{"b", "a bug", "1. Section", "", "topic", "TODO 1", {"m9.scene"}, "", ""}};
    lib.pictures = {{"b", "m9.scene", 7, {}, {"[topic] (TODO 1) fix TODO 1 first\twith a tab", "second clue"}}};
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "raster_diagnosis_index_test" / "m9";
    std::filesystem::create_directories(dir);
    {
        std::ofstream out(dir / "bugs.txt");
        out << cp::bug_library_index(lib);
    }
    const cp::BugLibrary back = cp::read_bug_library(dir.parent_path().string(), "m9", "");
    REQUIRE(back.pictures.size() == 1);
    CHECK(back.pictures[0].clues == std::vector<std::string>{"[topic] (TODO 1) fix TODO 1 first with a tab", "second clue"});
    std::filesystem::remove_all(dir.parent_path());
}
