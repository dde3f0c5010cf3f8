// The analytic furnace: inside a closed box where every surface has albedo a and emits Le, the
// radiance along every ray is L = Le + a L, i.e. Le / (1 - a); truncated after D bounces it is
// Le * (1 - a^(D+1)) / (1 - a). With a = 0.5 and Le = 1: 2 - 0.5^D. Every integrator must agree.
#include <gtest/gtest.h>

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
    Renderer renderer(furnaceBox(0.5f, 1.0f));
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

}  // namespace
}  // namespace fp::test
