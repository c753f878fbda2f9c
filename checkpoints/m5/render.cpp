// Render half: turns a scene into calls to the milestone-5 functions. Everything here runs
// the code under test, so nothing here decides a verdict. Value keys are read by judge.cpp.
// The matrices, clipping and depth keys come from milestones 3 and 4 (the reference, in the
// checkpoint programs).
#include "m5/render.h"

#include <algorithm>
#include <cmath>

#include "m5/scenes.h"
#include "textures_shadows.h"

namespace m5cp {
namespace RASTER_FLAVOUR {

namespace {

using m3::Mat4;
using Values = std::map<std::string, double>;

// Every call into the code under test goes through cp::traced: CALL("name", expression).
cp::Artifacts* g_out = nullptr;
#define CALL(name, ...) cp::traced(*g_out, name, [&] { return __VA_ARGS__; })

void put(Values& v, const std::string& key, Vec3 p) {
    v[key + ".x"] = p.x;
    v[key + ".y"] = p.y;
    v[key + ".z"] = p.z;
}
void put(Values& v, const std::string& key, const Mat4& m) {
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) v[key + "." + std::to_string(i) + std::to_string(j)] = m.m[i][j];
    }
}

m5::Wrap wrap(Wrap w) { return static_cast<m5::Wrap>(w); }
m5::Filter filter(Filter f) { return static_cast<m5::Filter>(f); }

m5::Level to_level(const LevelData& d) {
    m5::Level l;
    l.width = d.width;
    l.height = d.height;
    l.texels = d.texels;
    return l;
}

m5::Texture to_texture(const TextureSpec& t) { return m5::make_texture(texture_image(t), wrap(t.wrap_u), wrap(t.wrap_v)); }

m4::Mesh to_mesh(const Mesh& m) { return {m.positions, m.triangles, m.face_colors, m.vertex_colors, m.uvs, m.normals}; }

Mat4 model_matrix(const Item& it) { return m3::translate(it.position) * m3::rotate(it.axis, it.angle) * m3::scale(it.size); }

m5::Material to_material(const MaterialSpec& s, std::vector<m5::Texture>& textures) {
    m5::Material m;
    m.color = s.color;
    auto texture = [&textures](int i) { return i >= 0 && std::size_t(i) < textures.size() ? &textures[std::size_t(i)] : nullptr; };
    m.texture = texture(s.texture);
    m.filter = filter(s.filter);
    m.specular = s.specular;
    m.shininess = s.shininess;
    m.normal_map = texture(s.normal_map);
    m.lit = s.lit;
    return m;
}

// The light's matrix as the header pins it, built here with milestone 3's functions (for the
// ready-made shadow map of the lookup numbers).
Mat4 pinned_light_matrix(Vec3 direction, Vec3 center, double r) {
    const Vec3 d = raster::normalize(direction);
    const Vec3 up = std::abs(d.y) > 0.99 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    return m3::orthographic(-r, r, -r, r, r, 3 * r) * m3::look_at(center - d * (2 * r), center, up);
}

void numbers(Group g, Values& v) {
    switch (g) {
        case Group::kWrap: {
            const auto cases = wrap_cases();
            for (std::size_t i = 0; i < cases.size(); ++i) {
                const auto& c = cases[i];
                v["wrap" + std::to_string(i)] = CALL("wrap_index", m5::wrap_index(c.i, c.n, wrap(c.mode)));
            }
            const auto fetches = fetch_cases();
            for (std::size_t i = 0; i < fetches.size(); ++i) {
                const auto& c = fetches[i];
                const m5::Level level = to_level(sample_level(c.level));
                put(v, "fetch" + std::to_string(i), CALL("fetch", m5::fetch(level, c.i, c.j, wrap(c.wu), wrap(c.wv))));
            }
            break;
        }
        case Group::kSampling: {
            const auto cases = sample_cases();
            for (std::size_t i = 0; i < cases.size(); ++i) {
                const auto& c = cases[i];
                const m5::Level level = to_level(sample_level(c.level));
                put(v, "nearest" + std::to_string(i), CALL("sample_nearest", m5::sample_nearest(level, c.uv, wrap(c.wu), wrap(c.wv))));
                put(v, "bilinear" + std::to_string(i), CALL("sample_bilinear", m5::sample_bilinear(level, c.uv, wrap(c.wu), wrap(c.wv))));
            }
            break;
        }
        case Group::kMipmaps: {
            const auto bases = mip_bases();
            for (std::size_t b = 0; b < bases.size(); ++b) {
                m5::Texture t;
                t.levels.push_back(to_level(bases[b]));
                CALL("build_mipmaps", (m5::build_mipmaps(t), 0));
                const std::string key = "mip" + std::to_string(b);
                v[key + ".levels"] = double(t.levels.size());
                v[key + ".mipmapped"] = t.mipmapped;
                for (std::size_t k = 0; k < t.levels.size() && k < 16; ++k) {
                    const m5::Level& l = t.levels[k];
                    const std::string lk = key + ".L" + std::to_string(k);
                    v[lk + ".w"] = l.width;
                    v[lk + ".h"] = l.height;
                    v[lk + ".n"] = double(l.texels.size());
                    for (std::size_t i = 0; i < l.texels.size() && i < 64; ++i) put(v, lk + ".t" + std::to_string(i), l.texels[i]);
                }
                // Built again: the levels are replaced, not added.
                CALL("build_mipmaps", (m5::build_mipmaps(t), 0));
                v[key + ".again.levels"] = double(t.levels.size());
            }
            m5::Texture empty;
            empty.levels.emplace_back();
            CALL("build_mipmaps", (m5::build_mipmaps(empty), 0));
            v["empty.levels"] = double(empty.levels.size());
            v["empty.mipmapped"] = empty.mipmapped;
            m5::Texture none;
            CALL("build_mipmaps", (m5::build_mipmaps(none), 0));
            v["none.levels"] = double(none.levels.size());
            break;
        }
        case Group::kLod: {
            const auto cases = lod_cases();
            for (std::size_t i = 0; i < cases.size(); ++i) {
                const auto& c = cases[i];
                const m5::UvDerivatives d = CALL("uv_derivatives", m5::uv_derivatives(c.screen, c.w, c.uv, c.x, c.y));
                const std::string key = "lod" + std::to_string(i);
                v[key + ".du_dx"] = d.du_dx;
                v[key + ".dv_dx"] = d.dv_dx;
                v[key + ".du_dy"] = d.du_dy;
                v[key + ".dv_dy"] = d.dv_dy;
            }
            const auto lambdas = lambda_cases();
            for (std::size_t i = 0; i < lambdas.size(); ++i) {
                const auto& c = lambdas[i];
                m5::UvDerivatives d;
                d.du_dx = c.du_dx;
                d.dv_dx = c.dv_dx;
                d.du_dy = c.du_dy;
                d.dv_dy = c.dv_dy;
                v["lambda" + std::to_string(i)] = CALL("level_of_detail", m5::level_of_detail(d, c.width, c.height));
            }
            break;
        }
        case Group::kFilter: {
            const auto bases = mip_bases();
            const auto cases = filter_cases();
            m5::Texture t;
            long long builds = 0;
            for (std::size_t i = 0; i < cases.size(); ++i) {
                const auto& c = cases[i];
                if (i == 0 || c.base != cases[i - 1].base || c.filter != cases[i - 1].filter) {
                    t = m5::Texture{};
                    t.levels.push_back(to_level(bases[std::size_t(c.base)]));
                    builds = 0;
                }
                t.wrap_u = wrap(c.wrap_u);
                t.wrap_v = wrap(c.wrap_v);
                const std::string key = "filter" + std::to_string(i);
                put(v, key, CALL("sample", m5::sample(t, c.uv, c.lambda, filter(c.filter), &builds)));
                v[key + ".builds"] = double(builds);
                v[key + ".levels"] = double(t.levels.size());
            }
            // No counter to add to: must not crash.
            m5::Texture fresh;
            fresh.levels.push_back(to_level(bases[0]));
            put(v, "filter.null", CALL("sample", m5::sample(fresh, {0.3, 0.7}, 1.5, m5::Filter::kTrilinear, nullptr)));
            // A texture with no texels, sampled twice by a mip filter: black, and at most one
            // pyramid counted (there is nothing to build).
            m5::Texture empty;
            empty.levels.push_back(m5::Level{});
            long long empty_builds = 0;
            for (int k = 0; k < 2; ++k) {
                put(v, "filter.empty" + std::to_string(k),
                    CALL("sample", m5::sample(empty, {0.3, 0.7}, 1.5, m5::Filter::kTrilinear, &empty_builds)));
            }
            v["filter.empty.builds"] = double(empty_builds);
            break;
        }
        case Group::kBlinnPhong: {
            const auto cases = phong_cases();
            for (std::size_t i = 0; i < cases.size(); ++i) {
                const auto& c = cases[i];
                put(v, "phong" + std::to_string(i),
                    CALL("blinn_phong", m5::blinn_phong(c.base, c.specular, c.shininess, c.normal, c.to_eye, c.to_light, c.intensity)));
            }
            break;
        }
        case Group::kTangent: {
            const auto frames = frame_cases();
            for (std::size_t i = 0; i < frames.size(); ++i) {
                const auto& c = frames[i];
                const m5::TangentFrame f = CALL("tangent_frame", m5::tangent_frame(c.p[0], c.p[1], c.p[2], c.uv[0], c.uv[1], c.uv[2]));
                const std::string key = "frame" + std::to_string(i);
                put(v, key + ".t", f.tangent);
                put(v, key + ".b", f.bitangent);
                v[key + ".valid"] = f.valid;
            }
            const auto cases = perturb_cases();
            for (std::size_t i = 0; i < cases.size(); ++i) {
                const auto& c = cases[i];
                m5::TangentFrame f;
                f.tangent = c.tangent;
                f.bitangent = c.bitangent;
                f.valid = c.valid;
                put(v, "perturb" + std::to_string(i), CALL("perturb_normal", m5::perturb_normal(f, c.n, c.texel)));
            }
            break;
        }
        case Group::kShadow: {
            const auto lights = light_matrix_cases();
            for (std::size_t i = 0; i < lights.size(); ++i) {
                const auto& c = lights[i];
                m5::ShadowSettings settings;
                settings.center = c.center;
                settings.radius = c.radius;
                put(v, "light" + std::to_string(i), CALL("light_view_projection", m5::light_view_projection(c.direction, settings)));
            }
            const TinyMap tiny = tiny_map();
            m5::ShadowMap map;
            map.light = pinned_light_matrix(tiny.direction, tiny.center, tiny.radius);
            map.radius = tiny.radius;
            map.resolution = tiny.resolution;
            map.keys = tiny.keys;
            const auto cases = shadow_cases();
            for (std::size_t i = 0; i < cases.size(); ++i) {
                const auto& c = cases[i];
                m5::ShadowSettings settings;
                settings.resolution = tiny.resolution;
                settings.center = tiny.center;
                settings.radius = c.settings_radius > 0 ? c.settings_radius : tiny.radius;
                settings.constant_bias = c.constant_bias;
                settings.slope_bias = c.slope_bias;
                settings.pcf = c.pcf;
                v["shadow" + std::to_string(i)] = CALL("shadow_factor", m5::shadow_factor(map, c.p, c.n, tiny.direction * c.direction_scale, settings));
            }
            break;
        }
    }
}

void put_stats(Values& v, const std::string& key, const m5::Stats& st) {
    v[key + ".shadow_passes"] = double(st.shadow_passes);
    v[key + ".shadow_texels"] = double(st.shadow_texels);
    v[key + ".triangles_drawn"] = double(st.triangles_drawn);
    v[key + ".fragments"] = double(st.fragments);
    v[key + ".shaded"] = double(st.shaded);
    v[key + ".texture_samples"] = double(st.texture_samples);
    v[key + ".lod_computed"] = double(st.lod_computed);
    v[key + ".mipmap_builds"] = double(st.mipmap_builds);
    v[key + ".normal_map_samples"] = double(st.normal_map_samples);
    v[key + ".tangent_frames"] = double(st.tangent_frames);
    v[key + ".specular_terms"] = double(st.specular_terms);
    v[key + ".shadow_lookups"] = double(st.shadow_lookups);
}

void draw_panels(const Scene& s, raster::Image& img, cp::Artifacts& out) {
    for (std::size_t p = 0; p < s.panels.size(); ++p) {
        const Panel& panel = s.panels[p];
        const Camera& c = panel.camera;
        m5::Camera camera;
        camera.view = m3::look_at(c.eye, c.target, c.up);
        camera.projection = m3::perspective(c.fovy, double(panel.w) / panel.h, c.near, c.far);
        camera.eye = c.eye;
        m5::Lighting lighting;
        lighting.ambient = panel.ambient;
        for (const LightSpec& l : panel.lights) lighting.lights.push_back({l.direction, l.intensity, l.casts_shadows});
        m5::ShadowSettings settings;
        settings.resolution = panel.shadows.resolution;
        settings.center = panel.shadows.center;
        settings.radius = panel.shadows.radius;
        settings.constant_bias = panel.shadows.constant_bias;
        settings.slope_bias = panel.shadows.slope_bias;
        settings.pcf = panel.shadows.pcf;
        std::vector<m4::Mesh> meshes;
        std::vector<Mat4> models;
        for (const Item& it : panel.items) {
            meshes.push_back(to_mesh(it.mesh));
            models.push_back(model_matrix(it));
        }

        m4::Frame frame;
        frame.color = cp::guarded_image(panel.w, panel.h);
        m5::Stats total;
        std::vector<m5::Texture> textures;
        auto draw = [&] {
            total = {};
            // Fresh textures for every run: a pyramid built by one run must not be found by the next.
            textures.clear();
            for (const TextureSpec& t : panel.textures) textures.push_back(to_texture(t));
            if (!panel.screen_tris.empty()) {
                // fill_triangle alone: the frame is cleared here (as m4::clear_frame would) and the
                // triangles come ready-made, so this picture depends on TODO 5 and what it calls.
                frame.color.fill(panel.background);
                frame.format = m4::DepthFormat::kFloatZ;
                frame.depth.assign(std::size_t(panel.w) * std::size_t(panel.h), m4::kClearKey);
                const std::vector<const m5::ShadowMap*> no_maps(lighting.lights.size(), nullptr);
                for (const ScreenTri& t : panel.screen_tris) {
                    const m5::Material material = to_material(t.material, textures);
                    m5::FillState state;
                    state.material = &material;
                    state.lighting = &lighting;
                    state.shadow_maps = &no_maps;
                    state.shadow_settings = &settings;
                    state.eye = c.eye;
                    std::array<m5::ScreenVertex, 3> sv;
                    for (std::size_t k = 0; k < 3; ++k) sv[k] = {t.screen[k], t.w[k], {}, {0, 0, 1}, {}, t.uv[k]};
                    cp::traced(*g_out, "fill_triangle", frame.color, [&] { m5::fill_triangle(frame, sv, state, total); });
                }
                return;
            }
            std::vector<m5::Object> objects;
            for (std::size_t i = 0; i < panel.items.size(); ++i) {
                m5::Object o;
                o.mesh = &meshes[i];
                o.model = models[i];
                o.material = to_material(panel.items[i].material, textures);
                o.casts_shadow = panel.items[i].casts_shadow;
                objects.push_back(o);
            }
            m4::clear_frame(frame, panel.background, true, m4::DepthFormat::kFloatZ);
            total = cp::traced(*g_out, "draw_scene", frame.color,
                               [&] { return m5::draw_scene(frame, objects, camera, lighting, settings); });
        };
        const std::string key = "panel" + std::to_string(p);
        out.values[key + ".seconds"] = cp::seconds_of(draw, panel.timed);
        put_stats(out.values, key + ".stats", total);
        cp::place_panel(out, key, frame.color, img, panel.x0, panel.y0, panel.w, panel.h);
    }
}

}  // namespace

