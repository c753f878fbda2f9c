// Unit tests of meshes: the shipped OBJ models, the loader's handling of bad files, and the
// generators. The conventions tested here are the ones raster/mesh.h names.
#include "raster_catch.h"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <numbers>
#include <random>
#include <sstream>

#include "raster/mesh.h"

using namespace raster;
namespace fs = std::filesystem;

namespace {

std::string temp_obj(const std::string& name) {
    return (fs::temp_directory_path() /
            ("raster_mesh_" + std::to_string(::getpid()) + "_" + name + ".obj"))
        .string();
}

std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// Closed, 2-manifold and consistently wound: every directed edge (a -> b) of every face occurs
// exactly once, and so does its reverse (b -> a), which belongs to the neighbouring face.
void require_closed_and_consistent(const Mesh& m) {
    std::map<std::pair<int, int>, int> directed;
    for (const auto& f : m.faces) {
        for (std::size_t i = 0; i < f.size(); ++i) ++directed[{f[i], f[(i + 1) % f.size()]}];
    }
    for (const auto& [edge, count] : directed) {
        INFO("edge " << edge.first << " -> " << edge.second);
        REQUIRE(count == 1);
        REQUIRE(directed.count({edge.second, edge.first}) == 1);
    }
}

long long euler(const Mesh& m) {
    return static_cast<long long>(m.positions.size()) - static_cast<long long>(unique_edges(m).size()) +
           static_cast<long long>(m.faces.size());
}

Vec3 centroid(const Mesh& m, const std::vector<int>& face) {
    Vec3 c{};
    for (int i : face) c = c + m.positions[static_cast<std::size_t>(i)];
    return c / static_cast<double>(face.size());
}

// The message of the MeshError that loading `text` throws ("" when it loads).
std::string load_error(const std::string& text) {
    try {
        load_obj_string(text);
    } catch (const MeshError& e) {
        return e.what();
    }
    return "";
}

const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

}  // namespace

TEST_CASE("models: every shipped model loads with its vertex, edge and face counts") {
    struct Expected {
        const char* name;
        std::size_t v, e, f;
    };
    const Expected expected[] = {
        {"cube", 8, 12, 6}, {"octahedron", 6, 12, 8}, {"pyramid", 5, 8, 5}, {"soccer_ball", 60, 90, 32}};
    REQUIRE(model_names().size() == std::size(expected));
    for (const Expected& x : expected) {
        INFO(x.name);
        const Mesh m = load_obj(model_path(x.name));
        CHECK(m.positions.size() == x.v);
        CHECK(unique_edges(m).size() == x.e);
        CHECK(m.faces.size() == x.f);
        CHECK(euler(m) == 2);
        CHECK(m.normals.empty());
        require_closed_and_consistent(m);
        std::size_t expected_triangles = 0;
        for (const auto& f : m.faces) expected_triangles += f.size() - 2;
        CHECK(m.triangles.size() == expected_triangles);
    }
}

TEST_CASE("models: faces are counter-clockwise seen from outside (outward normals)") {
    for (const std::string& name : model_names()) {
        INFO(name);
        const Mesh m = load_obj(model_path(name));
        CHECK(signed_volume(m) > 0);
        // Convex and centered on the origin's side: each face normal points away from the
        // solid's inside, and every triangle of the fan agrees with its polygon.
        Vec3 inside{};
        for (const Vec3& p : m.positions) inside = inside + p;
        inside = inside / static_cast<double>(m.positions.size());
        for (std::size_t f = 0; f < m.faces.size(); ++f) {
            const Vec3 n = face_normal(m, static_cast<int>(f));
            CHECK(dot(n, centroid(m, m.faces[f]) - inside) > 0);
        }
        for (const auto& t : m.triangles) {
            const Vec3 a = m.positions[static_cast<std::size_t>(t[0])];
            const Vec3 b = m.positions[static_cast<std::size_t>(t[1])];
            const Vec3 c = m.positions[static_cast<std::size_t>(t[2])];
            CHECK(dot(cross(b - a, c - a), (a + b + c) / 3 - inside) > 0);
        }
    }
    const Mesh cube = load_obj(model_path("cube"));
    CHECK(signed_volume(cube) == Approx(8));
}

