// Judge half of the milestone-3 checkpoints (trusted: it runs no code under test).
//
// The oracle is the reference solution (compiled into this library with the reference
// flavour) plus hand-worked values for the conventions a bug typically breaks: the judge
// compares every number the render half recorded with the reference's, within a relative
// 1e-9, compares clipped polygons as sets of vertices (the order of the clip planes is free),
// and then tells apart the usual mistakes (storage order, multiplication order, degrees,
// missing divide, unflipped y, left-handed camera, near plane, clipping after the divide...).
#include "m3/judge.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <set>
#include <sstream>
#include <tuple>

#include "harness/diagnosis.h"
#include "m3/render.h"
#include "m3/scenes.h"
#include "raster/io.h"

namespace m3cp {

namespace {

using Values = std::map<std::string, double>;

std::string num(double v) {
    if (std::abs(v) < 1e-12) v = 0;  // rounding noise (and -0) printed as 0
    std::ostringstream s;
    s.precision(10);
    s << v;
    return s.str();
}

bool close(double a, double b, double rel = 1e-9) {
    if (std::isnan(a) || std::isnan(b)) return false;
    return std::abs(a - b) <= rel * std::max(1.0, std::abs(b));
}

double get(const Values& v, const std::string& key) {
    const auto it = v.find(key);
    return it == v.end() ? std::nan("") : it->second;
}

// Entries of a 4x4 matrix stored under `key`.
Matrix mat(const Values& v, const std::string& key) {
    Matrix m{};
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) m[i][j] = get(v, key + "." + std::to_string(i) + std::to_string(j));
    }
    return m;
}

Matrix mul(const Matrix& a, const Matrix& b) {
    Matrix r{};
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            for (int k = 0; k < 4; ++k) r[i][j] += a[i][k] * b[k][j];
        }
    }
    return r;
}

bool same(const Matrix& a, const Matrix& b, double rel = 1e-9) {
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            if (!close(a[i][j], b[i][j], rel)) return false;
        }
    }
    return true;
}

std::string str(const Matrix& m) {
    std::string s = "[";
    for (int i = 0; i < 4; ++i) {
        s += i ? "; " : "";
        for (int j = 0; j < 4; ++j) s += (j ? " " : "") + num(m[i][j]);
    }
    return s + "]";
}

Vec3 vec3(const Values& v, const std::string& key) { return {get(v, key + ".x"), get(v, key + ".y"), get(v, key + ".z")}; }
Vec4 vec4(const Values& v, const std::string& key) {
    return {get(v, key + ".x"), get(v, key + ".y"), get(v, key + ".z"), get(v, key + ".w")};
}
bool same3(Vec3 a, Vec3 b, double rel = 1e-9) { return close(a.x, b.x, rel) && close(a.y, b.y, rel) && close(a.z, b.z, rel); }
std::string str(Vec3 p) { return "(" + num(p.x) + ", " + num(p.y) + ", " + num(p.z) + ")"; }
std::string str(Vec4 p) { return "(" + num(p.x) + ", " + num(p.y) + ", " + num(p.z) + ", " + num(p.w) + ")"; }

// A polygon stored under `key`; repeated consecutive vertices are merged.
std::vector<Vec4> polygon(const Values& v, const std::string& key) {
    std::vector<Vec4> out;
    const double n = get(v, key + ".n");
    if (!(n >= 0 && n <= 32)) return out;
    for (int i = 0; i < int(n); ++i) out.push_back(vec4(v, key + "." + std::to_string(i)));
    return out;
}

bool same4(Vec4 a, Vec4 b, double scale) {
    const double tol = 1e-9 * std::max(1.0, scale);
    return std::abs(a.x - b.x) <= tol && std::abs(a.y - b.y) <= tol && std::abs(a.z - b.z) <= tol &&
           std::abs(a.w - b.w) <= tol;
}

double scale_of(const std::vector<Vec4>& p) {
    double s = 0;
    for (Vec4 q : p) s = std::max({s, std::abs(q.x), std::abs(q.y), std::abs(q.z), std::abs(q.w)});
    return s;
}

// Same vertex set (each vertex of one within tolerance of a vertex of the other), and the
// same orientation on screen when the polygon has area.
bool same_polygon(const std::vector<Vec4>& mine, const std::vector<Vec4>& ref) {
    if (mine.size() < 3 || ref.size() < 3) return mine.size() < 3 && ref.size() < 3;
    const double s = std::max(scale_of(mine), scale_of(ref));
    auto covered = [s](const std::vector<Vec4>& a, const std::vector<Vec4>& b) {
        for (Vec4 p : a) {
            if (std::none_of(b.begin(), b.end(), [&](Vec4 q) { return same4(p, q, s); })) return false;
        }
        return true;
    };
    if (!covered(mine, ref) || !covered(ref, mine)) return false;
    auto area = [](const std::vector<Vec4>& p) {
        double a = 0;
        for (std::size_t i = 0; i < p.size(); ++i) {
            const Vec4 u = p[i], w = p[(i + 1) % p.size()];
            a += u.x / u.w * (w.y / w.w) - w.x / w.w * (u.y / u.w);
        }
        return a;
    };
    const double am = area(mine), ar = area(ref);
    return std::abs(ar) < 1e-6 || (am > 0) == (ar > 0);
}

// A vertex outside the near plane (z < -w), allowing for rounding.
bool beyond_near(const std::vector<Vec4>& p) {
    const double tol = 1e-9 * std::max(1.0, scale_of(p));
    return std::any_of(p.begin(), p.end(), [tol](Vec4 q) { return q.z + q.w < -tol || q.w <= 0; });
}
// The signed distances of q to the six planes, in the order x >= -w, x <= w, y >= -w, y <= w,
// z >= -w, z <= w (inside: all >= 0).
std::array<double, 6> plane_distances(Vec4 q) {
    return {q.w + q.x, q.w - q.x, q.w + q.y, q.w - q.y, q.w + q.z, q.w - q.z};
}
bool all_finite(const std::vector<Vec4>& p) {
    return std::all_of(p.begin(), p.end(), [](Vec4 q) {
        return std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z) && std::isfinite(q.w);
    });
}
bool beyond_any(const std::vector<Vec4>& p) {
    const double tol = 1e-9 * std::max(1.0, scale_of(p));
    return std::any_of(p.begin(), p.end(), [tol](Vec4 q) {
        const auto d = plane_distances(q);
        return !std::all_of(d.begin(), d.end(), [tol](double x) { return x >= -tol; });
    });
}

// Sutherland-Hodgman as a clipper that gets one rule wrong would run it: `dist(q, plane)` is
// the signed distance it uses (>= 0 inside), and with `keep_outside` each plane keeps the
// vertices OUTSIDE it (da < 0) while still adding the crossings.
std::vector<Vec4> clip_as(std::vector<Vec4> poly, const std::function<double(Vec4, int)>& dist, bool keep_outside) {
    for (int plane = 0; plane < 6 && !poly.empty(); ++plane) {
        std::vector<Vec4> next;
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const Vec4 a = poly[i], b = poly[(i + 1) % poly.size()];
            const double da = dist(a, plane), db = dist(b, plane);
            if ((da >= 0) != keep_outside) next.push_back(a);
            if ((da >= 0) != (db >= 0)) next.push_back(a + (b - a) * (da / (da - db)));
        }
        poly = next;
    }
    if (poly.size() < 3) poly.clear();
    return poly;
}
double plane_distance(Vec4 q, int plane) { return plane_distances(q)[std::size_t(plane)]; }

// The keep test turned round: a clip_polygon whose every answer matches this one has it reversed.
std::vector<Vec4> clip_keeping_outside(std::vector<Vec4> poly) { return clip_as(std::move(poly), plane_distance, true); }

// The near plane at z >= 0 (Direct3D's depth range [0, 1]) in place of z >= -w: what a clipper
// written for the other clip-space convention returns.
std::vector<Vec4> clip_near_at_zero(std::vector<Vec4> poly) {
    return clip_as(std::move(poly), [](Vec4 q, int plane) { return plane == 4 ? q.z : plane_distance(q, plane); }, false);
}

// "(x, y, z, w) lies on the plane x = w" for the first vertex of `tri` inside the closed view
// volume and exactly on one of its planes (d = 0); empty when there is none.
std::string on_a_plane(const std::array<Vec4, 3>& tri) {
    static const char* kNames[6] = {"x = -w", "x = w", "y = -w", "y = w", "z = -w", "z = w"};
    for (const Vec4& q : tri) {
        const auto d = plane_distances(q);
        if (!std::all_of(d.begin(), d.end(), [](double x) { return x >= 0; })) continue;
        for (int k = 0; k < 6; ++k) {
            if (d[k] == 0) {
                return "(" + num(q.x) + ", " + num(q.y) + ", " + num(q.z) + ", " + num(q.w) + ") lies on the plane " +
                       kNames[k];
            }
        }
    }
    return "";
}

struct Ctx {
    const Scene& s;
    const Values& mine;
    const Values& ref;
    cp::Judgement& j;
    const raster::Image& expected;  // may be empty (the harness reports that)
    // A message that starts with "TODO 4: " or "TODO 5, 6: " carries its TODO: it goes into
    // Finding::todo, which the harness prints as "(TODO 4)".
    // A hint of its own (shown instead of the scene's) is set only when the finding is new.
    void add(const std::string& topic, const std::string& msg, const std::string& hint = "") {
        std::string todo, text = msg;
        const auto colon = msg.find(": ");
        if (msg.rfind("TODO ", 0) == 0 && colon != std::string::npos && colon < 16) {
            todo = msg.substr(0, colon);
            if (todo.find(',') != std::string::npos) todo = "TODOs" + todo.substr(4);
            text = msg.substr(colon + 2);
        }
        for (const cp::Finding& f : j.findings) {
            if (f.topic == topic && f.message == text) return;
        }
        j.findings.push_back({topic, text, hint, todo});
    }
    // Compares matrix `key` with the reference's; returns false (and adds a finding) if off.
    bool matrix(const std::string& key, const std::string& topic, const std::string& what) {
        const Matrix a = mat(mine, key), b = mat(ref, key);
        if (same(a, b)) return true;
        add(topic, what + ": got " + str(a) + ", expected " + str(b));
        return false;
    }
    bool point(const std::string& key, const std::string& topic, const std::string& what) {
        const Vec3 a = vec3(mine, key), b = vec3(ref, key);
        if (same3(a, b)) return true;
        add(topic, what + ": got " + str(a) + ", expected " + str(b));
        return false;
    }
};

Matrix transpose(const Matrix& a) {
    Matrix t{};
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) t[i][j] = a[j][i];
    }
    return t;
}

bool has_nan(const Matrix& m) {
    for (const auto& row : m) {
        for (double x : row) {
            if (std::isnan(x)) return true;
        }
    }
    return false;
}

bool is_zero(const Matrix& m) {
    for (const auto& row : m) {
        for (double x : row) {
            if (x != 0) return false;
        }
    }
    return true;
}

Matrix identity_matrix() {
    Matrix m{};
    for (int i = 0; i < 4; ++i) m[i][i] = 1;
    return m;
}

// " (it holds NaN)", " (it holds infinity)" or nothing: said after a matrix a student returned.
std::string nonfinite_note(const Matrix& m) {
    bool inf = false;
    for (const auto& row : m) {
        for (double x : row) inf |= std::isinf(x);
    }
    return has_nan(m) ? " (it holds NaN)" : inf ? " (it holds infinity)" : "";
}

