// The viewer's scripted mode: a list of steps that main.cpp turns into REAL SDL events
// (SDL_PushEvent), handled by the same event loop as a person's keys and mouse, plus
// screenshots of what the window shows. Used by the tests (under Xvfb or SDL's dummy video
// driver) and by `make viewer-screenshots`.
//
// Steps are separated by ';' or new lines; '#' starts a comment. One step per frame:
//
//   key NAME [COUNT]           press and release a key COUNT times (SDL's key names: w, 1,
//                              Left, Space, Escape...; "shift+Left" holds shift)
//   drag BUTTON X0 Y0 X1 Y1    press BUTTON (left, right, middle, shift+left) at (X0, Y0),
//                              move to (X1, Y1) in 10 steps, release
//   wheel N                    turn the mouse wheel N notches (positive: away, zooms in)
//   frames N                   draw N frames without input
//   screenshot FILE            save the window's pixels (after the steps before) as a PNG
//   quit                       end (the end of the script ends the viewer too)
//
// e.g.  viewer --events "key 2; screenshot flat.png; drag left 400 300 500 300; screenshot b.png"
#pragma once

#include <string>
#include <vector>

namespace viewer {

struct Step {
    enum class Kind { kKey, kDrag, kWheel, kFrames, kScreenshot, kQuit };
    Kind kind = Kind::kFrames;
    std::string name;  // kKey: the key; kDrag: the button; kScreenshot: the file
    bool shift = false;
    int count = 1;     // kKey: presses; kWheel: notches; kFrames: frames
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// Parses a script; on a malformed step returns false with `error` naming it.
bool parse_script(const std::string& text, std::vector<Step>& steps, std::string& error);

}  // namespace viewer
