// Small helpers the milestone judges share (see judging.h).
#include "harness/judging.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace cp {

std::string num(double v) {
    if (std::abs(v) < 1e-12) v = 0;
    std::ostringstream s;
    s.precision(10);
    s << v;
    return s.str();
}

std::string plural(double n, const std::string& one, const std::string& many) {
    return num(n) + " " + (n == 1 ? one : many.empty() ? one + "s" : many);
}

double get(const Values& v, const std::string& key) {
    const auto it = v.find(key);
    return it == v.end() ? std::nan("") : it->second;
}

bool close(double a, double b, double tol) {
    if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
    return std::abs(a - b) <= tol * std::max(1.0, std::abs(b));
}

raster::Vec3 vec3(const Values& v, const std::string& key) {
    return {get(v, key + ".x"), get(v, key + ".y"), get(v, key + ".z")};
}
std::string str(raster::Vec3 p) { return "(" + num(p.x) + ", " + num(p.y) + ", " + num(p.z) + ")"; }
bool same3(raster::Vec3 a, raster::Vec3 b, double tol) {
    return close(a.x, b.x, tol) && close(a.y, b.y, tol) && close(a.z, b.z, tol);
}

std::string str(raster::Color c) {
    return "(" + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " + std::to_string(c.b) + ")";
}

int max_diff(raster::Color a, raster::Color b) {
    return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

bool PixelVote::cast(raster::Color got, raster::Color right, raster::Color wrong) {
    if (max_diff(right, wrong) <= apart_) return false;
    ++telling_;
    mistake_like_ += max_diff(got, wrong) <= 3;
    rule_like_ += max_diff(got, right) <= 3;
    return true;
}

std::string PixelVote::tally() const {
    return "at " + std::to_string(mistake_like_) + " of " + std::to_string(telling_) + " pixels";
}

void add_finding(Judgement& j, const std::string& topic, const std::string& msg, const std::string& hint) {
    std::string todo, text = msg;
    const auto colon = msg.find(": ");
    if (msg.rfind("TODO", 0) == 0 && colon != std::string::npos && colon < 20) {
        todo = msg.substr(0, colon);
        text = msg.substr(colon + 2);
    }
    for (const Finding& f : j.findings) {
        if (f.topic == topic && f.message == text) return;
    }
    j.findings.push_back({topic, text, hint, todo});
}

Tolerance edge_tolerance(const raster::Image& expected, const std::string& why) {
    Tolerance t;
    t.strict_channel_diff = 3;
    t.lenient = raster::Mask(expected.width(), expected.height());
    auto far_apart = [](raster::Color a, raster::Color b) {
        return std::abs(a.r - b.r) > 16 || std::abs(a.g - b.g) > 16 || std::abs(a.b - b.b) > 16;
    };
    for (int y = 0; y < expected.height(); ++y) {
        for (int x = 0; x < expected.width(); ++x) {
            const raster::Color c = expected.at(x, y);
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    if (expected.in_bounds(x + dx, y + dy) && far_apart(expected.at(x + dx, y + dy), c)) t.lenient.set(x, y);
                }
            }
        }
    }
    t.max_lenient_diffs = t.lenient.count() / 5;
    t.why = why;
    return t;
}

double rect_error(const raster::Image& img, int x0, int y0, int w, int h, const raster::Image& truth) {
    double sum = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const raster::Color a = img.at(x0 + x, y0 + y), e = truth.at(x, y);
            sum += std::abs(a.r - e.r) + std::abs(a.g - e.g) + std::abs(a.b - e.b);
        }
    }
    return sum / (3.0 * w * h);
}

bool drew_nothing(const Artifacts& art, const Artifacts& reference) {
    bool nothing = false;
    for (const auto& [name, t] : reference.trace) {
        const auto it = art.trace.find(name);
        nothing |= t.writes > 0 && it != art.trace.end() && it->second.calls > 0 && it->second.writes == 0;
    }
    return nothing;
}

void judge_pipeline(Judgement& j, const Artifacts& art, const Artifacts& reference, const raster::Image& expected,
                    bool has_panels, const std::function<void()>& numbers, const std::function<void()>& picture,
                    const std::function<std::vector<Finding>()>& prerequisites) {
    const std::size_t before = j.findings.size();
    numbers();
    const bool own_failed = j.findings.size() > before;
    const bool nothing = drew_nothing(art, reference);
    if (has_panels && !own_failed && !nothing) picture();
    bool fails = j.findings.size() > before || (has_panels && nothing);
    if (!fails && has_panels && !expected.empty()) {
        const auto it = art.images.find("main");
        fails = it == art.images.end() || exceeds_tolerance(it->second, expected, j.tolerance);
    }
    const std::vector<Finding> first = fails ? prerequisites() : std::vector<Finding>{};
    if (!first.empty()) {
        j.findings.resize(before);
        j.findings.insert(j.findings.end(), first.begin(), first.end());
    }
    j.upstream_failed = !first.empty() || (has_panels && own_failed);
}

std::optional<Finding> prerequisite_finding(
    const Artifacts& art, const Artifacts& reference, const std::string& prefix, const std::string& checkpoint,
    const std::function<void(const Values& mine, const Values& ref, Judgement& scratch)>& judge, bool has_picture) {
    const Values mine = values_under(art.values, prefix), ref = values_under(reference.values, prefix);
    Judgement scratch;
    judge(mine, ref, scratch);
    if (scratch.findings.empty()) return std::nullopt;
    if (!has_picture) {
        return fix_first(scratch.findings.front(), checkpoint, "these numbers are computed with it",
                         "these numbers cannot come out right before that checkpoint passes");
    }
    return fix_first(scratch.findings.front(), checkpoint, "this picture is drawn with it",
                     "this picture cannot come out right before that checkpoint passes");
}

std::string join_once(const std::vector<std::string>& ids) {
    std::vector<std::string> once;
    for (const std::string& id : ids) {
        if (std::find(once.begin(), once.end(), id) == once.end()) once.push_back(id);
    }
    std::string list;
    for (std::size_t i = 0; i < once.size(); ++i) list += (i ? ", " : "") + once[i];
    return list;
}

void report_totals(Judgement& j, const std::map<std::string, std::pair<double, double>>& totals) {
    for (const auto& [name, t] : totals) {
        if (t.first != 0 || t.second != 0) j.measures[name + " (reference " + num(t.second) + ")"] = t.first;
    }
}

}  // namespace cp
