// Judge half of the milestone-1 checkpoints: decides from the scene (trusted data), the
// artifacts and nothing else. It never calls the code under test or the reference; its
// oracles are written independently (exact integer arithmetic for Bresenham, Liang-Barsky for
// clipping, "coverage = 1 - distance" for Wu) so a bug shared with the reference is unlikely.
#include "m1/judge.h"
#include "harness/judging.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <deque>
#include <optional>
#include <sstream>

#include "m1/scenes.h"

namespace m1cp {

namespace {

using raster::Image;
using raster::Mask;

struct Pix {
    int x = 0, y = 0;
};

std::string str(Vec2 p) {
    std::ostringstream s;
    s << "(" << p.x << ", " << p.y << ")";
    return s.str();
}
std::string str(Pix p) { return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")"; }

// Liang-Barsky: the part of p0-p1 inside the closed box, or nothing.
std::optional<std::pair<Vec2, Vec2>> clip_oracle(Vec2 p0, Vec2 p1, const Box& r) {
    const Vec2 d = p1 - p0;
    double t0 = 0, t1 = 1;
    // Keep the t where p0 + t * d satisfies p * t <= q.
    auto edge = [&](double p, double q) {
        if (p == 0) return q >= 0;
        const double t = q / p;
        if (p < 0) {
            if (t > t1) return false;
            t0 = std::max(t0, t);
        } else {
            if (t < t0) return false;
            t1 = std::min(t1, t);
        }
        return true;
    };
    if (!edge(-d.x, p0.x - r.xmin) || !edge(d.x, r.xmax - p0.x) || !edge(-d.y, p0.y - r.ymin) ||
        !edge(d.y, r.ymax - p0.y)) {
        return std::nullopt;
    }
    auto clamp = [&](Vec2 p) {
        return Vec2{std::clamp(p.x, r.xmin, r.xmax), std::clamp(p.y, r.ymin, r.ymax)};
    };
    const Vec2 q0 = t0 == 0 ? p0 : clamp(p0 + t0 * d);
    const Vec2 q1 = t1 == 1 ? p1 : clamp(p0 + t1 * d);
    return std::make_pair(q0, q1);
}

int outcode_oracle(Vec2 p, const Box& r) {
    return (p.x < r.xmin ? 1 : 0) | (p.x > r.xmax ? 2 : 0) | (p.y < r.ymin ? 4 : 0) |
           (p.y > r.ymax ? 8 : 0);
}

std::string describe_direction(long long dx, long long dy) {
    if (dx == 0 && dy == 0) return "a single pixel";
    if (dy == 0) return dx > 0 ? "horizontal, going right" : "horizontal, going left";
    if (dx == 0) return dy > 0 ? "vertical, going down" : "vertical, going up";
    if (std::llabs(dx) == std::llabs(dy)) return "diagonal";
    const bool steep = std::llabs(dy) > std::llabs(dx);
    int octant;
    if (dx > 0 && dy > 0) octant = steep ? 2 : 1;
    else if (dx < 0 && dy > 0) octant = steep ? 3 : 4;
    else if (dx < 0) octant = steep ? 6 : 5;
    else octant = steep ? 7 : 8;
    return "octant " + std::to_string(octant) + ", " + (steep ? "steep" : "shallow");
}

// What one segment of a scene may and must draw.
struct Plan {
    std::string name;  // "line from (..) to (..)" for messages
    Color color;
    bool aa = false;     // drawn with draw_line_aa
    bool exact = false;  // pixel-exact Bresenham rules apply
    Pix p0, p1;          // exact: the endpoint pixels
    long long steps = 0;  // exact: max(|dx|, |dy|)
    std::vector<Pix> required;
    std::vector<std::pair<Pix, Pix>> ties;     // exactly one of each pair (at least one if overlapping)
    std::vector<Pix> candidates;               // every pixel it may draw
    std::vector<std::vector<Pix>> band_columns;  // fuzzy: each needs one drawn pixel
    std::vector<Pix> lenient;                  // may differ from the expected image
    struct Aa {
        Pix p;
        double coverage;
    };
    std::vector<Aa> aa_expected;  // Wu interior pixels with their exact coverage
    bool aa_diagonal = false;     // Wu, |dx| == |dy| != 0: x is the major axis (lines.h)
    // Wu, zero length on a column center: the rule covers that column, so one of these (the
    // nearer pixel, or either at an exact tie) must be lit, whatever the endpoint weighting.
    std::vector<Pix> aa_zero_length;
    bool aa_zero_length_center = false;  // ... and the point is a pixel center
    // An endpoint at least kFar away: clipping it by a parameter t along the whole segment
    // loses every digit, so a failure gets the "precision" explanation.
    bool far = false;
    bool far_both = false;  // both endpoints are that far
    bool x_major = true;    // band lines: which axis the columns of the messages are
    // Both endpoints farther than kUnresolved from the image along the minor axis: no double
    // arithmetic can place the line to the pixel, so lines.h promises only safety for it and
    // its pixels are not judged.
    bool unjudged = false;
    // Band lines: endpoint pixels that every correct draw_line draws all the same (an endpoint
    // inside the image that no clipping moved: draw_line snaps it to its own pixel).
    std::vector<Pix> pinned_ends;
    // The endpoints as the scene gives them, before draw_line snaps them (see lost_unsnapped
    // and wu_mistake).
    Vec2 raw_a{}, raw_b{};
};

constexpr double kFar = 1e15;

const char* const kFarBothClipLesson =
    "Both endpoints are far away, so the image is a tiny sliver of this segment and a parameter t "
    "along it cannot resolve a pixel (1e300 + 0.5 == 1e300 in double). Computed as a + t (b - a), "
    "the clipped coordinate misses the edge: for (1e300, 40.5) to (-1e300, 44.5), t = 0.5 at both "
    "edges and x = 1e300 - 0.5 * 2e300 = 0, so both ends land on one point. Put the clipped "
    "coordinate exactly on the edge (x = xmin, never a.x + t (b.x - a.x)) and compute only the "
    "other one from t";
const char* const kFarOneClipLesson =
    "One endpoint is far away and the other near the image. Interpolated from the far endpoint, "
    "the clipped point cancels to the wrong place (-1e300 + 1e300 * 1.0 == 0: a parameter t "
    "measured from 1e300 away cannot resolve a pixel, since 1e300 + 0.5 == 1e300 in double). "
    "Put the clipped coordinate exactly on the edge and interpolate the other one from the "
    "endpoint nearer the image, with t measured from there";
const char* const kFarWuLesson =
    "One endpoint is at least 1e15 away: computed from it, y = a.y + gradient (x + 0.5 - a.x) "
    "cancels to the wrong row (-1e300 + 1e300 == 0, whatever the 0.5). Compute each column's y from "
    "the endpoint whose y is nearer the image (for a steep line, x)";
const char* const kFarClipHint =
    "Put each clipped coordinate exactly on its edge (x = xmin) and interpolate the other one from "
    "the endpoint nearer the image, with t measured from there (lesson, section 3: Precision).";
const char* const kFarWuHint =
    "Compute each column's y from the endpoint whose y is nearer the image (lesson, section 6).";
const char* const kMajorAxisHint =
    "Decide steep with |dy| > |dx|: every other line, 45 degrees and zero length included, steps along x.";
const char* const kEndpointHint =
    "A line from pixel a to pixel b has max(dx, dy) + 1 pixels, both ends included: plot the pixel "
    "before testing whether it was the last one (or loop with <=, not <).";
const char* const kDrawingNotClippingHint =
    "clip_line is right on this scene, so the drawing is wrong: make the octant checkpoints "
    "(m1.octant_1 ... m1.octant_8) pass first, checking the step signs sx and sy.";
constexpr double kUnresolved = 1e12;
// Why an outcode that puts the image's border outside breaks lines that stay inside the image.
constexpr const char* kBorderWhy =
    "draw_line clips every line to the rectangle of pixel centers with clip_line, which starts from "
    "outcode(), so a line that touches that rectangle's border is clipped wrongly";
constexpr const char* kStepSignHint =
    "Each step moves toward the end pixel: x += sx and y += sy, with sx and sy the signs of x1 - x0 and y1 - y0, "
    "in both branches (the steep one and the shallow one).";

// How far v lies outside [0, size] (0 inside).
double outside_by(double v, double size) { return v < 0 ? -v : v > size ? v - size : 0.0; }

// Lines whose pixels lines.h does not promise (see Plan::unjudged): any pixel may be drawn.
void plan_unjudged(Plan& plan, int w, int h) {
    plan.unjudged = true;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            plan.candidates.push_back({x, y});
            plan.lenient.push_back({x, y});
        }
    }
}

