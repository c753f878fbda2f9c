#include "script.h"

#include <sstream>

namespace viewer {

namespace {

// "shift+left" -> shift, "left"
std::string strip_shift(const std::string& word, bool& shift) {
    const std::string prefix = "shift+";
    shift = word.size() > prefix.size() && word.compare(0, prefix.size(), prefix) == 0;
    return shift ? word.substr(prefix.size()) : word;
}

bool parse_step(const std::string& text, Step& step, std::string& error) {
    std::istringstream in(text);
    std::string verb;
    in >> verb;
    const auto fail = [&](const std::string& why) {
        error = "script step \"" + text + "\": " + why;
        return false;
    };
    const auto at_end = [&] {
        std::string extra;
        return !(in >> extra);
    };
    if (verb == "key") {
        std::string name;
        if (!(in >> name)) return fail("expected: key NAME [COUNT]");
        step.kind = Step::Kind::kKey;
        step.name = strip_shift(name, step.shift);
        if (!(in >> step.count)) {  // no COUNT: once
            step.count = 1;
            in.clear();
        }
        if (step.count < 1 || step.count > 10000) return fail("COUNT must be 1 to 10000");
    } else if (verb == "drag") {
        std::string button;
        if (!(in >> button >> step.x0 >> step.y0 >> step.x1 >> step.y1)) return fail("expected: drag BUTTON X0 Y0 X1 Y1");
        step.kind = Step::Kind::kDrag;
        step.name = strip_shift(button, step.shift);
        if (step.name != "left" && step.name != "right" && step.name != "middle") {
            return fail("BUTTON is left, right, middle or shift+left");
        }
    } else if (verb == "wheel") {
        if (!(in >> step.count)) return fail("expected: wheel N");
        step.kind = Step::Kind::kWheel;
    } else if (verb == "frames") {
        if (!(in >> step.count) || step.count < 1 || step.count > 100000) return fail("expected: frames N (1 to 100000)");
        step.kind = Step::Kind::kFrames;
    } else if (verb == "screenshot") {
        if (!(in >> step.name)) return fail("expected: screenshot FILE");
        step.kind = Step::Kind::kScreenshot;
    } else if (verb == "quit") {
        step.kind = Step::Kind::kQuit;
    } else {
        return fail("unknown step (key, drag, wheel, frames, screenshot, quit)");
    }
    if (!at_end()) return fail("unexpected words at the end");
    return true;
}

}  // namespace

bool parse_script(const std::string& text, std::vector<Step>& steps, std::string& error) {
    steps.clear();
    std::string current;
    bool comment = false;
    const auto flush = [&]() {
        const auto first = current.find_first_not_of(" \t\r");
        if (first != std::string::npos) {
            Step step;
            if (!parse_step(current.substr(first), step, error)) return false;
            steps.push_back(step);
        }
        current.clear();
        return true;
    };
    for (const char c : text) {
        if (c == '\n' || (c == ';' && !comment)) {
            if (!flush()) return false;
            comment = false;
        } else if (c == '#') {
            comment = true;
        } else if (!comment) {
            current += c;
        }
    }
    return flush();
}

}  // namespace viewer
