// Bidirectional path tracing (glsl/integrators/bdpt.glsl) against the analytic furnace and against nee:
// both estimate the same integral, so their images must agree within the noise each one measures; and
// on a caustic scene its extra strategies must pay for themselves in variance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "image/image_stats.h"
#include "render_test_util.h"
#include "scene/builtin_scene.h"
#include "scene/procedural.h"
#include "shader_variants.h"

namespace fp::test {
namespace {

// ---- the analytic furnace: L = 2 - 0.5^D (see furnace_test.cpp) ----

class BdptFurnace : public ::testing::TestWithParam<int> {};

TEST_P(BdptFurnace, MeanRadianceMatchesTheGeometricSeries) {
    ensureGlContext();
    const int depth = GetParam();
    Renderer renderer(furnaceBox(0.5f, 1.0f), testShaders());
    Accumulation acc = renderScene(renderer, insideCamera(), Integrator::Bdpt, 24, 64, depth);
    ImageEstimate e = estimate(acc);
    const float expected = 2.0f - std::pow(0.5f, float(depth));
    for (int ch = 0; ch < 3; ++ch) {
        float tolerance = 5.0f * e.standardError[ch] + 1e-5f * expected;
        EXPECT_NEAR(e.mean[ch], expected, tolerance)
            << "depth " << depth << " standard error " << e.standardError[ch];
    }
    EXPECT_EQ(acc.droppedSamples(), 0u);
    // At depth 0 the emission is found by two strategies, s = 0 and light tracing (1, 1), so even that
    // image has noise; it must still be small enough to tell the depths apart.
    float step = std::pow(0.5f, float(depth + 1));
    EXPECT_LT(5.0f * e.standardError.x, step) << "test too noisy to check the depth convention";
    EXPECT_FALSE(acc.splatSum.empty()) << "bdpt traces light paths into a light image";
}

INSTANTIATE_TEST_SUITE_P(Depths, BdptFurnace, ::testing::Values(0, 1, 3),
                         [](const ::testing::TestParamInfo<int>& p) {
                             return "depth" + std::to_string(p.param);
                         });

// ---- comparisons with nee ----

// The whole-image means agree within 5 standard errors (and the comparison is sharp), and per block no
// z-score exceeds 5 and their mean square is near 1, as for independent estimates of the same image.
void expectSameImage(const Accumulation& bdpt, const Accumulation& nee, int block, float sharpness) {
    ImageEstimate eb = estimate(bdpt), en = estimate(nee);
    for (int c = 0; c < 3; ++c) {
        float se =
            std::sqrt(eb.standardError[c] * eb.standardError[c] + en.standardError[c] * en.standardError[c]);
        EXPECT_NEAR(eb.mean[c], en.mean[c], 5.0f * se) << "channel " << c;
        EXPECT_LT(se, sharpness * en.mean[c]) << "the comparison must be sharp enough to mean something";
    }
    std::vector<float> z = blockZScores(bdpt, nee, block);
    ASSERT_GT(z.size(), 100u);
    expectZScoresOfNoise(z);
    EXPECT_EQ(bdpt.droppedSamples() + nee.droppedSamples(), 0u);
}

Accumulation renderPasses(Renderer& renderer, const Camera& camera, Integrator integrator, int size, int spp,
                          int depth, uint32_t seed = 1) {
    RenderSettings s;
    s.width = s.height = size;
    s.integrator = integrator;
    s.maxDepth = depth;
    s.seed = seed;
    s.samplesPerPass = 16;
    s.sampler = Sampler::Independent;  // the z-scores take pixels' errors as independent
    s.caustics = Caustics::Path;       // nee by camera paths alone, against which bdpt's strategies are told
    renderer.configure(s, camera);
    renderer.render(spp);
    Accumulation acc = renderer.readback();
    for (const glm::vec4& v : acc.sum) EXPECT_EQ(v.w, float(spp));
    return acc;
}
Accumulation render(const Scene& scene, const Camera& camera, Integrator integrator, int size, int spp,
                    int depth, uint32_t seed = 1) {
    Renderer renderer(scene, testShaders());
    return renderPasses(renderer, camera, integrator, size, spp, depth, seed);
}

TEST(Bdpt, ConvergesToNeeOnTheCornellBox) {
    ensureGlContext();
    Scene scene = builtinCornellBox();
    Accumulation bdpt = render(scene, *scene.camera, Integrator::Bdpt, 32, 256, 4);
    Accumulation nee = render(scene, *scene.camera, Integrator::Nee, 32, 512, 4, 2);
    expectSameImage(bdpt, nee, 4, 0.02f);
}

// The Cornell box with its white surfaces (walls, floor, ceiling and both blocks) made a rough metal:
// glossy-to-glossy connections, and densities that differ strongly between the two directions.
TEST(Bdpt, ConvergesToNeeOnAGlossyCornellBox) {
    ensureGlContext();
    Scene scene = builtinCornellBox();
    for (Material& m : scene.materials)
        if (m.name == "white") {
            m.type = MaterialType::Conductor;
            m.specular = glm::vec3(0.9f, 0.85f, 0.8f);
            m.roughness = 0.4f;
        }
    Accumulation bdpt = render(scene, *scene.camera, Integrator::Bdpt, 32, 256, 4);
    Accumulation nee = render(scene, *scene.camera, Integrator::Nee, 32, 512, 4, 2);
    expectSameImage(bdpt, nee, 4, 0.02f);
}

// Delta vertices in the middle of paths (cornellWithDeltaSurfaces), which no strategy can join to.
TEST(Bdpt, ConvergesToNeeWithDeltaSurfaces) {
    ensureGlContext();
    Scene scene = cornellWithDeltaSurfaces();
    Accumulation bdpt = render(scene, *scene.camera, Integrator::Bdpt, 32, 256, 4);
    Accumulation nee = render(scene, *scene.camera, Integrator::Nee, 32, 512, 4, 2);
    expectSameImage(bdpt, nee, 4, 0.02f);
}

// ---- a caustic: a small light above a smooth glass sphere above a diffuse floor ----

const PixelRect kUnderSphere = kCausticUnderSphere;

// lightTracingOnlyShaders() (shader_variants.h): every MIS weight is 0 but those of the light-tracing
// strategies, which are 1. Light tracing alone then estimates every path whose camera-side vertex z_1 is
// not delta and that has at most BDPT_MAX_LIGHT_VERTICES light vertices.

// The caustic on the floor is seen directly: light -> glass -> glass -> floor -> camera. With smooth
// glass the only joins of that path are at its two ends: s = 0 (the camera subpath hits the small light
// through the glass, which is what nee does too) and t = 1 (light tracing: the light subpath reaches the
// floor through the glass, and the floor point is joined to the camera). Light tracing finds it with
// every light subpath that passes through the sphere, so at equal samples bdpt's variance there must be
// far below nee's; both must converge to the same caustic (the delta vertices are weighted correctly).
TEST(Bdpt, LightTracingResolvesASmoothGlassCaustic) {
    ensureGlContext();
    Scene scene = causticScene(0.0f);
    Accumulation bdpt = render(scene, *scene.camera, Integrator::Bdpt, 24, 256, 5);
    Accumulation nee = render(scene, *scene.camera, Integrator::Nee, 24, 256, 5, 2);
    ImageEstimate eb =
        estimate(bdpt, kUnderSphere.x, kUnderSphere.y, kUnderSphere.width, kUnderSphere.height);
    ImageEstimate en = estimate(nee, kUnderSphere.x, kUnderSphere.y, kUnderSphere.width, kUnderSphere.height);
    for (int c = 0; c < 3; ++c) {
        float se =
            std::sqrt(eb.standardError[c] * eb.standardError[c] + en.standardError[c] * en.standardError[c]);
        EXPECT_NEAR(eb.mean[c], en.mean[c], 5.0f * se) << "channel " << c;
    }
    double vb = regionVariance(bdpt, kUnderSphere), vn = regionVariance(nee, kUnderSphere);
    std::printf(
        "under the sphere, 256 spp: variance of the mean summed over the region: bdpt %.4g, nee %.4g\n", vb,
        vn);
    EXPECT_LT(vb, 0.25 * vn) << "light tracing should find the caustic far more often than nee";
    EXPECT_EQ(bdpt.droppedSamples() + nee.droppedSamples(), 0u);
    // nee is too noisy here for a sharp check of the weights; light tracing alone (weight 1, every
    // other strategy 0) finds this caustic as well as bdpt does, so the two must agree block by block.
    // (This caught delta flags lost on llvmpipe, which halved the caustic.)
    Renderer lightTracing(scene, lightTracingOnlyShaders());
    Accumulation light = renderPasses(lightTracing, *scene.camera, Integrator::Bdpt, 24, 256, 5, 2);
    std::vector<float> z = blockZScores(bdpt, light, 2, kUnderSphere);
    ASSERT_GT(z.size(), 40u);
    for (float v : z) EXPECT_LT(std::abs(v), 5.0f);
}

// ---- strategy t = 1 on its own ----

// The Cornell box is all diffuse and depth 3 paths have at most 4 light vertices, so light tracing alone
// must give nee's whole image: the emitter seen directly ((1, 1), y0 facing the camera), direct light on
// the walls ((2, 1)) and the indirect bounces; this checks the camera importance, its density, the
// projection to pixels and the adjoint BSDF, and the light image's variance estimate (the z-scores).
TEST(Bdpt, LightTracingAloneConvergesToNee) {
    ensureGlContext();
    Scene scene = builtinCornellBox();
    Renderer lightTracing(scene, lightTracingOnlyShaders());
    Accumulation light = renderPasses(lightTracing, *scene.camera, Integrator::Bdpt, 32, 256, 3);
    Image cameraOnly = light.mean();
    for (size_t i = 0; i < light.sum.size(); ++i)
        ASSERT_EQ(glm::vec3(light.sum[i]), glm::vec3(0.0f)) << "the camera pass must add nothing here";
    Accumulation nee = render(scene, *scene.camera, Integrator::Nee, 32, 512, 3, 2);
    expectSameImage(light, nee, 4, 0.03f);
}

// Tiles (the viewer) launch each tile's share of the light paths, splatting anywhere: after a whole
// pass the light image holds the same paths as a whole-frame pass, summed in another order.
TEST(Bdpt, TilesGiveTheWholeFrameImage) {
    ensureGlContext();
    Scene scene = builtinCornellBox();
    Renderer renderer(scene, testShaders());
    Accumulation whole = renderPasses(renderer, *scene.camera, Integrator::Bdpt, 24, 2, 4);
    renderer.configure(renderer.settings(), *scene.camera);
    int completed = 0;
    while (completed < 2)
        if (renderer.renderTile(8)) ++completed;
    Accumulation tiled = renderer.readback();
    EXPECT_EQ(tiled.lightPathsPerPixel, 2.0);
    ASSERT_EQ(tiled.sum, whole.sum) << "the camera pass does not depend on the tiling";
    Image a = whole.mean(), b = tiled.mean();
    for (size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(a.pixels[i][c], b.pixels[i][c], 1e-4f * (1.0f + a.pixels[i][c])) << "pixel " << i;
}

// A split view with bdpt on its right half: the light paths of the whole image splat into that half
// only, which then shows what a whole bdpt render shows there; the left half has no light image.
TEST(Bdpt, SplitViewHalfEqualsAWholeRender) {
    ensureGlContext();
    Scene scene = builtinCornellBox();
    Renderer renderer(scene, testShaders());
    Accumulation whole = renderPasses(renderer, *scene.camera, Integrator::Bdpt, 24, 4, 4);
    RenderSettings s = renderer.settings();
    s.integrator = Integrator::Nee;
    s.split = SplitView{Integrator::Bdpt, 4};
    renderer.configure(s, *scene.camera);
    renderer.render(4);
    Accumulation split = renderer.readback();
    Image a = whole.mean(), b = split.mean();
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 24; ++x) {
            if (x < 12) {
                EXPECT_EQ(split.splatSum[size_t(y * 24 + x)], glm::vec4(0.0f)) << x << "," << y;
                continue;
            }
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(a.at(x, y)[c], b.at(x, y)[c], 1e-5f * (1.0f + a.at(x, y)[c])) << x << "," << y;
        }
}

// The same seed gives the same image, the light image included; another seed another one.
TEST(Bdpt, RepeatableWithAFixedSeed) {
    ensureGlContext();
    Scene scene = causticScene(0.0f);
    Renderer renderer(scene, testShaders());
    Accumulation a = renderPasses(renderer, *scene.camera, Integrator::Bdpt, 16, 4, 5, 3);
    Accumulation b = renderPasses(renderer, *scene.camera, Integrator::Bdpt, 16, 4, 5, 3);
    Accumulation c = renderPasses(renderer, *scene.camera, Integrator::Bdpt, 16, 4, 5, 4);
    EXPECT_EQ(a.sum, b.sum);
    EXPECT_EQ(a.splatSum, b.splatSum);
    EXPECT_NE(a.splatSum, c.splatSum);
    EXPECT_EQ(a.droppedSamples(), 0u);
}

}  // namespace
}  // namespace fp::test
