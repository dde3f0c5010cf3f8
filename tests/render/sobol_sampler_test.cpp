// The integrators with the Sobol sampler (glsl/common/rng.glsl): still unbiased, and better than
// independent numbers. Stratified samples make each pixel's sample variance overstate the error of its
// mean, so these tests take their error bars from independent repetitions with different seeds (the
// scrambles are independent across seeds: randomised quasi-Monte Carlo), not from the sample variance.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "render_test_util.h"
#include "shader_variants.h"

namespace fp::test {
namespace {

// Mean and standard error of the whole-image means of `runs` renders with seeds 1 .. runs.
struct Repeated {
    glm::dvec3 mean{0.0}, standardError{0.0};
};

Repeated repeatedMean(Renderer& renderer, const Camera& camera, Integrator integrator, int size, int spp,
                      int maxDepth, Sampler sampler, int runs) {
    std::vector<glm::dvec3> means;
    for (int r = 1; r <= runs; ++r)
        means.push_back(glm::dvec3(
            estimate(renderScene(renderer, camera, integrator, size, spp, maxDepth, uint32_t(r), sampler))
                .mean));
    Repeated out;
    for (const glm::dvec3& m : means) out.mean += m / double(runs);
    glm::dvec3 var(0.0);
    for (const glm::dvec3& m : means) var += (m - out.mean) * (m - out.mean) / double(runs - 1);
    out.standardError = glm::sqrt(var / double(runs));
    return out;
}

// The analytic furnace (furnace_test.cpp): radiance 2 - 0.5^D after D bounces, for every integrator.
// Catches a sampler whose numbers are not uniform on [0, 1) (a missing scramble of one coordinate, a
// shuffle that repeats indices) and an integrator that draws its dimensions inconsistently. Depth 8 runs
// Russian roulette (from the fourth bounce), whose pair is coherent over 8x8 pixels (rng.glsl).
TEST(SobolSampler, FurnaceMatchesTheGeometricSeries) {
    ensureGlContext();
    Renderer renderer(furnaceBox(0.5f, 1.0f), testShaders());
    for (Integrator integrator : kAllIntegrators)
        for (int depth : {3, 8}) {
            Repeated r = repeatedMean(renderer, insideCamera(), integrator, 16, 16, depth, Sampler::Sobol, 8);
            const double expected = 2.0 - std::pow(0.5, depth);
            EXPECT_NEAR(r.mean.g, expected, 5.0 * r.standardError.g + 1e-5)
                << integratorName(integrator) << " depth " << depth << ": standard error "
                << r.standardError.g;
            // Depth 3 against its neighbours' 2 - 0.5^2 and 2 - 0.5^4 (0.0625 apart); depth 8, whose
            // neighbours are closer, against a roulette that ends every path at once (1.875).
            EXPECT_LT(r.standardError.g, depth == 3 ? 0.004 : 0.02)
                << integratorName(integrator) << " depth " << depth << ": too noisy to mean anything";
        }
}

// The Cornell box with the Sobol sampler converges to the image of independent numbers, block by block
// (the Sobol render's per-pixel variance overstates its error, so these z-scores are conservative), and
// at equal samples its error against a long render is smaller: the stratified pixel jitter and light
// points resolve the lamp's edge and the shadows' penumbrae faster than 1 / sqrt(N).
TEST(SobolSampler, CornellBoxConvergesToTheSameImageWithLessError) {
    ensureGlContext();
    Scene scene = builtinCornellBox();
    Renderer renderer(scene, testShaders());
    const Camera& camera = *scene.camera;
    Accumulation reference =
        renderScene(renderer, camera, Integrator::Nee, 32, 2048, 4, 100, Sampler::Independent);
    Accumulation sobol = renderScene(renderer, camera, Integrator::Nee, 32, 256, 4, 1, Sampler::Sobol);
    expectSameImage(sobol, reference, 4, 0.02f, "nee, Sobol against independent");

    auto squaredError = [&](const Accumulation& a) {
        Image ma = a.mean(), mr = reference.mean();
        double sum = 0.0;
        for (size_t i = 0; i < ma.pixels.size(); ++i) {
            glm::dvec3 d = glm::dvec3(ma.pixels[i]) - glm::dvec3(mr.pixels[i]);
            sum += glm::dot(d, d);
        }
        return sum / double(ma.pixels.size());
    };
    // At 32 spp the reference's own error is a small part of either.
    double errorSobol = 0.0, errorIndependent = 0.0;
    for (uint32_t seed = 1; seed <= 4; ++seed) {
        errorSobol +=
            squaredError(renderScene(renderer, camera, Integrator::Nee, 32, 32, 4, seed, Sampler::Sobol));
        errorIndependent += squaredError(
            renderScene(renderer, camera, Integrator::Nee, 32, 32, 4, seed, Sampler::Independent));
    }
    std::printf(
        "Cornell box, nee 32 spp, mean squared error against 2048 spp: Sobol %.3g, independent %.3g\n",
        errorSobol / 4.0, errorIndependent / 4.0);
    EXPECT_LT(errorSobol, 0.5 * errorIndependent);  // measured 0.18
}

// The pixel jitter and the first hit's light point are one 4D Sobol point (rng.glsl, kJointPairs):
// where the light a point receives changes across the pixel, padding the two pairs by independent
// shuffles leaves that interplay's error falling as N^-1/2. Direct light (depth 1) on the Cornell box at
// 64x64, 256 spp, away from the lamp (pixels with a neighbour brighter than 2 left out: the lamp's edge
// is pair 0's alone): the per-pixel variance across 2 seeds, each an independent randomisation (so no
// reference is needed). Measured (4 seeds): joint 0.044 of independent numbers', the padded pairs 0.10
// (0.48 of that); at 1024 spp the padded pairs' variance is 5.3 times the joint one's.
TEST(SobolSampler, JitterAndLightPointAreStratifiedTogether) {
    ensureGlContext();
    Scene scene = builtinCornellBox();
    const Camera& camera = *scene.camera;
    const int size = 64, spp = 256, seeds = 2;
    auto seedVariance = [&](Renderer& renderer, Sampler sampler) {
        std::vector<Image> images;
        for (uint32_t seed = 1; seed <= uint32_t(seeds); ++seed)
            images.push_back(
                renderScene(renderer, camera, Integrator::Nee, size, spp, 1, seed, sampler).mean());
        auto grey = [&](int i, int x, int y) {
            const glm::vec3& p = images[size_t(i)].pixels[size_t(y) * size_t(size) + size_t(x)];
            return (double(p.r) + double(p.g) + double(p.b)) / 3.0;
        };
        auto mean = [&](int x, int y) {
            double m = 0.0;
            for (int i = 0; i < seeds; ++i) m += grey(i, x, y) / double(seeds);
            return m;
        };
        double sum = 0.0;
        int pixels = 0;
        for (int y = 1; y + 1 < size; ++y)
            for (int x = 1; x + 1 < size; ++x) {
                bool nearLamp = false;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) nearLamp = nearLamp || mean(x + dx, y + dy) > 2.0;
                if (nearLamp) continue;
                const double m = mean(x, y);
                for (int i = 0; i < seeds; ++i)
                    sum += (grey(i, x, y) - m) * (grey(i, x, y) - m) / double(seeds - 1);
                ++pixels;
            }
        return sum / double(pixels);
    };
    Renderer renderer(scene, testShaders());
    Renderer padded(scene, paddedSobolPairsShaders());
    const double joint = seedVariance(renderer, Sampler::Sobol);
    const double independent = seedVariance(renderer, Sampler::Independent);
    const double paddedVariance = seedVariance(padded, Sampler::Sobol);
    std::printf(
        "direct light, 256 spp, variance away from the lamp: joint %.3g, padded %.3g, independent %.3g\n",
        joint, paddedVariance, independent);
    EXPECT_LT(joint, 0.07 * independent);
    EXPECT_LT(joint, 0.7 * paddedVariance) << "pairs 0 and 1 no better together than padded";
}

// Blue noise (rng.glsl): neighbouring pixels' errors cancel. Direct light in the Cornell box at 1 spp,
// rows below the lamp (whose edge pixels would dominate any measure): the mean error of a 4x4 block of
// pixels, against the image's per-pixel error. Independent errors give sqrt(16) = 4 times less in
// the block mean (ratio 1, which independent numbers must show: the control); errors that cancel give
// less still (about 0.6 here; less clearly at more samples, where the reference's own noise and
// the pixels' edges weigh more). 4 seeds x 768 blocks: the ratio's standard error is about 2 %.
TEST(SobolSampler, NeighboursErrorsCancel) {
    ensureGlContext();
    Scene scene = builtinCornellBox();
    Renderer renderer(scene, testShaders());
    const Camera& camera = *scene.camera;
    const int size = 128, rows = 96, block = 4;
    Image reference =
        renderScene(renderer, camera, Integrator::Nee, size, 1024, 1, 100, Sampler::Independent).mean();
    auto blockRatio = [&](Sampler sampler) {
        double pixelSum = 0.0, blockSum = 0.0;
        for (uint32_t seed = 1; seed <= 4; ++seed) {
            Image image = renderScene(renderer, camera, Integrator::Nee, size, 1, 1, seed, sampler).mean();
            auto error = [&](int x, int y) {
                size_t i = size_t(y) * size_t(size) + size_t(x);
                glm::dvec3 d = glm::dvec3(image.pixels[i]) - glm::dvec3(reference.pixels[i]);
                return (d.r + d.g + d.b) / 3.0;
            };
            for (int by = size - rows; by < size; by += block)  // row 0 is the top
                for (int bx = 0; bx < size; bx += block) {
                    double mean = 0.0;
                    for (int y = by; y < by + block; ++y)
                        for (int x = bx; x < bx + block; ++x) {
                            mean += error(x, y) / double(block * block);
                            pixelSum += error(x, y) * error(x, y);
                        }
                    blockSum += mean * mean;
                }
        }
        return std::sqrt(blockSum * double(block * block * block * block) / pixelSum);
    };
    double sobol = blockRatio(Sampler::Sobol), independent = blockRatio(Sampler::Independent);
    std::printf("4x4 block-mean error / per-pixel error / (1/4): Sobol %.3f, independent %.3f\n", sobol,
                independent);
    EXPECT_GT(independent, 0.85) << "the measure does not see independent errors as independent";
    EXPECT_LT(sobol, 0.8) << "neighbouring pixels' errors do not cancel";
}

// bdpt's light subpaths land anywhere on the screen; with the camera stream's scramble shared by all
// pixels, all pixels' light paths of one sample would be one stratified set whose splats pile up in
// bright specks (relative MSE 2.2x that of independent numbers). They keep per-pixel scrambles
// (rng.glsl, rand2), which makes bdpt's error smaller than with independent numbers. The Cornell box at
// 128x128 (two 64x64 tiles of the blue-noise Z-order across), 8 spp, against 512 spp of nee; the mean of
// squared error over (reference^2 + 0.01), which weighs the dark pixels the specks fall on.
TEST(SobolSampler, BdptLightSubpathsDoNotPileUp) {
    ensureGlContext();
    Scene scene = builtinCornellBox();
    Renderer renderer(scene, testShaders());
    const Camera& camera = *scene.camera;
    const int size = 128;
    Image reference = renderScene(renderer, camera, Integrator::Nee, size, 512, 5, 50).mean();
    auto relativeError = [&](Sampler sampler) {
        Image image = renderScene(renderer, camera, Integrator::Bdpt, size, 8, 5, 1, sampler).mean();
        double sum = 0.0;
        for (size_t i = 0; i < image.pixels.size(); ++i)
            for (int c = 0; c < 3; ++c) {
                double r = reference.pixels[i][c], d = image.pixels[i][c] - r;
                sum += d * d / (r * r + 0.01);
            }
        return sum / double(3 * image.pixels.size());
    };
    double sobol = relativeError(Sampler::Sobol), independent = relativeError(Sampler::Independent);
    std::printf("bdpt 8 spp, relative MSE: Sobol %.4g, independent %.4g\n", sobol, independent);
    EXPECT_LT(sobol, independent);
}

}  // namespace
}  // namespace fp::test