TEST_CASE("models: the soccer ball is a truncated icosahedron") {
    const Mesh m = load_obj(model_path("soccer_ball"));
    int pentagons = 0, hexagons = 0;
    for (const auto& f : m.faces) {
        pentagons += f.size() == 5;
        hexagons += f.size() == 6;
    }
    CHECK(pentagons == 12);
    CHECK(hexagons == 20);
    for (const Vec3& p : m.positions) CHECK(length(p) == Approx(1).epsilon(1e-12));
    const auto edges = unique_edges(m);
    const double first = length(m.positions[static_cast<std::size_t>(edges[0][0])] -
                                m.positions[static_cast<std::size_t>(edges[0][1])]);
    for (const auto& e : edges) {
        CHECK(length(m.positions[static_cast<std::size_t>(e[0])] - m.positions[static_cast<std::size_t>(e[1])]) ==
              Approx(first).epsilon(1e-12));
    }
    // Edge length 2 / sqrt(9 phi + 10) at circumradius 1.
    CHECK(first == Approx(2 / std::sqrt(9 * std::numbers::phi + 10)).epsilon(1e-12));
    // Every vertex: one pentagon and two hexagons.
    std::vector<int> pent(60), hex(60);
    for (const auto& f : m.faces)
        for (int i : f) (f.size() == 5 ? pent : hex)[static_cast<std::size_t>(i)]++;
    for (int i = 0; i < 60; ++i) {
        CHECK(pent[static_cast<std::size_t>(i)] == 1);
        CHECK(hex[static_cast<std::size_t>(i)] == 2);
    }
}

TEST_CASE("models: shipped files equal their generators (`make models` rewrites them)") {
    const std::pair<const char*, Mesh (*)()> generators[] = {{"cube", make_cube},
                                                             {"octahedron", make_octahedron},
                                                             {"pyramid", make_square_pyramid},
                                                             {"soccer_ball", make_truncated_icosahedron}};
    for (const auto& [name, make] : generators) {
        INFO(name << ": run `make models` and commit common/models if the generator changed");
        const Mesh file = load_obj(model_path(name));
        const Mesh gen = make();
        REQUIRE(file.positions.size() == gen.positions.size());
        for (std::size_t i = 0; i < gen.positions.size(); ++i) {
            // %.17g round-trips doubles; allow an ulp or so for another libm's sqrt/phi.
            CHECK(length(file.positions[i] - gen.positions[i]) <= 1e-14);
        }
        CHECK(file.faces == gen.faces);
        CHECK(file.triangles == gen.triangles);
    }
}

TEST_CASE("models: model_path names a file in common/models and refuses path tricks") {
    const std::string p = model_path("cube");
    CHECK(fs::path(p).is_absolute());
    CHECK(fs::path(p).filename() == "cube.obj");
    CHECK(fs::path(p).parent_path().filename() == "models");
    CHECK(fs::exists(p));
    for (const std::string& name : model_names()) CHECK(fs::exists(model_path(name)));
    CHECK_THROWS_AS(model_path(""), MeshError);
    CHECK_THROWS_AS(model_path("../secret"), MeshError);
    CHECK_THROWS_AS(model_path("cube.obj"), MeshError);
    CHECK_THROWS_AS(model_path("a/b"), MeshError);
    CHECK_THROWS_AS(load_obj(model_path("no_such_model")), MeshError);
}

