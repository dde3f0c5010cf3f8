// Point, spot and directional lights (src/scene/scene.h, glsl/common/lights.glsl) rendered by the GPU
// integrators, against closed forms and against each other:
//   - a Lambertian plane of albedo k under a point light of intensity I has radiance k / pi I cos / r^2,
//     under a spot that times glTF's falloff (0 outside the outer cone), under a directional light of
//     irradiance E the uniform k / pi E cos; at depth 1 nee's only noise is the pixel jitter, and bdpt
//     weighs its two strategies (s = 1 and light tracing) against each other, so each must sum to it;
//     light tracing alone (lightTracingOnlyShaders, shader_variants.h) checks each light's emission sampling
//     on its own;
//   - a point light at the centre of a closed sphere of albedo k: every bounce is uniform, so the
//     radiance is I / (pi R^2) (k + k^2 + ... + k^D) at depth D;
//   - nee and bdpt converge to the same Cornell box lit by a point light, and by a spot, a directional
//     light and the lamp together;
//   - naive and bsdf cannot see such lights (nothing can hit them): they converge to the image without
//     them, and the renderer says so.
// Tolerances come from the variance each render measures (render_test_util.h), plus 1e-5 of the value
// for the shader's float arithmetic where the estimate is noise-free.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "core/log.h"
#include "render/floor_image.h"
#include "render_test_util.h"
#include "scene/builtin_scene.h"
#include "scene/procedural.h"
#include "shader_variants.h"