// m3.nonfinite: each input is extreme, and the answer is the one transforms.h pins for it
// (where it pins several, any of them passes). Ordinary answers come from the reference.
// draw_model culled more triangles than the reference: it may cull before it clips.
bool culls_first(const Ctx& c) {
    return get(c.mine, "stats.triangles_culled") > get(c.ref, "stats.triangles_culled");
}

void judge_nonfinite(Ctx& c) {
    const Values& v = c.mine;
    // TODO 2b: a non-finite axis gives the identity.
    const std::pair<const char*, const char*> rotations[] = {{"rot.nan", "rotate((nan, 0, 1), 0.7)"},
                                                             {"rot.inf", "rotate((inf, 1, 0), 0.7)"}};
    for (const auto& [key, call] : rotations) {
        const Matrix a = mat(v, key);
        if (same(a, identity_matrix())) continue;
        c.add("rotation",
              std::string("TODO 2b: ") + call + " gave " + str(a) + nonfinite_note(a) +
                  ", expected the identity: transforms.h pins that a non-finite axis, like the zero "
                  "axis, gives the identity. A NaN is neither 0 nor anything else (every comparison with "
                  "it is false), so a test such as len == 0 lets it through; test std::isfinite(len) too "
                  "before dividing by the length",
              "rotate: return the identity when the axis's length is zero or not finite "
              "(std::isfinite), before dividing by it");
    }
    // TODO 2b: a tiny or huge axis is still a direction: its rotation, as the reference's.
    const std::pair<const char*, const char*> scaled_axes[] = {{"rot.tiny", "rotate((1e-200, 0, 2e-200), 0.7)"},
                                                               {"rot.huge", "rotate((1e200, -2e200, 0), 0.7)"}};
    for (const auto& [key, call] : scaled_axes) {
        const Matrix a = mat(v, key), b = mat(c.ref, key);
        if (same(a, b)) continue;
        c.add("rotation",
              std::string("TODO 2b: ") + call + " gave " + str(a) + nonfinite_note(a) + ", expected " + str(b) +
                  ": that axis is finite and not zero, so it names a direction, but its "
                  "squared length " +
                  (std::string(key) == "rot.tiny" ? "underflows to 0" : "overflows to infinity") +
                  ". transforms.h pins that normalizing never loses a direction: scale the axis by a power of "
                  "two first (std::ldexp by -std::ilogb of its largest component), as look_at does",
              "rotate: normalize the axis as look_at does, with power-of-two scaling when its "
              "length underflows or overflows");
    }
    // TODO 3a: false, with `out` left alone, for a non-finite entry or a result too large.
    static const std::map<std::string, std::string> inverses = {
        {"inv.nan", "a matrix with a NaN entry (m[1][2])"},
        {"inv.inf", "a perspective-like matrix with an infinite entry (m[2][2] = -inf)"},
        {"inv.tiny", "[2e-320 1e-320 0 0; 1e-320 3e-320 0 1e-320; 0 0 1e-320 0; 0 1e-320 0 2e-320], whose inverse "
                     "would have entries near 1e320, too large for a double"},
    };
    for (const auto& [key, what] : inverses) {
        const double ok = get(v, key + ".ok");
        const Matrix out = mat(v, key);
        bool untouched = true;
        for (const auto& row : out) {
            for (double x : row) untouched &= x == -7;
        }
        if (ok != 0) {
            c.add("inverse",
                  "TODO 3a: inverse() returned true for " + what + ", with " + str(out) + nonfinite_note(out) +
                      ". transforms.h pins false here: a matrix with an entry that is NaN or infinite has "
                      "no inverse, and neither has one whose inverse would not be finite. Check the entries "
                      "with std::isfinite first, and check every entry of the result before writing `out`",
                  "inverse(): false for a non-finite entry, and false when an entry of the "
                  "result is not finite (test it before writing out)");
        } else if (!untouched) {
            c.add("inverse", "TODO 3a: inverse() returned false for " + what + ", as it must, but changed `out` to " +
                                 str(out) + ": transforms.h pins that false leaves `out` alone (the caller may keep "
                                 "the matrix it had). Work in a copy and write `out` only when you return true");
        }
    }
    // TODO 4: look_at.
    struct LookAt {
        const char* key;
        const char* call;
        const char* rule;
    };
    static const LookAt look_ats[] = {
        {"la.nan_eye", "look_at((nan, 1, 2), (0, 0, 0), (0, 1, 0))", "an eye that is not finite gives the zero matrix"},
        {"la.inf_eye", "look_at((0, -inf, 0), (0, 0, 0), (0, 1, 0))", "an eye that is not finite gives the zero matrix"},
        {"la.nan_target", "look_at((1, 2, 3), (nan, 0, 0), (0, 1, 0))",
         "a target - eye that is not finite gives f = (0, 0, -1), and r and u follow from it as usual"},
        {"la.inf_target", "look_at((1, 2, 3), (inf, 0, 0), (0.3, 1, 0))",
         "a target - eye that is not finite gives f = (0, 0, -1) (not +x), and r and u follow from it as usual"},
        {"la.huge", "look_at((0, 0, 0), (1e308, -1e308, 5e307), (0, 1, 0))",
         "the length of target - eye overflows (its square is infinite), so scale the vector by a power of two "
         "(std::ldexp by minus std::ilogb of its largest |component|) before normalizing: f still has length 1"},
        {"la.tiny", "look_at((1e-310, 0, 0), (0, 3e-310, -2e-310), (0, 1, 0))",
         "the square of target - eye underflows to 0 (its components are subnormal), so scale the vector by a "
         "power of two before normalizing: f still has length 1 and points from eye to target"},
        {"la.huge_up", "look_at((1, 2, 3), (0, 0, 0), (0, 1e308, 1e308))",
         "up's length overflows: scale it by a power of two before normalizing, as for target - eye"},
        {"la.tiny_up", "look_at((1, 2, 3), (0, 0, 0), (1e-170, 1e-170, 0))",
         "the square of up's length underflows to 0 (1e-340), but up is not zero: scale it by a power of two "
         "before normalizing, and it still gives the direction (1, 1, 0); the world-axis fallback is for an up "
         "that is zero or parallel to f"},
    };
    static const char* kLookAtHint = "look_at: the zero matrix when eye is not finite; f = (0, 0, -1) when target - eye "
                                     "is not finite; a vector too long or too short to normalize is first scaled by a "
                                     "power of two (std::ldexp); never NaN";
    for (const LookAt& l : look_ats) {
        const Matrix a = mat(v, l.key), b = mat(c.ref, l.key);
        if (same(a, b)) continue;
        c.add("look at fallback",
              std::string("TODO 4: ") + l.call + " gave " + str(a) + nonfinite_note(a) + ", expected " + str(b) +
                  ": transforms.h pins that " + l.rule,
              kLookAtHint);
    }
    {
        // An eye beyond 1e308: the rows must be right; the last column may overflow to
        // +/-infinity (transforms.h), so there an infinite entry passes, but never NaN.
        const Matrix a = mat(v, "la.huge_eye"), b = mat(c.ref, "la.huge_eye");
        bool ok = !has_nan(a);
        for (int i = 0; i < 4 && ok; ++i) {
            for (int j = 0; j < 4; ++j) {
                ok &= close(a[i][j], b[i][j]) || (j == 3 && i < 3 && (std::isinf(a[i][j]) || std::isinf(b[i][j])) &&
                                                  std::abs(a[i][j]) > 1e306 && std::abs(b[i][j]) > 1e306 &&
                                                  (a[i][j] > 0) == (b[i][j] > 0));
            }
        }
        if (!ok) {
            c.add("look at fallback",
                  "TODO 4: look_at((1.7e308, -1.2e308, 9e307), that eye + (-1e307, 5e306, -3e306), (0, 1, 0)) gave " +
                      str(a) + nonfinite_note(a) + ", expected " + str(b) +
                      " (in the last column, an infinity of the expected sign passes too): transforms.h pins that "
                      "the rows r, u, -f are right and the last column may overflow to +/-infinity, but nothing is "
                      "NaN. The direction target - eye is an ordinary 1e307-sized vector here; normalize it with the "
                      "power-of-two scaling",
                  kLookAtHint);
        }
    }
    {
        const Matrix a = mat(v, "la.nan_up"), b = mat(c.ref, "la.nan_up");
        if (!same(a, b)) {
            c.add("look at fallback",
                  "TODO 4: look_at((1, 2, 3), (0, 0, 0), (0, nan, 1)) gave " + str(a) + nonfinite_note(a) +
                      ", expected " + str(b) +
                      ": transforms.h pins that an up that is not finite is replaced like a zero "
                      "up, by the world axis along which |f| has its smallest component",
                  kLookAtHint);
        }
    }
    // TODO 5: the projections.
    static const std::pair<const char*, const char*> zero[] = {
        {"p.nan_fov", "perspective(nan, 1, 0.1, 10): an argument that is not finite"},
        {"p.inf_far", "perspective(60, 1, 0.1, inf): an argument that is not finite"},
        {"p.max_far", "perspective(60, 1, 1, DBL_MAX): 2 * far * near overflows to infinity (computed in "
                      "another order, 2 * near * (far / (near - far)) = -2 is finite: that matrix passes too)"},
        {"p.tiny_aspect", "perspective(60, 1e-320, 0.1, 10): f / aspect overflows to infinity"},
        {"o.nan", "orthographic(nan, 1, -1, 1, 0.1, 10): an argument that is not finite"},
        {"o.inf", "orthographic(-1, 1, -inf, 1, 0.1, 10): an argument that is not finite"},
        {"o.tiny_range", "orthographic(-1, 1, -1, 1, 1e-309, 0): 2 / (far - near) overflows to infinity"},
    };
    // far = DBL_MAX: the entry 2 far near / (near - far) is about -2, finite, though 2 * far *
    // near overflows on the way; transforms.h accepts the zero matrix or the finite one.
    const auto finite_max_far = [](const Matrix& a) {
        const double f = 1 / std::tan(std::acos(-1.0) / 6);
        const Matrix want{{{f, 0, 0, 0}, {0, f, 0, 0}, {0, 0, -1, -2}, {0, 0, -1, 0}}};
        for (int i = 0; i < 4; ++i) {
            for (int j = 0; j < 4; ++j) {
                if (!close(a[i][j], want[i][j])) return false;
            }
        }
        return true;
    };
    for (const auto& [key, what] : zero) {
        const Matrix a = mat(v, key);
        if (is_zero(a)) continue;
        if (std::string(key) == "p.max_far" && finite_max_far(a)) continue;
        c.add("projection",
              std::string("TODO 5: ") + what + "; it gave " + str(a) + nonfinite_note(a) +
                  ", expected the zero matrix, which transforms.h pins for invalid arguments and for "
                  "arguments that would put an infinite entry in the matrix. Check every argument with "
                  "std::isfinite, and every entry you computed, before returning",
              "projections: the zero matrix for an argument that is not finite, and for an entry "
              "that overflows to infinity (check each entry with std::isfinite)");
    }
    static const std::pair<const char*, const char*> valid[] = {
        {"p.huge_far", "perspective(60, 1.5, 0.1, 1e300)"},
        {"p.subnormal_near", "perspective(60, 1.5, 5e-324, 1) (near is the smallest positive double, still valid)"},
        {"o.huge", "orthographic(-1e300, 1e300, -1e300, 1e300, 1, 1e300)"},
    };
    for (const auto& [key, what] : valid) {
        const Matrix a = mat(v, key);
        // Both perspectives have fovy = 60: 60 "degrees" taken as radians gives f = 1 / tan(30).
        if (key[0] == 'p' && !same(a, mat(c.ref, key)) && close(a[1][1], 1 / std::tan(30.0))) {
            c.add("degrees", std::string("TODO 5: ") + what + " has f = " + num(a[1][1]) +
                                 ", which is 1 / tan(30 radians). fovy is in DEGREES: convert with * pi / 180");
            continue;
        }
        c.matrix(key, "projection", std::string("TODO 5: ") + what + ", valid arguments with a finite matrix");
    }
    // TODO 11: indices outside positions.
    {
        const double filled = get(v, "dm.bad_index.filled"), lines = get(v, "dm.bad_index.lines");
        const double rfilled = get(c.ref, "dm.bad_index.filled"), rlines = get(c.ref, "dm.bad_index.lines");
        if (filled != rfilled || lines != rlines) {
            c.add("bad input",
                  "TODO 11: draw_model of a model with 3 positions whose triangles are (0, 1, 2), (-1, 0, 1), "
                  "(0, 1, 3) and whose edges are (0, 1), (-1, 2), (1, 3) filled " +
                      num(filled) + " triangles and drew " + num(lines) + " lines, expected " + num(rfilled) + " and " +
                      num(rlines) +
                      ": transforms.h pins that a triangle or edge with an index outside "
                      "[0, positions.size()) is skipped. Reading positions[-1] is undefined behaviour: it may "
                      "crash, or draw from whatever memory lies there",
                  "draw_model: check every index of a triangle or edge against "
                  "positions.size() before using it, and skip the ones out of range");
        }
    }
    // TODO 7: coordinates near 1e308: finite ends, the reference's points.
    static const char* kHugeClipHint = "clipping near 1e308: when some |coordinate| exceeds 2^500, scale every vertex by "
                                       "2^-ilogb(largest) with std::ldexp, clip, and scale the result back";
    const auto cases = nonfinite_clip_cases();
    const auto& tri = cases.first;
    {
        const auto a = polygon(v, "c.poly"), b = polygon(c.ref, "c.poly");
        const bool finite = all_finite(a);
        if (!finite || !same_polygon(a, b)) {
            std::string pts, rpts;
            for (const Vec4& p : a) pts += (pts.empty() ? "" : " ") + str(p);
            for (const Vec4& p : b) rpts += (rpts.empty() ? "" : " ") + str(p);
            c.add("clipping",
                  "TODO 7a: clip_polygon of the triangle " + str(tri[0]) + " " + str(tri[1]) + " " + str(tri[2]) +
                      " gave " + std::to_string(a.size()) + " vertices (" + pts + "), expected " +
                      std::to_string(b.size()) + " (" + rpts + ")" +
                      (finite ? "" : ", and some of yours are not finite") +
                      ". A plane distance such as w + x overflows to infinity here, and a crossing "
                      "inf / inf is NaN. transforms.h pins the remedy: when some |coordinate| exceeds "
                      "2^500, scale every vertex by the same power of two (std::ldexp), clip, and scale "
                      "the result back: finite input gives finite output",
                  kHugeClipHint);
        }
    }
    {
        const std::array<Vec4, 3> edge = inside_end_clip_case();
        const auto a = polygon(v, "c.inside_end"), b = polygon(c.ref, "c.inside_end");
        const bool finite = all_finite(a);
        if (!finite || !same_polygon(a, b)) {
            std::string pts;
            for (const Vec4& p : a) pts += (pts.empty() ? "" : " ") + str(p);
            c.add("clipping",
                  "TODO 7a: clip_polygon of the triangle " + str(edge[0]) + " " + str(edge[1]) + " " + str(edge[2]) +
                      " gave " + std::to_string(a.size()) + " vertices (" + pts + ")" +
                      (finite ? ", not the reference's" : ", some of them not finite") +
                      ". Only the first vertex is outside (x > w), and the edge from it enters the plane "
                      "x = w exactly at the second, whose w is the largest double. Interpolated from the "
                      "outside end, o + (i - o) * 1 rounds w past it and overflows to infinity; "
                      "transforms.h pins the crossing from the inside end, a + (b - a) * da / (da - db) "
                      "with da >= 0 > db, which gives that vertex exactly",
                  "clip_polygon: interpolate each crossing from the edge's inside end (for an "
                  "edge that enters, b + (a - b) * db / (db - da))");
        }
    }
    {
        const auto& seg = cases.second;
        const double ok = get(v, "c.line.ok"), rok = get(c.ref, "c.line.ok");
        const Vec4 a = vec4(v, "c.line.a"), b = vec4(v, "c.line.b");
        const Vec4 ra = vec4(c.ref, "c.line.a"), rb = vec4(c.ref, "c.line.b");
        const double sc = scale_of({ra, rb});
        if (ok != rok || (rok == 1 && !(same4(a, ra, sc) && same4(b, rb, sc)))) {
            c.add("clipping",
                  "TODO 7b: clip_line of " + str(seg[0]) + " - " + str(seg[1]) + " gave " +
                      (ok == 1 ? str(a) + " - " + str(b) : std::string("nothing")) + ", expected " +
                      (rok == 1 ? str(ra) + " - " + str(rb) : std::string("nothing")) +
                      ". w + x overflows to infinity at the right end; as in clip_polygon, scale both ends "
                      "by a power of two when some |coordinate| exceeds 2^500 (transforms.h): finite ends "
                      "give finite ends",
                  kHugeClipHint);
        }
    }
    {
        // inside_end_clip_case()'s first edge as a segment: a is outside x <= w only, and the
        // segment enters that plane exactly at b, whose w is the largest double.
        const std::array<Vec4, 3> edge = inside_end_clip_case();
        const double ok = get(v, "c.inside_end_line.ok"), rok = get(c.ref, "c.inside_end_line.ok");
        const Vec4 a = vec4(v, "c.inside_end_line.a"), b = vec4(v, "c.inside_end_line.b");
        const Vec4 ra = vec4(c.ref, "c.inside_end_line.a"), rb = vec4(c.ref, "c.inside_end_line.b");
        const double sc = scale_of({ra, rb});
        if (ok != rok || (rok == 1 && !(same4(a, ra, sc) && same4(b, rb, sc)))) {
            const bool finite = all_finite({a, b});
            c.add("clipping",
                  "TODO 7b: clip_line of " + str(edge[0]) + " - " + str(edge[1]) + " gave " +
                      (ok == 1 ? str(a) + " - " + str(b) : std::string("nothing")) + ", expected " +
                      (rok == 1 ? str(ra) + " - " + str(rb) : std::string("nothing")) +
                      (ok == 1 && !finite ? ": an end is not finite" : "") +
                      ". Only a is outside (x > w), and the segment enters the plane x = w exactly at b, "
                      "whose w is the largest double, so the new a is b itself. Computed from the outside "
                      "end, a + (b - a) * 1 can round one step past b, and scaled back that step overflows "
                      "to infinity. transforms.h pins finite ends for finite ends: compute a moved end from "
                      "the inside end (b + (a - b) * (1 - t0)), or keep each of its coordinates between "
                      "the ends' before scaling back",
                  "clip_line: a moved end computed from the other end can round past it near 1e308; "
                  "compute it from the inside end, or clamp it between the ends");
        }
    }
}

