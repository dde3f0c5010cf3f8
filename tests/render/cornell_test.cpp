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

// z-scores of the difference of two independent estimates over the bands of `width` rows, then of
// `width` columns, spanning the image: a bias of one sign over a band (light sampling's density wrong
// at grazing angles to the lamp shows on the walls' upper rows and the ceiling's) adds up over the
// band's blocks, while their noise averages out, so a band sees a bias sqrt(blocks) times smaller than
// any one block does.
std::vector<float> bandZScores(const Accumulation& a, const Accumulation& b, int width) {
    std::vector<float> z;
    for (int offset = 0; offset + width <= a.width; offset += width)
        for (bool rows : {true, false}) {
            ImageEstimate ea =
                rows ? estimate(a, 0, offset, a.width, width) : estimate(a, offset, 0, width, a.height);
            ImageEstimate eb =
                rows ? estimate(b, 0, offset, b.width, width) : estimate(b, offset, 0, width, b.height);
            for (int c = 0; c < 3; ++c)
                z.push_back((ea.mean[c] - eb.mean[c]) / std::hypot(ea.standardError[c], eb.standardError[c]));
        }
    return z;
}

class CornellBoxSeeds : public CornellBoxSuite, public ::testing::WithParamInterface<uint32_t> {};

// What the comparisons catch, each tried on a copy of the shaders (FP_RENDER_TEST_SHADERS), seeds 1-3:
// light sampling's density without the cosine at the lamp (lights.glsl sampleLight, dist2 / cosLight
// -> dist2; with or without the same change in lightPdf): 4 x 4 blocks up to 35 standard errors off,
// bands up to 79. The cosine clamped at 0.3 (a bias at grazing angles only): blocks up to 6.7, bands
// up to 6.6, the whole image beyond 5. Not caught: the cosine dropped in lightPdf alone, which only
// re-weights (MIS) the lamp hits that BSDF sampling finds; here they carry so little of a small lamp's
// light on diffuse walls that the bands move by about 0.05 standard errors: no comparison of this
// scene at this cost can see it. The seed is a parameter so that other seeds can be run.
TEST_P(CornellBoxSeeds, AllIntegratorsConvergeToTheSameImage) {
    const uint32_t seed = GetParam();
    auto render = [seed](Integrator integrator, int spp) {
        return renderScene(*renderer_, *scene_->camera, integrator, kSize, spp, kDepth, seed);
    };
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
    // Bands of 4 rows and of 4 columns, three channels: 48 z-scores, each beyond 4 by chance with
    // probability 6e-5, so all 48 pass by chance with probability 0.997.
    for (float v : bandZScores(nee, bsdf, 4))
        EXPECT_LT(std::abs(v), 4.0f) << "a band of blocks biased one way";
    EXPECT_EQ(nee.droppedSamples() + bsdf.droppedSamples() + naive.droppedSamples(), 0u);
}

INSTANTIATE_TEST_SUITE_P(Seed, CornellBoxSeeds, ::testing::Values(1u));

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
    // Sample k at pixel p draws the same random numbers however the passes are split: fixed counts, and
    // the counts chosen from the passes' times (render/pass_pacer.h), which vary from run to run.
    RenderSettings s;
    s.width = s.height = kSize;
    s.maxDepth = kDepth;
    s.seed = 9;
    s.samplesPerPass = 1;
    renderer_->configure(s, *scene_->camera);
    renderer_->render(20);
    Accumulation onePerPass = renderer_->readback();
    EXPECT_EQ(renderer_->passes(), 20);
    for (int perPass : {4, RenderSettings::kAutoSamplesPerPass}) {
        SCOPED_TRACE(samplesPerPassName(perPass));
        s.samplesPerPass = perPass;
        renderer_->configure(s, *scene_->camera);
        renderer_->render(20);
        // This small image's passes are fast: 1 sample, then as many as allowed (1 + 16 + 3).
        if (perPass == RenderSettings::kAutoSamplesPerPass) {
            EXPECT_LE(renderer_->passes(), 6);
        }
        Accumulation other = renderer_->readback();
        EXPECT_EQ(renderer_->samples(), 20);
        EXPECT_EQ(
            std::memcmp(onePerPass.sum.data(), other.sum.data(), onePerPass.sum.size() * sizeof(glm::vec4)),
            0);
    }
}

TEST_F(CornellBox, RegeneratedPathsAreTheSamplesTracedOneByOne) {
    // Without guides, nee's pass starts a pixel's next sample as soon as its path ends (path
    // regeneration, passes/trace.frag.glsl); with them it traces the samples one by one through
    // radiance(). Same samples, same bits, with many samples in a pass (their paths interleaved).
    RenderSettings s;
    s.width = s.height = kSize;
    s.maxDepth = kDepth;
    s.seed = 5;
    s.samplesPerPass = RenderSettings::kMaxSamplesPerPass;
    renderer_->configure(s, *scene_->camera);
    renderer_->render(2 * s.samplesPerPass);
    Accumulation regenerated = renderer_->readback();
    s.guides = true;
    renderer_->configure(s, *scene_->camera);
    renderer_->render(2 * s.samplesPerPass);
    Accumulation oneByOne = renderer_->readback();
    ASSERT_EQ(regenerated.sum.size(), oneByOne.sum.size());
    EXPECT_EQ(
        std::memcmp(regenerated.sum.data(), oneByOne.sum.data(), regenerated.sum.size() * sizeof(glm::vec4)),
        0);
    EXPECT_EQ(std::memcmp(regenerated.squares.data(), oneByOne.squares.data(),
                          regenerated.squares.size() * sizeof(glm::vec4)),
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
