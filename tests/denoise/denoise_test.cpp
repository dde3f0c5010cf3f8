// The denoisers (src/denoise/, glsl/denoise/) through OSMesa with the real shaders: they keep flat
// regions, never make NaN or Inf, bring a noisy Cornell box closer to a converged one, and do not
// blur across a normal discontinuity.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "denoise/denoise_passes.h"
#include "denoise/denoiser.h"
#include "image/image_stats.h"
#include "render/render_test_util.h"
#include "scene/light_selection.h"

namespace fp::test {
namespace {

constexpr Denoiser kFilters[] = {Denoiser::Bilateral, Denoiser::Atrous};

// A quad a, b, c, d (counter-clockwise seen from the front) of one material, with flat normals.
void addQuad(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, uint32_t material) {
    glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    for (auto tri : {std::array<glm::vec3, 3>{a, b, c}, std::array<glm::vec3, 3>{a, c, d}}) {
        Triangle t;
        t.p = tri;
        t.n = {n, n, n};
        t.material = material;
        scene.triangles.push_back(t);
    }
}

uint32_t addMaterial(Scene& scene, glm::vec3 diffuse, glm::vec3 emission = glm::vec3(0.0f)) {
    Material m;
    m.name = "m" + std::to_string(scene.materials.size());
    m.diffuse = diffuse;
    m.emission = emission;
    scene.materials.push_back(m);
    return uint32_t(scene.materials.size() - 1);
}

// Looking down -z from z = 5 at the plane z = 0; +x is to the right of the image.
Camera frontCamera() {
    Camera c;
    c.eye = glm::vec3(0.0f, 0.0f, 5.0f);
    c.target = glm::vec3(0.0f);
    c.fovY = 30.0f;
    return c;
}

RenderSettings guided(int size, Integrator integrator, int maxDepth) {
    RenderSettings s;
    s.width = s.height = size;
    s.integrator = integrator;
    s.maxDepth = maxDepth;
    s.seed = 7;
    s.guides = true;
    return s;
}

TEST(DenoiserNames, RoundTripAndListTheChoices) {
    for (Denoiser d : kAllDenoisers) EXPECT_EQ(parseDenoiser(denoiserName(d)), d);
    try {
        parseDenoiser("nlmeans");
        FAIL() << "an unknown name must throw";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("'nlmeans'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("none, bilateral or atrous"), std::string::npos) << e.what();
    }
}

// A plane under a uniform white sky with BSDF sampling: every sample of a Lambertian surface returns
// exactly its albedo (weight albedo, then the sky). Left half albedo 0.2, right half 0.8: a sharp
// texture edge on a flat, noise-free image. Divided by the albedo it is 1 everywhere, so the a-trous
// filter must give back every pixel; the bilateral filter (no demodulation, 9x9 window) every pixel
// more than 4 columns from the edge.
TEST(Denoise, FlatRegionsAndAnAlbedoEdgeStayExact) {
    ensureGlContext();
    Scene scene;
    scene.source = "two albedos under a white sky";
    scene.environment.color = glm::vec3(1.0f);
    uint32_t dark = addMaterial(scene, glm::vec3(0.2f)), light = addMaterial(scene, glm::vec3(0.8f));
    addQuad(scene, {-50, -50, 0}, {0, -50, 0}, {0, 50, 0}, {-50, 50, 0}, dark);
    addQuad(scene, {0, -50, 0}, {50, -50, 0}, {50, 50, 0}, {0, 50, 0}, light);
    Renderer renderer(scene, testShaders());
    const int size = 24;
    renderer.configure(guided(size, Integrator::Bsdf, 2), frontCamera());
    renderer.render(4);
    Image raw = renderer.readback().mean();
    ASSERT_NEAR(raw.at(0, 0).r, 0.2f, 1e-6f);
    ASSERT_NEAR(raw.at(size - 1, 0).r, 0.8f, 1e-6f);
    for (Denoiser d : kFilters) {
        Image out = denoise(renderer, d);
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                if (d == Denoiser::Bilateral && std::abs(x - size / 2) <= 4) continue;
                for (int c = 0; c < 3; ++c)
                    ASSERT_NEAR(out.at(x, y)[c], raw.at(x, y)[c], 2e-6f * raw.at(x, y)[c])
                        << denoiserName(d) << " at " << x << "," << y;
            }
    }
}

// Emitters (not demodulated), a black surface (albedo 0), background (no hit) and pixels without
// samples (an unfinished tiled pass), at 1 sample (variance estimated spatially) and at 4.
TEST(Denoise, NeverMakesNanOrInf) {
    ensureGlContext();
    Scene scene;
    scene.source = "black, white, emitter and background";
    uint32_t black = addMaterial(scene, glm::vec3(0.0f)), white = addMaterial(scene, glm::vec3(0.9f));
    uint32_t lamp = addMaterial(scene, glm::vec3(0.5f), glm::vec3(20.0f));
    addQuad(scene, {-1, -1, 0}, {0, -1, 0}, {0, 0, 0}, {-1, 0, 0}, black);
    addQuad(scene, {0, -1, 0}, {1, -1, 0}, {1, 0, 0}, {0, 0, 0}, white);
    addQuad(scene, {-0.5f, 0.2f, 0.5f}, {0.5f, 0.2f, 0.5f}, {0.5f, 0.6f, 0.5f}, {-0.5f, 0.6f, 0.5f}, lamp);
    Renderer renderer(scene, testShaders());
    DenoisePasses passes(testShaders());
    for (int spp : {1, 4}) {
        renderer.configure(guided(32, Integrator::Nee, 3), frontCamera());
        renderer.render(spp);
        renderer.renderTile(8);  // one more sample in one tile only
        for (Denoiser d : kFilters) {
            passes.run(renderer, d);
            EXPECT_TRUE(allFinite(passes.result())) << denoiserName(d) << " at " << spp << " spp";
        }
    }
    renderer.configure(guided(32, Integrator::Nee, 3), frontCamera());
    for (int tile = 0; tile < 3; ++tile) renderer.renderTile(8);  // most pixels have no sample at all
    for (Denoiser d : kFilters) {
        passes.run(renderer, d);
        Image out = passes.result();
        EXPECT_TRUE(allFinite(out)) << denoiserName(d) << " with unrendered pixels";
    }
}

// The denoisers read their shaders where the renderer reads its own: a renderer given a shader directory
// (--shader-dir, the viewer's hot reload) whose a-trous pass does not compile makes denoise() fail
// naming that file, while the built-in passes would have run. What this catches: denoise() compiling the
// built-in passes whatever the renderer was given (it did: `render --shader-dir` and `study
// --shader-dir` could not try a changed denoiser).
TEST(Denoise, PassesComeFromTheRenderersShaderDirectory) {
    ensureGlContext();
    ShaderLibrary broken =
        testShadersEdited("broken_atrous", {{"denoise/atrous.frag.glsl", "", "\nthis does not compile\n"}});
    Scene scene = furnaceBox(0.5f, 1.0f);
    Renderer renderer(scene, broken);
    renderer.configure(guided(8, Integrator::Nee, 2), insideCamera());
    renderer.render(2);
    EXPECT_NO_THROW(denoise(renderer, Denoiser::Bilateral));
    try {
        denoise(renderer, Denoiser::Atrous);
        ADD_FAILURE() << "the broken a-trous pass compiled";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("atrous.frag.glsl"), std::string::npos) << e.what();
    }
}

TEST(Denoise, NoneIsTheRawMeanAndFiltersNeedGuides) {
    ensureGlContext();
    Scene scene = furnaceBox(0.5f, 1.0f);
    Renderer renderer(scene, testShaders());
    RenderSettings s = guided(8, Integrator::Nee, 2);
    s.guides = false;
    renderer.configure(s, insideCamera());
    renderer.render(2);
    Image raw = renderer.readback().mean();
    EXPECT_EQ(denoise(renderer, Denoiser::None).pixels, raw.pixels);
    for (Denoiser d : kFilters) {
        try {
            denoise(renderer, d);
            FAIL() << denoiserName(d) << " without guides must throw";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("guides"), std::string::npos) << e.what();
        }
    }
    // The accumulation is only read: rendering on after denoising gives what rendering alone gives.
    s.guides = true;
    renderer.configure(s, insideCamera());
    renderer.render(2);
    denoise(renderer, Denoiser::Atrous);
    renderer.render(2);
    Image denoisedBetween = renderer.readback().mean();
    renderer.configure(s, insideCamera());
    renderer.render(4);
    EXPECT_EQ(denoisedBetween.pixels, renderer.readback().mean().pixels);
}

