// Judge half of the milestone-2 checkpoints (trusted: it runs no code under test).
//
// Its oracle classifies a sample point against a triangle in one of two ways:
//  * exact, when all vertices lie on the 1/16-pixel grid (as the scene gives them): 128-bit
//    integer edge functions with the pinned top-left rule, so even samples exactly on an edge
//    are decided, and checked strictly;
//  * with a margin otherwise: a sample farther than kMargin from every edge line is certainly
//    in or out, anything nearer is ambiguous (snapping to 1/16 moves an edge by at most
//    0.045 pixel, so a correct implementation can decide those either way).
//
// Gradients on the grid are judged exactly too: the barycentric color of a pixel center is a
// ratio of 128-bit integers, so its nearest level is known exactly; only where that ratio is
// within kTieWindow of a half level may a correct implementation (float, stepped weights)
// round either way.
#include "m2/judge.h"
#include "harness/judging.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <sstream>
#include <tuple>

#include "m2/scenes.h"

namespace m2cp {

namespace {

using cp::str;
using raster::Image;
using raster::Mask;

constexpr double kMargin = 1.0 / 16;
constexpr double kMaxCoordinate = 1 << 24;  // as pinned in triangles.h
// Half-level ties of an exact gradient value: within this many levels of x.5, either
// neighbour is accepted (float weights are off by ~1e-4 level; stepped float weights by ~1e-3).
constexpr double kTieWindow = 0.01;
using i128 = __int128;

enum class Side { kIn, kOut, kAmbiguous };

struct Verdict {
    Side side = Side::kOut;
    bool on_edge = false;  // exact mode: the sample is exactly on an edge (fill rule decided)
};

// Every digit a point of these scenes has (sixteenths of 1e7 need 12): a message that says
// -1e+07 for -9999999.9375 hides the very fraction it is about.
std::string str(Vec2 p) {
    std::ostringstream s;
    s.precision(12);
    s << "(" << p.x << ", " << p.y << ")";
    return s.str();
}

// A triangle as the judge sees it.
class Shape {
public:
    explicit Shape(const Tri& t) {
        for (int i = 0; i < 3; ++i) {
            v_[i] = t.v[i];
            drawable_ &= raster::is_finite(t.v[i]) && std::abs(t.v[i].x) <= kMaxCoordinate &&
                         std::abs(t.v[i].y) <= kMaxCoordinate;
        }
        if (!drawable_) return;
        for (int i = 0; i < 3; ++i) {
            s_[i][0] = std::llround(t.v[i].x * 16);
            s_[i][1] = std::llround(t.v[i].y * 16);
        }
        exact_ = true;
        for (int i = 0; i < 3; ++i) {
            const double gx = t.v[i].x * 16, gy = t.v[i].y * 16;
            exact_ &= gx == std::floor(gx) && gy == std::floor(gy);
            g_[i][0] = static_cast<i128>(gx);
            g_[i][1] = static_cast<i128>(gy);
        }
        if (exact_) {
            const i128 area = cross(g_[0], g_[1], g_[2]);
            drawable_ = area != 0;
            sign_ = area > 0 ? 1 : -1;
        } else {
            const double area = (v_[1].x - v_[0].x) * (v_[2].y - v_[0].y) - (v_[1].y - v_[0].y) * (v_[2].x - v_[0].x);
            sign_ = area >= 0 ? 1 : -1;
        }
    }

    bool drawable() const { return drawable_; }
    bool exact() const { return exact_; }

    // p in pixels; in exact mode p must be on the 1/16 grid too (pixel centers and the
    // supersampling positions for n = 1, 2, 4, 8 all are).
    Verdict classify(Vec2 p) const {
        if (!drawable_) return {Side::kOut, false};
        if (exact_) {
            const i128 q[2] = {static_cast<i128>(p.x * 16), static_cast<i128>(p.y * 16)};
            bool on_edge = false;
            for (int i = 0; i < 3; ++i) {
                // Walk the edges in the order that makes the area positive.
                const int a = sign_ > 0 ? i : (3 - i) % 3, b = sign_ > 0 ? (i + 1) % 3 : (2 - i + 3) % 3;
                const i128 e = cross(g_[a], g_[b], q);
                if (e == 0) {
                    on_edge = true;
                    // Top edge: horizontal, going right; left edge: going up (y decreasing).
                    const i128 dy = g_[b][1] - g_[a][1], dx = g_[b][0] - g_[a][0];
                    if (!((dy == 0 && dx > 0) || dy < 0)) return {Side::kOut, true};
                } else if (e < 0) {
                    return {Side::kOut, on_edge};
                }
            }
            return {Side::kIn, on_edge};
        }
        double nearest = 1e300;
        for (int i = 0; i < 3; ++i) {
            const Vec2 a = v_[i], b = v_[(i + 1) % 3];
            const double len = raster::length(b - a);
            if (len == 0) return {Side::kAmbiguous, false};
            nearest = std::min(nearest, sign_ * raster::cross(b - a, p - a) / len);
        }
        if (nearest > kMargin) return {Side::kIn, false};
        if (nearest < -kMargin) return {Side::kOut, false};
        return {Side::kAmbiguous, false};
    }

    // Exact mode: is p in the closed triangle (every oriented edge value >= 0) and in the open
    // one (every value > 0)? In between, p is exactly on the boundary and the fill rule decides.
    std::pair<bool, bool> closed_open(Vec2 p) const {
        if (!drawable_ || !exact_) return {false, false};
        const i128 q[2] = {static_cast<i128>(p.x * 16), static_cast<i128>(p.y * 16)};
        bool closed = true, open = true;
        for (int i = 0; i < 3; ++i) {
            const i128 e = sign_ * cross(g_[i], g_[(i + 1) % 3], q);
            closed &= e >= 0;
            open &= e > 0;
        }
        return {closed, open};
    }

    // Is pixel (x, y) among the pixels bounding_box() returns (before clamping): its center
    // within the snapped vertices' range on both axes?
    bool in_center_box(int x, int y) const {
        if (!drawable_) return false;
        auto in = [&](int axis, long long c) {
            const long long lo = std::min({s_[0][axis], s_[1][axis], s_[2][axis]});
            const long long hi = std::max({s_[0][axis], s_[1][axis], s_[2][axis]});
            return lo <= c && c <= hi;
        };
        return in(0, 16LL * x + 8) && in(1, 16LL * y + 8);
    }

    // Exact mode: the levels a correct gradient may give at p (on the grid): the exact value
    // l0 * c0 + l1 * c1 + l2 * c2 rounded to nearest, or both neighbours near a half level.
    // `exact` receives the unrounded values, for messages.
    void gradient_levels(const Tri& t, Vec2 p, Color& lo, Color& hi, double exact[3]) const {
        const i128 q[2] = {static_cast<i128>(p.x * 16), static_cast<i128>(p.y * 16)};
        i128 l[3] = {cross(g_[1], g_[2], q), cross(g_[2], g_[0], q), cross(g_[0], g_[1], q)};
        i128 d = cross(g_[0], g_[1], g_[2]);
        if (d < 0) {
            d = -d;
            for (i128& v : l) v = -v;
        }
        std::uint8_t* los[3] = {&lo.r, &lo.g, &lo.b};
        std::uint8_t* his[3] = {&hi.r, &hi.g, &hi.b};
        for (int ch = 0; ch < 3; ++ch) {
            auto channel = [&](int k) { return static_cast<i128>(ch == 0 ? t.c[k].r : ch == 1 ? t.c[k].g : t.c[k].b); };
            i128 n = l[0] * channel(0) + l[1] * channel(1) + l[2] * channel(2);
            if (n < 0) n = 0;  // p is inside the closed triangle, so n >= 0 already
            const i128 whole = n / d, rest = n % d;  // value = whole + rest / d
            exact[ch] = double(whole) + double(rest) / double(d);
            const i128 off = 2 * rest - d;           // < 0: round down, > 0: round up
            const bool tie = (off < 0 ? -off : off) <= static_cast<i128>(2 * kTieWindow * double(d));
            const i128 down = std::min<i128>(whole, 255), up = std::min<i128>(whole + 1, 255);
            *los[ch] = static_cast<std::uint8_t>(tie || off < 0 ? down : up);
            *his[ch] = static_cast<std::uint8_t>(tie || off >= 0 ? up : down);
        }
    }

