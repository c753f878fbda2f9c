// The project's fuzzing harnesses (tools/fuzz/fuzz_m*.cpp) share this: a decoder that turns
// libFuzzer's bytes into the arguments of a milestone's functions, mixing ordinary values
// (pixel coordinates on the 1/16 grid, small reals) with the extreme ones the headers promise
// to survive (NaN, infinities, 1e300, DBL_MAX, subnormals, the 2^24 snapping limit, values
// whose squares overflow or underflow), and the checks every input ends with: no stray write
// (raster::Image counts them process-wide) and, under libFuzzer, no input slower than 500 ms.
//
// The same harness source builds two ways:
//  * with libFuzzer (tools/fuzz.sh, `make fuzz`): clang, -fsanitize=fuzzer,address,undefined;
//  * as a plain program (replay_main.cpp) that runs saved inputs, in the normal build, so every
//    input that ever found a bug replays in the test suite (and under CI's sanitizer build).
#pragma once

#include <array>
#include <bit>
#include <ctime>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <tuple>
#include <vector>

#include "raster/color.h"
#include "raster/image.h"
#include "raster/vec.h"

namespace fuzz {

// Reads values off the input (always in the order of the source: the harnesses never read
// two values in one function call's arguments, whose order C++ leaves open, so an input
// decodes the same with every compiler); past its end every read gives zeros (so short inputs are fine).
class Input {
public:
    Input(const std::uint8_t* data, std::size_t size) : p_(data), n_(size) {}

    bool empty() const { return n_ == 0; }

    std::uint8_t byte() {
        if (n_ == 0) return 0;
        --n_;
        return *p_++;
    }
    bool flag() { return (byte() & 1) != 0; }
    // An integer in [lo, hi].
    int range(int lo, int hi) {
        const unsigned span = static_cast<unsigned>(hi - lo) + 1;
        const unsigned high = byte();
        const unsigned v = (high << 8) | byte();
        return lo + static_cast<int>(v % span);
    }
    std::uint64_t bits64() {
        std::uint64_t v = 0;
        for (int i = 0; i < 8; ++i) v = (v << 8) | byte();
        return v;
    }

    // A double: about one in six is extreme (the table below), most are ordinary values on the
    // 1/16 grid around an image, some are small reals, and a few are any bit pattern at all.
    double real() {
        const std::uint8_t b = byte();
        if (b < 40) return special(b);
        if (b < 150) {  // -64 .. 192 pixels in 1/16 steps: inside and around a small image
            return static_cast<double>(range(-1024, 3072)) / 16.0;
        }
        if (b < 230) {  // a small real with a fractional part off the grid
            return static_cast<double>(range(-32768, 32767)) / 4099.0;
        }
        return std::bit_cast<double>(bits64());  // anything: NaN payloads, subnormals, ...
    }
    // A double that is usually finite and moderate (angles, aspects, intensities), sometimes
    // extreme.
    double mild() {
        const std::uint8_t b = byte();
        if (b < 24) return special(b);
        return static_cast<double>(range(-4096, 4096)) / 256.0;
    }

    static double special(unsigned i) {
        constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
        constexpr double kInf = std::numeric_limits<double>::infinity();
        constexpr double kTiny = std::numeric_limits<double>::denorm_min();
        constexpr double table[] = {
            0.0,      -0.0,    1.0,      -1.0,     0.5,       kNaN,    -kNaN,    kInf,
            -kInf,    1e300,   -1e300,   DBL_MAX,  -DBL_MAX,  kTiny,   -kTiny,   DBL_MIN,
            1e-300,   1e-320,  16777216, -16777216, 16777216.5, 16777215.9375, 16777217, 1e262,
            -1e262,   1e308,   1e154,    1e-162,   2e-162,    0.49999999999999994, 1e7, -1e7,
            1e-9,     9007199254740992.0, 255.5, 1e-6, 0.5 + 1.0 / 32, 4.9e-324 * 7, 179.99999, 1e6,
        };
        constexpr unsigned n = sizeof(table) / sizeof(table[0]);
        return table[i % n];
    }