void judge_group(Group g, Ctx& c) {
    const Values& v = c.mine;
    switch (g) {
        case Group::kMatrixOps: {
            const Matrix a{{{1, 2, 0, 4}, {0, 1, 3, 0}, {2, 0, 1, -1}, {0, 0, 0, 1}}};
            const Matrix b{{{0, 1, 0, 2}, {1, 0, 0, 0}, {0, 0, 2, 1}, {0, 0, 0, 1}}};
            const Matrix ab = mat(v, "ab");
            if (!same(ab, mul(a, b))) {
                if (same(ab, mul(b, a))) {
                    c.add("multiplication order", "TODO 1: your A * B equals B * A. Entry (i, j) of A * B is row i of A "
                                                  "times column j of B");
                } else {
                    // One factor (or the product) read with rows and columns exchanged: m[col][row].
                    std::string which;
                    if (same(ab, mul(transpose(a), b))) which = "A^T * B: A is read as a[k][i] where a[i][k] is meant";
                    else if (same(ab, mul(a, transpose(b)))) which = "A * B^T: B is read as b[j][k] where b[k][j] is meant";
                    else if (same(ab, transpose(mul(a, b)))) which = "(A * B)^T: the result is stored as r[j][i]";
                    c.add("matrix", "TODO 1: A * B is wrong: got " + str(ab) + ", expected " + str(mul(a, b)) +
                                        (which.empty() ? std::string()
                                                       : "; yours equals " + which +
                                                             ". Entry (i, j) of A * B = sum over k of a[i][k] * b[k][j]: "
                                                             "row i of A times column j of B, with Mat4 stored m[row][col]"));
                }
            }
            if (!same(mat(v, "at"), transpose(a))) c.add("matrix", "TODO 1: transpose(A) is wrong: got " + str(mat(v, "at")));
            // A * (1, 2, 3, 1) = (9, 11, 4, 1); with rows and columns exchanged: (7, 4, 9, 2).
            const Vec4 av = vec4(v, "av");
            if (!(close(av.x, 9) && close(av.y, 11) && close(av.z, 4) && close(av.w, 1))) {
                if (close(av.x, 7) && close(av.y, 4) && close(av.z, 9) && close(av.w, 2)) {
                    c.add("storage order", "TODO 1: M * v reads m[col][row]: A * (1, 2, 3, 1) gave " + str(av) +
                                               " instead of (9, 11, 4, 1). Mat4 is m[row][col]; (M v)[r] = sum_c m[r][c] v[c], "
                                               "so the translation is the last COLUMN");
                } else {
                    c.add("matrix", "TODO 1: A * (1, 2, 3, 1) gave " + str(av) + " instead of (9, 11, 4, 1)");
                }
            }
            const Vec3 pt = vec3(v, "pt"), dir = vec3(v, "dir");
            if (!same3(pt, {9, 11, 4})) c.add("matrix", "TODO 1: transform_point(A, (1, 2, 3)) gave " + str(pt) + ", expected (9, 11, 4)");
            if (!same3(dir, {5, 11, 5})) {
                c.add(same3(dir, {9, 11, 4}) ? "direction" : "matrix",
                      "TODO 1: transform_direction(A, (1, 2, 3)) gave " + str(dir) + ", expected (5, 11, 5)" +
                          (same3(dir, {9, 11, 4}) ? ": a direction has w = 0, so the translation column must not move it"
                                                  : std::string()));
            }
            break;
        }
        case Group::kBuilders: {
            c.matrix("translate", "builders", "TODO 2: translate((1, -2, 3))");
            c.matrix("scale", "builders", "TODO 2: scale((2, 3, 4))");
            const char* names[3] = {"rx", "ry", "rz"};
            for (const char* n : names) {
                const Matrix a = mat(v, n), b = mat(c.ref, n);
                if (!same(a, b)) {
                    c.add("builders", std::string("TODO 2: rotate_") + n[1] + "(0.3) = " + str(a) + ", expected " + str(b) +
                                          (same(a, transpose(b)) ? ": it turns the wrong way (a transposed rotation)" : ""));
                }
            }
            c.point("rz90", "builders", "TODO 2: rotate_z(pi / 2) applied to +x must give +y");
            c.point("rx90", "builders", "TODO 2: rotate_x(pi / 2) applied to +y must give +z");
            c.point("ry90", "builders", "TODO 2: rotate_y(pi / 2) applied to +z must give +x");
            break;
        }
        case Group::kRodrigues: {
            // A matrix that is the reference's transposed turns by -angle: the sin terms (the
            // cross-product matrix K) have the wrong sign. Said as such, not as "normalize".
            bool transposed = false;
            auto rotation = [&](const char* key, const std::string& what, const std::string& otherwise) {
                const Matrix a = mat(v, key), b = mat(c.ref, key);
                if (same(a, b)) return;
                if (same(a, transpose(b)) && !same(b, transpose(b))) {
                    c.add("rotation", "TODO 2b: " + what + ": got " + str(a) + ", expected " + str(b) +
                                          (std::string(key) == "rz" ? " (yours equals rotate_z(-0.7))" : "") +
                                          (transposed ? ": transposed again, the sin terms' sign"
                                                      : ". Yours is the expected matrix transposed, the rotation by MINUS "
                                                        "the angle: it turns the other way, so the sin terms have the "
                                                        "wrong sign. With k the unit axis, R = cos(a) I + (1 - cos(a)) "
                                                        "k k^T + sin(a) K, where K = [0 -kz ky; kz 0 -kx; -ky kx 0]: "
                                                        "m[0][1] gets - sin(a) kz and m[1][0] + sin(a) kz"));
                    transposed = true;
                } else {
                    c.add("rotation", "TODO 2b: " + what + otherwise + ": got " + str(a) + ", expected " + str(b));
                }
            };
            rotation("r111", "rotate((1, 1, 1), 120 degrees) must cycle x -> y -> z", "");
            rotation("rz", "rotate((0, 0, 2), 0.7) must equal rotate_z(0.7)", " (normalize the axis)");
            c.matrix("zero", "rotation", "TODO 2b: rotate about the zero axis must give the identity (not NaN)");
            rotation("general", "rotate((1, -2, 0.5), 1.3)", "");
            if (transposed) {
                for (cp::Finding& f : c.j.findings) {
                    if (f.topic == "rotation") f.hint = "the sin terms' sign: a positive angle turns counter-clockwise "
                                                        "seen from the axis's tip, so rotate((0, 0, 1), a) must equal "
                                                        "rotate_z(a), whose m[0][1] is -sin(a)";
                }
            }
            break;
        }
        case Group::kComposition: {
            const Vec3 tr = vec3(v, "tr");
            if (!same3(tr, {3, 1, 0})) {
                c.add(same3(tr, {0, 4, 0}) ? "multiplication order" : "composition",
                      "TODO 1: (translate((3, 0, 0)) * rotate_z(pi / 2)) applied to (1, 0, 0) gave " + str(tr) +
                          "; expected (3, 1, 0): first turn (to (0, 1, 0)), then move. A * B applies B first");
            }
            const Vec3 rt = vec3(v, "rt");
            if (!same3(rt, {0, 4, 0})) {
                c.add(same3(rt, {3, 1, 0}) ? "multiplication order" : "composition",
                      "TODO 1: (rotate_z(pi / 2) * translate((3, 0, 0))) applied to (1, 0, 0) gave " + str(rt) +
                          "; expected (0, 4, 0): first move to (4, 0, 0), then turn");
            }
            c.point("srt", "composition", "TODO 1: translate * rotate_x * scale applied to (0, 1, 0)");
            break;
        }
        case Group::kInverse: {
            for (int k = 0; k < 6; ++k) {
                const std::string key = "inv" + std::to_string(k);
                const bool singular = k == 3 || k == 4;
                const double ok = get(v, key + ".ok");
                if (singular) {
                    if (ok != 0) {
                        c.add("inverse", "TODO 3a: matrix " + std::to_string(k) + (k == 3 ? " (a zero column)" : " (two equal rows)") +
                                             " is singular, but inverse() returned true; report a zero pivot");
                    }
                } else if (ok != 1) {
                    c.add("inverse", "TODO 3a: matrix " + std::to_string(k) + " is invertible, but inverse() returned false" +
                                         (k == 5 ? std::string(" (its first pivot is 1e-17, though its other entries are 1 "
                                                               "and the matrix is far from singular: pivot on the row with "
                                                               "the LARGEST |entry| of the column, a row swap here)")
                                                 : std::string()));
                } else {
                    const Matrix a = mat(v, key), b = mat(c.ref, key);
                    // Every entry of the right size, some of the wrong sign: the cofactors' signs.
                    bool sizes = true;
                    for (int i = 0; i < 4; ++i) {
                        for (int j = 0; j < 4; ++j) sizes &= close(std::abs(a[i][j]), std::abs(b[i][j]));
                    }
                    const std::string what =
                        "TODO 3a: the inverse of matrix " + std::to_string(k) +
                        (k == 1   ? " (its first pivot needs a row swap)"
                         : k == 5 ? " (its first pivot is 1e-17 beside a 1: Gauss-Jordan must swap in the row with "
                                    "the LARGEST |entry| of the column (partial pivoting), not only a zero pivot; "
                                    "dividing by 1e-17 makes every later entry 1e17 times too large to keep its digits)"
                                  : "");
                    if (same(a, b)) continue;
                    if (sizes) {
                        c.add("inverse",
                              what + ": got " + str(a) + ", expected " + str(b) +
                                  ". Every entry has the right size, but some have the wrong sign. With "
                                  "cofactors, cofactor (i, j) is (-1)^(i + j) times the minor without row i "
                                  "and column j (a checkerboard of signs, not one sign per column or row), "
                                  "and the inverse is the TRANSPOSED cofactor matrix divided by det",
                              "cofactors: inverse[i][j] = (-1)^(i + j) * minor(j, i) / det; "
                              "Gauss-Jordan: pivot on the largest |entry| of the column");
                    } else {
                        c.matrix(key, "inverse", what);
                    }
                }
            }
            {
                const Matrix a = mat(v, "rigid"), b = mat(c.ref, "rigid");
                if (!same(a, b)) {
                    // The rotation part right, the last column -t instead of -R^T t.
                    bool rot_ok = true;
                    for (int i = 0; i < 4; ++i) {
                        for (int j = 0; j < 3; ++j) rot_ok &= close(a[i][j], b[i][j]);
                    }
                    const bool minus_t = rot_ok && close(a[0][3], -3) && close(a[1][3], 1) && close(a[2][3], -2);
                    c.add("inverse",
                          "TODO 3b: rigid_inverse of rotate_z(0.5) with translation t = (3, -1, 2): got " + str(a) +
                              ", expected " + str(b) +
                              (minus_t ? ". The rotation part is right (R^T), but the last column is -t; it "
                                         "must be -R^T t: the inverse first undoes the move (-t), then the "
                                         "turn (R^T), so R^T turns the move back as well"
                                       : ""),
                          "rigid_inverse: R^T in the upper-left 3x3, -R^T t in the last column, "
                          "0 0 0 1 below; no elimination (the inverse of [R t] is [R^T -R^T t])");
                }
            }
            break;
        }
        case Group::kNearSingular: {
            const Matrix a = near_singular_matrix();
            if (get(v, "ok") != 1) {
                c.add("inverse",
                      "TODO 3a: this matrix (condition number 1e12) is invertible, but inverse() returned false: "
                      "is your singularity threshold absolute, or too large? With Gauss-Jordan, compare each "
                      "pivot with a threshold relative to the entries (the reference: 1e-14 times the largest "
                      "|entry|). With cofactors, no threshold on det carries over: det is about 1e-24 here "
                      "(the product of all pivots), so call the matrix singular only when det == 0 or when det "
                      "or an entry of the result is not finite",
                      "singular means: a pivot <= 1e-14 * largest |entry| (Gauss-Jordan), or det "
                      "== 0 / a non-finite result (cofactors); never a fixed threshold");
                break;
            }
            // Every entry of the right size, some of the wrong sign: the cofactors' signs.
            bool sizes = get(c.ref, "ok") == 1;
            bool signs = false;
            {
                const Matrix mi = mat(v, "inv"), ri = mat(c.ref, "inv");
                for (int i = 0; i < 4; ++i) {
                    for (int j = 0; j < 4; ++j) {
                        sizes &= close(std::abs(mi[i][j]), std::abs(ri[i][j]), 1e-3);
                        signs |= std::abs(ri[i][j]) > 1e-9 * std::max(1.0, std::abs(ri[i][j])) && (mi[i][j] > 0) != (ri[i][j] > 0);
                    }
                }
            }
            const Matrix r = mul(a, mat(v, "inv"));
            double worst = 0;
            for (int i = 0; i < 4; ++i) {
                for (int j = 0; j < 4; ++j) worst = std::max(worst, std::abs(r[i][j] - (i == j ? 1 : 0)));
            }
            if (std::isnan(worst)) worst = 1e300;
            for (int i = 0; i < 4; ++i) {
                for (int j = 0; j < 4; ++j) {
                    if (std::isnan(r[i][j])) worst = 1e300;
                }
            }
            c.j.measures["residual |M M^-1 - I|"] = worst;
            if (!(worst <= 1e-3)) {
                if (sizes && signs) {
                    c.add("inverse",
                          "TODO 3a: |M * inverse(M) - I| = " + num(worst) +
                              " (at most 1e-3 allowed for condition 1e12): every entry of your inverse has "
                              "the right size, but some have the wrong sign. With cofactors, cofactor (i, j) "
                              "is (-1)^(i + j) times its minor, and the inverse is the TRANSPOSED cofactor "
                              "matrix divided by det",
                          "cofactors: inverse[i][j] = (-1)^(i + j) * minor(j, i) / det");
                } else {
                    c.add("inverse", "TODO 3a: |M * inverse(M) - I| = " + num(worst) +
                                         " (at most 1e-3 allowed for condition 1e12): pivot on the largest |entry| of "
                                         "each column, in double");
                }
            }
            break;
        }
        case Group::kLookAt: {
            for (const char* key : {"plain", "general", "down", "same", "noup"}) {
                const Matrix a = mat(v, key), b = mat(c.ref, key);
                if (same(a, b)) continue;
                const bool fallback = std::string(key) == "down" || key == std::string("same") || key == std::string("noup");
                // r (row 0) negated, and with it u = cross(r, f) (row 1); -f (row 2) unchanged.
                bool flipped_r = true;
                for (int col = 0; col < 3; ++col) flipped_r &= close(a[0][col], -b[0][col]) && close(a[2][col], b[2][col]);
                flipped_r &= !close(b[0][0], 0) || !close(b[0][1], 0) || !close(b[0][2], 0);
                bool finite = true;
                for (const auto& row : a) {
                    for (double x : row) finite &= std::isfinite(x);
                }
                static const std::map<std::string, std::string> inputs = {
                    {"plain", "look_at((1, 2, 3), (0, 0, 0), (0, 1, 0))"},
                    {"general", "look_at((-2, 1, 4), (1, 0.5, -1), (0.2, 1, 0.1))"},
                    {"down", "look_at((0, 5, 0), (0, 0, 0), (0, 1, 0)), up parallel to the view"},
                    {"same", "look_at((1, 1, 1), (1, 1, 1), (0, 1, 0)), eye == target"},
                    {"noup", "look_at((3, 0, 0), (0, 0, 0), (0, 0, 0)), a zero up vector"},
                };
                const std::string what = inputs.at(key) + ": got " + str(a) + ", expected " + str(b);
                if (flipped_r) {
                    c.add("handedness", "TODO 4: " + what + ". Your right vector points left: r = cross(f, up), not "
                                                             "cross(up, f), so that r, u, -f is right-handed");
                } else if (fallback) {
                    const std::map<std::string, std::string> pinned = {
                        {"down", ": f = (0, -1, 0) is parallel to up, so up is replaced by the world axis along which "
                                 "|f| has its SMALLEST component, the first on a tie: x, so up = (1, 0, 0)"},
                        {"same", ": eye == target gives no direction, so f = (0, 0, -1); up (0, 1, 0) is not "
                                 "parallel to it and stays"},
                        {"noup", ": up is zero, so it is replaced by the world axis along which |f| = (1, 0, 0) has "
                                 "its SMALLEST component, the first on a tie: y (0 beside z's 0), so up = (0, 1, 0)"},
                    };
                    c.add("look at fallback", "TODO 4: " + what + (finite ? "" : " (NaN!)") +
                                                  ". transforms.h pins the fallback" +
                                                  (pinned.count(key) ? pinned.at(key)
                                                                     : std::string(" for up parallel to the view and for "
                                                                                   "eye == target")));
                } else {
                    c.add("look at", "TODO 4: " + what);
                }
            }
            break;
        }
        case Group::kProjection: {
            const Matrix p = mat(v, "persp"), pr = mat(c.ref, "persp");
            if (!same(p, pr)) {
                // 90 "degrees" taken as radians: 1 / tan(45 rad) = 0.617...
                if (close(p[1][1], 1 / std::tan(45.0))) {
                    c.add("degrees", "TODO 5: perspective(90, ...) has f = " + num(p[1][1]) +
                                         ", which is 1 / tan(45 radians). fovy is in DEGREES: convert with * pi / 180");
                } else if (close(mat(v, "persp60")[1][1], 1 / std::tan(std::numbers::pi / 3))) {
                    // f = 1 / tan(fovy) instead of 1 / tan(fovy / 2): 90 degrees gives f = 0.
                    c.add("projection",
                          "TODO 5: perspective(60, 1.5, 0.5, 50) has f = " + num(mat(v, "persp60")[1][1]) +
                              " = 1 / tan(60 degrees), expected 1 / tan(30 degrees) = " +
                              num(1 / std::tan(std::numbers::pi / 6)) +
                              ": fovy is the whole vertical angle, "
                              "from the bottom of the view to the top, so f = 1 / tan(fovy / 2)",
                          "halve fovy: the half angle, from the view's axis to its top edge, sets f");
                } else {
                    // The reference's matrix with a few entries changed: a known other convention.
                    auto reference_but = [&](std::initializer_list<std::tuple<int, int, double>> changes) {
                        Matrix q = pr;
                        for (const auto& [i, j, x] : changes) q[std::size_t(i)][std::size_t(j)] = x;
                        return same(p, q);
                    };
                    std::string why;
                    if (reference_but({{2, 2, 10.0 / (1 - 10)}, {2, 3, 10.0 / (1 - 10)}})) {
                        why = ": its third row maps the depth range onto [0, 1], Direct3D's convention (row (0, 0, "
                              "far / (near - far), far near / (near - far))). This course's clip space is OpenGL's: "
                              "z_ndc runs from -1 at the near plane to 1 at the far one, so the row is (0, 0, "
                              "(far + near) / (near - far), 2 far near / (near - far))";
                    } else if (reference_but({{0, 0, 2}})) {
                        why = ": x is scaled by f * aspect = 2; expected f / aspect = 0.5. aspect = width / height, "
                              "and a wide view must fit more of the scene across, so x shrinks: m[0][0] = f / aspect";
                    }
                    c.add("projection", "TODO 5: perspective(90, 2, 1, 10) = " + str(p) + ", expected " + str(pr) + why);
                }
            }
            const std::pair<const char*, const char*> calls[] = {
                {"persp60", "perspective(60, 1.5, 0.5, 50)"}, {"fov1", "perspective(1, 1, 0.1, 10)"},
                {"fov179", "perspective(179, 1, 0.1, 10)"}, {"ortho", "orthographic(-2, 2, -1, 1, 1, 11)"}};
            for (const auto& [key, call] : calls) c.matrix(key, "projection", std::string("TODO 5: ") + call);
            const std::pair<const char*, const char*> bad[] = {{"bad_fov", "perspective(180, 1, 1, 10)"},
                                                               {"bad_near", "perspective(60, 1, 0, 10)"},
                                                               {"bad_ortho", "orthographic(1, 1, -1, 1, 1, 10)"}};
            for (const auto& [key, call] : bad) {
                c.matrix(key, "projection", std::string("TODO 5: ") + call + " has invalid arguments and must give the zero matrix");
            }
            {
                // A NaN here comes from dividing by something that is 0 for this point (its z),
                // not by w, which is 1.
                const Vec3 s0 = vec3(v, "s0");
                const bool finite = std::isfinite(s0.x) && std::isfinite(s0.y) && std::isfinite(s0.z);
                c.point("s0", finite ? "viewport" : "perspective divide",
                        std::string("TODO 6: to_screen((0, 0, 0, 1)) in 100 x 50 pixels is the center") +
                            (finite ? "" : " (its w is 1, so the divide changes nothing; a NaN means a division by its x, y or z, which are 0)"));
            }
            const Vec3 s1 = vec3(v, "s1");
            if (!same3(s1, {62.5, 18.75, 0.1})) {
                if (close(s1.x, 75)) {
                    c.add("perspective divide", "TODO 6: to_screen((0.5, 0.5, 0.2, 2)) gave " + str(s1) +
                                                    ": divide x, y and z by w first (NDC = (0.25, 0.25, 0.1)), then expect (62.5, 18.75)");
                } else if (close(s1.y, 31.25)) {
                    c.add("viewport", "TODO 6: to_screen((0.5, 0.5, 0.2, 2)) gave y = 31.25, expected 18.75: NDC y points "
                                      "up but rows grow down, so y_pixel = (1 - y_ndc) / 2 * H");
                } else {
                    c.add("viewport", "TODO 6: to_screen((0.5, 0.5, 0.2, 2)) in 100 x 50 gave " + str(s1) + ", expected (62.5, 18.75, 0.1)");
                }
            }
            c.point("chain0", "projection", "TODO 5, 6: view-space (0, 0, -5) through perspective(90, 1, 1, 10) to 64 x 64 pixels");
            c.point("chain1", "projection", "TODO 5, 6: view-space (1, 1, -2) must land on pixel (48, 16)");
            c.point("chain2", "projection", "TODO 5, 6: view-space (1, -1, -3) through orthographic(-2, 2, -2, 2, 1, 10)");
            break;
        }
        case Group::kClip: {
            const auto tris = clip_cases();
            // clip_polygon returned nothing for every triangle, even the one entirely inside (the
            // skeleton's `return out;`): one finding that says so, not a theory per triangle.
            bool all_empty = true, ref_any = false;
            for (std::size_t k = 0; k < tris.size(); ++k) {
                all_empty &= polygon(v, "poly" + std::to_string(k)).empty();
                ref_any |= !polygon(c.ref, "poly" + std::to_string(k)).empty();
            }
            if (all_empty && ref_any) {
                c.add("clipping",
                      "TODO 7a: clip_polygon returned no vertices at all, for each of the " +
                          std::to_string(tris.size()) + " triangles, even for " + str(tris[0][0]) + " " +
                          str(tris[0][1]) + " " + str(tris[0][2]) +
                          ", which lies entirely inside the view "
                          "volume and must come back unchanged: clip_polygon is not written yet (or returns "
                          "its empty result). Start from the input polygon and clip it against each of the "
                          "six planes in turn",
                      "TODO 7a is not written yet: start with cur = poly; for each plane, walk the "
                      "edges (a, b) of cur, keep a when da >= 0, add the crossing when (da >= 0) != "
                      "(db >= 0); return cur");
            }
            // Every triangle clipped as if the keep test were reversed: one finding that says so.
            bool keeps_outside = !(all_empty && ref_any);
            for (std::size_t k = 0; k < tris.size() && keeps_outside; ++k) {
                keeps_outside = same_polygon(polygon(v, "poly" + std::to_string(k)),
                                             clip_keeping_outside({tris[k][0], tris[k][1], tris[k][2]}));
            }
            bool differs = false;
            for (std::size_t k = 0; k < tris.size(); ++k) {
                differs |= !same_polygon(polygon(v, "poly" + std::to_string(k)), polygon(c.ref, "poly" + std::to_string(k)));
            }
            if (keeps_outside && differs) {
                c.add("inside test",
                      "TODO 7a: clip_polygon's answers for all " + std::to_string(tris.size()) +
                          " triangles are what Sutherland-Hodgman gives when each plane keeps the "
                          "vertices OUTSIDE it: e.g. " +
                          str(tris[0][0]) + " " + str(tris[0][1]) + " " + str(tris[0][2]) +
                          ", entirely inside, came back empty. For a plane with "
                          "distance d (d = w - x for x <= w), a vertex is inside when d >= 0: keep a "
                          "when da >= 0, not when da < 0",
                      "Sutherland-Hodgman: keep a when da >= 0; add the crossing when (da >= 0) "
                      "!= (db >= 0)");
            }
            bool crossing_told = false;  // the crossing formula is explained once
            for (std::size_t k = 0; k < tris.size() && !(all_empty && ref_any) && !(keeps_outside && differs); ++k) {
                const std::string key = "poly" + std::to_string(k);
                const auto a = polygon(v, key), b = polygon(c.ref, key);
                if (same_polygon(a, b)) continue;
                const std::string what = "clip_polygon of triangle " + str(tris[k][0]) + " " + str(tris[k][1]) + " " +
                                         str(tris[k][2]) + " gave " + std::to_string(a.size()) + " vertices, expected " +
                                         std::to_string(b.size());
                const std::string touching = on_a_plane(tris[k]);
                // As many vertices as the reference's, but other points: which ones are kept is
                // right (the inside test), where the new ones are is not (the crossing).
                std::string wrong_point;
                const double sc = std::max(scale_of(a), scale_of(b));
                auto has = [sc](const std::vector<Vec4>& p, Vec4 q) {
                    return std::any_of(p.begin(), p.end(), [&](Vec4 r) { return same4(r, q, sc); });
                };
                // The triangle's own vertices that the reference keeps are all in yours (a crossing
                // computed from the wrong end may land on an outside vertex: that is no inside test).
                const bool same_kept = std::all_of(tris[k].begin(), tris[k].end(), [&](Vec4 q) { return has(a, q) || !has(b, q); });
                if (a.size() == b.size() && a.size() >= 3 && same_kept && !beyond_near(a)) {
                    for (std::size_t i = 0; i < a.size() && wrong_point.empty(); ++i) {
                        if (std::none_of(b.begin(), b.end(), [&](Vec4 q) { return same4(a[i], q, sc); })) {
                            wrong_point = "your vertex " + std::to_string(i) + ", " + str(a[i]) + ", is none of the expected points";
                        }
                    }
                    for (const Vec4& q : b) {
                        if (std::none_of(a.begin(), a.end(), [&](Vec4 p) { return same4(p, q, sc); })) {
                            wrong_point += (wrong_point.empty() ? "" : ", and ") + std::string("the expected point ") +
                                           str(q) + " is missing";
                            break;
                        }
                    }
                }
                if (same_polygon(a, clip_near_at_zero({tris[k][0], tris[k][1], tris[k][2]}))) {
                    c.add("near plane", "TODO 7a: " + what + ": yours is the triangle clipped against z >= 0 as its near "
                                        "plane, the clip space of a [0, 1] depth range (Direct3D's). This course's clip "
                                        "space is OpenGL's: the near plane is z >= -w, so its distance is w + z, as "
                                        "-w <= x, y, z <= w says for all six",
                          "six planes, each distance >= 0 inside: w + x, w - x, w + y, w - y, w + z, w - z");
                } else if (!wrong_point.empty()) {
                    c.add("clipping", "TODO 7a: " + what + ", but not the same points: " + wrong_point +
                                          (crossing_told ? ": a crossing point again"
                                                         : ". The triangle's vertices inside the volume are all there, so "
                                                           "the inside test looks right; the crossing points are wrong. "
                                                           "On the edge from a to b (da >= 0 > db, or the other way), "
                                                           "t = da / (da - db) is measured FROM a: the crossing is "
                                                           "a + (b - a) * t, where t = 0 gives a and t = 1 gives b "
                                                           "(b + (a - b) * t starts from the wrong end)"));
                    crossing_told = true;
                    c.j.findings.back().hint = "the crossing of edge a-b with a plane: t = da / (da - db), then "
                                               "a + (b - a) * t: interpolate from a, the vertex whose distance is da";
                } else if (beyond_near(a)) {
                    c.add("near plane", "TODO 7a: " + what + "; some lie outside the near plane (z < -w or w <= 0): clip "
                                        "against z >= -w too, or points behind the camera reach the divide");
                } else if (!touching.empty()) {
                    c.add("inside test", "TODO 7a: " + what + ". The vertex " + touching +
                                             ", and the six planes are closed (-w <= x <= w): a vertex with d = 0 is "
                                             "INSIDE. Keep a when da >= 0, and add a crossing exactly when (da >= 0) != "
                                             "(db >= 0); with > in place of >= in either test, the vertex on the plane is "
                                             "lost or its crossing is not added. Where the triangle only touches the view volume at "
                                             "that vertex, what is inside is that one point, and the rule returns it "
                                             "(three times: a polygon of no area)");
                } else {
                    c.add("clipping", "TODO 7a: " + what + (beyond_any(a) ? " (some outside the view volume)" : ""));
                }
            }
            const auto lines = clip_line_cases();
            // clip_line returned false for every segment, even the one entirely inside: not written yet.
            bool no_line = true, ref_line = false;
            for (std::size_t k = 0; k < lines.size(); ++k) {
                no_line &= get(v, "line" + std::to_string(k) + ".ok") == 0;
                ref_line |= get(c.ref, "line" + std::to_string(k) + ".ok") == 1;
            }
            if (no_line && ref_line) {
                c.add("clipping", "TODO 7b: clip_line returned false for each of the " + std::to_string(lines.size()) +
                                      " segments, even for " + str(lines[0][0]) + " - " + str(lines[0][1]) +
                                      ", which lies entirely inside the view volume and must come back unchanged with "
                                      "true: clip_line is not written yet (or returns false before clipping)");
            }
            for (std::size_t k = 0; k < lines.size() && !(no_line && ref_line); ++k) {
                const std::string key = "line" + std::to_string(k);
                const double ok = get(v, key + ".ok"), rok = get(c.ref, key + ".ok");
                const Vec4 a = vec4(v, key + ".a"), b = vec4(v, key + ".b");
                const Vec4 ra = vec4(c.ref, key + ".a"), rb = vec4(c.ref, key + ".b");
                const double sc = scale_of({ra, rb});
                if (ok != rok || (rok == 1 && !(same4(a, ra, sc) && same4(b, rb, sc)))) {
                    const std::string what = "clip_line of " + str(lines[k][0]) + " - " + str(lines[k][1]) + " gave " +
                                             (ok == 1 ? str(a) + " - " + str(b) : std::string("nothing")) + ", expected " +
                                             (rok == 1 ? str(ra) + " - " + str(rb) : std::string("nothing"));
                    const Vec4 mid = (a + b) * 0.5;
                    const double da_on = lines[k][0].w - lines[k][0].x, db_on = lines[k][1].w - lines[k][1].x;
                    if (ok == 1 && rok == 1 && beyond_any({mid}) && !beyond_any({(ra + rb) * 0.5})) {
                        // The piece kept lies outside: the parameter range is the complement.
                        c.add("clipping",
                              "TODO 7b: " + what + ". The middle of the part you kept, " + str(mid) +
                                  ", is outside the view volume: you kept the piece beyond a plane "
                                  "instead of the piece inside. Where the segment ENTERS a plane (da < 0 "
                                  "<= db) the crossing raises t0; where it LEAVES (db < 0 <= da) it lowers "
                                  "t1. Swapped, the outside piece survives",
                              "Liang-Barsky: t0 = max over entering planes, t1 = min over leaving "
                              "planes, reject when t0 > t1");
                    } else if (ok == 0 && rok == 1 && da_on == 0 && db_on == 0) {
                        c.add("clipping",
                              "TODO 7b: " + what +
                                  ". Both ends lie exactly on the plane x = w (d = 0), "
                                  "and the planes are closed: a segment on a plane is inside it. Reject "
                                  "a segment only when both distances are negative (da < 0 and db < 0), "
                                  "not when they are <= 0",
                              "the six planes are closed: d = 0 is inside");
                    } else {
                        c.add(ok == 1 && beyond_near({a, b}) ? "near plane" : "clipping", "TODO 7b: " + what);
                    }
                }
            }
            break;
        }
        case Group::kCulling:
            if (get(v, "cull.cw") != 1 || get(v, "cull.ccw") != 0 || get(v, "cull.flat") != 1) {
                // Only the cases that are wrong, each with its inputs, its answer and the expected one.
                std::string wrong;
                auto check = [&](const char* key, const std::string& call, double want, const std::string& why) {
                    if (get(v, key) == want) return;
                    wrong += (wrong.empty() ? "" : "; ") + call + " gave " + num(get(v, key)) + ", expected " + num(want) + " (" + why + ")";
                };
                check("cull.cw", "is_back_facing((10, 10), (20, 10), (10, 20))", 1, "signed area > 0 in pixels: a back face");
                check("cull.ccw", "is_back_facing((10, 10), (10, 20), (20, 10))", 0, "the reverse order: a front face");
                check("cull.flat", "is_back_facing((10, 10), (20, 20), (30, 30))", 1, "zero area: culled too");
                c.add("culling", "TODO 8: " + wrong + ". A front face has a NEGATIVE cross(s1 - s0, s2 - s0) when y grows downward");
            }
            break;
        case Group::kBezier:
            for (int k = 0; k < 5; ++k) c.point("b" + std::to_string(k), "bezier", "TODO 9: bezier at t = " + std::vector<std::string>{"0", "0.25", "0.5", "0.8", "1"}[k]);
            break;
        case Group::kPainter: {
            const int expected[5] = {4, 1, 3, 0, 2};
            bool ok = get(v, "order.n") == 5;
            for (int k = 0; k < 5 && ok; ++k) ok = get(v, "order." + std::to_string(k)) == expected[k];
            if (!ok) {
                std::string got;
                for (int k = 0; k < int(std::max(0.0, std::min(16.0, get(v, "order.n")))); ++k) got += (k ? " " : "") + num(get(v, "order." + std::to_string(k)));
                const bool reversed = got == "2 0 3 1 4";
                c.add("painter", "TODO 10: painter_order gave [" + got + "], expected [4 1 3 0 2]: the mean view-space z "
                                 "of triangles 0 to 4 is -2, -5, -0.6, -3.5 and -7, and the farthest (most negative z) "
                                 "comes first" +
                                     std::string(reversed ? "; yours is the exact reverse, nearest first: the camera "
                                                            "looks down -z, so a smaller z is farther away"
                                                          : "") +
                                     ". The picture follows from these numbers (draw_model fills in the order "
                                     "painter_order returns): fix TODO 10 first");
            }
            break;
        }
        case Group::kRotationDrift: {
            const Matrix r = mat(v, "r"), rr = mat(c.ref, "r");
            double drift = 0;
            const Matrix rrt = mul(r, transpose(r));
            for (int i = 0; i < 4; ++i) {
                for (int j = 0; j < 4; ++j) {
                    const double d = std::abs(rrt[i][j] - (i == j ? 1 : 0));
                    drift = std::isnan(d) ? 1e300 : std::max(drift, d);
                }
            }
            c.j.measures["orthonormality drift |R R^T - I|"] = drift;
            if (!(drift <= 1e-10) || !same(r, rr, 1e-9)) {
                c.add("precision", "TODO 1, 2b: after 10,000 products of rotate((1, 2, 3), 0.001) the matrix is " + str(r) +
                                       " (drift |R R^T - I| = " + num(drift) + "); expected rotate((1, 2, 3), 10) = " + str(rr) +
                                       ". Use double throughout");
            }
            break;
        }
        case Group::kNonFinite: judge_nonfinite(c); break;
    }
}

