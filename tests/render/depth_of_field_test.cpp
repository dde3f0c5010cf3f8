// Thin-lens depth of field (Camera::aperture and Camera::focusDistance, src/scene/scene.h;
// glsl/common/camera.glsl), checked against thin-lens geometry and against the pinhole, never against
// a copy of the shader's formulas:
// - the camera rays, read back through a probe pass: a pinhole's are bit for bit cameraRay's and draw
//   no lens number; a lens's start on the lens disc, uniformly, and cross the plane of focus where the
//   pinhole ray through the same film point does;
// - rendered images of three small emitters, one on the plane of focus, one behind it and one in front
//   of it, each in its own colour channel: the one on the plane stays as sharp as through a pinhole,
//   the others spread into discs whose radius is the circle of confusion, measured from the image's
//   second moments, and no light is lost or gained;
// - bdpt, whose light tracing joins vertices to points of the lens, converges to nee's image.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "core/error.h"
#include "gl/gl.h"
#include "gl/program.h"
#include "render_test_util.h"
#include "scene/builtin_scene.h"
#include "scene/procedural.h"
#include "shader_variants.h"

namespace fp::test {
namespace {

// ---- the camera rays, through glsl/tests/camera_probe.frag.glsl ----

// The camera's basis from its definition (scene.h): forward toward the target, right = forward x up,
// the image plane at depth 1 spanning tan(fov / 2) (times the aspect ratio) each way.
struct Basis {
    glm::dvec3 eye, forward, right, up;  // right, up: unit
    double tanHalf, aspect, lensRadius, focus;
};
Basis basisOf(const Camera& c, int width, int height) {
    Basis b;
    b.eye = glm::dvec3(c.eye);
    b.forward = glm::normalize(glm::dvec3(c.target) - b.eye);
    b.right = glm::normalize(glm::cross(b.forward, glm::dvec3(c.up)));
    b.up = glm::cross(b.right, b.forward);
    b.tanHalf = std::tan(0.5 * glm::radians(double(c.fovY)));
    b.aspect = double(width) / double(height);
    b.lensRadius = 0.5 * double(c.aperture);
    b.focus = c.focusDistance ? double(*c.focusDistance) : glm::length(glm::dvec3(c.target) - b.eye);
    return b;
}

struct ProbeSample {
    glm::dvec3 origin, dir, position;  // position: the jittered film position in pixels (z unused)
    uint32_t counter;                  // the stream's counter after the camera ray
    bool pinhole;                      // the ray is bit for bit cameraRay's
};

// One probe draw: sample `sample` of every pixel of a width x height image.
std::vector<ProbeSample> probe(const Camera& camera, int width, int height, Sampler sampler,
                               uint32_t sample) {
    ensureGlContext();
    Program program(testShaders(), "passes/fullscreen.vert.glsl", "tests/camera_probe.frag.glsl",
                    {{"SAMPLER", sampler == Sampler::Sobol ? "1" : "0"}});
    Basis b = basisOf(camera, width, height);
    program.use();
    program.set("uSeed", 7u);
    program.set("uSample", sample);
    program.set("uCameraEye", camera.eye);
    program.set("uCameraForward", glm::vec3(b.forward));
    program.set("uCameraRight", glm::vec3(b.right * b.tanHalf * b.aspect));
    program.set("uCameraUp", glm::vec3(b.up * b.tanHalf));
    program.set("uResolution", glm::vec2(width, height));
    program.set("uLensRadius", float(b.lensRadius));
    program.set("uFocusDistance", float(b.focus));

    constexpr int kOutputs = 3;
    GLuint textures[kOutputs], framebuffer, vertexArray;
    glGenTextures(kOutputs, textures);
    glGenFramebuffers(1, &framebuffer);
    glGenVertexArrays(1, &vertexArray);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    GLenum buffers[kOutputs];
    for (int i = 0; i < kOutputs; ++i) {
        glBindTexture(GL_TEXTURE_2D, textures[i]);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + i), GL_TEXTURE_2D, textures[i],
                               0);
        buffers[i] = GLenum(GL_COLOR_ATTACHMENT0 + i);
    }
    glDrawBuffers(kOutputs, buffers);
    glViewport(0, 0, width, height);
    glDisable(GL_BLEND);
    glBindVertexArray(vertexArray);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    std::vector<glm::vec4> out[kOutputs];
    for (int i = 0; i < kOutputs; ++i) {
        out[i].resize(size_t(width) * size_t(height));
        glReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + i));
        glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, out[i].data());
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteVertexArrays(1, &vertexArray);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteTextures(kOutputs, textures);
    if (glGetError() != GL_NO_ERROR) throw Error("camera probe: GL error");
    std::vector<ProbeSample> samples;
    for (size_t p = 0; p < out[0].size(); ++p)
        samples.push_back({glm::dvec3(out[0][p]), glm::dvec3(out[1][p]), glm::dvec3(out[2][p]),
                           uint32_t(out[0][p].w), out[1][p].w == 1.0f});
    return samples;
}