// RMSE over the pixels where `keep` is true.
double rmseWhere(const Image& a, const Image& b, const std::vector<bool>& keep) {
    double sum = 0.0;
    size_t count = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i)
        if (keep[i]) {
            glm::dvec3 d = glm::dvec3(a.pixels[i]) - glm::dvec3(b.pixels[i]);
            sum += glm::dot(d, d) / 3.0;
            ++count;
        }
    return std::sqrt(sum / double(count));
}

// The Cornell box at 16 spp against a 256-spp render of another seed. Over the whole image the lamp's
// edge dominates the squared error (radiance 17 against 0.5, coverage noise of 16 jittered samples),
// and the filters leave emitter pixels as they are: there they must not be worse. Elsewhere both must
// reduce the error clearly.
class DenoiseCornell : public CornellBoxSuite {};

// Independent numbers: the filters are judged on the noise of plain Monte Carlo. With the Sobol sampler
// the 16-sample input is already far cleaner (measured: RMSE 0.0249 against 0.1077, on surfaces alone
// 0.0120 against 0.0159) and the bilateral filter buys less there (0.86 of the raw error on surfaces
// against 0.71 here).
TEST_F(DenoiseCornell, FiltersBringSixteenSamplesCloserToConverged) {
    const int size = 48;
    RenderSettings s = guided(size, Integrator::Nee, 5);
    s.sampler = Sampler::Independent;
    s.samplesPerPass = RenderSettings::kMaxSamplesPerPass;
    s.seed = 1000;
    renderer_->configure(s, *scene_->camera);
    renderer_->render(256);
    Accumulation converged = renderer_->readback();
    Image reference = converged.mean();
    s.seed = 1;
    renderer_->configure(s, *scene_->camera);
    renderer_->render(16);
    Accumulation acc = renderer_->readback();
    Image raw = acc.mean();
    std::vector<bool> all(raw.pixels.size(), true), surfaces(raw.pixels.size());
    for (size_t i = 0; i < surfaces.size(); ++i)  // no sample of either render hit an emitter first
        surfaces[i] = acc.counters[i].y == 0.0f && converged.counters[i].y == 0.0f;
    double rawAll = rmseWhere(raw, reference, all), rawSurfaces = rmseWhere(raw, reference, surfaces);
    for (Denoiser d : kFilters) {
        Image out = denoise(*renderer_, d);
        ASSERT_TRUE(allFinite(out));
        double errorAll = rmseWhere(out, reference, all), errorSurfaces = rmseWhere(out, reference, surfaces);
        std::printf(
            "%s at 16 spp: RMSE %.4f (raw %.4f); without emitter pixels %.4f (raw %.4f, ratio %.2f)\n",
            denoiserName(d), errorAll, rawAll, errorSurfaces, rawSurfaces, errorSurfaces / rawSurfaces);
        EXPECT_LT(errorAll, rawAll) << denoiserName(d);
        EXPECT_LT(errorSurfaces, 0.8 * rawSurfaces) << denoiserName(d);
    }
}

