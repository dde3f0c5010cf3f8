// bench/caustic_study.h: the parts of the caustic study that need no GL context.
#include <gtest/gtest.h>

#include "bench/caustic_study.h"
#include "scene/procedural.h"

namespace fp::bench {
namespace {

TEST(CausticStudy, SettingsAreTheStudysSizeDepthAndSeed) {
    RenderSettings s = causticStudySettings(Integrator::Bdpt, 99);
    EXPECT_EQ(s.width, 24);
    EXPECT_EQ(s.height, 24);
    EXPECT_EQ(s.maxDepth, 5);
    EXPECT_EQ(s.seed, 99u);
    EXPECT_EQ(s.integrator, Integrator::Bdpt);
    EXPECT_EQ(s.samplesPerPass, 16);
    EXPECT_EQ(causticStudySettings(Integrator::Nee, 7).integrator, Integrator::Nee);
    // The region under the sphere is given for that size.
    const PixelRect r = kCausticUnderSphere;
    EXPECT_LE(r.x + r.width, s.width);
    EXPECT_LE(r.y + r.height, s.height);
}

TEST(CausticStudy, CropKeepsTheRectanglesPixels) {
    Image image(5, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 5; ++x) image.at(x, y) = glm::vec3(float(x), float(y), 0.0f);
    Image crop = cropImage(image, PixelRect{1, 2, 3, 2});
    ASSERT_EQ(crop.width, 3);
    ASSERT_EQ(crop.height, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x) EXPECT_EQ(crop.at(x, y), glm::vec3(float(x + 1), float(y + 2), 0.0f));
}

// Two samples per pixel: G values 1 and 3 have variance 2 and a mean of variance 1; R and B differ, so
// that the region's figure is seen to be the G channel's.
TEST(CausticStudy, RegionVarianceSumsTheGreenVarianceOfTheMean) {
    Accumulation acc;
    acc.width = 3;
    acc.height = 2;
    for (int i = 0; i < 6; ++i) {
        float scale = i % 3 == 0 ? 1.0f : 2.0f;  // column 0: G variance of the mean 1, else 4
        acc.sum.push_back(glm::vec4(0.0f, 4.0f * scale, 2.0f, 2.0f));
        acc.squares.push_back(glm::vec4(0.0f, 10.0f * scale * scale, 8.0f, 0.0f));
        acc.counters.push_back(glm::vec4(0.0f));
    }
    EXPECT_NEAR(regionVariance(acc, PixelRect{0, 0, 1, 2}), 2.0, 1e-6);  // column 0: 1 + 1
    EXPECT_NEAR(regionVariance(acc, PixelRect{0, 1, 3, 1}), 9.0, 1e-6);  // row 1: 1 + 4 + 4
    EXPECT_NEAR(regionVariance(acc, PixelRect{0, 0, 3, 2}), 18.0, 1e-6);
}

}  // namespace
}  // namespace fp::bench
