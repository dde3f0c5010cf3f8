#pragma once
// How many samples per pixel an integrator (with a denoiser) needs to get under the noise threshold.
#include <string>
#include <vector>

#include "study/sweep.h"

namespace fp::study {

enum class Crossing {
    Measured,      // at or between two measured levels (log-log interpolation)
    Extrapolated,  // past the last level, by MSE ~ 1/N (only for raw, unbiased estimates)
    NotReached,    // past the last level of a denoised series: its error need not fall as 1/N
};

struct SppNeeded {
    Crossing kind = Crossing::NotReached;
    double spp = 0.0;  // meaningful unless NotReached
    int maxSpp = 0;    // the last level measured
};

// `series` holds one integrator and denoiser, in increasing spp. The first level at or under
// `threshold` is the crossing; between it and the level before, relMSE is interpolated linearly in
// log(spp)-log(relMSE). Without one, a raw series ("none") is extrapolated from its last level by the
// Monte Carlo rate (an unbiased estimate's MSE is variance / N), a denoised one is NotReached.
SppNeeded sppNeeded(const std::vector<StudyRow>& series, double threshold);

// "12.3", "~2400 (extrapolated, MSE ~ 1/N)", "not reached by 64 spp".
std::string describe(const SppNeeded& needed);

}  // namespace fp::study