    raster::Vec2 vec2() { return {real(), real()}; }
    raster::Vec3 vec3() { return {real(), real(), real()}; }
    raster::Vec3 mild3() { return {mild(), mild(), mild()}; }
    raster::Vec4 vec4() { return {real(), real(), real(), real()}; }
    raster::Color color() { return {byte(), byte(), byte()}; }

private:
    const std::uint8_t* p_;
    std::size_t n_;
};

// Every input ends with this: a stray write is a bug (the reference clips first), and so is,
// under libFuzzer, an input that takes more than 500 ms of CPU time (CPU time, not the clock
// on the wall, so a busy machine does not fail it; a hang is caught by libFuzzer's -timeout).
class Guard {
public:
    Guard() : strays_(raster::Image::total_stray_writes()), start_(std::clock()) {}
    ~Guard() {
        const long long strays = raster::Image::total_stray_writes() - strays_;
        if (strays != 0) {
            std::fprintf(stderr, "fuzz: %lld write(s) outside the image\n", strays);
            std::abort();
        }
#ifdef RASTER_FUZZ_TIME_LIMIT_MS
        const double ms = 1000.0 * static_cast<double>(std::clock() - start_) / CLOCKS_PER_SEC;
        if (ms > RASTER_FUZZ_TIME_LIMIT_MS) {
            std::fprintf(stderr, "fuzz: one input took %.0f ms of CPU time (limit %d ms)\n", ms, RASTER_FUZZ_TIME_LIMIT_MS);
            std::abort();
        }
#endif
    }

private:
    long long strays_;
    std::clock_t start_;
};

// An image of 1 to 48 pixels a side, with a stray-write budget so a runaway loop stops.
inline raster::Image image(Input& in) {
    const int width = in.range(1, 48);
    const int height = in.range(1, 48);
    raster::Image img(width, height, in.color());
    img.limit_stray_writes(1000);
    return img;
}

// The scene pieces milestones 3 and 4 decode alike (fuzz_m3.cpp, fuzz_m4.cpp). Each reads its
// values in the order the harnesses always did, so saved inputs decode as before.

// n model positions, about one in five exactly at `eye` (w = 0 in clip space for a camera
// there), the others anywhere.
inline std::vector<raster::Vec3> positions(Input& in, int n, raster::Vec3 eye) {
    std::vector<raster::Vec3> out;
    for (int i = 0; i < n; ++i) out.push_back(in.byte() < 48 ? eye : in.vec3());
    return out;
}

// 0 to 8 triangles over n positions, with out-of-range indices (-1 and n) among them.
inline std::vector<std::array<int, 3>> triangles(Input& in, int n) {
    const int count = in.range(0, 8);
    std::vector<std::array<int, 3>> out;
    for (int i = 0; i < count; ++i) out.push_back({in.range(-1, n), in.range(-1, n), in.range(-1, n)});
    return out;
}

// A matrix of sixteen moderate (sometimes extreme) entries: m3::Mat4 and m4's alike.
template <class Matrix>
Matrix raw_matrix(Input& in) {
    Matrix m;
    for (auto& row : m.m) {
        for (double& e : row) e = in.mild();
    }
    return m;
}

// The arguments of m3::perspective (fovy, aspect, near, far) and m3::orthographic (left, right,
// bottom, top, near, far), for std::apply: a braced list is read left to right.
inline std::tuple<double, double, double, double> perspective_args(Input& in) {
    return {in.mild() * 16, in.mild(), in.real(), in.real()};
}
inline std::tuple<double, double, double, double, double, double> orthographic_args(Input& in) {
    return {in.real(), in.real(), in.real(), in.real(), in.real(), in.real()};
}

// Fails the input with a message (a broken promise of a header).
// what: the promise broken; hint: which TODO, and the header's rule to reread.
[[noreturn]] inline void broken(const char* what, const char* hint) {
    std::fprintf(stderr, "fuzz: broken promise: %s\n  look at: %s\n", what, hint);
    std::abort();
}

}  // namespace fuzz
