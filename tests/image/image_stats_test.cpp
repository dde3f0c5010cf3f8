#include "image/image_stats.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/error.h"

namespace fp {
namespace {

// 3x2:  row 0: (1,0,0) (2,0,0) (3,0,6)
//       row 1: (0,4,0) (0,8,0) (0,12,6)
Image sample() {
    Image image(3, 2);
    image.at(0, 0) = {1, 0, 0};
    image.at(1, 0) = {2, 0, 0};
    image.at(2, 0) = {3, 0, 6};
    image.at(0, 1) = {0, 4, 0};
    image.at(1, 1) = {0, 8, 0};
    image.at(2, 1) = {0, 12, 6};
    return image;
}

TEST(ImageStats, MeanColorOfWholeImage) {
    // Sums (6, 24, 12) over 6 pixels.
    EXPECT_EQ(meanColor(sample()), glm::dvec3(1.0, 4.0, 2.0));
}

TEST(ImageStats, MeanColorOfRectangle) {
    // Columns 1-2, both rows: sums (5, 20, 12) over 4 pixels.
    EXPECT_EQ(meanColor(sample(), {1, 0, 2, 2}), glm::dvec3(1.25, 5.0, 3.0));
    // The single bottom-left pixel: rows count from the top.
    EXPECT_EQ(meanColor(sample(), {0, 1, 1, 1}), glm::dvec3(0.0, 4.0, 0.0));
}

TEST(ImageStats, MeanAccumulatesInDouble) {
    // 2^24 + 1 is not a float; a float running sum of 2^24 ones followed by more ones stalls at 2^24.
    Image image(4096, 4097);
    for (glm::vec3& p : image.pixels) p = glm::vec3(1.0f);
    EXPECT_EQ(meanColor(image), glm::dvec3(1.0));
}

TEST(ImageStats, BadRectanglesAndEmptyImagesThrow) {
    const Image image = sample();
    EXPECT_THROW(meanColor(image, {0, 0, 0, 1}), Error);
    EXPECT_THROW(meanColor(image, {-1, 0, 1, 1}), Error);
    EXPECT_THROW(meanColor(image, {2, 0, 2, 1}), Error);
    EXPECT_THROW(meanColor(image, {0, 1, 1, 2}), Error);
    EXPECT_THROW(meanColor(Image()), Error);
}

TEST(ImageStats, RmseOverAllChannels) {
    Image a(2, 1), b(2, 1);
    b.at(0, 0) = {3, 0, 0};
    b.at(1, 0) = {0, 0, -4};
    // sqrt((9 + 16) / 6)
    EXPECT_DOUBLE_EQ(rmse(a, b), std::sqrt(25.0 / 6.0));
    EXPECT_DOUBLE_EQ(rmse(b, a), std::sqrt(25.0 / 6.0));
    EXPECT_EQ(rmse(sample(), sample()), 0.0);
}

TEST(ImageStats, RmseRejectsSizeMismatch) {
    EXPECT_THROW(rmse(Image(2, 3), Image(3, 2)), Error);
    EXPECT_THROW(rmse(Image(2, 2), Image(2, 3)), Error);
    EXPECT_THROW(rmse(Image(), Image()), Error);
}

TEST(ImageStats, AllFinite) {
    Image image = sample();
    EXPECT_TRUE(allFinite(image));
    EXPECT_TRUE(allFinite(Image()));
    for (float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                      -std::numeric_limits<float>::infinity()}) {
        Image broken = sample();
        broken.at(2, 1).g = bad;
        EXPECT_FALSE(allFinite(broken)) << bad;
    }
    image.at(0, 0) =
        glm::vec3(std::numeric_limits<float>::max(), std::numeric_limits<float>::denorm_min(), -0.0f);
    EXPECT_TRUE(allFinite(image));
}

}  // namespace
}  // namespace fp