Vec2 snapped_center(Vec2 p) { return {std::floor(p.x) + 0.5, std::floor(p.y) + 0.5}; }

bool inside(const Vec2& p, int w, int h) { return p.x >= 0 && p.y >= 0 && p.x < w && p.y < h; }

// Whether snapping to pixel centers moves either endpoint of the plan's segment.
bool snapping_moves(const Plan& plan) {
    return !(snapped_center(plan.raw_a) == plan.raw_a) || !(snapped_center(plan.raw_b) == plan.raw_b);
}

// Whether the segment a-b meets the closed box [x0, x1] x [y0, y1] (Liang-Barsky).
bool meets(Vec2 a, Vec2 b, double x0, double y0, double x1, double y1) {
    double t0 = 0, t1 = 1;
    const Vec2 d = b - a;
    const auto edge = [&](double p, double q) {  // keep t with p t <= q
        if (p == 0) return q >= 0;
        const double t = q / p;
        if (p < 0) t0 = std::max(t0, t);
        else t1 = std::min(t1, t);
        return t0 <= t1;
    };
    return edge(-d.x, a.x - x0) && edge(d.x, x1 - a.x) && edge(-d.y, a.y - y0) && edge(d.y, y1 - a.y);
}

// Bresenham's pixels, derived exactly: at step i the ideal minor coordinate is
// minor0 + dminor * i / n; the nearest pixel is unique unless the remainder is exactly n / 2.
void plan_exact(Plan& plan, Pix p0, Pix p1) {
    plan.exact = true;
    plan.p0 = p0;
    plan.p1 = p1;
    const long long dx = p1.x - p0.x, dy = p1.y - p0.y;
    const bool x_major = std::llabs(dx) >= std::llabs(dy);
    const long long n = std::max(std::llabs(dx), std::llabs(dy));
    plan.steps = n;
    const long long dmaj = x_major ? dx : dy, dmin = x_major ? dy : dx;
    const int smaj = dmaj < 0 ? -1 : 1, smin = dmin < 0 ? -1 : 1;
    const long long maj0 = x_major ? p0.x : p0.y, min0 = x_major ? p0.y : p0.x;
    auto make = [x_major](long long maj, long long mn) {
        return x_major ? Pix{int(maj), int(mn)} : Pix{int(mn), int(maj)};
    };
    for (long long i = 0; i <= n; ++i) {
        const long long maj = maj0 + smaj * i;
        if (n == 0) {
            plan.required.push_back(p0);
            break;
        }
        const long long num = std::llabs(dmin) * i, q = num / n, r = num % n;
        const long long base = min0 + smin * q;
        if (2 * r < n) {
            plan.required.push_back(make(maj, base));
        } else if (2 * r > n) {
            plan.required.push_back(make(maj, base + smin));
        } else {
            const Pix a = make(maj, base), b = make(maj, base + smin);
            plan.ties.push_back({a, b});
            plan.lenient.push_back(a);
            plan.lenient.push_back(b);
        }
    }
    plan.candidates = plan.required;
    for (const auto& [a, b] : plan.ties) {
        plan.candidates.push_back(a);
        plan.candidates.push_back(b);
    }
}

// A line that needs clipping (or whose clipped endpoints are not exactly known): correct
// implementations snap the clipped endpoints differently, so only a band is judged. The
// snapped endpoint can be off the ideal line by 0.5 in the minor axis plus 0.5 * slope, and
// the chosen pixel by another 0.5: hence the half-width 1 + 0.5 * |slope|.
//
// The line is walked column by column along its major axis, with its minor coordinate
// computed from the slope. (Clipping by a parameter t along the segment would lose every
// digit for endpoints at 1e300: the visible part is a 1e-298 sliver of t.)
void plan_band(Plan& plan, Vec2 c0, Vec2 c1, int w, int h) {
    const Vec2 d = c1 - c0;
    const bool x_major = std::abs(d.x) >= std::abs(d.y);
    const double dmaj = x_major ? d.x : d.y, dmin = x_major ? d.y : d.x;
    const double slope = dmaj != 0 ? dmin / dmaj : 0;
    const double half_width = 1.0 + 0.5 * std::abs(slope);
    const int major_size = x_major ? w : h, minor_size = x_major ? h : w;
    plan.x_major = x_major;
    // The minor coordinate at a column is computed from the endpoint whose minor coordinate
    // is nearer the image: from there, (c + 0.5 - maj0) * slope is a small number computed
    // to full precision, even when the other endpoint is 1e300 away. (From an endpoint at
    // -1e300 the same formula cancels to 0: -1e300 + (c + 0.5 + 1e300) * 1 == 0.)
    const bool from_c0 = outside_by(x_major ? c0.y : c0.x, minor_size) <= outside_by(x_major ? c1.y : c1.x, minor_size);
    const Vec2 n = from_c0 ? c0 : c1;
    const double maj0 = x_major ? n.x : n.y, min0 = x_major ? n.y : n.x;
    const double maj1 = x_major ? (from_c0 ? c1 : c0).x : (from_c0 ? c1 : c0).y;
    const double lo = std::max(std::ceil(std::min(maj0, maj1) - 0.5), 0.0);
    const double hi = std::min(std::floor(std::max(maj0, maj1) - 0.5), major_size - 1.0);
    std::vector<std::vector<Pix>> visible;  // columns where the line is inside the image
    for (double c = lo; c <= hi; ++c) {
        const double m = min0 + (c + 0.5 - maj0) * slope;
        if (!(m > -half_width && m < minor_size + half_width)) continue;
        std::vector<Pix> band;
        for (int r = std::max(0, int(std::floor(m - half_width))); r <= std::min(minor_size - 1, int(std::ceil(m + half_width))); ++r) {
            if (std::abs(r + 0.5 - m) < half_width) band.push_back(x_major ? Pix{int(c), r} : Pix{r, int(c)});
        }
        plan.candidates.insert(plan.candidates.end(), band.begin(), band.end());
        plan.lenient.insert(plan.lenient.end(), band.begin(), band.end());
        if (m >= 0.5 && m <= minor_size - 0.5 && !band.empty()) visible.push_back(band);
    }
    // Every visible column needs a pixel, except the first and the last, where the
    // implementation's own clipping decides.
    for (std::size_t i = 1; i + 1 < visible.size(); ++i) plan.band_columns.push_back(visible[i]);
}

// Wu as pinned in lines.h, written as "coverage = 1 - distance from the pixel center to the
// line, measured along the minor axis". Interior columns are exact; the end columns (and one
// beyond each end, for implementations that add Wu's endpoint weighting) are lenient.
void plan_aa(Plan& plan, Vec2 a, Vec2 b, int w, int h) {
    plan.aa_diagonal = std::abs(b.y - a.y) == std::abs(b.x - a.x) && a.x != b.x;
    if (a.x == b.x && a.y == b.y && a.x - 0.5 == std::floor(a.x - 0.5)) {
        const double t = a.y - 0.5, row = std::floor(t), f = t - row;
        const int column = int(a.x - 0.5);
        for (double r : {row, row + 1}) {
            const bool nearer = r == row ? f <= 0.5 : f >= 0.5;
            if (nearer && column >= 0 && column < w && r >= 0 && r < h) plan.aa_zero_length.push_back({column, int(r)});
        }
        plan.aa_zero_length_center = f == 0;
    }
    const bool steep = std::abs(b.y - a.y) > std::abs(b.x - a.x);
    if (steep) {
        std::swap(a.x, a.y);
        std::swap(b.x, b.y);
    }
    if (a.x > b.x) std::swap(a, b);
    const int columns = steep ? h : w, rows = steep ? w : h;
    const double gradient = b.x > a.x ? (b.y - a.y) / (b.x - a.x) : 0.0;
    if (!std::isfinite(gradient)) return;
    const double first = std::ceil(a.x - 0.5), last = std::floor(b.x - 0.5);
    const double lo = std::max(first - 1, 0.0), hi = std::min(last + 1, columns - 1.0);
    const Vec2 n = outside_by(a.y, rows) <= outside_by(b.y, rows) ? a : b;  // as in plan_band
    for (double c = lo; c <= hi; ++c) {
        const double yc = n.y + gradient * (c + 0.5 - n.x);
        if (!(yc > -2 && yc < rows + 2)) continue;
        const bool end_column = c <= first || c >= last;
        for (int r = std::max(0, int(std::floor(yc - 1.5))); r <= std::min(rows - 1, int(std::ceil(yc + 1.5))); ++r) {
            const double dist = std::abs(r + 0.5 - yc);
            const Pix p = steep ? Pix{r, int(c)} : Pix{int(c), r};
            if (end_column) {
                if (dist < 1.5) {
                    plan.candidates.push_back(p);
                    plan.lenient.push_back(p);
                }
            } else {
                if (dist < 1.0) plan.candidates.push_back(p);
                plan.aa_expected.push_back({p, std::max(0.0, 1.0 - dist)});
            }
        }
    }
}

