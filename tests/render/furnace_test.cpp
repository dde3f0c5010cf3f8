// The analytic furnace: inside a closed box where every surface has albedo a and emits Le, the
// radiance along every ray is L = Le + a L, i.e. Le / (1 - a); truncated after D bounces it is
// Le * (1 - a^(D+1)) / (1 - a). With a = 0.5 and Le = 1: 2 - 0.5^D. Every integrator must agree.
#include <gtest/gtest.h>

#include "core/error.h"
#include "render_test_util.h"

namespace fp::test {
namespace {

struct FurnaceCase {
    Integrator integrator;
    int maxDepth;
};

class Furnace : public ::testing::TestWithParam<FurnaceCase> {};

TEST_P(Furnace, MeanRadianceMatchesTheGeometricSeries) {
    ensureGlContext();
    const FurnaceCase c = GetParam();
    Renderer renderer(furnaceBox(0.5f, 1.0f), testShaders());
    Accumulation acc = renderScene(renderer, insideCamera(), c.integrator, 24, 64, c.maxDepth);
    ImageEstimate e = estimate(acc);
    const float expected = 2.0f - std::pow(0.5f, float(c.maxDepth));
    for (int ch = 0; ch < 3; ++ch) {
        // Five standard errors of the mean, plus float rounding of the sums.
        float tolerance = 5.0f * e.standardError[ch] + 1e-5f * expected;
        EXPECT_NEAR(e.mean[ch], expected, tolerance)
            << integratorName(c.integrator) << " depth " << c.maxDepth << " standard error "
            << e.standardError[ch];
    }
    EXPECT_EQ(acc.droppedSamples(), 0u);
    if (c.maxDepth == 0) {
        EXPECT_EQ(e.standardError.x, 0.0f) << "depth 0 sees only emission: no noise";
    } else if (c.maxDepth <= 3) {
        // The estimate is precise enough to tell this depth from its neighbours.
        float step = std::pow(0.5f, float(c.maxDepth + 1));
        EXPECT_LT(5.0f * e.standardError.x, step) << "test too noisy to check the depth convention";
    }
}

INSTANTIATE_TEST_SUITE_P(AllIntegrators, Furnace,
                         ::testing::Values(FurnaceCase{Integrator::Naive, 0},
                                           FurnaceCase{Integrator::Naive, 1},
                                           FurnaceCase{Integrator::Naive, 3},
                                           FurnaceCase{Integrator::Bsdf, 0}, FurnaceCase{Integrator::Bsdf, 1},
                                           FurnaceCase{Integrator::Bsdf, 3}, FurnaceCase{Integrator::Nee, 0},
                                           FurnaceCase{Integrator::Nee, 1}, FurnaceCase{Integrator::Nee, 3},
                                           FurnaceCase{Integrator::Nee, 12}),
                         [](const ::testing::TestParamInfo<FurnaceCase>& param) {
                             return std::string(integratorName(param.param.integrator)) + "_depth" +
                                    std::to_string(param.param.maxDepth);
                         });

// --clamp-indirect: in the furnace every path's light after two bounces or more is indirect, and the
// direct part is Le + a Le = 1.5 (emission seen, plus emission one bounce away). A clamp far below the
// indirect light leaves 1.5 (up to the clamp itself); a clamp far above it changes nothing, bit for bit.
// Catches a clamp applied to direct light, or to the wrong bounces, or never.
TEST(FurnaceClamp, ClampingIndirectLightLeavesTheDirectPart) {
    ensureGlContext();
    Renderer renderer(furnaceBox(0.5f, 1.0f), testShaders());
    for (Integrator integrator : {Integrator::Naive, Integrator::Bsdf, Integrator::Nee}) {
        RenderSettings s;
        s.width = s.height = 16;
        s.integrator = integrator;
        s.maxDepth = 3;
        s.sampler = Sampler::Independent;
        s.samplesPerPass = RenderSettings::kMaxSamplesPerPass;
        auto render = [&](float clamp) {
            s.clampIndirect = clamp;
            renderer.configure(s, insideCamera());
            renderer.render(64);
            return renderer.readback();
        };
        Accumulation clamped = render(1e-4f);
        ImageEstimate e = estimate(clamped);
        EXPECT_NEAR(e.mean.g, 1.5f, 5.0f * e.standardError.g + 1e-4f) << integratorName(integrator);
        Accumulation off = render(0.0f), loose = render(1e9f);
        EXPECT_EQ(off.sum, loose.sum)
            << integratorName(integrator) << ": a clamp above every sample changes nothing";
        EXPECT_GT(estimate(off).mean.g, 1.8f) << integratorName(integrator);
    }
    RenderSettings bdpt;
    bdpt.integrator = Integrator::Bdpt;
    bdpt.clampIndirect = 1.0f;
    EXPECT_THROW(renderer.configure(bdpt, insideCamera()), Error) << "bdpt has no indirect clamp";
}

}  // namespace
}  // namespace fp::test
