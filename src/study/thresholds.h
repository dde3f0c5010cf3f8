#pragma once
// The study's perceptual thresholds beside the relative MSE's (report.h): SSIM and mean HDR-FLIP, their
// defaults and the justification the report quotes.
namespace fp::study {

// SSIM >= 0.98: a dissimilarity 1 - SSIM of at most 0.02.
constexpr double kDefaultSsimThreshold = 0.98;
// Mean HDR-FLIP <= 0.05 at 67 pixels per degree (image/flip.h, kDefaultPixelsPerDegree).
constexpr double kDefaultFlipThreshold = 0.05;

extern const char* const kSsimRationale;
extern const char* const kFlipRationale;

}  // namespace fp::study
