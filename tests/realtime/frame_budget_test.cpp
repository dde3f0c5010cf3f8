#include "realtime/frame_budget.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fp {
namespace {

// 30 fps: a 33.3 ms budget; with 3.3 ms of overhead the trace has 30 ms.
TEST(FrameBudget, KeepsSppWithinTheHysteresisBand) {
    EXPECT_EQ(adaptSamplesPerFrame(4, 28.0, 30.0, 3.33), 4);  // 7 ms/sample: 5 would be 35 > 24
    EXPECT_EQ(adaptSamplesPerFrame(4, 32.0, 30.0, 3.33), 4);  // over, but by less than 10 %
}

TEST(FrameBudget, LowersWhenTheTraceOverruns) {
    EXPECT_EQ(adaptSamplesPerFrame(8, 60.0, 30.0, 3.33), 3);   // 7.5 ms/sample; 0.9 * 30 / 7.5 = 3.6
    EXPECT_EQ(adaptSamplesPerFrame(1, 500.0, 30.0, 3.33), 1);  // never below 1
    EXPECT_EQ(adaptSamplesPerFrame(2, 10.0, 30.0, 40.0), 1);   // the overhead alone exceeds the budget
}

TEST(FrameBudget, RaisesWhenThereIsRoom) {
    EXPECT_EQ(adaptSamplesPerFrame(1, 2.0, 30.0, 3.33), 13);  // 0.9 * 30 / 2 = 13.5
    EXPECT_EQ(adaptSamplesPerFrame(1, 0.01, 60.0, 0.0), FrameBudget::maxSpp);
}

TEST(FrameBudget, SettlesAfterOneStepOnALinearCost) {
    // A trace that costs 3 ms per sample at 20 fps with 5 ms of overhead: one adaptation, then stable.
    int spp = 1;
    for (int frame = 0; frame < 10; ++frame) spp = adaptSamplesPerFrame(spp, 3.0 * spp, 20.0, 5.0);
    EXPECT_EQ(spp, 13);  // 0.9 * 45 / 3 = 13.5
    EXPECT_EQ(adaptSamplesPerFrame(spp, 3.0 * spp, 20.0, 5.0), spp);
}

TEST(FrameBudget, IgnoresMeaninglessMeasurements) {
    EXPECT_EQ(adaptSamplesPerFrame(5, 0.0, 30.0, 1.0), 5);
    EXPECT_EQ(adaptSamplesPerFrame(5, 10.0, 0.0, 1.0), 5);
    EXPECT_EQ(adaptSamplesPerFrame(0, 10.0, 0.0, 1.0), 1);
}

// The resolution ladder, at 30 fps (33.3 ms; overrun above 36.7 ms, 90 % is 30 ms, headroom 26.7 ms).
TEST(ResolutionScale, KeepsTheScaleWithinTheHysteresisBand) {
    EXPECT_FLOAT_EQ(adaptResolutionScale(1.0f, 34.0, 30.0), 1.0f);  // over, but by less than 10 %
    EXPECT_FLOAT_EQ(adaptResolutionScale(1.0f, 1.0, 30.0), 1.0f);   // no step above full resolution
    EXPECT_FLOAT_EQ(adaptResolutionScale(0.5f, 14.0, 30.0), 0.5f);  // twice the pixels: 28 > 26.7
}

TEST(ResolutionScale, DropsAsManyStepsAsTheOverrunNeeds) {
    // 40 ms: log2(40 / 30) = 0.42, one step (half the pixels, 20 ms).
    EXPECT_FLOAT_EQ(adaptResolutionScale(1.0f, 40.0, 30.0), std::sqrt(0.5f));
    // 100 ms: log2(100 / 30) = 1.74, two steps: a quarter of the pixels, 25 ms.
    EXPECT_FLOAT_EQ(adaptResolutionScale(1.0f, 100.0, 30.0), 0.5f);
    // 1000 ms would need six steps (log2 33.3 = 5.06 -> 6): the floor, 1/8 of the side.
    EXPECT_FLOAT_EQ(adaptResolutionScale(1.0f, 1000.0, 30.0), FrameBudget::minScale);
    EXPECT_FLOAT_EQ(adaptResolutionScale(FrameBudget::minScale, 1000.0, 30.0), FrameBudget::minScale);
}

TEST(ResolutionScale, ClimbsOneStepWhenTwiceThePixelsFit) {
    EXPECT_FLOAT_EQ(adaptResolutionScale(0.5f, 13.0, 30.0), std::sqrt(0.5f));  // 26 < 26.7
}

TEST(ResolutionScale, SettlesOnAFrameTimeProportionalToThePixels) {
    // 200 ms at full resolution: log2(200 / 30) = 2.74, three steps (25 ms), then no change: 25 ms is
    // not an overrun and 50 ms at the next step up leaves no headroom.
    float scale = 1.0f;
    for (int frame = 0; frame < 10; ++frame) scale = adaptResolutionScale(scale, 200.0 * scale * scale, 30.0);
    EXPECT_FLOAT_EQ(scale, std::pow(2.0f, -1.5f));
}

TEST(ResolutionScale, SnapsToTheLadderAndIgnoresMeaninglessMeasurements) {
    EXPECT_FLOAT_EQ(adaptResolutionScale(0.6f, 0.0, 30.0), std::sqrt(0.5f));  // -2 log2 0.6 = 1.47 -> 1
    EXPECT_FLOAT_EQ(adaptResolutionScale(0.5f, 100.0, 0.0), 0.5f);
    EXPECT_FLOAT_EQ(adaptResolutionScale(std::nanf(""), 10.0, 30.0), 1.0f);
}

}  // namespace
}  // namespace fp
