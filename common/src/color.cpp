#include "raster/color.h"

#include <algorithm>
#include <cmath>

namespace raster {

std::uint8_t to_channel(double v) {
    if (!(v > 0)) return 0;  // also catches NaN
    if (v >= 255) return 255;
    return static_cast<std::uint8_t>(v + 0.5);  // round half up; v is positive here
}

Color from_unit(double r, double g, double b) {
    return {to_channel(r * 255), to_channel(g * 255), to_channel(b * 255)};
}

Color mix(Color a, Color b, double t) {
    if (!(t > 0)) return a;
    if (t >= 1) return b;
    auto lerp = [t](std::uint8_t from, std::uint8_t to) {
        return to_channel(from + t * (static_cast<double>(to) - from));
    };
    return {lerp(a.r, b.r), lerp(a.g, b.g), lerp(a.b, b.b)};
}

}  // namespace raster
