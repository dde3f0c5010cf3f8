#include "image/tone_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "image/test_files.h"

namespace fp {
namespace {

TEST(ToneMap, ParsesTheThreeNamesAndRoundTripsThem) {
    EXPECT_EQ(parseToneMap("clamp"), ToneMap::Clamp);
    EXPECT_EQ(parseToneMap("reinhard"), ToneMap::Reinhard);
    EXPECT_EQ(parseToneMap("aces"), ToneMap::Aces);
    for (ToneMap t : {ToneMap::Clamp, ToneMap::Reinhard, ToneMap::Aces}) {
        EXPECT_EQ(parseToneMap(toneMapName(t)), t);
    }
}

TEST(ToneMap, UnknownNameListsTheChoices) {
    for (const char* bad : {"", "filmic", "ACES ", "Reinhard2"}) {
        const std::string message = test::errorMessage([&] { parseToneMap(bad); });
        EXPECT_NE(message.find("'" + std::string(bad) + "'"), std::string::npos) << message;
        for (const char* choice : {"clamp", "reinhard", "aces"}) {
            EXPECT_NE(message.find(choice), std::string::npos) << message;
        }
    }
}

TEST(ToneMap, CurvesAtKnownPoints) {
    EXPECT_EQ(toneMapClamp(0.7f), 0.7f);
    EXPECT_FLOAT_EQ(toneMapReinhard(1.0f), 0.5f);
    EXPECT_FLOAT_EQ(toneMapReinhard(3.0f), 0.75f);
    EXPECT_EQ(toneMapAces(0.0f), 0.0f);
    EXPECT_FLOAT_EQ(toneMapAces(1.0f), 2.54f / 3.16f);  // (2.51 + 0.03) / (2.43 + 0.59 + 0.14)
}

TEST(ToneMap, AcesCapOnlyAffectsValuesThatClampToOne) {
    // The uncapped fit, in double, is >= 1 from 7.25 up, so capping the input at 16 cannot change a
    // clamped result.
    for (double x = 7.25; x < 1e30; x *= 1.01) {
        const double uncapped = (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14);
        ASSERT_GE(uncapped, 1.0) << x;
    }
    EXPECT_GE(toneMapAces(16.0f), 1.0f);
    const float white = srgbEncode(1.0f);
    EXPECT_EQ(displayChannel(1e38f, ToneMap::Aces), white);
    EXPECT_EQ(displayChannel(std::numeric_limits<float>::max(), ToneMap::Reinhard), white);
    EXPECT_EQ(displayChannel(std::numeric_limits<float>::infinity(), ToneMap::Aces), white);
}

TEST(ToneMap, SrgbEncodeMatchesIecDefinition) {
    EXPECT_EQ(srgbEncode(0.0f), 0.0f);
    EXPECT_NEAR(srgbEncode(1.0f), 1.0f, 1e-6f);
    EXPECT_FLOAT_EQ(srgbEncode(0.001f), 0.01292f);  // linear segment
    EXPECT_NEAR(srgbEncode(0.5f), 0.7353570f, 1e-6f);
    // The two segments meet (to within the standard's rounding of its constants) at 0.0031308.
    const float below = srgbEncode(0.0031308f), above = srgbEncode(std::nextafter(0.0031308f, 1.0f));
    EXPECT_NEAR(below, above, 1e-6f);
    EXPECT_NEAR(below, 0.04045f, 1e-6f);
}

TEST(ToneMap, DisplayChannelIsMonotonicAndBounded) {
    for (ToneMap t : {ToneMap::Clamp, ToneMap::Reinhard, ToneMap::Aces}) {
        float previous = 0.0f;
        for (float x = 1e-6f; x < 1e6f; x *= 1.02f) {
            const float v = displayChannel(x, t);
            ASSERT_GE(v, previous) << toneMapName(t) << " at " << x;
            ASSERT_LE(v, 1.0f) << toneMapName(t) << " at " << x;
            previous = v;
        }
    }
}

TEST(ToneMap, Quantize8RoundsAndClamps) {
    EXPECT_EQ(quantize8(0.0f), 0);
    EXPECT_EQ(quantize8(1.0f), 255);
    EXPECT_EQ(quantize8(-0.5f), 0);
    EXPECT_EQ(quantize8(7.0f), 255);
    EXPECT_EQ(quantize8(100.4f / 255.0f), 100);
    EXPECT_EQ(quantize8(100.6f / 255.0f), 101);
}

TEST(ToneMap, DisplayEncodeHandlesNonFinitePixelsAsAWhole) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const DisplaySettings display{0.0f, ToneMap::Reinhard};
    EXPECT_EQ(displayEncode({0.2f, nan, 0.3f}, display), glm::vec3(0.0f));
    EXPECT_EQ(displayEncode({0.0f, 0.0f, inf}, display), glm::vec3(srgbEncode(1.0f)));
    EXPECT_EQ(quantize8(srgbEncode(1.0f)), 255);
    EXPECT_EQ(displayEncode({-inf, 1.0f, 0.0f}, display), glm::vec3(0.0f, srgbEncode(0.5f), 0.0f));
}

}  // namespace
}  // namespace fp