Camera obliqueCamera(float aperture, std::optional<float> focus) {
    Camera c;
    c.eye = {1.0f, 2.0f, 3.0f};
    c.target = {-0.5f, 0.25f, 0.1f};
    c.up = {0.0f, 0.0f, 2.0f};
    c.fovY = 50.0f;
    c.aperture = aperture;
    c.focusDistance = focus;
    return c;
}

// The stream's counter after the jitter alone: one pair, with either sampler.
constexpr uint32_t kCounterAfterJitter = 1u;

// Aperture 0 is the pinhole camera as it was before lenses: the very same rays (whatever the focus
// distance says), and no number drawn for a lens, so that every later dimension of the path is where it
// was and images are bit for bit the same. (Breaking primaryRay to always go through cameraLensRay makes
// the rays differ in their last bits; drawing the lens with rand2() moves the counter.)
TEST(DepthOfFieldRays, APinholeDrawsNoLensNumberAndKeepsItsRays) {
    for (Sampler sampler : {Sampler::Sobol, Sampler::Independent})
        for (std::optional<float> focus : {std::optional<float>(), std::optional<float>(0.7f)}) {
            Camera camera = obliqueCamera(0.0f, focus);
            std::vector<ProbeSample> rays = probe(camera, 40, 30, sampler, 5);
            size_t bad = 0;
            for (const ProbeSample& r : rays)
                if (!r.pinhole || r.origin != glm::dvec3(camera.eye) || r.counter != kCounterAfterJitter)
                    ++bad;
            EXPECT_EQ(bad, 0u) << samplerName(sampler) << (focus ? ", focus set" : "");
        }
}

// With a lens, every ray starts on the lens (the disc of radius aperture / 2 about the eye, across the
// view direction) and passes through the point where the pinhole ray through its film position meets
// the plane of focus (thin-lens optics: that film point is the image of that point); the lens point
// comes from the lens's own pair, so the counter is still the jitter's alone. The lens points are
// uniform over the disc: half of them inside radius r / sqrt(2), a quarter in each quadrant, centred.
TEST(DepthOfFieldRays, LensRaysStartOnTheLensAndMeetThePinholeRayOnThePlaneOfFocus) {
    for (Sampler sampler : {Sampler::Sobol, Sampler::Independent}) {
        const int width = 64, height = 48;
        Camera camera = obliqueCamera(0.6f, 2.5f);
        Basis b = basisOf(camera, width, height);
        double inner = 0.0, quadrant[4] = {0, 0, 0, 0};
        glm::dvec2 mean(0.0);
        size_t n = 0;
        for (uint32_t sample = 0; sample < 4; ++sample) {
            std::vector<ProbeSample> rays = probe(camera, width, height, sampler, sample);
            for (const ProbeSample& r : rays) {
                glm::dvec3 offset = r.origin - b.eye;
                ASSERT_LT(std::abs(glm::dot(offset, b.forward)), 1e-5) << "the lens is across the view";
                glm::dvec2 lens(glm::dot(offset, b.right), glm::dot(offset, b.up));
                ASSERT_LE(glm::length(lens), b.lensRadius * (1.0 + 1e-5)) << "on the lens";
                ASSERT_EQ(r.counter, kCounterAfterJitter) << "the lens has a pair of its own";
                // Where the pinhole ray through this film position meets the plane of focus.
                glm::dvec2 ndc(2.0 * r.position.x / width - 1.0, 2.0 * r.position.y / height - 1.0);
                glm::dvec3 focusPoint =
                    b.eye +
                    b.focus * (b.forward + ndc.x * b.tanHalf * b.aspect * b.right + ndc.y * b.tanHalf * b.up);
                glm::dvec3 toFocus = focusPoint - r.origin;
                double miss = glm::length(toFocus - glm::dot(toFocus, r.dir) * r.dir);
                ASSERT_LT(miss, 2e-5 * b.focus) << "the ray misses the focus point by " << miss;
                ASSERT_GT(glm::dot(toFocus, r.dir), 0.0);
                inner += glm::length(lens) < b.lensRadius / std::sqrt(2.0) ? 1.0 : 0.0;
                quadrant[(lens.x >= 0.0 ? 1 : 0) + (lens.y >= 0.0 ? 2 : 0)] += 1.0;
                mean += lens / b.lensRadius;
                ++n;
            }
        }
        double count = double(n);
        // Four standard deviations of independent points (Sobol points are more even still).
        EXPECT_NEAR(inner / count, 0.5, 4.0 * std::sqrt(0.25 / count)) << samplerName(sampler);
        for (double q : quadrant)
            EXPECT_NEAR(q / count, 0.25, 4.0 * std::sqrt(0.1875 / count)) << samplerName(sampler);
        // Each coordinate of a uniform point of the unit disc has variance 1/4.
        EXPECT_NEAR(mean.x / count, 0.0, 4.0 * std::sqrt(0.25 / count)) << samplerName(sampler);
        EXPECT_NEAR(mean.y / count, 0.0, 4.0 * std::sqrt(0.25 / count)) << samplerName(sampler);
    }
}

