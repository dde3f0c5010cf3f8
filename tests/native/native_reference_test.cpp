// The native reference (src/native) must be the default integrator's algorithm, or `fragpath bench
// --native` compares the shader with something else: its Cornell box converges to the GPU's mean, and
// with the same seed it follows the same random stream, so most pixels come out alike.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "native/native_path.h"
#include "native/native_test_util.h"
#include "pack/layout.h"
#include "render/render_test_util.h"

namespace fp::test {
namespace {

constexpr int kSize = 32, kSpp = 64, kDepth = 5;

native::Result renderNative(const Scene& scene, uint32_t seed) {
    native::Settings s;
    s.width = s.height = kSize;
    s.spp = kSpp;
    s.maxDepth = kDepth;
    s.seed = seed;
    return native::render(native::buildScene(scene, layout::bvhOptions()), *scene.camera, s);
}

class NativeReference : public CornellBoxSuite {};

TEST_F(NativeReference, ConvergesToTheGpuMeanOnTheCornellBox) {
    // Different seeds, so the two estimates are independent and their standard errors add.
    Accumulation gpu = renderScene(*renderer_, *scene_->camera, Integrator::Nee, kSize, kSpp, kDepth, 1);
    Accumulation cpu = asAccumulation(renderNative(*scene_, 2));
    ImageEstimate g = estimate(gpu), c = estimate(cpu);
    for (int ch = 0; ch < 3; ++ch) {
        float se =
            std::sqrt(g.standardError[ch] * g.standardError[ch] + c.standardError[ch] * c.standardError[ch]);
        ASSERT_GT(se, 0.0f);
        EXPECT_LT(std::abs(g.mean[ch] - c.mean[ch]), 4.0f * se)
            << "channel " << ch << ": gpu " << g.mean[ch] << ", native " << c.mean[ch] << ", se " << se;
    }
    for (float z : blockZScores(gpu, cpu, 8)) EXPECT_LT(std::abs(z), 4.5f);
}

TEST_F(NativeReference, FollowsTheShadersRandomStream) {
    // Same seed: each sample draws the same numbers for the same decisions, so a pixel differs only
    // where float rounding sends one of its paths another way (a ray grazing an edge, a roulette draw
    // at the threshold). A different use of the stream would leave almost no pixel alike.
    Accumulation gpu = renderScene(*renderer_, *scene_->camera, Integrator::Nee, kSize, 4, kDepth, 7);
    native::Settings s;
    s.width = s.height = kSize;
    s.spp = 4;
    s.maxDepth = kDepth;
    s.seed = 7;
    Image cpu =
        asAccumulation(native::render(native::buildScene(*scene_, layout::bvhOptions()), *scene_->camera, s))
            .mean();
    Image mean = gpu.mean();
    int alike = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            glm::vec3 d = glm::abs(mean.at(x, y) - cpu.at(x, y));
            float scale =
                std::max(1e-3f, std::max(mean.at(x, y).x, std::max(mean.at(x, y).y, mean.at(x, y).z)));
            alike += std::max(d.x, std::max(d.y, d.z)) <= 1e-3f * scale;
        }
    EXPECT_GE(alike, kSize * kSize * 9 / 10) << alike << " of " << kSize * kSize << " pixels alike";
}

TEST(NativeReferenceScene, RejectsWhatItDoesNotImplement) {
    Scene scene = builtinCornellBox();
    ASSERT_FALSE(native::unsupportedFeature(scene));
    Scene metal = scene;
    metal.materials[0].type = MaterialType::Conductor;
    EXPECT_THROW(native::buildScene(metal, layout::bvhOptions()), Error);
    // A textured Lambertian material: the reference would render it untextured.
    Scene textured = scene;
    textured.textures.push_back({"grey.png", Rgba8Image{}});
    textured.materials[0].diffuseTexture = 0;
    EXPECT_THROW(native::buildScene(textured, layout::bvhOptions()), Error);
    EXPECT_TRUE(native::unsupportedFeature(textured));
    // A point light: the reference samples emissive triangles only.
    Scene lit = scene;
    lit.punctualLights.push_back(PunctualLight{});
    EXPECT_THROW(native::buildScene(lit, layout::bvhOptions()), Error);
    EXPECT_TRUE(native::unsupportedFeature(lit));
}

}  // namespace
}  // namespace fp::test