Plan make_plan(const Segment& s, int w, int h, bool force_band) {
    Plan plan;
    plan.name = "line from " + str(s.a) + " to " + str(s.b);
    plan.raw_a = s.a;
    plan.raw_b = s.b;
    plan.color = s.color;
    plan.aa = s.aa;
    if (!raster::is_finite(s.a) || !raster::is_finite(s.b)) return plan;  // draws nothing
    {
        const Vec2 d = s.b - s.a;
        const bool x_major = std::abs(d.x) >= std::abs(d.y);
        const int minor_size = x_major ? h : w;
        const double m0 = x_major ? s.a.y : s.a.x, m1 = x_major ? s.b.y : s.b.x;
        const double far_a = std::max(std::abs(s.a.x), std::abs(s.a.y)), far_b = std::max(std::abs(s.b.x), std::abs(s.b.y));
        plan.far = std::max(far_a, far_b) >= kFar;
        plan.far_both = std::min(far_a, far_b) >= kFar;
        if (std::min(outside_by(m0, minor_size), outside_by(m1, minor_size)) > kUnresolved) {
            plan_unjudged(plan, w, h);
            return plan;
        }
    }
    const Vec2 c0 = snapped_center(s.a), c1 = snapped_center(s.b);
    if (s.aa) {
        plan_aa(plan, s.a, s.b, w, h);
        return plan;
    }
    if (!force_band && inside(c0, w, h) && inside(c1, w, h)) {
        const Pix p0{int(c0.x), int(c0.y)}, p1{int(c1.x), int(c1.y)};
        plan.name = "line from pixel " + str(p0) + " to " + str(p1) + " (" +
                    describe_direction(p1.x - p0.x, p1.y - p0.y) + ")";
        plan_exact(plan, p0, p1);
    } else {
        plan_band(plan, c0, c1, w, h);
    }
    return plan;
}

// Wu's coverage of pixel p as a plausible mistake computes it, for the line a-b (not far):
// with the rows taken by a cast or std::trunc instead of std::floor (so the row above the
// image's first one is 0 and its weight 1 - f passes 1), with pixel centers at whole numbers
// (the textbook's convention), or between the endpoints' pixel centers (snapped as draw_line
// does, which lines.h says Wu must not). kCorrect is lines.h's rule, as plan_aa computes it.
// kTransposed: a steep line plotted without swapping x and y back, mirrored across the
// diagonal x = y.
enum class WuModel { kCorrect, kTrunc, kIntegerCenters, kSnapped, kTransposed };

double wu_model_coverage(WuModel model, Vec2 a, Vec2 b, Pix p) {
    if (model == WuModel::kTransposed) return wu_model_coverage(WuModel::kCorrect, a, b, {p.y, p.x});
    if (model == WuModel::kSnapped) {
        a = snapped_center(a);
        b = snapped_center(b);
    }
    const bool steep = std::abs(b.y - a.y) > std::abs(b.x - a.x);
    if (steep) {
        std::swap(a.x, a.y);
        std::swap(b.x, b.y);
    }
    const double gradient = b.x != a.x ? (b.y - a.y) / (b.x - a.x) : 0.0;
    const double c = steep ? p.y : p.x, r = steep ? p.x : p.y;
    const double half = model == WuModel::kIntegerCenters ? 0.0 : 0.5;
    const double t = a.y + gradient * (c + half - a.x) - half;  // between rows `row` and `row + 1`
    const double row = model == WuModel::kTrunc ? std::trunc(t) : std::floor(t), f = t - row;
    const double weight = r == row ? 1.0 - f : r == row + 1 ? f : 0.0;
    return std::clamp(weight, 0.0, 1.0);
}

bool lit(const Image& img, Pix p) { return img.at(p.x, p.y) != raster::colors::black; }

// ---- the checks ----

struct Checker {
    const Scene& scene;
    const Image& img;
    cp::Judgement& j;

    void add(const std::string& topic, const std::string& message, const std::string& todo = "",
             const std::string& hint = "") {
        j.findings.push_back({topic, message, hint, todo});
    }
    // Pixels of the lenient set (ties, bands, pinned ends) that a rule above rejected: diff.png
    // shows their differences in red, as errors, not in blue as allowed (Tolerance::wrong).
    void judged_wrong(const std::vector<Pix>& pixels) {
        for (Pix p : pixels) j.tolerance.wrong.set(p.x, p.y);
    }

    std::vector<int> claims;  // per pixel: how many lines may draw it (or expect it dark)
    bool zero_length_center_drawn = false;  // a zero-length Wu line at a pixel center is drawn
    struct FarFailure {
        std::string topic, plain;  // the finding if other lines are wrong too
        std::string precision;     // the finding if only far lines are wrong
        std::string plain_todo, precision_todo, precision_hint;
    };
    std::vector<FarFailure> far_failures;
    std::size_t strays_at = 0;  // where the lines' findings start (a far line's precision goes first)
    // Wu findings about a pixel that an aliased line may have overdrawn (see check_lines).
    std::vector<cp::Finding> overdrawn_wu = {};
    std::vector<std::size_t> clip_wrong = {};  // clip scenes: segments clip_line got wrong
    // Clip scenes: clip_line returned the right points for every segment, so a line that
    // leaves its band was drawn wrong, not clipped wrong.
    bool clip_values_right = false;
    // Set when the code under test's outcode() puts a point on a rectangle's border outside
    // (see border_probes): clipping goes wrong wherever a line touches that border, so a gap
    // is not the drawing loop's. The finding is kept only if something shows it.
    std::optional<cp::Finding> border_finding = std::nullopt;
    // draw_line wrote outside the image (its trace says so): a missing line whose mirror
    // image falls outside the picture has walked out of it (see mirrored()).
    bool draw_line_wrote_outside = false;

    int& claim(Pix p) { return claims[std::size_t(p.y) * img.width() + p.x]; }
    int claim(Pix p) const { return claims[std::size_t(p.y) * img.width() + p.x]; }

    void check_lines(const std::vector<Plan>& plans) {
        Mask allowed(img.width(), img.height());
        claims.assign(std::size_t(img.width()) * img.height(), 0);
        for (const Plan& plan : plans) {
            Mask mine(img.width(), img.height());
            for (Pix p : plan.candidates) mine.set(p.x, p.y);
            for (const Plan::Aa& e : plan.aa_expected) mine.set(e.p.x, e.p.y);
            for (int y = 0; y < img.height(); ++y) {
                for (int x = 0; x < img.width(); ++x) claim({x, y}) += mine.get(x, y);
            }
            for (Pix p : plan.candidates) allowed.set(p.x, p.y);
            for (Pix p : plan.lenient) j.tolerance.lenient.set(p.x, p.y);
        }
        // Stray pixels: lit, but no line may draw them.
        long long strays = 0;
        std::string first;
        for (int y = 0; y < img.height(); ++y) {
            for (int x = 0; x < img.width(); ++x) {
                if (!allowed.get(x, y) && lit(img, {x, y})) {
                    if (strays++ < 3) first += (first.empty() ? "" : ", ") + str(Pix{x, y});
                }
            }
        }
        strays_at = j.findings.size();
        for (const Plan& plan : plans) {
            if (plan.aa_zero_length_center && !plan.aa_zero_length.empty()) {
                zero_length_center_drawn |= lit(img, plan.aa_zero_length.front());
            }
        }
        const std::size_t before = j.findings.size();
        bool aliased_wrong = strays > 0;
        for (const Plan& plan : plans) {
            const std::size_t at = j.findings.size();
            check_plan(plan);
            aliased_wrong |= !plan.aa && j.findings.size() > at;
        }
        // A Wu pixel lit brighter than its line allows, in the full color of an aliased line of
        // the scene or in no shade of the Wu line's own, while some aliased line is wrong: that
        // line, drawn off its path, lit it.
        // Its own finding says so; the Wu line is left alone.
        for (const cp::Finding& f : overdrawn_wu) {
            if (!aliased_wrong) add(f.topic, f.message, f.todo, f.hint);
        }
        // A line from far away that is wrong where it crosses the image, while every ordinary
        // line is right: that is the precision of the far endpoint, not clipping in general.
        const bool others_fine = j.findings.size() == before;
        for (const auto& f : far_failures) {
            if (others_fine) {
                // First, before the findings of the other lines it crosses.
                j.findings.insert(j.findings.begin() + std::ptrdiff_t(strays_at++),
                                  {"precision", f.precision, f.precision_hint, f.precision_todo});
            } else {
                add(f.topic, f.plain, f.plain_todo);
            }
        }
        // Pixels off every line come after the lines' own findings, which say which line went
        // astray and why (the mirrored steps, the shifted grid); alone, they lead.
        if (strays > 0) {
            add("off the line",
                cp::plural(double(strays), "pixel") + (strays == 1 ? " is" : " are") + " drawn where no line passes within half a "
                "pixel of their center, e.g. " + first,
                "", clip_values_right ? kDrawingNotClippingHint : "");
        }
    }

