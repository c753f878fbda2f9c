// Animated GIF files (through giflib, Debian's libgif-dev), for the demos and the gallery.
//
// Palette (GIF allows at most 256 colors): the writer collects the distinct colors of all
// frames. When there are at most 256, they become the global palette and the GIF is LOSSLESS
// (typical for flat-shaded and aliased wireframe frames). Otherwise one global palette of 256
// colors is chosen by MEDIAN CUT over all frames: colors are counted in cells of 6 bits per
// channel; boxes of cells are split at the pixel-weighted median of their widest channel
// (the box with the largest pixel count x widest range first); each palette color is the
// pixel-weighted mean of its box, and each cell's pixels get the palette color nearest to the
// cell's mean (squared RGB distance). No dithering, so the result is deterministic. A color
// that covers many pixels (a background) comes back exact or nearly; smooth gradients show
// bands: use the PNG frames when exact pixels matter.
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