// A line of the wireframe whose end lies on a pixel boundary, most often one that clip_line cut
// at a side of the view: its end is then exactly at x = 0 or W (or y = 0 or H), and m1 snaps an
// end to the center of the pixel containing it, so x = 96 and 95.99999999 (the same point by
// another correct order of operations) start the line in neighbouring pixels and the whole line
// may take the neighbouring path. Marks every pixel within a pixel of each such path. The
// segments come from the reference's own matrices (its values, "panel0.model1").
void mark_ambiguous_line_ends(const Scene& s, const Values& ref, raster::Mask& lenient) {
    if (!s.wireframe) return;
    auto apply = [](const Matrix& m, Vec3 p) {
        double r[4];
        for (int i = 0; i < 4; ++i) r[i] = m[i][0] * p.x + m[i][1] * p.y + m[i][2] * p.z + m[i][3];
        return Vec4{r[0], r[1], r[2], r[3]};
    };
    // The pixel centers an end at coordinate v may snap to: both sides of a boundary it lies on.
    auto centers = [](double v) {
        const double k = std::round(v);
        if (std::abs(v - k) <= 1e-7) return std::vector<double>{k - 0.5, k + 0.5};
        return std::vector<double>{std::floor(v) + 0.5};
    };
    for (std::size_t p = 0; p < s.panels.size(); ++p) {
        const Panel& panel = s.panels[p];
        const std::string key = "panel" + std::to_string(p);
        const Matrix vp = mul(mat(ref, key + ".proj"), mat(ref, key + ".view"));
        for (std::size_t i = 0; i < panel.items.size(); ++i) {
            const Matrix mvp = mul(vp, mat(ref, key + ".model" + std::to_string(i)));
            const Mesh& mesh = panel.items[i].mesh;
            const int n = int(mesh.positions.size());
            for (const auto& e : mesh.edges) {
                if (e[0] < 0 || e[0] >= n || e[1] < 0 || e[1] >= n) continue;
                const Vec4 a = apply(mvp, mesh.positions[std::size_t(e[0])]);
                const Vec4 b = apply(mvp, mesh.positions[std::size_t(e[1])]);
                double t0 = 0, t1 = 1;
                bool empty = false;
                for (int plane = 0; plane < 6 && s.clip; ++plane) {
                    const double da = plane_distance(a, plane), db = plane_distance(b, plane);
                    if (da < 0 && db < 0) empty = true;
                    else if (da < 0) t0 = std::max(t0, da / (da - db));
                    else if (db < 0) t1 = std::min(t1, da / (da - db));
                }
                if (empty || !(t0 <= t1)) continue;
                std::vector<double> ends[2][2];  // [end][x or y]: the centers it may snap to
                bool ambiguous = false;
                for (int k = 0; k < 2; ++k) {
                    const Vec4 q = a + (b - a) * (k == 0 ? t0 : t1);
                    const double x = (q.x / q.w + 1) / 2 * panel.w, y = (1 - q.y / q.w) / 2 * panel.h;
                    if (!std::isfinite(x) || !std::isfinite(y) || std::abs(x) > 1e5 || std::abs(y) > 1e5) {
                        ambiguous = false;
                        break;
                    }
                    ends[k][0] = centers(x);
                    ends[k][1] = centers(y);
                    ambiguous |= ends[k][0].size() > 1 || ends[k][1].size() > 1;
                }
                if (!ambiguous) continue;
                for (double ax : ends[0][0]) for (double ay : ends[0][1]) for (double bx : ends[1][0]) for (double by : ends[1][1]) {
                    const double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
                    const int x_lo = std::max(0, int(std::floor(std::min(ax, bx))) - 1);
                    const int x_hi = std::min(panel.w - 1, int(std::floor(std::max(ax, bx))) + 1);
                    const int y_lo = std::max(0, int(std::floor(std::min(ay, by))) - 1);
                    const int y_hi = std::min(panel.h - 1, int(std::floor(std::max(ay, by))) + 1);
                    for (int y = y_lo; y <= y_hi; ++y) {
                        for (int x = x_lo; x <= x_hi; ++x) {
                            const double px = x + 0.5 - ax, py = y + 0.5 - ay;
                            const double t = len2 > 0 ? std::clamp((px * dx + py * dy) / len2, 0.0, 1.0) : 0.0;
                            const double ex = px - t * dx, ey = py - t * dy;
                            if (ex * ex + ey * ey <= 1.0) lenient.set(panel.x0 + x, panel.y0 + y);
                        }
                    }
                }
            }
        }
    }
}

