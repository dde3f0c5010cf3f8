// Analytic answers under a uniform environment of radiance 1 (a "white furnace"):
// - a ray that escapes sees exactly the environment;
// - a convex Lambertian object of albedo a shows exactly a: nothing it reflects comes back to it;
// - a smooth glass sphere shows exactly 1: Fresnel splits energy between reflection and refraction
//   without loss, and the 1/eta^2 radiance scaling on entering is undone on leaving.
#include <gtest/gtest.h>

#include "render_test_util.h"
#include "scene/procedural.h"

namespace fp::test {
namespace {

Scene sphereInFurnace(const Material& material, bool smooth) {
    Scene scene;
    scene.source = "sphere in a white furnace";
    scene.materials.push_back(material);
    scene.environment.color = glm::vec3(1.0f);
    appendSphere(scene, glm::vec3(0.0f), 1.0f, 24, 48, 0, smooth);
    return scene;
}

Camera outsideCamera() {
    Camera c;
    c.eye = glm::vec3(0.3f, 0.5f, -4.0f);
    c.target = glm::vec3(0.0f);
    c.fovY = 35.0f;
    return c;
}

void expectFurnace(const Scene& scene, Integrator integrator, float onSphere, int maxDepth) {
    ensureGlContext();
    Renderer renderer(scene);
    Accumulation acc = renderScene(renderer, outsideCamera(), integrator, 32, 64, maxDepth);
    // Which pixels see the sphere: the depth view of the same camera.
    RenderSettings s;
    s.width = s.height = 32;
    s.view = View::Depth;
    renderer.configure(s, outsideCamera());
    renderer.render(1);
    Image depth = renderer.readback().mean();
    Image mean = acc.mean(), variance = acc.varianceOfMean();
    glm::dvec3 sum(0.0), var(0.0);
    int count = 0;
    for (size_t i = 0; i < mean.pixels.size(); ++i) {
        bool sphereAtCentre = depth.pixels[i].x > 0.0f;
        // Pixels on the silhouette mix sphere and background within the pixel: leave them out.
        int x = int(i % 32), y = int(i / 32);
        bool edge = false;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                int nx = std::clamp(x + dx, 0, 31), ny = std::clamp(y + dy, 0, 31);
                edge |= (depth.at(nx, ny).x > 0.0f) != sphereAtCentre;
            }
        if (edge) continue;
        if (!sphereAtCentre) {
            EXPECT_EQ(mean.pixels[i], glm::vec3(1.0f)) << "background pixel " << x << "," << y;
            continue;
        }
        sum += glm::dvec3(mean.pixels[i]);
        var += glm::dvec3(variance.pixels[i]);
        ++count;
    }
    ASSERT_GT(count, 100);
    for (int c = 0; c < 3; ++c) {
        double average = sum[c] / count, standardError = std::sqrt(var[c]) / count;
        EXPECT_NEAR(average, onSphere, 5.0 * standardError + 1e-5)
            << integratorName(integrator) << " channel " << c;
        EXPECT_LT(standardError, 0.01) << "too noisy to mean anything";
    }
    EXPECT_EQ(acc.droppedSamples(), 0u);
}

TEST(WhiteFurnace, ConvexLambertianSphereShowsItsAlbedo) {
    Material m;
    m.diffuse = glm::vec3(0.5f);
    for (Integrator integrator : {Integrator::Naive, Integrator::Bsdf, Integrator::Nee})
        expectFurnace(sphereInFurnace(m, false), integrator, 0.5f, 5);
}

TEST(WhiteFurnace, SmoothGlassSphereShowsExactlyTheEnvironment) {
    Material glass;
    glass.type = MaterialType::Dielectric;
    glass.ior = 1.5f;
    glass.roughness = 0.0f;
    glass.transmission = glm::vec3(1.0f);
    for (Integrator integrator : {Integrator::Bsdf, Integrator::Nee})
        expectFurnace(sphereInFurnace(glass, false), integrator, 1.0f, 100);
}

TEST(WhiteFurnace, DispersiveGlassSphereStillShowsExactlyTheEnvironment) {
    // One wavelength per path, weighed back to RGB: unbiased only if the weights average to 1 per channel.
    Material glass;
    glass.type = MaterialType::Dielectric;
    glass.ior = 1.5f;
    glass.abbeNumber = 20.0f;  // strongly dispersive
    for (Integrator integrator : {Integrator::Bsdf, Integrator::Nee})
        expectFurnace(sphereInFurnace(glass, false), integrator, 1.0f, 100);
}

TEST(WhiteFurnace, SmoothMirrorSphereShowsItsReflectance) {
    Material mirror;
    mirror.type = MaterialType::Conductor;
    mirror.specular = glm::vec3(1.0f);
    mirror.roughness = 0.0f;
    for (Integrator integrator : {Integrator::Naive, Integrator::Bsdf, Integrator::Nee})
        expectFurnace(sphereInFurnace(mirror, false), integrator, 1.0f, 5);
}

}  // namespace
}  // namespace fp::test