    // Barycentric weights of p (unsnapped geometry).
    std::array<double, 3> weights(Vec2 p) const {
        const double area = raster::cross(v_[1] - v_[0], v_[2] - v_[0]);
        return {raster::cross(v_[2] - v_[1], p - v_[1]) / area, raster::cross(v_[0] - v_[2], p - v_[2]) / area,
                raster::cross(v_[1] - v_[0], p - v_[0]) / area};
    }

    // Exact area of the triangle inside pixel (x, y): the triangle clipped to the pixel's
    // square (Sutherland-Hodgman), then the shoelace formula.
    double area_in_pixel(int x, int y) const {
        if (!drawable_) return 0;
        std::vector<Vec2> poly(v_, v_ + 3);
        auto clip = [&](auto inside, auto cut) {
            std::vector<Vec2> out;
            for (std::size_t i = 0; i < poly.size(); ++i) {
                const Vec2 a = poly[i], b = poly[(i + 1) % poly.size()];
                if (inside(a)) out.push_back(a);
                if (inside(a) != inside(b)) out.push_back(cut(a, b));
            }
            poly = out;
        };
        auto at_x = [](double x0) {
            return [x0](Vec2 a, Vec2 b) { return Vec2{x0, a.y + (b.y - a.y) * (x0 - a.x) / (b.x - a.x)}; };
        };
        auto at_y = [](double y0) {
            return [y0](Vec2 a, Vec2 b) { return Vec2{a.x + (b.x - a.x) * (y0 - a.y) / (b.y - a.y), y0}; };
        };
        clip([x](Vec2 p) { return p.x >= x; }, at_x(x));
        clip([x](Vec2 p) { return p.x <= x + 1; }, at_x(x + 1));
        clip([y](Vec2 p) { return p.y >= y; }, at_y(y));
        clip([y](Vec2 p) { return p.y <= y + 1; }, at_y(y + 1));
        double twice = 0;
        for (std::size_t i = 0; i < poly.size(); ++i) twice += raster::cross(poly[i], poly[(i + 1) % poly.size()]);
        return std::abs(twice) / 2;
    }

    std::string name() const { return "triangle " + str(v_[0]) + " " + str(v_[1]) + " " + str(v_[2]); }

    // As listed, is the triangle clockwise on screen (negative signed area)?
    bool clockwise() const { return drawable_ && sign_ < 0; }

    // What a student's fill computes on the snapped vertices (as snap() pins them), at the
    // point (qx, qy) in sixteenths: the three edge values with the top-left rule. For the
    // pictures of typical mistakes, which sample at points other than pixel centers.
    bool snapped_covers(long long qx, long long qy) const {
        if (!drawable_) return false;
        const i128 g[3][2] = {{s_[0][0], s_[0][1]}, {s_[1][0], s_[1][1]}, {s_[2][0], s_[2][1]}};
        const i128 q[2] = {qx, qy};
        const i128 area = cross(g[0], g[1], g[2]);
        if (area == 0) return false;
        for (int i = 0; i < 3; ++i) {
            const int a = area > 0 ? i : (3 - i) % 3, b = area > 0 ? (i + 1) % 3 : (2 - i + 3) % 3;
            const i128 e = cross(g[a], g[b], q);
            const i128 dy = g[b][1] - g[a][1], dx = g[b][0] - g[a][0];
            if (e < 0 || (e == 0 && !((dy == 0 && dx > 0) || dy < 0))) return false;
        }
        return true;
    }

    // bounding_box() of the snapped vertices, clamped to a w x h image: [x0, x1) x [y0, y1),
    // false when empty.
    bool snapped_box(int w, int h, int& x0, int& y0, int& x1, int& y1) const {
        if (!drawable_) return false;
        auto range = [&](int axis, int size, int& first, int& end) {
            const long long lo = std::min({s_[0][axis], s_[1][axis], s_[2][axis]});
            const long long hi = std::max({s_[0][axis], s_[1][axis], s_[2][axis]});
            auto floor_div = [](long long a) { return a >= 0 ? a / 16 : -((-a + 15) / 16); };
            first = int(std::clamp<long long>(-floor_div(-(lo - 8)), 0, size));  // ceil((lo - 8) / 16)
            end = int(std::clamp<long long>(floor_div(hi - 8) + 1, 0, size));
        };
        range(0, w, x0, x1);
        range(1, h, y0, y1);
        return x0 < x1 && y0 < y1;
    }

private:
    static i128 cross(const i128 a[2], const i128 b[2], const i128 p[2]) {
        return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
    }

    Vec2 v_[3];
    i128 g_[3][2] = {};         // exact mode: the vertices in sixteenths
    long long s_[3][2] = {};    // the vertices snapped as snap() pins it (nearest sixteenth)
    bool drawable_ = true;
    bool exact_ = false;
    int sign_ = 1;
};

Color interpolate(const Tri& t, const std::array<double, 3>& w) {
    auto ch = [&](auto member) {
        return raster::to_channel(w[0] * (t.c[0].*member) + w[1] * (t.c[1].*member) + w[2] * (t.c[2].*member));
    };
    return {ch(&Color::r), ch(&Color::g), ch(&Color::b)};
}

bool near(Color a, Color b, int tol) {
    return std::abs(a.r - b.r) <= tol && std::abs(a.g - b.g) <= tol && std::abs(a.b - b.b) <= tol;
}

// Sets a finding's own TODO and hint where the harness's Finding has them (cp::Finding gained
// `hint` and `todo` while this judge was written; without them the finding is unchanged).
template <typename F>
void advise(F& f, const std::string& todo, const std::string& hint) {
    if constexpr (requires { f.todo = todo; f.hint = hint; }) {
        f.todo = todo;
        f.hint = hint;
    }
}

cp::Finding finding(std::string topic, std::string message, const std::string& todo = "", const std::string& hint = "") {
    cp::Finding f;
    f.topic = std::move(topic);
    f.message = std::move(message);
    advise(f, todo, hint);
    return f;
}

// Collects up to a few example pixels of one kind of mistake into one finding.
// `what` says what the pixels are ("inside a triangle are not filled"); `one` is its singular
// ("inside a triangle is not filled"), for a count of 1.
struct Tally {
    Tally(std::string t, std::string w, std::string o, std::string td = "", std::string h = "")
        : topic(std::move(t)), what(std::move(w)), one(std::move(o)), todo(std::move(td)), hint(std::move(h)) {}
    std::string topic, what, one, todo, hint;
    long long count = 0;
    std::string examples;
    raster::Mask* wrong = nullptr;  // Tolerance::wrong: each pixel added is red in diff.png
    void add(int x, int y, const std::string& detail = "") {
        if (wrong) wrong->set(x, y);
        if (count++ < 3) {
            examples += (examples.empty() ? "" : "; ") + std::string("(") + std::to_string(x) + ", " +
                        std::to_string(y) + ")" + detail;
        }
    }
    void report(cp::Judgement& j) const {
        if (count == 0) return;
        const std::string said = count == 1 ? "1 pixel " + one : std::to_string(count) + " pixels " + what;
        j.findings.push_back(finding(topic, said + ", e.g. " + examples, todo, hint));
    }
};

// Sample positions of fill_triangle_aa with n per axis, inside pixel (x, y).
std::vector<Vec2> samples(int x, int y, int n) {
    std::vector<Vec2> out;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) out.push_back({x + (i + 0.5) / n, y + (j + 0.5) / n});
    }
    return out;
}