    // Most missing pixels (of those whose mirror image is in the picture) have their mirror
    // image across one endpoint's minor coordinate drawn, in this line's color and off every
    // line: the minor step has the wrong sign.
    bool mirrored(const Plan& plan, const std::vector<Pix>& missing) const {
        const bool x_major = std::llabs(plan.p1.x - plan.p0.x) >= std::llabs(plan.p1.y - plan.p0.y);
        for (const Pix start : {plan.p0, plan.p1}) {
            int checked = 0, lit_mirrors = 0, in_color = 0, off = 0;
            for (Pix p : missing) {
                const Pix m = x_major ? Pix{p.x, 2 * start.y - p.y} : Pix{2 * start.x - p.x, p.y};
                if (m.x < 0 || m.y < 0 || m.x >= img.width() || m.y >= img.height()) {
                    ++off;
                    continue;
                }
                ++checked;
                // In this line's color, where no line may draw: not a crossing line's pixel.
                in_color += img.at(m.x, m.y) == plan.color;
                lit_mirrors += img.at(m.x, m.y) == plan.color && claims[std::size_t(m.y) * img.width() + m.x] == 0;
            }
            if (checked >= 2 && 4 * lit_mirrors >= 3 * checked) return true;
            // A line near the border: its mirror image is mostly outside the picture, where
            // draw_line did write, and what of it is inside is drawn in this line's color (a
            // far line's band may claim those pixels too, so the claims are not asked).
            if (draw_line_wrote_outside && off >= 2 && 4 * off >= 3 * int(missing.size()) && checked >= 1 &&
                in_color == checked) {
                return true;
            }
        }
        return false;
    }

    // Whether the segment as the scene gives it, unsnapped, runs through the box [x0, x1] x
    // [y0, y1] only in the half pixel between the image's edge and the rectangle of pixel
    // centers: a draw_line that clips the endpoints before snapping them cuts that part away,
    // though its pixels are in the image. No correct draw_line loses such a pixel.
    bool lost_unsnapped(const Plan& plan, double x0, double y0, double x1, double y1) const {
        if (!snapping_moves(plan) || plan.far || plan.aa) return false;
        const double w = img.width(), h = img.height();
        return meets(plan.raw_a, plan.raw_b, x0, y0, x1, y1) &&
               !meets(plan.raw_a, plan.raw_b, std::max(x0, 0.5), std::max(y0, 0.5), std::min(x1, w - 0.5),
                      std::min(y1, h - 0.5));
    }
    bool lost_unsnapped(const Plan& plan, const std::vector<Pix>& pixels) const {
        if (pixels.empty()) return false;
        Pix lo = pixels.front(), hi = pixels.front();
        for (Pix p : pixels) {
            lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
            hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
        }
        return lost_unsnapped(plan, lo.x, lo.y, hi.x + 1.0, hi.y + 1.0);
    }
    // Every pixel in `missing` (one box each) is one that clipping the unsnapped endpoints
    // loses: say so, with TODO 4's order of steps, instead of a loop or clipping finding.
    bool unsnapped_finding(const Plan& plan, const std::vector<std::vector<Pix>>& missing) {
        if (missing.empty()) return false;
        for (const auto& box : missing) {
            if (!lost_unsnapped(plan, box)) return false;
        }
        const Pix p = missing.front()[missing.front().size() / 2];
        judged_wrong(missing.front());
        add("pixel grid",
            plan.name + ": pixel " + str(p) + " is missing, and the line runs through it only in the half pixel "
                "between the image's edge and the rectangle of pixel centers (0.5 to width - 0.5, 0.5 to "
                "height - 0.5): draw_line clipped the endpoints as given. Snapped first, the endpoints are pixel "
                "centers, and the line is cut only where its pixels leave the image",
            "TODO 4",
            "draw_line's order is: reject non-finite, snap each endpoint to (floor(x) + 0.5, floor(y) + 0.5), "
            "order, clip to the rectangle of pixel centers, then convert and call bresenham.");
        return true;
    }

