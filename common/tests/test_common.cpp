// Unit tests of the shared library: what every milestone and the checkpoints rely on.
#include "raster_catch.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>

#include "raster/color.h"
#include "raster/compare.h"
#include "raster/image.h"
#include "raster/io.h"
#include "raster/vec.h"

using namespace raster;
namespace fs = std::filesystem;

namespace {
std::string temp_path(const std::string& name) {
    return (fs::temp_directory_path() / ("raster_common_" + name)).string();
}
}  // namespace

TEST_CASE("vectors: arithmetic, dot, cross, normalize") {
    constexpr Vec2 a{1, 2}, b{3, -1};
    STATIC_REQUIRE(a + b == Vec2{4, 1});
    STATIC_REQUIRE(dot(a, b) == 1);
    STATIC_REQUIRE(cross(a, b) == -7);
    constexpr Vec3 x{1, 0, 0}, y{0, 1, 0};
    STATIC_REQUIRE(cross(x, y) == Vec3{0, 0, 1});
    CHECK(length(normalize(Vec3{3, 4, 0})) == Approx(1));
    CHECK(normalize(Vec3{}) == Vec3{});  // no NaN from the zero vector
    CHECK_FALSE(is_finite(Vec2{std::nan(""), 0}));
    CHECK(xyz(point({1, 2, 3})) == Vec3{1, 2, 3});
}

TEST_CASE("colors: rounding, clamping and NaN") {
    CHECK(to_channel(127.5) == 128);
    CHECK(to_channel(-5) == 0);
    CHECK(to_channel(1e9) == 255);
    CHECK(to_channel(std::nan("")) == 0);
    CHECK(mix(colors::black, colors::white, 0.25) == Color{64, 64, 64});
    CHECK(mix(colors::black, colors::white, 2) == colors::white);
    CHECK(mix(colors::red, colors::blue, std::nan("")) == colors::red);
}

TEST_CASE("image: size limits, pixel access, stray writes") {
    CHECK_THROWS_AS(Image(0, 5), std::invalid_argument);
    CHECK_THROWS_AS(Image(5, Image::kMaxSide + 1), std::invalid_argument);
    Image img(4, 3, colors::blue);
    CHECK(img.at(3, 2) == colors::blue);
    img.set(1, 2, colors::red);
    CHECK(img.at(1, 2) == colors::red);
    CHECK(img.data()[3 * (2 * 4 + 1)] == 255);  // row-major RGB
    img.set(-1, 0, colors::red);
    img.set(4, 0, colors::red);
    img.blend(0, 3, colors::red, 1);
    CHECK(img.stray_writes() == 3);
    CHECK_THROWS_AS(img.at(4, 0), std::out_of_range);
    img.blend(0, 0, colors::white, 0.5);
    CHECK(img.at(0, 0) == Color{128, 128, 255});
    CHECK(img.writes() == 2);  // set(1, 2) and blend(0, 0); stray writes are not counted
    img.fill(colors::black);
    const Image copy = img;
    CHECK(copy.writes() == 2);
    CHECK(copy.stray_writes() == 3);
}

TEST_CASE("PNG and PPM: round trip, clear errors for missing and corrupt files") {
    Image img(5, 4, colors::black);
    img.set(2, 1, Color{10, 20, 30});
    const std::string png = temp_path("roundtrip.png");
    write_png(png, img);
    CHECK(read_png(png) == img);

    CHECK_THROWS_AS(read_png(temp_path("does_not_exist.png")), ImageIoError);
    const std::string bad = temp_path("corrupt.png");
    {
        std::ofstream f(bad, std::ios::binary);
        f << "\x89PNG\r\n\x1a\n this is not really a PNG";
    }
    CHECK_THROWS_WITH(read_png(bad), raster_test::contains("corrupt.png"));
    CHECK_THROWS_AS(write_png("/nonexistent-dir/x.png", img), ImageIoError);

    const std::string ppm = temp_path("out.ppm");
    write_ppm(ppm, img);
    std::ifstream f(ppm, std::ios::binary);
    std::string header;
    std::getline(f, header);
    CHECK(header == "P6");
    CHECK(fs::file_size(ppm) == std::string("P6\n5 4\n255\n").size() + 5 * 4 * 3);
}

TEST_CASE("compare: metrics and diff picture") {
    Image a(10, 10), b(10, 10);
    auto same = compare(a, b);
    CHECK(same.differing_pixels == 0);
    CHECK(std::isinf(same.psnr_db));
    b.set(3, 4, Color{0, 30, 0});
    b.set(5, 5, Color{255, 255, 255});
    const auto m = compare(a, b);
    CHECK(m.differing_pixels == 2);
    CHECK(m.differing_share == Approx(0.02));
    CHECK(m.max_channel_diff == 255);
    CHECK(m.mean_abs_error == Approx((30.0 + 3 * 255) / 300));
    CHECK(m.psnr_db > 0);
    const Image d = diff_image(a, b);
    CHECK(d.at(3, 4).r >= 128);
    CHECK(d.at(3, 4).g == 0);
    CHECK(d.at(0, 0) == colors::black);  // dimmed expected (black stays black)
    CHECK_FALSE(compare(Image(3, 3), b).same_size);
}
