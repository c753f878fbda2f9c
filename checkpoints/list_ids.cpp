// checkpoint_ids <m>: the checkpoint ids of milestone <m>, one per line, from the trusted scene
// tables. CTest registers the student's checkpoints from this list (see raster_variant in
// CMakeLists.txt) instead of asking the student's own program, which would run the student's
// code (its static initializers) while the project builds or the tests are listed.
#include <iostream>
#include <string>

#include "m1/scenes.h"
#include "m2/scenes.h"
#include "m3/scenes.h"
#include "m4/scenes.h"
#include "m5/scenes.h"

namespace {
template <typename Scene>
int print(const std::vector<Scene>& scenes) {
    for (const Scene& s : scenes) std::cout << s.id << "\n";
    return 0;
}
}  // namespace

int main(int argc, char** argv) {
    const std::string m = argc == 2 ? argv[1] : "";
    if (m == "m1") return print(m1cp::scenes());
    if (m == "m2") return print(m2cp::scenes());
    if (m == "m3") return print(m3cp::scenes());
    if (m == "m4") return print(m4cp::scenes());
    if (m == "m5") return print(m5cp::scenes());
    std::cerr << "usage: checkpoint_ids m1|m2|m3|m4|m5\n";
    return 2;
}
