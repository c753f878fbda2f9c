#include "raster/io.h"

#include <cerrno>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>

#include <stb_image.h>
#include <stb_image_write.h>

namespace raster {

namespace {

[[noreturn]] void fail(const std::string& what, const std::string& path, const std::string& why) {
    throw ImageIoError(what + " '" + path + "': " + why);
}

}  // namespace

void write_png(const std::string& path, const Image& img) {
    if (img.empty()) fail("cannot write PNG", path, "the image is empty");
    if (stbi_write_png(path.c_str(), img.width(), img.height(), 3, img.data(),
                       img.width() * 3) == 0) {
        fail("cannot write PNG", path, "the folder is missing or not writable");
    }
}

void write_ppm(const std::string& path, const Image& img) {
    if (img.empty()) fail("cannot write PPM", path, "the image is empty");
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "wb"),
                                                       &std::fclose);
    if (!f) fail("cannot write PPM", path, std::strerror(errno));
    std::fprintf(f.get(), "P6\n%d %d\n255\n", img.width(), img.height());
    if (std::fwrite(img.data(), 1, img.size_bytes(), f.get()) != img.size_bytes()) {
        fail("cannot write PPM", path, "short write");
    }
}

Image read_png(const std::string& path) {
    int w = 0, h = 0, channels_in_file = 0;
    std::unique_ptr<unsigned char, void (*)(void*)> pixels(
        stbi_load(path.c_str(), &w, &h, &channels_in_file, 3), &stbi_image_free);
    if (!pixels) {
        const char* why = stbi_failure_reason();
        fail("cannot read PNG", path, why ? why : "unknown error");
    }
    if (w < 1 || h < 1 || w > Image::kMaxSide || h > Image::kMaxSide) {
        fail("cannot read PNG", path, "unsupported size");
    }
    Image img(w, h);
    std::memcpy(img.data(), pixels.get(), img.size_bytes());
    return img;
}

Image decode_png(const unsigned char* data, std::size_t size, const std::string& name, int expect_width,
                 int expect_height) {
    static constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (size < 24 || std::memcmp(data, kSignature, 8) != 0 || std::memcmp(data + 12, "IHDR", 4) != 0) {
        fail("cannot read PNG", name, "not a PNG file");
    }
    if (size > static_cast<std::size_t>(std::numeric_limits<int>::max())) fail("cannot read PNG", name, "too large");
    auto be32 = [&](int at) {
        return (std::uint32_t{data[at]} << 24) | (std::uint32_t{data[at + 1]} << 16) |
               (std::uint32_t{data[at + 2]} << 8) | std::uint32_t{data[at + 3]};
    };
    const std::uint32_t w = be32(16), h = be32(20);
    if (expect_width > 0 && (w != static_cast<std::uint32_t>(expect_width) ||
                             h != static_cast<std::uint32_t>(expect_height))) {
        fail("cannot read PNG", name,
             "it is " + std::to_string(w) + "x" + std::to_string(h) + ", expected " + std::to_string(expect_width) +
                 "x" + std::to_string(expect_height));
    }
    if (w < 1 || h < 1 || w > static_cast<std::uint32_t>(Image::kMaxSide) ||
        h > static_cast<std::uint32_t>(Image::kMaxSide)) {
        fail("cannot read PNG", name, "unsupported size");
    }
    int iw = 0, ih = 0, channels_in_file = 0;
    std::unique_ptr<unsigned char, void (*)(void*)> pixels(
        stbi_load_from_memory(data, static_cast<int>(size), &iw, &ih, &channels_in_file, 3), &stbi_image_free);
    if (!pixels) {
        const char* why = stbi_failure_reason();
        fail("cannot read PNG", name, why ? why : "unknown error");
    }
    if (static_cast<std::uint32_t>(iw) != w || static_cast<std::uint32_t>(ih) != h) {
        fail("cannot read PNG", name, "its header and its pixels disagree on the size");
    }
    Image img(iw, ih);
    std::memcpy(img.data(), pixels.get(), img.size_bytes());
    return img;
}

}  // namespace raster
