// The image every milestone draws into.
//
// Conventions (the same in every lesson):
// - Pixel (x, y) is column x, row y. Row 0 is the TOP row; y grows downward, x to the right.
// - Pixel (x, y) covers the square [x, x+1) x [y, y+1) of the continuous image plane, so its
//   center is at (x + 0.5, y + 0.5). An image of width W spans 0 <= x < W.
// - Storage is row-major RGB, 3 bytes per pixel, no padding: the byte of channel c of pixel
//   (x, y) is data()[3 * (y * width + x) + c].
//
// Writing outside the image is never undefined behaviour: set() and blend() ignore such writes
// and count them (stray_writes()). A correct rasterizer clips first and never makes one; the
// checkpoints report the count, because a stray write is how "forgot to clip" shows up.
// The checkpoints also set a stray-write budget (limit_stray_writes): a loop that runs past
// its end writes outside the image forever, and the budget stops it with StrayWriteLimit
// instead of letting it hang.
//
// Every write inside the image (set() or blend()) is counted too (writes()). The checkpoints
// use the count to tell which function drew what, e.g. "fill_triangle_gradient drew nothing".
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include "raster/color.h"

namespace raster {

// Thrown by set() and blend() once an image's stray-write budget is spent.
struct StrayWriteLimit : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class Image {
public:
    // Largest accepted side, so that width * height * 3 never overflows and a typo in a scene
    // fails with a message instead of an allocation of many gigabytes.
    static constexpr int kMaxSide = 16384;

    Image() = default;
    // Throws std::invalid_argument unless 1 <= width, height <= kMaxSide.
    Image(int width, int height, Color background = colors::black);
    Image(const Image& other);
    Image& operator=(const Image& other);
    Image(Image&& other) noexcept;
    Image& operator=(Image&& other) noexcept;

    int width() const { return width_; }
    int height() const { return height_; }
    bool empty() const { return width_ == 0; }
    bool in_bounds(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }

    // Pixel read; throws std::out_of_range outside the image (reads are the harness's, and a
    // bad read there is a bug in the harness, not in a student's rasterizer).
    Color at(int x, int y) const;

    // Pixel write. Outside the image: ignored and counted in stray_writes().
    void set(int x, int y, Color c) {
        if (!in_bounds(x, y)) {
            count_stray_write();
            return;
        }
        count_write();
        std::uint8_t* p = &bytes_[offset(x, y)];
        p[0] = c.r;
        p[1] = c.g;
        p[2] = c.b;
    }

    // Linear blend of c over the current pixel: new = old + coverage * (c - old), rounded to
    // nearest; coverage is clamped to [0, 1] and NaN counts as 0. Outside: ignored and counted.
    // (set() and blend() are defined here, inline: a pixel loop calls them for every pixel, and
    // a call into another file costs more than the write itself.)
    void blend(int x, int y, Color c, double coverage) {
        if (!in_bounds(x, y)) {
            count_stray_write();
            return;
        }
        count_write();
        std::uint8_t* p = &bytes_[offset(x, y)];
        const Color mixed = mix({p[0], p[1], p[2]}, c, coverage);
        p[0] = mixed.r;
        p[1] = mixed.g;
        p[2] = mixed.b;
    }

    void fill(Color c);

    // How many set() and blend() calls landed inside the image (fill() is not counted).
    // Another thread may read it while this one draws (the checkpoints' watchdog does).
    long long writes() const { return writes_.load(std::memory_order_relaxed); }
    long long stray_writes() const { return stray_writes_; }
    // Every stray write of every image in this process since it started. Nothing resets it:
    // assigning a fresh Image over one that wrote outside (which copies the fresh image's
    // zero count) does not hide those writes from this total. The checkpoints use it.
    static long long total_stray_writes();
    // After `limit` stray writes, the next one throws StrayWriteLimit (default: no limit).
    void limit_stray_writes(long long limit) { stray_limit_ = limit; }

    const std::uint8_t* data() const { return bytes_.data(); }
    std::uint8_t* data() { return bytes_.data(); }
    std::size_t size_bytes() const { return bytes_.size(); }

private:
    std::size_t offset(int x, int y) const {
        return 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
                    static_cast<std::size_t>(x));
    }

    int width_ = 0;
    int height_ = 0;
    std::vector<std::uint8_t> bytes_;
    void count_stray_write();
    // A relaxed load and store, not an atomic increment: as cheap as a plain counter (only
    // the drawing thread writes it), yet safe to read from another thread.
    void count_write() { writes_.store(writes_.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed); }

    std::atomic<long long> writes_{0};

    long long stray_writes_ = 0;
    long long stray_limit_ = std::numeric_limits<long long>::max();
};

bool operator==(const Image& a, const Image& b);  // same size and same pixels

}  // namespace raster