// Pixels next to a color change in the expected image: a vertex rounding to a neighbouring
// pixel may move them, so they may differ (up to a fifth of them). So may the pixels of a
// wireframe line whose end lies on a pixel boundary (mark_ambiguous_line_ends).
cp::Tolerance tolerance_for(const Scene& s, const Values& ref, const raster::Image& expected) {
    cp::Tolerance t;
    t.lenient = raster::Mask(expected.width(), expected.height());
    for (int y = 0; y < expected.height(); ++y) {
        for (int x = 0; x < expected.width(); ++x) {
            const Color c = expected.at(x, y);
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    if (expected.in_bounds(x + dx, y + dy) && expected.at(x + dx, y + dy) != c) t.lenient.set(x, y);
                }
            }
        }
    }
    mark_ambiguous_line_ends(s, ref, t.lenient);
    t.max_lenient_diffs = t.lenient.count() / 5;
    t.why = "pixels next to an edge depend on how a vertex near a pixel boundary rounds";
    return t;
}

long long strict_diffs(const raster::Image& a, const raster::Image& e, const cp::Tolerance& t) {
    if (a.width() != e.width() || a.height() != e.height()) return 1;
    long long n = 0;
    for (int y = 0; y < e.height(); ++y) {
        for (int x = 0; x < e.width(); ++x) n += !t.lenient.get(x, y) && a.at(x, y) != e.at(x, y);
    }
    return n;
}

