// A submission for grade_test.sh's isolation cases (graded without the code check, beside an
// honest classmate in --batch): before drawing anything it leaves System V IPC objects (shared
// memory, a semaphore set, a message queue) and a POSIX message queue behind, then looks for
// the classmate's folder next to its own and tries to get in. Its exit status tells the test
// what it found (the judge reports it as "the render program exited with status N"):
//   43  it could enter a classmate's folder or run its program (the isolation failed)
//   42  it saw a classmate's folder but could not enter it (the premise of the test held)
//   41  it saw no classmate's folder at all (bubblewrap: nothing of theirs is mounted)
#include <dirent.h>
#include <fcntl.h>
#include <mqueue.h>
#include <sys/ipc.h>
#include <sys/msg.h>
#include <sys/sem.h>
#include <sys/shm.h>
#include <unistd.h>

#include <climits>
#include <cstdlib>
#include <string>

#include "lines.h"

namespace {
std::string up(const std::string& p) { return p.substr(0, p.rfind('/')); }

const bool probed = [] {
    shmget(IPC_PRIVATE, 4096, IPC_CREAT | 0600);
    semget(IPC_PRIVATE, 1, IPC_CREAT | 0600);
    msgget(IPC_PRIVATE, IPC_CREAT | 0600);
    mq_open("/raster-probe-queue", O_CREAT | O_RDWR, 0600, nullptr);
    char cwd[PATH_MAX];
    if (!getcwd(cwd, sizeof cwd)) std::_Exit(40);
    // The render runs in <tmp>/raster-grade.XXXXXX/run/<checkpoint>: the classmates' folders
    // are the other raster-grade.* in <tmp>.
    const std::string own = up(up(cwd)), parent = up(own);
    bool seen = false;
    for (int attempt = 0; attempt < 30 && !seen; ++attempt) {
        if (DIR* d = opendir(parent.c_str())) {
            while (dirent* e = readdir(d)) {
                const std::string name = e->d_name, other = parent + "/" + name;
                if (name.rfind("raster-grade.", 0) != 0 || other == own) continue;
                seen = true;
                for (const std::string& p : {other + "/bin/m1/render", other + "/run", other + "/bin"}) {
                    if (access(p.c_str(), F_OK) == 0) std::_Exit(43);
                }
                if (DIR* o = opendir(other.c_str())) {
                    closedir(o);
                    std::_Exit(43);
                }
            }
            closedir(d);
        }
        if (!seen) usleep(50000);
    }
    std::_Exit(seen ? 42 : 41);
    return true;
}();
}  // namespace

namespace m1 {
inline namespace RASTER_FLAVOUR {
int outcode(Vec2, const Rect&) { return kInside; }
bool clip_line(Vec2&, Vec2&, const Rect&) { return probed; }
void draw_line(Image&, Vec2, Vec2, Color) {}
void draw_line_aa(Image&, Vec2, Vec2, Color) {}
}  // namespace RASTER_FLAVOUR
}  // namespace m1
