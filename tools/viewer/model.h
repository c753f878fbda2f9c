// The model the viewer shows: an OBJ file (common's loader, raster::load_obj), a model shipped
// in common/models by name, or a mesh generated in code. Every model is moved and scaled to fit
// the unit sphere at the origin, so the camera (camera.h) needs no knowledge of its units.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "raster/mesh.h"

namespace viewer {

// How milestone 5's modes put a texture on the model (scene.h): the generated tori by their
// own two angles, everything else by a spherical mapping around the y axis.
enum class UvMapping { kSpherical, kTorus };

struct Model {
    raster::Mesh mesh;
    std::vector<std::array<int, 2>> edges;  // the wireframe: every polygon edge once
    std::string name;
    UvMapping uv_mapping = UvMapping::kSpherical;
    double ring_radius = 0;  // kTorus: the radius of the tube's center circle, after fitting
};

// A generated torus (the default), or any name make_named knows.
Model default_model();

// "torus", "sphere", "big-torus" (the benchmark's ~100,000 triangles) or a model shipped in
// common/models ("cube", "soccer_ball", ...). Returns false for an unknown name.
bool make_named(const std::string& name, Model& out);

// Loads `source` (a name as above, else a path to an OBJ file). Never throws: on any failure
// (missing file, malformed OBJ, a model of zero size or with coordinates too large to scale)
// `error` says why and the result is default_model().
Model load_model(const std::string& source, std::string& error);

// Centers the mesh's bounding box on the origin and scales it uniformly so that every vertex
// lies within distance 1 of it. False (mesh unchanged) when it has no extent or is not finite.
bool fit_unit_sphere(raster::Mesh& mesh);

}  // namespace viewer
