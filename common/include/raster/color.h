// 8-bit RGB colors.
//
// Images store three bytes per pixel (red, green, blue; no alpha). A color's channels are
// 0..255 and mean "that fraction of full intensity" with no gamma curve applied: blending and
// anti-aliasing in this course are linear in these numbers, which keeps the expected values
// in the checkpoints easy to derive by hand.
#pragma once

#include <cstdint>

namespace raster {

struct Color {
    std::uint8_t r = 0, g = 0, b = 0;
};

constexpr bool operator==(Color a, Color b) { return a.r == b.r && a.g == b.g && a.b == b.b; }
constexpr bool operator!=(Color a, Color b) { return !(a == b); }

namespace colors {
inline constexpr Color black{0, 0, 0};
inline constexpr Color white{255, 255, 255};
inline constexpr Color red{255, 0, 0};
inline constexpr Color green{0, 255, 0};
inline constexpr Color blue{0, 0, 255};
inline constexpr Color yellow{255, 255, 0};
inline constexpr Color cyan{0, 255, 255};
inline constexpr Color magenta{255, 0, 255};
inline constexpr Color gray{128, 128, 128};
}  // namespace colors

// Rounds a real channel value to the nearest byte, clamping to 0..255. NaN becomes 0, so a
// bad coverage or light value shows up as black instead of as undefined behaviour.
// (Defined here, inline, because pixel loops call it for every pixel.)
inline std::uint8_t to_channel(double v) {
    if (!(v > 0)) return 0;  // also catches NaN
    if (v >= 255) return 255;
    return static_cast<std::uint8_t>(v + 0.5);  // round half up; v is positive here
}

// Color from real channels in [0, 1] (clamped).
Color from_unit(double r, double g, double b);

// (1 - t) * a + t * b per channel, t clamped to [0, 1]; the result is rounded to nearest.
inline Color mix(Color a, Color b, double t) {
    if (!(t > 0)) return a;
    if (t >= 1) return b;
    // With 0 < t < 1 the value lies between `from` and `to` (rounding is monotonic), so it
    // needs no clamping: to_channel's tests would never fire, and adding 0.5 then truncating
    // is its rounding (half up).
    auto lerp = [t](std::uint8_t from, std::uint8_t to) {
        return static_cast<std::uint8_t>(from + t * (static_cast<double>(to) - from) + 0.5);
    };
    return {lerp(a.r, b.r), lerp(a.g, b.g), lerp(a.b, b.b)};
}

}  // namespace raster
