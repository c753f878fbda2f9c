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

// ---- median cut, for animations with more than 256 colors ----
// Colors are counted in cells of 6 bits per channel (64^3 cells); each cell keeps the sum of
// its exact colors, so a box holding a single color gets exactly that color back.
constexpr int kCellBits = 6;
constexpr int kCells = 1 << (3 * kCellBits);

int cell_of(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    constexpr int shift = 8 - kCellBits;
    return ((r >> shift) << (2 * kCellBits)) | ((g >> shift) << kCellBits) | (b >> shift);
}

struct Cell {
    int id = 0;
    long long count = 0;
    long long sum[3] = {0, 0, 0};
    std::uint8_t mean(int ch) const {
        return static_cast<std::uint8_t>((sum[ch] + count / 2) / count);
    }
};

struct Box {
    std::size_t begin, end;  // range in the cell list
    long long count;
    int lo[3], hi[3];        // channel ranges of the cells' mean colors
};

Box make_box(const std::vector<Cell>& cells, std::size_t begin, std::size_t end) {
    Box box{begin, end, 0, {255, 255, 255}, {0, 0, 0}};
    for (std::size_t i = begin; i < end; ++i) {
        box.count += cells[i].count;
        for (int ch = 0; ch < 3; ++ch) {
            box.lo[ch] = std::min<int>(box.lo[ch], cells[i].mean(ch));
            box.hi[ch] = std::max<int>(box.hi[ch], cells[i].mean(ch));
        }
    }
    return box;
}

int widest_channel(const Box& b) {
    int best = 0;
    for (int ch = 1; ch < 3; ++ch)
        if (b.hi[ch] - b.lo[ch] > b.hi[best] - b.lo[best]) best = ch;
    return best;
}

// Up to 256 colors for the frames: boxes of cells are split at the pixel-weighted median of
// their widest channel, the box to split next being the one with the largest
// pixels x widest range; each box's color is the pixel-weighted mean of its colors.
// Returns the palette and, for every cell, the index of its nearest palette color.
std::vector<Color> median_cut(const std::vector<Image>& frames, std::vector<std::uint8_t>& cell_index) {
    std::vector<Cell> all(kCells);
    for (const Image& f : frames) {
        const std::uint8_t* d = f.data();
        for (std::size_t i = 0; i + 2 < f.size_bytes(); i += 3) {
            Cell& c = all[static_cast<std::size_t>(cell_of(d[i], d[i + 1], d[i + 2]))];
            ++c.count;
            c.sum[0] += d[i];
            c.sum[1] += d[i + 1];
            c.sum[2] += d[i + 2];
        }
    }
    std::vector<Cell> cells;
    for (int id = 0; id < kCells; ++id) {
        if (all[static_cast<std::size_t>(id)].count > 0) {
            cells.push_back(all[static_cast<std::size_t>(id)]);
            cells.back().id = id;
        }
    }
    std::vector<Box> boxes{make_box(cells, 0, cells.size())};
    while (boxes.size() < 256) {
        std::size_t pick = boxes.size();
        long double best = 0;
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            const Box& b = boxes[i];
            const int ch = widest_channel(b);
            const long double score = static_cast<long double>(b.count) * (b.hi[ch] - b.lo[ch]);
            if (b.end - b.begin > 1 && score > best) {
                best = score;
                pick = i;
            }
        }
        if (pick == boxes.size()) break;  // every box is a single color
        const Box b = boxes[pick];
        const int ch = widest_channel(b);
        const auto first = cells.begin() + static_cast<std::ptrdiff_t>(b.begin);
        const auto last = cells.begin() + static_cast<std::ptrdiff_t>(b.end);
        std::sort(first, last, [ch](const Cell& x, const Cell& y) {
            return x.mean(ch) != y.mean(ch) ? x.mean(ch) < y.mean(ch) : x.id < y.id;
        });
        long long running = 0;
        std::size_t split = b.begin + 1;
        for (std::size_t i = b.begin; i + 1 < b.end; ++i) {
            running += cells[i].count;
            split = i + 1;
            if (2 * running >= b.count) break;
        }
        boxes[pick] = make_box(cells, b.begin, split);
        boxes.push_back(make_box(cells, split, b.end));
    }
    std::vector<Color> palette;
    for (const Box& b : boxes) {
        long long sum[3] = {0, 0, 0};
        for (std::size_t i = b.begin; i < b.end; ++i)
            for (int ch = 0; ch < 3; ++ch) sum[ch] += cells[i].sum[ch];
        auto avg = [&](int ch) { return static_cast<std::uint8_t>((sum[ch] + b.count / 2) / b.count); };
        palette.push_back({avg(0), avg(1), avg(2)});
    }
    cell_index.assign(kCells, 0);
    for (const Cell& c : cells) {
        int best = 0, best_d = 1 << 30;
        for (std::size_t i = 0; i < palette.size(); ++i) {
            const Color q = palette[i];
            const int dr = c.mean(0) - q.r, dg = c.mean(1) - q.g, db = c.mean(2) - q.b;
            const int d = dr * dr + dg * dg + db * db;
            if (d < best_d) {
                best_d = d;
                best = static_cast<int>(i);
            }
        }
        cell_index[static_cast<std::size_t>(c.id)] = static_cast<std::uint8_t>(best);
    }
    return palette;
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

    // Palette: exact when the frames use at most 256 colors, else a median cut.
    std::vector<Color> palette;
    std::vector<std::uint8_t> cell_index;
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
            palette = median_cut(frames, cell_index);
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
                row[static_cast<std::size_t>(x)] =
                    exact ? index_of.at(pack(c)) : cell_index[static_cast<std::size_t>(cell_of(c.r, c.g, c.b))];
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
