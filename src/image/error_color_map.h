#pragma once
// The colour scale of error maps (`fragpath compare --heatmap`): lightness rises evenly with the error,
// so equal steps of error look like equal steps, and the hue turns from purple through red to orange
// on the way, as in the perceptually uniform maps (magma, inferno) that FLIP's authors show errors with.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"

namespace fp {

// Linear RGB for an error e in [0, 1] (clamped; NaN as 0), defined in CIELAB: L* = 5 + 90 e, hue angle
// 300 + 150 e degrees, chroma 60 sin(pi e)^0.8 (grey at both ends). Every value lies inside the sRGB
// cube, so no clipping bends the lightness ramp.
glm::dvec3 errorColor(double e);

// The red channel of `errorMap` through errorColor as 8-bit sRGB codes (3 bytes a pixel, top row
// first), for encodeRgb8Png.
std::vector<std::uint8_t> errorColorCodes(const Image& errorMap);

}  // namespace fp