TEST_CASE("obj: faces, fan triangles, relative indices, formats, groups") {
    SECTION("a quad keeps its polygon and gets a fan of two triangles, same winding") {
        const Mesh m = load_obj_string("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
        REQUIRE(m.faces == std::vector<std::vector<int>>{{0, 1, 2, 3}});
        CHECK(m.triangles == std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}});
        CHECK(face_normal(m, 0) == Vec3{0, 0, 1});  // counter-clockwise seen from +z
        CHECK(unique_edges(m) == std::vector<std::array<int, 2>>{{0, 1}, {0, 3}, {1, 2}, {2, 3}});
    }
    SECTION("negative indices are relative to the vertices read so far") {
        const Mesh m = load_obj_string(kTriangle + "f -3 -2 -1\nv 5 5 5\nf -4 -3 -1\n");
        CHECK(m.faces == std::vector<std::vector<int>>{{0, 1, 2}, {0, 1, 3}});
    }
    SECTION("v/vt/vn, v//vn, v/vt, comments, CRLF, tabs, groups merged in file order") {
        const Mesh m = load_obj_string(
            "# header\r\nmtllib none.mtl\r\no first\r\nv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nv 1 1 0 # c\r\n"
            "vt 0 0\r\nvt 1 0\r\nvn 0 0 1\r\ng a\r\nusemtl x\r\nf 1/1/1 2/2/1 3/1/1\r\n"
            "g b\r\nf\t2//1  4//1\t3//1\r\ns 1\r\nl 1 2\r\n");
        CHECK(m.positions.size() == 4);
        CHECK(m.positions[3] == Vec3{1, 1, 0});
        CHECK(m.faces == std::vector<std::vector<int>>{{0, 1, 2}, {1, 3, 2}});
        REQUIRE(m.normals.size() == 4);
        for (const Vec3& n : m.normals) CHECK(n == Vec3{0, 0, 1});
        const Mesh no_normals = load_obj_string(kTriangle + "vt 0 0\nf 1/1 2/1 3/1\n");
        CHECK(no_normals.normals.empty());
    }
    SECTION("normals: none unless every corner has one; per position, distinct ones averaged") {
        CHECK(load_obj_string(kTriangle + "vn 0 0 1\nf 1//1 2//1 3\n").normals.empty());
        const Mesh m = load_obj_string(
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 -1\nvn 0 -1 0\nvn 0 0 2\n"
            "f 1//1 3//1 2//1\nf 1//2 2//2 4//2\n");
        REQUIRE(m.normals.size() == 4);
        CHECK(length(m.normals[0] - normalize(Vec3{0, -1, -1})) < 1e-15);  // shared by both faces
        CHECK(m.normals[2] == Vec3{0, 0, -1});
        CHECK(m.normals[3] == Vec3{0, -1, 0});
        // Unused normals are ignored; normals are normalized.
        CHECK(load_obj_string(kTriangle + "vn 0 0 2\nvn 1 0 0\nf 1//1 2//1 3//1\n").normals[0] ==
              Vec3{0, 0, 1});
        // A flat-shaded cube (one normal per face) averages to the corner directions.
        const Mesh cube = load_obj(model_path("cube"));
        std::ostringstream text;
        for (const Vec3& p : cube.positions) text << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
        for (std::size_t f = 0; f < cube.faces.size(); ++f) {
            const Vec3 n = face_normal(cube, static_cast<int>(f));
            text << "vn " << n.x << ' ' << n.y << ' ' << n.z << '\n';
        }
        for (std::size_t f = 0; f < cube.faces.size(); ++f) {
            text << 'f';
            for (int i : cube.faces[f]) text << ' ' << i + 1 << "//" << f + 1;
            text << '\n';
        }
        const Mesh loaded = load_obj_string(text.str());
        REQUIRE(loaded.normals.size() == 8);
        for (std::size_t i = 0; i < 8; ++i) {
            CHECK(length(loaded.normals[i] - normalize(loaded.positions[i])) < 1e-12);
        }
    }
    SECTION("to_obj and load_obj give back the positions (to an ulp or two), faces and normals") {
        const Mesh s = make_uv_sphere(5, 7, 0.3);
        const Mesh back = load_obj_string(to_obj(s, "comment\nover two lines"));
        CHECK(back.positions.size() == s.positions.size());
        for (std::size_t i = 0; i < s.positions.size(); ++i) {
            // tinyobjloader's number parser is not correctly rounded: an ulp or two.
            CHECK(length(back.positions[i] - s.positions[i]) <= 1e-15 * length(s.positions[i]) + 1e-300);
            CHECK(length(back.normals[i] - s.normals[i]) < 1e-15);
        }
        CHECK(back.faces == s.faces);
        CHECK(back.triangles == s.triangles);
        const std::string path = temp_obj("roundtrip");
        write_obj(path, s);
        CHECK(load_obj(path).faces == s.faces);
        fs::remove(path);
        CHECK_THROWS_AS(write_obj("/nonexistent_dir_raster/x.obj", s), MeshError);
    }
}

