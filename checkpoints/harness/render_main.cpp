// render_<m>: the grader's render program for one milestone, and the ONLY grader program that
// runs a student's code. It links the student's implementation, the milestone's render half
// and scenes, and the render side of the harness (cp_render): no reference, no judge, no
// expected image. The grader starts it once per checkpoint, in a sandbox, in a fresh folder:
//
//   render_m1 <checkpoint-id> <scene-seed> <out-dir>
//
// It draws that one scene (under the variant of <scene-seed>; 0 = the public scene) and
// writes the artifacts (PNG images and values.txt) into <out-dir>. Nothing it writes is
// believed: the trusted judge reads them as hostile input (cp::read_artifacts). The watchdog
// (RASTER_WATCHDOG_SECONDS) stops a render that hangs and records where it was; the sandbox's
// own deadline stops everything else. The program ends right after the artifacts are written
// (std::_Exit): no static destructor of the student's runs after them.
//
// Built per milestone with RASTER_RENDER_HEADER / RASTER_SCENES_HEADER (the milestone's
// render.h and scenes.h) and RASTER_RENDER_NS (its namespace, e.g. m1cp).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

#include "harness/checkpoint.h"
#include RASTER_RENDER_HEADER
#include RASTER_SCENES_HEADER

int main(int argc, char** argv) {
    if (argc != 4) {
        std::cerr << "usage: " << argv[0] << " <checkpoint-id> <scene-seed> <out-dir>\n";
        return 2;
    }
    const std::string id = argv[1], out = argv[3];
    char* end = nullptr;
    const std::uint64_t seed = std::strtoull(argv[2], &end, 10);
    if (end == argv[2] || *end != '\0') {
        std::cerr << "not a seed: " << argv[2] << "\n";
        return 2;
    }
    try {
        RASTER_RENDER_NS::use_variant(seed);
        (void)RASTER_RENDER_NS::scene(id);  // an unknown id stops here, before any student code
        const cp::Watchdog watchdog(cp::watchdog_seconds(), [&](const cp::StoppedCall& s) {
            cp::Artifacts stopped;
            stopped.stopped = true;
            stopped.stopped_call = s;
            if (!s.picture.empty()) stopped.images["stopped"] = s.picture;
            cp::save_artifacts(out, stopped);
            std::fflush(nullptr);
            std::_Exit(0);
        });
        cp::Artifacts a;
        const double seconds = cp::time_best_of([&] { a = RASTER_RENDER_NS::student::render(id); });
        a.seconds = seconds;
        cp::save_artifacts(out, a);
        // Nothing of the student's may run after the artifacts are written: no static
        // destructor, no atexit handler (they could rewrite values.txt). Streams are flushed
        // here, and the process ends at once.
        std::cout.flush();
        std::cerr.flush();
        std::fflush(nullptr);
        std::_Exit(0);
    } catch (const std::exception& e) {
        std::cerr << "render " << id << ": " << e.what() << "\n";
        return 1;
    }
    return 0;
}
