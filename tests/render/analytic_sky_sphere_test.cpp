// Issue 35: a convex object under a uniform sky sees nothing but the sky, so a Lambertian one of
// albedo a reflects a L at every point and every depth from 1 on (a ray leaving it never meets it
// again), and the sky seen directly is L. Every integrator, to 0.05 % (analytic_reference.h). The
// sphere is flat-shaded: smooth shading normals would send some rays back into the facets, and a
// tessellated sphere is convex only with its facets' own normals.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "render/analytic_reference.h"
#include "render/floor_image.h"
#include "render_test_util.h"

namespace fp::test {
namespace {

constexpr glm::vec3 kSphereAlbedo{0.8f, 0.5f, 0.3f};
constexpr glm::vec3 kSkyRadiance{0.5f, 1.0f, 2.0f};

Scene sphereUnderUniformSky() {
    Scene scene = sphereInFurnace(diffuseMaterial(1.0f), false);
    scene.materials[0].diffuse = kSphereAlbedo;
    scene.environment.color = kSkyRadiance;
    return scene;
}

// 1.5 from the unit sphere's centre with a 60 degree field: every pixel sees the sphere, out to 71
// degrees from its normal in the image's corners (the test checks that it sees nothing else).
Camera closeUpCamera() {
    Camera c;
    c.eye = glm::vec3(0.0f, 0.0f, -1.5f);
    c.target = glm::vec3(0.0f);
    c.fovY = 60.0f;
    return c;
}

// The same camera turned round: the sky alone.
Camera skyCamera() {
    Camera c = closeUpCamera();
    c.target = glm::vec3(0.0f, 0.0f, -3.0f);
    return c;
}

// Whether every ray through the image's corners passes the centre closer than the nearest facet's
// plane (then every ray through the image hits the tessellated sphere: its facets bound a convex set
// holding that inner ball).
bool imageInsideSphere(const Scene& scene, const Camera& camera) {
    double inner = 1.0;
    for (const Triangle& t : scene.triangles)
        inner = std::min(
            inner, std::abs(glm::dot(glm::normalize(glm::dvec3(t.geometricNormal())), glm::dvec3(t.p[0]))));
    for (double x : {0.0, double(kAnalyticSize)})
        for (double y : {0.0, double(kAnalyticSize)}) {
            glm::dvec3 d = cameraDirection(camera, kAnalyticSize, x, y), toCentre = -glm::dvec3(camera.eye);
            double along = glm::dot(toCentre, d);
            if (glm::length(toCentre - along * d) >= inner) return false;
        }
    return true;
}

class AnalyticSkySphere : public ::testing::TestWithParam<AnalyticVariant> {};

TEST_P(AnalyticSkySphere, ReflectsAlbedoTimesSkyAtEveryDepth) {
    ensureGlContext();
    const AnalyticVariant v = GetParam();
    const Scene scene = sphereUnderUniformSky();
    ASSERT_TRUE(imageInsideSphere(scene, closeUpCamera())) << "the camera must see the sphere alone";
    Renderer renderer(scene, testShaders());
    const glm::dvec3 sky(kSkyRadiance), reflected = glm::dvec3(kSphereAlbedo) * sky;
    for (int depth : {1, 5})
        expectAnalytic(renderer, closeUpCamera(), v, depth, uniformImage(reflected),
                       variantName(v) + ", sphere at depth " + std::to_string(depth));
    expectAnalytic(renderer, skyCamera(), v, 1, uniformImage(sky), variantName(v) + ", sky");
}

// Samples per pixel of each replicate: bsdf's cosine-distributed directions make every path a L
// exactly; naive's uniform ones leave the cosine (relative noise 0.58 per path); nee weighs uniform
// sky directions against them; bdpt's light paths from the sky leave it nearly noise-free too.
INSTANTIATE_TEST_SUITE_P(Integrators, AnalyticSkySphere,
                         ::testing::Values(AnalyticVariant{Integrator::Naive, 256},
                                           AnalyticVariant{Integrator::Bsdf, 16},
                                           AnalyticVariant{Integrator::Nee, 64},
                                           AnalyticVariant{Integrator::Bdpt, 16, LightSampling::Auto,
                                                           LightSelection::Auto, Caustics::Auto, 64}),
                         variantTestName);

}  // namespace
}  // namespace fp::test
