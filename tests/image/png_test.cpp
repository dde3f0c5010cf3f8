#include "image/png.h"

#include <gtest/gtest.h>
#include <stb_image.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "image/test_files.h"
#include "image/tone_map.h"

namespace fp {
namespace {

using test::TempDir;

struct Rgb8 {
    int r, g, b;
    bool operator==(const Rgb8& o) const { return r == o.r && g == o.g && b == o.b; }
};
std::ostream& operator<<(std::ostream& out, const Rgb8& c) {
    return out << "(" << c.r << ", " << c.g << ", " << c.b << ")";
}

// Writes `image` as PNG through writeImage and decodes it again with stb_image.
std::vector<Rgb8> roundTripPng(const Image& image, const DisplaySettings& display) {
    TempDir dir;
    const std::string path = dir.file("out.png");
    writeImage(path, image, display);
    int width = 0, height = 0, channels = 0;
    stbi_uc* data = stbi_load(path.c_str(), &width, &height, &channels, 3);
    if (!data) {
        ADD_FAILURE() << "stb_image cannot read " << path << ": " << stbi_failure_reason();
        return {};
    }
    EXPECT_EQ(width, image.width);
    EXPECT_EQ(height, image.height);
    EXPECT_EQ(channels, 3);  // RGB, no alpha
    std::vector<Rgb8> pixels;
    for (int i = 0; i < width * height; ++i)
        pixels.push_back({data[3 * i], data[3 * i + 1], data[3 * i + 2]});
    stbi_image_free(data);
    return pixels;
}

Rgb8 codesFor(glm::vec3 linear, DisplaySettings display) {
    Image image(1, 1);
    image.at(0, 0) = linear;
    const std::vector<Rgb8> pixels = roundTripPng(image, display);
    return pixels.empty() ? Rgb8{-1, -1, -1} : pixels[0];
}

struct Case {
    ToneMap toneMap;
    float exposure;
    glm::vec3 linear;
    Rgb8 expected;
};

// Expected codes worked out in double precision (outside this code base) from the definitions: 2^exposure
// scaling, the curve, the IEC 61966-2-1 sRGB OETF, round(255 v). E.g. clamp 0.5 -> 1.055*0.5^(1/2.4)-0.055 =
// 0.73536 -> 187.52 -> 188; reinhard 3 -> 0.75 -> 0.88083 -> 224.61 -> 225; aces 1 -> 2.54/3.16 =
// 0.80380 -> 0.90823 -> 231.60 -> 232. Inputs are chosen away from rounding ties.
const Case kCases[] = {
    {ToneMap::Clamp, 0.0f, {0.0f, 0.001f, 0.18f}, {0, 3, 118}},
    {ToneMap::Clamp, 0.0f, {0.5f, 1.0f, 2.0f}, {188, 255, 255}},
    {ToneMap::Clamp, 1.0f, {0.25f, 0.05f, 0.5f}, {188, 89, 255}},
    {ToneMap::Clamp, -1.0f, {1.0f, 0.25f, 0.5f}, {188, 99, 137}},
    {ToneMap::Clamp, -2.0f, {3.0f, 0.05f, 100.0f}, {225, 29, 255}},
    {ToneMap::Reinhard, 0.0f, {0.18f, 1.0f, 3.0f}, {109, 188, 225}},
    {ToneMap::Reinhard, 0.0f, {100.0f, 0.5f, 0.25f}, {254, 156, 124}},
    {ToneMap::Reinhard, 1.0f, {1.0f, 0.18f, 16.0f}, {213, 141, 252}},
    {ToneMap::Reinhard, -2.0f, {4.0f, 100.0f, 0.002f}, {188, 251, 2}},
    {ToneMap::Aces, 0.0f, {0.18f, 0.5f, 1.0f}, {141, 206, 232}},
    {ToneMap::Aces, 0.0f, {3.0f, 16.0f, 1e30f}, {250, 255, 255}},
    {ToneMap::Aces, 1.0f, {0.18f, 3.0f, 0.05f}, {188, 254, 99}},
    {ToneMap::Aces, -1.0f, {1.0f, 0.5f, 0.25f}, {206, 165, 115}},
    {ToneMap::Aces, -2.0f, {0.002f, 100.0f, 2.0f}, {0, 255, 206}},
    {ToneMap::Aces, 2.0f, {0.05f, 0.01f, 0.0f}, {149, 49, 0}},
};

TEST(Png, KnownValuesGiveExpectedSrgbCodes) {
    for (const Case& c : kCases) {
        const DisplaySettings display{c.exposure, c.toneMap};
        EXPECT_EQ(codesFor(c.linear, display), c.expected)
            << toneMapName(c.toneMap) << " exposure " << c.exposure << " input (" << c.linear.r << ", "
            << c.linear.g << ", " << c.linear.b << ")";
    }
}

TEST(Png, NanBecomesBlackAndInfinityWhiteUnderEveryToneMap) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    for (ToneMap toneMap : {ToneMap::Clamp, ToneMap::Reinhard, ToneMap::Aces}) {
        for (float exposure : {-3.0f, 0.0f, 3.0f}) {
            const DisplaySettings display{exposure, toneMap};
            SCOPED_TRACE(std::string(toneMapName(toneMap)) + " exposure " + std::to_string(exposure));
            EXPECT_EQ(codesFor({nan, nan, nan}, display), (Rgb8{0, 0, 0}));
            EXPECT_EQ(codesFor({nan, 0.5f, 0.5f}, display), (Rgb8{0, 0, 0}));
            EXPECT_EQ(codesFor({nan, inf, 1.0f}, display), (Rgb8{0, 0, 0}));
            EXPECT_EQ(codesFor({inf, inf, inf}, display), (Rgb8{255, 255, 255}));
            EXPECT_EQ(codesFor({inf, 0.0f, 0.0f}, display), (Rgb8{255, 255, 255}));
            EXPECT_EQ(codesFor({-inf, -inf, -inf}, display), (Rgb8{0, 0, 0}));
            EXPECT_EQ(codesFor({-1.0f, -1.0f, -1e30f}, display), (Rgb8{0, 0, 0}));
        }
    }
}

TEST(Png, OverflowingExposureStaysDefined) {
    // 2^200 is +inf in float: 0 * inf is NaN (shown as 0) and any positive value saturates.
    for (ToneMap toneMap : {ToneMap::Clamp, ToneMap::Reinhard, ToneMap::Aces}) {
        EXPECT_EQ(codesFor({0.0f, 1e-30f, 1e30f}, {200.0f, toneMap}), (Rgb8{0, 255, 255}))
            << toneMapName(toneMap);
        EXPECT_EQ(codesFor({1e30f, 1.0f, 0.0f}, {-200.0f, toneMap}), (Rgb8{0, 0, 0})) << toneMapName(toneMap);
    }
}

TEST(Png, TopRowIsStoredFirst) {
    Image image(2, 2);
    image.at(0, 0) = glm::vec3(1.0f, 0.0f, 0.0f);
    image.at(1, 0) = glm::vec3(0.0f, 1.0f, 0.0f);
    image.at(0, 1) = glm::vec3(0.0f, 0.0f, 1.0f);
    image.at(1, 1) = glm::vec3(1.0f);
    const std::vector<Rgb8> pixels = roundTripPng(image, {});
    ASSERT_EQ(pixels.size(), 4u);
    EXPECT_EQ(pixels[0], (Rgb8{255, 0, 0}));
    EXPECT_EQ(pixels[1], (Rgb8{0, 255, 0}));
    EXPECT_EQ(pixels[2], (Rgb8{0, 0, 255}));
    EXPECT_EQ(pixels[3], (Rgb8{255, 255, 255}));
}

// An independent double-precision evaluation of the documented pipeline.
int referenceCode(double x, double exposure, ToneMap toneMap) {
    x *= std::pow(2.0, exposure);
    if (toneMap == ToneMap::Reinhard) x = x / (1.0 + x);
    if (toneMap == ToneMap::Aces) x = (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14);
    x = std::min(std::max(x, 0.0), 1.0);
    const double v = x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
    return int(std::floor(v * 255.0 + 0.5));
}

TEST(Png, MatchesDoublePrecisionReferenceAwayFromRoundingTies) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> logValue(-12.0f, 6.0f);
    for (ToneMap toneMap : {ToneMap::Clamp, ToneMap::Reinhard, ToneMap::Aces}) {
        for (float exposure : {-2.0f, 0.0f, 1.5f}) {
            Image image(64, 4);
            for (glm::vec3& p : image.pixels) {
                p = {std::exp2(logValue(random)), std::exp2(logValue(random)), std::exp2(logValue(random))};
            }
            const std::vector<Rgb8> pixels = roundTripPng(image, {exposure, toneMap});
            ASSERT_EQ(pixels.size(), image.pixels.size());
            int compared = 0;
            for (size_t i = 0; i < pixels.size(); ++i) {
                const int got[3] = {pixels[i].r, pixels[i].g, pixels[i].b};
                for (int c = 0; c < 3; ++c) {
                    const double x = image.pixels[i][c];
                    // Skip inputs within 1e-3 code of a tie, where float and double may round apart.
                    const double scaled = x * std::pow(2.0, exposure);
                    const double nudge = 1e-4 * scaled;
                    if (referenceCode(x - nudge, exposure, toneMap) !=
                        referenceCode(x + nudge, exposure, toneMap)) {
                        continue;
                    }
                    EXPECT_EQ(got[c], referenceCode(x, exposure, toneMap))
                        << toneMapName(toneMap) << " exposure " << exposure << " x " << x;
                    ++compared;
                }
            }
            EXPECT_GT(compared, 700);
        }
    }
}

TEST(Png, ToDisplay8MatchesTheStoredFile) {
    Image image(5, 3);
    for (size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = glm::vec3(0.07f * float(i), 0.3f, 2.0f);
    const DisplaySettings display{0.5f, ToneMap::Aces};
    const std::vector<std::uint8_t> codes = toDisplay8(image, display);
    const std::vector<Rgb8> pixels = roundTripPng(image, display);
    ASSERT_EQ(codes.size(), 3 * pixels.size());
    for (size_t i = 0; i < pixels.size(); ++i) {
        EXPECT_EQ(pixels[i], (Rgb8{codes[3 * i], codes[3 * i + 1], codes[3 * i + 2]}));
    }
}

}  // namespace
}  // namespace fp
