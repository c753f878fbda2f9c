// Milestone 5's harness: wrapping of any index, fetching and sampling with every filter at any
// uv (NaN, infinity, 1e300) on textures from 0x0 to 9x9 (odd sizes, 1x1, single rows), the
// pyramid, uv derivatives and level of detail of any triangle, Blinn-Phong with any vectors,
// tangent frames of degenerate mappings, normal perturbation, the light's matrix and shadow
// lookups on small maps, fill_triangle called directly, and the whole draw_scene with
// textures, normal maps and shadow-casting lights (see fuzz_input.h). It checks the promises
// textures_shadows.h makes: wrap_index lands in [0, n - 1], samples of finite textures are
// never NaN and stay within the texels' range, shadow factors lie in [0, 1], a frame without a
// normal map or with an invalid one leaves the normal as it was.
#include <algorithm>
#include <cmath>
#include <vector>

#include "fuzz_input.h"
#include "textures_shadows.h"

namespace {

using m5::Mat4;
using raster::Vec2;
using raster::Vec3;

constexpr m5::Wrap kWraps[] = {m5::Wrap::kRepeat, m5::Wrap::kClampToEdge, m5::Wrap::kMirroredRepeat};
constexpr m5::Filter kFilters[] = {m5::Filter::kNearest, m5::Filter::kBilinear, m5::Filter::kNearestMip,
                                   m5::Filter::kTrilinear};

// A texture of 0 to 9 texels a side (0 makes an empty level), texel levels in [0, 255].
m5::Texture texture(fuzz::Input& in) {
    const int w = in.range(0, 9);
    const int h = w == 0 ? 0 : in.range(1, 9);
    m5::Texture t;
    t.wrap_u = kWraps[in.byte() % 3];
    t.wrap_v = kWraps[in.byte() % 3];
    m5::Level base;
    base.width = w;
    base.height = h;
    for (int i = 0; i < w * h; ++i) {
        const raster::Color c = in.color();
        base.texels.push_back({double(c.r), double(c.g), double(c.b)});
    }
    t.levels.push_back(std::move(base));
    return t;
}

void check_sample(Vec3 s, const char* what, const char* hint) {
    for (double c : {s.x, s.y, s.z}) {
        if (!(c >= -1e-9 && c <= 255 + 1e-9)) fuzz::broken(what, hint);
    }
}

void textures(fuzz::Input& in) {
    const int n = in.range(1, 1000);
    const double i = in.real();
    const m5::Wrap mode = kWraps[in.byte() % 3];
    const double wrapped = m5::wrap_index(std::isfinite(i) ? std::floor(i) : i, n, mode);
    if (!(wrapped >= 0 && wrapped <= n - 1 && wrapped == std::floor(wrapped)))
        fuzz::broken("m5::wrap_index: outside [0, n - 1] or not a whole number",
                     "TODO 1 (textures_shadows.h): wrap_index puts any finite whole-number index into "
                     "0 .. n - 1 by its mode, and a non-finite one at 0");

    m5::Texture t = texture(in);
    // A copy: sample() may build the pyramid, and growing t.levels moves level 0.
    const m5::Level base = t.levels[0];
    const double fi = in.real(), fj = in.real();
    if (std::isfinite(fi) && std::isfinite(fj))
        check_sample(m5::fetch(base, std::floor(fi), std::floor(fj), t.wrap_u, t.wrap_v), "m5::fetch out of range",
                     "TODO 1 (textures_shadows.h): fetch wraps each index with wrap_index, and a level with "
                     "no texels gives black");
    for (int k = 0; k < 4 && !in.empty(); ++k) {
        const Vec2 uv = in.vec2();
        check_sample(m5::sample_nearest(base, uv, t.wrap_u, t.wrap_v), "m5::sample_nearest: NaN or out of range",
                     "TODO 2 (textures_shadows.h): a NaN or infinite uv samples black, and every texel "
                     "read is wrapped, so a sample is a texel, within 0 .. 255");
        check_sample(m5::sample_bilinear(base, uv, t.wrap_u, t.wrap_v), "m5::sample_bilinear: NaN or out of range",
                     "TODO 2 (textures_shadows.h): a NaN or infinite uv samples black; otherwise the four "
                     "texels read are wrapped and their weights lie in [0, 1] and sum to 1");
        long long builds = 0;
        const double lambda = in.real();
        check_sample(m5::sample(t, uv, lambda, kFilters[in.byte() % 4], &builds), "m5::sample: NaN or out of range",
                     "TODO 4 (textures_shadows.h, Filters): the level read is clamped to the pyramid, and a "
                     "NaN or infinite uv gives black");
        if (builds > 1)
            fuzz::broken("m5::sample built the pyramid twice",
                         "TODO 4 (textures_shadows.h): sample builds the mipmaps once, only when a filter "
                         "needs them and the texture has none yet");
    }
    m5::build_mipmaps(t);
    for (const m5::Level& level : t.levels) {
        if (level.texels.size() != static_cast<std::size_t>(level.width) * static_cast<std::size_t>(level.height))
            fuzz::broken("m5::build_mipmaps: a level's texel count is not width * height",
                         "TODO 3 (textures_shadows.h, Mipmaps): level k + 1 is max(1, floor(w / 2)) by "
                         "max(1, floor(h / 2)) texels, and holds exactly that many");
    }
}

void derivatives_and_light(fuzz::Input& in) {
    std::array<Vec3, 3> screen;
    std::array<double, 3> w;
    std::array<Vec2, 3> uv;
    for (int k = 0; k < 3; ++k) {
        screen[k] = in.vec3();
        w[k] = in.flag() ? 1.0 : in.real();
        uv[k] = in.vec2();
    }
    const double x = in.real(), y = in.real();
    const m5::UvDerivatives d = m5::uv_derivatives(screen, w, uv, x, y);
    (void)m5::level_of_detail(d, in.range(0, 4096), in.range(0, 4096));

    const Vec3 base = in.vec3(), specular = in.vec3();
    const double shininess = in.mild();
    const Vec3 normal = in.vec3(), to_eye = in.vec3(), to_light = in.vec3(), intensity = in.mild3();
    (void)m5::blinn_phong(base, specular, shininess, normal, to_eye, to_light, intensity);

    const m5::TangentFrame f = m5::tangent_frame(in.vec3(), in.vec3(), in.vec3(), in.vec2(), in.vec2(), in.vec2());
    const Vec3 n = raster::normalize(in.vec3());
    const Vec3 texel = in.vec3();
    const Vec3 p = m5::perturb_normal(f, n, texel);
    if (!f.valid && raster::is_finite(n) && !(p == n)) fuzz::broken("m5::perturb_normal changed n without a frame",
                     "TODO 7 (textures_shadows.h): without a valid tangent frame, perturb_normal returns n "
                     "unchanged");
}

m5::ShadowSettings settings(fuzz::Input& in) {
    m5::ShadowSettings s;
    s.resolution = in.range(1, 48);
    s.center = in.flag() ? Vec3{} : in.vec3();
    s.radius = in.flag() ? 4.0 : in.real();
    s.constant_bias = in.flag() ? 0.02 : in.mild();
    s.slope_bias = in.flag() ? 0.02 : in.mild();
    s.pcf = in.flag();
    return s;
}

void shadows(fuzz::Input& in) {
    const m5::ShadowSettings s = settings(in);
    const Vec3 direction = in.vec3();
    m5::ShadowMap map;
    map.light = m5::light_view_projection(direction, s);
    map.radius = s.radius;
    map.resolution = s.resolution;
    map.keys.assign(static_cast<std::size_t>(s.resolution) * static_cast<std::size_t>(s.resolution), m4::kClearKey);
    for (std::uint32_t& k : map.keys) {
        if (in.flag()) k = std::bit_cast<std::uint32_t>(static_cast<float>(in.range(0, 65535)) / 65535.0f);
    }
    for (int k = 0; k < 4 && !in.empty(); ++k) {
        const double f = m5::shadow_factor(map, in.vec3(), raster::normalize(in.vec3()), direction, s);
        if (!(f >= 0 && f <= 1)) fuzz::broken("m5::shadow_factor outside [0, 1]",
                                                "TODO 8 (textures_shadows.h): 1 when lit, 0 when shadowed, the "
                                                "lit fraction of the 3x3 texels with pcf: never outside [0, 1]");
    }
}

Mat4 matrix(fuzz::Input& in) {
    switch (in.byte() % 4) {
        case 0: return m3::identity();
        case 1: return m3::translate(in.vec3());
        case 2: return m3::scale(in.mild3());
        default: return fuzz::raw_matrix<Mat4>(in);
    }
}

Mat4 projection(fuzz::Input& in) {
    switch (in.byte() % 4) {
        case 0: return m3::perspective(60, 1, 0.1, 100);
        case 1: return std::apply(m3::perspective, fuzz::perspective_args(in));
        case 2: return m3::perspective(60, 1, 1e-6, 1e6);
        default: return std::apply(m3::orthographic, fuzz::orthographic_args(in));
    }
}

m5::Lighting lighting(fuzz::Input& in) {
    m5::Lighting l;
    l.ambient = in.flag() ? Vec3{0.1, 0.1, 0.1} : in.mild3();
    for (int i = 0, n = in.range(0, 2); i < n; ++i) {
        m5::Light light;
        light.direction = in.vec3();
        light.intensity = in.flag() ? Vec3{1, 1, 1} : in.mild3();
        light.casts_shadows = in.flag();
        l.lights.push_back(light);
    }
    return l;
}

m5::Material material(fuzz::Input& in, m5::Texture* tex, m5::Texture* normals) {
    m5::Material m;
    m.color = in.color();
    const std::uint8_t b = in.byte();
    m.texture = (b & 1) ? tex : nullptr;
    m.normal_map = (b & 2) ? normals : nullptr;
    m.lit = !(b & 4);
    m.filter = kFilters[(b >> 3) & 3];
    m.specular = (b & 32) ? in.vec3() : Vec3{};
    m.shininess = in.mild();
    return m;
}

void draw(fuzz::Input& in) {
    m5::Frame frame;
    frame.color = fuzz::image(in);
    m4::clear_frame(frame, in.color(), true, m4::DepthFormat::kFloatZ);
    m5::Texture tex = texture(in), normals = texture(in);
    std::vector<m4::Mesh> meshes(in.range(1, 2));
    const Vec3 eye = in.flag() ? Vec3{} : in.vec3();
    for (m4::Mesh& mesh : meshes) {
        const int n = in.range(0, 9);
        mesh.positions = fuzz::positions(in, n, eye);
        mesh.triangles = fuzz::triangles(in, n);
        for (int i = 0, k = in.range(0, n); i < k; ++i) mesh.uvs.push_back(in.vec2());
        if (in.flag()) {
            for (int i = 0, k = in.range(0, n); i < k; ++i) mesh.normals.push_back(in.vec3());
        }
    }
    std::vector<m5::Object> objects;
    for (const m4::Mesh& mesh : meshes) {
        m5::Object o;
        o.mesh = &mesh;
        o.model = matrix(in);
        o.material = material(in, &tex, &normals);
        o.casts_shadow = in.flag();
        objects.push_back(o);
    }
    m5::Camera camera;
    camera.eye = eye + Vec3{0, 0, 3};
    camera.view = in.flag() ? m3::look_at(camera.eye, eye, {0, 1, 0}) : matrix(in);
    camera.projection = projection(in);
    const m5::Lighting light = lighting(in);
    const m5::ShadowSettings s = settings(in);
    (void)m5::draw_scene(frame, objects, camera, light, s);
}

// fill_triangle called directly with any vertices, w and attributes, on a textured material.
void fill(fuzz::Input& in) {
    m5::Frame frame;
    frame.color = fuzz::image(in);
    m4::clear_frame(frame, in.color(), true, m4::DepthFormat::kFloatZ);
    m5::Texture tex = texture(in), normals = texture(in);
    const m5::Material mat = material(in, &tex, &normals);
    const m5::Lighting light = lighting(in);
    const m5::ShadowSettings s = settings(in);
    const std::vector<const m5::ShadowMap*> maps(light.lights.size(), nullptr);
    m5::FillState state;
    state.material = &mat;
    state.lighting = &light;
    state.shadow_maps = &maps;
    state.shadow_settings = &s;
    state.eye = in.vec3();
    state.tangent = m5::tangent_frame(in.vec3(), in.vec3(), in.vec3(), in.vec2(), in.vec2(), in.vec2());
    for (int t = 0; t < 3 && !in.empty(); ++t) {
        std::array<m5::ScreenVertex, 3> v;
        for (auto& sv : v) {
            sv.screen = {in.real(), in.real(), in.flag() ? in.mild() : in.real()};
            sv.w = in.flag() ? 1.0 : in.real();
            sv.normal = in.flag() ? Vec3{0, 0, 1} : in.vec3();
            sv.world = in.flag() ? Vec3{} : in.vec3();
            sv.uv = in.flag() ? Vec2{0.5, 0.5} : in.vec2();
        }
        m5::Stats stats;
        m5::fill_triangle(frame, v, state, stats);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::Input in(data, size);
    fuzz::Guard guard;
    switch (in.byte() % 5) {
        case 0: textures(in); break;
        case 1: derivatives_and_light(in); break;
        case 2: shadows(in); break;
        case 3: fill(in); break;
        default: draw(in);
    }
    return 0;
}
