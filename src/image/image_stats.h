#pragma once
// Summary numbers for comparing renders in tests and reports. Sums run in double so that means over
// millions of pixels are not limited by float accumulation error.
#include <glm/glm.hpp>

#include "image/image.h"

namespace fp {

// A rectangle of pixels: columns [x, x + width), rows [y, y + height), row 0 at the top as in Image.
struct PixelRect {
    int x = 0, y = 0, width = 0, height = 0;
};

// Per-channel mean. Throws fp::Error for an empty image.
glm::dvec3 meanColor(const Image& image);
// Per-channel mean over `rect`; throws fp::Error if it is empty or not inside the image.
glm::dvec3 meanColor(const Image& image, const PixelRect& rect);
// Root-mean-square difference over all pixels and all three channels:
// sqrt(sum over pixels and channels of (a - b)^2 / (3 * pixel count)).
// Throws fp::Error if the sizes differ or the images are empty.
double rmse(const Image& a, const Image& b);
// True if no channel of any pixel is NaN or infinite (true for an empty image).
bool allFinite(const Image& image);

}  // namespace fp