namespace fp::test {
namespace {

constexpr double kPi = 3.14159265358979324;
constexpr glm::dvec3 kAlbedo{0.8, 0.5, 0.3};

// A square Lambertian floor of albedo kAlbedo at y = 0, 2 `half` wide, facing up; nothing else.
Scene floorScene(float half) {
    Scene scene;
    scene.source = "floor";
    Material floor;
    floor.name = "floor";
    floor.diffuse = glm::vec3(kAlbedo);
    scene.materials.push_back(floor);
    appendQuad(scene, glm::vec3(-half, 0, -half), glm::vec3(-half, 0, half), glm::vec3(half, 0, half),
               glm::vec3(half, 0, -half), 0);
    return scene;
}

// k / pi I cos(theta) / r^2 at floor point p (normal +y) from a light at `light` whose intensity toward
// p is `intensity`.
glm::dvec3 pointLit(const glm::dvec3& p, const glm::dvec3& light, const glm::dvec3& intensity) {
    glm::dvec3 d = light - p;
    double r2 = glm::dot(d, d), cosTheta = d.y / std::sqrt(r2);
    return cosTheta > 0.0 ? kAlbedo / kPi * intensity * cosTheta / r2 : glm::dvec3(0.0);
}

// glTF's spot falloff, written out again here (not scene/punctual_light.h's): the cosine's linear ramp
// from the outer cone to the inner one, squared.
double gltfSpotFalloff(double cosTheta, double innerDegrees, double outerDegrees) {
    double ci = std::cos(innerDegrees * kPi / 180.0), co = std::cos(outerDegrees * kPi / 180.0);
    double t = std::min(1.0, std::max(0.0, (cosTheta - co) / (ci - co)));
    return t * t;
}

// The relative spread of an expected image: the test means little on a flat one.
double spread(const std::vector<glm::dvec3>& image) {
    double lo = 1e30, hi = 0.0;
    for (const glm::dvec3& v : image) {
        lo = std::min(lo, v.y);
        hi = std::max(hi, v.y);
    }
    return hi / std::max(lo, 1e-30);
}

// ---- the floor under a point light ----

constexpr int kSize = 24;

Camera obliqueCamera() {
    Camera c;
    c.eye = glm::vec3(0.0f, 3.0f, -3.0f);
    c.target = glm::vec3(0.0f, 0.0f, 0.5f);
    c.fovY = 50.0f;
    return c;
}

PunctualLight pointLight() {
    PunctualLight l;
    l.position = glm::vec3(0.7f, 2.0f, -0.4f);
    l.intensity = glm::vec3(5.0f, 10.0f, 20.0f);
    return l;
}

// Caught (each tried on a copy of the shaders, FP_RENDER_TEST_SHADERS): nee's irradiance I / r instead of
// I / r^2 (max |z| 1749); bdpt's s = 1 density zRevLast tripled (bdpt max |z| 159); light subpaths that
// leave the point light over half the sphere with the whole sphere's density (bdpt max |z| 413).
TEST(PunctualLight, PointLightOverAPlaneIsKOverPiICosOverR2) {
    ensureGlContext();
    Scene scene = floorScene(20.0f);
    scene.punctualLights = {pointLight()};
    const Camera camera = obliqueCamera();
    const glm::dvec3 light(scene.punctualLights[0].position), intensity(scene.punctualLights[0].intensity);
    std::vector<glm::dvec3> expected =
        expectedFloorImage(camera, kSize, [&](const glm::dvec3& p) { return pointLit(p, light, intensity); });
    EXPECT_GT(spread(expected), 3.0) << "the light must vary over the image";
    Renderer renderer(scene, testShaders());
    expectImage(renderScene(renderer, camera, Integrator::Nee, kSize, 64, 1, 3), expected, 4,
                "nee, point light");
    expectImage(renderScene(renderer, camera, Integrator::Bdpt, kSize, 256, 1, 4), expected, 4,
                "bdpt, point light");
    Renderer tracing(scene, lightTracingOnlyShaders());
    expectImage(renderScene(tracing, camera, Integrator::Bdpt, kSize, 512, 1, 5), expected, 4,
                "light tracing alone, point light");
}

// ---- a spot's cone ----

// The spot 2 above the floor pointing straight down, the camera above it: the image holds the inner
// cone (full intensity), the falloff ring and the dark outside.
// Caught: the falloff t instead of t^2 (nee max |z| 56, bdpt 42); bdpt's s = 1 density zRevLast tripled
// (bdpt max |z| 8.8: light tracing carries most of this image, whose camera is far from the floor).
TEST(PunctualLight, SpotLightsItsConeWithGltfsFalloff) {
    ensureGlContext();
    Scene scene = floorScene(20.0f);
    constexpr double kInner = 20.0, kOuter = 35.0;
    PunctualLight spot;
    spot.type = PunctualLightType::Spot;
    spot.position = glm::vec3(0.1f, 2.0f, -0.2f);
    spot.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    spot.intensity = glm::vec3(30.0f, 20.0f, 10.0f);
    spot.innerConeAngle = float(kInner * kPi / 180.0);
    spot.outerConeAngle = float(kOuter * kPi / 180.0);
    scene.punctualLights = {spot};
    Camera camera;
    camera.eye = glm::vec3(0.0f, 6.0f, 0.0f);
    camera.target = glm::vec3(0.0f);
    camera.up = glm::vec3(0.0f, 0.0f, 1.0f);
    camera.fovY = 40.0f;
    const glm::dvec3 light(spot.position), intensity(spot.intensity);
    auto cosToAxis = [&](const glm::dvec3& p) { return glm::normalize(p - light).y * -1.0; };
    auto lit = [&](const glm::dvec3& p) {
        return pointLit(p, light, intensity * gltfSpotFalloff(cosToAxis(p), kInner, kOuter));
    };
    std::vector<glm::dvec3> expected = expectedFloorImage(camera, kSize, lit);
    Renderer renderer(scene, testShaders());
    Accumulation nee = renderScene(renderer, camera, Integrator::Nee, kSize, 64, 1, 3);
    expectImage(nee, expected, 4, "nee, spot");

    // Pixel by pixel: wholly outside the outer cone exactly black, wholly inside the inner cone the point
    // light's value (covered by the blocks above), and the ring in between counted so that the image
    // really has all three.
    const double cosOuter = std::cos(kOuter * kPi / 180.0), cosInner = std::cos(kInner * kPi / 180.0);
    const Image mean = nee.mean();
    int outside = 0, inside = 0, ring = 0;
    for (int row = 0; row < kSize; ++row)
        for (int x = 0; x < kSize; ++x) {
            double lo = 1.0, hi = -1.0;
            for (int corner = 0; corner < 4; ++corner) {
                double c = cosToAxis(floorPoint(camera, kSize, x + corner % 2, kSize - 1 - row + corner / 2));
                lo = std::min(lo, c);
                hi = std::max(hi, c);
            }
            if (hi < cosOuter) {
                ++outside;
                EXPECT_EQ(mean.at(x, row), glm::vec3(0.0f))
                    << "outside the outer cone: pixel " << x << ", " << row;
            } else if (lo > cosInner) {
                ++inside;
            } else if (lo > cosOuter && hi < cosInner) {
                ++ring;
            }
        }
    std::printf("  pixels wholly outside the cone %d, inside the inner cone %d, in the falloff %d\n", outside,
                inside, ring);
    EXPECT_GT(outside, 100);
    EXPECT_GT(inside, 25);
    EXPECT_GT(ring, 50);

    expectImage(renderScene(renderer, camera, Integrator::Bdpt, kSize, 256, 1, 4), expected, 4, "bdpt, spot");
    Renderer tracing(scene, lightTracingOnlyShaders());
    expectImage(renderScene(tracing, camera, Integrator::Bdpt, kSize, 512, 1, 5), expected, 4,
                "light tracing alone, spot");
}

// ---- a directional light ----

// 60 degrees from the floor's normal: k / pi E cos(60) = k E / (2 pi) everywhere. The floor is small, so
// that the disk bdpt's light subpaths start from (the scene's bounding sphere's) is mostly floor in view.
// Caught: nee's direction toward the light reversed (black); bdpt's disk points drawn with r u instead of
// r sqrt(u), not uniform in area (bdpt max |z| 57).
TEST(PunctualLight, DirectionalLightGivesKOverPiECosEverywhere) {
    ensureGlContext();
    Scene scene = floorScene(3.0f);
    PunctualLight sun;
    sun.type = PunctualLightType::Directional;
    sun.direction = glm::normalize(glm::vec3(std::sqrt(3.0f), -1.0f, 0.0f));  // 60 degrees from -y
    sun.intensity = glm::vec3(2.0f, 3.0f, 4.0f);
    scene.punctualLights = {sun};
    Camera camera;
    camera.eye = glm::vec3(0.0f, 4.0f, 0.0f);
    camera.target = glm::vec3(0.0f);
    camera.up = glm::vec3(0.0f, 0.0f, 1.0f);
    camera.fovY = 50.0f;
    const glm::dvec3 value = kAlbedo / kPi * glm::dvec3(sun.intensity) * 0.5;
    std::vector<glm::dvec3> expected(size_t(kSize) * kSize, value);
    Renderer renderer(scene, testShaders());
    expectImage(renderScene(renderer, camera, Integrator::Nee, kSize, 16, 1, 3), expected, 4,
                "nee, directional");
    expectImage(renderScene(renderer, camera, Integrator::Bdpt, kSize, 256, 1, 4), expected, 4,
                "bdpt, directional");
    Renderer tracing(scene, lightTracingOnlyShaders());
    expectImage(renderScene(tracing, camera, Integrator::Bdpt, kSize, 512, 1, 5), expected, 4,
                "light tracing alone, directional");
}

// ---- energy: a point light inside a closed white furnace sphere ----

// In a sphere of radius R, cos(theta_x) cos(theta_y) / |x - y|^2 = 1 / (4 R^2) for any two points, so
// the first bounce spreads the light's power 4 pi I evenly: the irradiance from every bounce is uniform,
// I / R^2 from the light at the centre, then k I / R^2, k^2 I / R^2, ..., and the radiance after D
// bounces is I / (pi R^2) (k + k^2 + ... + k^D) everywhere. The sphere is a 64 x 128 UV sphere, whose
// facets lie up to 0.12 % inside the true one (1 / r^2 up to 0.25 % larger): the closed form holds to
// 0.3 %, which the tolerance adds to the noise.
// Caught: nee weighing its delta-light samples by the power heuristic (9 % low); bdpt counting strategy
// s = 0 for the light (27 % low).
TEST(PunctualLight, PointLightInAFurnaceSphereConservesEnergy) {
    ensureGlContext();
    constexpr float kR = 2.0f, k = 0.6f;
    constexpr int kDepth = 6;
    Scene scene;
    scene.source = "furnace sphere";
    Material white;
    white.diffuse = glm::vec3(k);
    scene.materials.push_back(white);
    appendSphere(scene, glm::vec3(0.0f), kR, 64, 128, 0, false);
    PunctualLight light;
    light.intensity = glm::vec3(1.0f, 2.0f, 3.0f);
    scene.punctualLights = {light};
    Camera camera;
    camera.eye = glm::vec3(0.3f, -0.2f, 0.4f);
    camera.target = glm::vec3(1.0f, 0.5f, -1.0f);
    camera.fovY = 70.0f;
    double series = 0.0;
    for (int n = 1; n <= kDepth; ++n) series += std::pow(double(k), n);
    Renderer renderer(scene, testShaders());
    for (Integrator integrator : {Integrator::Nee, Integrator::Bdpt}) {
        Accumulation acc = renderScene(renderer, camera, integrator, 16, 128, kDepth, 7);
        ImageEstimate e = estimate(acc);
        for (int ch = 0; ch < 3; ++ch) {
            double want = double(light.intensity[ch]) / (kPi * kR * kR) * series;
            double tolerance = 5.0 * e.standardError[ch] + 0.003 * want;
            std::printf("  %s, channel %d: %.5f, closed form %.5f (standard error %.5f)\n",
                        integratorName(integrator), ch, e.mean[ch], want, e.standardError[ch]);
            EXPECT_NEAR(e.mean[ch], want, tolerance) << integratorName(integrator) << " channel " << ch;
            EXPECT_LT(e.standardError[ch], 0.003 * want) << "sharp enough to tell the bounces apart";
        }
        EXPECT_EQ(acc.droppedSamples(), 0u);
    }
}

// ---- nee against bdpt on the Cornell box ----

Scene cornellWithout(const char* emitter) {
    Scene scene = builtinCornellBox();
    for (Material& m : scene.materials)
        if (m.name == emitter) m.emission = glm::vec3(0.0f);
    return scene;
}

// A point light under the ceiling, as bright as the lamp (4 pi I = pi Le A), the lamp switched off.
// Caught: bdpt counting strategy s = 0 for a delta light (misWeight's deltaLight ignored: bdpt 14 %
// darker, whole-image z -85).
TEST(PunctualLight, NeeAndBdptAgreeOnACornellBoxLitByAPointLight) {
    ensureGlContext();
    Scene scene = cornellWithout("light");
    PunctualLight bulb;
    bulb.position = glm::vec3(278.0f, 450.0f, 279.5f);
    bulb.intensity = glm::vec3(17.0f, 12.0f, 4.0f) * (130.0f * 105.0f / 4.0f);
    scene.punctualLights = {bulb};
    Renderer renderer(scene, testShaders());
    Accumulation bdpt = renderScene(renderer, *scene.camera, Integrator::Bdpt, 32, 256, 4, 1);
    Accumulation nee = renderScene(renderer, *scene.camera, Integrator::Nee, 32, 512, 4, 2);
    expectSameImage(bdpt, nee, 4, 0.02f, "bdpt against nee, point light");
}

// The lamp, a spot aimed at the tall block and a directional light shining in through the open front:
// three kinds of light picked by power from one cdf.
// Caught: bdpt counting strategy s = 0 for delta lights (17 to 23 % darker, whole-image z -66).
TEST(PunctualLight, NeeAndBdptAgreeWithLampSpotAndDirectionalLight) {
    ensureGlContext();
    Scene scene = builtinCornellBox();
    PunctualLight spot, sun;
    spot.type = PunctualLightType::Spot;
    spot.position = glm::vec3(100.0f, 500.0f, 100.0f);
    spot.direction = glm::normalize(glm::vec3(0.5f, -1.0f, 0.6f));
    spot.intensity = glm::vec3(60000.0f, 120000.0f, 200000.0f);
    spot.innerConeAngle = float(10.0 * kPi / 180.0);
    spot.outerConeAngle = float(25.0 * kPi / 180.0);
    sun.type = PunctualLightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.3f, -0.5f, 1.0f));
    sun.intensity = glm::vec3(3.0f, 2.5f, 2.0f);
    scene.punctualLights = {spot, sun};
    Renderer renderer(scene, testShaders());
    Accumulation bdpt = renderScene(renderer, *scene.camera, Integrator::Bdpt, 32, 256, 4, 1);
    Accumulation nee = renderScene(renderer, *scene.camera, Integrator::Nee, 32, 512, 4, 2);
    expectSameImage(bdpt, nee, 4, 0.02f, "bdpt against nee, lamp + spot + directional");
}

