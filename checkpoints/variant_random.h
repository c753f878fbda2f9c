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

// A milestone's scenes as a checkpoint program sees them: the public ones, or, after use(seed)
// with a seed other than 0, each public scene passed through the milestone's vary() with a
// generator of its own (the seed and the scene's id), as grading's hidden variants are made.
// use(0) returns to the public scenes. Scene needs an `id`.
template <typename Scene>
class SceneVariants {
public:
    using PublicScenes = const std::vector<Scene>& (*)();
    using Vary = Scene (*)(const Scene&, VariantRng&);
    constexpr SceneVariants(PublicScenes public_scenes, Vary vary) : public_(public_scenes), vary_(vary) {}

    const std::vector<Scene>& scenes() const { return seed_ == 0 ? public_() : varied_; }
    std::uint64_t seed() const { return seed_; }
    void use(std::uint64_t seed) {
        if (seed == seed_) return;
        seed_ = 0;  // the public scenes until the varied ones are complete
        varied_.clear();
        if (seed == 0) return;
        for (const Scene& s : public_()) {
            VariantRng rng(seed, s.id);
            varied_.push_back(vary_(s, rng));
        }
        seed_ = seed;
    }

private:
    PublicScenes public_;
    Vary vary_;
    std::uint64_t seed_ = 0;
    std::vector<Scene> varied_;
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
