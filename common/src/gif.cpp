// Animated GIF writing and reading through giflib. Palette rules: raster/gif.h.
#include "raster/gif.h"

#include <gif_lib.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <unordered_map>

namespace raster {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& reason) {
    throw ImageIoError(path + ": " + reason);
}

std::string gif_error(int code) {
    const char* s = GifErrorString(code);
    return s != nullptr ? s : "giflib error " + std::to_string(code);
}

std::uint32_t pack(Color c) {
    return (static_cast<std::uint32_t>(c.r) << 16) | (static_cast<std::uint32_t>(c.g) << 8) | c.b;
}

// The fixed palette: the 6 x 6 x 6 cube (index 36 r + 6 g + b, levels 51 apart), then 40
// grays, 8 evenly spaced inside each of the 5 gaps between the cube's gray levels.
std::vector<Color> fixed_palette() {
    std::vector<Color> p;
    for (int r = 0; r < 6; ++r)
        for (int g = 0; g < 6; ++g)
            for (int b = 0; b < 6; ++b)
                p.push_back({static_cast<std::uint8_t>(51 * r), static_cast<std::uint8_t>(51 * g),
                             static_cast<std::uint8_t>(51 * b)});
    for (int gap = 0; gap < 5; ++gap) {
        for (int k = 1; k <= 8; ++k) {
            const auto v = static_cast<std::uint8_t>(51 * gap + (51 * k + 4) / 9);
            p.push_back({v, v, v});
        }
    }
    return p;
}

int sq(int v) { return v * v; }

// Nearest color of fixed_palette(): the nearest cube color is per-channel rounding, the
// nearest gray is the closest of the gray levels; the closer of the two is the nearest of all.
std::uint8_t nearest_fixed(Color c, const std::vector<Color>& palette) {
    auto level = [](int v) { return (v + 25) / 51; };
    const int r = level(c.r), g = level(c.g), b = level(c.b);
    int best = 36 * r + 6 * g + b;
    int best_d = sq(c.r - 51 * r) + sq(c.g - 51 * g) + sq(c.b - 51 * b);
    for (int i = 216; i < 256; ++i) {
        const Color q = palette[static_cast<std::size_t>(i)];
        const int d = sq(c.r - q.r) + sq(c.g - q.g) + sq(c.b - q.b);
        if (d < best_d) {
            best_d = d;
            best = i;
        }
    }
    return static_cast<std::uint8_t>(best);
}

}  // namespace