cp::Artifacts render(const std::string& id) { return render_scene(scene(id)); }

cp::Artifacts render_scene(const Scene& s) {
    return cp::render_guarded(s.width, s.height, [&](raster::Image& img, cp::Artifacts& out) {
        g_out = &out;
        for (Group g : s.groups) numbers(g, out.values);
        // The functions the picture is drawn with, each on its own checkpoint's inputs: the
        // judge checks them before it judges the picture (scenes.h, prerequisite_groups).
        for (Group g : prerequisite_groups(s)) cp::record_under(out, prerequisite_key(g), [&](Values& v) { numbers(g, v); });
        // fill_triangle on m5.fill_triangle's own triangles, for a scene drawn through
        // draw_scene: when the picture differs, the judge tells a wrong fill_triangle (TODO 5)
        // from a wrong draw_scene (TODO 9) by these.
        const bool pipeline = std::any_of(s.panels.begin(), s.panels.end(), [](const Panel& p) { return p.screen_tris.empty(); });
        if (pipeline) {
            const Scene& fill = scene(kFillScene);
            cp::record_fill_scene(out, kFillKey, fill.width, fill.height, [&](raster::Image& fill_img, cp::Artifacts& scratch) {
                g_out = &scratch;
                draw_panels(fill, fill_img, scratch);
                g_out = &out;
            });
        }
        if (!s.panels.empty()) draw_panels(s, img, out);
    });
}

#undef CALL

}  // namespace RASTER_FLAVOUR
}  // namespace m5cp
