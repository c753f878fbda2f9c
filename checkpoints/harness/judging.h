// Small helpers the milestone judges share (milestones 4 and 5): numbers as findings print them,
// values read back by key, comparisons within a tolerance, a finding filed under its TODO, the
// tolerance of a picture with edges, the error of a panel against an exact picture.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "harness/checkpoint.h"
#include "raster/image.h"
#include "raster/vec.h"

namespace cp {

using Values = std::map<std::string, double>;

// v with 10 significant digits; |v| < 1e-12 prints as 0.
std::string num(double v);
// n as num() prints it and a noun, singular for exactly 1: plural(1, "level") is "1 level",
// plural(3, "level") "3 levels", plural(0.5, "level") "0.5 levels"; `many` where the plural is
// not the noun and "s": plural(4, "vertex", "vertices").
std::string plural(double n, const std::string& one, const std::string& many = "");
// The value stored under key, NaN when there is none.
double get(const Values& v, const std::string& key);
// a within tol of b, relative to max(1, |b|); NaN only matches NaN.
bool close(double a, double b, double tol);
// The vector stored under key.x, key.y, key.z; "(x, y, z)"; each component close().
raster::Vec3 vec3(const Values& v, const std::string& key);
std::string str(raster::Vec3 p);
bool same3(raster::Vec3 a, raster::Vec3 b, double tol);
// A color as findings print it: "(r, g, b)".
std::string str(raster::Color c);
// The largest difference of a channel between two colors, in levels.
int max_diff(raster::Color a, raster::Color b);

// A vote between the rule and one known mistake, pixel by pixel, where the two predict colors
// more than `apart` levels apart (a "telling" pixel; the caller leaves out those where the
// reference does not show the rule's color): the student's pixel is counted for each it
// matches within 3 levels. The mistake is named when at least 10 telling pixels match it and
// more match it than the rule, so that a picture wrong in some other way names nothing.
class PixelVote {
public:
    explicit PixelVote(int apart = 10) : apart_(apart) {}
    // Counts the pixel when the predictions tell apart; returns whether they did.
    bool cast(raster::Color got, raster::Color right, raster::Color wrong);
    bool names_mistake() const { return mistake_like_ >= 10 && mistake_like_ > rule_like_; }
    // The telling pixels that matched the mistake: of two votes that both name theirs, the
    // larger count is the nearer mistake.
    long long mistake_like() const { return mistake_like_; }
    // "at <mistake-like> of <telling> pixels", for the finding's text.
    std::string tally() const;

private:
    int apart_;
    long long telling_ = 0, mistake_like_ = 0, rule_like_ = 0;
};

// Adds a finding unless one with this topic and text is there: "TODO 5: message" (the label
// before the first ": ", when it starts with "TODO" and is short) puts "TODO 5" into its todo.
// `hint`, if any, is the finding's own (shown instead of the scene's hint).
void add_finding(Judgement& j, const std::string& topic, const std::string& msg, const std::string& hint = "");

// Pixels next to an edge or a color boundary of the expected image (a neighbour differs by more
// than 16 levels in a channel) may differ, up to a fifth of them; elsewhere 3 levels. `why` is
// printed on failure.
Tolerance edge_tolerance(const raster::Image& expected, const std::string& why);

// The mean absolute channel difference, in levels, between the rectangle (x0, y0, w, h) of
// `img` and `truth` (w x h).
double rect_error(const raster::Image& img, int x0, int y0, int w, int h, const raster::Image& truth);

// Whether a function the reference draws with was called and drew nothing (most often the
// pipeline's last TODO, not written yet): the harness names it, and every finding about the
// picture would follow from it.
bool drew_nothing(const Artifacts& art, const Artifacts& reference);

// The verdict of a checkpoint whose pictures are drawn through a pipeline of TODOs (m4, m5),
// around the milestone's own checks: `numbers` files the findings of the scene's number groups,
// and `picture` those of its picture, called when there are panels, the numbers pass and no
// function drew nothing. A checkpoint that fails (a finding of these, a function that drew
// nothing, or the main image beyond j.tolerance) then calls `prerequisites` for the findings of
// the functions its panels use, each judged on its own checkpoint's inputs; any there are
// replace every finding since `numbers` began, and then j.upstream_failed is set (as it is when
// the numbers of a picture scene fail). A checkpoint that passes stays passed, whatever its
// prerequisites do.
void judge_pipeline(Judgement& j, const Artifacts& art, const Artifacts& reference, const raster::Image& expected,
                    bool has_panels, const std::function<void()>& numbers, const std::function<void()>& picture,
                    const std::function<std::vector<Finding>()>& prerequisites);

// A prerequisite judged on its own checkpoint's inputs, the values stored under prefix: `judge`
// files its findings into a scratch judgement. The first of them, told as "fix TODO N first (see
// <checkpoint>)", or none when it passes. has_picture: whether the checkpoint asking draws a
// picture (else its numbers are what the prerequisite computes).
std::optional<Finding> prerequisite_finding(
    const Artifacts& art, const Artifacts& reference, const std::string& prefix, const std::string& checkpoint,
    const std::function<void(const Values& mine, const Values& ref, Judgement& scratch)>& judge, bool has_picture = true);

// "a, b" of the ids, each once, in their first order: the checkpoints a picture's functions pass.
std::string join_once(const std::vector<std::string>& ids);

// The measures of the counts summed over a scene's panels (yours, the reference's): each that is
// not zero on either side, as "<name> (reference <theirs>)".
void report_totals(Judgement& j, const std::map<std::string, std::pair<double, double>>& totals);

}  // namespace cp