std::string generic_topic(const std::string& id) {
    if (id == "m2.huge") return "precision";
    if (id == "m2.degenerate") return "degenerate";
    if (id == "m2.nonfinite") return "bad input";
    return "coverage";
}

// What a pixel should look like, built by applying the scene's triangles in order, and the
// pictures a few typical mistakes would leave instead (to name the mistake, not to judge).
struct Expectation {
    Color want = raster::colors::black;     // the color (the low end of the range for one AA triangle)
    Color want_hi = raster::colors::black;  // the high end of that range
    Color under = raster::colors::black;    // before the top triangle (the last one covering the center)
    Color before_aa = raster::colors::black;  // before the first anti-aliased triangle on top
    Color alt_flip = raster::colors::black;   // every center exactly on an edge decided the other way
    Color alt_all = raster::colors::black;    // AA: every sample exactly on an edge counted
    Color alt_none = raster::colors::black;   // AA: no sample exactly on an edge counted
    Color alt_box = raster::colors::black;    // AA: triangles skip pixels outside their center box
    Color alt_set = raster::colors::black;    // AA: the last triangle's share mixed with black, set not blended
    int top = -1;                             // that triangle (not anti-aliased), or -1
    bool lenient = false, on_edge = false, in_last = false;
    int aa_tris = 0, layers = 0;  // AA triangles on top; solid or gradient triangles covering the center
    bool aa_ambiguous = false, aa_edge_samples = false, aa_box_skipped = false;
    bool gradient_exact = false;
    Color grad_lo, grad_hi;  // exact gradient: the accepted levels per channel
    double exact[3] = {};
};

Expectation expect_pixel(const Scene& s, const std::vector<Shape>& shapes, int x, int y) {
    const Vec2 center{x + 0.5, y + 0.5};
    Expectation e;
    for (std::size_t k = 0; k < s.tris.size(); ++k) {
        const Tri& t = s.tris[k];
        const Shape& shape = shapes[k];
        if (t.aa > 0) {
            if (t.aa != 1 && t.aa != 2 && t.aa != 4 && t.aa != 8) continue;  // pinned: draws nothing
            int in = 0, amb = 0, closed = 0, open = 0;
            for (Vec2 p : samples(x, y, t.aa)) {
                const Side side = shape.classify(p).side;
                in += side == Side::kIn;
                amb += side == Side::kAmbiguous;
                if (shape.exact()) {
                    const auto [c, o] = shape.closed_open(p);
                    closed += c;
                    open += o;
                } else {
                    closed += side == Side::kIn;
                    open += side == Side::kIn;
                }
            }
            if (in + amb + closed == 0) continue;
            if (e.aa_tris++ == 0) e.before_aa = e.want;
            const double n2 = t.aa * t.aa;
            const Color c = t.c[0];
            e.aa_ambiguous |= amb > 0;
            e.aa_edge_samples |= closed != open;
            e.want = raster::mix(e.want, c, in / n2);
            e.want_hi = raster::mix(e.want_hi, c, (in + amb) / n2);
            e.alt_all = raster::mix(e.alt_all, c, closed / n2);
            e.alt_none = raster::mix(e.alt_none, c, open / n2);
            e.alt_flip = raster::mix(e.alt_flip, c, in / n2);
            e.alt_set = raster::mix(raster::colors::black, c, in / n2);
            if (shape.in_center_box(x, y)) {
                e.alt_box = raster::mix(e.alt_box, c, in / n2);
            } else {
                e.aa_box_skipped |= in > 0;
            }
            continue;
        }
        const Verdict v = shape.classify(center);
        e.on_edge |= v.on_edge;  // an edge through the center: the fill rule decides it
        const auto [closed, open] = shape.closed_open(center);
        const bool boundary = closed && !open;  // exactly on this triangle's edge
        if (v.side == Side::kAmbiguous) {
            e.lenient = true;
            continue;
        }
        Color color = t.c[0];
        Color lo = color, hi = color;
        double exact[3] = {};
        if (t.gradient && shape.exact() && closed) {
            shape.gradient_levels(t, center, lo, hi, exact);
            color = {static_cast<std::uint8_t>((lo.r + hi.r) / 2), static_cast<std::uint8_t>((lo.g + hi.g) / 2),
                     static_cast<std::uint8_t>((lo.b + hi.b) / 2)};
        } else if (t.gradient) {
            color = lo = hi = interpolate(t, shape.weights(center));
        }
        if (v.side == Side::kOut) {
            if (boundary) e.alt_flip = color;  // excluded by the fill rule; included, it would look so
            continue;
        }
        e.under = e.want;
        e.top = static_cast<int>(k);
        e.want = e.want_hi = e.alt_all = e.alt_none = e.alt_box = color;
        if (!boundary) e.alt_flip = color;  // a center on the boundary: excluded, alt_flip keeps what was below
        e.aa_tris = 0;
        e.aa_ambiguous = e.aa_edge_samples = e.aa_box_skipped = false;
        ++e.layers;
        e.gradient_exact = t.gradient && shape.exact();
        e.grad_lo = lo;
        e.grad_hi = hi;
        std::copy(exact, exact + 3, e.exact);
        // Is this pixel in the last row or column of the triangle's candidate pixels?
        const double max_x = std::max({t.v[0].x, t.v[1].x, t.v[2].x}), max_y = std::max({t.v[0].y, t.v[1].y, t.v[2].y});
        e.in_last = std::floor(max_x - 0.5) == x || std::floor(max_y - 0.5) == y;
    }
    return e;
}

// Every channel of c within [min(a, b) - tol, max(a, b) + tol].
bool within(Color c, Color a, Color b, int tol) {
    auto in = [tol](int v, int p, int q) { return v >= std::min(p, q) - tol && v <= std::max(p, q) + tol; };
    return in(c.r, a.r, b.r) && in(c.g, a.g, b.g) && in(c.b, a.b, b.b);
}

std::string str_exact(const double v[3]) {
    std::ostringstream m;
    m.setf(std::ios::fixed);
    m.precision(2);
    m << "(" << v[0] << ", " << v[1] << ", " << v[2] << ")";
    return m.str();
}

// What judge_pixels saw, for the findings judged after it.
struct PixelStats {
    long long wrong = 0;      // pixels judged wrong (not anti-aliased, not lenient)
    long long cw = 0;         // pixels whose expected top triangle is clockwise as listed
    long long cw_wrong = 0;   // ... of them wrong
};

// The picture one typical mistake draws with solid triangles, compared with the student's:
// `explained` collects the wrong pixels it draws the same way, `apart` counts the pixels where
// the two disagree about being wrong (wrong in one picture only, or wrong in another color).
struct MistakeModel {
    Tally explained;
    long long apart = 0;
    long long off_ties = 0;  // explained pixels whose center is not exactly on an edge
    double match() const { return explained.count == 0 ? 0 : double(explained.count) / double(explained.count + apart); }
    // Names the mistake when it explains nearly every wrong pixel, nearly every pixel it changes
    // is wrong in the student's picture too, and some of those pixels have their center off
    // every edge. A fill-rule mistake changes only centers exactly on an edge (ties), and where
    // a scene puts many centers on edges, moving the edges half a pixel flips much the same
    // ones: pixels off the ties tell the two apart (the mistakes here move whole edges).
    bool names_it() const {
        return explained.count >= 3 && match() >= 0.8 && off_ties >= 3 && off_ties * 20 >= explained.count;
    }
};