    void check_plan(const Plan& plan) {
        // Missing pixels. Only endpoints missing: the loop bounds. More than that: the line
        // runs in the wrong direction or on the wrong axis for its octant.
        std::vector<Pix> missing;
        bool only_endpoints = true;
        for (Pix p : plan.required) {
            if (lit(img, p)) continue;
            missing.push_back(p);
            only_endpoints &= (p.x == plan.p0.x && p.y == plan.p0.y) || (p.x == plan.p1.x && p.y == plan.p1.y);
        }
        if (!missing.empty() && only_endpoints) {
            std::vector<std::vector<Pix>> boxes;
            for (Pix p : missing) boxes.push_back({p});
            if (unsnapped_finding(plan, boxes)) return;
            const Pix e = missing.front();
            // In the image's last column or row, the clip rectangle ending short of width - 0.5
            // (height - 0.5) loses it as well as a loop that stops a pixel early does.
            const char* edge = e.x == img.width() - 1 ? "last column" : e.y == img.height() - 1 ? "last row" : nullptr;
            if (edge != nullptr) {
                add("endpoint",
                    plan.name + ": endpoint pixel " + str(e) + ", in the image's " + edge + ", is not drawn. Either "
                    "the loop stops a pixel early (then every line misses its last pixel, and the octant "
                    "checkpoints show it), or draw_line's clip rectangle ends a pixel short: the rectangle of "
                    "pixel centers goes to width - 0.5 and height - 0.5",
                    "TODOs 3-4", "Clip to {0.5, 0.5, width - 0.5, height - 0.5}, border included, and plot every pixel "
                                 "from a to b, both ends included.");
                return;
            }
            add("endpoint", plan.name + ": endpoint pixel " + str(e) + " is not drawn; both endpoints belong to the line",
                "TODOs 3-4", kEndpointHint);
            return;
        }
        const auto in_color = [&](Pix p) { return p.x < img.width() && p.y < img.height() && img.at(p.x, p.y) == plan.color; };
        if (missing.size() >= 2 && plan.exact && !in_color(plan.p0) && !in_color(plan.p1)) {
            // The whole line one pixel right, down, or both, its two end pixels included: the
            // endpoints' pixels were found with round() (or a cast after adding 0.5), not
            // floor(). (A line that starts right and drifts off a row is the loop's error term.)
            for (const Pix d : {Pix{1, 1}, Pix{1, 0}, Pix{0, 1}}) {
                std::size_t shifted = 0;
                for (Pix p : plan.required) shifted += in_color({p.x + d.x, p.y + d.y});
                if (10 * shifted < 9 * plan.required.size()) continue;
                const std::string where = d.x && d.y ? "right and down" : d.x ? "to the right" : "down";
                add("pixel grid", plan.name + ": " + std::to_string(missing.size()) + " of its " +
                                      std::to_string(plan.required.size()) + " certain pixels are missing, and the "
                                      "line is drawn one pixel " + where + " instead: the pixel that contains a "
                                      "point is (floor(x), floor(y)), while round() (or adding 0.5 before the cast) "
                                      "picks the next one whenever the fraction is .5 or more",
                    "TODO 4", "Pixel (x, y) covers [x, x + 1) x [y, y + 1): take the endpoints' pixels with "
                              "std::floor, then run Bresenham between them.");
                return;
            }
        }
        if (missing.size() >= 2 && plan.exact && mirrored(plan, missing)) {
            const bool x_major = std::llabs(plan.p1.x - plan.p0.x) >= std::llabs(plan.p1.y - plan.p0.y);
            add("step sign", plan.name + ": " + std::to_string(missing.size()) + " of its " +
                                 std::to_string(plan.required.size()) + " certain pixels are missing, e.g. " +
                                 str(missing[missing.size() / 2]) + ", and the pixels drawn instead are the line "
                                 "mirrored across its first pixel: the minor axis (" + (x_major ? "y" : "x") +
                                 " here) steps the wrong way",
                "TODO 3",
                kStepSignHint);
            return;
        }
        // A line along the image's first or last row or column, (nearly) all missing: no loop
        // bug loses such a line whole while drawing the others, so draw_line dropped it before
        // the loop, in the snapping or the clipping to the rectangle of pixel centers, whose
        // border is inside.
        const bool on_border_row = plan.p0.y == plan.p1.y && (plan.p0.y == 0 || plan.p0.y == img.height() - 1);
        const bool on_border_column = plan.p0.x == plan.p1.x && (plan.p0.x == 0 || plan.p0.x == img.width() - 1);
        if (plan.exact && (on_border_row || on_border_column) && plan.required.size() >= 4 &&
            missing.size() + 1 >= plan.required.size()) {
            add("clipping",
                plan.name + " lies along the image's " +
                    (on_border_row ? (plan.p0.y == 0 ? "first row" : "last row")
                                   : (plan.p0.x == 0 ? "first column" : "last column")) +
                    ", and " + (missing.size() == plan.required.size() ? "none" : "almost none") +
                    " of it is drawn: draw_line dropped it before its loop. Snap each endpoint to its pixel's "
                    "center (floor(x) + 0.5, floor(y) + 0.5) before clipping, and clip to the rectangle of pixel "
                    "centers, 0.5 to width - 0.5 and 0.5 to height - 0.5, border included",
                "TODO 4",
                "A line on the border of the rectangle of pixel centers is inside it: after snapping, its endpoints "
                "lie exactly on that border, and clip_line must keep them.");
            return;
        }
        if (!missing.empty() && missing.size() == plan.required.size()) {
            add("octant", plan.name + ": the line is not drawn at all", "TODO 3");
            return;
        }
        if (!missing.empty()) {
            add("octant", plan.name + ": " + std::to_string(missing.size()) + " of its " +
                              std::to_string(plan.required.size()) + " certain pixels are missing, e.g. " +
                              str(missing[missing.size() / 2]) +
                              " (the pixel nearest the ideal line at that step)",
                "TODO 3");
            return;
        }
        for (const auto& [a, b] : plan.ties) {
            if (!lit(img, a) && !lit(img, b)) {
                judged_wrong({a, b});
                add("octant", plan.name + ": the line passes exactly between " + str(a) + " and " +
                                  str(b) + "; one of them must be drawn",
                    "TODO 3");
                return;
            }
        }
        std::size_t drawn_columns = 0;
        std::optional<Pix> gap;
        for (const auto& band : plan.band_columns) {
            if (std::any_of(band.begin(), band.end(), [&](Pix p) { return lit(img, p); })) {
                ++drawn_columns;
            } else {
                judged_wrong(band);  // a column with no pixel: red in diff.png, not "allowed"
                if (!gap) gap = band[band.size() / 2];
            }
        }
        if (gap) {
            std::vector<std::vector<Pix>> empty_bands;
            for (const auto& band : plan.band_columns) {
                if (std::none_of(band.begin(), band.end(), [&](Pix p) { return lit(img, p); })) empty_bands.push_back(band);
            }
            if (unsnapped_finding(plan, empty_bands)) return;
            const std::string message = plan.name + ": the visible part has a gap near " + str(*gap) +
                                        "; after clipping, every column (or row) the line crosses needs a pixel";
            if (plan.far) {
                std::ostringstream why;
                const char* columns = plan.x_major ? " columns" : " rows";
                why << plan.name << ": only " << drawn_columns << " of the " << plan.band_columns.size() << columns
                    << " where it crosses the image have a pixel of it (a gap near " << str(*gap) << "). "
                    << (plan.far_both ? kFarBothClipLesson : kFarOneClipLesson);
                far_failures.push_back({"clipping", message, why.str(), "TODOs 2, 4", "TODO 2", kFarClipHint});
            } else if (clip_values_right && !border_finding) {
                add("octant", plan.name + ": the line has a gap near " + str(*gap) + ", though clip_line returned the "
                              "right points for every line of this scene: the drawing loop leaves the line",
                    "TODO 3", kDrawingNotClippingHint);
            } else {
                add("clipping", message, "TODOs 2, 4");
            }
            return;
        }
        // After the gap: a line that leaves its band also misses its end pixel.
        for (Pix p : plan.pinned_ends) {
            if (lit(img, p)) continue;
            judged_wrong({p});
            add("endpoint", plan.name + ": endpoint pixel " + str(p) + " is not drawn; both endpoints belong to the line",
                "TODOs 3-4", kEndpointHint);
            return;
        }
        if (scene.disjoint && plan.exact) check_exact_disjoint(plan);
        check_aa(plan);
    }

