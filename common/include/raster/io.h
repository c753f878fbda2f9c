// Reading and writing images. PNG goes through stb_image / stb_image_write (Debian's
// libstb-dev); PPM (binary P6) is written by hand because it is the format a student can read
// with a hex dump.
//
// All functions throw raster::ImageIoError with the path and the reason on failure; none of
// them crash on a missing, truncated or corrupt file.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

#include "raster/image.h"

namespace raster {

struct ImageIoError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

void write_png(const std::string& path, const Image& img);
void write_ppm(const std::string& path, const Image& img);
// Accepts any PNG stb_image can decode (gray, gray+alpha, RGB, RGBA); alpha is dropped.
Image read_png(const std::string& path);
// The same from bytes in memory (`name` only labels errors). With expect_width/height > 0, the
// size in the PNG header must be exactly that, checked before anything is decoded: a file
// from an untrusted source cannot make the reader allocate more than the caller expects.
Image decode_png(const unsigned char* data, std::size_t size, const std::string& name, int expect_width = 0,
                 int expect_height = 0);

}  // namespace raster