void judge_pixels(const Scene& s, const std::vector<Shape>& shapes, const Image& img, cp::Judgement& j,
                  PixelStats& stats) {
    const std::string topic = generic_topic(s.id);
    // Advice per kind of mistake; the generic topics of m2.huge, m2.degenerate and m2.nonfinite
    // keep their scene's hint.
    const bool plain = topic == "coverage";
    Tally missing{topic, "inside a triangle are not filled", "inside a triangle is not filled", plain ? "TODO 4" : "",
                  plain ? "Test every pixel center of the bounding box against the three edge functions: a center is "
                          "in when none is negative (a zero: the fill rule decides)." : ""};
    Tally missing_gradient{topic,
                           "inside a gradient triangle were left as they were: fill_triangle_gradient did not draw them",
                           "inside a gradient triangle was left as it was: fill_triangle_gradient did not draw it",
                           "TODO 5",
                           "fill_triangle_gradient covers exactly the pixels fill_triangle covers: set up, bounding box, "
                           "the same coverage test; only the color differs."};
    Tally extra{topic, "outside every triangle are filled", "outside every triangle is filled", plain ? "TODO 4" : "",
                plain ? "A pixel is drawn only when its center is inside all three edges; check the signs and which "
                        "edge function belongs to which pair of vertices." : ""};
    const bool only_aa = !s.tris.empty() && std::all_of(s.tris.begin(), s.tris.end(), [](const Tri& t) { return t.aa > 0; });
    // A pixel none of whose samples is inside, lit where only fill_triangle_aa draws (the whole
    // scene, or the neighbourhood of anti-aliased triangles alone): samples placed elsewhere lit it.
    const std::string sample_rest = " n * n sample positions is inside any triangle: the samples are not where the "
                                    "rule puts them (or coverage is counted outside the triangle)";
    Tally aa_extra{"supersampling", "are drawn, though none of their" + sample_rest,
                   "is drawn, though none of its" + sample_rest, "TODO 6",
                   "Sample (i, j) of pixel (x, y) is at (x + (i + 0.5) / n, y + (j + 0.5) / n): 16 * x + (2 * i + 1) * "
                   "8 / n in sixteenths, never at the pixel's corner."};
    const std::string rule_rest = " decided wrongly (top and left edges include such centers, bottom and right edges "
                                  "exclude them)";
    Tally rule{"fill rule", "have their center exactly on an edge and are" + rule_rest,
               "has its center exactly on an edge and is" + rule_rest, "TODO 4b",
               "Once the area is positive, edge a->b is top when b.y == a.y and b.x > a.x, left when b.y < a.y; a zero "
               "edge value counts only for those (set_up marks them, covers applies it)."};
    Tally last_row{"bounding box", "in the last row or column of a triangle's bounding box (or of the image) are missing",
                   "in the last row or column of a triangle's bounding box (or of the image) is missing", "TODO 3",
                   "PixelRect's ends are exclusive: x1 is one past the last column whose center is in range, and "
                   "clamped to the image it is at most width (not width - 1), y1 at most height."};
    Tally colors{"barycentric", "have the wrong interpolated color", "has the wrong interpolated color", "TODO 5",
                 "The weight of vertex k is the edge value of the edge OPPOSITE it divided by area2, in floating "
                 "point (integer division gives 0); round each channel to nearest with raster::to_channel."};
    const std::string aa_hint = "Samples sit at (x + (i + 0.5) / n, y + (j + 0.5) / n); coverage = covered samples / "
                                "(n * n), blended over the pixel with Image::blend.";
    Tally aa_wrong{"supersampling", "have the wrong coverage for their number of covered samples",
                   "has the wrong coverage for its number of covered samples", "TODO 6", aa_hint};
    const std::string unwritten_rest = " but fill_triangle_aa left unchanged: either it never blended there, or it "
                                       "blended with coverage 0 (covered / (n * n) in integers is 0 until every "
                                       "sample is covered: divide as double)";
    Tally aa_unwritten{"supersampling", "have covered samples" + unwritten_rest, "has covered samples" + unwritten_rest,
                       "TODO 6", aa_hint};
    const std::string box_rest = " outside the triangle's bounding_box(): that box holds the pixels whose CENTERS can "
                                 "be inside, but a sample off the center reaches the pixels around it too. "
                                 "fill_triangle_aa must visit every pixel the triangle's box overlaps";
    Tally aa_box{"aa bounding box", "have covered samples but were never written, and their centers lie" + box_rest,
                 "has covered samples but was never written, and its center lies" + box_rest, "TODO 6",
                 "Loop from floor(min / 16) to ceil(max / 16) in sixteenths on each axis, clamped to the image: every "
                 "pixel the vertices' box overlaps, not bounding_box()."};
    const std::string set_rest = " only the last triangle's coverage over black, as if the pixel was set instead of "
                                 "blended: use Image::blend, which mixes the color over what is already there";
    Tally aa_set{"supersampling", "show" + set_rest, "shows" + set_rest, "TODO 6",
                 "img.blend(x, y, c, coverage) mixes over the pixel's current color; do not set a color mixed with "
                 "black."};
    const std::string aa_rule_rest = " samples exactly on an edge counted wrongly (the coverage matches counting every "
                                     "such sample, or none): apply the top-left rule to each sample, as to a pixel "
                                     "center. If m2.top_left fails too, the rule itself is wrong (TODO 4b, covers()); "
                                     "if it passes, fill_triangle_aa does not test its samples with covers() (TODO 6)";
    Tally aa_rule{"fill rule", "have" + aa_rule_rest, "has" + aa_rule_rest, "TODO 4b or 6",
                  "Test each sample with the same covers() as a pixel center: a sample on an edge counts only for a "
                  "top or left edge; m2.top_left checks covers() alone."};
    // How often each wrong color of a gradient pixel occurs (see `flat` below).
    std::map<Color, long long, bool (*)(Color, Color)> wrong_gradient_colors{
        [](Color a, Color b) { return std::tie(a.r, a.g, a.b) < std::tie(b.r, b.g, b.b); }};
    // Two mistakes of fill_triangle's loop move pixels far beyond the edges' ties, so the
    // fill-rule and coverage tallies would misname them; their pictures are computed here
    // (solid triangles only, where a pixel's color says which triangle drew it):
    //  * sampling pixel (x, y) at its top-left corner, 16x and 16y in sixteenths: every edge
    //    moves half a pixel right and down, along its whole length;
    //  * an incremental walk whose steps are the per-sixteenth change of each edge function
    //    instead of the per-pixel one (16 times it): from the first center of the box, pixel
    //    (x0 + i, y0 + j) sees the point i and j SIXTEENTHS further, the triangle magnified 16
    //    times about that center.
    const bool solid_only = !s.tris.empty() && std::all_of(s.tris.begin(), s.tris.end(), [](const Tri& t) {
        return t.aa == 0 && !t.gradient;
    });
    struct Box {
        bool any = false;
        int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
        // Pixel (x, y) is in the box grown by a pixel (samples reach past the centers' box).
        bool near(int x, int y) const { return any && x >= x0 - 1 && x <= x1 && y >= y0 - 1 && y <= y1; }
    };
    std::vector<Box> boxes(shapes.size());
    for (std::size_t k = 0; k < shapes.size(); ++k) {
        Box& b = boxes[k];
        b.any = shapes[k].snapped_box(s.width, s.height, b.x0, b.y0, b.x1, b.y1);
    }
    // Whether pixel (x, y) lies near triangles of one kind only (anti-aliased or not): in the
    // box of one of them grown by a pixel (samples reach past the centers' box), and in no such
    // box of the other kind.
    auto near_only = [&](int x, int y, bool aa) {
        bool near_kind = false;
        for (std::size_t k = 0; k < shapes.size(); ++k) {
            if (!boxes[k].near(x, y)) continue;
            if ((s.tris[k].aa > 0) != aa) return false;
            near_kind = true;
        }
        return near_kind;
    };
    // Whether pixel (x, y) lies in the box (grown by a pixel) of an anti-aliased triangle whose
    // sample count is not supported, and so must not be drawn.
    auto near_unsupported_n = [&](int x, int y) {
        for (std::size_t k = 0; k < shapes.size(); ++k) {
            const int n = s.tris[k].aa;
            if (n > 0 && n != 1 && n != 2 && n != 4 && n != 8 && boxes[k].near(x, y)) return true;
        }
        return false;
    };
    auto corner_picture = [&](int x, int y) {
        Color c = raster::colors::black;
        for (std::size_t k = 0; k < shapes.size(); ++k) {
            if (shapes[k].snapped_covers(16LL * x, 16LL * y)) c = s.tris[k].c[0];
        }
        return c;
    };
    auto unscaled_step_picture = [&](int x, int y) {
        Color c = raster::colors::black;
        for (std::size_t k = 0; k < shapes.size(); ++k) {
            const Box& b = boxes[k];
            if (!b.any || x < b.x0 || x >= b.x1 || y < b.y0 || y >= b.y1) continue;
            if (shapes[k].snapped_covers(16LL * b.x0 + 8 + (x - b.x0), 16LL * b.y0 + 8 + (y - b.y0))) c = s.tris[k].c[0];
        }
        return c;
    };
    MistakeModel at_corner{Tally{"pixel center",
        "are wrong exactly as if each pixel were tested at its top-left corner (x, y) instead of its center "
        "(x + 0.5, y + 0.5): every edge of your triangles sits half a pixel too far right and down, along its whole "
        "length, not only where a center lies exactly on it. triangles.h pins the pixel center; the loop of TODO 4c "
        "(fill_triangle) must test the point 16x + 8, 16y + 8 in sixteenths, not 16x, 16y",
        "is wrong exactly as if each pixel were tested at its top-left corner (x, y) instead of its center "
        "(x + 0.5, y + 0.5). triangles.h pins the pixel center; the loop of TODO 4c (fill_triangle) must test the "
        "point 16x + 8, 16y + 8 in sixteenths, not 16x, 16y",
        "TODO 4c",
        "Pixel (x, y) is covered when its center is: Fixed{16 * x + 8, 16 * y + 8}, that is kSubpixelSteps * x + "
        "kSubpixelSteps / 2 on each axis."}};
    MistakeModel unscaled_step{Tally{"incremental steps",
        "are wrong exactly as if the edge values were stepped in the wrong units: moving one pixel right changes "
        "edge a->b by -(b.y - a.y) times the pixel's width in sixteenths, 16, but your steps add -(b.y - a.y) "
        "alone, the change for one SIXTEENTH. So the picture is each triangle magnified 16 times about the first "
        "pixel of its box. In the loop of TODO 4c (fill_triangle), multiply both steps by kSubpixelSteps (or "
        "compute each center's edge values anew)",
        "is wrong exactly as if the edge values were stepped in the wrong units: one pixel right changes edge "
        "a->b by -(b.y - a.y) * 16, not -(b.y - a.y). In the loop of TODO 4c (fill_triangle), multiply both steps "
        "by kSubpixelSteps",
        "TODO 4c",
        "A pixel is kSubpixelSteps sixteenths wide: the step of edge a->b per pixel is -(b.y - a.y) * 16 to the "
        "right and (b.x - a.x) * 16 downward, since the edge values are in (1/16 pixel)^2."}};

    bool has_aa = false, has_gradient = false;
    // A pixel lit where only a call with an unsupported sample count n could have drawn it.
    const std::string bad_n_rest = " where only a fill_triangle_aa call with an unsupported sample count (n other than "
                                   "1, 2, 4 and 8) could have drawn, and such a call must draw nothing";
    Tally bad_n{"bad input", "are drawn" + bad_n_rest, "is drawn" + bad_n_rest, "TODO 6",
                "At the top of fill_triangle_aa: return unless n is 1, 2, 4 or 8 (their sample positions are points "
                "of the 1/16 grid; other n are not)."};
    for (Tally* t : {&missing, &missing_gradient, &extra, &aa_extra, &bad_n, &rule, &last_row, &colors, &aa_wrong, &aa_unwritten, &aa_box,
                     &aa_rule, &aa_set}) {
        t->wrong = &j.tolerance.wrong;
    }

    for (int y = 0; y < s.height; ++y) {
        for (int x = 0; x < s.width; ++x) {
            const Expectation e = expect_pixel(s, shapes, x, y);
            const Color got = img.at(x, y);
            const bool gradient_top = e.top >= 0 && s.tris[e.top].gradient;
            const bool image_edge = x == s.width - 1 || y == s.height - 1;
            has_gradient |= gradient_top;
            if (e.aa_tris > 0) {
                // Anti-aliased triangles on top: each channel must match the covered-sample
                // counts, blended in order (a range where samples are ambiguous).
                has_aa = true;
                j.tolerance.lenient.set(x, y);  // judged here, with the sample-count range
                if (e.lenient || (e.aa_ambiguous && e.aa_tris + e.layers > 1)) continue;
                if (within(got, e.want, e.want_hi, 2)) continue;
                const std::string detail =
                    " is " + str(got) + ", expected " + str(e.want) + (e.want_hi != e.want ? " to " + str(e.want_hi) : "");
                if (e.aa_box_skipped && within(got, e.alt_box, e.alt_box, 2)) {
                    aa_box.add(x, y);
                } else if (got == e.before_aa) {
                    aa_unwritten.add(x, y);
                } else if (e.aa_edge_samples && (within(got, e.alt_all, e.alt_all, 2) || within(got, e.alt_none, e.alt_none, 2))) {
                    aa_rule.add(x, y, detail);
                } else if (!within(e.alt_set, e.want, e.want_hi, 2) && within(got, e.alt_set, e.alt_set, 2)) {
                    aa_set.add(x, y, detail);
                } else {
                    aa_wrong.add(x, y, detail);
                }
                continue;
            }
            if (e.lenient) {
                j.tolerance.lenient.set(x, y);
                continue;
            }
            const int tol = gradient_top && !e.gradient_exact ? 2 : 0;  // off the grid: snapping moves weights
            const bool ok = e.gradient_exact && gradient_top ? within(got, e.grad_lo, e.grad_hi, 0) : near(got, e.want, tol);
            const bool cw = e.top >= 0 && shapes[std::size_t(e.top)].clockwise();
            stats.wrong += !ok;
            stats.cw += cw;
            stats.cw_wrong += cw && !ok;
            if (solid_only) {
                for (auto [model, picture] : {std::pair{&at_corner, corner_picture(x, y)},
                                              std::pair{&unscaled_step, unscaled_step_picture(x, y)}}) {
                    if (!ok && got == picture) {
                        model->explained.add(x, y);
                        model->off_ties += !e.on_edge;
                    } else if (!ok || picture != e.want) {
                        ++model->apart;
                    }
                }
            }
            if (ok) continue;
            if (e.on_edge && !near(e.alt_flip, e.want, 2) && near(got, e.alt_flip, gradient_top ? 2 : 0)) {
                rule.add(x, y);
            } else if (e.top < 0 && near_unsupported_n(x, y)) {
                bad_n.add(x, y);
            } else if (e.top < 0) {
                (plain && (only_aa || near_only(x, y, true)) ? aa_extra : extra).add(x, y);
            } else if (got == e.under || (image_edge && got == raster::colors::black)) {
                // (In the image's last column or row, nothing drawn at all: no triangle's box reached it.)
                (e.in_last || image_edge ? last_row : gradient_top ? missing_gradient : missing).add(x, y);
            } else if (gradient_top) {
                ++wrong_gradient_colors[got];
                colors.add(x, y, " is " + str(got) + ", expected " + str(e.want) +
                                     (e.gradient_exact ? " (exact " + str_exact(e.exact) + ", rounded to nearest)" : ""));
            } else {
                missing.add(x, y, " has the wrong color " + str(got) + ", expected " + str(e.want));
            }
        }
    }
    j.tolerance.strict_channel_diff = has_aa ? 2 : has_gradient ? 1 : 0;
    // Nothing drawn at all (the untouched skeleton, or an early return): one plain finding.
    bool blank = true;
    for (int y = 0; y < s.height && blank; ++y) {
        for (int x = 0; x < s.width && blank; ++x) blank = img.at(x, y) == raster::colors::black;
    }
    const long long wrong = missing.count + missing_gradient.count + rule.count + last_row.count + colors.count + aa_wrong.count +
                            aa_unwritten.count + aa_box.count + aa_rule.count + aa_set.count;
    if (blank && wrong > 0) {
        // Name the functions this scene calls: one of them (or all) is still a stub.
        bool solid = false, gradient = false, aa = false;
        for (const Tri& t : s.tris) {
            aa |= t.aa > 0;
            gradient |= t.aa == 0 && t.gradient;
            solid |= t.aa == 0 && !t.gradient;
        }
        std::string calls;
        for (const auto& [used, name] : {std::pair{solid, "fill_triangle (TODO 4)"},
                                         std::pair{gradient, "fill_triangle_gradient (TODO 5)"},
                                         std::pair{aa, "fill_triangle_aa (TODO 6)"}}) {
            if (used) calls += (calls.empty() ? "" : ", ") + std::string(name);
        }
        j.findings.push_back({"coverage", "nothing is drawn, but " + std::to_string(wrong) +
                                              " pixels should be; this scene draws with " + calls});
        return;
    }
    // Missing pixels only in last rows/columns point at the bounding box; mixed with others,
    // they are ordinary misses. Likewise unwritten anti-aliased pixels only outside the center
    // boxes point at the box of fill_triangle_aa.
    if (missing.count + missing_gradient.count > 0 && last_row.count > 0) {
        (missing.count > 0 ? missing : missing_gradient).count += last_row.count;
        last_row.count = 0;
    }
    if (aa_unwritten.count > 0 && aa_box.count > 0) {
        aa_unwritten.count += aa_box.count;
        aa_box.count = 0;
    }
    // Wrong gradient pixels nearly all of one color: the weights do not vary from pixel to pixel,
    // so they are not the edge values over area2. Integer division does that (0 but at the
    // vertices), and so does a covers() that fills e[] with the values' signs (TODO 4b): shade
    // divides 1 by area2.
    if (colors.count >= 10) {
        const auto flat = std::max_element(wrong_gradient_colors.begin(), wrong_gradient_colors.end(),
                                           [](const auto& a, const auto& b) { return a.second < b.second; });
        if (10 * flat->second >= 9 * colors.count) {
            colors.todo = "TODO 5 or 4b";
            colors.hint = (flat->second == colors.count ? "All " + std::to_string(colors.count)
                                                        : std::to_string(flat->second) + " of the " +
                                                              std::to_string(colors.count)) +
                          " wrong pixels are " + str(flat->first) + ": the weights do not change across the triangle. Either they are computed with integer "
                          "division (0 everywhere but at the vertices), or covers() (TODO 4b) fills e[] with "
                          "something other than the edge values themselves, such as their signs. The weight of "
                          "vertex k is the edge value of the edge opposite k over area2, in floating point.";
        }
    }
    // One of the two loop mistakes above explains the picture: it leads, and the fill-rule
    // finding goes (its pixels are among the ones it names; the ties were not the problem).
    const MistakeModel* lead = nullptr;
    for (const MistakeModel* m : {&at_corner, &unscaled_step}) {
        if (m->names_it() && (lead == nullptr || m->match() > lead->match())) lead = m;
    }
    if (lead != nullptr) {
        lead->explained.report(j);
        rule.count = 0;
    }
    // Where only fill_triangle_aa draws, a pixel lit though none of its samples is inside (none
    // on an edge either: those are lenient) shows samples in the wrong place, whatever else is
    // wrong: a fill-rule slip cannot light it. That finding leads; the edge-sample tally after
    // it may be the same misplaced samples, landing on the edges by chance.
    for (const Tally* t : {&bad_n, &aa_extra, &rule, &aa_rule, &last_row, &aa_box, &missing, &missing_gradient, &extra, &colors,
                           &aa_unwritten, &aa_set, &aa_wrong}) {
        t->report(j);
    }
}

