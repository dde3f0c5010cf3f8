#pragma once
// The two pipelines of LDR-FLIP (Andersson et al. 2020; flip.h), each on its own so that it can be
// tested on its own. Both take linear RGB images of one size, clamped to [0, 1] as ldrPixel does, and
// return one value in [0, 1] per pixel, row-major; ldrFlip checks the arguments and combines them:
// deltaE = deltaE_c ^ (1 - deltaE_f).
#include <algorithm>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"

namespace fp {

// The paper's constants. qc: the exponent of colour distances; pc and pt: the remapping's knee
// (distances below pc * cmax take the errors [0, pt], the rest (pt, 1]); w: the visual angle in degrees
// between the peak and trough of the edge detector (two standard deviations); qf: the exponent of
// feature differences.
constexpr double kFlipQc = 0.7, kFlipPc = 0.4, kFlipPt = 0.95, kFlipW = 0.082, kFlipQf = 0.5;

// An LDR input pixel: each channel clamped to [0, 1], NaN taken as 0.
inline glm::dvec3 ldrPixel(const glm::vec3& p) {
    auto unit = [](float v) { return v > 0.0f ? std::min(double(v), 1.0) : 0.0; };
    return {unit(p.r), unit(p.g), unit(p.b)};
}

// deltaE_c: how different the colours look once the eye's contrast sensitivity has filtered both
// images (flip_color.cpp).
std::vector<double> flipColorError(const Image& test, const Image& reference, double pixelsPerDegree);

// deltaE_f: how much the edges and points of the achromatic channel differ (flip_features.cpp).
std::vector<double> flipFeatureError(const Image& test, const Image& reference, double pixelsPerDegree);

}  // namespace fp