void judge_picture(Ctx& c, const cp::Artifacts& art) {
    const Scene& s = c.s;
    bool camera_ok = true;
    for (std::size_t p = 0; p < s.panels.size(); ++p) {
        const std::string key = "panel" + std::to_string(p);
        camera_ok &= c.matrix(key + ".view", "look at", "TODO 4: the view matrix of look_at(" + str(s.panels[p].camera.eye) + ", " +
                                                      str(s.panels[p].camera.target) + ", up) (m3.look_at has the details)");
        camera_ok &= c.matrix(key + ".proj", "projection", std::string("TODO 5: the ") + (s.panels[p].camera.ortho ? "orthographic" : "perspective") +
                                                         " matrix of this scene (m3.projection has the details)");
    }
    // The order of the product (render.cpp, draw_model_use): a test triangle drawn twice, with
    // a move and a halving as two of the three matrices. The matrix functions it is drawn with
    // pass their own checks (else the judge says "fix TODO N first"), so a triangle in another
    // place comes from how draw_model combines the matrices. The first placement that is wrong
    // is told.
    struct Placement {
        const char* key;
        const char* matrices;  // what the triangle was drawn with
        const char* why;       // the rule, and where the mistake puts the triangle
    };
    static const Placement kPlacements[] = {
        {"use.order", "model = a move right by 0.5, view = a halving and projection = identity",
         "Each clip-space position is projection * view * model * p: the rightmost matrix acts first, so the model "
         "matrix stands next to the point: the move, then the halving, puts the triangle at x = 30. (model * view * "
         "projection halves the triangle but not the move, which puts it at x = 36.)"},
        {"use.order2", "model = identity, view = a move right by 0.5 and projection = a halving",
         "The projection acts LAST: projection * view * model * p moves the triangle and then halves everything, "
         "x = 30. (view * projection * model halves it before the move, which puts it at x = 36.)"},
    };
    for (const Placement& pl : kPlacements) {
        const std::string key = pl.key;
        const double mine_x = get(c.mine, key + ".x"), ref_x = get(c.ref, key + ".x");
        if (!(get(c.ref, key + ".n") > 0 && std::abs(mine_x - ref_x) > 2)) continue;
        std::string list;  // the matrix functions' checkpoints (not clipping, culling or painter's)
        for (Group g : prerequisite_groups(s)) {
            if (g != Group::kMatrixOps && g != Group::kBuilders && g != Group::kRodrigues && g != Group::kLookAt &&
                g != Group::kProjection) {
                continue;
            }
            const std::string id = prerequisite_checkpoint(g);
            if (list.find(id) == std::string::npos) list += (list.empty() ? "" : ", ") + id;
        }
        cp::Finding f{"pipeline",
                      "the matrix functions this picture is drawn with " + std::string(cp::kPassOwnChecks) + " (" +
                          list + "), yet draw_model puts a test triangle in the wrong place: drawn with " +
                          pl.matrices + " on a 48-pixel image, its pixels " +
                          (get(c.mine, key + ".n") > 0 ? "centre on x = " + num(mine_x) : std::string("are nowhere")) +
                          " where the reference's centre on x = " + num(ref_x) + ". " + pl.why};
        f.todo = "TODO 11";
        f.hint = "clip = projection * view * model * p: read a product right to left";
        c.j.findings.push_back(f);
        break;
    }
    // Face colors: draw_model fills triangle i with model.face_colors[i]. A picture whose faces
    // are all one of the scene's colors, where the expected one shows three or more, has the
    // right shapes in the wrong colors (one index for every face).
    if (s.fill && !c.expected.empty()) {
        const auto it = art.images.find("main");
        std::set<std::array<int, 3>> palette;
        for (const Panel& panel : s.panels) {
            for (const Item& item : panel.items) {
                for (const Color& fc : item.mesh.face_colors) palette.insert({fc.r, fc.g, fc.b});
            }
        }
        // The face colors a picture shows, and how many pixels have one.
        auto faces = [&](const raster::Image& img, long long& pixels) {
            std::set<std::array<int, 3>> used;
            pixels = 0;
            for (int y = 0; y < img.height(); ++y) {
                for (int x = 0; x < img.width(); ++x) {
                    const Color px = img.at(x, y);
                    if (palette.count({px.r, px.g, px.b})) used.insert({px.r, px.g, px.b}), ++pixels;
                }
            }
            return used;
        };
        if (it != art.images.end() && it->second.width() == c.expected.width() &&
            it->second.height() == c.expected.height()) {
            long long mine_px = 0, want_px = 0;
            const auto mine = faces(it->second, mine_px), want = faces(c.expected, want_px);
            if (want.size() >= 3 && mine.size() == 1 && 2 * mine_px >= want_px) {
                const auto& one = *mine.begin();
                c.add("face colors", "TODO 11: every face is filled in one color, (" + std::to_string(one[0]) + ", " +
                                         std::to_string(one[1]) + ", " + std::to_string(one[2]) + "), where the expected " +
                                         "picture shows " + std::to_string(want.size()) + " of the model's face colors: "
                                         "triangle i takes model.face_colors[i] (white when the list is shorter), the "
                                         "index of the triangle being filled, not a fixed one",
                      "fill model.triangles[i] with model.face_colors[i]");
            }
        }
    }
    // The stage counts.
    static const char* kStats[][3] = {
        {"vertices_transformed", "pipeline", "vertices transformed (each position once)"},
        {"triangles_clipped", "clipping", "triangles sent to the clipper (those not entirely inside the view volume)"},
        {"triangles_culled", "culling", "triangles culled as back faces"},
        {"triangles_filled", "pipeline", "triangles filled"},
        {"lines_clipped", "clipping", "edges sent to clip_line (those not entirely inside)"},
        {"lines_drawn", "pipeline", "lines drawn"},
    };
    bool clipped_any = false;
    bool counts_ok = true;  // every count compared matches the reference's
    for (const auto& st : kStats) {
        const std::string key = std::string("stats.") + st[0];
        const double mine = get(c.mine, key), ref = get(c.ref, key);
        // The report lists the counts that are not zero (for yours or the reference).
        if (mine != 0 || ref != 0) c.j.measures[std::string(st[0]) + " (reference " + num(ref) + ")"] = mine;
        // draw_model ran (it counted work) even if it drew nothing: not "TODO 11 not written yet".
        if (mine != 0 && c.j.ran.empty()) c.j.ran.push_back("draw_model");
        clipped_any |= (key == "stats.triangles_clipped" || key == "stats.lines_clipped") && ref > 0;
        // After clipping, a fan may hold zero-area triangles whose culling rounding decides:
        // culled and filled counts are exact only for scenes that clip nothing.
        const bool exact = !(clipped_any && (key == "stats.triangles_culled" || key == "stats.triangles_filled")) || ref == 0;
        // Those few zero-area triangles aside, the culled count must still hold.
        const bool off = exact ? mine != ref : key == "stats.triangles_culled" && std::abs(mine - ref) > 2 + 0.05 * ref;
        if (off) {
            counts_ok = false;
            std::string why;
            if (ref == 0 && (key == "stats.triangles_filled" || key == "stats.lines_drawn")) {
                why = ": this scene does not need that stage (Needs), so draw_model must not run it";
            } else if (key == "stats.triangles_clipped" && ref == 0) {
                why = ": every vertex is inside the view volume, so nothing needs clipping";
            } else if (key == "stats.triangles_clipped" && mine < ref) {
                why = ": fewer triangles reached the clipper than the reference's. A triangle goes to clip_polygon "
                      "when any of its vertices is outside any of the six planes -w <= x, y, z <= w";
                why += culls_first(c) ? ". Yours also culled more triangles than the reference: draw_model seems to "
                                        "cull whole triangles before clipping them. Clipping comes first, in clip "
                                        "space; then each fan triangle of the clipped polygon goes to the screen and "
                                        "is culled there (a triangle crossing the near plane has no screen position "
                                        "before it is clipped, so its winding is not known yet)"
                                      : ". Two causes are common: a triangle sent to clip_polygon but not counted "
                                        "(count each one you send), or the test of which to send: testing only "
                                        "w <= 0 (behind the camera) misses the triangles that cross a side, the top, "
                                        "the bottom or the far plane; test all six planes, as clip_polygon does";
            }
            c.add(st[1], "TODO 11: " + num(mine) + " " + st[2] + ", expected " + num(ref) + why);
            if (key == "stats.triangles_clipped" && mine < ref) {
                c.j.findings.back().hint = culls_first(c)
                                               ? "per triangle: clip (if not all inside), fan, to_screen, THEN cull "
                                                 "each fan triangle; culling never comes before clipping"
                                               : "per triangle: clip unless all three vertices are inside all six "
                                                 "planes (-w <= x, y, z <= w), then fan, to_screen, cull, fill";
            }
        }
    }
    // The clipper on the scene's own triangles (scenes with one panel and small items).
    bool clipper_ok = true;
    for (const auto& [key, value] : c.ref) {
        (void)value;
        if (key.rfind("clip", 0) != 0 || key.size() < 2 || key.substr(key.size() - 2) != ".n") continue;
        const std::string k = key.substr(0, key.size() - 2);
        const auto a = polygon(c.mine, k), b = polygon(c.ref, k);
        if (!same_polygon(a, b)) {
            clipper_ok = false;
            const std::string count = a.size() == b.size()
                                          ? std::to_string(a.size()) + " vertices, as many as the reference's, but not the same points"
                                          : std::to_string(a.size()) + " vertices, expected " + std::to_string(b.size());
            std::string pts;
            for (const Vec4& p : a) pts += (pts.empty() ? "" : " ") + str(p);
            std::string rpts;
            for (const Vec4& p : b) rpts += (rpts.empty() ? "" : " ") + str(p);
            c.add(beyond_near(a) ? "near plane" : "clipping",
                  "TODO 7a: clip_polygon on this scene's triangle gave " + count + " (yours: " + pts + "; expected: " + rpts +
                      ")" + (beyond_near(a) ? ", some outside the near plane (z < -w)" : ""));
        }
    }
    // How draw_model calls is_back_facing and painter_order (render.cpp, draw_model_use): both
    // pass their own checks by now (judge() checked them first), so a difference is the caller's.
    const std::size_t before_use = c.j.findings.size();
    if (c.s.cull) {
        const double mine0 = get(c.mine, "use.cull0"), mine1 = get(c.mine, "use.cull1");
        const double ref0 = get(c.ref, "use.cull0"), ref1 = get(c.ref, "use.cull1");
        if ((ref0 > 0) != (ref1 > 0) && (mine0 > 0) != (ref0 > 0) && (mine1 > 0) != (ref1 > 0)) {
            c.add("culling", "TODO 11: is_back_facing passes its own checks (m3.solid_cube's cases), yet draw_model "
                             "filled a test triangle that the reference culls as a back face and culled the same "
                             "triangle wound the other way, which the reference fills: draw_model must skip a "
                             "triangle exactly when is_back_facing returns true, and fill it otherwise");
        }
    }
    if (c.s.painter) {
        const Vec3 mine = vec3(c.mine, "use.painter"), ref = vec3(c.ref, "use.painter");
        const bool far_on_top = mine.x == 60 && mine.y == 60 && mine.z == 230;  // the far triangle's color
        if (far_on_top && !(mine.x == ref.x && mine.y == ref.y && mine.z == ref.z)) {
            c.add("painter", "TODO 11: painter_order passes its own checks, yet with a near triangle listed before a "
                             "far one that covers it, draw_model left the pixel in the middle " + str(mine) +
                             " where the reference shows the near triangle's " + str(ref) +
                             ": draw_model must fill the triangles in the order painter_order returns (farthest "
                             "first), so the near one is drawn last");
        }
    }
    const bool use_wrong = c.j.findings.size() > before_use;
    // Every function draw_model calls is right (judge() checked them first), the scene's matrices
    // and clipped triangles too, but the picture differs: the fault is draw_model's own.
    // A painter scene: painter_order passes its own checks here (a failing one is reported as
    // "fix TODO 10 first" instead of this judgement), so with the right counts (every triangle
    // filled) faces covering each other in another order come from the caller, draw_model.
    const bool differs = [&] {
        const auto it = art.images.find("main");
        return camera_ok && clipper_ok && !c.expected.empty() && it != art.images.end() &&
               strict_diffs(it->second, c.expected, c.j.tolerance) > 0;
    }();
    bool culled_ok = true, colors_told = false;
    for (const cp::Finding& f : c.j.findings) {
        culled_ok &= f.topic != "culling";
        colors_told |= f.topic == "face colors";  // then the picture's difference is explained
    }
    if (s.painter && counts_ok && differs && !use_wrong && !colors_told) {
        c.add("painter",
              "TODO 11: painter_order passes its own checks (m3.painter's numbers), and so do the "
              "matrices and the clipper, yet the picture differs where no edge is "
              "near: the faces cover each other in another order. draw_model must fill the triangles in the "
              "order painter_order returns: model.triangles[order[0]] first (the farthest), then "
              "model.triangles[order[1]] and so on; not in list order, not backwards, and not triangle k "
              "where order[k] is meant. Another cause: painter_order must be given the VIEW-space "
              "triangles, view * model_matrix * p (after the view matrix, before the projection). "
              "Clip-space z (after the projection) or screen z grows the other way for a perspective, so "
              "sorting by it puts the near faces first" +
                  std::string(clipped_any ? ". (If the faces do overlap in the right order, look at where "
                                            "draw_model clips: in clip space, before the divide.)"
                                          : ""),
              "order = painter_order of the VIEW-space triangles (view * model_matrix * p, before "
              "the projection), then fill model.triangles[order[0]], [order[1]], ... in that order");
    } else if (camera_ok && clipper_ok && clipped_any && !use_wrong && culled_ok && !colors_told) {
        const raster::Image& expected = c.expected;
        const auto it = art.images.find("main");
        if (!expected.empty() && it != art.images.end() &&
            strict_diffs(it->second, expected, c.j.tolerance) > 0) {
            c.add("clip space", "TODO 11: every function draw_model calls passes its own checks here (matrices, "
                                "look_at, projection, to_screen, clip_polygon" +
                                    std::string(c.s.wireframe ? ", clip_line" : "") +
                                    std::string(c.s.cull ? ", is_back_facing" : "") + (c.s.painter ? ", painter_order" : "") +
                                    ")"
                                    ", yet the picture differs where no edge is near, so "
                                    "draw_model uses them wrongly. Does it clip in clip space, BEFORE the perspective "
                                    "divide (a vertex with w <= 0 divided by w lands on the wrong side of the screen)?");
        }
    }
}

