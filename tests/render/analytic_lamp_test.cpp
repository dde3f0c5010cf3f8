// The GPU integrators against a closed form: a small lamp just above a diffuse floor
// (analytic_lamp.h), direct light only, must light the floor under its centre with radiance rho Le F,
// at the origin, at x = 1e5, with a 1 mm and a 10 km lamp. What it catches (issue 15): rays that start
// too far off their surface, or shadow rays that stop short by a fraction of their length and find the
// lamp they aim at, both of which lose light wherever two surfaces are close compared with the offset.
#include <gtest/gtest.h>

#include <cstdio>

#include "render/analytic_lamp.h"
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

}  // namespace
}  // namespace fp::test
