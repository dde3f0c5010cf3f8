#pragma once
// Issue 35's bound for the analytic references (a plane under a square lamp, a convex object under a
// uniform sky, a glass slab's transmittance): every integrator within 0.05 % of the closed form. A
// Monte Carlo image meets such a bound only when its noise is well below it, and 16 x 16 pixels of
// independent samples would need some 10^8 paths for that with naive or bsdf under the lamp (relative
// noise 0.9-1.4 per path). So each check is twofold:
//   - per pixel and per block: one render with independent numbers, its z-scores against the closed
//     form pixel by pixel (expectImage, render_test_util.h), from the variance the renderer accumulates;
//   - the whole image's mean to 0.05 %: kReplicates renders with the Owen-scrambled Sobol sampler,
//     each with its own seed (its own scrambles and shifts, so the renders are independent randomised
//     quasi-Monte Carlo replicates, Owen 1997), whose spread gives the standard error (a pixel's own
//     sample variance overstates a stratified estimate's error, and its blue noise makes neighbouring
//     pixels' errors cancel, so neither can give it). The mean over replicates must be within 0.05 %
//     of the closed form and within 5 standard errors of it, and that standard error at most a quarter
//     of 0.05 %, so that the bound says something the noise cannot.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "render/render_test_util.h"

namespace fp::test {

constexpr double kAnalyticTolerance = 5e-4;  // relative
constexpr int kReplicates = 16;              // Student's t with 15 degrees of freedom: P(|t| > 5) = 1.6e-4
constexpr int kAnalyticSize = 16;            // pixels across, 4 x 4 blocks of 4 x 4
constexpr int kIndependentSpp = 256;

// An integrator with the strategies it chooses between, and the Sobol samples per pixel each replicate
// takes (what its noise on the scene needs; bdpt's paths cost several of the others').
struct AnalyticVariant {
    Integrator integrator;
    int replicateSpp;
    LightSampling lightSampling = LightSampling::Auto;
    LightSelection lightSelection = LightSelection::Auto;
    Caustics caustics = Caustics::Auto;
    int independentSpp = kIndependentSpp;  // of the render whose blocks are checked
};

// A name for gtest's parameterised tests: letters, digits and underscores.
inline std::string variantName(const AnalyticVariant& v) {
    std::string name = integratorName(v.integrator);
    if (v.lightSampling != LightSampling::Auto) name += std::string("_") + lightSamplingName(v.lightSampling);
    if (v.lightSelection != LightSelection::Auto)
        name += std::string("_") + lightSelectionName(v.lightSelection);
    if (v.caustics != Caustics::Auto) name += std::string("_caustics_") + causticsName(v.caustics);
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

// The same as INSTANTIATE_TEST_SUITE_P's name generator, and as gtest prints a parameter.
inline std::string variantTestName(const ::testing::TestParamInfo<AnalyticVariant>& info) {
    return variantName(info.param);
}
inline void PrintTo(const AnalyticVariant& v, std::ostream* os) {
    *os << variantName(v);
}

inline Accumulation renderVariant(Renderer& renderer, const Camera& camera, const AnalyticVariant& v, int spp,
                                  int maxDepth, uint32_t seed, Sampler sampler) {
    return renderScene(renderer, camera, v.integrator, kAnalyticSize, spp, maxDepth, seed, sampler,
                       v.lightSampling, v.lightSelection, v.caustics);
}

// The relative error of the image mean, averaged over kReplicates Sobol renders of `v` at `maxDepth`
// (seeds 1000 on), against `expected` (kAnalyticSize^2 pixels, rows top first), and its standard error
// from their spread. Prints both.
struct ReplicateError {
    glm::dvec3 mean{0.0}, standardError{0.0};
};

inline ReplicateError replicateError(Renderer& renderer, const Camera& camera, const AnalyticVariant& v,
                                     int maxDepth, const std::vector<glm::dvec3>& expected,
                                     const std::string& what) {
    glm::dvec3 want(0.0);
    for (const glm::dvec3& value : expected) want += value / double(expected.size());
    glm::dvec3 sum(0.0), squares(0.0);
    for (int r = 0; r < kReplicates; ++r) {
        Accumulation acc =
            renderVariant(renderer, camera, v, v.replicateSpp, maxDepth, 1000u + uint32_t(r), Sampler::Sobol);
        EXPECT_EQ(acc.droppedSamples(), 0u) << what;
        glm::dvec3 relative = glm::dvec3(estimate(acc).mean) / want - 1.0;
        sum += relative;
        squares += relative * relative;
    }
    const double n = kReplicates;
    glm::dvec3 mean = sum / n, variance = glm::max((squares - n * mean * mean) / (n - 1.0), glm::dvec3(0.0));
    ReplicateError e{mean, glm::sqrt(variance / n)};
    std::printf("  %s: %d x %d spp, relative error %+.5f%% %+.5f%% %+.5f%%, standard error %.5f%%\n",
                what.c_str(), kReplicates, v.replicateSpp, 100.0 * mean.x, 100.0 * mean.y, 100.0 * mean.z,
                100.0 * e.standardError.y);
    return e;
}

// The twofold check above of `v` at `maxDepth` against `expected`. Returns the relative error of the
// replicates' mean in the first channel.
inline double expectAnalytic(Renderer& renderer, const Camera& camera, const AnalyticVariant& v, int maxDepth,
                             const std::vector<glm::dvec3>& expected, const std::string& what) {
    expectImage(renderVariant(renderer, camera, v, v.independentSpp, maxDepth, 1, Sampler::Independent),
                expected, 4, what + ", independent numbers");
    const ReplicateError e = replicateError(renderer, camera, v, maxDepth, expected, what);
    for (int ch = 0; ch < 3; ++ch) {
        double error = e.mean[ch], se = e.standardError[ch];
        EXPECT_LT(std::abs(error), kAnalyticTolerance)
            << what << ", channel " << ch << ": relative error " << error;
        EXPECT_LT(se, 0.25 * kAnalyticTolerance)
            << what << ", channel " << ch << ": too noisy for a 0.05 % bound to mean anything";
        // 1e-5 for the shader's float arithmetic, where the estimate is noise-free.
        EXPECT_LT(std::abs(error), 5.0 * std::sqrt(se * se + 1e-10))
            << what << ", channel " << ch << ": relative error " << error << ", standard error " << se;
    }
    return e.mean.x;
}

// The same closed form at every pixel.
inline std::vector<glm::dvec3> uniformImage(const glm::dvec3& value) {
    return std::vector<glm::dvec3>(size_t(kAnalyticSize) * size_t(kAnalyticSize), value);
}

}  // namespace fp::test