// The probes of a scene variant (render.cpp, probes()): "probe.<topic>.<name>[.<component>]",
// each compared with the reference's on the same inputs; one finding per name.
void judge_probes(Ctx& c) {
    std::set<std::string> reported;
    for (const auto& [key, ref] : c.ref) {
        if (key.rfind("probe.", 0) != 0) continue;
        const auto topic_end = key.find('.', 6);
        if (topic_end == std::string::npos) continue;
        const auto name_end = key.find('.', topic_end + 1);
        const std::string name = key.substr(0, name_end);
        if (reported.count(name) || close(get(c.mine, key), ref)) continue;
        reported.insert(name);
        std::string topic = key.substr(6, topic_end - 6);  // value names hold no spaces: look_at
        std::replace(topic.begin(), topic.end(), '_', ' ');
        c.add(topic, "on inputs drawn for this grading (not the lesson's), " + name.substr(topic_end + 1) + " gave " +
                         num(get(c.mine, key)) + " where the reference gives " + num(ref) + " (" + key.substr(6) +
                         "): the function must work for any input, not only the public ones");
    }
}

// "fix TODO N first (see <checkpoint>)": one finding per prerequisite group of the scene that
// fails its own checks, in the order of the TODOs; a group whose checks go through one that
// failed is not judged (its failure would only repeat that one).
std::vector<cp::Finding> prerequisite_findings(const Scene& s, const cp::Artifacts& artifacts,
                                               const cp::Artifacts& reference, const raster::Image& expected) {
    std::vector<cp::Finding> first;
    std::set<Group> broken;
    for (Group g : prerequisite_groups(s)) {
        const std::vector<Group> deps = group_dependencies(g);
        if (std::any_of(deps.begin(), deps.end(), [&](Group d) { return broken.count(d) > 0; })) {
            broken.insert(g);
            continue;
        }
        const std::string prefix = prerequisite_key(g);
        const Values mine = cp::values_under(artifacts.values, prefix), ref = cp::values_under(reference.values, prefix);
        cp::Judgement scratch;
        Ctx sub{s, mine, ref, scratch, expected};
        judge_group(g, sub);
        if (scratch.findings.empty()) continue;
        broken.insert(g);
        const std::string what = s.panels.empty() ? "these numbers are computed with it" : "this picture is drawn with it";
        first.push_back(cp::fix_first(scratch.findings.front(), prerequisite_checkpoint(g), what,
                                      "this checkpoint cannot pass before that one does",
                                      scene(prerequisite_checkpoint(g)).panels.empty()));
    }
    return first;
}

}  // namespace

