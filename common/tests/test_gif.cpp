// Unit tests of the GIF writer (and the reader the tests and gallery use), checked through
// giflib directly as well, so a bug shared by writer and reader cannot hide.
#include "raster_catch.h"

#include <gif_lib.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>

#include "raster/color.h"
#include "raster/gif.h"

using namespace raster;
namespace fs = std::filesystem;

namespace {
std::string temp_gif(const std::string& name) {
    return (fs::temp_directory_path() /
            ("raster_gif_" + std::to_string(::getpid()) + "_" + name + ".gif"))
        .string();
}

Image gradient(int w, int h) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            img.set(x, y, {static_cast<std::uint8_t>(x * 255 / (w - 1)),
                           static_cast<std::uint8_t>(y * 255 / (h - 1)), 77});
    return img;
}
}  // namespace

TEST_CASE("gif: frames, size, delay, loop and solid colors survive (checked with giflib)") {
    const std::string path = temp_gif("solid");
    std::vector<Image> frames{Image(7, 5, Color{200, 30, 40}), Image(7, 5, colors::blue),
                              Image(7, 5, Color{1, 2, 3})};
    frames[1].set(3, 2, colors::white);
    write_gif(path, frames, 4, true);

    // Straight through giflib.
    int err = 0;
    GifFileType* gif = DGifOpenFileName(path.c_str(), &err);
    REQUIRE(gif != nullptr);
    REQUIRE(DGifSlurp(gif) == GIF_OK);
    CHECK(gif->SWidth == 7);
    CHECK(gif->SHeight == 5);
    CHECK(gif->ImageCount == 3);
    GraphicsControlBlock gcb{};
    REQUIRE(DGifSavedExtensionToGCB(gif, 2, &gcb) == GIF_OK);
    CHECK(gcb.DelayTime == 4);
    const ColorMapObject* map = gif->SColorMap;
    REQUIRE(map != nullptr);
    const GifColorType c = map->Colors[gif->SavedImages[0].RasterBits[0]];
    CHECK((c.Red == 200 && c.Green == 30 && c.Blue == 40));
    DGifCloseFile(gif, &err);

    // Through read_gif.
    const GifInfo info = read_gif(path);
    CHECK(info.width == 7);
    CHECK(info.height == 5);
    CHECK(info.loops);
    REQUIRE(info.frames.size() == 3);
    CHECK(info.delays == std::vector<int>{4, 4, 4});
    for (std::size_t i = 0; i < frames.size(); ++i) CHECK(info.frames[i] == frames[i]);  // lossless
    fs::remove(path);
}

TEST_CASE("gif: no loop extension when asked to play once") {
    const std::string path = temp_gif("once");
    write_gif(path, {Image(2, 2, colors::red)}, 0, false);
    const GifInfo info = read_gif(path);
    CHECK_FALSE(info.loops);
    CHECK(info.frames.size() == 1);
    fs::remove(path);
}

TEST_CASE("gif: more than 256 colors: a median-cut palette, close colors, exact background") {
    const std::string path = temp_gif("many");
    const Image img = gradient(64, 64);  // 64 x 64 distinct colors
    // A dark-blue background (most pixels) with an anti-aliased-looking gradient patch.
    const Color background{16, 18, 28};
    Image scene(64, 64, background);
    for (int y = 40; y < 60; ++y)
        for (int x = 10; x < 60; ++x) scene.set(x, y, mix(background, Color{240, 200, 80}, (x - 10) / 49.0));
    write_gif(path, {img, scene}, 10);
    const GifInfo info = read_gif(path);
    REQUIRE(info.frames.size() == 2);
    int worst = 0;
    long long total = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const Color a = img.at(x, y), b = info.frames[0].at(x, y);
            const int d = std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
            worst = std::max(worst, d);
            total += d;
        }
    CHECK(worst <= 16);
    CHECK(static_cast<double>(total) / (64 * 64) <= 6);
    CHECK(info.frames[1].at(0, 0) == background);  // the most common color survives exactly
    CHECK(info.frames[1].at(63, 0) == background);
    // The same frames give the same file (deterministic palette).
    const std::string again = temp_gif("many_again");
    write_gif(again, {img, scene}, 10);
    std::ifstream a(path, std::ios::binary), b(again, std::ios::binary);
    const std::string bytes_a{std::istreambuf_iterator<char>(a), {}}, bytes_b{std::istreambuf_iterator<char>(b), {}};
    CHECK(bytes_a == bytes_b);
    fs::remove(path);
    fs::remove(again);
}

TEST_CASE("gif: bad input is an ImageIoError, never a crash") {
    const std::string path = temp_gif("bad");
    CHECK_THROWS_AS(write_gif(path, {}, 5), ImageIoError);
    CHECK_THROWS_AS(write_gif(path, {Image(2, 2), Image(3, 2)}, 5), ImageIoError);
    CHECK_THROWS_AS(write_gif(path, {Image(2, 2)}, -1), ImageIoError);
    CHECK_THROWS_AS(write_gif(path, {Image(2, 2)}, 65536), ImageIoError);
    CHECK_THROWS_AS(write_gif(path, {Image()}, 5), ImageIoError);
    CHECK_FALSE(fs::exists(path));
    CHECK_THROWS_AS(write_gif("/nonexistent_dir_raster/x.gif", {Image(2, 2)}, 5), ImageIoError);

    CHECK_THROWS_AS(read_gif("/nonexistent_dir_raster/x.gif"), ImageIoError);
    {
        std::ofstream(path, std::ios::binary) << "GIF89a garbage";
    }
    CHECK_THROWS_AS(read_gif(path), ImageIoError);
    // A valid file cut in half.
    write_gif(path, {gradient(40, 40), gradient(40, 40)}, 5);
    const auto size = fs::file_size(path);
    fs::resize_file(path, size / 2);
    CHECK_THROWS_AS(read_gif(path), ImageIoError);
    fs::remove(path);
}

TEST_CASE("gif: every truncation and random corruption of a file reads or fails cleanly") {
    const std::string path = temp_gif("fuzz");
    write_gif(path, {gradient(24, 16), Image(24, 16, colors::red), gradient(24, 16)}, 3);
    std::string bytes;
    {
        std::ifstream in(path, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    REQUIRE(bytes.size() > 100);
    int read = 0, rejected = 0;
    auto attempt = [&](const std::string& data) {
        {
            std::ofstream out(path, std::ios::binary | std::ios::trunc);
            out.write(data.data(), static_cast<std::streamsize>(data.size()));
        }
        try {
            const GifInfo info = read_gif(path);
            CHECK(info.frames.size() == info.delays.size());
            for (const Image& f : info.frames) CHECK((f.width() == info.width && f.height() == info.height));
            ++read;
        } catch (const ImageIoError&) {
            ++rejected;
        }
    };
    for (std::size_t cut = 0; cut < bytes.size(); cut += 13) attempt(bytes.substr(0, cut));
    std::mt19937 rng(777);
    for (int i = 0; i < 400; ++i) {
        std::string data = bytes;
        const int edits = 1 + static_cast<int>(rng() % 3);
        for (int e = 0; e < edits; ++e) data[rng() % data.size()] = static_cast<char>(rng() & 255);
        attempt(data);
    }
    CHECK(read > 0);
    CHECK(rejected > 0);
    fs::remove(path);
}
