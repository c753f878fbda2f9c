// Milestone 3's harness: every matrix function, the camera and the projections with ordinary
// and extreme arguments, clipping of huge, degenerate and non-finite polygons and lines, and
// the whole draw_model with vertices at the eye, behind it and far away (see fuzz_input.h).
// It also checks the promises transforms.h makes about such input (look_at never NaN, the
// projections finite or zero, clipping finite for finite input).
#include <cmath>
#include <vector>

#include "fuzz_input.h"
#include "transforms.h"

namespace {

using m3::Mat4;
using raster::Vec3;
using raster::Vec4;

bool finite(const Mat4& m) {
    for (const auto& row : m.m) {
        for (double e : row) {
            if (!std::isfinite(e)) return false;
        }
    }
    return true;
}
bool has_nan(const Mat4& m) {
    for (const auto& row : m.m) {
        for (double e : row) {
            if (std::isnan(e)) return true;
        }
    }
    return false;
}
bool finite(Vec4 p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w); }

// A matrix: one of the building blocks, a camera, a projection, or sixteen raw entries.
Mat4 matrix(fuzz::Input& in) {
    switch (in.byte() % 9) {
        case 0: return m3::identity();
        case 1: return m3::translate(in.vec3());
        case 2: return m3::scale(in.mild3());
        case 3: return std::apply(m3::rotate, std::tuple{in.mild3(), in.mild()});
        case 4: return std::apply(m3::look_at, std::tuple{in.vec3(), in.vec3(), in.mild3()});
        case 5: return std::apply(m3::perspective, fuzz::perspective_args(in));
        case 6: return std::apply(m3::orthographic, fuzz::orthographic_args(in));
        case 7: {
            const Mat4 y = m3::rotate_y(in.mild());
            return y * m3::rotate_x(in.mild());
        }
        default: return fuzz::raw_matrix<Mat4>(in);
    }
}