// For scenes of white anti-aliased triangles on black that do not overlap (m2.aa_*): the
// mean difference between each pixel's coverage (its intensity) and the exact area of the
// triangle inside it, over every pixel that either is nonzero. Reported, not judged: it is
// the "error" half of the error-against-time table.
void measure_area_error(const Scene& s, const std::vector<Shape>& shapes, const Image& img, cp::Judgement& j) {
    for (const Tri& t : s.tris) {
        if (t.aa == 0 || t.c[0] != raster::colors::white) return;
    }
    double total = 0;
    long long pixels = 0;
    for (int y = 0; y < s.height; ++y) {
        for (int x = 0; x < s.width; ++x) {
            double area = 0;
            for (const Shape& shape : shapes) area += shape.area_in_pixel(x, y);
            const double level = img.at(x, y).r / 255.0;
            if (area <= 0 && level <= 0) continue;
            total += std::abs(level - std::min(area, 1.0));
            ++pixels;
        }
    }
    if (pixels > 0) j.measures["coverage error vs exact area (mean, 0..1)"] = total / pixels;
}

// Watertightness: the triangles tile a region, so a pixel whose center is certainly inside
// that region must be covered exactly once, and one near its outer boundary at most once.
void judge_watertight(const Scene& s, const std::vector<Shape>& shapes, const Image& count, cp::Judgement& j) {
    const std::string rule_hint = "Two triangles see a shared edge in opposite directions: with the top-left rule exactly "
                                  "one of them counts a center on it. Compare edge values with 0 exactly (integers).";
    Tally twice{"fill rule", "are covered by two or more triangles (double coverage on a shared edge)",
                "is covered by two or more triangles (double coverage on a shared edge)", "TODO 4b", rule_hint};
    Tally gaps{"watertight", "inside the mesh are covered by no triangle (a gap on a shared edge)",
               "inside the mesh is covered by no triangle (a gap on a shared edge)", "TODO 4b", rule_hint};
    // The outer boundary: edges used by one triangle only.
    std::vector<std::pair<Vec2, Vec2>> boundary;
    auto same = [](Vec2 a, Vec2 b) { return a.x == b.x && a.y == b.y; };
    for (std::size_t k = 0; k < s.tris.size(); ++k) {
        for (int i = 0; i < 3; ++i) {
            const Vec2 a = s.tris[k].v[i], b = s.tris[k].v[(i + 1) % 3];
            bool shared = false;
            for (std::size_t m = 0; m < s.tris.size() && !shared; ++m) {
                for (int q = 0; q < 3 && m != k; ++q) {
                    const Vec2 c = s.tris[m].v[q], d = s.tris[m].v[(q + 1) % 3];
                    shared |= (same(a, d) && same(b, c)) || (same(a, c) && same(b, d));
                }
            }
            if (!shared) boundary.push_back({a, b});
        }
    }
    auto near_boundary = [&](Vec2 p) {
        for (const auto& [a, b] : boundary) {
            const Vec2 d = b - a;
            const double t = std::clamp(raster::dot(p - a, d) / raster::dot(d, d), 0.0, 1.0);
            if (raster::length(p - (a + t * d)) <= kMargin) return true;
        }
        return false;
    };
    // Nothing drawn at all is not a gap between triangles: the coverage finding says it.
    bool any = false;
    for (int y = 0; y < s.height && !any; ++y) {
        for (int x = 0; x < s.width && !any; ++x) any = count.at(x, y) != raster::colors::black;
    }
    if (!any) return;
    for (int y = 0; y < s.height; ++y) {
        for (int x = 0; x < s.width; ++x) {
            const Vec2 center{x + 0.5, y + 0.5};
            int in = 0, amb = 0;
            for (const Shape& shape : shapes) {
                const Side side = shape.classify(center).side;
                in += side == Side::kIn;
                amb += side == Side::kAmbiguous;
            }
            const Color c = count.at(x, y);  // encoding: see render.cpp
            const int got = c == raster::colors::black ? 0 : c.r == 255 ? c.b : 1;
            if (got > 1) twice.add(x, y);
            else if (got == 0 && in + amb > 0 && !near_boundary(center)) gaps.add(x, y);
        }
    }
    twice.report(j);
    gaps.report(j);
}

