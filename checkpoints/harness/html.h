// Small pieces shared by the pages the checkpoints write (the check report, the grader's
// report and class page).
#pragma once

#include <algorithm>
#include <string>

namespace cp {

// Text made safe for HTML element content and quoted attribute values.
inline std::string html_escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '&': out += "&amp;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&#39;"; break;
            default: out += c;
        }
    }
    return out;
}

// The width and height of a PNG from its first 24 bytes (the IHDR chunk), or 0 when they are
// not a PNG's.
inline int png_dimension(const std::string& head, int offset) {
    if (head.size() < 24 || head.compare(1, 3, "PNG") != 0) return 0;
    int v = 0;
    for (int i = offset; i < offset + 4; ++i)
        v = v * 256 + static_cast<unsigned char>(head[static_cast<std::size_t>(i)]);
    return v;
}
inline int png_width(const std::string& head) { return png_dimension(head, 16); }
inline int png_height(const std::string& head) { return png_dimension(head, 20); }

// The width in CSS pixels to show a picture `natural` pixels wide: the whole multiple of it
// (at least `min_times` of it, but no wider than 1024 unless it is itself) nearest to `about`,
// and large enough that a picture `natural_height` pixels high shows at least `min_height`
// high (a wide strip of panels is enlarged too), so that nearest-neighbour scaling
// (image-rendering: pixelated) repeats every pixel the same number of times and drops none: a
// single red pixel in a diff.png stays visible. `about` when the width is unknown.
inline int shown_width(int natural, int about, int min_times = 1, int natural_height = 0, int min_height = 0) {
    if (natural <= 0) return about;
    int times = std::max(min_times, (about + natural / 2) / natural);
    if (natural_height > 0) times = std::max(times, (min_height + natural_height - 1) / natural_height);
    return natural * std::max(1, std::min(times, 1024 / natural));
}

// What a checkpoint of numbers shows instead of its pictures (Verdict::numbers_only: its
// expected picture is one flat color that both main images match, so they would show a blank
// canvas, enlarged).
inline constexpr const char* kNumbersOnlyNote =
    "<p class=\"numbers-only\">Numbers only: this checkpoint judges the numbers your functions return, so "
    "there is no picture to show.</p>\n";

// Marks the page once every picture has loaded: data-broken counts the ones that did not (the
// project's tests read it through headless Chromium). The only script on these pages.
inline constexpr const char* kPictureLoadMarker =
    "<script>addEventListener('load',()=>{document.body.dataset.broken="
    "[...document.images].filter(i=>!i.naturalWidth).length;"
    "document.body.dataset.pictures=document.images.length;});</script>\n";

}  // namespace cp
