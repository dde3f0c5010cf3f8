// The pieces of `fragpath realtime` that are plain arithmetic, with values worked out by hand.
#include <gtest/gtest.h>

#include "core/error.h"
#include "realtime/realtime_run.h"

namespace fp {
namespace {

TEST(SamplesForBudget, FitsWhatTheBudgetLeavesAfterThePipeline) {
    EXPECT_EQ(samplesForBudget(33.3, 5.0, 8.0), 5);   // (33.3 - 8) / 5 = 5.06
    EXPECT_EQ(samplesForBudget(16.7, 5.0, 8.0), 1);   // 1.74
    EXPECT_EQ(samplesForBudget(16.7, 20.0, 8.0), 1);  // never fewer than one
    EXPECT_EQ(samplesForBudget(1000.0, 1.0, 0.0), RenderSettings::kMaxSamplesPerPass);
    EXPECT_EQ(samplesForBudget(30.0, 0.0, 0.0), 1);  // no measurement yet
}

TEST(Flicker, IsTheMeanChangeOfTheErrorFromFrameToFrame) {
    std::vector<float> before = {0.5f, 0.5f}, now = {0.7f, 0.1f};
    EXPECT_NEAR(flicker(now, before, nullptr, nullptr), (0.2 + 0.4) / 2.0, 1e-6);
    // What the references change too (the view moved) is not flicker: here all of it.
    std::vector<float> refBefore = {0.5f, 0.5f}, refNow = {0.7f, 0.1f};
    EXPECT_NEAR(flicker(now, before, &refNow, &refBefore), 0.0, 1e-6);
    std::vector<float> refSteady = {0.5f, 0.5f};
    EXPECT_NEAR(flicker(now, before, &refSteady, &refSteady), 0.3, 1e-6);
    EXPECT_THROW(flicker(now, {0.5f}, nullptr, nullptr), Error);
}

}  // namespace
}  // namespace fp