// ---- the circle of confusion, measured in rendered images ----

// A camera at the origin looking along +z, 30 degrees high, and three small square emitters facing it
// on a black background: red on the plane of focus (depth f), green behind it (2 f), blue in front of it
// (0.6 f), each about 2.5 pixels across through a pinhole and at its own place in the image.
constexpr int kSize = 96;
constexpr float kFov = 30.0f, kFocus = 4.0f;
const float kDepths[3] = {kFocus, 2.0f * kFocus, 0.6f * kFocus};

double pixelsPerUnitAtDepth(double depth) {
    return 0.5 * kSize / (depth * std::tan(0.5 * glm::radians(double(kFov))));
}

Scene threeEmitters() {
    Scene scene;
    scene.source = "three emitters at three depths";
    const glm::vec2 ndc[3] = {{0.45f, 0.45f}, {-0.45f, 0.45f}, {0.0f, -0.45f}};
    for (int i = 0; i < 3; ++i) {
        glm::vec3 radiance(0.0f);
        radiance[i] = 10.0f;
        scene.materials.push_back(lampMaterial(radiance));
        float d = kDepths[i];
        float half = 0.5f * float(2.5 / pixelsPerUnitAtDepth(d));
        float tanHalf = std::tan(0.5f * glm::radians(kFov));
        glm::vec3 c(ndc[i].x * tanHalf * d, ndc[i].y * tanHalf * d, d);
        // Counter-clockwise as seen from the camera (from -z): the emitting front faces the eye.
        appendQuad(scene, c + glm::vec3(-half, -half, 0.0f), c + glm::vec3(-half, half, 0.0f),
                   c + glm::vec3(half, half, 0.0f), c + glm::vec3(half, -half, 0.0f), uint32_t(i));
    }
    return scene;
}

Camera lensCamera(float aperture) {
    Camera c;
    c.eye = glm::vec3(0.0f);
    c.target = glm::vec3(0.0f, 0.0f, 1.0f);  // 1 away: the focus distance is given
    c.fovY = kFov;
    c.aperture = aperture;
    c.focusDistance = kFocus;
    return c;
}

// Light, centroid and second moment about it (x^2 + y^2, pixels^2) of one channel of an image, with
// their standard errors from the pixels' measured variances (pixels are independent with the
// independent sampler; to first order, an error dI_j of pixel j moves the flux by dI_j, the centroid by
// dI_j (p_j - c) / F and the moment by dI_j (|p_j - c|^2 - M) / F).
struct Spot {
    double flux = 0.0, moment = 0.0;
    glm::dvec2 centre{0.0};
    double fluxError = 0.0, centreError = 0.0, momentError = 0.0;
};
Spot spot(const Accumulation& acc, int channel) {
    Image mean = acc.mean(), variance = acc.varianceOfMean();
    Spot s;
    glm::dvec2 sum(0.0);
    for (int y = 0; y < mean.height; ++y)
        for (int x = 0; x < mean.width; ++x) {
            double v = mean.at(x, y)[channel];
            s.flux += v;
            sum += v * glm::dvec2(x + 0.5, y + 0.5);
        }
    s.centre = sum / s.flux;
    for (int y = 0; y < mean.height; ++y)
        for (int x = 0; x < mean.width; ++x) {
            glm::dvec2 d = glm::dvec2(x + 0.5, y + 0.5) - s.centre;
            s.moment += mean.at(x, y)[channel] * glm::dot(d, d) / s.flux;
        }
    double centreVariance = 0.0, momentVariance = 0.0, fluxVariance = 0.0;
    for (int y = 0; y < mean.height; ++y)
        for (int x = 0; x < mean.width; ++x) {
            double var = variance.at(x, y)[channel];
            glm::dvec2 d = glm::dvec2(x + 0.5, y + 0.5) - s.centre;
            fluxVariance += var;
            centreVariance += var * glm::dot(d, d) / (s.flux * s.flux);
            double r2 = glm::dot(d, d) - s.moment;
            momentVariance += var * r2 * r2 / (s.flux * s.flux);
        }
    s.fluxError = std::sqrt(fluxVariance);
    s.centreError = std::sqrt(centreVariance);
    s.momentError = std::sqrt(momentVariance);
    return s;
}