    // On their own (no other line touches them), exact lines have a known pixel count,
    // color, and form one 8-connected chain from endpoint to endpoint.
    void check_exact_disjoint(const Plan& plan) {
        Mask mine(img.width(), img.height());
        long long count = 0;
        for (Pix p : plan.candidates) {
            if (mine.get(p.x, p.y)) continue;
            mine.set(p.x, p.y);
            if (!lit(img, p)) continue;
            ++count;
            if (img.at(p.x, p.y) != plan.color) {
                add("color", plan.name + ": pixel " + str(p) + " has the wrong color", "TODO 3");
                return;
            }
        }
        if (count != plan.steps + 1) {
            add("pixel count", plan.name + ": " + std::to_string(count) + " pixels drawn, expected " +
                                   std::to_string(plan.steps + 1) +
                                   " (one per step along the longer axis, both endpoints included)",
                "TODO 3");
            return;
        }
        // Breadth-first search over the line's lit pixels.
        Mask seen(img.width(), img.height());
        std::deque<Pix> queue{plan.p0};
        seen.set(plan.p0.x, plan.p0.y);
        while (!queue.empty()) {
            const Pix p = queue.front();
            queue.pop_front();
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    const Pix q{p.x + dx, p.y + dy};
                    if (mine.get(q.x, q.y) && !seen.get(q.x, q.y) && lit(img, q)) {
                        seen.set(q.x, q.y);
                        queue.push_back(q);
                    }
                }
            }
        }
        if (!seen.get(plan.p1.x, plan.p1.y)) {
            add("connectivity", plan.name + ": the pixels do not form one 8-connected chain from " +
                                    str(plan.p0) + " to " + str(plan.p1),
                "TODO 3");
        }
    }

    // A wrong anti-aliased line whose interior pixels (nearly all of those no other line
    // touches) match a mistake model instead of the rule: the finding that names it.
    std::optional<cp::Finding> wu_mistake(const Plan& plan) const {
        if (plan.far) return std::nullopt;
        // Whether the model explains the line, and the first pixel it explains that the rule
        // does not.
        const auto explains = [&](WuModel model) -> std::optional<Plan::Aa> {  // see needed below
            std::size_t judged = 0, matched = 0;
            std::optional<Plan::Aa> first;
            for (const Plan::Aa& e : plan.aa_expected) {
                if (claim(e.p) > 1) continue;
                ++judged;
                const Color got = img.at(e.p.x, e.p.y);
                const Color modelled =
                    raster::mix(raster::colors::black, plan.color, wu_model_coverage(model, plan.raw_a, plan.raw_b, e.p));
                if (!near_color(got, modelled)) continue;
                ++matched;
                if (!first && !near_color(got, raster::mix(raster::colors::black, plan.color, e.coverage))) first = e;
            }
            // A transposed line also meets the other steep lines' mirror images, which this
            // one-line model leaves out: it needs 85% of the pixels, the others all but 1 in 30.
            const double needed = model == WuModel::kTransposed ? 0.85 : 29.0 / 30.0;
            if (judged < 8 || double(matched) < needed * double(judged)) return std::nullopt;
            return first;
        };
        const auto head = [&](const Plan::Aa& e) {
            const auto intensity = [](Color c) { return std::to_string(int(std::max({c.r, c.g, c.b}))); };
            return plan.name + ": pixel " + str(e.p) + " has intensity " + intensity(img.at(e.p.x, e.p.y)) +
                   ", expected about " + intensity(raster::mix(raster::colors::black, plan.color, e.coverage)) + "; ";
        };
        const bool steep = std::abs(plan.raw_b.y - plan.raw_a.y) > std::abs(plan.raw_b.x - plan.raw_a.x);
        const std::string row = steep ? "column" : "row";
        if (const auto e = steep ? explains(WuModel::kTransposed) : std::nullopt) {
            return cp::Finding{"wu coverage",
                               head(*e) + "this steep line is drawn mirrored across the diagonal x = y, as if x "
                                          "and y were swapped to step along y and never swapped back when plotting",
                               "For a steep line the loop's (column, row) is (y, x) in the image: plot "
                               "blend(row, column), not blend(column, row).",
                               "TODO 5"};
        }
        if (const auto e = explains(WuModel::kTrunc)) {
            return cp::Finding{"wu coverage",
                               head(*e) + "the line passes outside the image's first " + row + " there, between " +
                                   row + "s -1 and 0. Your " + row + "s come from a cast or std::trunc, which rounds "
                                   "a t between -1 and 0 up to 0 instead of down to -1, so the pixel inside gets the "
                                   "weight 1 - f > 1: full intensity",
                               "Take the row with std::floor(t): it rounds down for negative t too. A cast to int "
                               "rounds toward zero.",
                               "TODO 5"};
        }
        const std::optional<Plan::Aa> snapped = snapping_moves(plan) ? explains(WuModel::kSnapped) : std::nullopt;
        const std::optional<Plan::Aa> integer = explains(WuModel::kIntegerCenters);
        const std::string integer_words =
            "Wu with pixel centers at whole numbers (the textbook's convention). Here pixel (x, y) has its center at "
            "(x + 0.5, y + 0.5): evaluate the line at the column's center x + 0.5 and measure the distance to the "
            "row centers r + 0.5";
        const std::string snapped_words =
            "Wu drawn between the centers of the endpoints' pixels. lines.h says draw_line_aa uses the endpoints as "
            "given, with no snapping: that is what lets an anti-aliased line sit between pixels";
        if (snapped && integer) {  // whole-number endpoints: the two mistakes draw the same line
            return cp::Finding{"wu coverage",
                               head(*snapped) + "every pixel of this line matches it drawn half a pixel right and "
                                                "down. Its endpoints are whole numbers, and two mistakes do that: "
                                                "pixel centers at whole numbers (the textbook's convention; here the "
                                                "center of pixel (x, y) is (x + 0.5, y + 0.5)), or endpoints snapped "
                                                "to pixel centers (lines.h: draw_line_aa uses them as given). The "
                                                "other lines of the scene tell which",
                               "", "TODO 5"};
        }
        if (snapped) {
            return cp::Finding{"wu coverage", head(*snapped) + "every pixel of this line matches " + snapped_words,
                               "Snapping belongs to draw_line only; draw_line_aa starts from a and b themselves.",
                               "TODO 5"};
        }
        if (integer) {
            return cp::Finding{"wu coverage", head(*integer) + "every pixel of this line matches " + integer_words,
                               "Wu in this course: y = a.y + gradient * (x + 0.5 - a.x) at column x; t = y - 0.5 "
                               "lies between rows floor(t) and floor(t) + 1.",
                               "TODO 5"};
        }
        return std::nullopt;
    }

    // Tolerance for anti-aliased pixels: 3 levels per channel. Rounding in blend() and
    // floating-point differences (FMA, -O3) move a channel by at most 1; a real error (swapped
    // weights, half-pixel offset) moves it by tens of levels.
    static constexpr int kTol = 3;
    static bool near_color(Color a, Color b) {
        return std::abs(a.r - b.r) <= kTol && std::abs(a.g - b.g) <= kTol && std::abs(a.b - b.b) <= kTol;
    }

    void check_aa(const Plan& plan) {
        // The scene background is black, so a pixel's expected color is color * coverage
        // (within kTol).
        const bool any_lit = std::any_of(plan.aa_expected.begin(), plan.aa_expected.end(),
                                         [&](const Plan::Aa& e) { return lit(img, e.p); });
        if (!plan.aa_expected.empty() && !any_lit) {
            if (plan.far) {
                far_failures.push_back({"wu coverage", plan.name + ": the anti-aliased line is not drawn at all",
                                        plan.name + ": the anti-aliased line is not drawn where it crosses the image. " +
                                            kFarWuLesson,
                                        "TODO 5", "TODO 5", kFarWuHint});
            } else if (plan.aa_diagonal) {
                add("wu major axis", plan.name + ": this exact 45-degree anti-aliased line is not drawn at all. "
                                     "With |dx| == |dy| it is neither steep nor shallow if both tests use >; "
                                     "lines.h makes x the major axis whenever |dx| >= |dy|",
                    "TODO 5", kMajorAxisHint);
            } else {
                add("wu coverage", plan.name + ": the anti-aliased line is not drawn at all", "TODO 5");
            }
            return;
        }
        if (!plan.aa_zero_length.empty() &&
            std::none_of(plan.aa_zero_length.begin(), plan.aa_zero_length.end(), [&](Pix p) { return lit(img, p); })) {
            const Pix p = plan.aa_zero_length.front();
            std::ostringstream msg;
            msg << plan.name << ": this zero-length anti-aliased line draws nothing, but its point lies on the "
                << "center of column " << p.x << ", so Wu's rule covers that column and pixel " << str(p)
                << " must be lit. ";
            if (zero_length_center_drawn && !plan.aa_zero_length_center) {
                msg << "A zero-length line at a pixel center is drawn, so your code steps along y when |dx| == |dy|: "
                       "lines.h makes x the major axis whenever |dx| >= |dy| (also for 45-degree and zero-length lines)";
                add("wu major axis", msg.str(), "TODO 5", kMajorAxisHint);
            } else {
                msg << "With a == b the slope is 0 / 0 = NaN: use slope 0 when b.x == a.x, and keep x as the major "
                       "axis (|dx| >= |dy|). If you weight the end columns, the weight must not reach 0 here: the "
                       "textbook's gap 1 - frac(x + 0.5) is 1 on a column center, while the segment's length inside "
                       "the column is 0";
                add("zero length", msg.str(), "TODO 5",
                    "With a == b, use slope 0 (dy / dx would be 0 / 0 = NaN) and keep x as the major axis: "
                    "the column whose center is a.x is covered like any other.");
            }
            return;
        }
        bool overdrawn = false;
        for (const Plan::Aa& e : plan.aa_expected) {
            if (claim(e.p) > 1) {  // another line crosses here: only the other checks apply
                j.tolerance.lenient.set(e.p.x, e.p.y);
                continue;
            }
            const Color want = raster::mix(raster::colors::black, plan.color, e.coverage);
            const Color swapped = raster::mix(raster::colors::black, plan.color, 1.0 - e.coverage);
            const Color got = img.at(e.p.x, e.p.y);
            const auto near = near_color;
            if (near(got, want)) continue;
            std::ostringstream msg;
            msg << plan.name << ": pixel " << str(e.p) << " has intensity " << int(std::max({got.r, got.g, got.b}))
                << ", expected about " << int(std::max({want.r, want.g, want.b})) << " (coverage "
                << e.coverage << ")";
            const bool brighter = got.r > want.r + kTol || got.g > want.g + kTol || got.b > want.b + kTol;
            const bool aliased_color = std::any_of(scene.lines.begin(), scene.lines.end(),
                                                   [&](const Segment& g) { return !g.aa && g.color == got; });
            // No shade of this line's color (Wu blends it over black): something else drew here.
            const double cc = double(plan.color.r) * plan.color.r + double(plan.color.g) * plan.color.g +
                              double(plan.color.b) * plan.color.b;
            const double t = cc > 0 ? (double(got.r) * plan.color.r + double(got.g) * plan.color.g +
                                       double(got.b) * plan.color.b) / cc
                                    : 0.0;
            const bool other_color = !near(got, raster::mix(raster::colors::black, plan.color, std::clamp(t, 0.0, 1.0)));
            if (brighter && (aliased_color || other_color)) {
                // Decided once every line is checked; the rest of this line is still judged.
                if (!overdrawn) overdrawn_wu.push_back({"wu coverage", msg.str(), "", "TODO 5"});
                overdrawn = true;
                continue;
            }
            if (plan.far) {
                far_failures.push_back({"wu coverage", msg.str(), msg.str() + ". " + kFarWuLesson, "TODO 5", "TODO 5", kFarWuHint});
            } else if (const auto mistake = wu_mistake(plan)) {
                j.findings.push_back(*mistake);
            } else if (e.coverage < 1.0 && near(got, swapped) && std::abs(e.coverage - 0.5) > 0.05) {
                msg << ". The weights look swapped: the pixel nearer the line must get 1 - f";
                add("wu weights", msg.str(), "TODO 5");
            } else {
                add("wu coverage", msg.str(), "TODO 5");
            }
            return;
        }
    }

    void check_outcodes() {
        long long wrong = 0;
        std::string first;
        for (int y = 0; y < img.height(); ++y) {
            for (int x = 0; x < img.width(); ++x) {
                const int want = outcode_oracle({x + 0.5, y + 0.5}, scene.viewport);
                if (img.at(x, y) != outcode_color(want) && wrong++ == 0) {
                    std::ostringstream s;
                    auto name = [](int code) {
                        std::string n = code == 0 ? "inside" : "";
                        for (const auto& [bit, word] : {std::pair{1, "LEFT"}, {2, "RIGHT"}, {4, "TOP"}, {8, "BOTTOM"}}) {
                            if (code & bit) n += (n.empty() ? "" : " ") + std::string(word);
                        }
                        return n;
                    };
                    s << "the pixel center (" << x + 0.5 << ", " << y + 0.5 << ") should get outcode " << want
                      << " (" << name(want) << ")";
                    // The picture colors each outcode 0..10 in its own color: read the student's back.
                    for (int code = 0; code <= 15; ++code) {
                        if (code != want && img.at(x, y) == outcode_color(code) && outcode_color(code) != Color{}) {
                            s << ", yours gave " << code << " (" << name(code) << ")";
                            break;
                        }
                    }
                    // A center exactly on a side: the border is inside (< and >, not <= and >=).
                    const Box& v = scene.viewport;
                    const double cx = x + 0.5, cy = y + 0.5;
                    const char* side = cx == v.xmin ? "x = xmin" : cx == v.xmax ? "x = xmax"
                                     : cy == v.ymin ? "y = ymin" : cy == v.ymax ? "y = ymax" : nullptr;
                    if (side != nullptr) {
                        s << ": that center lies exactly on the rectangle's border (" << side
                          << "), and the border is inside: compare with < and >, not <= and >=";
                    }
                    first = s.str();
                }
            }
        }
        if (wrong > 0) add("outcode", cp::plural(double(wrong), "pixel center") + " got the wrong outcode; " + first, "TODO 1");
    }

    // An outcode() that puts a point of a rectangle's border outside, found by the probes the
    // render half asked about (values "<prefix><k>"): one finding, sending the student to
    // m1.outcodes, put ahead of the gaps and wrong clip_line results it causes (and left out
    // when the scene shows nothing wrong: its lines may never touch that border).
    void check_border_outcodes(const cp::Artifacts& art, const std::string& prefix, const Box& box,
                               const std::string& why) {
        if (border_finding) return;  // one such finding is enough
        const std::vector<Vec2> probes = border_probes(box);
        for (std::size_t k = 0; k < probes.size(); ++k) {
            const auto it = art.values.find(prefix + std::to_string(k));
            if (it == art.values.end() || it->second == 0) continue;
            std::ostringstream rect;
            rect << "{" << box.xmin << ", " << box.ymin << ", " << box.xmax << ", " << box.ymax << "}";
            const cp::Finding f{"outcode",
                                "outcode(" + str(probes[k]) + ", " + rect.str() + ") gave " +
                                    std::to_string(static_cast<long long>(it->second)) +
                                    ", but that point lies on the rectangle's border, and the border is inside "
                                    "(outcode 0)",
                                "", "TODO 1"};
            border_finding = cp::fix_first(f, "m1.outcodes", why,
                                           "a point on the border is inside: compare with < and >, not <= and >=.");
            return;
        }
    }

    void check_clip_values(const cp::Artifacts& art) {
        for (std::size_t i = 0; i < scene.lines.size(); ++i) {
            const Segment& s = scene.lines[i];
            const std::string key = "clip." + std::to_string(i) + ".";
            auto value = [&](const std::string& k) {
                const auto it = art.values.find(key + k);
                return it == art.values.end() ? std::nan("") : it->second;
            };
            const auto want = clip_oracle(s.a, s.b, scene.viewport);
            const bool kept = value("kept") == 1.0;
            const std::string call = "clip_line(" + str(s.a) + ", " + str(s.b) + ")";
            if (kept != want.has_value()) {
                add("clipping", call + " returned " + (kept ? "true" : "false") +
                                    (want ? ", but the segment crosses the viewport from " + str(want->first) +
                                                " to " + str(want->second)
                                          : ", but the segment misses the viewport"),
                    "TODO 2");
                clip_wrong.push_back(i);
                continue;
            }
            if (!kept) continue;
            const Vec2 a{value("ax"), value("ay")}, b{value("bx"), value("by")};
            auto close = [](Vec2 p, Vec2 q) {
                const double tol = 1e-7 * (1 + std::max(std::abs(q.x), std::abs(q.y)));
                return std::abs(p.x - q.x) <= tol && std::abs(p.y - q.y) <= tol;
            };
            if (!close(a, want->first) || !close(b, want->second)) {
                add("clipping", call + " gave " + str(a) + " - " + str(b) + ", expected " + str(want->first) +
                                    " - " + str(want->second) + " (a stays on a's side)",
                    "TODO 2");
                clip_wrong.push_back(i);
            }
        }
    }
};

