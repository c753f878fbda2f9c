// Diagnosis from known bugs: "your picture matches what happens when ...".
//
// Every milestone's deliberate bugs (checkpoints/<m>/bugs/*.bug) are rendered on every scene
// by `make bug-pictures` (the bug_tool program), and the pictures of the checkpoints each bug
// fails are kept in a small committed library, checkpoints/bug_pictures/<m>/:
//
//   bugs.txt              the index: per bug its summary, lesson section, fix, the
//                         checkpoints it fails, its symptom, and which pictures exist; and the
//                         measured hit rates of the diagnosis on the bugs themselves
//   <bug>/<scene>.png     the bug's main image on a scene, where it differs from the expected
//                         image and the bug fails that checkpoint (and it differs from the
//                         skeleton's picture: what an untouched TODO draws is no diagnosis)
//   skeleton/<scene>.png  the untouched skeleton's picture of a scene
//   gallery/<bug>.png     expected | with the bug | where they differ, for the lesson's
//                         troubleshooting gallery
//
// Nothing here is edited by hand, and the project's tests fail when the library, its rates
// or the lessons' galleries are not what the tool makes from the current code.
//
// When a checkpoint fails, the harness compares the student's main image with the library's
// pictures for that scene (picture_match) and names the bug whose picture matches closely, or
// says nothing. A diagnosis is advice: it never changes a verdict.
#pragma once

#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "harness/record.h"
#include "raster/image.h"

