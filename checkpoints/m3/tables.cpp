// Measures, for the lesson: (1) inverse by Gauss-Jordan, by cofactors and by the rigid
// shortcut; (2) drift of composed rotations in double and float, with and without
// re-orthonormalization; (3) a model 1e6 units from the origin in float, double, and
// camera-relative float. Errors come first, the time (machine-dependent) is the last column.
#include "m3/tables.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "harness/checkpoint.h"
#include "m3/scenes.h"
#include "transforms.h"

namespace m3cp {

namespace {

using m3::Mat4;

std::string sci(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1e", v);
    return buf;
}
std::string ms(double seconds, double per) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f", seconds * 1e3 / per);
    return buf;
}

double residual(const Mat4& a, const Mat4& inv) {
    const Mat4 r = a * inv;
    double worst = 0;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) worst = std::max(worst, std::abs(r.m[i][j] - (i == j ? 1 : 0)));
    }
    return worst;
}

// Cofactors: the adjugate over the determinant, each cofactor a 3x3 determinant.
Mat4 cofactor_inverse(const Mat4& a) {
    auto minor = [&](int row, int col) {
        double m[3][3];
        for (int i = 0, r = 0; i < 4; ++i) {
            if (i == row) continue;
            for (int j = 0, c = 0; j < 4; ++j) {
                if (j != col) m[r][c++] = a.m[i][j];
            }
            ++r;
        }
        return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    Mat4 adj;
    double det = 0;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) adj.m[j][i] = ((i + j) % 2 ? -1 : 1) * minor(i, j);
    }
    for (int j = 0; j < 4; ++j) det += a.m[0][j] * adj.m[j][0];
    for (auto& row : adj.m) {
        for (double& v : row) v /= det;
    }
    return adj;
}

std::string inverse_table() {
    const Mat4 rigid = m3::translate({3, -1, 2}) * m3::rotate({1, 2, 3}, 0.9);
    Mat4 stiff;
    const Matrix ns = near_singular_matrix();
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) stiff.m[i][j] = ns[i][j];
    }
    const int n = 10000;
    std::ostringstream out;
    out << "| inverse | residual, rigid transform | residual, condition 1e12 | time per inverse (us) |\n|---|---|---|---|\n";
    Mat4 r1, r2, sink;
    m3::inverse(rigid, r1);
    m3::inverse(stiff, r2);
    double t = cp::time_best_of([&] {
        for (int k = 0; k < n; ++k) m3::inverse(rigid, sink);
    });
    out << "| Gauss-Jordan, partial pivoting | " << sci(residual(rigid, r1)) << " | " << sci(residual(stiff, r2)) << " | "
        << ms(t * 1e3, n) << " |\n";
    t = cp::time_best_of([&] {
        for (int k = 0; k < n; ++k) sink = cofactor_inverse(rigid);
    });
    out << "| cofactors (adjugate / determinant) | " << sci(residual(rigid, cofactor_inverse(rigid))) << " | "
        << sci(residual(stiff, cofactor_inverse(stiff))) << " | " << ms(t * 1e3, n) << " |\n";
    t = cp::time_best_of([&] {
        for (int k = 0; k < n; ++k) sink = m3::rigid_inverse(rigid);
    });
    out << "| rigid shortcut (R^T, -R^T t) | " << sci(residual(rigid, m3::rigid_inverse(rigid))) << " | not rigid | "
        << ms(t * 1e3, n) << " |\n";
    return out.str();
}

template <typename T>
struct M3 {
    T m[3][3];
};
template <typename T>
M3<T> mul(const M3<T>& a, const M3<T>& b) {
    M3<T> r{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            T s = 0;
            for (int k = 0; k < 3; ++k) s += a.m[i][k] * b.m[k][j];
            r.m[i][j] = s;
        }
    }
    return r;
}
// Gram-Schmidt on the rows.
template <typename T>
void orthonormalize(M3<T>& a) {
    for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < i; ++k) {
            T d = 0;
            for (int j = 0; j < 3; ++j) d += a.m[i][j] * a.m[k][j];
            for (int j = 0; j < 3; ++j) a.m[i][j] -= d * a.m[k][j];
        }
        T len = 0;
        for (int j = 0; j < 3; ++j) len += a.m[i][j] * a.m[i][j];
        len = std::sqrt(len);
        for (int j = 0; j < 3; ++j) a.m[i][j] /= len;
    }
}
template <typename T>
double drift(const M3<T>& a) {
    double worst = 0;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double d = 0;
            for (int k = 0; k < 3; ++k) d += double(a.m[i][k]) * double(a.m[j][k]);
            worst = std::max(worst, std::abs(d - (i == j ? 1 : 0)));
        }
    }
    return worst;
}