// Every line this scene draws with draw_line lies inside the image (in clip scenes, the
// viewport and the clipped parts lie inside the whole lines' box): clipping has nothing to cut.
bool draw_line_stays_inside(const Scene& s) {
    auto in = [&](Vec2 p) { return raster::is_finite(p) && p.x >= 0 && p.y >= 0 && p.x < s.width && p.y < s.height; };
    return std::all_of(s.lines.begin(), s.lines.end(), [&](const Segment& g) { return g.aa || (in(g.a) && in(g.b)); });
}

// What a function's writes outside the image mean (the trace says which function made them, and
// each has its own usual cause). `step_sign`: the picture shows a line whose
// pixels are mirrored, which walks out of the image however well the scene's lines are clipped.
cp::Finding stray_finding(const Scene& scene, bool step_sign, const std::string& name, long long count) {
    const std::string n = cp::plural(double(count), "pixel");
    if (name == "draw_line_aa") {
        return {"clipping",
                "draw_line_aa asked to write " + n + " outside the image: where an "
                "anti-aliased line leaves the image through the top or bottom (left or right, for "
                "a steep line), one or both of a column's two pixels are outside it",
                "Test 0 <= row < height (for a steep line, the x against the width) before each "
                "blend, and skip a column whose t is out of range before converting it to int.",
                "TODO 5"};
    }
    if (name == "draw_line" && draw_line_stays_inside(scene)) {
        return {"step sign",
                "draw_line asked to write " + n + " outside the image, though every line it "
                "draws here lies inside the image, so clipping has nothing to cut: the loop "
                "walks away from the line. A step in the wrong direction does this (x -= sx "
                "where x += sx is meant, or a step sign fixed at +1), and so does an error term "
                "that takes the minor step at the wrong times (a reversed sign test, or an update "
                "without its factor 2), which drifts off the line by 45 degrees",
                "Each step moves toward the end pixel: x += sx and y += sy, with sx and sy the "
                "signs of x1 - x0 and y1 - y0, in both branches; and the minor step comes only when "
                "the error term says so (lesson section 4). Check which lines are wrong in diff.png: "
                "the steep ones, or the shallow ones.",
                "TODO 3"};
    }
    if (name == "draw_line" && step_sign) {
        // The scene has lines to clip, but a line stepping the wrong way walks out of the image
        // anyway: its stray writes are the step sign's, not a clipping mistake's.
        return {"step sign",
                "draw_line asked to write " + n + " outside the image: the line below whose pixels are "
                "mirrored walks out of the image, because a step goes the wrong way. (Once every line "
                "steps the right way, any stray writes left are lines that were not clipped.)",
                kStepSignHint, "TODO 3"};
    }
    if (name == "draw_line") {
        return {"clipping",
                "draw_line asked to write " + n + " outside the image: clip the segment "
                "to the rectangle of pixel centers (in double) before converting to int, so the "
                "loop only walks visible pixels; a coordinate that became NaN or infinite before "
                "the conversion (0 / 0 on a zero-length line, an unchecked NaN endpoint) does "
                "this too",
                "", "TODOs 2, 4"};
    }
    return {"clipping", name + " asked to write " + n + " outside the image"};
}

}  // namespace