TEST_CASE("obj: bad files give a clear MeshError naming the problem") {
    struct Case {
        const char* what;
        std::string text;
        const char* message;  // part of the error message
    };
    const Case cases[] = {
        {"empty", "", "empty file"},
        {"blank", "  \n\t\r\n", "empty file"},
        {"only comments and vertices", "# nothing\n" + kTriangle, "no faces"},
        {"face with 2 vertices", kTriangle + "f 1 2\n", "at least 3 vertices"},
        {"face with no vertices", kTriangle + "f\n", "at least 3 vertices"},
        {"index 0", kTriangle + "f 0 1 2\n", "index 0"},
        {"index past the end", kTriangle + "f 1 2 4\n", "position index 4 but the file has only 3"},
        {"huge index", kTriangle + "f 1 2 2147483647\n", "file has only 3"},
        {"index beyond int", kTriangle + "f 1 2 4294967297\n", "does not fit in an int"},
        {"index far beyond int", kTriangle + "f 1 2 99999999999999999999999\n", "does not fit"},
        {"negative index too far back", kTriangle + "f -1 -2 -4\n", "only 3 defined so far"},
        {"relative index before its vertex", "f -1 -2 -3\n" + kTriangle, "only 0 defined so far"},
        {"most negative int", kTriangle + "f 1 2 -2147483648\n", "relative position index"},
        {"normal index out of range", kTriangle + "vn 0 0 1\nf 1//1 2//1 3//2\n",
         "normal index 2 but the file has only 1"},
        {"texcoord index 0", kTriangle + "vt 0 0\nf 1/0 2/1 3/1\n", "index 0"},
        {"text as index", kTriangle + "f 1 2 three\n", "is not a position index"},
        {"too many slashes", kTriangle + "f 1/1/1/1 2 3\n", "bad face corner"},
        {"NaN coordinate", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "not a finite number"},
        {"infinite coordinate", "v 0 inf 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "not a finite number"},
        {"overflowing coordinate", "v 0 0 1e999\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "1e999"},
        {"NaN normal", kTriangle + "vn nan 0 1\nf 1//1 2//1 3//1\n", "not a finite number"},
        {"garbage coordinate", "v 0 0 zero\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "`zero` is not a number"},
        {"truncated vertex line", "v 0 0 0\nv 1 0 0\nv 0 1", "needs 3 numbers, found 2"},
        {"truncated face line", kTriangle + "f 1 2", "at least 3 vertices"},
        {"vertex used twice", kTriangle + "f 1 2 1\n", "uses a vertex twice"},
        {"NUL byte", std::string("v 0 0 0\0\nf 1 1 1\n", 17), "NUL byte"},
    };
    for (const Case& c : cases) {
        INFO(c.what << ": " << c.text);
        const std::string message = load_error(c.text);
        CHECK_THAT(message, raster_test::contains(c.message));
        CHECK_THAT(message, raster_test::starts_with("<OBJ text>"));
    }
    // The line is named when known.
    CHECK_THAT(load_error(kTriangle + "\n\nf 1 2\n"), raster_test::starts_with("<OBJ text>:6:"));
}

TEST_CASE("obj: missing files, directories and bad paths") {
    CHECK_THROWS_WITH(load_obj("/nonexistent_dir_raster/model.obj"), raster_test::contains("no such file"));
    CHECK_THROWS_WITH(load_obj(fs::temp_directory_path().string()), raster_test::contains("is a directory"));
    if (fs::exists("/dev/zero")) CHECK_THROWS_WITH(load_obj("/dev/zero"), raster_test::contains("not a regular file"));
    const std::string path = temp_obj("bad");
    {
        std::ofstream(path) << kTriangle << "f 1 2 9\n";
    }
    CHECK_THROWS_WITH(load_obj(path), raster_test::starts_with(path + ":4:"));
    {
        std::ofstream(path, std::ios::trunc) << "";
    }
    CHECK_THROWS_WITH(load_obj(path), raster_test::contains("empty file"));
    fs::remove(path);
}

TEST_CASE("obj: every truncation and random corruption of a model loads or fails cleanly") {
    const std::string text = read_text(model_path("soccer_ball"));
    REQUIRE(text.size() > 1000);
    int loaded = 0, rejected = 0;
    auto attempt = [&](const std::string& t) {
        try {
            const Mesh m = load_obj_string(t);
            check_mesh(m);  // whatever loads is well formed
            ++loaded;
        } catch (const MeshError&) {
            ++rejected;
        }
    };
    for (std::size_t cut = 0; cut < text.size(); cut += 7) attempt(text.substr(0, cut));
    std::mt19937 rng(12345);
    const std::string alphabet = "0123456789-+./ \nfvne#\0";
    for (int i = 0; i < 1500; ++i) {
        std::string t = text;
        const int edits = 1 + static_cast<int>(rng() % 4);
        for (int e = 0; e < edits; ++e) {
            t[rng() % t.size()] = alphabet[rng() % alphabet.size()];
        }
        attempt(t);
    }
    CHECK(loaded > 0);
    CHECK(rejected > 0);
}

TEST_CASE("check_mesh: rejects what a renderer could trip on") {
    Mesh m = make_cube();
    CHECK_NOTHROW(check_mesh(m));
    Mesh bad = m;
    bad.positions[0].x = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH(check_mesh(bad), raster_test::contains("not finite"));
    bad = m;
    bad.faces[0][0] = 8;
    CHECK_THROWS_AS(check_mesh(bad), MeshError);
    bad = m;
    bad.faces[0].resize(2);
    CHECK_THROWS_WITH(check_mesh(bad), raster_test::contains("at least 3"));
    bad = m;
    bad.triangles.pop_back();
    CHECK_THROWS_WITH(check_mesh(bad), raster_test::contains("fan"));
    bad = m;
    bad.normals.assign(3, Vec3{0, 0, 1});
    CHECK_THROWS_WITH(check_mesh(bad), raster_test::contains("normals"));
}

TEST_CASE("generators: uv sphere") {
    const int stacks = 8, slices = 12;
    const double r = 2.5;
    const Mesh m = make_uv_sphere(stacks, slices, r);
    CHECK(m.positions.size() == static_cast<std::size_t>(2 + (stacks - 1) * slices));
    CHECK(m.faces.size() == static_cast<std::size_t>(stacks * slices));
    CHECK(m.triangles.size() == static_cast<std::size_t>(2 * (stacks - 1) * slices));
    CHECK(unique_edges(m).size() == static_cast<std::size_t>((2 * stacks - 1) * slices));
    CHECK(euler(m) == 2);
    require_closed_and_consistent(m);
    CHECK(m.positions.front() == Vec3{0, r, 0});  // poles on the y axis
    CHECK(m.positions.back() == Vec3{0, -r, 0});
    REQUIRE(m.normals.size() == m.positions.size());
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        CHECK(length(m.positions[i]) == Approx(r));
        CHECK(length(m.normals[i] - m.positions[i] / r) < 1e-12);
    }
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
        CHECK(dot(face_normal(m, static_cast<int>(f)), centroid(m, m.faces[f])) > 0);
    }
    const double volume = signed_volume(m);
    CHECK(volume > 0);
    CHECK(volume < 4.0 / 3 * std::numbers::pi * r * r * r);  // inscribed
    const Mesh fine = make_uv_sphere(64, 128, 1);
    CHECK(signed_volume(fine) == Approx(4.0 / 3 * std::numbers::pi).epsilon(0.01));
    CHECK(make_uv_sphere(2, 3).faces.size() == 6);  // the smallest: two triangular pyramids

    CHECK_THROWS_AS(make_uv_sphere(1, 8), std::invalid_argument);
    CHECK_THROWS_AS(make_uv_sphere(8, 2), std::invalid_argument);
    CHECK_THROWS_AS(make_uv_sphere(8, 8, 0), std::invalid_argument);
    CHECK_THROWS_AS(make_uv_sphere(8, 8, -1), std::invalid_argument);
    CHECK_THROWS_AS(make_uv_sphere(8, 8, std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
    CHECK_THROWS_AS(make_uv_sphere(8, 8, std::numeric_limits<double>::infinity()), std::invalid_argument);
    CHECK_THROWS_AS(make_uv_sphere(100000, 100000), std::invalid_argument);
}

TEST_CASE("generators: torus") {
    const int rings = 10, sides = 6;
    const double big = 2, small = 0.5;
    const Mesh m = make_torus(big, small, rings, sides);
    CHECK(m.positions.size() == static_cast<std::size_t>(rings * sides));
    CHECK(m.faces.size() == static_cast<std::size_t>(rings * sides));
    CHECK(unique_edges(m).size() == static_cast<std::size_t>(2 * rings * sides));
    CHECK(euler(m) == 0);  // a torus, not a sphere
    require_closed_and_consistent(m);
    REQUIRE(m.normals.size() == m.positions.size());
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        const Vec3 p = m.positions[i];
        CHECK(std::abs(p.y) <= small + 1e-12);  // lies in the xz plane, around the y axis
        const Vec3 tube_center = normalize(Vec3{p.x, 0, p.z}) * big;
        CHECK(length(p - tube_center) == Approx(small));
        CHECK(length(m.normals[i] - (p - tube_center) / small) < 1e-12);
    }
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
        const Vec3 c = centroid(m, m.faces[f]);
        const Vec3 tube_center = normalize(Vec3{c.x, 0, c.z}) * big;
        CHECK(dot(face_normal(m, static_cast<int>(f)), c - tube_center) > 0);  // outward
    }
    CHECK(signed_volume(m) > 0);
    const double exact = 2 * std::numbers::pi * std::numbers::pi * big * small * small;
    CHECK(signed_volume(make_torus(big, small, 128, 64)) == Approx(exact).epsilon(0.01));

    CHECK_THROWS_AS(make_torus(1, 1, 8, 8), std::invalid_argument);  // self-intersecting
    CHECK_THROWS_AS(make_torus(1, 0, 8, 8), std::invalid_argument);
    CHECK_THROWS_AS(make_torus(1, 0.5, 2, 8), std::invalid_argument);
    CHECK_THROWS_AS(make_torus(1, 0.5, 8, 2), std::invalid_argument);
    CHECK_THROWS_AS(make_torus(std::numeric_limits<double>::infinity(), 0.5, 8, 8), std::invalid_argument);
    CHECK_THROWS_AS(make_torus(1, 0.5, 1 << 20, 1 << 20), std::invalid_argument);
}

TEST_CASE("generators: convex polyhedron from points") {
    // A cube with an extra point inside and one in the middle of an edge.
    std::vector<Vec3> pts = make_cube().positions;
    pts.push_back({0, 0, 0});
    pts.push_back({0, -1, -1});
    const Mesh m = make_convex_polyhedron(pts);
    CHECK(m.faces.size() == 6);
    CHECK(signed_volume(m) == Approx(8));
    int uses_inside = 0;
    for (const auto& f : m.faces)
        for (int i : f) uses_inside += i == 8;
    CHECK(uses_inside == 0);
    CHECK(m.triangles.size() == 2 * 3 + 4 * 2);  // the 2 faces on the edge point are pentagons
    CHECK_THROWS_AS(make_convex_polyhedron({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), std::invalid_argument);
    CHECK_THROWS_AS(make_convex_polyhedron({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}),
                    std::invalid_argument);  // coplanar
    CHECK_THROWS_AS(make_convex_polyhedron({{0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                                            {0, 0, std::numeric_limits<double>::quiet_NaN()}}),
                    std::invalid_argument);
}
