// Small pieces shared by the pages the checkpoints write (the check report, the grader's
// report and class page).
#pragma once

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

// Marks the page once every picture has loaded: data-broken counts the ones that did not (the
// project's tests read it through headless Chromium). The only script on these pages.
inline constexpr const char* kPictureLoadMarker =
    "<script>addEventListener('load',()=>{document.body.dataset.broken="
    "[...document.images].filter(i=>!i.naturalWidth).length;"
    "document.body.dataset.pictures=document.images.length;});</script>\n";

}  // namespace cp