std::string describe_call(const std::string& id, const std::string& function, long long call) {
    const Scene& s = scene(id);
    const auto line_text = [](Vec2 a, Vec2 b) { return "the line from " + str(a) + " to " + str(b); };
    if (s.kind == Kind::kLines && (function == "draw_line" || function == "draw_line_aa")) {
        // Every segment of its kind in order, then (check_reversed) again from b to a.
        std::vector<const Segment*> mine;
        for (const Segment& g : s.lines) {
            if (g.aa == (function == "draw_line_aa")) mine.push_back(&g);
        }
        const long long n = static_cast<long long>(mine.size());
        if (call < 1 || n == 0 || call > (s.check_reversed ? 2 * n : n)) return "";
        const Segment& g = *mine[std::size_t((call - 1) % n)];
        return call <= n ? line_text(g.a, g.b) : line_text(g.b, g.a);
    }
    if (s.kind == Kind::kClip && function == "draw_line") {
        // The whole lines, then the viewport's four sides; the clipped parts after them.
        const long long n = static_cast<long long>(s.lines.size());
        if (call >= 1 && call <= n) return line_text(s.lines[std::size_t(call - 1)].a, s.lines[std::size_t(call - 1)].b);
        const Box& v = s.viewport;
        const Vec2 corners[] = {{v.xmin, v.ymin}, {v.xmax, v.ymin}, {v.xmax, v.ymax}, {v.xmin, v.ymax}};
        const long long k = call - n - 1;
        if (k >= 0 && k < 4) return "the viewport's side from " + str(corners[k]) + " to " + str(corners[(k + 1) % 4]);
    }
    return "";
}

cp::Judgement judge(const std::string& id, const cp::Artifacts& art, const cp::Artifacts& /*reference*/,
                    const raster::Image& /*expected*/) {
    const Scene& s = scene(id);
    cp::Judgement j;
    const Image* main = cp::main_image_for_judging(art, s.width, s.height, j);
    if (main == nullptr) return j;  // the harness reports a missing or mis-sized image
    const Image& img = *main;
    Checker check{s, img, j, {}, false, {}};
    const auto line_trace = art.trace.find("draw_line");
    check.draw_line_wrote_outside = line_trace != art.trace.end() && line_trace->second.stray_writes > 0;
    std::vector<Plan> plans;
    const bool has_aa = std::any_of(s.lines.begin(), s.lines.end(), [](const Segment& g) { return g.aa; });
    switch (s.kind) {
        case Kind::kOutcodes:
            check.check_outcodes();
            break;
        case Kind::kLines: {
            for (const Segment& seg : s.lines) plans.push_back(make_plan(seg, s.width, s.height, false));
            check.check_border_outcodes(art, "border_outcode.", pixel_center_box(s.width, s.height), kBorderWhy);
            check.check_lines(plans);
            for (std::size_t i = 0; s.clip_nonfinite && i < s.lines.size(); ++i) {
                const auto it = art.values.find("nonfinite_clip." + std::to_string(i));
                if (it == art.values.end() || it->second == 0) continue;
                const Segment& g = s.lines[i];
                j.findings.push_back({"clipping",
                                      "clip_line(" + str(g.a) + ", " + str(g.b) + ") returned true: a segment "
                                      "with a NaN or infinite endpoint must return false (draw_line may test "
                                      "first, but clip_line's own rule says so: NaN compares false with "
                                      "everything, so its outcode looks inside)",
                                      "Test std::isfinite on all four coordinates at the top of clip_line and "
                                      "return false.",
                                      "TODO 2"});
            }
            // A function whose every line here is one lines.h does not place (both endpoints
            // far away: only safety is tested) may draw nothing at all.
            for (const bool aa : {false, true}) {
                bool any = false, all_unjudged = true;
                for (std::size_t i = 0; i < s.lines.size(); ++i) {
                    const Segment& g = s.lines[i];
                    if (g.aa != aa || !raster::is_finite(g.a) || !raster::is_finite(g.b)) continue;
                    any = true;
                    all_unjudged &= plans[i].unjudged;
                }
                if (any && all_unjudged) j.may_draw_nothing.push_back(aa ? "draw_line_aa" : "draw_line");
            }
            break;
        }
        case Kind::kClip: {
            // The picture: each whole line, the viewport border and each clipped part, all drawn
            // with draw_line. Judged as bands: the numbers from clip_line are judged exactly.
            // The endpoints that clip_line does not move (every whole line's, a clipped part's
            // inside one) are drawn at their own pixels, like any line's: those are judged.
            auto pin = [&](Plan& plan, std::initializer_list<Vec2> ends) {
                for (Vec2 e : ends) {
                    const Vec2 c = snapped_center(e);
                    if (inside(c, s.width, s.height)) plan.pinned_ends.push_back({int(c.x), int(c.y)});
                }
            };
            for (const Segment& seg : s.lines) {
                plans.push_back(make_plan({seg.a, seg.b, kUnclippedColor}, s.width, s.height, true));
                pin(plans.back(), {seg.a, seg.b});
            }
            const Box& v = s.viewport;
            const Vec2 corners[] = {{v.xmin, v.ymin}, {v.xmax, v.ymin}, {v.xmax, v.ymax}, {v.xmin, v.ymax}};
            for (int k = 0; k < 4; ++k) {
                plans.push_back(make_plan({corners[k], corners[(k + 1) % 4], kViewportColor}, s.width, s.height, true));
                pin(plans.back(), {corners[k], corners[(k + 1) % 4]});
            }
            for (const Segment& seg : s.lines) {
                if (const auto part = clip_oracle(seg.a, seg.b, v)) {
                    plans.push_back(make_plan({part->first, part->second, seg.color}, s.width, s.height, true));
                    if (part->first == seg.a) pin(plans.back(), {seg.a});
                    if (part->second == seg.b) pin(plans.back(), {seg.b});
                }
            }
            // The numbers first, to know whether a line off its band is a clipping mistake;
            // their findings still come after the picture's.
            check.check_border_outcodes(art, "viewport_outcode.", v,
                                        "clip_line starts from outcode(), so a segment that touches the viewport's "
                                        "border is clipped wrongly");
            check.check_border_outcodes(art, "border_outcode.", pixel_center_box(s.width, s.height), kBorderWhy);
            const std::size_t at = j.findings.size();
            check.check_clip_values(art);
            const std::vector<cp::Finding> clip_findings(j.findings.begin() + std::ptrdiff_t(at), j.findings.end());
            j.findings.erase(j.findings.begin() + std::ptrdiff_t(at), j.findings.end());
            check.clip_values_right = clip_findings.empty();
            check.check_lines(plans);
            // The picture of a segment clip_line got wrong differs along the whole line (the
            // first plans): those differences are errors the numbers explain, not allowed ones.
            for (const std::size_t i : check.clip_wrong) check.judged_wrong(plans[i].candidates);
            j.findings.insert(j.findings.end(), clip_findings.begin(), clip_findings.end());
            break;
        }
    }
    if (check.border_finding && !j.findings.empty()) j.findings.insert(j.findings.begin(), *check.border_finding);
    // Writes outside the image, first: which function made them and why. A line stepping the
    // wrong way (a step-sign finding above) walks out of the image whatever the clipping does.
    const bool step_sign = std::any_of(j.findings.begin(), j.findings.end(),
                                       [](const cp::Finding& f) { return f.topic == "step sign"; });
    const std::vector<cp::Finding> strays = cp::stray_write_findings(
        art, [&](const std::string& name, long long count) { return stray_finding(s, step_sign, name, count); },
        {"clipping", "clip first, so the work stays proportional to the visible pixels"});
    j.findings.insert(j.findings.begin(), strays.begin(), strays.end());
    if (s.check_reversed) {
        const auto rev = art.images.find("reversed");
        // (No reversed image after a runaway loop: the render stopped before drawing it, the
        // runaway finding says so, and there is nothing to compare.)
        const bool stopped = rev == art.images.end() && art.values.count(cp::kRunawayKey) > 0;
        if (!stopped && (rev == art.images.end() || !(rev->second == img))) {
            long long differ = 0;
            if (rev != art.images.end() && rev->second.width() == img.width() && rev->second.height() == img.height()) {
                differ = raster::compare(rev->second, img).differing_pixels;
            }
            j.findings.push_back({"symmetry", "drawing every line from b to a changed " + cp::plural(double(differ), "pixel") +
                                                  " (see reversed.png): where the line passes exactly "
                                                  "between two pixels, the choice must not depend on the direction",
                                  "", "TODO 4"});
        }
    }

    j.tolerance.strict_channel_diff = has_aa ? 3 : 0;
    j.tolerance.max_lenient_diffs = j.tolerance.lenient.count();
    j.tolerance.why = "the lenient pixels are exactly those where correct implementations may "
                      "legitimately differ (ties, bands of clipped lines, ends of Wu lines), and the "
                      "pixel rules above check them instead";
    return j;
}

}  // namespace m1cp
