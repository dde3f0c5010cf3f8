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

}  // namespace
}  // namespace fp::test