void draw(fuzz::Input& in) {
    raster::Image img = fuzz::image(in);
    m3::Model model;
    const int n = in.range(0, 9);
    const Vec3 eye = in.vec3();
    model.positions = fuzz::positions(in, n, eye);
    model.triangles = fuzz::triangles(in, n);
    const int edges = in.range(0, 6);
    for (int i = 0; i < edges; ++i) model.edges.push_back({in.range(-1, n), in.range(-1, n)});
    const int colors = in.range(0, static_cast<int>(model.triangles.size()));
    for (int i = 0; i < colors; ++i) model.face_colors.push_back(in.color());
    const Mat4 model_matrix = in.flag() ? m3::identity() : matrix(in);
    const Mat4 view = in.flag() ? m3::look_at(eye, in.vec3(), {0, 1, 0}) : matrix(in);  // one read each
    const Mat4 projection = in.flag() ? m3::perspective(60, 1, 0.1, 100) : matrix(in);
    m3::Needs needs;
    const std::uint8_t f = in.byte();
    needs.fill = f & 1;
    needs.wireframe = f & 2;
    needs.cull = f & 4;
    needs.clip = true;  // draw_model may skip clipping only for a scene entirely inside
    needs.painter = f & 16;
    (void)m3::draw_model(img, model, model_matrix, view, projection, needs, in.color());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::Input in(data, size);
    fuzz::Guard guard;
    switch (in.byte() % 8) {
        case 0: {
            const Mat4 a = matrix(in), b = matrix(in);
            (void)(a * b);
            (void)(a * in.vec4());
            (void)m3::transpose(a);
            (void)m3::transform_point(a, in.vec3());
            (void)m3::transform_direction(a, in.vec3());
            (void)m3::rigid_inverse(a);
            Mat4 inv;
            if (m3::inverse(a, inv) && (!finite(a) || has_nan(inv))) fuzz::broken("m3::inverse returned true with NaN",
                             "TODO 3a (transforms.h): false for a matrix with an entry that is NaN or infinite, "
                             "and for one whose inverse is not finite (check the result before writing out)");
            break;
        }
        case 1: {
            const Vec3 eye = in.vec3(), target = in.flag() ? eye + in.vec3() * 1e-160 : in.vec3(), up = in.vec3();
            const Mat4 v = m3::look_at(eye, target, up);
            if (has_nan(v)) fuzz::broken("m3::look_at returned NaN",
                                  "TODO 4 (transforms.h, fallbacks): a non-finite eye gives the zero matrix, "
                                  "eye == target gives f = (0, 0, -1), and an up that is zero, not finite or "
                                  "parallel to f is replaced by a world axis");
            if (raster::is_finite(eye)) {
                // The rotation rows have length 1 (the fallbacks included).
                for (int r = 0; r < 3; ++r) {
                    const double len = std::sqrt(v.m[r][0] * v.m[r][0] + v.m[r][1] * v.m[r][1] + v.m[r][2] * v.m[r][2]);
                    if (!(std::abs(len - 1) < 1e-6)) fuzz::broken("m3::look_at: a row of the rotation is not a unit vector",
                                     "TODO 4 (transforms.h, fallbacks): a vector whose length overflows or whose "
                                     "square underflows is scaled by a power of two before it is normalized, so "
                                     "no direction is lost (the reference's unit() does it)");
                }
            }
            break;
        }
        case 2: {
            if (!finite(std::apply(m3::perspective, fuzz::perspective_args(in))))
                fuzz::broken("m3::perspective holds an entry that is not finite",
                             "TODO 5 (transforms.h): invalid arguments, and arguments that would put an infinite "
                             "entry in the matrix, give the zero matrix");
            if (!finite(std::apply(m3::orthographic, fuzz::orthographic_args(in))))
                fuzz::broken("m3::orthographic holds an entry that is not finite",
                             "TODO 5 (transforms.h): invalid arguments, and arguments that would put an infinite "
                             "entry in the matrix (a tiny range), give the zero matrix");
            (void)std::apply(m3::rotate, std::tuple{in.vec3(), in.real()});
            (void)m3::rotate_x(in.real());
            (void)m3::rotate_z(in.real());
            break;
        }
        case 3: {
            std::vector<Vec4> poly(in.range(0, 6));
            bool all_finite = true;
            for (Vec4& p : poly) {
                p = in.vec4();
                all_finite &= finite(p);
            }
            for (const Vec4& p : m3::clip_polygon(poly)) {
                if (all_finite && !finite(p)) fuzz::broken("m3::clip_polygon made a non-finite vertex of finite ones",
                                                   "TODO 7a (lesson 3, clipping): interpolate a crossing from "
                                                   "the inside end, with t = d_in / (d_in - d_out), so that "
                                                   "coordinates near 1e308 never overflow");
            }
            Vec4 a = in.vec4(), b = in.vec4();
            const bool ends_finite = finite(a) && finite(b);
            if (m3::clip_line(a, b) && ends_finite && !(finite(a) && finite(b)))
                fuzz::broken("m3::clip_line made a non-finite end of finite ones",
                             "TODO 7b (lesson 3, clipping): compute the new ends from the inside end, as in "
                             "clip_polygon, so that coordinates near 1e308 never overflow");
            break;
        }
        case 4: {
            const auto [c, width, height] = std::tuple{in.vec4(), in.range(1, 4096), in.range(1, 4096)};
            if (c.w > 0) (void)m3::to_screen(c, width, height);  // only called with w > 0
            (void)std::apply(m3::is_back_facing, std::tuple{in.vec3(), in.vec3(), in.vec3()});
            (void)std::apply(m3::bezier, std::tuple{in.vec3(), in.vec3(), in.vec3(), in.vec3(), in.real()});
            std::vector<std::array<Vec3, 3>> tris(in.range(0, 6));
            for (auto& t : tris) t = {in.vec3(), in.vec3(), in.vec3()};
            const std::vector<int> order = m3::painter_order(tris);
            std::vector<bool> seen(tris.size());
            // A NaN mean makes a < b no strict weak order: std::sort may then run past the vector
            // or repeat elements.
            const char* hint =
                "TODO 10 (transforms.h): a permutation of 0 .. n-1, whatever the coordinates; a NaN mean z "
                "needs a place of its own in the order (the reference sorts it as the farthest)";
            if (order.size() != tris.size()) fuzz::broken("m3::painter_order is not a permutation", hint);
            for (int i : order) {
                if (i < 0 || i >= static_cast<int>(tris.size()) || seen[i])
                    fuzz::broken("m3::painter_order is not a permutation", hint);
                seen[i] = true;
            }
            break;
        }
        default: draw(in);
    }
    return 0;
}
