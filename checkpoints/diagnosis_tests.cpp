// The known-bug diagnosis (harness/diagnosis.cpp) on pictures from the committed library: it
// names the bug a picture matches, and never one the findings rule out.
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