void write_gif(const std::string& path, const std::vector<Image>& frames, int delay_centiseconds,
               bool loop) {
    if (frames.empty()) fail(path, "no frames to write");
    const int w = frames[0].width(), h = frames[0].height();
    if (w == 0) fail(path, "frame 0 is empty");
    for (std::size_t i = 1; i < frames.size(); ++i) {
        if (frames[i].width() != w || frames[i].height() != h) {
            fail(path, "frame " + std::to_string(i) + " is " + std::to_string(frames[i].width()) +
                           "x" + std::to_string(frames[i].height()) + ", frame 0 is " +
                           std::to_string(w) + "x" + std::to_string(h) +
                           " (all frames must have the same size)");
        }
    }
    if (delay_centiseconds < 0 || delay_centiseconds > 65535) {
        fail(path, "delay " + std::to_string(delay_centiseconds) + " outside 0..65535 centiseconds");
    }

    // Palette: exact when the frames use at most 256 colors, else the fixed one.
    std::vector<Color> palette;
    std::unordered_map<std::uint32_t, std::uint8_t> index_of;
    {
        std::vector<std::uint32_t> distinct;
        std::unordered_map<std::uint32_t, bool> seen;
        for (const Image& f : frames) {
            const std::uint8_t* d = f.data();
            for (std::size_t i = 0; i + 2 < f.size_bytes() && seen.size() <= 256; i += 3) {
                seen.emplace(pack({d[i], d[i + 1], d[i + 2]}), true);
            }
        }
        if (seen.size() <= 256) {
            for (const auto& [key, unused] : seen) distinct.push_back(key);
            std::sort(distinct.begin(), distinct.end());
            for (std::size_t i = 0; i < distinct.size(); ++i) {
                const std::uint32_t k = distinct[i];
                palette.push_back({static_cast<std::uint8_t>(k >> 16),
                                   static_cast<std::uint8_t>((k >> 8) & 255),
                                   static_cast<std::uint8_t>(k & 255)});
                index_of[k] = static_cast<std::uint8_t>(i);
            }
        } else {
            palette = fixed_palette();
        }
    }
    const bool exact = !index_of.empty();
    const int map_size = 1 << GifBitSize(static_cast<int>(std::max<std::size_t>(palette.size(), 2)));
    std::vector<GifColorType> colors(static_cast<std::size_t>(map_size), GifColorType{0, 0, 0});
    for (std::size_t i = 0; i < palette.size(); ++i) {
        colors[i] = GifColorType{palette[i].r, palette[i].g, palette[i].b};
    }

    int err = 0;
    GifFileType* gif = EGifOpenFileName(path.c_str(), false, &err);
    if (gif == nullptr) fail(path, "cannot open for writing: " + gif_error(err));
    ColorMapObject* map = GifMakeMapObject(map_size, colors.data());
    bool ok = map != nullptr;
    std::string why = ok ? "" : "out of memory for the palette";
    auto step = [&](int result, const char* what) {
        if (ok && result == GIF_ERROR) {
            ok = false;
            why = std::string(what) + ": " + gif_error(gif->Error);
        }
    };
    if (ok) {
        EGifSetGifVersion(gif, true);  // GIF89a: needed for delays and looping
        step(EGifPutScreenDesc(gif, w, h, 8, 0, map), "screen descriptor");
    }
    if (ok && loop) {
        static const GifByteType netscape[] = {'N', 'E', 'T', 'S', 'C', 'A', 'P', 'E', '2', '.', '0'};
        static const GifByteType forever[] = {1, 0, 0};  // sub-block 1, loop count 0 = forever
        step(EGifPutExtensionLeader(gif, APPLICATION_EXT_FUNC_CODE), "loop extension");
        step(EGifPutExtensionBlock(gif, sizeof netscape, netscape), "loop extension");
        step(EGifPutExtensionBlock(gif, sizeof forever, forever), "loop extension");
        step(EGifPutExtensionTrailer(gif), "loop extension");
    }
    std::vector<GifPixelType> row(static_cast<std::size_t>(w));
    for (std::size_t f = 0; ok && f < frames.size(); ++f) {
        GraphicsControlBlock gcb{};
        gcb.DisposalMode = DISPOSE_DO_NOT;
        gcb.UserInputFlag = false;
        gcb.DelayTime = delay_centiseconds;
        gcb.TransparentColor = NO_TRANSPARENT_COLOR;
        GifByteType ext[4];
        const auto len = EGifGCBToExtension(&gcb, ext);
        step(EGifPutExtension(gif, GRAPHICS_EXT_FUNC_CODE, static_cast<int>(len), ext), "frame delay");
        step(EGifPutImageDesc(gif, 0, 0, w, h, false, nullptr), "image descriptor");
        const std::uint8_t* d = frames[f].data();
        for (int y = 0; ok && y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const std::size_t o = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) +
                                           static_cast<std::size_t>(x));
                const Color c{d[o], d[o + 1], d[o + 2]};
                row[static_cast<std::size_t>(x)] = exact ? index_of.at(pack(c)) : nearest_fixed(c, palette);
            }
            step(EGifPutLine(gif, row.data(), w), "pixels");
        }
    }
    if (map != nullptr) GifFreeMapObject(map);
    // EGifCloseFile writes the trailer and frees `gif` in every case.
    if (EGifCloseFile(gif, &err) == GIF_ERROR && ok) {
        ok = false;
        why = "closing: " + gif_error(err);
    }
    if (!ok) {
        std::remove(path.c_str());
        fail(path, "cannot write GIF: " + why);
    }
}

