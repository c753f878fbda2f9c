// Animated GIF files (through giflib, Debian's libgif-dev), for the demos and the gallery.
//
// Palette (GIF allows at most 256 colors): the writer collects the distinct colors of all
// frames. When there are at most 256, they become the global palette and the GIF is LOSSLESS
// (typical for flat-shaded and wireframe frames). Otherwise every pixel becomes the nearest
// color (squared RGB distance) of a FIXED palette: the 6 x 6 x 6 cube of levels
// 0, 51, 102, 153, 204, 255 plus 40 grays, 8 evenly spaced in each gap between the cube's
// grays (so gray ramps, as in anti-aliased wireframes, keep 46 levels), without dithering, so the result is deterministic and the same for every run. Gradients
// then show bands; use PNG frames when exact pixels matter.
//
// Every frame is a full image (no transparency, no partial rectangles); the frames keep their
// order; each is shown for `delay_centiseconds` hundredths of a second (0..65535; browsers
// show delays below 2 as 10). With loop = true the file carries the NETSCAPE2.0 extension that
// makes viewers repeat it forever; with false it plays once.
#pragma once

#include <string>
#include <vector>

#include "raster/image.h"
#include "raster/io.h"  // ImageIoError

namespace raster {

// Throws ImageIoError (with the path and the reason) for no frames, frames of different
// sizes, a delay outside 0..65535, or a file that cannot be written; a partly written file is
// removed.
void write_gif(const std::string& path, const std::vector<Image>& frames, int delay_centiseconds,
               bool loop = true);

// What a GIF file holds, as far as this project writes and checks it (tests, the gallery).
struct GifInfo {
    int width = 0, height = 0;
    std::vector<Image> frames;  // each image drawn over the previous frame, in order
    std::vector<int> delays;    // centiseconds per frame (0 when a frame has no delay)
    bool loops = false;         // has a NETSCAPE2.0 loop extension
};

// Reads any GIF giflib can decode; throws ImageIoError on a missing, truncated or corrupt file.
// Frames are composed on a canvas of the logical screen size (background: the screen's
// background color), honouring each frame's position and transparent color.
GifInfo read_gif(const std::string& path);

}  // namespace raster
