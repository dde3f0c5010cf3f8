#pragma once
// Error of a rendered estimate against a converged reference, beyond the RMSE of image/image_stats.h.
#include <vector>

#include "image/image.h"

namespace fp {

// The epsilon of the relative MSE: keeps black reference pixels from dividing by zero. 0.01 is the
// value of Rousselle, Knaus and Zwicker 2011 ("Adaptive Sampling and Reconstruction using Greedy
// Error Minimization", SIGGRAPH Asia) and of the denoising literature that followed them.
constexpr double kRelMseEpsilon = 0.01;

// Relative mean squared error (Rousselle et al. 2011, as pbrt's and most denoising papers' relMSE):
// the mean over pixels and channels of (x - y)^2 / (y^2 + epsilon), x the estimate, y the reference.
// Throws fp::Error if the sizes differ or the images are empty.
double relativeMse(const Image& estimate, const Image& reference, double epsilon = kRelMseEpsilon);

// The relative MSE an unbiased estimate with per-pixel variance `variance` is expected to have against
// `reference`: the mean of variance / (y^2 + epsilon), since E[(x - y)^2] = Var(x) when E[x] = y.
double expectedRelativeMse(const Image& variance, const Image& reference, double epsilon = kRelMseEpsilon);

// What SSIM compares: the luma (Rec. 709 weights) of the display-encoded image (clamp tone map,
// exposure 0, sRGB encoding, as the PNG writer shows it), so the dynamic range is L = 1 whatever the
// radiance. Rows top first.
std::vector<float> displayLuma(const Image& image);

// Mean structural similarity (Wang, Bovik, Sheikh and Simoncelli 2004, "Image Quality Assessment: From
// Error Visibility to Structural Similarity", IEEE TIP 13(4), eq. 13 and section III-C): local means,
// variances and covariance under an 11x11 Gaussian window of sigma 1.5, C1 = (K1 L)^2 and
// C2 = (K2 L)^2 with K1 = 0.01, K2 = 0.03, L = 1, averaged over every window position that lies inside
// the image; computed on displayLuma. 1 means identical. Throws fp::Error if the sizes differ or the
// image is smaller than the 11x11 window.
double ssim(const Image& estimate, const Image& reference);
constexpr int kSsimWindow = 11;

}  // namespace fp