namespace cp {

// One deliberate bug, as the library's index describes it.
struct KnownBug {
    std::string name;     // the .bug file's name, e.g. "wrong_octants"
    std::string summary;  // the cause, one sentence (the .bug file's summary: line)
    std::string lesson;   // the lesson section to reread: the full heading, e.g. "4. TODO 3: ..."
    std::string fix;      // what the right code does (fix: line); may be empty
    std::string says;     // the concept its checkpoints name
    std::string todo;     // the TODO it blames (blames: line, "TODO 8"); may be empty
    std::vector<std::string> fails;  // every checkpoint the bug fails, in the suite's order
    std::string symptom_scene;       // the checkpoint the gallery shows (empty: none)
    std::string symptom;             // that checkpoint's first finding, as printed
};

// One picture of the library: bug `bug` drawing scene `scene`.
struct BugPicture {
    std::string bug, scene;
    long long differing = 0;  // pixels that differ from the expected image (beyond kPixelNoise)
    raster::Image image;      // empty until loaded
    // The findings of that checkpoint that steer the diagnosis (steers_diagnosis): what the
    // student with this bug is told beside the picture, so that the rates measure the line
    // the student reads.
    std::vector<std::string> clues;
};

// How well the diagnosis does on the deliberate bugs themselves, as diagnosis_for names them
// (the picture's match, then its checkpoint's findings, the picture's clues, leaving out the
// bugs they rule out).
//  in-sample: every library picture, diagnosed against the full library, must name its own
//    bug (or a bug whose picture on that scene is identical).
//  leave-one-out: every library picture, diagnosed with its own bug removed from the library,
//    should name nothing; naming a bug with a different picture is a wrong claim.
struct DiagnosisRates {
    int in_sample_hits = 0, in_sample_total = 0;
    int loo_wrong = 0, loo_total = 0;
};

struct BugLibrary {
    std::string milestone;    // "m1"
    std::string lesson_file;  // the lesson, relative to the repository: "milestone1_lines/README.md"
    std::vector<KnownBug> bugs;
    std::vector<BugPicture> pictures;  // in the index's order
    // The untouched skeleton's pictures (bug ""): what "not written yet" looks like. A picture
    // closer to the skeleton's than to a bug's is never diagnosed as that bug.
    std::vector<BugPicture> skeleton;
    DiagnosisRates rates;              // as measured when the library was made
    const KnownBug* bug(const std::string& name) const;  // nullptr if unknown
};

// The words a picture's finding uses for "the functions it is drawn with pass their own
// checks (m5.blinn_phong, m5.shadow_lookup)": the judges write them, diagnosis_for reads the
// checkpoints listed after them.
inline constexpr const char* kPassOwnChecks = "pass their own checks";

// A channel difference of at most this many levels is noise (compilers, FMA, rounding of
// blends), never a symptom.
inline constexpr int kPixelNoise = 3;
// Pixels of two pictures that both differ from the expected image "agree" when their colors
// are within this many levels of each other.
inline constexpr int kAgreeLevels = 12;
// A picture matches a bug's when picture_match() reaches this.
inline constexpr double kMatchThreshold = 0.8;

// The folder of the libraries: $RASTER_BUG_PICTURES_DIR, or checkpoints/bug_pictures.
std::string bug_pictures_dir();

// Reads <root>/<milestone>/bugs.txt. Pictures are loaded only for `scene` ("*": all, "": none).
// A missing library gives an empty one (a milestone with no bugs yet); a malformed one throws.
BugLibrary read_bug_library(const std::string& root, const std::string& milestone, const std::string& scene);

// The index text of a library (what read_bug_library reads back).
std::string bug_library_index(const BugLibrary& lib);

// Pixels where `img` differs from `expected` by more than kPixelNoise in some channel.
std::vector<unsigned char> differing_pixels(const raster::Image& img, const raster::Image& expected);

// How closely a picture matches a bug's picture of the same scene, from 0 to 1: the pixels
// where both differ from the expected image and agree in color, divided by the pixels where
// either differs (the intersection-over-union of the two sets of wrong pixels, counting only
// agreeing colors). 0 when the sizes differ or neither differs from the expected image.
double picture_match(const raster::Image& picture, const raster::Image& bug_picture, const raster::Image& expected);

// The bugs whose picture of `scene` matches `picture` (best first): those reaching
// kMatchThreshold, within 0.05 of the best, and matching better than the skeleton's picture
// does. `without` removes one bug from the library (for leave-one-out). Uses the pictures
// loaded in `lib`.
std::vector<const BugPicture*> diagnose(const BugLibrary& lib, const std::string& scene, const raster::Image& picture,
                                        const raster::Image& expected, const std::string& without = {});

// Two pictures of a scene are the same symptom: each matches the other perfectly.
bool same_symptom(const raster::Image& a, const raster::Image& b, const raster::Image& expected);

// Measures DiagnosisRates on a library whose pictures are all loaded; `expected(scene)` gives
// each scene's expected image.
// With `log`, each miss and each wrong claim is written there, one line each.
DiagnosisRates measure_rates(const BugLibrary& lib, const std::vector<raster::Image>& expected_per_picture,
                             std::ostream* log = nullptr);

// Whether a printed finding steers the diagnosis: it sends the student to another TODO first
// ("fix TODO 7 first") or says the functions a picture is drawn with pass their own checks.
bool steers_diagnosis(const std::string& finding);

// The TODO numbers in `text`'s "TODO 8", "TODOs 2 and 8", "TODOs 1-2" (3a counts as 3).
std::set<int> todo_numbers(const std::string& text);

// Whether a checkpoint's findings leave known bug `b` in the diagnosis (see diagnosis_for).
bool findings_admit(const KnownBug& b, const std::vector<std::string>& findings);

// The harness's hook: for a failing checkpoint of `milestone`, the sentence that names the
// matching known bug(s) and the lesson section to reread, or "" when none matches (or the
// library cannot be read: a diagnosis is never worth failing over).
// `findings` are the checkpoint's printed findings: a known bug of a TODO none of them names
// is left out, so the line never contradicts them (and says nothing when no bug is left); so is
// a known bug that fails a checkpoint a finding says the student's functions pass ("pass their
// own checks (m5.shadow_lookup)").
std::string diagnosis_for(const std::string& milestone, const std::string& id, const raster::Image& picture,
                          const raster::Image& expected, const std::vector<std::string>& findings = {});

// "m1: 27 of 27 pictures of the deliberate bugs diagnosed right (100%), ..." for each of the
// milestones given that has a library; one line each, for the report's footer.
std::vector<std::string> diagnosis_rates_lines(const std::vector<std::string>& milestones);
std::string rates_text(const DiagnosisRates& r);

// The HTML report's footer: the rates of the milestones the records belong to.
std::string diagnosis_footer_html(const std::vector<Record>& records);

}  // namespace cp