// ---- a caustic only light paths find ----

// The caustic scene (procedural.h) lit by a point light where its lamp was: light -> glass -> glass ->
// floor -> camera has one strategy left, light tracing (s = 0 cannot hit the light, and the delta glass
// vertices cannot be joined), so bdpt's weight for it must be 1: bdpt and light tracing alone agree
// block by block under the sphere. nee's camera paths cannot find it at all (their shadow rays stop at
// the glass): with --caustics path the floor under the sphere stays in shadow there; nee's light pass
// (--caustics light, auto's choice here) must find what bdpt finds.
// Caught: bdpt counting strategy s = 0 (misWeight's deltaLight ignored: the caustic ten times dimmer,
// max |z| 27); nee's light paths from a point light weighted by the sphere's density, not the cones'
// (caustic_casters.glsl: pdf 1 / (4 pi) in place of sampleTowardCasters' pdf: 64x bdpt's caustic).
TEST(PunctualLight, OnlyLightPathsFindThePointLightsCausticThroughGlass) {
    ensureGlContext();
    Scene scene = causticScene(0.0f);
    for (Material& m : scene.materials) m.emission = glm::vec3(0.0f);
    PunctualLight bulb;
    bulb.position = glm::vec3(0.0f, 3.0f, 0.0f);
    bulb.intensity = glm::vec3(4.0f);
    scene.punctualLights = {bulb};
    const PixelRect& r = kCausticUnderSphere;
    Renderer renderer(scene, testShaders());
    Accumulation bdpt = renderScene(renderer, *scene.camera, Integrator::Bdpt, 24, 256, 5, 1);
    Accumulation nee =
        renderScene(renderer, *scene.camera, Integrator::Nee, 24, 256, 5, 2, Sampler::Independent,
                    LightSampling::Auto, LightSelection::Auto, Caustics::Path);
    Accumulation neeLight =
        renderScene(renderer, *scene.camera, Integrator::Nee, 24, 256, 5, 4, Sampler::Independent,
                    LightSampling::Auto, LightSelection::Auto, Caustics::Light);
    expectSameImage(neeLight, bdpt, 2, 0.03f, "nee's light pass against bdpt under the sphere", &r);
    Renderer tracing(scene, lightTracingOnlyShaders());
    Accumulation light = renderScene(tracing, *scene.camera, Integrator::Bdpt, 24, 256, 5, 3);
    std::vector<float> z = blockZScores(bdpt, light, 2, r);
    ASSERT_GT(z.size(), 40u);
    float maxZ = 0.0f;
    for (float v : z) maxZ = std::max(maxZ, std::abs(v));
    double caustic = estimate(bdpt, r.x, r.y, r.width, r.height).mean.g,
           shadow = estimate(nee, r.x, r.y, r.width, r.height).mean.g;
    std::printf("  under the sphere: bdpt %.4f, nee %.4f; bdpt against light tracing alone: max |z| %.2f\n",
                caustic, shadow, maxZ);
    EXPECT_LT(maxZ, 5.0f) << "the caustic's one strategy must have weight 1";
    EXPECT_GT(caustic, 3.0 * shadow) << "the caustic (bdpt) against the shadow nee sees";
    EXPECT_EQ(bdpt.droppedSamples() + light.droppedSamples(), 0u);
}

