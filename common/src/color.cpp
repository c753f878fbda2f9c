#include "raster/color.h"

#include <algorithm>
#include <cmath>

namespace raster {

Color from_unit(double r, double g, double b) {
    return {to_channel(r * 255), to_channel(g * 255), to_channel(b * 255)};
}

}  // namespace raster
