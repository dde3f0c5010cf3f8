#include "image/error_color_map.h"

#include <algorithm>
#include <cmath>

#include "image/color_space.h"
#include "image/tone_map.h"

namespace fp {

glm::dvec3 errorColor(double e) {
    const double pi = 3.14159265358979323846;
    e = e > 0.0 ? std::min(e, 1.0) : 0.0;
    const double lightness = 5.0 + 90.0 * e, hue = (300.0 + 150.0 * e) * pi / 180.0;
    const double chroma = 60.0 * std::pow(std::sin(pi * e), 0.8);
    return xyzToLinearRgb(labToXyz({lightness, chroma * std::cos(hue), chroma * std::sin(hue)}));
}

std::vector<std::uint8_t> errorColorCodes(const Image& errorMap) {
    std::vector<std::uint8_t> codes;
    codes.reserve(errorMap.pixels.size() * 3);
    for (const glm::vec3& p : errorMap.pixels) {
        const glm::dvec3 rgb = errorColor(p.r);
        for (int c = 0; c < 3; ++c) codes.push_back(quantize8(srgbEncode(float(rgb[c]))));
    }
    return codes;
}

}  // namespace fp
