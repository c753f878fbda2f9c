// Milestone 4's harness: depth keys in every format, the depth test, perspective weights,
// normals, lighting (infinite intensities included), the debug views, clipping with
// attributes, fill_triangle called directly with extreme w and attributes, and the whole
// draw_mesh in every shading mode and depth format, with vertices at the eye, tiny near
// planes and extreme uvs (see fuzz_input.h). It checks the promises depth_lighting.h makes
// about such input: shade never NaN for a finite base and lighting, to_color's clamp.
#include <cmath>
#include <vector>

#include "depth_lighting.h"
#include "fuzz_input.h"

namespace {

using m4::Mat4;
using raster::Vec2;
using raster::Vec3;
using raster::Vec4;

constexpr m4::DepthFormat kFormats[] = {m4::DepthFormat::kFloatZ, m4::DepthFormat::kReversedZ,
                                        m4::DepthFormat::kFixed24, m4::DepthFormat::kInverseW};
constexpr m4::Shading kModes[] = {m4::Shading::kFaceColor, m4::Shading::kVertexColor, m4::Shading::kFlat,
                                  m4::Shading::kGouraud,   m4::Shading::kPerPixel,    m4::Shading::kChecker,
                                  m4::Shading::kDepthView, m4::Shading::kNormalView};

m4::Lighting lighting(fuzz::Input& in) {
    m4::Lighting l;
    l.ambient = in.flag() ? Vec3{0.1, 0.1, 0.1} : in.mild3();
    const int n = in.range(0, 3);
    for (int i = 0; i < n; ++i) {
        m4::Light light;
        light.kind = in.flag() ? m4::Light::Kind::kPoint : m4::Light::Kind::kDirectional;
        light.vector = in.vec3();
        light.intensity = in.flag() ? Vec3{1, 1, 1} : in.mild3();
        l.lights.push_back(light);
    }
    return l;
}

m4::Needs needs(fuzz::Input& in) {
    m4::Needs n;
    const std::uint8_t b = in.byte();
    n.depth_test = b & 1;
    n.perspective_correct = !(b & 2);
    n.cull = b & 4;
    n.depth_format = kFormats[(b >> 3) & 3];
    n.shading = kModes[(b >> 5) & 7];
    return n;
}

// A projection: usually a perspective with a near plane from ordinary to subnormal.
Mat4 projection(fuzz::Input& in) {
    switch (in.byte() % 4) {
        case 0: return m3::perspective(60, 1, 0.1, 100);
        case 1: return std::apply(m3::perspective, fuzz::perspective_args(in));
        case 2: {
            const double near = std::numeric_limits<double>::denorm_min() * in.range(1, 1000);
            return m3::perspective(90, 1, near, in.mild());
        }
        default: return std::apply(m3::orthographic, fuzz::orthographic_args(in));
    }
}

Mat4 matrix(fuzz::Input& in) {
    switch (in.byte() % 4) {
        case 0: return m3::identity();
        case 1: {
            const Mat4 t = m3::translate(in.vec3());
            return t * std::apply(m3::rotate, std::tuple{in.mild3(), in.mild()});
        }
        case 2: return m3::scale(in.mild3());
        default: return fuzz::raw_matrix<Mat4>(in);
    }
}

void draw(fuzz::Input& in) {
    m4::Frame frame;
    frame.color = fuzz::image(in);
    const m4::Needs nd = needs(in);
    m4::clear_frame(frame, in.color(), nd.depth_test, nd.depth_format);
    m4::Mesh mesh;
    const int n = in.range(0, 9);
    const Vec3 eye = in.flag() ? Vec3{} : in.vec3();
    mesh.positions = fuzz::positions(in, n, eye);
    mesh.triangles = fuzz::triangles(in, n);
    const int triangles = static_cast<int>(mesh.triangles.size());
    const std::uint8_t arrays = in.byte();
    if (arrays & 1) {
        for (int i = 0, k = in.range(0, triangles); i < k; ++i) mesh.face_colors.push_back(in.color());
    }
    if (arrays & 2) {
        for (int i = 0, k = in.range(0, n); i < k; ++i) mesh.vertex_colors.push_back(in.color());
    }
    if (arrays & 4) {
        for (int i = 0, k = in.range(0, n); i < k; ++i) mesh.uvs.push_back(in.vec2());
    }
    if (arrays & 8) {
        for (int i = 0, k = (arrays & 16) ? n : in.range(0, n); i < k; ++i) mesh.normals.push_back(in.vec3());
    }
    const Mat4 model = matrix(in);
    const Mat4 view = in.flag() ? m3::look_at(eye + Vec3{0, 0, 3}, eye, {0, 1, 0}) : matrix(in);
    const Mat4 proj = projection(in);
    const m4::Lighting light = lighting(in);
    (void)m4::draw_mesh(frame, mesh, model, view, proj, light, in.color(), nd);
}

// fill_triangle called directly: vertices on and around the image, with any w and attributes.
void fill(fuzz::Input& in) {
    m4::Frame frame;
    frame.color = fuzz::image(in);
    const m4::Needs nd = needs(in);
    m4::clear_frame(frame, in.color(), nd.depth_test, nd.depth_format);
    const m4::Lighting light = lighting(in);
    m4::FillState state;
    state.needs = nd;
    state.lighting = &light;
    state.material = in.color();
    state.flat_color = in.color();
    for (const m4::Light& l : light.lights) state.point_light |= l.kind == m4::Light::Kind::kPoint;
    for (int t = 0; t < 3 && !in.empty(); ++t) {
        std::array<m4::ScreenVertex, 3> v;
        for (auto& s : v) {
            s.screen = {in.real(), in.real(), in.flag() ? in.mild() : in.real()};
            s.w = in.flag() ? 1.0 : in.real();
            s.color = in.flag() ? Vec3{} : in.vec3();
            s.normal = in.flag() ? Vec3{0, 0, 1} : in.vec3();
            s.world = in.flag() ? Vec3{} : in.vec3();
            s.uv = in.flag() ? Vec2{0.5, 0.5} : in.vec2();
        }
        m4::Stats stats;
        m4::fill_triangle(frame, v, state, stats);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::Input in(data, size);
    fuzz::Guard guard;
    switch (in.byte() % 6) {
        case 0: {
            for (m4::DepthFormat f : kFormats) (void)std::apply(m4::depth_key, std::tuple{f, in.real(), in.real()});
            (void)std::apply(m4::depth_passes, std::tuple{in.byte() < 64 ? m4::kClearKey : in.range(0, 65535) * 65537u,
                                                          in.color(), in.range(0, 65535) * 65537u, in.color()});
            const std::array<double, 3> screen{in.real(), in.real(), in.real()};
            (void)m4::perspective_weights(screen, {in.real(), in.real(), in.real()});
            (void)m4::depth_gray(in.real());
            (void)m4::normal_color(in.vec3());
            (void)m4::checker(in.vec2());
            (void)m4::to_color(in.vec3());
            break;
        }
        case 1: {
            (void)std::apply(m4::face_normal, std::tuple{in.vec3(), in.vec3(), in.vec3()});
            std::vector<Vec3> positions(in.range(0, 6));
            for (Vec3& p : positions) p = in.vec3();
            std::vector<std::array<int, 3>> tris(in.range(0, 6));
            const int n = static_cast<int>(positions.size());
            for (auto& t : tris) t = {in.range(-1, n), in.range(-1, n), in.range(-1, n)};
            if (m4::vertex_normals(positions, tris).size() != positions.size())
                fuzz::broken("m4::vertex_normals: not one normal per position",
                             "TODO 4 (depth_lighting.h): one normal per position, whatever the triangles "
                             "(an index out of range skips its triangle)");
            (void)m4::normal_matrix(matrix(in));
            break;
        }
        case 2: {
            const m4::Lighting l = lighting(in);
            const raster::Color base = in.color();
            const auto [position, normal] = std::tuple{in.vec3(), in.vec3()};
            const Vec3 levels = m4::shade(l, base, position, normal);
            // NaN only where it cannot be helped: a channel of base 0 under an infinite sum of
            // light (0 * infinity), or a NaN given in the lighting.
            bool no_nan_light = !std::isnan(l.ambient.x) && !std::isnan(l.ambient.y) && !std::isnan(l.ambient.z);
            for (const m4::Light& light : l.lights) {
                no_nan_light &= !std::isnan(light.intensity.x) && !std::isnan(light.intensity.y) &&
                                !std::isnan(light.intensity.z);
                // +infinity and -infinity intensities (or ambient) could cancel into NaN.
                no_nan_light &= raster::is_finite(light.intensity);
            }
            if (no_nan_light && base.r > 0 && base.g > 0 && base.b > 0 &&
                (std::isnan(levels.x) || std::isnan(levels.y) || std::isnan(levels.z)))
                fuzz::broken("m4::shade returned NaN",
                             "TODO 5 (depth_lighting.h): a light with max(0, dot(N, L)) = 0 adds nothing at all, "
                             "so a zero normal under an infinite light gives the ambient color, never infinity * 0");
            break;
        }
        case 3: {
            std::array<m4::ClipVertex, 3> t;
            for (auto& v : t) v = {in.vec4(), in.vec3(), in.vec3(), in.vec3(), in.vec2()};
            (void)m4::clip_triangle(t);
            (void)m4::lerp(t[0], t[1], in.real());
            break;
        }
        case 4: fill(in); break;
        default: draw(in);
    }
    return 0;
}
