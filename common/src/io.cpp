#include "raster/io.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
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

}  // namespace raster
