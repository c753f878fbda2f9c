// make_models <dir>: writes the OBJ models this project ships (cube, octahedron, pyramid,
// soccer_ball) into <dir> from their generators in common/src/mesh.cpp. The files are
// committed; the unit test "shipped models equal their generators" checks they still match.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include "raster/mesh.h"

namespace {

struct Model {
    const char* name;
    raster::Mesh (*make)();
    const char* description;
};

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: make_models <output directory>\n");
        return 2;
    }
    const Model models[] = {
        {"cube", raster::make_cube, "Cube [-1, 1]^3: 8 vertices, 12 edges, 6 square faces."},
        {"octahedron", raster::make_octahedron,
         "Regular octahedron, vertices on the axes at distance 1: 6 vertices, 12 edges, 8 faces."},
        {"pyramid", raster::make_square_pyramid,
         "Square pyramid: base y = -1 with corners (+-1, -1, +-1), apex (0, 1, 0):\n"
         "5 vertices, 8 edges, 5 faces (1 square, 4 triangles)."},
        {"soccer_ball", raster::make_truncated_icosahedron,
         "Truncated icosahedron (\"soccer ball\"), circumradius 1: 60 vertices, 90 edges,\n"
         "32 faces (12 pentagons, 20 hexagons)."},
    };
    try {
        std::filesystem::create_directories(argv[1]);
        for (const Model& m : models) {
            const std::string path = (std::filesystem::path(argv[1]) / (std::string(m.name) + ".obj")).string();
            raster::write_obj(path, m.make(),
                              std::string(m.description) +
                                  "\nWritten by common/tools/make_models.cpp (`make models`); do not edit.\n"
                                  "Right-handed, y up; faces counter-clockwise seen from outside.");
            std::printf("wrote %s\n", path.c_str());
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "make_models: %s\n", e.what());
        return 1;
    }
    return 0;
}
