// When the viewer restarts accumulation: exactly when the image being estimated changes.
#include "viewer/accumulation_policy.h"

#include <gtest/gtest.h>

namespace fp {
namespace {

class AccumulationPolicyTest : public ::testing::Test {
  protected:
    AccumulationPolicyTest() {
        request.windowSize = {800, 600};
        request.now = 10.0;
    }
    // One frame `dt` seconds after the previous one.
    AccumulationPolicy::Decision frame(double dt = 0.04) {
        request.now += dt;
        return policy.update(request);
    }
    AccumulationPolicy policy;
    AccumulationPolicy::Request request;
};

TEST_F(AccumulationPolicyTest, FirstFrameStartsAtFullResolution) {
    AccumulationPolicy::Decision d = frame();
    EXPECT_TRUE(d.restart);
    EXPECT_TRUE(d.render);
    EXPECT_FALSE(d.reduced);
    EXPECT_EQ(d.settings.width, 800);
    EXPECT_EQ(d.settings.height, 600);
    EXPECT_EQ(policy.restarts(), 1u);
}

TEST_F(AccumulationPolicyTest, NothingChangedKeepsAccumulating) {
    frame();
    for (int i = 0; i < 100; ++i) {
        AccumulationPolicy::Decision d = frame();
        EXPECT_FALSE(d.restart) << "frame " << i;
        EXPECT_TRUE(d.render);
    }
    EXPECT_EQ(policy.restarts(), 1u);
}

TEST_F(AccumulationPolicyTest, CameraMotionRestartsAtReducedResolutionThenFull) {
    frame();
    request.cameraVersion = 1;
    AccumulationPolicy::Decision d = frame();
    EXPECT_TRUE(d.restart);
    EXPECT_TRUE(d.reduced);
    EXPECT_EQ(d.settings.width, 200);  // window / 4
    EXPECT_EQ(d.settings.height, 150);

    // Still moving: every new camera restarts, at the reduced size.
    request.cameraVersion = 2;
    d = frame();
    EXPECT_TRUE(d.restart);
    EXPECT_TRUE(d.reduced);

    // Stopped, but within the settle time: the reduced accumulation refines.
    d = frame(0.1);
    EXPECT_FALSE(d.restart);
    EXPECT_TRUE(d.reduced);

    // Settled: one restart at full resolution, then nothing.
    d = frame(0.15);
    EXPECT_TRUE(d.restart);
    EXPECT_FALSE(d.reduced);
    EXPECT_EQ(d.settings.width, 800);
    EXPECT_FALSE(frame().restart);
    EXPECT_EQ(policy.restarts(), 4u);
}

TEST_F(AccumulationPolicyTest, NoReductionWhenAFullPassIsCheap) {
    frame();
    request.reduceWhileMoving = false;
    request.cameraVersion = 1;
    AccumulationPolicy::Decision d = frame();
    EXPECT_TRUE(d.restart);
    EXPECT_FALSE(d.reduced);
    EXPECT_EQ(d.settings.width, 800);
    // And no second restart when it settles: the size never changed.
    EXPECT_FALSE(frame(1.0).restart);
}

TEST_F(AccumulationPolicyTest, EverySettingTheRendererReadsRestarts) {
    frame();
    auto changes = std::vector<void (*)(RenderSettings&)>{
        [](RenderSettings& s) { s.maxDepth = 3; },
        [](RenderSettings& s) { s.seed = 7; },
        [](RenderSettings& s) { s.integrator = Integrator::Bsdf; },
        [](RenderSettings& s) { s.view = View::Nodes; },
        [](RenderSettings& s) { s.samplesPerPass = 2; },
        [](RenderSettings& s) { s.sampleOffset = 5; },
        [](RenderSettings& s) { s.split = SplitView{}; },
        [](RenderSettings& s) { s.split->integrator = Integrator::Nee; },
        [](RenderSettings& s) { s.split->maxDepth = 1; },
        [](RenderSettings& s) { s.split.reset(); },
    };
    for (size_t i = 0; i < changes.size(); ++i) {
        changes[i](request.settings);
        AccumulationPolicy::Decision d = frame();
        EXPECT_TRUE(d.restart) << "change " << i;
        EXPECT_FALSE(d.reduced) << "a setting is not motion";
        EXPECT_FALSE(frame().restart) << "change " << i << " restarted twice";
    }
}

TEST_F(AccumulationPolicyTest, MovingScaleFromTheRequest) {
    frame();
    request.movingScale = 0.125f;  // the viewer's choice: a whole pass must fit in a frame
    request.cameraVersion = 1;
    AccumulationPolicy::Decision d = frame();
    EXPECT_TRUE(d.reduced);
    EXPECT_EQ(d.settings.width, 100);
    EXPECT_EQ(d.settings.height, 75);
}

TEST_F(AccumulationPolicyTest, WindowSizeIsNotASettingButTheWindowIs) {
    frame();
    // The request's width and height are ignored: the accumulation follows the window.
    request.settings.width = 17;
    request.settings.height = 5;
    EXPECT_FALSE(frame().restart);

    request.windowSize = {1024, 768};
    AccumulationPolicy::Decision d = frame();
    EXPECT_TRUE(d.restart);
    EXPECT_TRUE(d.reduced) << "a resize drag is motion";
    EXPECT_EQ(d.settings.width, 256);
    d = frame(0.5);
    EXPECT_TRUE(d.restart);
    EXPECT_EQ(d.settings.width, 1024);
    EXPECT_EQ(d.settings.height, 768);
}

TEST_F(AccumulationPolicyTest, ResolutionScale) {
    request.resolutionScale = 0.5f;
    AccumulationPolicy::Decision d = frame();
    EXPECT_EQ(d.settings.width, 400);
    EXPECT_EQ(d.settings.height, 300);
    request.resolutionScale = 0.25f;
    d = frame();
    EXPECT_TRUE(d.restart);
    EXPECT_EQ(d.settings.width, 200);
    // Moving never goes below the still scale's own reduction: at 1/4 already there is nothing to gain.
    request.cameraVersion = 1;
    d = frame();
    EXPECT_TRUE(d.restart);
    EXPECT_FALSE(d.reduced);
    EXPECT_EQ(d.settings.width, 200);
    // Out-of-range scales are clamped; sizes never reach zero.
    request.resolutionScale = 1e-6f;
    request.windowSize = {3, 2};
    d = frame(1.0);
    EXPECT_GE(d.settings.width, 1);
    EXPECT_GE(d.settings.height, 1);
}

TEST_F(AccumulationPolicyTest, MinimisedWindowRendersNothingAndKeepsTheAccumulation) {
    frame();
    request.windowSize = {0, 0};
    AccumulationPolicy::Decision d = frame();
    EXPECT_FALSE(d.render);
    EXPECT_FALSE(d.restart);
    request.windowSize = {800, 600};
    d = frame(1.0);
    EXPECT_TRUE(d.render);
    EXPECT_FALSE(d.restart) << "the same window size again: the samples are still valid";
}

TEST_F(AccumulationPolicyTest, CameraChangedWhileMinimisedRestartsOnReturn) {
    frame();
    request.windowSize = {0, 0};
    frame();
    request.cameraVersion = 5;
    EXPECT_FALSE(frame().restart);
    request.windowSize = {800, 600};
    EXPECT_TRUE(frame(1.0).restart);
}

TEST_F(AccumulationPolicyTest, FailedRestartComparesAgainstWhatTheRendererKept) {
    AccumulationPolicy::Decision first = frame();
    request.settings.integrator = Integrator::Naive;
    EXPECT_TRUE(frame().restart);
    // configure() failed; the viewer fell back to the first settings.
    policy.restartFailed(first.settings);
    request.settings = first.settings;
    EXPECT_FALSE(frame().restart);
    request.settings.integrator = Integrator::Naive;
    EXPECT_TRUE(frame().restart) << "asking again tries again";
}

TEST(SameAccumulation, IgnoresNothingTheRendererReads) {
    RenderSettings a, b;
    EXPECT_TRUE(sameAccumulation(a, b));
    b.height = 1;
    EXPECT_FALSE(sameAccumulation(a, b));
    b = a;
    b.sampler = Sampler::Independent;
    EXPECT_FALSE(sameAccumulation(a, b)) << "another sampler";
    b = a;
    b.lightSampling = LightSampling::Area;
    EXPECT_FALSE(sameAccumulation(a, b)) << "another light sampling";
    b = a;
    b.clampIndirect = 4.0f;
    EXPECT_FALSE(sameAccumulation(a, b)) << "a clamp";
    b = a;
    a.split = SplitView{};
    b.split = SplitView{};
    EXPECT_TRUE(sameAccumulation(a, b));
}

}  // namespace
}  // namespace fp
