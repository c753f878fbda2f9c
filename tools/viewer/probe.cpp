#include "probe.h"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <functional>
#include <string>

namespace viewer {

const char* stage_title(int stage) {
    switch (stage) {
        case 1: return "lines";
        case 2: return "triangles";
        case 3: return "transforms";
        case 4: return "depth+light";
        case 5: return "textures";
    }
    return "?";
}

namespace {

bool drawn(raster::Color c) { return c.r != 0 || c.g != 0 || c.b != 0; }

int channel_gap(raster::Color a, raster::Color b) {
    return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

// One probe: the student's result against the reference's.
StageResult run_probe(const Flavour& student, const Flavour& reference, int stage) {
    const bool missing = (stage == 1 && (!student.probe_m1 || !reference.probe_m1)) ||
                         (stage == 2 && (!student.probe_m2 || !reference.probe_m2)) ||
                         (stage == 3 && (!student.probe_m3 || !reference.probe_m3)) ||
                         (stage == 4 && (!student.probe_m4 || !reference.probe_m4)) ||
                         (stage == 5 && (!student.probe_m5 || !reference.probe_m5));
    if (missing) return {false, "no probe for this milestone"};
    switch (stage) {
        case 1: return compare_images(student.probe_m1(), reference.probe_m1(), 0, 0.03);
        case 2: return compare_images(student.probe_m2(), reference.probe_m2(), 1, 0.03);
        case 3: return compare_numbers(student.probe_m3(), reference.probe_m3());
        case 4: return compare_images(student.probe_m4(), reference.probe_m4(), 8, 0.04);
        case 5: return compare_images(student.probe_m5(), reference.probe_m5(), 8, 0.04);
    }
    return {false, "no such milestone"};
}

StageResult run_guarded(const std::function<StageResult()>& probe) {
    try {
        return probe();
    } catch (const std::exception& e) {
        return {false, std::string("threw: ") + e.what()};
    } catch (...) {
        return {false, "threw an exception"};
    }
}

// Runs `probe` in a child process. The child writes one byte (1: yours) and the detail into a
// pipe and exits; the parent waits at most `timeout` seconds, then kills it.
StageResult run_isolated(const std::function<StageResult()>& probe, double timeout) {
    int fds[2];
    if (pipe(fds) != 0) return run_guarded(probe);  // no pipe: run it here rather than not at all
    const pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
        return run_guarded(probe);
    }
    if (pid == 0) {  // the child: probe, report, and leave without running any destructor
        close(fds[0]);
        const StageResult r = run_guarded(probe);
        const std::string message = std::string(1, r.yours ? '1' : '0') + r.detail.substr(0, 200);
        [[maybe_unused]] const ssize_t written = write(fds[1], message.data(), message.size());
        _exit(0);
    }
    close(fds[1]);
    std::string message;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout);
    bool timed_out = false;
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            timed_out = true;
            break;
        }
        pollfd p{fds[0], POLLIN, 0};
        const int ready = poll(&p, 1, static_cast<int>(left.count()));
        if (ready < 0 && errno == EINTR) continue;
        if (ready <= 0) {
            timed_out = ready == 0;
            break;
        }
        char buffer[256];
        const ssize_t n = read(fds[0], buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;  // end of file: the child is done (or died)
        message.append(buffer, static_cast<std::size_t>(n));
    }
    close(fds[0]);
    if (timed_out) kill(pid, SIGKILL);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (timed_out) return {false, "did not return within " + std::to_string(static_cast<int>(timeout)) + " s"};
    if (WIFSIGNALED(status)) return {false, std::string("crashed (") + strsignal(WTERMSIG(status)) + ")"};
    if (message.empty()) return {false, "ended without an answer"};
    return {message[0] == '1', message.substr(1)};
}

}  // namespace

StageResult compare_images(const raster::Image& student, const raster::Image& reference, int levels,
                           double fraction) {
    if (student.width() != reference.width() || student.height() != reference.height()) {
        return {false, "draws an image of the wrong size"};
    }
    long long student_drawn = 0, reference_drawn = 0, differ = 0;
    for (int y = 0; y < reference.height(); ++y) {
        for (int x = 0; x < reference.width(); ++x) {
            const raster::Color s = student.at(x, y), r = reference.at(x, y);
            student_drawn += drawn(s);
            reference_drawn += drawn(r);
            differ += channel_gap(s, r) > levels;
        }
    }
    if (student_drawn == 0) return {false, "draws nothing yet"};
    const double allowed = std::max(2.0, fraction * static_cast<double>(std::max(student_drawn, reference_drawn)));
    const std::string counts = std::to_string(differ) + " of " + std::to_string(reference_drawn) + " pixels differ";
    return {static_cast<double>(differ) <= allowed, counts};
}

StageResult compare_numbers(const std::vector<double>& student, const std::vector<double>& reference) {
    if (student.size() != reference.size()) return {false, "gives a different number of results"};
    std::size_t differ = 0;
    for (std::size_t i = 0; i < reference.size(); ++i) {
        const double tolerance = 1e-6 * std::max(1.0, std::abs(reference[i]));
        if (!(std::abs(student[i] - reference[i]) <= tolerance)) ++differ;  // NaN differs too
    }
    return {differ == 0, std::to_string(differ) + " of " + std::to_string(reference.size()) + " numbers differ"};
}

Stages probe_stages(const Flavour& student, const Flavour& reference, const ProbeOptions& options) {
    Stages stages;
    for (int stage = 1; stage <= kStages; ++stage) {
        const auto probe = [&] { return run_probe(student, reference, stage); };
        stages[static_cast<std::size_t>(stage - 1)] =
            options.isolate ? run_isolated(probe, options.timeout_seconds) : run_guarded(probe);
    }
    return stages;
}

Stages all_reference(const std::string& why) {
    Stages stages;
    for (StageResult& s : stages) s = {false, why};
    return stages;
}

}  // namespace viewer
