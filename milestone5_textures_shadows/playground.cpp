// Milestone 5 playground: this file is yours. Draw whatever you want to look at with YOUR
// textures_shadows.cpp (and your own milestones 1 to 4); `make` rebuilds it with your current
// code, and the checkpoints never read it.
//
//   ./checkpoints/playground_m5 [output-folder]     (default: playground_out/m5)
//
// It draws a bumpy, shiny cube standing on a checkerboard floor that recedes to the horizon,
// lit by the sun, which casts shadows, in four versions: trilinear, nearest, without the
// shadow and with the bias set to zero. Try: a shadow map of 64 or 4096 texels, pcf off, the
// sun low (direction (-1, -0.05, -0.3)) or below the floor, the floor's uv moved by 1e7, a wrap
// of kClampToEdge or kMirroredRepeat, shininess 4 or 400, the normal map's texels read as
// [0, 1], a 1 x 1 texture.
#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>

#include "raster/io.h"
#include "textures_shadows.h"

using raster::Color;
using raster::Image;
using raster::Vec2;
using raster::Vec3;

namespace {

// A checkerboard of `cells` x `cells` squares on an n x n image.
Image checkerboard(int n, int cells) {
    Image img(n, n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const bool light = (x * cells / n + y * cells / n) % 2 == 0;
            img.set(x, y, light ? Color{235, 225, 200} : Color{60, 70, 90});
        }
    return img;
}

// A tangent-space normal map of round bumps: each texel is (2 t / 255 - 1) encoded back to
// [0, 255], red along +u, green along +v (down the image), blue out of the surface.
Image bumps(int n, int per_side) {
    Image img(n, n);
    const double cell = double(n) / per_side;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            // Position inside the bump's cell, in [-1, 1]; the bump's height is 1 - r^2.
            const double px = std::fmod(x + 0.5, cell) / cell * 2 - 1, py = std::fmod(y + 0.5, cell) / cell * 2 - 1;
            const bool inside = px * px + py * py < 1;
            const Vec3 n3 = raster::normalize(inside ? Vec3{1.2 * px, 1.2 * py, 1} : Vec3{0, 0, 1});
            auto encode = [](double c) { return static_cast<std::uint8_t>(std::lround((c + 1) / 2 * 255)); };
            img.set(x, y, Color{encode(n3.x), encode(n3.y), encode(n3.z)});
        }
    return img;
}

// A cube of side 2 with four vertices per face, so each face has its own normal and uv square.
m4::Mesh cube() {
    m4::Mesh m;
    const Vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const Vec3& n : normals) {
        // Two axes across the face, chosen so that (right, up, n) is right-handed.
        const Vec3 up = std::abs(n.y) > 0.5 ? Vec3{0, 0, -n.y} : Vec3{0, 1, 0};
        const Vec3 right = raster::cross(up, n);
        const int first = static_cast<int>(m.positions.size());
        // Corners counter-clockwise seen from outside; v runs down the image, so down the face.
        const Vec3 corner[4] = {n - right - up, n + right - up, n + right + up, n - right + up};
        const Vec2 uv[4] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
        for (int k = 0; k < 4; ++k) {
            m.positions.push_back(corner[k]);
            m.normals.push_back(n);
            m.uvs.push_back(uv[k]);
        }
        m.triangles.push_back({first, first + 1, first + 2});
        m.triangles.push_back({first, first + 2, first + 3});
    }
    return m;
}

// A floor at y = -1, 60 units on a side, its checkerboard repeated 30 times each way.
m4::Mesh floor_mesh() {
    m4::Mesh m;
    m.positions = {{-30, -1, 30}, {30, -1, 30}, {30, -1, -30}, {-30, -1, -30}};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    m.uvs = {{0, 30}, {30, 30}, {30, 0}, {0, 0}};
    m.normals = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
    return m;
}

}  // namespace

int main(int argc, char** argv) {
    const std::filesystem::path out = argc > 1 ? argv[1] : "playground_out/m5";
    std::filesystem::create_directories(out);

    const m4::Mesh box = cube(), ground = floor_mesh();
    m5::Texture checker = m5::make_texture(checkerboard(64, 8));  // repeat in u and v
    m5::Texture crate = m5::make_texture(checkerboard(32, 2));
    m5::Texture bump = m5::make_texture(bumps(64, 4));
    // The textures live across the four versions: a pyramid built in the first is there for the
    // others, so only the first builds (and counts) them.

    m5::Camera camera;
    camera.eye = {3.5, 1.5, 5};
    camera.view = m3::look_at(camera.eye, {0, -0.2, 0}, {0, 1, 0});
    camera.projection = m3::perspective(50, 1, 0.5, 80);

    m5::Lighting lighting;
    lighting.ambient = {0.15, 0.15, 0.18};
    lighting.lights.push_back({{-1, -1.1, 0.1}, {0.9, 0.9, 0.85}, true});  // the sun, casting shadows

    // The light's box: radius 4 around the cube covers it and its shadow on the floor; outside the
    // box everything is lit.
    m5::ShadowSettings shadows;
    shadows.resolution = 1024;
    shadows.center = {0, -0.5, 0};
    shadows.radius = 4;

    struct Version {
        const char* name;
        m5::Filter floor_filter;
        bool casts_shadows;
        double bias;
    };
    const Version versions[] = {{"trilinear", m5::Filter::kTrilinear, true, 0.02},
                                {"nearest", m5::Filter::kNearest, true, 0.02},
                                {"no_shadow", m5::Filter::kTrilinear, false, 0.02},
                                {"no_bias", m5::Filter::kTrilinear, true, 0.0}};
    for (const Version& version : versions) {
        std::vector<m5::Object> objects(2);
        objects[0].mesh = &ground;
        objects[0].material.texture = &checker;
        objects[0].material.filter = version.floor_filter;
        objects[1].mesh = &box;
        objects[1].model = m3::rotate({0, 1, 0}, 0.5);
        objects[1].material.texture = &crate;
        objects[1].material.filter = m5::Filter::kTrilinear;
        objects[1].material.specular = {180, 180, 180};
        objects[1].material.shininess = 32;
        objects[1].material.normal_map = &bump;

        lighting.lights[0].casts_shadows = version.casts_shadows;
        shadows.constant_bias = version.bias;
        shadows.slope_bias = version.bias;

        m4::Frame frame;
        frame.color = Image(256, 256);
        m4::clear_frame(frame, {150, 180, 220}, true, m4::DepthFormat::kFloatZ);
        const m5::Stats st = m5::draw_scene(frame, objects, camera, lighting, shadows);
        const std::string path = (out / (std::string(version.name) + ".png")).string();
        raster::write_png(path, frame.color);
        const bool first = &version == &versions[0];
        std::cout << "wrote " << path << ": " << st.fragments << " fragments, " << st.shaded << " shaded, "
                  << st.texture_samples << " texture samples, " << st.mipmap_builds << " pyramids built"
                  << (first ? "" : " (the first version's are reused)") << ", "
                  << st.shadow_passes << " shadow passes, " << st.shadow_lookups << " shadow lookups\n";
    }
    return 0;
}