template <typename T>
std::string drift_row(const std::string& name, int steps, int every) {
    const Mat4 step = m3::rotate({1, 2, 3}, 0.001);
    M3<T> s{}, r{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            s.m[i][j] = static_cast<T>(step.m[i][j]);
            r.m[i][j] = i == j ? 1 : 0;
        }
    }
    M3<T> result{};
    const double t = cp::time_best_of([&] {
        M3<T> a = r;
        for (int k = 1; k <= steps; ++k) {
            a = mul(s, a);
            if (every > 0 && k % every == 0) orthonormalize(a);
        }
        result = a;
    });
    return "| " + name + " | " + std::to_string(steps) + " | " + sci(drift(result)) + " | " + ms(t, 1) + " |\n";
}

std::string drift_table() {
    std::string out = "| composition | rotations | drift max abs(R R^T - I) | time (ms) |\n|---|---|---|---|\n";
    out += drift_row<double>("double", 10000, 0);
    out += drift_row<double>("double", 1000000, 0);
    out += drift_row<float>("float", 10000, 0);
    out += drift_row<float>("float, re-orthonormalized every 100", 10000, 100);
    return out;
}

// The corners of a cube 1e6 units from the origin, seen from 5 units away, in an 800 x 800
// image: the largest distance from the exact pixel positions (long double).
std::string far_table() {
    const Vec3 far{1e6, -2.5e5, 7.5e5};
    const Vec3 eye = far + Vec3{2.3, 1.7, 4.1};
    const Mat4 view = m3::look_at(eye, far, {0, 1, 0});
    const Mat4 proj = m3::perspective(50, 1, 0.5, 100);
    const Mat4 model = m3::translate(far) * m3::rotate({0, 1, 0}, 0.3);
    const Mesh cube = cube_mesh(false);
    const int size = 800;
    auto pixel = [&](auto x, auto y, auto w) { return std::array<long double, 2>{((long double)x / w + 1) / 2 * size, (1 - (long double)y / w) / 2 * size}; };
    std::vector<std::array<long double, 2>> exact;
    const Mat4 pv = proj * view;
    for (Vec3 p : cube.positions) {
        // Exact enough: long double throughout, world space first.
        long double world[4] = {0, 0, 0, 0}, clip[4] = {0, 0, 0, 0};
        const long double in[4] = {p.x, p.y, p.z, 1};
        for (int i = 0; i < 4; ++i) {
            for (int j = 0; j < 4; ++j) world[i] += (long double)model.m[i][j] * in[j];
        }
        for (int i = 0; i < 4; ++i) {
            for (int j = 0; j < 4; ++j) clip[i] += (long double)pv.m[i][j] * world[j];
        }
        exact.push_back(pixel(clip[0], clip[1], clip[3]));
    }
    auto row = [&](const std::string& name, auto project) {
        std::vector<std::array<long double, 2>> got;
        const double t = cp::time_best_of([&] {
            got.clear();
            for (Vec3 p : cube.positions) got.push_back(project(p));
        });
        long double worst = 0;
        for (std::size_t i = 0; i < got.size(); ++i) {
            worst = std::max(worst, std::hypot(got[i][0] - exact[i][0], got[i][1] - exact[i][1]));
        }
        return "| " + name + " | " + sci(double(worst)) + " | " + ms(t * 1e3, double(got.size())) + " |\n";
    };
    // World space first, then view and projection, all in T.
    auto world_first = [&](auto zero) {
        using T = decltype(zero);
        return [&, zero](Vec3 p) {
            (void)zero;
            T world[4] = {}, clip[4] = {};
            const T in[4] = {T(p.x), T(p.y), T(p.z), 1};
            for (int i = 0; i < 4; ++i) {
                for (int j = 0; j < 4; ++j) world[i] += T(model.m[i][j]) * in[j];
            }
            for (int i = 0; i < 4; ++i) {
                for (int j = 0; j < 4; ++j) clip[i] += T(pv.m[i][j]) * world[j];
            }
            return pixel(clip[0], clip[1], clip[3]);
        };
    };
    // Camera-relative: projection * view * model composed once in double (the large
    // translations cancel there), then each vertex in float.
    const Mat4 mvp = proj * view * model;
    auto relative = [&](Vec3 p) {
        float clip[4] = {};
        const float in[4] = {float(p.x), float(p.y), float(p.z), 1};
        for (int i = 0; i < 4; ++i) {
            for (int j = 0; j < 4; ++j) clip[i] += float(mvp.m[i][j]) * in[j];
        }
        return pixel(clip[0], clip[1], clip[3]);
    };
    std::string out = "| vertices to pixels (cube 1e6 from the origin, 800 x 800) | max pixel error | time per vertex (us) |\n|---|---|---|\n";
    out += row("float, world space first", world_first(0.0f));
    out += row("double, world space first", world_first(0.0));
    out += row("float, camera-relative (matrices composed in double)", relative);
    return out;
}

}  // namespace

std::string error_time_tables() { return inverse_table() + "\n" + drift_table() + "\n" + far_table(); }

}  // namespace m3cp