GifInfo read_gif(const std::string& path) {
    int err = 0;
    GifFileType* gif = DGifOpenFileName(path.c_str(), &err);
    if (gif == nullptr) fail(path, "cannot read GIF: " + gif_error(err));
    struct Closer {
        GifFileType* g;
        ~Closer() {
            int e = 0;
            DGifCloseFile(g, &e);
        }
    } closer{gif};
    if (DGifSlurp(gif) == GIF_ERROR) fail(path, "cannot read GIF: " + gif_error(gif->Error));

    GifInfo info;
    info.width = gif->SWidth;
    info.height = gif->SHeight;
    if (info.width < 1 || info.height < 1 || info.width > Image::kMaxSide || info.height > Image::kMaxSide) {
        fail(path, "unsupported screen size " + std::to_string(info.width) + "x" +
                       std::to_string(info.height));
    }
    if (gif->ImageCount < 1) fail(path, "no images in the GIF");
    const long long frame_bytes = 3LL * info.width * info.height;
    if (frame_bytes * gif->ImageCount > (1LL << 30)) fail(path, "too many pixels (over 1 GiB of frames)");

    auto is_netscape_loop = [](const ExtensionBlock* blocks, int count) {
        for (int i = 0; i + 1 < count; ++i) {
            if (blocks[i].Function == APPLICATION_EXT_FUNC_CODE && blocks[i].ByteCount == 11 &&
                std::memcmp(blocks[i].Bytes, "NETSCAPE2.0", 11) == 0) {
                return true;
            }
        }
        return false;
    };
    info.loops = is_netscape_loop(gif->ExtensionBlocks, gif->ExtensionBlockCount);

    Color background{};
    if (gif->SColorMap != nullptr && gif->SBackGroundColor < gif->SColorMap->ColorCount) {
        const GifColorType c = gif->SColorMap->Colors[gif->SBackGroundColor];
        background = {c.Red, c.Green, c.Blue};
    }
    Image canvas(info.width, info.height, background);
    for (int i = 0; i < gif->ImageCount; ++i) {
        const SavedImage& img = gif->SavedImages[i];
        info.loops = info.loops || is_netscape_loop(img.ExtensionBlocks, img.ExtensionBlockCount);
        GraphicsControlBlock gcb{};
        gcb.TransparentColor = NO_TRANSPARENT_COLOR;
        if (DGifSavedExtensionToGCB(gif, i, &gcb) == GIF_ERROR) {
            gcb = GraphicsControlBlock{};
            gcb.TransparentColor = NO_TRANSPARENT_COLOR;
        }
        const ColorMapObject* map = img.ImageDesc.ColorMap != nullptr ? img.ImageDesc.ColorMap : gif->SColorMap;
        if (map == nullptr) fail(path, "image " + std::to_string(i) + " has no color map");
        const Image before = canvas;
        const GifImageDesc& desc = img.ImageDesc;
        for (int y = 0; y < desc.Height; ++y) {
            for (int x = 0; x < desc.Width; ++x) {
                const int idx = img.RasterBits[static_cast<std::size_t>(y) * static_cast<std::size_t>(desc.Width) +
                                               static_cast<std::size_t>(x)];
                if (idx == gcb.TransparentColor) continue;
                if (idx >= map->ColorCount) {
                    fail(path, "image " + std::to_string(i) + " uses color " + std::to_string(idx) +
                                   " outside its palette of " + std::to_string(map->ColorCount));
                }
                const int cx = desc.Left + x, cy = desc.Top + y;
                if (!canvas.in_bounds(cx, cy)) continue;
                const GifColorType c = map->Colors[idx];
                canvas.set(cx, cy, {c.Red, c.Green, c.Blue});
            }
        }
        info.frames.push_back(canvas);
        info.delays.push_back(gcb.DelayTime);
        if (gcb.DisposalMode == DISPOSE_BACKGROUND) {
            for (int y = 0; y < desc.Height; ++y)
                for (int x = 0; x < desc.Width; ++x)
                    if (canvas.in_bounds(desc.Left + x, desc.Top + y)) canvas.set(desc.Left + x, desc.Top + y, background);
        } else if (gcb.DisposalMode == DISPOSE_PREVIOUS) {
            canvas = before;
        }
    }
    return info;
}

}  // namespace raster