void judge_numbers(const Scene& s, const cp::Artifacts& art, cp::Judgement& j) {
    auto value = [&](const std::string& k) {
        const auto it = art.values.find(k);
        return it == art.values.end() ? std::nan("") : it->second;
    };
    const std::string snap_hint = "Reject NaN, infinity and |coordinate| > kMaxCoordinate first, then std::llround(x * 16) "
                                  "for each coordinate.";
    for (std::size_t i = 0; i < s.numbers.snaps.size(); ++i) {
        const Vec2 p = s.numbers.snaps[i];
        const std::string key = "snap." + std::to_string(i) + ".";
        const bool ok = raster::is_finite(p) && std::abs(p.x) <= kMaxCoordinate && std::abs(p.y) <= kMaxCoordinate;
        if ((value(key + "ok") == 1) != ok) {
            j.findings.push_back(finding("snap", "snap" + str(p) + " returned " + (ok ? "false" : "true") + ", expected " +
                                                     (ok ? "true" : "false (not finite, or beyond kMaxCoordinate)"),
                                         "TODO 1", snap_hint));
        } else if (ok && (value(key + "x") != std::round(p.x * 16) || value(key + "y") != std::round(p.y * 16))) {
            std::ostringstream m;
            // Which part of the rule: a half (x * 16 ends in .5) goes away from zero; otherwise the nearest.
            auto off_by_half = [&](double c, double got) {
                const double t = c * 16;
                return t - std::floor(t) == 0.5 && got != std::round(t) && std::abs(got - t) == 0.5;
            };
            const bool halves = off_by_half(p.x, value(key + "x")) || off_by_half(p.y, value(key + "y"));
            m << "snap" << str(p) << " gave (" << value(key + "x") << ", " << value(key + "y") << "), expected ("
              << std::round(p.x * 16) << ", " << std::round(p.y * 16) << ") sixteenths "
              << (halves ? "(a half goes AWAY from zero, as std::llround does: -0.5 sixteenths is -1, not 0)"
                         : "(the nearest sixteenth, not truncated)");
            j.findings.push_back(finding("snap", m.str(), "TODO 1", snap_hint));
        }
    }
    for (std::size_t i = 0; i < s.numbers.boxes.size(); ++i) {
        const auto& v = s.numbers.boxes[i];
        i128 g[3][2];
        for (int k = 0; k < 3; ++k) {
            g[k][0] = static_cast<i128>(std::llround(v[k].x * 16));
            g[k][1] = static_cast<i128>(std::llround(v[k].y * 16));
        }
        const i128 e = (g[1][0] - g[0][0]) * (g[2][1] - g[0][1]) - (g[1][1] - g[0][1]) * (g[2][0] - g[0][0]);
        const double low = double(static_cast<std::uint64_t>(static_cast<std::int64_t>(e)) & 0xFFFF);
        const std::string edge_hint =
            "edge(a, b, p) = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x), in 64-bit integers on the sixteenths.";
        if (value("edge." + std::to_string(i)) != double(e)) {
            std::ostringstream m;
            m << "edge(v0, v1, v2) for vertices " << str(v[0]) << " " << str(v[1]) << " " << str(v[2]) << " gave "
              << value("edge." + std::to_string(i)) << ", expected " << double(e)
              << " = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) in sixteenths";
            j.findings.push_back(finding("edge function", m.str(), "TODO 2", edge_hint));
        } else if (value("edge." + std::to_string(i) + ".low") != low) {
            // Right to 53 bits, wrong in the last ones: products rounded (computed in double).
            std::ostringstream m;
            // The exact value in digits (an int128 has no operator<<).
            std::string digits;
            for (i128 r = e < 0 ? -e : e; digits.empty() || r > 0; r /= 10) digits.insert(digits.begin(), char('0' + int(r % 10)));
            m << "edge(v0, v1, v2) for vertices " << str(v[0]) << " " << str(v[1]) << " " << str(v[2])
              << " must be exactly " << (e < 0 ? "-" : "") << digits << "; yours is close, but its last 16 bits are "
              << value("edge." + std::to_string(i) + ".low") << ", not " << low
              << ". A value this large needs 57 bits; a double keeps 53, so products computed in double (or float) "
                 "come out a few units off. Multiply the int64 differences as int64";
            j.findings.push_back(finding("edge function", m.str(), "TODO 2", edge_hint));
        }
        // Pixel x is in the box when its center x + 0.5 lies in [min x, max x] (of the snapped
        // vertices), clamped to the image.
        auto range = [&](int axis, int size) {
            const double lo = std::min({g[0][axis], g[1][axis], g[2][axis]}) / 16.0;
            const double hi = std::max({g[0][axis], g[1][axis], g[2][axis]}) / 16.0;
            const double first = std::clamp(std::ceil(lo - 0.5), 0.0, double(size));
            const double end = std::clamp(std::floor(hi - 0.5) + 1, 0.0, double(size));
            return std::pair<double, double>{first, end};
        };
        const auto [x0, x1] = range(0, s.width);
        const auto [y0, y1] = range(1, s.height);
        const std::string key = "box." + std::to_string(i) + ".";
        const double gx0 = value(key + "x0"), gx1 = value(key + "x1"), gy0 = value(key + "y0"), gy1 = value(key + "y1");
        const bool want_empty = x0 >= x1 || y0 >= y1, got_empty = gx0 >= gx1 || gy0 >= gy1;
        if (want_empty != got_empty || (!want_empty && (gx0 != x0 || gx1 != x1 || gy0 != y0 || gy1 != y1))) {
            std::ostringstream m;
            m << "bounding_box for " << str(v[0]) << " " << str(v[1]) << " " << str(v[2]) << " gave [" << gx0 << ", "
              << gx1 << ") x [" << gy0 << ", " << gy1 << "), expected [" << x0 << ", " << x1 << ") x [" << y0 << ", "
              << y1 << ")" << (want_empty ? " (empty)" : "");
            j.findings.push_back(finding("bounding box", m.str(), "TODO 3",
                                         "First column: ceil((min_x - 8) / 16); end: floor((max_x - 8) / 16) + 1, with a "
                                         "floor division that rounds negative numbers down; then clamp to the image."));
        }
    }
}

}  // namespace