// ---- naive and bsdf cannot see them ----

// The analytic furnace (a closed box of albedo 0.5 and emission 1: radiance 2 - 0.5^D) with a bright point
// light inside: naive and bsdf, which find light only by hitting it, still give 2 - 0.5^D, and the
// renderer warns that they cannot see it. nee, which can, gives more.
// Caught: bsdf.glsl given a light sample toward delta lights (its mean above 2 - 0.5^D), and the
// renderer's warning removed.
TEST(PunctualLight, NaiveAndBsdfConvergeToTheImageWithoutThem) {
    ensureGlContext();
    Scene scene = furnaceBox(0.5f, 1.0f);
    PunctualLight bulb;
    bulb.intensity = glm::vec3(2.0f);
    scene.punctualLights = {bulb};
    constexpr int kDepth = 3;
    const float expected = 2.0f - std::pow(0.5f, float(kDepth));
    Renderer renderer(scene, testShaders());
    for (Integrator integrator : {Integrator::Naive, Integrator::Bsdf}) {
        WarningCapture capture;
        Accumulation acc = renderScene(renderer, insideCamera(), integrator, 16, 64, kDepth, 3);
        EXPECT_TRUE(capture.contains(std::string("the ") + integratorName(integrator) +
                                     " integrator cannot see the scene's 1 point, spot or directional"))
            << (capture.messages().empty() ? "no warning" : capture.messages()[0]);
        ImageEstimate e = estimate(acc);
        for (int ch = 0; ch < 3; ++ch)
            EXPECT_NEAR(e.mean[ch], expected, 5.0f * e.standardError[ch] + 1e-5f)
                << integratorName(integrator) << " channel " << ch;
    }
    WarningCapture capture;
    Accumulation nee = renderScene(renderer, insideCamera(), Integrator::Nee, 16, 64, kDepth, 3);
    EXPECT_TRUE(capture.messages().empty()) << "nee sees them: no warning";
    EXPECT_GT(estimate(nee).mean.g, expected + 0.1f) << "the point light adds to what nee sees";
}

}  // namespace
}  // namespace fp::test