// What the a-trous filter is told about each pixel's noise, for bdpt (whose estimate adds the light
// image, render/light_splat.h, to the camera samples' mean): the prepare pass's variance must be
// Accumulation::varianceOfMean of the same read-back, per pixel, combined over the channels as the pass
// does (standard deviations add; divided by the demodulating albedo). What this catches: the camera
// variance computed around the total mean, camera plus light image, while the squares are the camera
// samples' alone (it was: at 8 spp 367 of these 576 pixels got variance 0 and 464 less than half of
// it, and bdpt + atrous got worse from 2 to 4 spp in the study), and a light image whose own variance
// is left out. Measured with the fix: at most 3.3e-7 relative difference.
TEST_F(DenoiseCornell, PreparedVarianceIsTheVarianceOfBdptsMean) {
    const int size = 24;
    renderer_->configure(guided(size, Integrator::Bdpt, 5), *scene_->camera);
    renderer_->render(8);  // at least 4 samples: the per-pixel variance, not the spatial estimate
    Accumulation acc = renderer_->readback();
    ASSERT_GT(acc.lightPathsPerPixel, 0.0) << "bdpt must have a light image for the test to mean anything";
    Image variance = acc.varianceOfMean();
    DenoisePasses passes(renderer_->shaders());
    passes.prepare(*renderer_, Denoiser::Atrous);
    std::vector<glm::vec4> prepared = passes.prepared();
    ASSERT_EQ(prepared.size(), variance.pixels.size());
    int lightImagePixels = 0;
    for (size_t i = 0; i < prepared.size(); ++i) {
        // The albedo the pass divides by (prepare.frag.glsl): the mean first-hit albedo, at least 0.01,
        // except at emitters and background.
        float guideSamples = acc.albedo[i].w, depth = acc.normalDepth[i].w / guideSamples;
        glm::vec3 albedo(1.0f);
        if (acc.counters[i].y == 0.0f && depth > 0.0f)
            albedo = glm::max(glm::vec3(acc.albedo[i]) / guideSamples, glm::vec3(0.01f));
        float deviation = luminance(glm::sqrt(variance.pixels[i]) / albedo);
        float expected = deviation * deviation;
        if (acc.splatSquares[i].r > 0.0f) ++lightImagePixels;
        // Float sums on both sides, the same formula: agreement to float rounding, amplified by the
        // cancellation in sum x^2 - n m^2 (at most a few ulps of the squares' sum).
        float squares = luminance(glm::vec3(acc.squares[i])) / (acc.sum[i].w * acc.sum[i].w);
        ASSERT_NEAR(prepared[i].a, expected, 1e-4f * expected + 1e-6f * squares) << "pixel " << i;
    }
    EXPECT_GT(lightImagePixels, int(prepared.size()) / 2) << "the light image must reach most pixels";
}

