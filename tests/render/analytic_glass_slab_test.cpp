// Issue 35: a smooth glass slab (index n = 1.5, two parallel faces) between the camera and a large
// emitter of radiance L, nothing else (what the slab reflects back finds only the black void). Light
// crosses it after 2k reflections inside for every k >= 0, each face letting 1 - R through, so
// T = (1 - R)^2 sum_k R^2k = (1 - R) / (1 + R), 2n / (n^2 + 1) = 0.923077 at normal incidence where
// R = ((n - 1) / (n + 1))^2 = 0.04 (Born & Wolf, Principles of Optics, 1.5.3; the renderer's
// unpolarised Fresnel at each face, as pbrt-v4 eq. 9.5). A path with 2k reflections reaches the emitter
// at depth 2 + 2k, so at max depth D the sum stops at k = floor((D - 2) / 2): 0.9216 at depth 2 and 3,
// 0.9216 x 1.0016 = 0.92307456 at 4 and 5 (2.6e-6 short of the whole sum). Every integrator, to
// 0.05 % of that truncated sum (analytic_reference.h), at depth 2 (which the whole sum would fail by
// 0.16 %) and 5.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "render/analytic_reference.h"
#include "render/floor_image.h"
#include "render_test_util.h"

namespace fp::test {
namespace {

constexpr glm::vec3 kEmitterRadiance{1.0f, 2.0f, 4.0f};
constexpr float kIor = 1.5f;

// The slab: 10 x 10, 0.2 thick, between z = 0 and 0.2; the emitter: 10 x 10 at z = 1, facing -z.
Scene glassSlab() {
    Scene scene;
    scene.source = "glass slab";
    Material glass;
    glass.name = "glass";
    glass.type = MaterialType::Dielectric;
    glass.ior = kIor;
    glass.transmission = glm::vec3(1.0f);
    glass.roughness = 0.0f;
    scene.materials = {glass, lampMaterial(kEmitterRadiance)};
    appendBox(scene, glm::vec3(-5.0f, -5.0f, 0.0f), glm::vec3(5.0f, 5.0f, 0.2f), 0);
    // Counter-clockwise seen from -z: its front face, the emitting one, toward the slab.
    appendQuad(scene, glm::vec3(-5.0f, -5.0f, 1.0f), glm::vec3(-5.0f, 5.0f, 1.0f),
               glm::vec3(5.0f, 5.0f, 1.0f), glm::vec3(5.0f, -5.0f, 1.0f), 1);
    return scene;
}

// Looking straight through the slab with a 2 degree field: at most 1.4 degrees off normal incidence,
// where R differs from 0.04 by 1e-7 (each pixel is checked against its own angles all the same).
Camera throughSlabCamera() {
    Camera c;
    c.eye = glm::vec3(0.0f, 0.0f, -1.0f);
    c.target = glm::vec3(0.0f, 0.0f, 1.0f);
    c.fovY = 2.0f;
    return c;
}

// Unpolarised Fresnel reflectance from air into index n at cos(theta_i) = cosI (Born & Wolf 1.5.2,
// the average of the s and p reflectances); the way out at the refracted angle reflects the same.
double fresnel(double cosI, double n) {
    double sinT2 = (1.0 - cosI * cosI) / (n * n), cosT = std::sqrt(1.0 - sinT2);
    double rs = (cosI - n * cosT) / (cosI + n * cosT), rp = (n * cosI - cosT) / (n * cosI + cosT);
    return 0.5 * (rs * rs + rp * rp);
}

// The slab's transmittance at cos(theta) = cosI, with the reflections inside a depth-D path can take.
double truncatedTransmittance(double cosI, int maxDepth) {
    double r = fresnel(cosI, kIor), sum = 0.0;
    for (int k = 0; 2 + 2 * k <= maxDepth; ++k) sum += std::pow(r, 2.0 * k);
    return (1.0 - r) * (1.0 - r) * sum;
}

// Each pixel's expected mean: L times the transmittance at its rays' angles.
std::vector<glm::dvec3> expectedSlabImage(const Camera& camera, int maxDepth) {
    return pixelAverages(kAnalyticSize, [&](double x, double y) {
        double cosI = cameraDirection(camera, kAnalyticSize, x, y).z;
        return glm::dvec3(kEmitterRadiance) * truncatedTransmittance(cosI, maxDepth);
    });
}

TEST(AnalyticGlassSlab, TheClosedFormsGiveTheWorkedValues) {
    EXPECT_NEAR(fresnel(1.0, 1.5), 0.04, 1e-15);
    EXPECT_NEAR(truncatedTransmittance(1.0, 2), 0.9216, 1e-12);
    EXPECT_NEAR(truncatedTransmittance(1.0, 5), 0.9216 * 1.0016, 1e-12);
    EXPECT_NEAR(truncatedTransmittance(1.0, 200), 2.0 * 1.5 / (1.5 * 1.5 + 1.0), 1e-12);
    EXPECT_GT(truncatedTransmittance(1.0, 200) / truncatedTransmittance(1.0, 2) - 1.0,
              3.0 * kAnalyticTolerance)
        << "depth 2 must be told from the whole sum";
}

class AnalyticGlassSlab : public ::testing::TestWithParam<AnalyticVariant> {};

TEST_P(AnalyticGlassSlab, TransmitsTheTruncatedFresnelSeries) {
    ensureGlContext();
    const AnalyticVariant v = GetParam();
    const Scene scene = glassSlab();
    ASSERT_LT(scene.triangles.back().geometricNormal().z, 0.0f) << "the emitter must face the slab";
    Renderer renderer(scene, testShaders());
    const Camera camera = throughSlabCamera();
    // Every integrator follows the same delta chain (measured: bit for bit the same images), so the
    // depth convention is checked once per camera-path loop; the light passes cost, and run at 5 alone.
    const bool lightPaths = v.integrator == Integrator::Bdpt || v.caustics == Caustics::Light;
    for (int depth : lightPaths ? std::vector<int>{5} : std::vector<int>{2, 5})
        expectAnalytic(renderer, camera, v, depth, expectedSlabImage(camera, depth),
                       variantName(v) + " at depth " + std::to_string(depth));
}

INSTANTIATE_TEST_SUITE_P(Integrators, AnalyticGlassSlab,
                         ::testing::Values(AnalyticVariant{Integrator::Naive, 256},
                                           AnalyticVariant{Integrator::Bsdf, 256},
                                           AnalyticVariant{Integrator::Nee, 256, LightSampling::Auto,
                                                           LightSelection::Auto, Caustics::Path},
                                           AnalyticVariant{Integrator::Nee, 256, LightSampling::Auto,
                                                           LightSelection::Auto, Caustics::Light},
                                           AnalyticVariant{Integrator::Bdpt, 256, LightSampling::Auto,
                                                           LightSelection::Auto, Caustics::Auto, 64}),
                         variantTestName);

}  // namespace
}  // namespace fp::test
