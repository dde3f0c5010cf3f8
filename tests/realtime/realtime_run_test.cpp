// Flicker, the temporal-stability figure of `fragpath realtime`, with values worked out by hand (the
// samples per frame are realtime/frame_budget.h's, tested in frame_budget_test.cpp).
#include <gtest/gtest.h>

#include "core/error.h"
#include "realtime/realtime_run.h"

namespace fp {
namespace {

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