// A convex ridge: two faces of albedo 0.5 meeting at x = 0, under a sky of radiance 1. A bright emitter
// far to the left lights the left face only; the right face lies with its back to it and sees nothing
// but sky, so its radiance is exactly 0.5 in expectation. Next to the ridge the right face must stay
// there: a filter that blurred across the normal discontinuity would pull in the much brighter left face.
TEST(Denoise, DoesNotBlurAcrossANormalDiscontinuity) {
    ensureGlContext();
    Scene scene;
    scene.source = "ridge";
    scene.environment.color = glm::vec3(1.0f);
    uint32_t grey = addMaterial(scene, glm::vec3(0.5f));
    uint32_t lamp = addMaterial(scene, glm::vec3(0.0f), glm::vec3(30.0f));
    const float t = 0.5f;  // slope of each face away from the camera
    addQuad(scene, {-20, -20, -20 * t}, {0, -20, 0}, {0, 20, 0}, {-20, 20, -20 * t}, grey);  // left: z = t x
    addQuad(scene, {0, -20, 0}, {20, -20, -20 * t}, {20, 20, -20 * t}, {0, 20, 0}, grey);  // right: z = -t x
    // At x = -30, facing +x; every point has t x + z < 0: behind the right face's plane.
    addQuad(scene, {-30, -10, -10}, {-30, 10, -10}, {-30, 10, 4}, {-30, -10, 4}, lamp);
    Renderer renderer(scene, testShaders());
    const int size = 32;
    renderer.configure(guided(size, Integrator::Nee, 3), frontCamera());
    renderer.render(16);
    Accumulation acc = renderer.readback();
    Image raw = acc.mean();
    // Columns 16.. image the right face (x > 0); the strip next to the ridge, and the left face.
    PixelRect strip{size / 2, 0, 3, size}, left{0, 0, size / 2 - 1, size};
    double leftMean = meanColor(raw, left).g;
    ASSERT_GT(leftMean, 0.8) << "the left face must be clearly brighter for the test to mean anything";
    // Without a leak, the denoised strip is a weighted average of at least as many right-face pixels as
    // the raw strip, so 5 standard errors of the raw strip's mean bound its error. Measured: dropping
    // the normal weight (eq. 4) moves it by about 7 (atrous) and 38 (bilateral) of them.
    double bound = 5.0 * estimate(acc, strip.x, strip.y, strip.width, strip.height).standardError.g;
    for (Denoiser d : kFilters) {
        double m = meanColor(denoise(renderer, d), strip).g;
        std::printf(
            "%s: right face next to the ridge %.4f (expected 0.5 +- %.4f; raw %.4f, left face %.2f)\n",
            denoiserName(d), m, bound, meanColor(raw, strip).g, leftMean);
        EXPECT_NEAR(m, 0.5, bound) << denoiserName(d);
    }
}