Accumulation renderEmitters(Renderer& renderer, Integrator integrator, float aperture, int spp) {
    RenderSettings s;
    s.width = s.height = kSize;
    s.integrator = integrator;
    s.maxDepth = 0;  // emitters seen directly: the image is the lens's image of them, nothing else
    s.seed = 3;
    s.samplesPerPass = 16;
    s.sampler = Sampler::Independent;  // the standard errors take pixels' errors as independent
    renderer.configure(s, lensCamera(aperture));
    renderer.render(spp);
    Accumulation acc = renderer.readback();
    EXPECT_EQ(acc.droppedSamples(), 0u);
    return acc;
}

// A point at depth d is imaged by the thin lens as a uniform disc on the plane of focus of radius
// r |d - f| / d (r = aperture / 2: the rays from the lens's rim through the point, continued to depth
// f); the image plane sees that plane at pixelsPerUnitAtDepth(f). The emitters are fronto-parallel, so
// each image is the pinhole's image convolved with that disc: the flux stays, the centroid stays, and
// the second moment x^2 + y^2 grows by R^2 / 2, that of a uniform disc of radius R. On the plane of
// focus R = 0: no growth at all. Tolerances: 5 standard errors, plus 1% of R and 0.05 px^2 for what
// the pixels' box filter does to moments of sharp-edged images.
void expectCirclesOfConfusion(Renderer& renderer, Integrator integrator, const std::vector<float>& apertures,
                              int spp, const char* what) {
    Accumulation pinhole = renderEmitters(renderer, integrator, 0.0f, spp);
    Spot sharp[3];
    for (int c = 0; c < 3; ++c) sharp[c] = spot(pinhole, c);
    for (float aperture : apertures) {
        Accumulation image = renderEmitters(renderer, integrator, aperture, spp);
        for (int c = 0; c < 3; ++c) {
            Spot s = spot(image, c);
            double d = kDepths[c];
            double expected = 0.5 * aperture * std::abs(d - kFocus) / d * pixelsPerUnitAtDepth(kFocus);
            double growth = s.moment - sharp[c].moment;
            double growthError = std::hypot(s.momentError, sharp[c].momentError);
            double measured = std::sqrt(std::max(0.0, 2.0 * growth));
            std::printf(
                "%s, aperture %.2f, depth %.1f: circle of confusion radius %.3f +- %.3f px, expected %.3f; "
                "flux ratio %.4f +- %.4f\n",
                what, double(aperture), d, measured, expected > 0.0 ? growthError / expected : 0.0, expected,
                s.flux / sharp[c].flux, std::hypot(s.fluxError, sharp[c].fluxError) / sharp[c].flux);
            EXPECT_NEAR(s.flux, sharp[c].flux, 5.0 * std::hypot(s.fluxError, sharp[c].fluxError))
                << what << ": light is neither lost nor gained";
            EXPECT_LT(glm::length(s.centre - sharp[c].centre),
                      5.0 * std::hypot(s.centreError, sharp[c].centreError) + 0.02)
                << what << ": the blur is centred";
            if (expected == 0.0) {
                EXPECT_LT(std::abs(growth), 5.0 * growthError + 0.05)
                    << what << ": on the plane of focus the image stays as sharp as the pinhole's";
            } else {
                // dR = d(growth) / R.
                EXPECT_NEAR(measured, expected, 5.0 * growthError / expected + 0.01 * expected)
                    << what << ", depth " << d;
                EXPECT_LT(5.0 * growthError / expected, 0.05 * expected) << "too noisy to mean much";
            }
        }
    }
}

TEST(DepthOfField, CirclesOfConfusionMatchThinLensGeometryNee) {
    ensureGlContext();
    Renderer renderer(threeEmitters(), testShaders());
    expectCirclesOfConfusion(renderer, Integrator::Nee, {0.3f, 0.6f}, 1024, "nee");
}

// bdpt at depth 0: the camera subpath's hits (s = 0) and light tracing (s = 1, t = 1: points of the
// emitters joined to points of the lens, splatted where they land), weighed by MIS.
TEST(DepthOfField, CirclesOfConfusionMatchThinLensGeometryBdpt) {
    ensureGlContext();
    Renderer renderer(threeEmitters(), testShaders());
    expectCirclesOfConfusion(renderer, Integrator::Bdpt, {0.6f}, 64, "bdpt");
}

