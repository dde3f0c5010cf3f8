// The Cornell box through every integrator: they estimate the same integral, so their images must
// agree within the noise each one measures for itself; and a render is a pure function of its seed.
#include <gtest/gtest.h>

#include <cstring>

#include "render_test_util.h"
#include "scene/builtin_scene.h"

namespace fp::test {
namespace {

const int kSize = 32;
const int kDepth = 4;

class CornellBox : public CornellBoxSuite {
  protected:
    static Accumulation render(Integrator integrator, int spp, int depth = kDepth, uint32_t seed = 1) {
        return renderScene(*renderer_, *scene_->camera, integrator, kSize, spp, depth, seed);
    }
};

void expectSameMean(const Accumulation& a, const Accumulation& b, const char* what) {
    ImageEstimate ea = estimate(a), eb = estimate(b);
    for (int c = 0; c < 3; ++c) {
        float se =
            std::sqrt(ea.standardError[c] * ea.standardError[c] + eb.standardError[c] * eb.standardError[c]);
        EXPECT_NEAR(ea.mean[c], eb.mean[c], 5.0f * se) << what << ", channel " << c;
        EXPECT_LT(se, 0.02f * ea.mean[c])
            << what << ": the comparison must be sharp enough to mean something";
    }
}

TEST_F(CornellBox, AllIntegratorsConvergeToTheSameImage) {
    Accumulation nee = render(Integrator::Nee, 256);
    Accumulation bsdf = render(Integrator::Bsdf, 1024);
    Accumulation naive = render(Integrator::Naive, 1024);
    expectSameMean(nee, bsdf, "nee vs bsdf");
    expectSameMean(nee, naive, "nee vs naive");

    // Per region: 8x8 blocks of 4x4 pixels, three channels. Independent estimates give roughly standard
    // normal z-scores: none beyond 5, and a mean square near 1. Only nee against bsdf: the naive
    // estimator's samples are so heavy-tailed (rare light hits) at this count that its per-block
    // variance estimates are unreliable (measured: z up to 7 in random places, always naive-low).
    std::vector<float> z = blockZScores(nee, bsdf, 4);
    ASSERT_GT(z.size(), 150u);
    expectZScoresOfNoise(z);
    EXPECT_EQ(nee.droppedSamples() + bsdf.droppedSamples() + naive.droppedSamples(), 0u);
}

TEST_F(CornellBox, EachIntegratorHasLessNoiseThanTheOneBefore) {
    ImageEstimate nee = estimate(render(Integrator::Nee, 256));
    ImageEstimate bsdf = estimate(render(Integrator::Bsdf, 256));
    ImageEstimate naive = estimate(render(Integrator::Naive, 256));
    EXPECT_LT(nee.standardError.g * 1.5f, bsdf.standardError.g);
    EXPECT_LT(bsdf.standardError.g, naive.standardError.g);
}

TEST_F(CornellBox, SameSeedSameImageBitForBit) {
    Accumulation a = render(Integrator::Nee, 8, kDepth, 42);
    Accumulation b = render(Integrator::Nee, 8, kDepth, 42);
    ASSERT_EQ(a.sum.size(), b.sum.size());
    EXPECT_EQ(std::memcmp(a.sum.data(), b.sum.data(), a.sum.size() * sizeof(glm::vec4)), 0);
    EXPECT_EQ(std::memcmp(a.squares.data(), b.squares.data(), a.squares.size() * sizeof(glm::vec4)), 0);
}

TEST_F(CornellBox, DifferentSeedDifferentNoiseSameMean) {
    Accumulation a = render(Integrator::Nee, 32, kDepth, 1);
    Accumulation b = render(Integrator::Nee, 32, kDepth, 2);
    size_t differing = 0;
    for (size_t i = 0; i < a.sum.size(); ++i) differing += glm::vec3(a.sum[i]) != glm::vec3(b.sum[i]);
    EXPECT_GT(differing, a.sum.size() * 9 / 10);
    ImageEstimate ea = estimate(a), eb = estimate(b);
    for (int c = 0; c < 3; ++c) {
        float se =
            std::sqrt(ea.standardError[c] * ea.standardError[c] + eb.standardError[c] * eb.standardError[c]);
        EXPECT_NEAR(ea.mean[c], eb.mean[c], 5.0f * se);
    }
}

TEST_F(CornellBox, SamplesPerPassDoesNotChangeTheImage) {
    // Sample k at pixel p draws the same random numbers however the passes are split.
    RenderSettings s;
    s.width = s.height = kSize;
    s.maxDepth = kDepth;
    s.seed = 9;
    s.samplesPerPass = 1;
    renderer_->configure(s, *scene_->camera);
    renderer_->render(6);
    Accumulation onePerPass = renderer_->readback();
    s.samplesPerPass = 4;
    renderer_->configure(s, *scene_->camera);
    renderer_->render(6);
    Accumulation fourPerPass = renderer_->readback();
    EXPECT_EQ(
        std::memcmp(onePerPass.sum.data(), fourPerPass.sum.data(), onePerPass.sum.size() * sizeof(glm::vec4)),
        0);
}

TEST_F(CornellBox, EveryPixelGetsEverySampleItWasAskedFor) {
    // Guards the per-pass limit (RenderSettings::kMaxSamplesPerPass): llvmpipe ends long shader loops early.
    Accumulation acc = render(Integrator::Nee, 96);
    for (const glm::vec4& s : acc.sum) ASSERT_EQ(s.w, 96.0f);
}

TEST_F(CornellBox, DepthZeroShowsOnlyTheLightExactly) {
    Accumulation acc = render(Integrator::Nee, 16, 0);
    Image mean = acc.mean();
    const glm::vec3 le(17.0f, 12.0f, 4.0f);
    int lightPixels = 0;
    for (const glm::vec3& p : mean.pixels) {
        // Each sample is 0 or exactly Le, so a pixel is Le times the fraction of samples on the light.
        float f = p.x / le.x;
        EXPECT_NEAR(p.y, f * le.y, 1e-4f);
        EXPECT_NEAR(p.z, f * le.z, 1e-4f);
        EXPECT_NEAR(f * 16.0f, std::round(f * 16.0f), 1e-3f);
        lightPixels += f == 1.0f;
    }
    EXPECT_GE(lightPixels, 2);  // the light (about 4x3 pixels here) is in view from the published camera
}

}  // namespace
}  // namespace fp::test
