// Russian roulette (glsl/common/surface.glsl, survivesRoulette) is unbiased only if a survivor's weight is
// divided by exactly the probability it survived with. A weight off by a few percent hides on ordinary
// scenes, whose light comes mostly from the first bounces (dividing by 1.05 q: -0.4 % on the Cornell box
// at depth 32), so these tests put the light in the deep bounces: a closed white furnace of high albedo,
// where every bounce keeps 90-95 % of the light and the roulette decides at almost every vertex.
//
// Inside a closed box whose every surface has albedo a and emits Le, the radiance along every ray is
// L = Le + a L (furnace_test.cpp); truncated after D bounces it is the geometric series
// Le (1 + a + ... + a^D) = Le (1 - a^(D+1)) / (1 - a), and without a limit Le / (1 - a). Lossless
// objects in the box (smooth glass, a white mirror: directional albedo 1, no emission) leave that limit
// unchanged: a uniform field of radiance L passes through them as it is (at glass, the 1/eta^2 of a
// refraction in is undone by the eta^2 of the refraction out). Their bounces are delta, so the roulette
// waits for the walls, and nee's light samples and MIS weights meet glass and mirrors at depth.
//
// Rough (glossy) lobes lose a little light to single scattering, so where they are in the box the
// reference is the same scene rendered by paths the roulette never stops.
//
// Caught (tried on a copy of the shaders through FP_RENDER_TEST_SHADERS): the survivors' weight divided
// by 1.05 q instead of q. Every case fails: the image means 0.70x the series (bsdf), 0.71x (nee), 0.92x
// (bdpt), 0.93x (naive) in the Lambertian box, 0.77x with glass and mirror; with the rough lobes 0.77x
// (bsdf), 0.78x (nee), 0.92x (bdpt) the paths without roulette; whole-image z -18 to -81.
//
// Cost: 2.0 s of CPU with Mesa's shader cache warm, 14.4 s cold (the compiles; machine loaded).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "render_test_util.h"
#include "shader_variants.h"