// The real-time pipeline's pass-through (DenoisePasses::filter with `settled`): pixels whose history is
// long are never shaded, and their neighbours must read their input at every level. On a flat field
// (one colour, one plane) with every other pixel settled, every pixel comes out as the input times the
// albedo. Filtering another image first (1.5 times as bright, close enough for the luminance weight to
// admit it) leaves that image in the filter's textures, where a neighbour whose input was not copied
// would show it.
TEST(Denoise, PassedThroughPixelsLendTheirInputToTheirNeighbours) {
    ensureGlContext();
    const int size = 16;
    auto texture = [&](auto valueAt) {
        std::vector<glm::vec4> texels;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) texels.push_back(valueAt(x, y));
        GLuint t = 0;
        glGenTextures(1, &t);
        glBindTexture(GL_TEXTURE_2D, t);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, size, size, 0, GL_RGBA, GL_FLOAT, texels.data());
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        return t;
    };
    const glm::vec4 color(0.2f, 0.4f, 0.6f, 0.01f), old(0.3f, 0.6f, 0.9f, 0.01f);
    GLuint input = texture([&](int, int) { return color; });
    GLuint oldInput = texture([&](int, int) { return old; });
    GLuint guide = texture([](int, int) { return glm::vec4(0.0f, 0.0f, 1.0f, 2.0f); });  // a plane at 2
    GLuint modulate = texture([](int, int) { return glm::vec4(2.0f, 2.0f, 2.0f, 0.0f); });
    GLuint settled =
        texture([](int x, int y) { return glm::vec4(0.0f, 0.0f, 0.0f, (x + y) % 2 ? 0.0f : 16.0f); });
    DenoisePasses passes(testShaders());
    passes.filter(oldInput, guide, modulate, size, size, Denoiser::Atrous);
    passes.filter(input, guide, modulate, size, size, Denoiser::Atrous, settled, 16.0f);
    Image out = passes.result();
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(out.at(x, y)[c], 2.0f * color[c], 1e-5f) << "at " << x << "," << y;
    GLuint textures[] = {input, oldInput, guide, modulate, settled};
    glDeleteTextures(5, textures);
}

}  // namespace
}  // namespace fp::test
