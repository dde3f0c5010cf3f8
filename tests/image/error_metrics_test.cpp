// The error metrics of the study, `fragpath compare` and `fragpath realtime` on images whose answers are
// known in closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "image/error_metrics.h"
#include "image/image_stats.h"

namespace fp {
namespace {

// A smooth gradient with some texture, so that SSIM's variances are not all zero.
Image pattern(int w, int h) {
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            image.at(x, y) = glm::vec3(0.05f * x, 0.5f + 0.4f * std::sin(0.7f * float(x + y)), 0.03f * y);
    return image;
}

TEST(RelativeMse, FollowsItsDefinition) {
    Image reference(2, 1), estimate(2, 1);
    reference.at(0, 0) = glm::vec3(1.0f, 0.0f, 2.0f);
    reference.at(1, 0) = glm::vec3(0.5f);
    estimate.at(0, 0) = glm::vec3(1.5f, 0.1f, 2.0f);
    estimate.at(1, 0) = glm::vec3(0.5f, 0.5f, 0.0f);
    double eps = kRelMseEpsilon;
    double expected = (0.25 / (1 + eps) + 0.01 / eps + 0.0 + 0.0 + 0.0 + 0.25 / (0.25 + eps)) / 6.0;
    EXPECT_NEAR(relativeMse(estimate, reference), expected, 1e-6 * expected);
    EXPECT_EQ(relativeMse(reference, reference), 0.0);
}

TEST(ExpectedRelativeMse, IsVarianceOverTheRelativeScale) {
    Image variance(1, 1), reference(1, 1);
    variance.at(0, 0) = glm::vec3(0.01f, 0.0f, 0.04f);
    reference.at(0, 0) = glm::vec3(1.0f, 5.0f, 0.0f);
    double expected = (0.01 / 1.01 + 0.0 + 0.04 / 0.01) / 3.0;
    EXPECT_NEAR(expectedRelativeMse(variance, reference), expected, 1e-6 * expected);
}

TEST(Rmse, OfKnownImages) {
    Image a(4, 4), b(4, 4);
    for (auto& p : b.pixels) p = glm::vec3(0.5f);
    EXPECT_NEAR(rmse(a, b), 0.5, 1e-12);
    b.at(0, 0) =
        glm::vec3(0.5f, 0.5f, 4.5f);  // one channel of 48 off by 4 more: sqrt((47*0.25 + 20.25) / 48)
    EXPECT_NEAR(rmse(a, b), std::sqrt((47 * 0.25 + 20.25) / 48.0), 1e-6);
}

TEST(Ssim, IsOneForTheSameImageAndFallsWithNoise) {
    Image image = pattern(24, 20);
    EXPECT_NEAR(ssim(image, image), 1.0, 1e-12);
    Image noisy = image;
    uint32_t state = 12345u;
    for (auto& p : noisy.pixels) {
        state = state * 1664525u + 1013904223u;
        p += glm::vec3(0.3f * (float(state >> 8) / 16777216.0f - 0.5f));
    }
    double s = ssim(noisy, image);
    EXPECT_LT(s, 0.99);
    EXPECT_GT(s, 0.0);
    // Symmetric in its arguments (eq. 13 of Wang et al. is).
    EXPECT_NEAR(ssim(image, noisy), s, 1e-12);
}

TEST(Ssim, OfAConstantImageMatchesTheLuminanceTerm) {
    // Two flat images: the variances vanish, so SSIM reduces to (2 mx my + C1) / (mx^2 + my^2 + C1).
    Image a(16, 16), b(16, 16);
    for (auto& p : a.pixels) p = glm::vec3(1.0f);  // display luma 1
    for (auto& p : b.pixels) p = glm::vec3(0.0f);  // display luma 0
    double c1 = 1e-4;
    EXPECT_NEAR(ssim(a, b), c1 / (1.0 + c1), 1e-9);
}

TEST(Metrics, RejectMismatchedOrTooSmallImages) {
    EXPECT_THROW(relativeMse(Image(4, 4), Image(4, 5)), Error);
    EXPECT_THROW(ssim(Image(16, 16), Image(16, 15)), Error);
    EXPECT_THROW(ssim(Image(8, 8), Image(8, 8)), Error);
}

}  // namespace
}  // namespace fp
