// Judge half of the milestone-4 checkpoints (trusted: it runs no code under test).
//
// Oracles: hand-worked values for the pinned rules (depth keys, the depth test and its tie
// rule, weights, Lambert, clamping, debug colors), the reference's numbers on the same inputs
// (normals, clipping, stage counts, depth keys read back from the buffer), the expected
// picture, and analytic pictures computed here from the scene alone (the checkerboard floor
// by ray casting, the perfect sphere), against which the error is measured and reported.
#include "m4/judge.h"

#include <algorithm>
#include <functional>
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <set>
#include <sstream>

#include "harness/diagnosis.h"
#include "harness/judging.h"
#include "m4/scenes.h"
#include "raster/plot.h"

namespace m4cp {

namespace {

using cp::close;
using cp::get;
using cp::num;
using cp::plural;
using cp::same3;
using cp::str;
using cp::Values;
using cp::vec3;

Color color3(const Values& v, const std::string& key) {
    auto ch = [&](const char* c) {
        const double x = get(v, key + c);
        return static_cast<std::uint8_t>(std::isfinite(x) ? std::clamp(x, 0.0, 255.0) : 0);
    };
    return {ch(".r"), ch(".g"), ch(".b")};
}

struct Ctx {
    const Scene& s;
    const Values& mine;
    const Values& ref;
    cp::Judgement& j;
    // With a hint of its own (shown instead of the scene's), set only when the finding is new.
    void add(const std::string& topic, const std::string& msg, const std::string& hint = "") {
        cp::add_finding(j, topic, msg, hint);
    }
    // Moves the last finding ahead of the others: it says why the picture differs, which the
    // picture's own finding does not.
    void lead() {
        if (!j.findings.empty()) std::rotate(j.findings.begin(), j.findings.end() - 1, j.findings.end());
    }
};

// judge_picture's finding that the picture differs beyond the tolerance, which names no cause:
// a finding that says why goes ahead of it, or replaces it.
bool only_says_picture_differs(const cp::Finding& f) { return f.message.rfind("the picture differs", 0) == 0; }

// ---- the pinned rules, recomputed here ----

std::uint32_t trusted_key(int format, double z, double w) {
    if (std::isnan(z)) return 0xFFFFFFFFu;
    const double d = std::clamp((z + 1) / 2, 0.0, 1.0);
    switch (format) {
        case 0: return std::bit_cast<std::uint32_t>(static_cast<float>(d));
        case 1: return 0x7F800000u - std::bit_cast<std::uint32_t>(static_cast<float>(std::clamp((1 - z) / 2, 0.0, 1.0)));
        case 2: return static_cast<std::uint32_t>(std::llround(d * double((1u << 24) - 1)));
        default:
            if (!(w > 0) || !std::isfinite(w)) return 0xFFFFFFFFu;
            return 0x7F800000u - std::bit_cast<std::uint32_t>(static_cast<float>(1 / w));
    }
}

const char* kFormatNames[4] = {"float z", "reversed-Z", "24-bit fixed", "1/w"};

Vec3 unit_or_zero(Vec3 v) {
    const double len = raster::length(v);
    if (!(len > 0) || !std::isfinite(len)) return {};
    return v / len;
}

Vec3 lambert(Vec3 ambient, const std::vector<LightSpec>& lights, Color base, Vec3 position, Vec3 normal) {
    const Vec3 n = unit_or_zero(normal);
    Vec3 sum = ambient;
    for (const LightSpec& l : lights) {
        const Vec3 dir = l.point ? unit_or_zero(l.vector - position) : unit_or_zero(-l.vector);
        const double d = raster::dot(n, dir);
        if (d > 0) sum = sum + l.intensity * d;  // a light that does not arrive adds nothing, even an infinite one
    }
    return {base.r * sum.x, base.g * sum.y, base.b * sum.z};
}

Color clamp_color(Vec3 v) {
    auto ch = [](double x) { return static_cast<std::uint8_t>(std::isnan(x) ? 0 : std::lround(std::clamp(x, 0.0, 255.0))); };
    return {ch(v.x), ch(v.y), ch(v.z)};
}

void judge_group(Group g, Ctx& c) {
    const Values& v = c.mine;
    switch (g) {
        case Group::kDepthKeys: {
            const auto cases = key_cases();
            for (std::size_t i = 0; i < cases.size(); ++i) {
                const auto& k = cases[i];
                const double mine = get(v, "key" + std::to_string(i));
                const double want = trusted_key(k.format, k.z_ndc, k.w);
                if (mine == want) continue;
                std::string other;
                for (int f = 0; f < 4; ++f) {
                    if (f != k.format && mine != 0 && mine == trusted_key(f, k.z_ndc, k.w)) other = kFormatNames[f];
                }
                const bool big = k.format == 2 || (k.format != 2 && std::abs(mine - want) > 1);
                if (!big) continue;  // one unit in the last place of a float: rounding
                // 24-bit fixed point: d * (2^24 - 1) cut down to a whole number is one below the
                // pinned key whenever the fraction is at least a half.
                std::string truncated;
                if (k.format == 2 && !std::isnan(k.z_ndc)) {
                    const double scaled = std::clamp((k.z_ndc + 1) / 2, 0.0, 1.0) * double((1u << 24) - 1);
                    if (mine == std::floor(scaled) && mine + 1 == want) {
                        truncated = ": d * (2^24 - 1) = " + num(scaled) + " was cut down to " + num(mine) +
                                    "; the key ROUNDS to the nearest whole number (std::llround), so " + num(want);
                    }
                }
                // Reversed-Z and 1/w without the reversal: the float's bits themselves, which GROW
                // toward the eye (1/w and 1 - d are larger there).
                std::string unreversed;
                if ((k.format == 1 || k.format == 3) && !std::isnan(k.z_ndc) && want != 0xFFFFFFFFu &&
                    mine == 0x7F800000u - want) {
                    unreversed = std::string(": that is the bits of float(") + (k.format == 3 ? "1 / w" : "(1 - z_ndc) / 2") +
                                 ") themselves, which grow toward the eye; the key is kReversedBase - those bits, "
                                 "reversed so that a nearer point has a SMALLER key like every format's";
                }
                c.add(k.format == 1 || k.format == 3 ? "depth format" : "depth key",
                      "TODO 1: depth_key(" + std::string(kFormatNames[k.format]) + ", z_ndc " + num(k.z_ndc) + ", w " +
                          num(k.w) + ") gave " + num(mine) + ", expected " + num(want) +
                          (other.empty() ? "" : " (that is the key of " + other + ")") +
                          (std::isnan(k.z_ndc) ? ": NaN must give kClearKey"
                           : k.format == 3 && (!(k.w > 0) || !std::isfinite(k.w))
                               ? ": the 1/w key needs a w > 0 and finite; any other w gives kClearKey"
                           : k.format != 3 && (k.z_ndc < -1 || k.z_ndc > 1)
                               ? ": z_ndc is outside [-1, 1] here, so d = (z_ndc + 1) / 2 (or (1 - z_ndc) / 2 for "
                                 "reversed-Z) is clamped to [0, 1] first: a fragment a rounding error outside the "
                                 "view volume gets the key of the near or the far plane"
                               : "") +
                          truncated + unreversed);
                if (!unreversed.empty() && !c.j.findings.empty()) {
                    c.j.findings.back().hint = "reversed-Z and 1/w keys are kReversedBase - the bits of the float, so "
                                               "that nearer is smaller";
                }
            }
            break;
        }
        case Group::kDepthTest: {
            const bool want[] = {true, false, true, false, false, false, true, true, true, true, false};
            // The colors are the render half's: (10, 200, 30) against (11, 0, 0) and so on.
            const char* what[] = {"key 5 against stored 6 (nearer)", "key 6 against stored 5 (farther)",
                                  "a tie, the new color (11, 0, 0) against the stored (10, 200, 30): brighter in red",
                                  "a tie, the new color (10, 200, 30) against the stored (11, 0, 0): darker in red",
                                  "a tie with the very same color (10, 200, 30)", "kClearKey against kClearKey",
                                  "key 0 against a cleared pixel", "kClearKey - 1 against a cleared pixel",
                                  "a tie, the new color (10, 201, 0) against the stored (10, 200, 30): equal red, "
                                  "brighter green",
                                  "a tie, the new color (10, 200, 31) against the stored (10, 200, 30): equal red and "
                                  "green, brighter blue",
                                  "a tie, the new color (10, 199, 255) against the stored (10, 200, 30): equal red, "
                                  "darker green"};
            const bool reversed = get(v, "pass0") == 0 && get(v, "pass1") == 1;
            for (int i = 0; i < 11; ++i) {
                const double mine = get(v, "pass" + std::to_string(i));
                if ((mine != 0) == want[i]) continue;
                const bool tie = i >= 2 && i != 6 && i != 7;
                c.add(reversed || !tie ? "depth test" : "tie rule",
                      std::string("TODO 2: depth_passes on ") + what[i] + " returned " + (mine != 0 ? "true" : "false") +
                          (reversed ? ": the comparison is reversed (a SMALLER key is nearer)"
                           : i == 5 ? " (a fragment whose key is kClearKey never passes)"
                           : i == 4 ? " (on a tie only a BRIGHTER color passes, and a color is not brighter than itself)"
                           : tie    ? " (on a tie the brighter color wins: larger r; equal r, larger g; equal r and g, "
                                      "larger b; not the sum of the channels)"
                                    : ""));
            }
            break;
        }
        case Group::kClearFrame: {
            if (get(v, "depth.size") != 35 || get(v, "depth.not_clear") != 0) {
                c.add("depth clear", "TODO 2: after clear_frame of a 7x5 frame with depth, the buffer held " +
                                         plural(get(v, "depth.size"), "key") + ", " + num(get(v, "depth.not_clear")) +
                                         " of them not kClearKey; expected 35 keys, all kClearKey");
            }
            if (get(v, "again.key4") < 0) {
                c.add("depth clear", "TODO 2: after a second clear_frame the depth buffer held fewer than 5 keys: "
                                     "it must have one per pixel");
            } else if (get(v, "again.key4") != 0xFFFFFFFFu) {
                c.add("depth clear", "TODO 2: a second clear_frame left a key of the previous frame (" +
                                         num(get(v, "again.key4")) + "): every frame starts with every key kClearKey");
            }
            if (get(v, "format") != 2) c.add("depth clear", "TODO 2: clear_frame must set frame.format");
            if (get(v, "color.wrong") != 0 || get(v, "color.width") != 7) {
                c.add("depth clear", "TODO 2: clear_frame must fill every pixel of frame.color with the background "
                                     "and keep its size (" + plural(get(v, "color.wrong"), "pixel") +
                                     (get(v, "color.wrong") == 1 ? " was not)" : " were not)"));
            }
            if (get(v, "off.capacity") != 0) {
                c.add("needs", "TODO 2: clear_frame without a depth test kept " + plural(get(v, "off.capacity"), "key") +
                                   " of memory, allocated earlier or here: a frame without a depth test holds no "
                                   "keys, so release them (std::vector<...>().swap(keys), or clear() and then "
                                   "shrink_to_fit(): clear() alone keeps the capacity), and allocate none");
            }
            break;
        }
        case Group::kWeights: {
            // num() shows numbers below 1e-12 as 0; a w of 1e-320 must read as what it is.
            auto tiny = [](double x) {
                std::ostringstream o;
                o << x;
                return x != 0 && std::abs(x) < 1e-12 ? o.str() : num(x);
            };
            // A NaN's sign is the platform's business: every NaN reads "NaN".
            auto given = [&tiny](double x) { return std::isnan(x) ? std::string("NaN") : tiny(x); };
            const auto cases = weight_cases();
            for (std::size_t i = 0; i < cases.size(); ++i) {
                const auto& ls = cases[i].screen;
                const auto& ws = cases[i].w;
                double q[3], sum = 0;
                for (int k = 0; k < 3; ++k) sum += q[k] = ls[k] / ws[k];
                const bool fallback = !(sum > 0) || !std::isfinite(sum);
                double want[3];
                for (int k = 0; k < 3; ++k) want[k] = fallback ? ls[k] : q[k] / sum;
                bool ok = true, screen = true;
                double mine[3];
                for (int k = 0; k < 3; ++k) {
                    mine[k] = get(v, "w" + std::to_string(i) + "." + std::to_string(k));
                    ok &= close(mine[k], want[k], 1e-9);
                    screen &= close(mine[k], ls[k], 1e-12);
                }
                if (!ok) {
                    c.add(fallback ? "extreme w" : "perspective",
                          "TODO 3: perspective_weights((" + num(ls[0]) + ", " + num(ls[1]) + ", " + num(ls[2]) +
                              "), w (" + tiny(ws[0]) + ", " + num(ws[1]) + ", " + num(ws[2]) + ")) gave (" +
                              given(mine[0]) + ", " + given(mine[1]) + ", " + given(mine[2]) + "), expected (" +
                              num(want[0]) + ", " + num(want[1]) + ", " + num(want[2]) + ")" +
                              (fallback ? ": here sum(l_i / w_i) = " + num(sum) +
                                              " is not > 0 and finite (a w of 0, a 1 / w that overflows, or NaN), so the "
                                              "screen weights come back unchanged, never NaN"
                                        : screen ? ": you returned the screen weights unchanged" : ""));
                }
            }
            break;
        }
        case Group::kNormals: {
            const double r3 = 1 / std::sqrt(3.0);
            const std::pair<const char*, Vec3> faces[] = {
                {"face", {0, 0, 1}}, {"face_tilted", {r3, r3, r3}}, {"face_cw", {0, 0, -1}}, {"face_degenerate", {0, 0, 0}}};
            for (const auto& [key, want] : faces) {
                const Vec3 mine = vec3(v, key);
                if (!same3(mine, want, 1e-9)) {
                    c.add(std::string(key) == "face_degenerate" ? "zero normal" : "normals",
                          std::string("TODO 4a: face_normal (") + key + ") gave " + str(mine) + ", expected " + str(want));
                }
            }
            if (get(v, "vn.size") != 6) c.add("normals", "TODO 4b: vertex_normals must return one normal per position");
            for (int i = 0; i < 6; ++i) {
                const std::string key = "vn" + std::to_string(i);
                const Vec3 mine = vec3(v, key), want = vec3(c.ref, key);
                if (!same3(mine, want, 1e-9)) {
                    c.add("normals", "TODO 4b: vertex normal " + std::to_string(i) + " is " + str(mine) + ", expected " +
                                         str(want) + " (sum the UNnormalized cross products, so a big face weighs "
                                                     "more; a vertex no valid triangle uses gets zero)");
                }
            }
            for (const char* key : {"nm", "nm_singular"}) {
                bool ok = true;
                for (int i = 0; i < 4; ++i) {
                    for (int k = 0; k < 4; ++k) {
                        const std::string e = std::string(key) + "." + std::to_string(i) + std::to_string(k);
                        ok &= close(get(v, e), get(c.ref, e), 1e-9);
                    }
                }
                if (!ok) {
                    c.add("normal matrix", std::string("TODO 4c: normal_matrix of ") +
                                               (std::string(key) == "nm" ? "translate * scale(2, 0.5, 1) * rotate_z(0.3)"
                                                                         : "the singular scale(1, 0, 1) (expected: the zero matrix)") +
                                               " is wrong: the inverse transpose of the upper-left 3x3, last row and "
                                               "column (0, 0, 0, 1)");
                }
            }
            break;
        }
        case Group::kLambert: {
            const auto cases = lambert_cases();
            // Which cases fail: when the only one is the case with a normal longer than 1, the
            // mistake is the missing normalization, whatever the numbers look like.
            std::vector<std::size_t> failing;
            for (std::size_t i = 0; i < cases.size(); ++i) {
                const auto& k = cases[i];
                if (!same3(vec3(v, "shade" + std::to_string(i)), lambert(k.ambient, k.lights, k.base, k.position, k.normal), 1e-9)) {
                    failing.push_back(i);
                }
            }
            // A normal whose length is not finite is the zero normal by the header's rule: its
            // case has a finding of its own, and does not count here either way.
            auto infinite_normal = [&](std::size_t i) { return !std::isfinite(raster::length(cases[i].normal)); };
            auto non_unit = [&](std::size_t i) {
                const double len = raster::length(cases[i].normal);
                return len > 0 && std::isfinite(len) && std::abs(len - 1) > 1e-9;
            };
            const bool only_non_unit =
                std::any_of(failing.begin(), failing.end(), non_unit) &&
                std::all_of(failing.begin(), failing.end(), [&](std::size_t i) { return non_unit(i) || infinite_normal(i); });
            // Every failing case is exactly what the right formula gives with every directional
            // light reversed, and so is case 0 or 1 (one light, straight on or from behind): L
            // is the light's travel direction. That finding explains the rest (a light behind
            // now adds, the grazing case's other light is lost), so they are not reported apart.
            auto reversed_lights = [](std::vector<LightSpec> ls) {
                for (LightSpec& l : ls) {
                    if (!l.point) l.vector = -l.vector;
                }
                return ls;
            };
            const bool flipped =
                !only_non_unit && !failing.empty() && (failing.front() == 0 || failing.front() == 1) &&
                std::all_of(failing.begin(), failing.end(), [&](std::size_t i) {
                    const auto& k = cases[i];
                    return same3(vec3(v, "shade" + std::to_string(i)),
                                 lambert(k.ambient, reversed_lights(k.lights), k.base, k.position, k.normal), 1e-9);
                });
            // Every failing case is exactly B * ambient brighter than the rule (and some case has a
            // nonzero ambient): the ambient term is added twice. One finding says it.
            auto ambient_of = [&](std::size_t i) {
                const auto& k = cases[i];
                return Vec3{k.base.r * k.ambient.x, k.base.g * k.ambient.y, k.base.b * k.ambient.z};
            };
            const bool ambient_twice =
                !flipped && !only_non_unit && !failing.empty() && std::all_of(failing.begin(), failing.end(), [&](std::size_t i) {
                    const auto& k = cases[i];
                    const Vec3 a = ambient_of(i);
                    return (a.x != 0 || a.y != 0 || a.z != 0) &&
                           same3(vec3(v, "shade" + std::to_string(i)), lambert(k.ambient, k.lights, k.base, k.position, k.normal) + a, 1e-6);
                });
            if (ambient_twice) {
                const std::size_t i = failing.front();
                std::string list;
                for (std::size_t f : failing) list += (list.empty() ? "" : ", ") + std::to_string(f);
                const auto& k = cases[i];
                c.add("lambert",
                      "TODO 5a: shade() case " + std::to_string(i) + " gave " +
                          str(vec3(v, "shade" + std::to_string(i))) + " levels, expected " +
                          str(lambert(k.ambient, k.lights, k.base, k.position, k.normal)) + ": exactly B * ambient = " +
                          str(ambient_of(i)) + " too much, as in every failing case (" + list +
                          "): the ambient term is added twice. B * (ambient + sum of I * max(0, N . L)) "
                          "counts the ambient once, whatever the lights",
                      "add the ambient term once: B * (ambient + sum of the lights' I * max(0, N . L))");
            }
            // Three more ways to be wrong in every failing case at once, each told once: the ambient
            // term not multiplied by the base color (255 * A instead of B * A), a point light's L
            // reversed (from the light to the surface), and a point light that fades with the
            // squared distance (the header has no fall-off).
            auto all_failing_match = [&](const std::function<Vec3(std::size_t)>& predict) {
                return !flipped && !only_non_unit && !ambient_twice && !failing.empty() &&
                       std::all_of(failing.begin(), failing.end(), [&](std::size_t i) {
                           return same3(vec3(v, "shade" + std::to_string(i)), predict(i), 1e-6);
                       });
            };
            auto points_changed = [&](std::size_t i, bool reverse) {
                const auto& k = cases[i];
                std::vector<LightSpec> ls = k.lights;
                for (LightSpec& l : ls) {
                    if (!l.point) continue;
                    const Vec3 d = l.vector - k.position;
                    const double d2 = raster::dot(d, d);
                    if (reverse) {
                        l.vector = k.position - d;  // the light mirrored through the point: L reversed
                    } else {
                        l.intensity = d2 > 0 ? l.intensity * (1 / d2) : Vec3{};
                    }
                }
                return lambert(k.ambient, ls, k.base, k.position, k.normal);
            };
            std::string told;  // the one finding that explains every failing case, if any
            std::string failing_list;
            for (std::size_t f : failing) failing_list += (failing_list.empty() ? "" : ", ") + std::to_string(f);
            if (all_failing_match([&](std::size_t i) {
                    const auto& k = cases[i];
                    return lambert(k.ambient, k.lights, k.base, k.position, k.normal) - ambient_of(i) + k.ambient * 255.0;
                })) {
                told = "lambert";
                c.add("lambert", "TODO 5a: in every failing case (" + failing_list + ") the ambient part of shade()'s "
                                 "result is 255 * ambient instead of B * ambient: the ambient light, like every light, "
                                 "is multiplied by the base color: B * (ambient + sum of I * max(0, N . L))",
                      "multiply the ambient term by the base color too: B * (ambient + sum of the lights' terms)");
            } else if (all_failing_match([&](std::size_t i) { return points_changed(i, true); })) {
                told = "light direction";
                c.add("light direction", "TODO 5a: every failing case (" + failing_list + ") has a point light, and "
                                         "each comes out exactly as with L from the light to the surface: for a point "
                                         "light, L = normalize(light position - surface position), pointing TOWARD "
                                         "the light",
                      "L = normalize(light - position) for a point light, from the surface toward the light");
            } else if (all_failing_match([&](std::size_t i) { return points_changed(i, false); })) {
                told = "lambert";
                c.add("lambert", "TODO 5a: every failing case (" + failing_list + ") has a point light, and each comes "
                                 "out exactly as with the light's intensity divided by the squared distance: "
                                 "depth_lighting.h's point lights do not fade with distance; only the direction L = "
                                 "normalize(light - position) depends on where the light is",
                      "no fall-off: a point light adds I * max(0, N . L), whatever its distance");
            }
            std::string also;  // the other failing cases the reversal explains
            for (std::size_t i : failing) {
                if (flipped && i > 1) also += (also.empty() ? "" : ", ") + std::to_string(i);
            }
            for (std::size_t i = 0; i < cases.size() && !ambient_twice && told.empty(); ++i) {
                const auto& k = cases[i];
                const Vec3 want = lambert(k.ambient, k.lights, k.base, k.position, k.normal);
                const Vec3 mine = vec3(v, "shade" + std::to_string(i));
                if (same3(mine, want, 1e-9)) continue;
                if (flipped && i > 1) continue;  // explained by the finding of case 0 or 1
                const Vec3 ambient_only{k.base.r * k.ambient.x, k.base.g * k.ambient.y, k.base.b * k.ambient.z};
                std::string topic = "lambert", why;
                const bool all_zero = same3(mine, Vec3{}, 0);
                if (infinite_normal(i)) {
                    topic = "zero normal";
                    why = std::string(": the normal has an infinite component, so its length is not finite, and "
                                      "depth_lighting.h counts such a normal as the zero normal: ambient only, as "
                                      "normal_color gives it the zero normal's gray") +
                          (std::isnan(mine.x) || std::isnan(mine.y) || std::isnan(mine.z)
                               ? ". Yours is NaN: divided by its length, inf / inf is NaN (raster::normalize does "
                                 "that); test std::isfinite(length) before dividing"
                               : "");
                } else if (only_non_unit) {
                    why = ": its normal is not of unit length (its length is " + num(raster::length(k.normal)) +
                          "), like that of every failing case, and every case with a unit normal passes: normalize N "
                          "inside shade() before the dot products, whether it is longer or shorter than 1 "
                          "(depth_lighting.h says the normal need not be unit; an interpolated one is shorter)";
                } else if (all_zero && !same3(want, Vec3{}, 0)) {
                    why = ": shade() returned nothing; start from the ambient term";
                } else if (i == 1 && (mine.x < ambient_only.x - 1e-6)) {
                    topic = "negative light";
                    why = ": a light behind the surface made it darker than ambient; use max(0, N . L)";
                } else if ((i == 0 && same3(mine, ambient_only, 1e-9)) || (i == 1 && mine.x > ambient_only.x + 1e-6)) {
                    topic = "light direction";
                    why = ": L must point from the surface TOWARD the light, i.e. -direction for a directional light";
                    if (flipped && !also.empty() && i == failing[failing.size() > 1 && failing[1] == 1 ? 1 : 0]) {
                        const bool one = also.find(',') == std::string::npos;
                        why += std::string(one ? " (case " : " (cases ") + also + (one ? " fails" : " fail") +
                               " too, exactly as the right formula gives with every directional light reversed: the "
                               "same mistake)";
                    }
                } else if (i == 2 || i == 8) {
                    topic = "grazing light";
                } else if (i == 6) {
                    topic = "zero normal";
                    why = ": a zero normal lights nothing (ambient only), never NaN";
                } else if (i == 10) {
                    // The lights' N . L summed first and clamped once: the one behind subtracts.
                    Vec3 summed{};
                    for (const auto& l : k.lights) summed = summed + l.intensity * raster::dot(unit_or_zero(k.normal), unit_or_zero(-l.vector));
                    const Vec3 clamped_sum{std::max(0.0, summed.x), std::max(0.0, summed.y), std::max(0.0, summed.z)};
                    const Vec3 as_sum = lambert(k.ambient + clamped_sum, {}, k.base, k.position, k.normal);
                    topic = "negative light";
                    why = same3(mine, as_sum, 1e-6)
                              ? ": the light behind the surface cancelled part of the one in front: the sum of the "
                                "lights' N . L was clamped at 0 once; clamp EACH light's, max(0, N . L), then add"
                              : ": the first light is in front of the surface, the second behind it: the second adds "
                                "nothing and takes nothing away (max(0, N . L) per light)";
                } else if (i == 11) {
                    topic = "grazing light";
                    why = ": the infinite light runs exactly along the surface (N . L = 0), so it adds nothing; "
                          "infinity * 0 is NaN, so skip a light whose max(0, N . L) is 0 instead of multiplying";
                }
                // The case's inputs, so that the student can redo it by hand.
                std::string inputs = "base " + str(Vec3{double(k.base.r), double(k.base.g), double(k.base.b)}) +
                                     ", ambient " + str(k.ambient) + ", normal " + str(k.normal) + ", position " +
                                     str(k.position);
                for (const auto& l : k.lights) {
                    inputs += std::string(l.point ? ", point light at " : ", directional light going ") + str(l.vector) +
                              " of intensity " + str(l.intensity);
                }
                c.add(topic, "TODO 5a: shade() case " + std::to_string(i) + " (" + inputs + ") gave " + str(mine) +
                                 " levels, expected " + str(want) + why);
            }
            const Color want[] = {{12, 13, 128}, {255, 0, 255}, {255, 0, 255}, {0, 0, 128}};
            // The levels render.cpp passes (kept in step with it).
            const char* const inputs[] = {"(12.4, 12.6, 128.2)", "(300, -20, 255.4)", "(1e9, -1e9, 254.6)",
                                          "(NaN, 0.49, 127.7)"};
            // The same levels clamped, then truncated instead of rounded.
            const Color truncated[] = {{12, 12, 128}, {255, 0, 255}, {255, 0, 254}, {0, 0, 127}};
            bool truncates = true, any_wrong = false;
            for (int i = 0; i < 4; ++i) {
                const Color mine = color3(v, "color" + std::to_string(i));
                any_wrong |= !(mine == want[i]);
                truncates &= mine == truncated[i];
            }
            if (any_wrong && truncates) {
                c.add("rounding", "TODO 5b: to_color case 0 (levels (12.4, 12.6, 128.2)) gave " + str(color3(v, "color0")) +
                                      ", expected (12, 13, 128), and cases 2 and 3 lose a level the same way: the clamp "
                                      "is right, but the channel is truncated (a cast drops the fraction); round to the "
                                      "nearest level after clamping, so 12.6 becomes 13");
            }
            for (int i = 0; i < 4 && !(any_wrong && truncates); ++i) {
                const std::string key = "color" + std::to_string(i);
                const Color mine = color3(v, key);
                if (mine == want[i]) continue;
                // Case 1's 300 and -20 wrap around to 44 and 236 when converted unclamped.
                const std::string wrapped = i != 1 ? ""
                                            : mine.r == 44 && mine.g == 236 ? "300 and -20 wrapped around to 44 and 236"
                                            : mine.r == 44                  ? "300 wrapped around to 44"
                                            : mine.g == 236                 ? "-20 wrapped around to 236"
                                                                            : "";
                c.add("clamp", "TODO 5b: to_color case " + std::to_string(i) + " (levels " + inputs[i] + ") gave " +
                                   str(mine) + ", expected " + str(want[i]) +
                                   (wrapped.empty() ? "" : ": " + wrapped + "; clamp each channel to [0, 255] before converting"),
                      wrapped.empty() ? "" : "clamp each channel to [0, 255] first (below 0 is 0, above 255 is 255), then round");
            }
            break;
        }
        case Group::kDebugColors: {
            const double zs[] = {-1, 1, 0.1, 0.5, -3, 2};
            for (int i = 0; i < 6; ++i) {
                const double d = std::clamp((zs[i] + 1) / 2, 0.0, 1.0), level = 255 * (1 - d);
                const Color mine = color3(v, "gray" + std::to_string(i));
                if (std::abs(mine.r - level) <= 1 && mine.r == mine.g && mine.g == mine.b) continue;
                c.add("debug view", "TODO 6: depth_gray(" + num(zs[i]) + ") gave " + str(mine) + ", expected a gray of " +
                                        num(level) + " (near white, far black)");
            }
            // The last two have a length that is not finite: the zero vector's gray by the rule.
            // (1e200, -1e200, 0) may also give the color of its direction (scaled down first);
            // (inf, 0, 0) is where raster::normalize gives NaN (inf / inf).
            const Vec3 ns[] = {{0, 0, 1}, {1, 0, 0}, {0, -2, 0}, {1, 1, 1}, {0, 0, 0}, {1e200, -1e200, 0},
                               {std::numeric_limits<double>::infinity(), 0, 0}};
            for (int i = 0; i < 7; ++i) {
                const Color mine = color3(v, "ncolor" + std::to_string(i));
                auto color_of = [](Vec3 n) { return (unit_or_zero(n) + Vec3{1, 1, 1}) * 127.5; };
                auto near = [&](Vec3 want) {
                    return std::abs(mine.r - want.x) <= 1 && std::abs(mine.g - want.y) <= 1 && std::abs(mine.b - want.z) <= 1;
                };
                const Vec3 want = color_of(ns[i]);
                // A finite normal whose length overflows may also give its direction's color.
                const bool huge = !std::isfinite(raster::length(ns[i]));
                if (near(want) || (huge && raster::is_finite(ns[i]) && near(color_of(ns[i] * 0x1p-700)))) continue;
                c.add("debug view",
                      "TODO 6: normal_color" + str(ns[i]) + " gave " + str(mine) + ", expected about " + str(want) +
                          " (of the NORMALIZED normal)" +
                          (huge ? "; its length is not finite, so it is the zero vector (lesson section 5), hence gray "
                                  "(raster::normalize gives NaN for an infinite component: inf / inf)"
                                : ""));
            }
            break;
        }
        case Group::kClip: {
            const auto cases = clip_cases();
            {
                // Nothing back for any case, where the reference keeps a polygon: clip_triangle
                // is not written yet (or returns before it walks the planes), not an inside test.
                bool none = true, ref_some = false;
                for (std::size_t i = 0; i < cases.size(); ++i) {
                    none &= get(v, "clip" + std::to_string(i) + ".n") == 0;
                    ref_some |= get(c.ref, "clip" + std::to_string(i) + ".n") > 0;
                }
                if (none && ref_some) {
                    c.add("clipping", "TODO 7: clip_triangle returned no vertices for any of the " +
                                          std::to_string(cases.size()) + " cases, even the triangle entirely inside "
                                          "(case 0, expected its 3 vertices): is it written yet? Start from the "
                                          "triangle's 3 vertices and clip the polygon against each of the six planes "
                                          "in turn, keeping a vertex when d >= 0");
                    break;
                }
            }
            static const char* kFields[] = {".cx", ".cy", ".cz", ".cw", ".color.x", ".color.y", ".color.z", ".normal.x",
                                            ".normal.y", ".normal.z", ".world.x", ".world.y", ".world.z", ".u", ".v"};
            for (std::size_t i = 0; i < cases.size(); ++i) {
                const std::string key = "clip" + std::to_string(i);
                // Counts from hostile artifacts: anything but a small whole number is -1.
                auto count = [](double x) { return std::isfinite(x) && x >= 0 && x <= 64 ? static_cast<int>(x) : -1; };
                const int n = count(get(v, key + ".n")), rn = count(get(c.ref, key + ".n"));
                // The case's inputs, so that the student can redo it by hand.
                std::string inputs;
                for (int k = 0; k < 3; ++k) {
                    const Vec4 p = cases[i].clip[std::size_t(k)];
                    inputs += std::string(k ? ", " : "") + "(" + num(p.x) + ", " + num(p.y) + ", " + num(p.z) + ", " + num(p.w) + ")";
                }
                const std::string what = "clip_triangle case " + std::to_string(i) + " (clip positions " + inputs + ")";
                if (n != rn) {
                    // A vertex inside the closed volume and exactly on one of its planes: the
                    // header's rule keeps it (d >= 0), which a strict test (d > 0) does not.
                    std::string touching;
                    for (const Vec4& q : cases[i].clip) {
                        const double d[6] = {q.w + q.x, q.w - q.x, q.w + q.y, q.w - q.y, q.w + q.z, q.w - q.z};
                        if (touching.empty() && std::all_of(d, d + 6, [](double x) { return x >= 0; }) &&
                            std::any_of(d, d + 6, [](double x) { return x == 0; })) {
                            touching = "(" + num(q.x) + ", " + num(q.y) + ", " + num(q.z) + ", " + num(q.w) + ")";
                        }
                    }
                    if (!touching.empty()) {
                        c.add("inside test", "TODO 7b: " + what + " gave " + plural(double(n), "vertex", "vertices") + ", expected " +
                                                 std::to_string(rn) + ". The vertex " + touching +
                                                 " lies exactly on a plane (d = 0), and a vertex on a plane is INSIDE it: "
                                                 "keep a when da >= 0 (not da > 0) and add a new vertex when (da >= 0) != "
                                                 "(db >= 0). The edge between it and an outside neighbour then adds a new "
                                                 "vertex at the very same point, which the count includes");
                    } else {
                        c.add("clipping", "TODO 7b: " + what + " gave " + plural(double(n), "vertex", "vertices") + ", expected " +
                                              std::to_string(rn));
                    }
                    continue;
                }
                // The same polygon, possibly starting at another vertex (the plane order is free).
                bool found_any = false, positions_only = false;
                std::set<std::string> wrong_attributes;  // where the positions match
                for (int shift = 0; shift < std::max(1, n) && !found_any; ++shift) {
                    bool all = true, pos = true;
                    std::set<std::string> wrong;
                    for (int a = 0; a < n; ++a) {
                        const std::string mk = key + "." + std::to_string((a + shift) % n), rk = key + "." + std::to_string(a);
                        for (int f = 0; f < 15; ++f) {
                            const bool ok = close(get(v, mk + kFields[f]), get(c.ref, rk + kFields[f]), 1e-9);
                            all &= ok;
                            if (f < 4) pos &= ok;
                            if (!ok && f >= 4) wrong.insert(f < 7 ? "color" : f < 10 ? "normal" : f < 13 ? "world position" : "uv");
                        }
                    }
                    found_any = all;
                    if (pos && !all) {
                        positions_only = true;
                        wrong_attributes = wrong;
                    }
                }
                if (!found_any) {
                    std::string names;
                    for (const std::string& w : wrong_attributes) names += (names.empty() ? "" : ", ") + w;
                    c.add("clipping", "TODO 7: " + what +
                                          (positions_only ? ": the positions are right but not the " + names +
                                                                " of the new vertices: lerp every attribute with the "
                                                                "same t as the position"
                                                          : ": the vertices differ from the reference's"));
                }
            }
            break;
        }
    }
}

// The probes of a scene variant (render.cpp, probes()): "probe.<topic>.<name>[.<component>]",
// each compared with the reference's on the same inputs; one finding per name. Colors (debug
// views) may differ by one level (rounding of an exact half), numbers by 1e-9 relative.
void judge_probes(Ctx& c) {
    std::set<std::string> reported;
    for (const auto& [key, ref] : c.ref) {
        if (key.rfind("probe.", 0) != 0) continue;
        const auto topic_end = key.find('.', 6);
        if (topic_end == std::string::npos) continue;
        const auto name_end = key.find('.', topic_end + 1);
        const std::string name = key.substr(0, name_end);
        std::string topic = key.substr(6, topic_end - 6);
        std::replace(topic.begin(), topic.end(), '_', ' ');
        const double mine = get(c.mine, key);
        const bool ok = topic == "debug view" ? std::abs(mine - ref) <= 1 : close(mine, ref, 1e-9);
        if (reported.count(name) || ok) continue;
        reported.insert(name);
        c.add(topic, "on inputs drawn for this grading (not the lesson's), " + name.substr(topic_end + 1) + " gave " +
                         num(mine) + " where the reference gives " + num(ref) + " (" + key.substr(6) +
                         "): the function must work for any input, not only the public ones");
    }
}

// ---- pictures ----

// Pixels next to an edge or a color boundary of the expected image (a neighbour differs by more
// than 16 levels) may differ, up to a fifth of them; elsewhere 3 levels (lighting rounding).
cp::Tolerance tolerance_for(const raster::Image& expected) {
    return cp::edge_tolerance(expected, "pixels next to an edge depend on how a vertex near a pixel boundary rounds");
}

// The view basis of a camera, as look_at pins it (f forward, r right, u up).
struct Basis {
    Vec3 r, u, f;
};
Basis basis(const Camera& c) {
    Vec3 f = unit_or_zero(c.target - c.eye);
    if (raster::length(f) == 0) f = {0, 0, -1};
    Vec3 side = raster::cross(f, unit_or_zero(c.up));
    if (!(raster::length(side) >= 1e-9)) side = {1, 0, 0};
    const Vec3 r = unit_or_zero(side);
    return {r, raster::cross(r, f), f};
}

// The ray through the center of pixel (x, y) of a perspective panel.
Vec3 ray(const Panel& p, const Basis& b, int x, int y) {
    const double t = std::tan(p.camera.fovy * std::numbers::pi / 360), aspect = double(p.w) / p.h;
    const double nx = 2 * (x + 0.5) / p.w - 1, ny = 1 - 2 * (y + 0.5) / p.h;
    return b.r * (nx * t * aspect) + b.u * (ny * t) + b.f;
}

}  // namespace

raster::Image analytic_checker(const Panel& p) {
    raster::Image img(p.w, p.h, p.background);
    if (p.items.empty() || p.items[0].mesh.positions.size() < 4) return img;
    const auto& q = p.items[0].mesh.positions;
    const Vec3 a = q[0], eu = q[1] - q[0], ev = q[3] - q[0];
    const Vec3 n = raster::cross(eu, ev);
    const Basis b = basis(p.camera);
    for (int y = 0; y < p.h; ++y) {
        for (int x = 0; x < p.w; ++x) {
            const Vec3 d = ray(p, b, x, y);
            const double denom = raster::dot(n, d);
            if (denom == 0) continue;
            const double t = raster::dot(n, a - p.camera.eye) / denom;
            if (!(t > 0)) continue;
            const Vec3 hit = p.camera.eye + d * t - a;
            const double u = raster::dot(hit, eu) / raster::dot(eu, eu), v = raster::dot(hit, ev) / raster::dot(ev, ev);
            if (u < 0 || u > 1 || v < 0 || v > 1) continue;
            const long long i = static_cast<long long>(std::floor(u * 8)), k = static_cast<long long>(std::floor(v * 8));
            img.set(x, y, ((i + k) % 2 == 0) ? Color{255, 255, 255} : Color{32, 32, 32});
        }
    }
    return img;
}

raster::Image analytic_sphere(const Panel& p) {
    raster::Image img(p.w, p.h, p.background);
    if (p.items.empty()) return img;
    const Item& it = p.items[0];
    const Basis b = basis(p.camera);
    for (int y = 0; y < p.h; ++y) {
        for (int x = 0; x < p.w; ++x) {
            const Vec3 d = unit_or_zero(ray(p, b, x, y));
            const Vec3 oc = p.camera.eye - it.position;
            const double r = it.size.x;  // uniform scale in these scenes
            const double half_b = raster::dot(oc, d), cc = raster::dot(oc, oc) - r * r;
            const double disc = half_b * half_b - cc;
            if (disc < 0) continue;
            const double t = -half_b - std::sqrt(disc);
            if (!(t > 0)) continue;
            const Vec3 hit = p.camera.eye + d * t;
            img.set(x, y, clamp_color(lambert(p.ambient, p.lights, it.material, hit, (hit - it.position) / r)));
        }
    }
    return img;
}

// The mean absolute channel difference between a panel of `img` and `truth`, in levels.
double panel_error(const raster::Image& img, const Panel& p, const raster::Image& truth) {
    return cp::rect_error(img, p.x0, p.y0, p.w, p.h, truth);
}

namespace {

const char* picture_topic(const std::string& id) {
    static const std::map<std::string, const char*> topics = {
        {"m4.occlusion_order", "depth test"},       {"m4.interpenetrating", "depth test"},
        {"m4.depth_view", "debug view"},            {"m4.clear_between_frames", "depth clear"},
        {"m4.perspective_checker", "perspective"},  {"m4.screen_space_checker", "interpolation"},
        {"m4.flat_sphere", "flat shading"},         {"m4.gouraud_sphere", "gouraud"},
        {"m4.per_pixel_sphere", "per-pixel normals"}, {"m4.light_behind", "negative light"},
        {"m4.nonuniform_scale", "normal matrix"},   {"m4.grazing_light", "grazing light"},
        {"m4.overflow", "clamp"},                   {"m4.normal_view", "debug view"},
        {"m4.zfight_formats", "depth format"},      {"m4.coplanar", "tie rule"},
        {"m4.degenerate_normals", "zero normal"},   {"m4.near_eye", "clipping"},
        {"m4.extreme_input", "bad input"},          {"m4.needs", "needs"},
        {"m4.fill_triangle", "rasterizer"},         {"m4.flat_clipped", "flat shading"},
        {"m4.missing_face_colors", "face color"},   {"m4.shared_edges", "fill rule"},
        {"m4.point_light_floor", "world position"},
    };
    const auto it = topics.find(id);
    return it == topics.end() ? "pipeline" : it->second;
}

// The caller that a picture's failure points to once the functions it calls pass their own
// checks: its concept tag and "TODO N" with what to look at. A theme that is already a
// caller's concept stays.
std::pair<std::string, std::string> caller_of(const std::string& theme, Shade shading, bool clipping_differs) {
    auto lighting_caller = [shading]() -> std::pair<std::string, std::string> {
        if (shading == Shade::kFlat) {
            return {"flat shading", "TODO 9: draw_mesh lights a flat triangle once, with the face normal of its world "
                                    "positions, at its centroid"};
        }
        if (shading == Shade::kGouraud) {
            return {"gouraud", "TODOs 8, 9: draw_mesh lights every vertex once, at its world position with its world "
                               "normal, and fill_triangle interpolates the lit colors with the perspective-correct "
                               "weights of perspective_weights: with the screen weights "
                               "l_i a Gouraud sphere's colors shift only a little, so only its picture shows it"};
        }
        return {"per-pixel normals", "TODOs 8 and 9: draw_mesh gives each vertex its world position (model * "
                                     "position) and world normal; fill_triangle interpolates both with the "
                                     "perspective-correct weights, as every attribute, normalizes the normal, then "
                                     "calls shade() and to_color() for every fragment"};
    };
    if (theme == "depth test" || theme == "tie rule" || theme == "depth format") {
        return {"rasterizer", "TODO 8: fill_triangle keys every fragment with depth_key and lets depth_passes decide, "
                              "writing color and key only when it passes"};
    }
    if (theme == "debug view") {
        return {"rasterizer", "TODO 8: fill_triangle colors each fragment with depth_gray or normal_color of the "
                              "interpolated value"};
    }
    if (theme == "fill rule") {
        return {"fill rule", "TODO 8: fill_triangle covers a pixel center on an edge by milestone 2's top-left rule, "
                             "so each center on an edge shared by two triangles is drawn once"};
    }
    if (theme == "perspective") {
        return {"rasterizer", "TODO 8: fill_triangle weighs the attributes with perspective_weights"};
    }
    if (theme == "world position" && clipping_differs) {
        return {"pipeline", "TODO 9: draw_mesh transforms, clips, culls, fans and fills every triangle as "
                            "depth_lighting.h says (the triangle counts below differ from the reference's)"};
    }
    if (theme == "world position") {
        return {"world position", "TODOs 8 and 9: for a point light, draw_mesh gives each vertex its world position "
                                  "(model * position) and sets FillState::point_light, and fill_triangle hands "
                                  "shade() the world position interpolated with the perspective-correct weights of "
                                  "perspective_weights, as every attribute: with the screen weights l_i each pixel "
                                  "of a receding floor is lit as a point nearer the camera, and the pool of light "
                                  "slides toward the viewer"};
    }
    if (theme == "face color") {
        return {"face color", "TODO 9: draw_mesh colors a kFaceColor triangle with face_colors[face], face being its "
                              "index in mesh.triangles (a triangle culled, clipped away or skipped before it still "
                              "owns its index, so never a count of the triangles drawn), and a triangle past the end "
                              "of that list (or of an empty one) white"};
    }
    if (theme == "depth clear") return {"pipeline", "TODO 9: every frame starts with clear_frame"};
    if (theme == "normal matrix") {
        return {"pipeline", "TODO 9: normal_matrix passes, so its caller is wrong: draw_mesh sends every normal "
                            "through normal_matrix(model), never through the model matrix itself, and normalizes "
                            "what comes out"};
    }
    if (theme == "clipping" && clipping_differs) {
        return {"pipeline", "TODO 9: draw_mesh clips in clip space with clip_triangle, fans the polygon it returns and "
                            "divides only then"};
    }
    if (theme == "clamp" || theme == "negative light" || theme == "grazing light" || theme == "zero normal" ||
        theme == "lambert" || theme == "light direction" || theme == "normals") {
        return lighting_caller();
    }
    if (theme == "flat shading" || theme == "gouraud" || theme == "per-pixel normals") return lighting_caller();
    if (theme == "interpolation" || theme == "rasterizer") {
        return {theme, "TODO 8: fill_triangle must interpolate every covered pixel's attributes and write it only "
                       "when it passes the depth test"};
    }
    if (theme == "pipeline" && (shading == Shade::kFlat || shading == Shade::kGouraud || shading == Shade::kPerPixel)) {
        return lighting_caller();  // a lit panel differs: how its lighting is called
    }
    return {theme == "clipping" ? "pipeline" : theme,
            "TODO 9: draw_mesh transforms, clips, fans and fills every triangle as depth_lighting.h says"};
}

const char* shade_name(Shade s) {
    switch (s) {
        case Shade::kFlat: return "flat";
        case Shade::kGouraud: return "Gouraud";
        case Shade::kPerPixel: return "per-pixel";
        default: return "other";
    }
}

// The error-against-run-time checkpoint: every sphere must be as close to the perfect sphere as
// the reference's (within half a level on average), and the chart of error against time, yours
// beside the reference's, goes into the report.
void judge_shading_chart(Ctx& c, const raster::Image& mine, const cp::Artifacts& ref) {
    const Scene& s = c.s;
    const auto ref_it = ref.images.find("main");
    raster::PlotSpec chart;
    chart.title = "error against run time";
    chart.x_label = "milliseconds per sphere (64 x 64 pixels), log scale";
    chart.y_label = "mean error vs the perfect sphere (levels)";
    chart.log_x = true;
    const Shade modes[3] = {Shade::kFlat, Shade::kGouraud, Shade::kPerPixel};
    const Color strong[3] = {{210, 60, 50}, {40, 150, 60}, {50, 90, 210}}, light[3] = {{240, 170, 160}, {160, 215, 170}, {165, 185, 240}};
    for (int m = 0; m < 3; ++m) {
        raster::PlotSeries yours{std::string(shade_name(modes[m])) + " (yours)", strong[m], {}, {}};
        raster::PlotSeries theirs{std::string(shade_name(modes[m])) + " (reference)", light[m], {}, {}};
        for (std::size_t p = 0; p < s.panels.size(); ++p) {
            const Panel& panel = s.panels[p];
            if (panel.shading != modes[m]) continue;
            const raster::Image truth = analytic_sphere(panel);
            const double err = panel_error(mine, panel, truth);
            const double ref_err = ref_it == ref.images.end() ? err : panel_error(ref_it->second, panel, truth);
            const std::string key = "panel" + std::to_string(p) + ".seconds";
            const double ms = 1e3 * get(c.mine, key), ref_ms = 1e3 * get(c.ref, key);
            const std::string what = std::string(shade_name(modes[m])) + ", " + std::to_string(panel.items.empty() ? 0 : panel.items[0].mesh.triangles.size()) + " triangles";
            c.j.measures["error " + what + " (reference " + num(std::round(ref_err * 100) / 100) + ")"] = std::round(err * 100) / 100;
            yours.points.push_back({ms, err});
            theirs.points.push_back({ref_ms, ref_err});
            const std::string label = std::to_string(panel.items.empty() ? 0 : panel.items[0].mesh.triangles.size());
            yours.labels.push_back(label);
            theirs.labels.push_back("");
            if (err > ref_err + 0.5) {
                const char* topic = modes[m] == Shade::kFlat ? "flat shading" : modes[m] == Shade::kGouraud ? "gouraud" : "per-pixel normals";
                c.add(topic, "TODO 9: the " + what + " sphere is " + plural(std::round(err * 100) / 100, "level") +
                                 " from the perfect sphere on average, the reference's " +
                                 num(std::round(ref_err * 100) / 100));
            }
        }
        chart.series.push_back(theirs);
        chart.series.push_back(yours);
    }
    c.j.pictures["error_vs_time"] = raster::plot(chart);
}

Color rounded(Vec3 v) { return Color{raster::to_channel(v.x), raster::to_channel(v.y), raster::to_channel(v.z)}; }

// Calls f(x, y, l) for each pixel of the panel whose center lies well inside the ready-made
// triangle t (every screen weight l_i at least 0.05), with its screen weights; nothing for a
// triangle of zero area.
template <class F>
void for_inner_pixels(const ScreenTri& t, const Panel& panel, F&& f) {
    const double area = (t.screen[1].x - t.screen[0].x) * (t.screen[2].y - t.screen[0].y) -
                        (t.screen[1].y - t.screen[0].y) * (t.screen[2].x - t.screen[0].x);
    if (area == 0) return;
    for (int y = 0; y < panel.h; ++y) {
        for (int x = 0; x < panel.w; ++x) {
            const double px = x + 0.5, py = y + 0.5;
            double l[3];
            for (int i = 0; i < 3; ++i) {
                const Vec3 a = t.screen[std::size_t((i + 1) % 3)], b = t.screen[std::size_t((i + 2) % 3)];
                l[i] = ((b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x)) / area;
            }
            if (l[0] < 0.05 || l[1] < 0.05 || l[2] < 0.05) continue;
            f(x, y, l);
        }
    }
}

// The ready-made triangles' colors, worked out here at pixels well inside the first triangle
// where the reference shows it (not hidden, not a tie lost to the gray copy), both with the
// perspective-correct weights and with the screen weights: more pixels matching the second
// than the first name the mistake.
void judge_screen_weights(Ctx& c, const raster::Image& mine, const cp::Artifacts& ref, const Panel& panel) {
    const auto ref_it = ref.images.find("main");
    if (ref_it == ref.images.end() || !panel.perspective_correct) return;
    const ScreenTri& t = panel.screen_tris[0];
    cp::PixelVote screen_weighted;
    for_inner_pixels(t, panel, [&](int x, int y, const double* l) {
        double q[3], sum = 0;
        for (int i = 0; i < 3; ++i) sum += q[i] = l[i] / t.w[std::size_t(i)];
        Vec3 persp{}, flat{};
        for (int i = 0; i < 3; ++i) {
            persp = persp + t.color[std::size_t(i)] * (q[i] / sum);
            flat = flat + t.color[std::size_t(i)] * l[i];
        }
        const Color pc = rounded(persp), sc = rounded(flat);
        if (cp::max_diff(ref_it->second.at(panel.x0 + x, panel.y0 + y), pc) > 3) return;
        screen_weighted.cast(mine.at(panel.x0 + x, panel.y0 + y), pc, sc);
    });
    if (screen_weighted.names_mistake()) {
        c.add("perspective",
              "TODO 8: " + screen_weighted.tally() +
                  " inside the first triangle your colors are the SCREEN-weighted ones: weigh "
                  "each vertex by l_i / w_i and normalize (perspective_weights) unless "
                  "needs.perspective_correct is false",
              "fill_triangle weighs every attribute with perspective_weights(l, w): l_i / w_i, "
              "normalized, unless needs.perspective_correct is false");
    }
}

// The w of a 1/w key (kReversedBase - the bits of float(1 / w)); NaN when it is none.
double inverse_w_of(double key) {
    if (!(key >= 0 && key <= 2139095040.0)) return std::nan("");
    const float inv = std::bit_cast<float>(static_cast<std::uint32_t>(0x7F800000u - static_cast<std::uint32_t>(key)));
    return inv > 0 ? 1 / double(inv) : std::nan("");
}

// The w (distance along the view direction) of every triangle of a perspective panel's items
// that the ray through the center of pixel (x, y) meets: the candidates for the pixel's w.
std::vector<double> surface_ws(const Panel& p, int x, int y) {
    std::vector<double> out;
    if (p.camera.ortho) return out;
    const Basis b = basis(p.camera);
    const Vec3 d = ray(p, b, x, y);  // its component along the view direction is 1
    for (const Item& it : p.items) {
        // model = translate(position) * rotate(axis, angle) * scale(size), Rodrigues' rotation.
        const Vec3 k = unit_or_zero(it.axis);
        const double cs = std::cos(it.angle), sn = std::sin(it.angle);
        auto world = [&](Vec3 v) {
            v = {v.x * it.size.x, v.y * it.size.y, v.z * it.size.z};
            v = v * cs + raster::cross(k, v) * sn + k * (raster::dot(k, v) * (1 - cs));
            return v + it.position;
        };
        for (const auto& t : it.mesh.triangles) {
            const int n = static_cast<int>(it.mesh.positions.size());
            if (t[0] < 0 || t[0] >= n || t[1] < 0 || t[1] >= n || t[2] < 0 || t[2] >= n) continue;
            const Vec3 a = world(it.mesh.positions[std::size_t(t[0])]), e1 = world(it.mesh.positions[std::size_t(t[1])]) - a,
                       e2 = world(it.mesh.positions[std::size_t(t[2])]) - a;
            const Vec3 pv = raster::cross(d, e2);
            const double det = raster::dot(e1, pv);
            if (det == 0 || !std::isfinite(det)) continue;
            const Vec3 tv = p.camera.eye - a;
            const double u = raster::dot(tv, pv) / det;
            const Vec3 qv = raster::cross(tv, e1);
            const double v = raster::dot(d, qv) / det, t_hit = raster::dot(e2, qv) / det;
            if (u >= -1e-9 && v >= -1e-9 && u + v <= 1 + 1e-9 && t_hit > 0) out.push_back(t_hit);
        }
    }
    return out;
}

// The normal view's color of a normal (normal_color's rule, recomputed here).
Color color_of(Vec3 n) {
    const Vec3 u = unit_or_zero(n);
    return Color{raster::to_channel(127.5 * (u.x + 1)), raster::to_channel(127.5 * (u.y + 1)),
                 raster::to_channel(127.5 * (u.z + 1))};
}

// A normal view of normals given per position (m4.nonuniform_scale's right panel), worked out
// by ray casting: at the hit, the world-space barycentric weights ARE the perspective-correct
// weights. The header's way normalizes each normal after the normal matrix (R * S^-1 for
// model R * S) and then interpolates; the mistake interpolates them at the lengths the matrix
// gives. Where the two colors differ clearly, more pixels like the second name it.
void judge_normal_lengths(Ctx& c, const raster::Image& mine, const Panel& p, const std::string& where) {
    if (p.camera.ortho || p.shading != Shade::kNormalView) return;
    const Basis b = basis(p.camera);
    cp::PixelVote unnormalized(12);
    for (int y = 0; y < p.h; ++y) {
        for (int x = 0; x < p.w; ++x) {
            const Vec3 d = ray(p, b, x, y);
            double best = std::numeric_limits<double>::infinity();
            Vec3 good{}, bad{};
            for (const Item& it : p.items) {
                if (it.mesh.normals.size() != it.mesh.positions.size()) continue;
                const Vec3 k = unit_or_zero(it.axis);
                const double cs = std::cos(it.angle), sn = std::sin(it.angle);
                auto turn = [&](Vec3 v) { return v * cs + raster::cross(k, v) * sn + k * (raster::dot(k, v) * (1 - cs)); };
                auto world = [&](Vec3 v) { return turn({v.x * it.size.x, v.y * it.size.y, v.z * it.size.z}) + it.position; };
                auto normal = [&](Vec3 n) { return turn({n.x / it.size.x, n.y / it.size.y, n.z / it.size.z}); };
                const int n = static_cast<int>(it.mesh.positions.size());
                for (const auto& t : it.mesh.triangles) {
                    if (t[0] < 0 || t[0] >= n || t[1] < 0 || t[1] >= n || t[2] < 0 || t[2] >= n) continue;
                    const Vec3 a = world(it.mesh.positions[std::size_t(t[0])]);
                    const Vec3 e1 = world(it.mesh.positions[std::size_t(t[1])]) - a, e2 = world(it.mesh.positions[std::size_t(t[2])]) - a;
                    const Vec3 pv = raster::cross(d, e2);
                    const double det = raster::dot(e1, pv);
                    if (det == 0 || !std::isfinite(det)) continue;
                    const Vec3 tv = p.camera.eye - a, qv = raster::cross(tv, e1);
                    const double u = raster::dot(tv, pv) / det, v = raster::dot(d, qv) / det, hit = raster::dot(e2, qv) / det;
                    // Well inside the triangle only: its edges depend on snapping.
                    if (u < 0.05 || v < 0.05 || u + v > 0.95 || !(hit > 0) || hit >= best) continue;
                    best = hit;
                    const double l[3] = {1 - u - v, u, v};
                    good = bad = Vec3{};
                    for (int i = 0; i < 3; ++i) {
                        const Vec3 nw = normal(it.mesh.normals[std::size_t(t[std::size_t(i)])]);
                        good = good + unit_or_zero(nw) * l[i];
                        bad = bad + nw * l[i];
                    }
                }
            }
            if (!std::isfinite(best)) continue;
            unnormalized.cast(mine.at(p.x0 + x, p.y0 + y), color_of(good), color_of(bad));
        }
    }
    if (unnormalized.names_mistake()) {
        c.add("normal matrix", "TODO 9: " + unnormalized.tally() + " well inside the quad" + where +
                                   " your normal colors are those of normals interpolated at the lengths the normal "
                                   "matrix gives them: under a non-uniform scale it lengthens some normals and shortens "
                                   "others, and a blend leans toward the longer ones. draw_mesh normalizes every normal "
                                   "right after normal_matrix (step 1), before anything interpolates it");
    }
}

// A normal view of a sphere (item 0 at its position, uniform size), worked out by ray casting:
// the colors are those of the WORLD normal at the hit. Colors of the same normal turned into
// view space (normal_matrix(view * model)) differ clearly only when the camera does not look
// down -z; where they do, more pixels like the view-space colors name that mistake.
void judge_normal_space(Ctx& c, const raster::Image& mine, const Panel& p, const std::string& where) {
    if (p.camera.ortho || p.shading != Shade::kNormalView || p.items.empty()) return;
    const Item& it = p.items[0];
    const Basis b = basis(p.camera);
    cp::PixelVote view_space(16);
    for (int y = 0; y < p.h; ++y) {
        for (int x = 0; x < p.w; ++x) {
            const Vec3 d = unit_or_zero(ray(p, b, x, y));
            const Vec3 oc = p.camera.eye - it.position;
            const double r = it.size.x;
            const double half_b = raster::dot(oc, d), cc = raster::dot(oc, oc) - r * r;
            const double disc = half_b * half_b - cc;
            if (disc < 0) continue;
            const double t = -half_b - std::sqrt(disc);
            if (!(t > 0)) continue;
            const Vec3 n = unit_or_zero(p.camera.eye + d * t - it.position);
            if (-raster::dot(n, d) < 0.3) continue;  // near the outline the facets decide
            const Vec3 nv{raster::dot(n, b.r), raster::dot(n, b.u), -raster::dot(n, b.f)};
            view_space.cast(mine.at(p.x0 + x, p.y0 + y), color_of(n), color_of(nv));
        }
    }
    if (view_space.names_mistake()) {
        c.add("debug view", "TODO 9: " + view_space.tally() + " of the ball" + where +
                                " your normal colors are those of VIEW-space normals (normal_matrix(view * model)): "
                                "kNormalView shows the WORLD-space normal, the one draw_mesh gives every vertex "
                                "through normal_matrix(model) in step 1, whatever the camera",
              "normals must be in world space: draw_mesh (TODO 9) sends them through "
              "normal_matrix(model), never through the view matrix");
        c.lead();
    }
}

// Two ready-made triangles on the same three vertices (m4.fill_triangle's first and its gray
// copy): every key of the second ties with the first's exactly, and depth_passes gives each tie
// to the brighter color. Where the reference shows the later one and yours still shows the
// earlier one, ties never reached depth_passes (rejected as key >= stored before it).
void judge_ties(Ctx& c, const raster::Image& mine, const cp::Artifacts& ref, const Panel& panel) {
    const auto ref_it = ref.images.find("main");
    if (ref_it == ref.images.end() || !panel.depth_test) return;
    for (std::size_t i = 0; i < panel.screen_tris.size(); ++i) {
        for (std::size_t j = i + 1; j < panel.screen_tris.size(); ++j) {
            const ScreenTri &t = panel.screen_tris[i], &u = panel.screen_tris[j];
            if (t.screen != u.screen || t.w != u.w) continue;
            long long shown = 0, kept = 0;
            for_inner_pixels(t, panel, [&](int x, int y, const double* l) {
                double q[3], sum = 0;
                for (int k = 0; k < 3; ++k) sum += q[k] = panel.perspective_correct ? l[k] / t.w[std::size_t(k)] : l[k];
                Vec3 first{}, later{};
                for (int k = 0; k < 3; ++k) {
                    first = first + t.color[std::size_t(k)] * (q[k] / sum);
                    later = later + u.color[std::size_t(k)] * (q[k] / sum);
                }
                const Color fc = rounded(first), lc = rounded(later);
                if (cp::max_diff(fc, lc) <= 12 || cp::max_diff(ref_it->second.at(panel.x0 + x, panel.y0 + y), lc) > 3) return;
                ++shown;
                kept += cp::max_diff(mine.at(panel.x0 + x, panel.y0 + y), fc) <= 3;
            });
            if (kept >= 10 && 5 * kept >= 4 * shown) {
                c.add("tie rule", "TODO 8: at " + std::to_string(kept) + " of " + std::to_string(shown) +
                                      " pixels where triangle " + std::to_string(j + 1) + " ties triangle " +
                                      std::to_string(i + 1) + "'s keys exactly (the same vertices) and its color is the "
                                      "brighter, yours kept triangle " + std::to_string(i + 1) + "'s: an exact tie "
                                      "never reached depth_passes. Skip a fragment only when its key is FARTHER "
                                      "(key > stored); a tie (key == stored) gets its color and goes to depth_passes, "
                                      "which gives it to the brighter color",
                      "an exact tie of keys must reach depth_passes (TODO 2's rule: the "
                      "brighter color wins); only a farther key may be rejected early");
                c.lead();
                return;
            }
        }
    }
}

// Ready-made triangles with a vertex whose 1 / w overflows (w = 1e-320): wherever that vertex
// weighs anything, sum(l_i / w_i) is infinite and the fragment falls back to the screen
// weights. Where the reference shows the screen-weighted color and yours clearly does not, the
// fallback is missing.
void judge_extreme_w(Ctx& c, const raster::Image& mine, const cp::Artifacts& ref, const Panel& panel) {
    const auto ref_it = ref.images.find("main");
    if (ref_it == ref.images.end()) return;
    for (const ScreenTri& t : panel.screen_tris) {
        if (std::isfinite(1 / t.w[0]) && std::isfinite(1 / t.w[1]) && std::isfinite(1 / t.w[2])) continue;
        long long shown = 0, off = 0;
        for_inner_pixels(t, panel, [&](int x, int y, const double* l) {
            const Color sc = rounded(t.color[0] * l[0] + t.color[1] * l[1] + t.color[2] * l[2]);
            if (cp::max_diff(ref_it->second.at(panel.x0 + x, panel.y0 + y), sc) > 3) return;
            ++shown;
            off += cp::max_diff(mine.at(panel.x0 + x, panel.y0 + y), sc) > 12;
        });
        if (off >= 10 && 2 * off > shown) {
            c.add("extreme w", "TODO 8: at " + std::to_string(off) + " of " + std::to_string(shown) +
                                   " pixels inside the triangle with a vertex of w = 1e-320 your colors are not the "
                                   "screen-weighted ones: 1 / w overflows there, so sum(l_i / w_i) is infinite, and "
                                   "fill_triangle must then fall back to the screen weights l (and w = sum(l_i * w_i)), "
                                   "as perspective_weights does, instead of dividing by the infinite sum (NaN)",
                  "in fill_triangle, where sum(l_i / w_i) is not > 0 or not finite, use the "
                  "screen weights l (the header's extreme-w rule)");
            c.lead();
            return;
        }
    }
}

// The fill rule on ready-made triangles whose vertices lie on pixel centers, drawn without a
// depth test (m4.shared_edges): worked out here in exact integers on the 1/16-pixel grid, each
// pixel shows the last triangle that covers its center by the top-left rule, or the
// background. Where the picture differs only at centers that lie exactly on an edge, the fill
// rule is the mistake.
void judge_fill_rule(Ctx& c, const raster::Image& mine, const Panel& panel, const std::string& where) {
    struct Tri {
        std::int64_t x[3], y[3];
        bool top_left[3];
        Color color;
    };
    auto edge = [](std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by, std::int64_t px, std::int64_t py) {
        return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
    };
    std::vector<Tri> tris;
    for (const ScreenTri& st : panel.screen_tris) {
        Tri t;
        for (int k = 0; k < 3; ++k) {
            t.x[k] = std::llround(st.screen[std::size_t(k)].x * 16);
            t.y[k] = std::llround(st.screen[std::size_t(k)].y * 16);
        }
        const std::int64_t area = edge(t.x[0], t.y[0], t.x[1], t.y[1], t.x[2], t.y[2]);
        if (area == 0) continue;
        if (area < 0) {
            std::swap(t.x[1], t.x[2]);
            std::swap(t.y[1], t.y[2]);
        }
        for (int k = 0; k < 3; ++k) {
            const int n = (k + 1) % 3;
            t.top_left[k] = (t.y[n] == t.y[k] && t.x[n] > t.x[k]) || t.y[n] < t.y[k];
        }
        const Vec3 v = st.color[0];
        t.color = {raster::to_channel(v.x), raster::to_channel(v.y), raster::to_channel(v.z)};
        tris.push_back(t);
    }
    long long on_edge = 0, on_wrong = 0, off_wrong = 0, excluded_shown = 0, dropped = 0;
    std::string example;
    for (int y = 0; y < panel.h; ++y) {
        for (int x = 0; x < panel.w; ++x) {
            const std::int64_t px = 16 * std::int64_t(x) + 8, py = 16 * std::int64_t(y) + 8;
            int owner = -1;
            std::vector<int> excluded;  // triangles whose closed area holds the center, which the rule leaves out
            bool touches = false;
            for (std::size_t i = 0; i < tris.size(); ++i) {
                const Tri& t = tris[i];
                bool inside = true, in = true, zero = false;
                for (int k = 0; k < 3 && inside; ++k) {
                    const int n = (k + 1) % 3;
                    const std::int64_t e = edge(t.x[k], t.y[k], t.x[n], t.y[n], px, py);
                    inside = e >= 0;
                    if (e == 0) {
                        zero = true;
                        in &= t.top_left[k];
                    }
                }
                if (!inside) continue;
                touches |= zero;
                if (in) owner = int(i);
                else excluded.push_back(int(i));
            }
            on_edge += touches;
            const Color want = owner >= 0 ? tris[std::size_t(owner)].color : panel.background;
            const Color got = mine.at(panel.x0 + x, panel.y0 + y);
            if (got == want) continue;
            if (!touches) {
                ++off_wrong;
                continue;
            }
            ++on_wrong;
            const bool shows_excluded = std::any_of(excluded.begin(), excluded.end(),
                                                    [&](int i) { return tris[std::size_t(i)].color == got; });
            excluded_shown += shows_excluded;
            dropped += got == panel.background;
            if (example.empty()) {
                example = "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") shows " + str(got) +
                          (shows_excluded ? ", the color of a triangle the rule leaves its center out of," : "") +
                          " where the top-left rule gives " +
                          (owner >= 0 ? "its center to the triangle of color " + str(want) : "its center to no triangle (background)");
            }
        }
    }
    c.j.measures["pixels whose center lies exactly on an edge"] = double(on_edge);
    c.j.measures["of those, shown wrong"] = double(on_wrong);
    if (on_wrong == 0 || on_wrong < off_wrong) return;
    std::string how;
    if (excluded_shown > 0) {
        how += std::to_string(excluded_shown) + " show a triangle the rule leaves out there (with no rule, e >= 0 on "
               "every edge, both triangles of a shared edge draw its centers and the later one wins)";
    }
    if (dropped > 0) {
        how += std::string(how.empty() ? "" : "; ") + std::to_string(dropped) +
               " show the background, drawn by neither triangle of their edge (e > 0 on every edge)";
    }
    c.add("fill rule", "TODO 8: " + std::to_string(on_wrong) + " of the " + std::to_string(on_edge) +
                           " pixels whose center lies exactly on an edge" + where + " show the wrong triangle" +
                           (how.empty() ? "" : ": " + how) + ". For example, " + example +
                           ". fill_triangle keeps milestone 2's top-left rule: once the area is positive, a center "
                           "whose edge value is 0 is in only when that edge is a top edge (b.y == a.y and b.x > a.x) "
                           "or a left edge (b.y < a.y), so of two triangles sharing an edge exactly one takes its "
                           "centers");
}

void judge_picture(Ctx& c, const cp::Artifacts& art, const cp::Artifacts& ref, const raster::Image& expected);

// A finding of fill_triangle's that names an idea (perspective weights, depth keys, the test
// order, the fill rule), not only a count or "the picture differs".
bool names_the_idea(const cp::Finding& f) {
    return f.topic == "perspective" || f.topic == "depth key" || f.topic == "indexing" || f.topic == "tie rule" ||
           f.topic == "extreme w" || f.message.find("was never written") != std::string::npos ||
           (f.topic == "fill rule" && f.message.find("lies exactly on an edge") != std::string::npos) ||
           f.message.find("failed the depth test") != std::string::npos;
}

// fill_triangle (TODO 8) on m4.fill_triangle's own triangles, then on m4.shared_edges', drawn
// by the render half of a scene that calls it through draw_mesh (render.cpp, kFillKey and
// kFillRuleKey), judged against the reference's run of the same triangles as those checkpoints
// judge them. The first that fails, with its most telling finding; or none.
std::optional<cp::Finding> fill_triangle_fails_on(const cp::Artifacts& art, const cp::Artifacts& ref, const std::string& id,
                                                  const std::string& fill_key);
std::optional<std::pair<cp::Finding, std::string>> fill_triangle_fails(const cp::Artifacts& art, const cp::Artifacts& ref) {
    for (const auto& [id, fill_key] : {std::pair{kFillScene, kFillKey}, std::pair{kFillRuleScene, kFillRuleKey}}) {
        if (auto f = fill_triangle_fails_on(art, ref, id, fill_key)) return std::pair{*f, id};
    }
    return std::nullopt;
}

std::optional<cp::Finding> fill_triangle_fails_on(const cp::Artifacts& art, const cp::Artifacts& ref, const std::string& id,
                                                  const std::string& fill_key) {
    const std::string image = fill_key.substr(0, fill_key.size() - 1);
    const auto mine_it = art.images.find(image), ref_it = ref.images.find(image);
    if (ref_it == ref.images.end() || mine_it == art.images.end()) return std::nullopt;
    cp::Artifacts mine_fill, ref_fill;
    mine_fill.images["main"] = mine_it->second;
    ref_fill.images["main"] = ref_it->second;
    mine_fill.values = cp::values_under(art.values, fill_key);
    ref_fill.values = cp::values_under(ref.values, fill_key);
    cp::Judgement scratch;
    Ctx sub{scene(id), mine_fill.values, ref_fill.values, scratch};
    judge_picture(sub, mine_fill, ref_fill, ref_it->second);
    if (scratch.findings.empty()) return std::nullopt;
    // The finding that names an idea (perspective weights, depth keys, the test order, the fill
    // rule) before a count, and a count before "the picture differs".
    auto rank = [](const cp::Finding& f) {
        if (names_the_idea(f)) return 0;
        return only_says_picture_differs(f) ? 2 : 1;
    };
    const cp::Finding* best = &scratch.findings.front();
    for (const cp::Finding& f : scratch.findings) {
        if (rank(f) < rank(*best)) best = &f;
    }
    return *best;
}

void judge_picture(Ctx& c, const cp::Artifacts& art, const cp::Artifacts& ref, const raster::Image& expected) {
    const Scene& s = c.s;
    const auto main_it = art.images.find("main");
    const raster::Image* mine = main_it == art.images.end() ? nullptr : &main_it->second;
    const bool sized = mine && mine->width() == s.width && mine->height() == s.height;
    const std::string topic = picture_topic(s.id);
    std::size_t keep = std::string::npos;

    if (sized && !expected.empty() && cp::exceeds_tolerance(*mine, expected, tolerance_for(expected))) {
        // judge() checked every function of TODOs 1-7 this picture is drawn with, and they
        // pass: the difference comes from their caller, fill_triangle (TODO 8) or draw_mesh
        // (TODO 9). The finding names that caller's concept, not the scene's theme.
        const cp::Tolerance tol = tolerance_for(expected);
        const Panel* worst = nullptr;
        long long worst_count = 0;
        for (const Panel& p : s.panels) {
            long long n = 0;
            for (int y = 0; y < p.h; ++y) {
                for (int x = 0; x < p.w; ++x) {
                    const Color a = mine->at(p.x0 + x, p.y0 + y), e = expected.at(p.x0 + x, p.y0 + y);
                    const int d = std::max({std::abs(a.r - e.r), std::abs(a.g - e.g), std::abs(a.b - e.b)});
                    n += d > tol.strict_channel_diff && !tol.lenient.get(p.x0 + x, p.y0 + y);
                }
            }
            if (n > worst_count || !worst) {
                worst = &p;
                worst_count = n;
            }
        }
        // Clipping is the question only when the clip counts of that panel differ (for the world
        // position's scene, any triangle count: culled or drawn triangles are the pipeline's).
        bool clipping_differs = false;
        if (worst) {
            const std::string pk = "panel" + std::to_string(worst - s.panels.data()) + ".stats.";
            for (const char* k : {"triangles_clipped", "triangles_drawn", "triangles_culled"}) {
                const bool counted = std::string(k) != "triangles_culled" || topic == "world position";
                clipping_differs |= counted && get(c.ref, pk + "triangles_clipped") > 0 && get(c.mine, pk + k) != get(c.ref, pk + k);
            }
        }
        const auto [caller_topic, advice] =
            caller_of(topic, worst ? worst->shading : Shade::kFaceColor, clipping_differs);
        const std::string where = s.panels.size() > 1 && worst ? " (most in panel " + std::to_string(worst - s.panels.data() + 1) + ")" : "";
        std::vector<std::string> passing;
        for (Group g : prerequisite_groups(s)) passing.push_back(prerequisite_checkpoint(g));
        const std::string list = cp::join_once(passing);
        const auto colon = advice.find(": ");  // "TODO 9: what its caller must do"
        const auto fill = s.id == kFillScene || s.id == kFillRuleScene ? std::nullopt : fill_triangle_fails(art, ref);
        if (fill) {
            // fill_triangle itself fails on its own checkpoint's triangles: that is the caller
            // to fix, whatever the scene is about.
            const cp::Finding f = cp::fix_first(fill->first, fill->second, "this picture is drawn with it",
                                                "this picture cannot come out right before that checkpoint passes");
            c.j.findings.push_back(f);
        } else c.add(caller_topic, advice.substr(0, colon) + ": the picture differs from the expected one beyond the tolerance" +
                                where + " (see diff.png), though the functions it is drawn with " + cp::kPassOwnChecks +
                                (list.empty() ? std::string() : " (" + list + ")") + ", so look at how they are called: " +
                                advice.substr(colon + 2) + ". This scene is about: " + s.hint);
        if (fill) keep = c.j.findings.size();  // the counts and keys below follow from fill_triangle's mistake
    }
    std::map<std::string, std::pair<double, double>> totals;  // per count: yours, the reference's (all panels)
    for (std::size_t p = 0; p < s.panels.size(); ++p) {
        const Panel& panel = s.panels[p];
        const std::string key = "panel" + std::to_string(p);
        const std::string where = s.panels.size() > 1 ? " (panel " + std::to_string(p + 1) + ")" : "";
        if (get(c.mine, key + ".resized") == 1) {
            c.add("depth clear", "TODO 2: clear_frame replaced frame.color by an image of another size" + where);
        }
        // Only what a scene needs: the depth buffer, read back by the render half.
        const double cap = get(c.mine, key + ".depth_capacity"), ref_cap = get(c.ref, key + ".depth_capacity");
        if (ref_cap == 0 && cap != 0) {
            c.add("needs", "TODO 2: this scene does not depth-test, yet the frame holds " + plural(cap, "depth key") +
                               " of memory" + where);
        } else if (ref_cap > 0 && cap < double(panel.w) * panel.h) {
            c.add("depth clear", "TODO 2: the depth buffer has room for " + plural(cap, "key") + ", the frame has " +
                                     std::to_string(panel.w * panel.h) + " pixels" + where);
        }
        // The counts.
        // Each count with its concept and the TODO that makes it: draw_mesh (9) counts
        // triangles and positions, fill_triangle (8) counts fragments; shade() is called by
        // draw_mesh per position or face (Gouraud, flat) and by fill_triangle per fragment.
        const bool per_pixel_shading = panel.shading == Shade::kPerPixel;
        // The count, its concept, what it counts (many, then one) and its TODO.
        const char* kStats[][5] = {
            {"triangles_clipped", "clipping", "triangles sent to clip_triangle", "triangle sent to clip_triangle", "TODO 9"},
            {"triangles_culled", "pipeline", "triangles culled", "triangle culled", "TODO 9"},
            {"triangles_drawn", "pipeline", "fan triangles drawn", "fan triangle drawn", "TODO 9"},
            {"fragments", "rasterizer", "fragments (covered pixel centers)", "fragment (covered pixel center)", "TODO 8"},
            {"depth_tests", "needs", "depth tests", "depth test", "TODO 8"},
            {"depth_writes", "depth test", "depth writes", "depth write", "TODO 8"},
            {"vertex_normals", "needs", "vertex normals computed", "vertex normal computed", "TODO 9"},
            {"shade_calls", "needs", "calls of shade()", "call of shade()", per_pixel_shading ? "TODO 8" : "TODO 9"},
            {"interpolated", "needs", "attribute values interpolated", "attribute value interpolated", "TODO 8"},
        };
        const bool clipped = get(c.ref, key + ".stats.triangles_clipped") > 0;
        // Keys read back from the depth buffer at known pixels, against the reference's. A
        // smaller key is nearer in every format, so a key that is FARTHER than the reference's
        // at every probe that differs was written by a fragment the depth test rejected.
        const bool float_format = panel.format == Format::kFloatZ || panel.format == Format::kReversedZ ||
                                  panel.format == Format::kInverseW;
        const double key_slack = float_format ? 4 : 2;
        int farther = 0, differ = 0, column_major = 0, off_surface = 0, cleared = 0;
        for (std::size_t k = 0; k < panel.depth_probes.size(); ++k) {
            const std::string pk = key + ".probe" + std::to_string(k);
            const double a = get(c.mine, pk), b = get(c.ref, pk);
            if (std::abs(a - b) <= key_slack) continue;
            ++differ;
            farther += a > b;
            cleared += a == 4294967295.0;  // kClearKey
            // The key this pixel should hold sits where a buffer indexed x * height + y keeps it.
            column_major += std::abs(get(c.mine, pk + ".column") - b) <= key_slack;
            if (panel.format == Format::kInverseW) {
                const auto [x, y] = panel.depth_probes[k];
                const double w = inverse_w_of(a), ref_w = inverse_w_of(b);
                bool mine_on = false, ref_on = false;
                for (double sw : surface_ws(panel, x, y)) {
                    mine_on |= std::abs(w - sw) <= 0.01 * sw;
                    ref_on |= std::abs(ref_w - sw) <= 0.01 * sw;
                }
                off_surface += ref_on && !mine_on;
            }
        }
        // Every probe that differs holds the key of another pixel: the indexing, not the test.
        const bool indexing = differ > 0 && column_major == differ;
        // Every probe that differs holds a 1/w key of no surface at its pixel: the pixel's w.
        const bool pixel_w = differ > 0 && off_surface == differ && !indexing;
        // Every probe that differs still holds kClearKey, though the reference drew there: no key
        // was ever written (the test passed, the color was written, the key was not).
        const bool never_written = differ > 0 && cleared == differ && !indexing && !pixel_w;
        const bool overwritten = differ > 0 && farther == differ && !indexing && !pixel_w && !never_written;
        // A wrong number of fan triangles drawn changes every pixel count after it: those
        // findings would only repeat it, under the rasterizer's TODO.
        bool triangles_off = false, fragments_off = false;
        // Fewer triangles culled and as many more drawn, with back faces culled: triangles the
        // reference finds back-facing were drawn. A mesh triangle that repeats a position has
        // zero area on the screen, which is a back face by the pinned sign (area >= 0).
        const double mine_culled = get(c.mine, key + ".stats.triangles_culled"), ref_culled = get(c.ref, key + ".stats.triangles_culled");
        // Without culling, any triangle counted as culled was drawn by the reference.
        const bool culled_drawn = (panel.cull ? mine_culled < ref_culled : ref_culled == 0 && mine_culled > 0) &&
                                  mine_culled + get(c.mine, key + ".stats.triangles_drawn") ==
                                      ref_culled + get(c.ref, key + ".stats.triangles_drawn");
        long long zero_area = 0;
        for (const Item& it : panel.items) {
            for (const auto& t : it.mesh.triangles) {
                const auto& q = it.mesh.positions;
                const int n = static_cast<int>(q.size());
                if (t[0] < 0 || t[0] >= n || t[1] < 0 || t[1] >= n || t[2] < 0 || t[2] >= n) continue;
                const Vec3 a = q[std::size_t(t[0])], b = q[std::size_t(t[1])], d = q[std::size_t(t[2])];
                zero_area += a == b || b == d || d == a;
            }
        }
        // kPerPixel interpolates 3 values per fragment lit, 6 with a point light (the world
        // position): 3 more per call of shade() than the reference with no point light is that.
        const double mine_shade = get(c.mine, key + ".stats.shade_calls"), ref_shade = get(c.ref, key + ".stats.shade_calls");
        const bool point_lit = std::any_of(panel.lights.begin(), panel.lights.end(), [](const LightSpec& l) { return l.point; });
        const bool world_needless = per_pixel_shading && !point_lit && mine_shade > 0 && ref_shade > 0 &&
                                    std::abs(get(c.mine, key + ".stats.interpolated") / mine_shade -
                                             get(c.ref, key + ".stats.interpolated") / ref_shade - 3) < 0.25;
        // The converse: a point light, and 3 values per lit fragment where the reference
        // interpolates 6: the world position was left out, so the point light is lit from the
        // wrong place (FillState::point_light never set, draw_mesh's TODO 9).
        const bool world_missing = per_pixel_shading && point_lit && mine_shade > 0 && ref_shade > 0 &&
                                   std::abs(get(c.ref, key + ".stats.interpolated") / ref_shade -
                                            get(c.mine, key + ".stats.interpolated") / mine_shade - 3) < 0.25;
        // Per-pixel shading that lit only the fragments it wrote, where the reference lights the
        // ties too (more shade() calls than writes): ties were rejected before depth_passes.
        const double mine_writes = get(c.mine, key + ".stats.depth_writes"), ref_writes = get(c.ref, key + ".stats.depth_writes");
        const bool ties_skipped = per_pixel_shading && panel.depth_test && mine_shade < ref_shade &&
                                  std::abs(mine_shade - mine_writes) <= 0.005 * mine_writes + 2 &&
                                  ref_shade > ref_writes + 0.02 * ref_writes + 4;
        // A depth-write count off with nothing else to say of it, which screen-weighted colors
        // explain (an exact tie goes to the brighter color, so other colors win other ties).
        std::size_t plain_writes = std::string::npos;
        for (const auto& st : kStats) {
            const std::string k = key + ".stats." + st[0];
            const double a = get(c.mine, k), b = get(c.ref, k);
            totals[st[0]].first += a;
            totals[st[0]].second += b;
            const std::string name = st[0];
            const bool per_triangle = name.rfind("triangles", 0) == 0 || name == "vertex_normals";
            bool ok;
            if (b == 0 || a == 0) {
                ok = a == b;
            } else if (per_triangle) {
                // After clipping, a fan may hold zero-area triangles whose culling rounding decides.
                ok = a == b || (clipped && name != "triangles_clipped" && std::abs(a - b) <= 0.02 * b + 2);
            } else {
                ok = std::abs(a - b) <= 0.02 * b + 4;  // pixel counts: rounding at edges
            }
            if (ok) continue;
            const bool per_pixel_count = name == "fragments" || name == "depth_tests" || name == "depth_writes" ||
                                         name == "interpolated" || (name == "shade_calls" && per_pixel_shading);
            if (per_pixel_count && (triangles_off || fragments_off)) continue;
            if (name == "triangles_culled" || name == "triangles_drawn") triangles_off = true;
            // Where every vertex lies on a pixel center, a fragment count off is the fill rule
            // (centers on shared edges taken twice or by neither); the counts per fragment
            // after it only repeat it.
            const bool fill_rule_count = name == "fragments" && s.checks.fill_rule && !panel.screen_tris.empty();
            fragments_off |= fill_rule_count;
            // Mesh triangles (indices in range) with a NaN or infinite position: draw_mesh drops
            // them before clipping.
            long long non_finite = 0;
            for (const Item& it : panel.items) {
                const auto& q = it.mesh.positions;
                const int n = static_cast<int>(q.size());
                for (const auto& t : it.mesh.triangles) {
                    if (t[0] < 0 || t[0] >= n || t[1] < 0 || t[1] >= n || t[2] < 0 || t[2] >= n) continue;
                    bool bad = false;
                    for (int i : t) {
                        const Vec3 pt = q[std::size_t(i)];
                        bad |= !std::isfinite(pt.x) || !std::isfinite(pt.y) || !std::isfinite(pt.z);
                    }
                    non_finite += bad;
                }
            }
            // Mesh triangles with an index out of range: draw_mesh skips them (reading them is
            // undefined behaviour: whatever lies beside the positions is drawn, or the program crashes).
            long long out_of_range = 0;
            std::string indices;
            for (const Item& it : panel.items) {
                const int n = static_cast<int>(it.mesh.positions.size());
                for (const auto& t : it.mesh.triangles) {
                    bool bad = false;
                    for (int i : t) {
                        if (i >= 0 && i < n) continue;
                        bad = true;
                        indices += (indices.empty() ? "" : ", ") + std::to_string(i);
                    }
                    out_of_range += bad;
                }
            }
            // (Each triangle read through a bad index adds at most one to a count: one sent to the
            // clipper, or one drawn or culled as it is; more is another mistake.)
            if ((name == "triangles_clipped" || name == "triangles_drawn" || name == "triangles_culled") && a > b &&
                out_of_range > 0 && a - b <= double(out_of_range)) {
                c.add("bad input", "TODO 9: " + num(a) + " " + st[2] + where + ", expected " + num(b) + ": this mesh has " +
                                       plural(double(out_of_range), "triangle") + " with an index out of range (" +
                                       indices + ", of " + plural(double(panel.items.empty() ? 0 : panel.items.front().mesh.positions.size()), "position") +
                                       "), which draw_mesh skips before anything else: check 0 <= index < positions.size() "
                                       "for all three (reading positions[40] is undefined behaviour, not an error C++ reports)");
                triangles_off = true;  // the fragment counts after it only follow from it
                continue;
            }
            if (name == "triangles_clipped" && a > b && non_finite > 0 && a - b == double(non_finite)) {
                c.add("bad input", "TODO 9: " + num(a) + " triangles sent to clip_triangle" + where + ", expected " + num(b) +
                                       ": the " + plural(double(non_finite), "triangle") + " with a NaN or infinite "
                                       "coordinate went there too. draw_mesh drops a triangle with any non-finite clip "
                                       "coordinate (x, y, z or w) before clipping, culling or counting it: a NaN fails "
                                       "every plane test, so the clipper alone cannot be trusted with it");
                continue;
            }
            if (name == "triangles_drawn" && a > b && non_finite > 0 && clipped &&
                get(c.mine, key + ".stats.triangles_clipped") == get(c.ref, key + ".stats.triangles_clipped")) {
                c.add("clipping",
                      "TODO 7b: " + num(a) + " fan triangles drawn" + where + ", expected " + num(b) +
                          ", with as many triangles clipped: the polygons of the huge triangles kept "
                          "vertices with w <= 0. Rounding between two huge vertices can cancel every digit "
                          "and leave (0, 0, 0, 0), which lies on all six planes; clip_triangle drops every "
                          "vertex whose w is not > 0 once the six planes are done, and returns nothing when "
                          "fewer than three remain",
                      "after the six planes, clip_triangle drops every vertex whose w is not > 0 "
                      "(it has no place on the screen)");
                continue;
            }
            std::string why;
            if (b == 0 && name == "triangles_culled" && panel.cull) {
                why = ": back faces are culled here, but every triangle faces the eye once clipped: clip first, then "
                      "cull each fan triangle by its own screen positions (a vertex behind the eye flips the winding "
                      "of the unclipped triangle's projection), and fan the polygon as (0, i, i + 1), which keeps its "
                      "orientation";
            } else if (b == 0 && name == "vertex_normals" &&
                       std::any_of(panel.items.begin(), panel.items.end(), [](const Item& it) {
                           return !it.mesh.positions.empty() && it.mesh.normals.size() == it.mesh.positions.size();
                       })) {
                why = ": the mesh brings its own normals (mesh.normals, one per position): use them; "
                      "vertex_normals() runs only for a mesh whose normals are empty or of another size than its "
                      "positions";
            } else if (b == 0) {
                why = ": this scene does not need that stage (Needs), so it must not run";
            } else if (name == "triangles_clipped") {
                why = a < b ? ": every mesh triangle not entirely inside the view volume (some vertex with d < 0 for "
                              "some plane) goes to clip_triangle and is counted, even one entirely outside a plane "
                              "that clip_triangle then returns empty: triangles_clipped counts the triangles sent, "
                              "not those that survive, so do not reject any before clip_triangle"
                            : ": only a mesh triangle with a vertex outside some plane (d < 0) goes to clip_triangle; "
                              "one with all three vertices inside is fanned as it is, uncounted";
            } else if (name == "interpolated" && world_missing) {
                c.add("per-pixel normals", "TODO 9: " + num(a) + " attribute values interpolated" + where + ", expected about " +
                                               num(b) + ": 3 per fragment lit, the normal alone, where the reference "
                                               "interpolates 6. This panel has a point light, whose L depends on where "
                                               "the fragment is: draw_mesh sets FillState::point_light when any light "
                                               "is a point light, so that fill_triangle interpolates the world position "
                                               "too and shade() gets it",
                      "with a point light, draw_mesh (TODO 9) sets FillState::point_light so "
                      "that fill_triangle interpolates the world position for shade()");
                // It says why the picture differs: before the picture's finding, which names no cause.
                if (keep == std::string::npos && only_says_picture_differs(c.j.findings.front())) {
                    c.lead();
                }
                continue;
            } else if ((name == "shade_calls" || name == "interpolated") && ties_skipped) {
                if (name == "interpolated") continue;  // the shade() count's finding says it
                c.add("tie rule",
                      "TODO 8: " + num(a) + " calls of shade()" + where + ", expected about " + num(b) +
                          ": yours lit exactly the fragments whose key was written (" + num(mine_writes) +
                          "), while the reference also lights the " + num(b - ref_writes) +
                          " fragments whose key TIES the stored one: an exact tie goes to depth_passes, "
                          "which gives it to the brighter color, so its color is needed. Skip a fragment "
                          "only when its key is FARTHER (key > stored)",
                      "a tie (key == stored) is not rejected before depth_passes: light it and "
                      "let depth_passes decide");
                continue;
            } else if (name == "interpolated" && world_needless) {
                why = ": that is " + num(std::round(a / mine_shade * 100) / 100) + " values per fragment lit (per call of "
                      "shade()), where the reference interpolates " + num(std::round(b / ref_shade * 100) / 100) +
                      ": the world position (3 values) was interpolated too, though no light of this panel is a point "
                      "light. Only a point light needs it (FillState::point_light); with directional lights alone a "
                      "kPerPixel fragment interpolates its normal only";
            } else if ((name == "interpolated" || (name == "shade_calls" && per_pixel_shading)) && a > b &&
                       panel.depth_test) {
                why = ": are hidden fragments interpolated too? Test the depth first; only a fragment that "
                      "passes (or ties) needs its attributes";
            } else if (name == "shade_calls" && panel.shading == Shade::kGouraud) {
                why = a < b ? ": Gouraud lights every position of the mesh once, in step 1 of draw_mesh, before any "
                              "triangle is clipped or culled, including positions no drawn triangle uses (lighting "
                              "only the positions a drawn triangle needs gives the same picture, but this count is "
                              "the rule's)"
                            : ": Gouraud lights each position once in step 1, not once per triangle corner or per "
                              "fragment; the triangles then interpolate the lit levels";
            } else if (name == "shade_calls" && panel.shading == Shade::kFlat) {
                why = a > b ? ": a flat face is lit once, when the first of its fan triangles is drawn: after "
                              "clipping and culling, so a culled or clipped-away face is never lit, and the other fan "
                              "triangles of a clipped face reuse its color"
                            : ": every face with a drawn fan triangle is lit once, when the first of them is drawn";
            } else if (name == "depth_writes" && never_written) {
                why = ": the depth probes below still hold kClearKey, so no key was ever stored and every later "
                      "fragment passes against the cleared value; when a fragment passes, write its key into "
                      "frame.depth as well as its color";
            } else if (name == "depth_writes" && a > b && overwritten) {
                why = ": the depth probes below hold keys farther than the reference's, so a fragment that failed "
                      "the depth test wrote its key; test first, and write color and key only when it passes";
            }
            if (culled_drawn && name == "triangles_drawn") continue;  // the culled count's finding says it
            if (culled_drawn && name == "triangles_culled" && !panel.cull) {
                why = ": this scene does not cull (needs.cull is false), so every fan triangle goes to fill_triangle "
                      "and counts as drawn" +
                      (zero_area >= a ? std::string(", one of zero area too (this mesh has ") +
                                            plural(double(zero_area), "triangle") +
                                            " repeating a position): fill_triangle draws nothing for it"
                                      : std::string());
            } else if (culled_drawn && name == "triangles_culled") {
                const double missed = b - a;
                why = ": " + plural(missed, "fan triangle") + (missed == 1 ? " was" : " were") +
                      " drawn that the reference culls" +
                      (zero_area >= missed
                           ? std::string(". This mesh has ") + plural(double(zero_area), "triangle") +
                                 " of zero area (a position repeated): such a triangle is a back face too, since "
                                 "m3::is_back_facing's signed screen area >= 0 includes 0, so with needs.cull it is "
                                 "culled and counted in triangles_culled, not drawn"
                           : ": a back face has a signed screen area >= 0 (m3::is_back_facing), 0 included");
            }
            if (fill_rule_count) {
                why = std::string(": the triangles tile their area and every vertex lies on a pixel center, so "
                                  "each center on a shared edge must be counted once, by the one triangle the "
                                  "top-left rule gives it to (") +
                      (a > b ? "more: centers on shared edges were counted twice)" : "fewer: centers on shared edges were counted by neither)");
            }
            const bool needless = b == 0 && !(name == "triangles_culled" && (panel.cull || culled_drawn));
            const char* counted = a == 1 ? st[3] : st[2];
            const std::size_t count_at = c.j.findings.size();
            c.add(needless ? "needs" : fill_rule_count ? "fill rule" : culled_drawn && name == "triangles_culled" ? "culling" : st[1], std::string(st[4]) + ": " + num(a) + " " + counted + where + ", expected " +
                                                (per_triangle ? num(b) : "about " + num(b)) + why);
            if (name == "depth_writes" && why.empty() && c.j.findings.size() > count_at) plain_writes = count_at;
        }
        // Colors lit from the wrong place decide exact ties otherwise (the brighter wins), so a
        // depth-write count off beside the point-light finding only repeats it.
        // (Found by its words: the point-light finding may have moved ahead of it.)
        if (world_missing && plain_writes != std::string::npos) {
            const std::string writes = num(get(c.mine, key + ".stats.depth_writes")) + " depth writes" + where + ",";
            std::erase_if(c.j.findings, [&](const cp::Finding& f) { return f.message.rfind(writes, 0) == 0; });
            plain_writes = std::string::npos;
        }
        for (std::size_t k = 0; k < panel.depth_probes.size(); ++k) {
            const std::string pk = key + ".probe" + std::to_string(k);
            const double a = get(c.mine, pk), b = get(c.ref, pk);
            if (std::abs(a - b) <= key_slack) continue;
            const auto [x, y] = panel.depth_probes[k];
            if (indexing) {
                c.add("indexing", "TODO 8: the depth buffer at pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")" +
                                      where + " holds key " + num(a) + ", expected " + num(b) + ", and the key expected there "
                                      "sits at index x * height + y = " + std::to_string(x * panel.h + y) +
                                      " instead, as at every probe that differs: the buffer is indexed column by column, "
                                      "so each fragment tests and writes another pixel's key. frame.depth is row-major "
                                      "like the image: the key of pixel (x, y) is depth[y * width + x]");
                break;  // one finding says it; every probe that differs is the same mistake
            }
            if (pixel_w) {
                c.add("depth key", "TODO 8: the 1/w key at pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")" +
                                       where + " is " + num(a) + " (w = " + num(inverse_w_of(a)) + "), expected " + num(b) +
                                       " (w = " + num(inverse_w_of(b)) + ", where the ray through the pixel meets the "
                                       "surface): no surface at this pixel is at your w. The pixel's w is 1 / sum(l_i / w_i): "
                                       "1/w is affine on the screen, w is not, so sum(l_i * w_i) is too far inside a "
                                       "triangle; that sum is only the fallback where sum(l_i / w_i) is not > 0 and finite");
                continue;
            }
            if (never_written) {
                c.add("depth test", "TODO 8: the depth buffer at pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                        ")" + where + " still holds kClearKey (" + num(a) + "), expected " + num(b) +
                                        ", as at every probe that differs, though a fragment was drawn there: the key "
                                        "was never written. When a fragment passes the depth test, fill_triangle "
                                        "stores its key in frame.depth (depth[y * width + x] = key) along with its "
                                        "color, or every later fragment passes too");
                break;  // one finding says it
            }
            double d = std::nan("");
            if (panel.format == Format::kFloatZ && b >= 0 && b < 4294967296.0) d = std::bit_cast<float>(static_cast<std::uint32_t>(b));
            // A key written by a rejected fragment is the depth test's order (test, then write).
            c.add(overwritten ? "depth test" : "depth key", "TODO 8: the depth buffer at pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                   ")" + where + " holds key " + num(a) + ", expected " + num(b) +
                                   (std::isnan(d) ? "" : " (d = " + num(d) + ")") +
                                   (overwritten ? ", a FARTHER key, as at every probe that differs: a hidden "
                                                  "fragment wrote its key though it failed the depth test"
                                                : std::string(a < b ? ", a nearer key" : ", a farther key") +
                                                      " (the rule: z_ndc is interpolated with the screen weights "
                                                      "l_i, then keyed by depth_key)"));
            if (!overwritten && !c.j.findings.empty() && c.j.findings.back().topic == "depth key") {
                c.j.findings.back().hint = "fill_triangle interpolates z_ndc with the screen weights l_i (depth is "
                                           "affine on the screen, unlike the attributes), then keys it with depth_key";
            }
        }
        if (!sized) continue;
        if (!panel.screen_tris.empty()) {
            const std::size_t before = c.j.findings.size();
            judge_screen_weights(c, *mine, ref, panel);
            if (c.j.findings.size() > before && plain_writes < before) {
                c.j.findings.erase(c.j.findings.begin() + std::ptrdiff_t(plain_writes));
            }
        }
        if (s.checks.fill_rule && !panel.screen_tris.empty()) judge_fill_rule(c, *mine, panel, where);
        if (s.checks.normal_lengths) judge_normal_lengths(c, *mine, panel, where);
        if (s.id == "m4.normal_view" && keep == std::string::npos) {
            const std::size_t before = c.j.findings.size();
            judge_normal_space(c, *mine, panel, where);
            // Normals in the wrong space explain the picture: the finding that names no cause goes.
            if (c.j.findings.size() > before) {
                std::erase_if(c.j.findings, only_says_picture_differs);
            }
        }
        if (!panel.screen_tris.empty()) judge_extreme_w(c, *mine, ref, panel);
        if (!panel.screen_tris.empty()) judge_ties(c, *mine, ref, panel);
        if (s.checks.checker_error) {
            const raster::Image truth = analytic_checker(panel);
            long long inside = 0, wrong = 0, ref_wrong = 0;
            const auto ref_it = ref.images.find("main");
            for (int y = 0; y < panel.h; ++y) {
                for (int x = 0; x < panel.w; ++x) {
                    const Color t = truth.at(x, y);
                    if (t == panel.background) continue;
                    ++inside;
                    wrong += !(mine->at(panel.x0 + x, panel.y0 + y) == t);
                    if (ref_it != ref.images.end()) ref_wrong += !(ref_it->second.at(panel.x0 + x, panel.y0 + y) == t);
                }
            }
            const double err = inside ? 100.0 * wrong / inside : 0, ref_err = inside ? 100.0 * ref_wrong / inside : 0;
            c.j.measures["pixels off the analytic checkerboard, % (reference " + num(std::round(ref_err * 10) / 10) + ")"] =
                std::round(err * 10) / 10;
            if (panel.perspective_correct && err > ref_err + 2) {
                c.add("perspective", "TODOs 3 and 8: " + num(std::round(err * 10) / 10) +
                                         "% of the floor's pixels are off the exact checkerboard (reference " +
                                         num(std::round(ref_err * 10) / 10) +
                                         "%): interpolate u/w, v/w and 1/w on the screen, not u and v (the weights "
                                         "of perspective_weights, TODO 3, used for every fragment by fill_triangle, "
                                         "TODO 8; m4.weights checks TODO 3 alone)");
            }
        }
        if (s.checks.sphere_error) {
            const double err = panel_error(*mine, panel, analytic_sphere(panel));
            const auto ref_it = ref.images.find("main");
            const double ref_err = ref_it == ref.images.end() ? 0 : panel_error(ref_it->second, panel, analytic_sphere(panel));
            c.j.measures["mean error vs the perfect sphere, levels (reference " + num(std::round(ref_err * 100) / 100) + ")"] =
                std::round(err * 100) / 100;
            // Lit from the wrong side? The perfect sphere with every directional light reversed.
            Panel reversed = panel;
            for (LightSpec& l : reversed.lights) {
                if (!l.point) l.vector = -l.vector;
            }
            if (err > ref_err + 2 && panel_error(*mine, panel, analytic_sphere(reversed)) < err / 2) {
                c.add("light direction", "TODO 5: your sphere" + where +
                                             " is lit from the opposite side: L must point from the surface TOWARD the "
                                             "light, -direction for a directional light");
            }
        }
        if (s.checks.zfight) {
            long long far_shows = 0;
            for (int y = 0; y < panel.h; ++y) {
                for (int x = 0; x < panel.w; ++x) far_shows += mine->at(panel.x0 + x, panel.y0 + y) == Color{250, 220, 80};
            }
            c.j.measures[std::string("z-fighting pixels, ") + kFormatNames[int(panel.format)]] = double(far_shows);
            c.j.measures[std::string("render time of the ") + kFormatNames[int(panel.format)] + " panel, ms"] = 1e3 * get(c.mine, key + ".seconds");
        }
    }
    cp::report_totals(c.j, totals);  // every count that is not zero, summed over the panels
    if (s.checks.shading_chart && sized) judge_shading_chart(c, *mine, ref);
    for (const auto& [p, q] : s.checks.same_panels) {
        if (!sized || keep != std::string::npos) break;
        const Panel &a = s.panels[std::size_t(p)], &b = s.panels[std::size_t(q)];
        long long diff = 0;
        for (int y = 0; y < a.h; ++y) {
            for (int x = 0; x < a.w; ++x) diff += !(mine->at(a.x0 + x, a.y0 + y) == mine->at(b.x0 + x, b.y0 + y));
        }
        if (diff > 0) {
            c.add(topic == std::string("tie rule") ? "tie rule" : "depth test",
                  "TODOs 2 and 8: the same triangles drawn in another order give another picture (" +
                      plural(double(diff), "pixel") + (diff == 1 ? " differs" : " differ") + " between panel " +
                      std::to_string(p + 1) + " and panel " +
                      std::to_string(q + 1) +
                      "): the depth test must decide every pixel (depth_passes, TODO 2), a fragment that fails must "
                      "write nothing, not even its depth, and an exact tie must go through depth_passes too "
                      "(fill_triangle, TODO 8)");
        }
    }
    if (keep < c.j.findings.size()) c.j.findings.resize(keep);
    // fill_triangle's own checkpoints: a finding that names the idea (screen weights, a depth
    // key, the test order, the fill rule) comes before "the picture differs", so that it leads
    // the report, its concept and its hint.
    if (s.id == kFillScene || s.id == kFillRuleScene) {
        std::stable_partition(c.j.findings.begin(), c.j.findings.end(), names_the_idea);
    }
}

}  // namespace

