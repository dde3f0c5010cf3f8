// Emitter selection probabilities (src/scene/light_selection.h).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "scene/light_selection.h"

namespace fp {
namespace {

// The shader picks the first emitter whose cdf exceeds u = k / 2^24 (pickLight, lights.glsl) and weighs
// the pick by the triangle's stored pmf (emitterAreaPdf): the two must be the same number for every
// emitter, or nee is biased wherever the pick and the pdf disagree. With 1e5 emitters of very different
// powers, a cdf summed in float drifts from the stored pmfs by many times a small emitter's share.
TEST(LightSelection, PickProbabilityIsThePmfExactly) {
    constexpr double kGrid = 16777216.0;  // 2^24, the resolution of rand()
    std::vector<double> power(100000);
    for (size_t i = 0; i < power.size(); ++i)
        power[i] = i % 7 == 3 ? 0.0 : 1.0 + 1000.0 * double((i * 7919) % 1000) * double(i) / 1e5;
    double total = 0.0;
    for (double w : power) total += w;
    std::vector<float> pmf = lightPmfs(power, total);
    // The probability that pickLight returns emitter i: the grid points k / 2^24 in [cdf_{i-1}, cdf_i),
    // the cdf summed in float as the packer stores it.
    float cdf = 0.0f;
    double pickSum = 0.0;
    for (size_t i = 0; i < power.size(); ++i) {
        if (power[i] == 0.0) {
            EXPECT_EQ(pmf[i], 0.0f) << i;
            continue;
        }
        float next = cdf + pmf[i];
        double pick = (std::ceil(double(next) * kGrid) - std::ceil(double(cdf) * kGrid)) / kGrid;
        ASSERT_EQ(pick, double(pmf[i])) << "emitter " << i;
        // And the pmf is its power's share, to the grid's resolution.
        EXPECT_NEAR(pmf[i], power[i] / total, 1.0 / kGrid) << i;
        pickSum += pick;
        cdf = next;
    }
    EXPECT_EQ(cdf, 1.0f);
    EXPECT_EQ(pickSum, 1.0);
}

}  // namespace
}  // namespace fp
