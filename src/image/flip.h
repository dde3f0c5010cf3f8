#pragma once
// FLIP, a perceptual error metric for rendered images: what a viewer flipping between a test image and
// its reference would notice, per pixel, in [0, 1].
//   LDR-FLIP: Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström and Fairchild 2020, "FLIP: A
//   Difference Evaluator for Alternating Images", Proc. ACM Comput. Graph. Interact. Tech. 3(2) (HPG).
//   HDR-FLIP: Andersson, Nilsson, Shirley and Akenine-Möller 2021, "Visualizing Errors in Rendered High
//   Dynamic Range Images", Eurographics short papers.
#include "image/image.h"

namespace fp {

// Pixels per degree of visual angle for an observer `distance` from a display `displayWidth` wide (both
// in metres) with `displayPixels` columns: distance * (displayPixels / displayWidth) * pi / 180.
double pixelsPerDegree(double distance, double displayWidth, int displayPixels);
// The papers' standard observer: 0.7 m from a 0.7 m wide display of 3840 columns, about 67.02.
constexpr double kDefaultPixelsPerDegree = 0.7 * (3840.0 / 0.7) * 3.14159265358979323846 / 180.0;

struct FlipResult {
    Image errorMap;     // the per-pixel error in [0, 1], the same value in all three channels
    double mean = 0.0;  // the mean over pixels: "mean FLIP"
};

// LDR-FLIP of `test` against `reference`, both linear RGB; channels are clamped to [0, 1] first (NaN
// counts as 0). Identical images give exactly 0. Throws fp::Error if the sizes differ, the images are
// empty or pixelsPerDegree is not a positive number.
FlipResult ldrFlip(const Image& test, const Image& reference,
                   double pixelsPerDegree = kDefaultPixelsPerDegree);

// The exposures (in stops) HDR-FLIP tone maps at: `count` evenly spaced from `start` to `stop`.
struct FlipExposures {
    double start = 0.0, stop = 0.0;
    int count = 2;
};

// The exposure range HDR-FLIP derives from the reference's luminance (HDR-FLIP paper): with t the
// tone curve below and x85 the radiance it maps to 0.85, start = log2(x85 / the largest luminance)
// (the brightest pixel just below white), stop = log2(x85 / the median luminance) (the typical pixel
// at the same place), count = max(2, ceil(stop - start)), about one exposure a stop. Luminance is
// Y of linearRgbToXyz of the channels, negatives taken as 0 (as the tone curve takes them). An all-black
// reference gives start = stop = 0. Where the paper divides by a median of 0 (a mostly black image) we take
// the median of the non-zero luminances instead: our choice, so that the dark pixels still get a finite, long
// exposure.
FlipExposures hdrFlipExposures(const Image& reference);

// The HDR tone curve of HDR-FLIP: ACES (Narkowicz's fit, image/tone_map.h) with his pre-exposure of 0.6
// applied, t(x) = toneMapAces(0.6 x), clamped to [0, 1]; negatives and NaN give 0.
float hdrFlipToneMap(float x);

// HDR-FLIP: both images (linear radiance) scaled by 2^exposure and tone mapped by hdrFlipToneMap at
// each exposure of `exposures`, LDR-FLIP of each pair, and per pixel the largest of those errors.
// The mean is over that per-pixel maximum. Throws as ldrFlip does.
FlipResult hdrFlip(const Image& test, const Image& reference, double pixelsPerDegree,
                   const FlipExposures& exposures);
// The same with the exposures hdrFlipExposures(reference) computes.
FlipResult hdrFlip(const Image& test, const Image& reference,
                   double pixelsPerDegree = kDefaultPixelsPerDegree);

}  // namespace fp