namespace fp::test {
namespace {

constexpr int kSize = 16, kBlock = 4, kSpp = 64;

// Le (1 + a + ... + a^D); depth < 0: the whole series.
double furnaceRadiance(double albedo, double emission, int depth) {
    double tail = depth < 0 ? 0.0 : std::pow(albedo, depth + 1);
    return emission * (1.0 - tail) / (1.0 - albedo);
}

// The box with walls of albedo `albedo` around two spheres of white (non-absorbing) glass and metal of
// GGX roughness `roughness` (0: smooth glass and a mirror; Schlick's Fresnel from F0 = 1 is 1 at every
// angle), both in view of insideCamera().
Scene boxWithGlassAndMetal(float albedo, float roughness) {
    Scene scene = furnaceBox(albedo, 1.0f);
    Material glass;
    glass.name = "glass";
    glass.type = MaterialType::Dielectric;
    glass.ior = 1.5f;
    glass.roughness = roughness;
    Material metal;
    metal.name = "metal";
    metal.type = MaterialType::Conductor;
    metal.specular = glm::vec3(1.0f);
    metal.roughness = roughness;
    scene.materials.push_back(glass);
    scene.materials.push_back(metal);
    appendSphere(scene, glm::vec3(0.05f, 0.0f, 0.55f), 0.3f, 12, 24, 1, true);
    appendSphere(scene, glm::vec3(0.6f, 0.15f, 0.75f), 0.25f, 12, 24, 2, true);
    return scene;
}

void expectFurnace(Renderer& renderer, Integrator integrator, int depth, double expected, uint32_t seed,
                   int spp = kSpp) {
    Accumulation acc = renderScene(renderer, insideCamera(), integrator, kSize, spp, depth, seed);
    const std::string what = std::string(integratorName(integrator)) + " at depth " + std::to_string(depth) +
                             ", expected " + std::to_string(expected);
    expectImage(acc, std::vector<glm::dvec3>(size_t(kSize) * kSize, glm::dvec3(expected)), kBlock, what);
    // The whole image's standard error must be well below the 5 % a broken roulette loses per bounce.
    ImageEstimate e = estimate(acc);
    std::printf("  %s: image mean %.4f, %.4f of the series\n", what.c_str(), e.mean.g, e.mean.g / expected);
    EXPECT_LT(e.standardError.g, 0.01f * e.mean.g) << what << ": too noisy to mean anything";
}

// Lambertian walls of albedo 0.95 at depth 32: the light of bounces 3 to 32, where the roulette plays, is
// 82 % of the image. bdpt stores at most 12 bounces (BDPT_MAX_DEPTH), so it is asked for those (71 %).
// naive's uniform directions weigh each bounce by 2 a cos(theta), whose product over many bounces has
// too heavy a tail for the sample variance to be trusted (at depth 32 and 64 spp: 8 % standard error,
// block z-scores of mean square 3.5), so it is asked for 8 bounces (61 %), at 4 times the samples.
TEST(RouletteFurnace, LambertianBoxMatchesTheGeometricSeriesAtDepth32) {
    ensureGlContext();
    const double albedo = 0.95;
    Renderer box(furnaceBox(float(albedo), 1.0f), testShaders());
    for (Integrator integrator : {Integrator::Naive, Integrator::Bsdf, Integrator::Nee, Integrator::Bdpt}) {
        const int depth = integrator == Integrator::Naive ? 8 : integrator == Integrator::Bdpt ? 12 : 32;
        const int spp = integrator == Integrator::Naive ? 4 * kSpp : kSpp;
        expectFurnace(box, integrator, depth, furnaceRadiance(albedo, 1.0, depth), 11, spp);
    }
}

// Walls of albedo 0.9 around a smooth glass sphere and a white mirror sphere, at depth 1000: the whole
// series, Le / (1 - a) = 10 (paths end by the roulette long before; what depth 1000 cuts off, light trapped
// by total internal reflection among the glass's facets for hundreds of bounces, is far below the noise).
// bdpt, which stops at 12 bounces, has no closed form here.
TEST(RouletteFurnace, GlassAndMirrorInTheBoxLeaveTheWholeSeries) {
    ensureGlContext();
    const double albedo = 0.9;
    Scene scene = boxWithGlassAndMetal(float(albedo), 0.0f);
    Renderer renderer(scene, testShaders());
    for (Integrator integrator : {Integrator::Bsdf, Integrator::Nee})
        expectFurnace(renderer, integrator, 1000, furnaceRadiance(albedo, 1.0, -1), 13);
}

// Rough glass and a rough white metal (GGX, roughness 0.1) in the box: glossy lobes, where the roulette
// plays and weighs beta with the refractions undone (etaScale). They lose about 1 % of the light to
// single scattering (the image mean 9.89-9.91 at 1024 spp, against 10 for lossless objects, 6 standard
// errors below), so the series is no reference; the same scene is, rendered by paths the roulette never
// stops (noRouletteShaders), unbiased whatever the roulette's code does. Depth 32 (bdpt 12), where the
// roulette has ended almost every path: the light of the bounces beyond it must be the same either way.
TEST(RouletteFurnace, RoughGlassAndMetalMatchPathsTheRouletteNeverStops) {
    ensureGlContext();
    Scene scene = boxWithGlassAndMetal(0.9f, 0.1f);
    Renderer roulette(scene, testShaders()), never(scene, noRouletteShaders());
    for (Integrator integrator : {Integrator::Bsdf, Integrator::Nee, Integrator::Bdpt}) {
        const int depth = integrator == Integrator::Bdpt ? 12 : 32;
        Accumulation a = renderScene(roulette, insideCamera(), integrator, kSize, kSpp, depth, 17);
        Accumulation b = renderScene(never, insideCamera(), integrator, kSize, kSpp, depth, 19);
        expectSameImage(a, b, kBlock, 0.02f,
                        std::string(integratorName(integrator)) + ": roulette against none, depth " +
                            std::to_string(depth));
    }
}

}  // namespace
}  // namespace fp::test
