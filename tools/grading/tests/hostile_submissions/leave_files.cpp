// Attack: leave things behind that outlive the grade where there is no private /tmp: a file in
// /run/lock (world-writable, and not /tmp), a POSIX message queue and a System V shared memory
// segment. Then draw nothing.
#include <fcntl.h>
#include <mqueue.h>
#include <sys/ipc.h>
#include <sys/shm.h>

#include <cstdio>

#include "lines.h"

namespace {
const bool attacked = [] {
    shmget(IPC_PRIVATE, 4096, IPC_CREAT | 0600);
    mq_open("/raster-hostile-queue", O_CREAT | O_RDWR, 0600, nullptr);
    for (const char* path : {"/run/lock/raster-hostile-left", "/var/tmp/raster-hostile-left", "/dev/shm/raster-hostile-left"}) {
        if (FILE* f = std::fopen(path, "w")) std::fclose(f);
    }
    return true;
}();
}  // namespace

namespace m1 {
inline namespace RASTER_FLAVOUR {
int outcode(Vec2, const Rect&) { return kInside; }
bool clip_line(Vec2&, Vec2&, const Rect&) { return attacked; }
void draw_line(Image&, Vec2, Vec2, Color) {}
void draw_line_aa(Image&, Vec2, Vec2, Color) {}
}  // namespace RASTER_FLAVOUR
}  // namespace m1
