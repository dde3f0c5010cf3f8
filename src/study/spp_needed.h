#pragma once
// How many samples per pixel an integrator (with a denoiser) needs to get under a noise threshold, by
// any of the study's metrics: an error that must fall to a threshold (relMSE, FLIP) or a similarity that
// must rise to one (SSIM).
#include <string>
#include <vector>

#include "study/sweep.h"

namespace fp::study {

// One of study.csv's error columns, with the direction in which it improves.
struct StudyMetric {
    const char* name;         // "relMSE", "SSIM", "FLIP"
    double StudyRow::*value;  // its column
    double perfect;           // its value for an exact match: 0 for an error, 1 for a similarity
    bool higherIsBetter;      // a similarity: the threshold is a lower bound
    // An unbiased raw estimate's distance from `perfect` falls as 1/N (true of the MSE, whose expectation
    // is variance / N; not known of SSIM or FLIP, which are non-linear in the error), so a raw series that
    // never crosses may be extrapolated by that rate.
    bool fallsAsOneOverN;
};
const StudyMetric& relMseMetric();
const StudyMetric& ssimMetric();
const StudyMetric& flipMetric();

// How far `value` is from a perfect match: |value - perfect|, what the crossing interpolates.
double distanceFromPerfect(const StudyMetric& metric, double value);
// The threshold whose distance from perfect is `factor` times that of `threshold`: 0.5 is twice as
// strict, 2 twice as lenient (for SSIM, halving or doubling the dissimilarity 1 - SSIM).
double scaledThreshold(const StudyMetric& metric, double threshold, double factor);

enum class Crossing {
    Measured,      // at or between two measured levels (log-log interpolation)
    Extrapolated,  // past the last level, by 1/N (only for raw, unbiased estimates of a 1/N metric)
    NotReached,    // past the last level otherwise: a denoised error need not fall as 1/N
};

struct SppNeeded {
    Crossing kind = Crossing::NotReached;
    double spp = 0.0;  // meaningful unless NotReached
    int maxSpp = 0;    // the last level measured
};

// `series` holds one integrator and denoiser, in increasing spp. The first level that meets `threshold`
// is the crossing; between it and the level before, the distance from perfect is interpolated linearly in
// log(spp)-log(distance). Without one, a raw series ("none") of a metric that falls as 1/N is
// extrapolated from its last level by that rate; otherwise it is NotReached.
SppNeeded sppNeeded(const std::vector<StudyRow>& series, const StudyMetric& metric, double threshold);
// By relative MSE.
SppNeeded sppNeeded(const std::vector<StudyRow>& series, double relMseThreshold);

// The sensitivity band: the spp needed at the threshold, at twice it (lenient: fewer samples) and at half
// it (strict: more), in scaledThreshold's sense.
struct SppBand {
    SppNeeded lenient, atThreshold, strict;
};
constexpr double kLenientFactor = 2.0, kStrictFactor = 0.5;
SppBand sppBand(const std::vector<StudyRow>& series, const StudyMetric& metric, double threshold);

// "12.3", "~2400 (extrapolated, MSE ~ 1/N)", "not reached by 64 spp".
std::string describe(const SppNeeded& needed);
// Short forms for a table cell: "12.3", "~2400" (extrapolated), ">64" (not reached); and a band as
// "12.3 [6.1, 25]": the spp at the threshold, then at twice and at half of it.
std::string describeShort(const SppNeeded& needed);
std::string describe(const SppBand& band);

}  // namespace fp::study