cp::Judgement judge(const std::string& id, const cp::Artifacts& artifacts, const cp::Artifacts& reference,
                    const raster::Image& expected) {
    const Scene& s = scene(id);
    cp::Judgement j;
    if (!expected.empty()) j.tolerance = tolerance_for(s, reference.values, expected);  // (a missing one: the harness says so)
    Ctx c{s, artifacts.values, reference.values, j, expected};
    if (artifacts.stray_writes > 0) {
        c.add("pipeline", std::to_string(artifacts.stray_writes) + " write(s) outside the image: milestones 1 and 2 "
                          "clip to the image, so this comes from your own code");
    }
    const std::size_t before = j.findings.size();
    for (Group g : s.groups) judge_group(g, c);
    judge_probes(c);
    // A picture scene whose own numbers fail (m3.solid_cube's is_back_facing) is judged on
    // them alone: its counts and its clip-space guess would blame draw_model for them.
    const bool own_failed = j.findings.size() > before;
    if (!s.panels.empty() && !own_failed) judge_picture(c, artifacts);
    bool fails = j.findings.size() > before;
    if (!fails && !s.panels.empty() && !expected.empty()) {
        const auto it = artifacts.images.find("main");
        fails = it == artifacts.images.end() || cp::exceeds_tolerance(it->second, expected, j.tolerance);
    }
    // A failing checkpoint first checks the functions of earlier TODOs it is computed or drawn
    // with, on their own checkpoints' inputs. One that is wrong is the finding ("fix TODO 1
    // first, see m3.matrix_ops"), and this scene's own findings, which would blame a later
    // TODO for what the broken function did, are left out (and so is the harness's "drew
    // nothing"). A checkpoint that passes stays passed, whatever its prerequisites do.
    const std::vector<cp::Finding> first = fails ? prerequisite_findings(s, artifacts, reference, expected)
                                                 : std::vector<cp::Finding>{};
    if (!first.empty()) {
        j.findings.resize(before);
        j.findings.insert(j.findings.end(), first.begin(), first.end());
    }
    j.upstream_failed = !first.empty() || (!s.panels.empty() && own_failed);
    return j;
}

}  // namespace m3cp
