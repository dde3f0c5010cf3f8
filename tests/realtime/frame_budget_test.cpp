#include "realtime/frame_budget.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace fp
