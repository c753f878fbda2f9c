#include "raster/image.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace raster {

Image::Image(int width, int height, Color background) {
    if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide) {
        throw std::invalid_argument("Image size " + std::to_string(width) + "x" +
                                    std::to_string(height) + " is outside 1.." +
                                    std::to_string(kMaxSide));
    }
    width_ = width;
    height_ = height;
    bytes_.resize(3 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    fill(background);
}

Color Image::at(int x, int y) const {
    if (!in_bounds(x, y)) {
        throw std::out_of_range("Image::at(" + std::to_string(x) + ", " + std::to_string(y) +
                                ") outside " + std::to_string(width_) + "x" +
                                std::to_string(height_));
    }
    const std::uint8_t* p = &bytes_[offset(x, y)];
    return {p[0], p[1], p[2]};
}

Image::Image(const Image& other)
    : width_(other.width_),
      height_(other.height_),
      bytes_(other.bytes_),
      writes_(other.writes()),
      stray_writes_(other.stray_writes_),
      stray_limit_(other.stray_limit_) {}

Image& Image::operator=(const Image& other) {
    if (this != &other) {
        width_ = other.width_;
        height_ = other.height_;
        bytes_ = other.bytes_;
        writes_.store(other.writes(), std::memory_order_relaxed);
        stray_writes_ = other.stray_writes_;
        stray_limit_ = other.stray_limit_;
    }
    return *this;
}

Image::Image(Image&& other) noexcept
    : width_(other.width_),
      height_(other.height_),
      bytes_(std::move(other.bytes_)),
      writes_(other.writes()),
      stray_writes_(other.stray_writes_),
      stray_limit_(other.stray_limit_) {
    other.width_ = other.height_ = 0;
    other.bytes_.clear();
}

Image& Image::operator=(Image&& other) noexcept {
    if (this != &other) {
        width_ = other.width_;
        height_ = other.height_;
        bytes_ = std::move(other.bytes_);
        writes_.store(other.writes(), std::memory_order_relaxed);
        stray_writes_ = other.stray_writes_;
        stray_limit_ = other.stray_limit_;
        other.width_ = other.height_ = 0;
        other.bytes_.clear();
    }
    return *this;
}

namespace {
std::atomic<long long> g_total_stray_writes{0};
}  // namespace

long long Image::total_stray_writes() { return g_total_stray_writes.load(std::memory_order_relaxed); }

void Image::count_stray_write() {
    g_total_stray_writes.fetch_add(1, std::memory_order_relaxed);
    if (++stray_writes_ > stray_limit_) {
        throw StrayWriteLimit("more than " + std::to_string(stray_limit_) +
                              " writes outside the image: a loop is running past its end");
    }
}

void Image::fill(Color c) {
    for (std::size_t i = 0; i < bytes_.size(); i += 3) {
        bytes_[i] = c.r;
        bytes_[i + 1] = c.g;
        bytes_[i + 2] = c.b;
    }
}

bool operator==(const Image& a, const Image& b) {
    return a.width() == b.width() && a.height() == b.height() &&
           std::equal(a.data(), a.data() + a.size_bytes(), b.data());
}

}  // namespace raster