cp::Judgement judge(const std::string& id, const cp::Artifacts& art, const cp::Artifacts& /*reference*/,
                    const raster::Image& /*expected*/) {
    const Scene& s = scene(id);
    cp::Judgement j;
    const Image* main = cp::main_image_for_judging(art, s.width, s.height, j);
    if (main == nullptr) return j;  // the harness reports a missing or mis-sized image
    // Stray writes: each function that made them (the trace says) loops over a box that was
    // not clamped to the image, which TODO 3 does.
    const auto stray = [](const std::string& function, long long count) {
        // fill_triangle_aa loops over a box of its own (the pixels the vertices' box overlaps).
        const bool aa = function.find("fill_triangle_aa") != std::string::npos;
        return finding("bounding box",
                       function + " asked to write " + cp::plural(double(count), "pixel") +
                           " outside the image (Image::stray_writes): " +
                           (aa ? "clamp fill_triangle_aa's box (the pixels the vertices' box overlaps) to the image, "
                                 "as bounding_box() clamps its own, and loop only over that box"
                               : "clamp the bounding box to the image (in bounding_box), and loop only over that box"),
                       aa ? "TODO 6" : "TODO 3");
    };
    j.findings = cp::stray_write_findings(
        art, stray, finding("bounding box", "clamp the bounding box to the image, and loop only over that box", "TODO 3"));
    const Image& img = *main;
    std::vector<Shape> shapes;
    for (const Tri& t : s.tris) shapes.emplace_back(t);
    // The numbers' findings come first (m2.edge_and_box: TODOs 1-3 before the picture's 4).
    const std::size_t numbers_at = j.findings.size();
    PixelStats stats;
    judge_pixels(s, shapes, img, j, stats);
    if (!s.tris.empty()) measure_area_error(s, shapes, img, j);
    if (s.watertight) {
        const auto count = art.images.find("count");
        if (count != art.images.end() && count->second.width() == s.width && count->second.height() == s.height) {
            judge_watertight(s, shapes, count->second, j);
        }
    }
    if (s.check_winding) {
        // Identical pixels, except that a gradient pixel whose exact value is within the tie
        // window may take either accepted level in each winding (float sums in another order).
        const auto other = art.images.find("other_winding");
        const bool sized = other != art.images.end() && other->second.width() == s.width && other->second.height() == s.height;
        long long differ = 0, colors_only = 0;  // colors_only: a gradient pixel filled in both orders
        long long black_in_one = 0;             // of those, black in one order: negative or zero weights
        std::string first;  // where, for the student to look: "at (x, y): ... as listed, ... reversed"
        for (int y = 0; sized && y < s.height; ++y) {
            for (int x = 0; x < s.width; ++x) {
                const Color a = img.at(x, y), b = other->second.at(x, y);
                if (a == b) continue;
                const Expectation e = expect_pixel(s, shapes, x, y);
                const bool gradient = e.top >= 0 && s.tris[e.top].gradient;
                const bool tie = gradient && e.gradient_exact && e.grad_lo != e.grad_hi;
                const bool counted = !(tie && within(a, e.grad_lo, e.grad_hi, 0) && within(b, e.grad_lo, e.grad_hi, 0));
                differ += counted;
                if (counted && first.empty()) {
                    first = "; the first at (" + std::to_string(x) + ", " + std::to_string(y) + "): " + str(a) +
                            " as listed, " + str(b) + " in the other order";
                }
                // Filled by the gradient triangle on top in both orders: neither is the color
                // under it (which a fill-rule change would show).
                colors_only += counted && gradient && a != e.under && b != e.under;
                black_in_one += counted && gradient && (a == raster::colors::black) != (b == raster::colors::black);
            }
        }
        if (sized && differ > 0 && colors_only == differ) {
            // Both orders fill the same pixels; only the gradient's colors move: the winding is
            // fixed (TODO 4a), but the colors did not follow their vertices (TODO 5).
            // It leads when the main picture's errors are the clockwise triangles' (their colors
            // are what moved): a barycentric finding about the same pixels would send the student
            // to the weights, which are right for the other winding.
            const bool clockwise_wrong = stats.cw_wrong > 0 && stats.cw_wrong * 10 >= stats.wrong * 9;
            // Black in one order nearly everywhere: that order's weights are negative (divided by
            // the signed area as listed, before the swap made it positive), not exchanged colors.
            const bool negative_weights = black_in_one * 10 >= differ * 9;
            j.findings.insert(clockwise_wrong ? j.findings.begin() + std::ptrdiff_t(numbers_at) : j.findings.end(),
                              negative_weights
                                  ? finding("winding",
                                            "listing each triangle's vertices in the other order filled the same "
                                            "pixels, but " + cp::plural(double(black_in_one), "gradient pixel") +
                                                " came out black in one of the orders" + first +
                                                " (see other_winding.png): there every weight was negative or zero, "
                                                "as when the edge values of the swapped (counter-clockwise) triangle "
                                                "are divided by the area as listed, which is negative for a "
                                                "clockwise triangle",
                                            "TODO 5",
                                            "after set_up's swap, divide by the swapped triangle's area2 (positive), "
                                            "the one its edge values belong to; and exchange the colors of the two "
                                            "vertices it exchanged.")
                                  : finding("winding",
                                      "listing each triangle's vertices in the other order filled the same pixels "
                                      "but changed the color of " + cp::plural(double(differ), "gradient pixel") +
                                          first + " (see other_winding.png): the colors did not follow their vertices. "
                                          "When a clockwise triangle's vertices are exchanged, fill_triangle_gradient "
                                          "must exchange the colors of the same two vertices, so each color stays "
                                          "with its vertex",
                                      "TODO 5",
                                      "exchange the colors of exactly the two vertices set_up exchanged: c1 and c2 "
                                      "for the skeleton's set_up (Setup::swapped says it exchanged v[1] and v[2]); "
                                      "c0 and c1 if your own code exchanges v[0] and v[1]."));
        } else if (differ > 0 || (!sized && art.values.count(cp::kRunawayKey) == 0)) {
            // (No other_winding image after a runaway loop: the render stopped before drawing
            // it, the runaway finding says so, and there is nothing to compare.)
            // When the main picture's errors are the clockwise triangles, wholesale (nearly all
            // of their pixels wrong, nearly every wrong pixel theirs), the winding is the cause
            // and leads: a precision or coverage finding about the same pixels would send the
            // student elsewhere (m2.huge's generic topic is "precision").
            const bool clockwise_wrong = stats.cw_wrong > 0 && stats.cw_wrong * 10 >= stats.cw * 9 &&
                                         stats.cw_wrong * 10 >= stats.wrong * 9;
            j.findings.insert(clockwise_wrong ? j.findings.begin() + std::ptrdiff_t(numbers_at) : j.findings.end(),
                              finding("winding",
                                         "listing each triangle's vertices in the other order changed " +
                                             cp::plural(double(differ), "pixel") + first +
                                             " (see other_winding.png, the picture drawn in the other order): both "
                                             "windings must give the same pixels",
                                         "TODO 4a",
                                         clockwise_wrong
                                             ? "Your clockwise triangles (negative signed area as listed) are wrong nearly "
                                               "everywhere, the others right: set_up must swap two vertices (v1 and v2; "
                                               "in fill_triangle_gradient, their colors too) when the area is negative. Skipping such a triangle, or making its area "
                                               "positive (|area|) without the swap, draws none of it: unswapped, the "
                                               "vertices stay clockwise, so every edge function has the wrong sign inside "
                                               "and no center passes."
                                             : "If the signed area is negative, swap v1 and v2 (and, in "
                                               "fill_triangle_gradient, their colors) before testing; do not skip the "
                                               "triangle or flip the fill rule."));
        }
    }
    if (!s.numbers.snaps.empty() || !s.numbers.boxes.empty()) {
        cp::Judgement numbers;
        judge_numbers(s, art, numbers);
        j.findings.insert(j.findings.begin() + std::ptrdiff_t(numbers_at), numbers.findings.begin(), numbers.findings.end());
    }

    j.tolerance.max_lenient_diffs = j.tolerance.lenient.count();
    j.tolerance.why = "the lenient pixels have a sample within 1/16 pixel of an edge (snapping decides them) or "
                      "an anti-aliased coverage already judged against its range of covered samples";
    return j;
}

}  // namespace m2cp