// Light tracing alone (every other strategy weighted 0): the lens point toward each emitter point and
// the pixel its ray comes from (projectThroughLens) form the whole image.
TEST(DepthOfField, CirclesOfConfusionMatchThinLensGeometryLightTracing) {
    ensureGlContext();
    Renderer renderer(threeEmitters(), lightTracingOnlyShaders());
    expectCirclesOfConfusion(renderer, Integrator::Bdpt, {0.6f}, 128, "light tracing");
}

// ---- bdpt against nee ----

// The Cornell box through a wide lens focused inside it: bdpt's strategies, light tracing with
// its lens points among them, must converge to nee's image, block by block within the noise each
// measures. (Breaking light tracing's lens, e.g. joining to the eye while the camera rays leave from
// the lens, or weighting it with the pinhole's density at the eye, fails this.)
Accumulation renderCornell(Renderer& renderer, Integrator integrator, int spp, uint32_t seed) {
    RenderSettings s;
    s.width = s.height = 32;
    s.integrator = integrator;
    s.maxDepth = 3;
    s.seed = seed;
    s.samplesPerPass = 16;
    s.sampler = Sampler::Independent;  // the z-scores take pixels' errors as independent
    Camera camera = *builtinCornellBox().camera;
    // Scene units: the box is 555 wide and deep, its open side 800 in front of the eye. Focused in the
    // middle of the box, a lens this wide blurs the back wall and the open side's edges over 2 pixels
    // of this 32-pixel image, the lamp over half a pixel.
    camera.aperture = 300.0f;
    camera.focusDistance = 1000.0f;
    renderer.configure(s, camera);
    renderer.render(spp);
    return renderer.readback();
}

TEST(DepthOfField, BdptConvergesToNeeThroughALens) {
    ensureGlContext();
    Scene scene = builtinCornellBox();
    Renderer renderer(scene, testShaders());
    Accumulation bdpt = renderCornell(renderer, Integrator::Bdpt, 256, 1);
    Accumulation nee = renderCornell(renderer, Integrator::Nee, 512, 2);
    expectSameImage(bdpt, nee, 4, 0.02f, "bdpt vs nee, thin lens");
}

TEST(DepthOfField, LightTracingAloneConvergesToNeeThroughALens) {
    ensureGlContext();
    Scene scene = builtinCornellBox();
    Renderer lightTracing(scene, lightTracingOnlyShaders());
    Accumulation light = renderCornell(lightTracing, Integrator::Bdpt, 256, 1);
    Renderer renderer(scene, testShaders());
    Accumulation nee = renderCornell(renderer, Integrator::Nee, 512, 2);
    expectSameImage(light, nee, 4, 0.03f, "light tracing vs nee, thin lens");
}

// ---- the renderer's side ----

// A pinhole's image does not depend on the focus distance (bit for bit), and a lens changes the image.
TEST(DepthOfField, APinholeIgnoresTheFocusDistance) {
    ensureGlContext();
    Scene scene = builtinCornellBox();
    Renderer renderer(scene, testShaders());
    auto sums = [&](float aperture, std::optional<float> focus) {
        RenderSettings s;
        s.width = s.height = 24;
        s.samplesPerPass = 4;
        Camera camera = *scene.camera;
        camera.aperture = aperture;
        camera.focusDistance = focus;
        renderer.configure(s, camera);
        renderer.render(4);
        return renderer.readback().sum;
    };
    std::vector<glm::vec4> plain = sums(0.0f, std::nullopt);
    EXPECT_EQ(sums(0.0f, 300.0f), plain);
    EXPECT_NE(sums(40.0f, 300.0f), plain);
}

TEST(DepthOfField, TheRendererRefusesABadLens) {
    ensureGlContext();
    Scene scene = builtinCornellBox();
    Renderer renderer(scene, testShaders());
    RenderSettings s;
    s.width = s.height = 8;
    Camera camera = *scene.camera;
    camera.aperture = -1.0f;
    EXPECT_THROW(renderer.configure(s, camera), Error);
    camera.aperture = std::nanf("");
    EXPECT_THROW(renderer.configure(s, camera), Error);
    camera.aperture = 10.0f;
    camera.focusDistance = 0.0f;
    EXPECT_THROW(renderer.configure(s, camera), Error);
    camera.focusDistance = 500.0f;
    EXPECT_NO_THROW(renderer.configure(s, camera));
}

}  // namespace
}  // namespace fp::test