cp::Judgement judge(const std::string& id, const cp::Artifacts& artifacts, const cp::Artifacts& reference,
                    const raster::Image& expected) {
    const Scene& s = scene(id);
    cp::Judgement j;
    if (!expected.empty()) j.tolerance = tolerance_for(expected);
    Ctx c{s, artifacts.values, reference.values, j};
    if (artifacts.stray_writes > 0) {
        c.add("rasterizer", "TODO 8: " + plural(double(artifacts.stray_writes), "write") +
                                " outside the image: clamp the bounding box to the image");
    }
    // A function the reference draws with that drew nothing (most often draw_mesh, TODO 9, not
    // written yet): the harness names it, and every finding about the picture (counts that
    // blame fill_triangle, keys read back, the scene's theme) would follow from it.
    // A failing checkpoint first checks the functions of TODOs 1-7 its panels use, on their own
    // checkpoints' inputs. One that is wrong is the finding ("fix TODO 4 first, see
    // m4.normals"), and the picture's findings, which would blame fill_triangle, draw_mesh or
    // the scene's theme for what it did, are left out (and so is the harness's "drew nothing").
    // A checkpoint that passes stays passed, whatever its prerequisites do.
    auto numbers = [&] {
        for (Group g : s.groups) judge_group(g, c);
        judge_probes(c);
    };
    auto prerequisites = [&] {
        std::vector<cp::Finding> first;
        for (Group g : prerequisite_groups(s)) {
            const auto f = cp::prerequisite_finding(artifacts, reference, prerequisite_key(g), prerequisite_checkpoint(g),
                                                    [&](const Values& mine, const Values& ref, cp::Judgement& scratch) {
                                                        Ctx sub{s, mine, ref, scratch};
                                                        judge_group(g, sub);
                                                    },
                                                    !s.panels.empty());
            if (f) first.push_back(*f);
        }
        return first;
    };
    cp::judge_pipeline(j, artifacts, reference, expected, !s.panels.empty(), numbers,
                       [&] { judge_picture(c, artifacts, reference, expected); }, prerequisites);
    return j;
}

}  // namespace m4cp
