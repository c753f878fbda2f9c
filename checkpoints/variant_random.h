// Scene variants (grading): the random numbers every milestone's use_variant() draws from.
// Deterministic on every platform: FNV-1a for the scene id (std::hash differs between standard
// libraries), std::mt19937_64 (its sequence is fixed by the standard), and integers drawn by
// hand (std::uniform_int_distribution's results differ between standard libraries).
#pragma once

#include <cstdint>
#include <random>
#include <string_view>
#include <utility>
#include <vector>

#include "raster/vec.h"

namespace cp {

inline std::uint64_t fnv1a(std::string_view text) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (const char c : text) {
        h ^= static_cast<unsigned char>(c);
        h *= 0x100000001b3ull;
    }
    return h;
}

class VariantRng {
public:
    // The generator of one scene's variant: seeded with seed XOR fnv1a(scene id).
    VariantRng(std::uint64_t seed, std::string_view id) : gen_(seed ^ fnv1a(id)) {}
    // Uniform in [lo, hi] (lo when the range is empty); the modulo bias is irrelevant here.
    int uniform(int lo, int hi) {
        if (hi <= lo) return lo;
        return lo + static_cast<int>(gen_() % static_cast<std::uint64_t>(hi - lo + 1));
    }
    bool coin() { return (gen_() >> 11) & 1; }
    template <typename T>
    void shuffle(std::vector<T>& v) {
        for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[std::size_t(uniform(0, int(i) - 1))]);
    }

private:
    std::mt19937_64 gen_;
};

// A symmetry of the w x h image (transpose only when square), then an integer translation.
// Each maps pixel centers to pixel centers, the 1/16 grid to itself and the sample grid of
// fill_triangle_aa to itself (a mirror maps x to w - x exactly). Milestones 1 and 2 use it.
struct ImageSymmetry {
    int w = 0, h = 0;
    bool transpose = false, mirror_x = false, mirror_y = false;
    int tx = 0, ty = 0;
    raster::Vec2 operator()(raster::Vec2 p) const {
        if (transpose) std::swap(p.x, p.y);
        if (mirror_x) p.x = w - p.x;
        if (mirror_y) p.y = h - p.y;
        return {p.x + tx, p.y + ty};
    }
};

}  // namespace cp
