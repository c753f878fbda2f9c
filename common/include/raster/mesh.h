// Triangle meshes: loaded from Wavefront OBJ files (through tinyobjloader, Debian's
// libtinyobjloader-dev) or generated in code. This is library code, not a student TODO.
//
// Conventions (tested in common/tests/test_mesh.cpp):
// - Coordinates are right-handed model coordinates, y up. Units are whatever the file says;
//   the models shipped in common/models fit in the cube [-1, 1]^3 and are centered on the
//   origin (see common/models/README.md).
// - Every face is wound COUNTER-CLOCKWISE when seen from OUTSIDE the solid, so the face normal
//   cross(b - a, c - a) of a triangle (a, b, c) points outward, and a closed mesh has a
//   positive signed volume. Back-face culling in milestone 3 relies on this.
// - Indices are 0-based (the OBJ file's 1-based and negative, relative indices are converted).
// - `faces` keeps each polygon as the file gives it (for wireframes: a cube face is one
//   quad, drawn without a diagonal). `triangles` holds the same faces fan-triangulated from
//   their first vertex, (v0, v1, v2), (v0, v2, v3), ..., with the same winding, in face order.
//   The fan is exact for the convex faces this project ships and generates.
// - `normals` is empty unless the file gives a normal at every face corner; then it has one
//   unit normal per position: the normalized sum of the distinct normals its corners use (a
//   file with one normal per position gets exactly those; a flat-shaded cube gets the
//   averaged corner directions). A position no face uses gets the zero vector.
//
// Errors: every function that reads input throws MeshError with the path, the line when
// known, and the reason; malformed, truncated, empty or huge-index files never crash.
#pragma once

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "raster/vec.h"

namespace raster {

struct Mesh {
    std::vector<Vec3> positions;
    std::vector<std::vector<int>> faces;        // polygons as in the file (0-based), for wireframes
    std::vector<std::array<int, 3>> triangles;  // faces fan-triangulated, same winding
    std::vector<Vec3> normals;                  // per position when the file has normals, else empty
};

class MeshError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Largest accepted OBJ file and mesh, so that a corrupt file fails with a message instead of
// an allocation of many gigabytes.
inline constexpr long long kMaxObjBytes = 256LL * 1024 * 1024;
inline constexpr int kMaxMeshVertices = 10'000'000;

// Loads positions, polygon faces and (optional) normals. Texture coordinates, materials,
// groups, lines and points are ignored (groups are merged into one mesh, in file order).
// Rejected with MeshError: a missing or unreadable file (or a directory, device or pipe), a
// file larger than kMaxObjBytes, no faces, a face with fewer than 3 vertices or with a vertex
// twice, a face index of 0 or one that does not fit in an int, an index outside the file's
// positions (or normals, texture coordinates; a negative, relative index: outside those
// defined before it), a vertex with fewer than 3 coordinates, a coordinate that is not a
// finite number (nan, inf, 1e999), more than kMaxMeshVertices positions.
Mesh load_obj(const std::string& path);
// The same, from the text of an OBJ file (tests, generated files). `mtllib` is ignored.
Mesh load_obj_string(const std::string& text);

// The text of an OBJ file for a mesh: an optional comment (each line prefixed with "# "),
// then `v` lines (17 significant digits; load_obj gives them back to an ulp or two, as
// tinyobjloader's number parser is not correctly rounded), `vn` lines
// when the mesh has normals, and one `f` line per polygon (`f a//a ...` with normals).
std::string to_obj(const Mesh& mesh, const std::string& comment = "");
// Writes to_obj(mesh, comment) to path; throws MeshError when the file cannot be written.
void write_obj(const std::string& path, const Mesh& mesh, const std::string& comment = "");

// Throws MeshError unless the mesh is well formed: at most kMaxMeshVertices positions, all
// finite; every face has at least 3 vertices, all in range, none twice; triangles are the fan
// of the faces; normals empty or one finite normal per position. load_obj and the
// generators below check their result with it.
void check_mesh(const Mesh& mesh);

// Every polygon edge once, as {smaller index, larger index}, sorted ascending. A closed
// mesh of V positions and F faces has V - E + F = 2 (a sphere) or 0 (a torus) edges E.
std::vector<std::array<int, 2>> unique_edges(const Mesh& mesh);

// Signed volume enclosed by a closed mesh (divergence theorem over its triangles): positive
// when the faces are wound counter-clockwise seen from outside, as this project requires.
double signed_volume(const Mesh& mesh);

// Unit normal of a polygon (Newell's method: exact for planar polygons, robust for slightly
// bent ones); points outward for counter-clockwise faces. Zero for a degenerate face.
Vec3 face_normal(const Mesh& mesh, int face);

// Absolute path of a model shipped in common/models: model_path("cube") is
// ".../common/models/cube.obj". The directory is fixed at build time (RASTER_MODELS_DIR) and
// can be overridden at run time with the environment variable RASTER_MODELS_DIR. Names are
// letters, digits and '_' only; anything else throws MeshError (no path tricks).
std::string model_path(const std::string& name);
// The models shipped in common/models, in a fixed order: cube, octahedron, pyramid,
// soccer_ball.
std::vector<std::string> model_names();

// ---- generated meshes (all: counter-clockwise from outside, with exact unit normals) ----
// Invalid arguments (counts too small or too large, sizes not finite or not positive) throw
// std::invalid_argument.

// Sphere centered on the origin, poles on the y axis: one vertex at each pole, `stacks`
// bands of latitude (>= 2) and `slices` meridians (>= 3): 2 + (stacks - 1) * slices
// positions; triangles at the poles, quads elsewhere; stacks * slices <= 1,000,000.
Mesh make_uv_sphere(int stacks, int slices, double radius = 1);

// Torus centered on the origin around the y axis (lying in the xz plane): `rings` segments
// around the y axis (>= 3), `sides` around the tube (>= 3), 0 < minor < major;
// rings * sides positions and quads; rings * sides <= 1,000,000.
Mesh make_torus(double major, double minor, int rings, int sides);

// The convex hull of the points as a polygon mesh: every face is a maximal planar polygon
// (a cube gives 6 quads, not 12 triangles), counter-clockwise from outside, its vertices the
// input points on that plane. Points inside the hull (not on it) are kept but unused.
// Needs 4 to 1000 points, not all coplanar (else std::invalid_argument); brute force, meant
// for small solids. No normals.
Mesh make_convex_polyhedron(const std::vector<Vec3>& points);

// The solids shipped in common/models, as make_models (common/tools) generates them; a test
// checks that every file still equals its generator.
Mesh make_cube();                  // [-1, 1]^3: 8 vertices, 12 edges, 6 squares
Mesh make_octahedron();            // vertices on the axes at distance 1: 6, 12, 8 triangles
Mesh make_square_pyramid();        // base y = -1 (corners +-1), apex (0, 1, 0): 5, 8, 5 faces
Mesh make_truncated_icosahedron(); // "soccer ball", circumradius 1: 60 vertices, 90 edges,
                                   // 32 faces (12 pentagons, 20 hexagons)

}  // namespace raster
