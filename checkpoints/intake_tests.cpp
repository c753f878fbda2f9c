// The judge's reading of a render program's artifacts (cp::read_artifacts), fed with hostile
// folders: what a submission can leave behind must give a clear ArtifactError or be ignored,
// never a hang, a crash or an allocation the scene does not justify. CI runs these under
// AddressSanitizer and UndefinedBehaviorSanitizer too.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "raster_catch.h"

#include "harness/checkpoint.h"
#include "harness/html.h"
#include "raster/io.h"

namespace fs = std::filesystem;

namespace {

struct Folder {
    fs::path dir;
    Folder() {
        char tmpl[] = "/tmp/intake-test.XXXXXX";
        dir = ::mkdtemp(tmpl);
    }
    ~Folder() { fs::remove_all(dir); }
    void write(const std::string& name, const std::string& bytes) const {
        std::ofstream(dir / name, std::ios::binary) << bytes;
    }
};

cp::ArtifactRules rules_48() {
    cp::ArtifactRules r;
    r.images["main"] = {48, 48};
    return r;
}

std::string png_of(int w, int h) {
    Folder f;
    raster::write_png((f.dir / "x.png").string(), raster::Image(w, h, raster::colors::white));
    std::ifstream in(f.dir / "x.png", std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

TEST_CASE("well-formed artifacts are read", "[intake]") {
    Folder f;
    f.write("values.txt", "seconds 0.5\nstray_writes 3\nvalue clip.0.kept 1\nvalue odd nan\ntrace draw_line 4 10 3\n");
    f.write("main.png", png_of(48, 48));
    f.write("unexpected.png", png_of(2000, 2000));  // not a name the scene makes: ignored
    const cp::Artifacts a = cp::read_artifacts(f.dir.string(), rules_48());
    CHECK(a.seconds == 0.5);
    CHECK(a.stray_writes == 3);
    CHECK(a.values.at("clip.0.kept") == 1);
    CHECK(std::isnan(a.values.at("odd")));
    CHECK(a.trace.at("draw_line").calls == 4);
    CHECK(a.images.size() == 1);
    CHECK(a.images.at("main").width() == 48);
}

TEST_CASE("a missing values.txt or folder is an error, a missing image is not", "[intake]") {
    Folder f;
    CHECK_THROWS_AS(cp::read_artifacts(f.dir.string(), rules_48()), cp::ArtifactError);
    CHECK_THROWS_AS(cp::read_artifacts((f.dir / "nope").string(), rules_48()), cp::ArtifactError);
    f.write("values.txt", "seconds 0\n");
    CHECK(cp::read_artifacts(f.dir.string(), rules_48()).images.empty());
}

TEST_CASE("symbolic links are refused, for files and for the folder", "[intake]") {
    Folder f;
    f.write("values.txt", "seconds 0\n");
    f.write("real.png", png_of(48, 48));
    fs::create_symlink(f.dir / "real.png", f.dir / "main.png");
    CHECK_THROWS_WITH(cp::read_artifacts(f.dir.string(), rules_48()), raster_test::contains("symbolic link"));
    Folder g;
    fs::create_directory_symlink(f.dir, g.dir / "out");
    CHECK_THROWS_AS(cp::read_artifacts((g.dir / "out").string(), rules_48()), cp::ArtifactError);
}

TEST_CASE("a FIFO is refused without waiting for a writer", "[intake]") {
    Folder f;
    REQUIRE(::mkfifo((f.dir / "values.txt").c_str(), 0644) == 0);
    CHECK_THROWS_WITH(cp::read_artifacts(f.dir.string(), rules_48()), raster_test::contains("not a plain file"));
}

TEST_CASE("files beyond the size cap are refused", "[intake]") {
    Folder f;
    f.write("values.txt", std::string(5u << 20, '\n'));
    CHECK_THROWS_WITH(cp::read_artifacts(f.dir.string(), rules_48()), raster_test::contains("allowed"));
}

TEST_CASE("a PNG of another size or a corrupt one is refused before decoding", "[intake]") {
    Folder f;
    f.write("values.txt", "seconds 0\n");
    f.write("main.png", png_of(64, 48));
    CHECK_THROWS_WITH(cp::read_artifacts(f.dir.string(), rules_48()), raster_test::contains("expected 48x48"));
    // A header claiming 60000 x 60000 pixels.
    std::string bomb = png_of(48, 48);
    bomb[16] = 0, bomb[17] = 0, bomb[18] = char(0xea), bomb[19] = 0x60;
    bomb[20] = 0, bomb[21] = 0, bomb[22] = char(0xea), bomb[23] = 0x60;
    f.write("main.png", bomb);
    CHECK_THROWS_WITH(cp::read_artifacts(f.dir.string(), rules_48()), raster_test::contains("60000x60000"));
    f.write("main.png", png_of(48, 48).substr(0, 40));  // truncated
    CHECK_THROWS_AS(cp::read_artifacts(f.dir.string(), rules_48()), cp::ArtifactError);
    f.write("main.png", "GIF89a not a png at all, but long enough to have a header");
    CHECK_THROWS_WITH(cp::read_artifacts(f.dir.string(), rules_48()), raster_test::contains("not a PNG"));
}

TEST_CASE("garbage lines in values.txt are ignored, not trusted", "[intake]") {
    Folder f;
    f.write("values.txt", std::string("trace\nstopped\nvalue\nseconds\n\x01\x02\x03 junk\nstray_writes 1e300\n") +
                              "trace x notanumber 5 6\n");
    const cp::Artifacts a = cp::read_artifacts(f.dir.string(), rules_48());
    CHECK(a.trace.at("x").calls == 0);
    CHECK(a.stopped);
}

// Not the intake, but the same harness: the width a report shows a picture at (cp::shown_width)
// is a whole multiple of its own, so pixelated scaling drops no pixel of a diff.
TEST_CASE("report pictures are shown at whole multiples, at least the minimum height", "[pages]") {
    CHECK(cp::shown_width(96, 320) == 288);                 // 3 times, nearest 320
    CHECK(cp::shown_width(384, 320, 1, 96, 192) == 768);    // a strip of panels: 192 high
    CHECK(cp::shown_width(192, 320, 2) == 384);             // a diff at least twice
    CHECK(cp::shown_width(1024, 320, 1, 48, 192) == 1024);  // never wider than 1024 unless itself
    CHECK(cp::shown_width(600, 320, 1, 10, 192) == 600);
    CHECK(cp::shown_width(0, 320) == 320);                  // width unknown
    std::string head = png_of(48, 32).substr(0, 24);
    CHECK(cp::png_width(head) == 48);
    CHECK(cp::png_height(head) == 32);
    CHECK(cp::png_height("GIF89a") == 0);
}
