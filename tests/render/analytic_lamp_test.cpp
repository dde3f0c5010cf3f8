// The GPU integrators against a closed form: a small lamp just above a diffuse floor
// (analytic_lamp.h), direct light only, must light the floor under its centre with radiance rho Le F,
// at the origin, at x = 1e5, with a 1 mm and a 10 km lamp. What it catches (issue 15): rays that start
// too far off their surface, or shadow rays that stop short by a fraction of their length and find the
// lamp they aim at, both of which lose light wherever two surfaces are close compared with the offset.
#include <gtest/gtest.h>

#include <cstdio>

#include "render/analytic_lamp.h"
#include "render/analytic_reference.h"
#include "render/floor_image.h"
#include "render/render_test_util.h"

namespace fp::test {
namespace {

void expectAnalyticLamp(Integrator integrator) {
    ensureGlContext();
    uint32_t seed = 5;
    for (const LampCase& c : lampCases()) {
        Scene scene = lampOverFloor(c);
        Renderer renderer(scene, testShaders());
        Accumulation acc = renderScene(renderer, lampCamera(c), integrator, 16, 64, 1, seed++);
        double error = expectLampRadiance(acc, c, 4);
        std::printf("  %s, %-24s relative error %+.4f\n", integratorName(integrator), c.name.c_str(), error);
    }
}

TEST(AnalyticLamp, NeeLightsTheFloorUnderALampCloseAboveIt) {
    expectAnalyticLamp(Integrator::Nee);
}

TEST(AnalyticLamp, BsdfLightsTheFloorUnderALampCloseAboveIt) {
    expectAnalyticLamp(Integrator::Bsdf);
}

TEST(AnalyticLamp, BdptLightsTheFloorUnderALampCloseAboveIt) {
    expectAnalyticLamp(Integrator::Bdpt);
}

// nee samples a lamp that subtends a large solid angle uniformly in that solid angle (lights.glsl,
// Arvo 1995), not by area: the floor under a lamp 0.2 of its side above it gets the same radiance with
// less than half the variance (the 1 / r^2 and the lamp's cosine leave the estimate). Both by the
// analytic value; --light-sampling auto chooses solid angle for this scene (pack/light_strategy.h).
TEST(AnalyticLamp, NeeSamplesACloseLampBySolidAngle) {
    ensureGlContext();
    const LampCase c = lampCases()[0];
    Scene scene = lampOverFloor(c);
    Renderer renderer(scene, testShaders());
    auto render = [&](LightSampling sampling) {
        Accumulation acc = renderScene(renderer, lampCamera(c), Integrator::Nee, 16, 64, 1, 11,
                                       Sampler::Independent, sampling);
        expectLampRadiance(acc, c, 4);
        return acc;
    };
    Accumulation automatic = render(LightSampling::Auto), spherical = render(LightSampling::SolidAngle),
                 area = render(LightSampling::Area);
    expectBitIdentical(automatic, spherical, "auto against solid-angle on a lamp close above a floor");
    auto variance = [](const Accumulation& acc) {
        double se = estimate(acc).standardError.g;
        return se * se;
    };
    std::printf("  variance of the image mean: by solid angle %.3g, by area %.3g\n", variance(spherical),
                variance(area));
    EXPECT_LT(variance(spherical), 0.5 * variance(area));
}

// Issue 35: every integrator, with each strategy it chooses between, lights the floor under the lamp
// of side 2, 1 above, as the closed form does pixel by pixel (each pixel its own floor points' form
// factor) and to 0.05 % over the image (analytic_reference.h). Direct light only exists here (the lamp
// is black, the floor has nothing above it but the lamp), so depth 1 is exact (deeper paths add
// exactly nothing: measured, bit for bit the same means at depth 3). The replicates' samples per pixel
// follow each integrator's noise: naive (uniform directions, relative noise 1.4 per path) and bsdf (0.9)
// need 8 times nee's, bdpt a quarter of it. The lamp is 4 x 4 squares, so that the light tree, which
// weighs each by its distance and orientation from the shading point, chooses otherwise than by power.
// Left out as it gave bit for bit the same image: bdpt with --light-sampling solid-angle.
class AnalyticLampAllIntegrators : public ::testing::TestWithParam<AnalyticVariant> {};

TEST_P(AnalyticLampAllIntegrators, FloorRadianceIsRhoLeFToAFractionOfAPerMille) {
    ensureGlContext();
    const AnalyticVariant v = GetParam();
    LampCase c = issue35Lamp();
    c.tiles = 4;
    const Camera camera = lampWideCamera(c);
    std::vector<glm::dvec3> expected = expectedFloorImage(
        camera, kAnalyticSize, [&](const glm::dvec3& p) { return lampFloorRadiance(c, p); });
    Renderer renderer(lampOverFloor(c), testShaders());
    expectAnalytic(renderer, camera, v, 1, expected, variantName(v));
}

INSTANTIATE_TEST_SUITE_P(
    Integrators, AnalyticLampAllIntegrators,
    ::testing::Values(AnalyticVariant{Integrator::Naive, 2048}, AnalyticVariant{Integrator::Bsdf, 2048},
                      AnalyticVariant{Integrator::Nee, 256, LightSampling::Area, LightSelection::Power},
                      AnalyticVariant{Integrator::Nee, 256, LightSampling::SolidAngle, LightSelection::Power},
                      AnalyticVariant{Integrator::Nee, 256, LightSampling::Area, LightSelection::Tree},
                      AnalyticVariant{Integrator::Nee, 256, LightSampling::SolidAngle, LightSelection::Tree},
                      AnalyticVariant{Integrator::Bdpt, 64, LightSampling::Auto, LightSelection::Auto,
                                      Caustics::Auto, 64}),
    variantTestName);

// nee's two strategies for one path, a light sample and a BSDF ray that hits the lamp, must weigh it
// with densities measured from the same point, or the MIS weights do not sum to 1. The BSDF ray leaves
// from the shading point moved off its surface (ray_offset.glsl: 2^-18 of the triangle's largest
// coordinate bound, 2.3e-4 on the default floor 40 wide), and lightPdf took the lamp's distance from
// there, shorter than sampleLight's from the point itself. Measured on that floor, with area sampling:
// +0.0176 % +- 0.0009 % before lightPdf measured from the point, +0.0062 % +- 0.0009 % after. What is
// left is the offset itself: BSDF rays see the lamp from 2.3e-4 nearer, F(h - 2.3e-4) = F(h) (1 +
// 0.020 %) (bsdf alone: +0.024 % +- 0.003 %), in nee only through the share of light its BSDF rays
// carry. 0.01 % lies 4 standard errors from both figures.
TEST(AnalyticLamp, NeeMeasuresBothStrategiesOfAPathFromTheSamePoint) {
    ensureGlContext();
    LampCase c = issue35Lamp();
    c.floorHalf = 0.0;  // the default floor, 40 wide
    const Camera camera = lampWideCamera(c);
    std::vector<glm::dvec3> expected = expectedFloorImage(
        camera, kAnalyticSize, [&](const glm::dvec3& p) { return lampFloorRadiance(c, p); });
    Renderer renderer(lampOverFloor(c), testShaders());
    const AnalyticVariant v{Integrator::Nee, 1024, LightSampling::Area, LightSelection::Power};
    ReplicateError e = replicateError(renderer, camera, v, 1, expected, "nee by area, floor 40 wide");
    EXPECT_LT(e.standardError.y, 2.5e-5);
    EXPECT_LT(std::abs(e.mean.y), 1e-4);
}

}  // namespace
}  // namespace fp::test
