// nee with the light tree (`--light-selection tree`, glsl/common/light_tree.glsl) against nee choosing
// emitters by power, in a floor lit by many small lamps at different heights, some facing away from it:
// the two must converge to the same image (the tree's choice and the density MIS weighs a BSDF-sampled
// hit with must agree, and no bound may skip an emitter that lights the point), and the tree must spend
// its samples on the lamps that light each point.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "core/error.h"
#include "render_test_util.h"

namespace fp::test {
namespace {

Scene manyLamps() {
    Scene scene;
    scene.source = "many lamps";
    scene.materials.push_back(diffuseMaterial(0.5f));
    appendQuad(scene, {-4, 0, -4}, {-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, 0);  // the floor, facing up
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int i = 0; i < 32; ++i) {
        glm::vec3 c(7.0f * u(rng) - 3.5f, 0.3f + 1.2f * u(rng), 7.0f * u(rng) - 3.5f);
        glm::vec3 radiance = glm::vec3(2.0f + 18.0f * u(rng), 2.0f + 18.0f * u(rng), 2.0f + 18.0f * u(rng));
        scene.materials.push_back(lampMaterial(radiance));
        uint32_t m = uint32_t(scene.materials.size() - 1);
        const float h = 0.125f;
        if (i % 4 == 3)  // facing up, into nothing: it lights no point of the floor
            appendQuad(scene, c + glm::vec3(-h, 0, -h), c + glm::vec3(-h, 0, h), c + glm::vec3(h, 0, h),
                       c + glm::vec3(h, 0, -h), m);
        else  // facing down
            appendQuad(scene, c + glm::vec3(-h, 0, -h), c + glm::vec3(h, 0, -h), c + glm::vec3(h, 0, h),
                       c + glm::vec3(-h, 0, h), m);
    }
    return scene;
}

Camera aboveTheFloor() {
    Camera c;
    c.eye = glm::vec3(0.0f, 6.0f, -5.0f);
    c.target = glm::vec3(0.0f);
    c.fovY = 60.0f;
    return c;
}

Accumulation render(Renderer& renderer, LightSelection selection, int spp, int maxDepth, uint32_t seed) {
    return renderScene(renderer, aboveTheFloor(), Integrator::Nee, 32, spp, maxDepth, seed,
                       Sampler::Independent, LightSampling::Auto, selection);
}

// Depth 3: light reaches the floor from the lamps by light samples and by BSDF samples that hit a lamp,
// which MIS weighs with lightPdf's density of the tree's choice at the previous vertex. Catches a
// density that is not the choice's (lightPdf reading the power pmf), a bound that leaves an emitter out
// (cones not widened: the tree never picks it, and the image is darker where it shines) and an emitter
// entry that points at the wrong leaf.
TEST(LightTree, NeeConvergesToTheImageOfThePowerChoice) {
    ensureGlContext();
    Scene scene = manyLamps();
    Renderer renderer(scene, testShaders());
    Accumulation tree = render(renderer, LightSelection::Tree, 256, 3, 1);
    Accumulation power = render(renderer, LightSelection::Power, 256, 3, 2);
    expectSameImage(tree, power, 4, 0.02f, "many lamps, depth 3, tree against power");
}

// Direct light alone, the same samples per pixel: a point of the floor is lit by the few lamps above it,
// and a quarter of the lamps face away, so a choice by power wastes most of its samples. The tree must
// at least halve the variance (a tree whose importance ignored distance and orientation would be the
// power choice again).
TEST(LightTree, ChoosesTheLampsThatLightThePoint) {
    ensureGlContext();
    Scene scene = manyLamps();
    Renderer renderer(scene, testShaders());
    Accumulation tree = render(renderer, LightSelection::Tree, 64, 1, 3);
    Accumulation power = render(renderer, LightSelection::Power, 64, 1, 4);
    // Per pixel, the ratio of the variances of the mean; the median, so that the pixels at a visible
    // lamp's edge (whose noise is the pixel's coverage, which no light choice changes) do not decide.
    Image treeVariance = tree.varianceOfMean(), powerVariance = power.varianceOfMean();
    std::vector<double> ratios;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x)
            if (powerVariance.at(x, y).g > 0.0f)
                ratios.push_back(double(treeVariance.at(x, y).g) / double(powerVariance.at(x, y).g));
    ASSERT_GT(ratios.size(), 500u);  // the floor (the rest sees nothing)
    std::nth_element(ratios.begin(), ratios.begin() + long(ratios.size() / 2), ratios.end());
    double median = ratios[ratios.size() / 2];
    std::printf("  variance of the mean, tree over power: median over pixels %.3f\n", median);
    EXPECT_LT(median, 0.5);
}

// `--light-selection tree` where there is no tree is an error, not a silent choice by power.
TEST(LightTree, AskingForATreeInASceneWithoutOneIsAnError) {
    ensureGlContext();
    Scene scene = manyLamps();
    PunctualLight point;
    point.position = glm::vec3(0.0f, 2.0f, 0.0f);
    point.intensity = glm::vec3(1.0f);
    scene.punctualLights.push_back(point);
    Renderer renderer(scene, testShaders());
    RenderSettings s;
    s.width = s.height = 8;
    s.lightSelection = LightSelection::Tree;
    EXPECT_THROW(renderer.configure(s, aboveTheFloor()), Error);
    s.lightSelection = LightSelection::Auto;  // falls back to power, as documented
    EXPECT_NO_THROW(renderer.configure(s, aboveTheFloor()));
}

}  // namespace
}  // namespace fp::test
