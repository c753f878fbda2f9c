#include "model.h"

#include <algorithm>
#include <cmath>
#include <exception>

namespace viewer {

using raster::Vec3;

namespace {

Model finish(raster::Mesh mesh, std::string name) {
    Model m;
    m.mesh = std::move(mesh);
    m.edges = raster::unique_edges(m.mesh);
    m.name = std::move(name);
    return m;
}

}  // namespace

bool fit_unit_sphere(raster::Mesh& mesh) {
    if (mesh.positions.empty()) return false;
    Vec3 lo = mesh.positions[0], hi = lo;
    for (const Vec3 p : mesh.positions) {
        if (!raster::is_finite(p)) return false;
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    // Halves first: (hi - lo) overflows for coordinates near 1e308, hi / 2 - lo / 2 does not.
    const Vec3 center = hi / 2 + lo / 2;
    const Vec3 half = hi / 2 - lo / 2;
    const double extent = std::max({half.x, half.y, half.z});
    if (!(extent > 0) || !std::isfinite(extent)) return false;
    // First into the cube [-1, 1]^3 around the box's center (scaling before subtracting, so
    // that nothing overflows), then by the farthest vertex's distance onto the unit sphere.
    const double s = 1 / extent;
    std::vector<Vec3> fitted;
    fitted.reserve(mesh.positions.size());
    double radius = 0;
    for (const Vec3 p : mesh.positions) {
        fitted.push_back(p * s - center * s);
        radius = std::max(radius, raster::length(fitted.back()));
    }
    if (!(radius > 0) || !std::isfinite(radius)) return false;
    for (Vec3& q : fitted) q = q / radius;
    mesh.positions = std::move(fitted);
    return true;
}

bool make_named(const std::string& name, Model& out) {
    constexpr double kMajor = 1.0, kMinor = 0.42;
    if (name == "torus" || name == "big-torus") {
        out = name == "torus" ? finish(raster::make_torus(kMajor, kMinor, 48, 24), "torus (generated)")
                              : finish(raster::make_torus(kMajor, kMinor, 250, 200), "torus of 100,000 triangles (generated)");
        out.uv_mapping = UvMapping::kTorus;
        out.ring_radius = kMajor / (kMajor + kMinor);  // fitting scales the outer radius to 1
    } else if (name == "sphere") {
        out = finish(raster::make_uv_sphere(24, 48), "sphere (generated)");
    } else {
        const std::vector<std::string> shipped = raster::model_names();
        if (std::find(shipped.begin(), shipped.end(), name) == shipped.end()) return false;
        out = finish(raster::load_obj(raster::model_path(name)), name + " (common/models)");
    }
    if (!fit_unit_sphere(out.mesh)) return false;
    return true;
}

Model default_model() {
    Model m;
    make_named("torus", m);
    return m;
}

Model load_model(const std::string& source, std::string& error) {
    error.clear();
    try {
        Model m;
        if (make_named(source, m)) return m;
        m = finish(raster::load_obj(source), source);
        if (!fit_unit_sphere(m.mesh)) {
            error = "cannot show " + source + ": the model has no size or coordinates too large to scale";
            return default_model();
        }
        return m;
    } catch (const std::exception& e) {
        error = std::string("cannot load ") + e.what();
    }
    return default_model();
}

}  // namespace viewer
