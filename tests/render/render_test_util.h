#pragma once
// Shared pieces of the GPU tests: one OSMesa context per test binary, small analytic scenes, and
// statistics of accumulated images for tolerances derived from the sample variance.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <vector>


#include "gl/context.h"
#include "image/image_stats.h"
#include "render/renderer.h"
#include "scene/builtin_scene.h"
#include "scene/procedural.h"
#include "scene/scene.h"
#include "test_shaders.h"

namespace fp::test {

inline void ensureGlContext() {
    static std::unique_ptr<GlContext> context = createOsMesaContext();
}

// Sets an environment variable for one scope, restoring what was there.
class ScopedEnv {
  public:
    ScopedEnv(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        if (value)
            setenv(name, value, 1);
        else
            unsetenv(name);
    }
    ~ScopedEnv() {
        if (old_)
            setenv(name_, old_->c_str(), 1);
        else
            unsetenv(name_);
    }

  private:
    const char* name_;
    std::optional<std::string> old_;
};

// A smooth grey unit sphere at the origin, lit only by the environment map `map`.
inline Scene sphereUnderSky(const Image& map) {
    Scene scene;
    scene.source = "sphere under a sky";
    Material m;
    m.diffuse = glm::vec3(0.7f);
    scene.materials.push_back(m);
    scene.environment.map = map;
    appendSphere(scene, glm::vec3(0.0f), 1.0f, 16, 32, 0, true);
    return scene;
}

// The closed cube [-1, 1]^3 with every face facing inward, one material for all of it.
inline Scene furnaceBox(float albedo, float emission) {
    Scene scene;
    scene.source = "furnace box";
    Material m;
    m.name = "furnace";
    m.diffuse = glm::vec3(albedo);
    m.emission = glm::vec3(emission);
    scene.materials.push_back(m);
    for (int axis = 0; axis < 3; ++axis) {
        for (float side : {-1.0f, 1.0f}) {
            glm::vec3 c[4];
            int a = (axis + 1) % 3, b = (axis + 2) % 3;
            const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
            for (int i = 0; i < 4; ++i) {
                c[i][axis] = side;
                c[i][a] = corners[i][0];
                c[i][b] = corners[i][1];
            }
            for (auto tri : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
                Triangle t;
                t.p = {c[tri[0]], c[tri[1]], c[tri[2]]};
                // Face the inside: the geometric normal must point back toward the centre.
                if (glm::dot(t.geometricNormal(), t.p[0]) > 0.0f) std::swap(t.p[1], t.p[2]);
                glm::vec3 n = glm::normalize(t.geometricNormal());
                t.n = {n, n, n};
                scene.triangles.push_back(t);
            }
        }
    }
    return scene;
}

inline Camera insideCamera() {
    Camera c;
    c.eye = glm::vec3(0.1f, 0.2f, -0.3f);
    c.target = glm::vec3(0.3f, 0.1f, 1.0f);
    c.fovY = 80.0f;
    return c;
}

// A unit sphere at the origin (24 rings x 48 segments, flat or smooth-shaded) of one material in a white
// furnace: a uniform environment of radiance 1.
inline Scene sphereInFurnace(const Material& material, bool smooth) {
    Scene scene;
    scene.source = "sphere in a white furnace";
    scene.materials.push_back(material);
    scene.environment.color = glm::vec3(1.0f);
    appendSphere(scene, glm::vec3(0.0f), 1.0f, 24, 48, 0, smooth);
    return scene;
}

// Looks at the unit sphere at the origin from 4 away on the -z side; the sphere fills about half of it.
inline Camera outsideCamera() {
    Camera c;
    c.eye = glm::vec3(0.3f, 0.5f, -4.0f);
    c.target = glm::vec3(0.0f);
    c.fovY = 35.0f;
    return c;
}

struct ImageEstimate {
    glm::vec3 mean{0.0f};           // average over pixels of the per-pixel estimates
    glm::vec3 standardError{0.0f};  // of that average, from the per-pixel sample variances
};

// Pixels are independent (separate random streams), so Var(average) = sum of Var(pixel means) / P^2.
inline ImageEstimate estimate(const Accumulation& acc, int x0 = 0, int y0 = 0, int w = -1, int h = -1) {
    if (w < 0) w = acc.width;
    if (h < 0) h = acc.height;
    Image mean = acc.mean(), variance = acc.varianceOfMean();
    glm::dvec3 sum(0.0), varSum(0.0);
    for (int y = y0; y < y0 + h; ++y)
        for (int x = x0; x < x0 + w; ++x) {
            sum += glm::dvec3(mean.at(x, y));
            varSum += glm::dvec3(variance.at(x, y));
        }
    double count = double(w) * double(h);
    return {glm::vec3(sum / count), glm::vec3(glm::sqrt(varSum) / count)};
}

// The variance of the mean in the luminance channel G, summed over the pixels of `r`.
inline double regionVariance(const Accumulation& acc, const PixelRect& r) {
    return meanColor(acc.varianceOfMean(), r).y * double(r.width) * double(r.height);
}

// z-scores of the difference of two independent estimates over blocks of b x b pixels inside `rect`.
inline std::vector<float> blockZScores(const Accumulation& a, const Accumulation& b, int block,
                                       const PixelRect& rect) {
    std::vector<float> z;
    for (int y = rect.y; y + block <= rect.y + rect.height; y += block)
        for (int x = rect.x; x + block <= rect.x + rect.width; x += block) {
            ImageEstimate ea = estimate(a, x, y, block, block), eb = estimate(b, x, y, block, block);
            for (int c = 0; c < 3; ++c) {
                float se = std::sqrt(ea.standardError[c] * ea.standardError[c] +
                                     eb.standardError[c] * eb.standardError[c]);
                if (se > 0.0f) z.push_back((ea.mean[c] - eb.mean[c]) / se);
            }
        }
    return z;
}

inline std::vector<float> blockZScores(const Accumulation& a, const Accumulation& b, int block) {
    return blockZScores(a, b, block, PixelRect{0, 0, a.width, a.height});
}

// What independent estimates of the same image give: roughly standard normal z-scores, none beyond 5
// and a mean square near 1 (below 2 allows for the variance estimates' own noise).
inline void expectZScoresOfNoise(const std::vector<float>& z) {
    double meanSquare = 0.0;
    for (float v : z) {
        EXPECT_LT(std::abs(v), 5.0f);
        meanSquare += double(v) * v / double(z.size());
    }
    EXPECT_LT(meanSquare, 2.0) << "differences larger than the noise explains";
}

// A Lambertian material of grey albedo `albedo`.
inline Material diffuseMaterial(float albedo) {
    Material m;
    m.diffuse = glm::vec3(albedo);
    return m;
}

// A black one-sided emitter of radiance `radiance` (its front face emits).
inline Material lampMaterial(glm::vec3 radiance) {
    Material m;
    m.name = "lamp";
    m.diffuse = glm::vec3(0.0f);
    m.emission = radiance;
    return m;
}

// The built-in Cornell box with delta vertices in the middle of paths: a smooth plastic (a delta coat
// over a diffuse base: vertices that are delta or not depending on the lobe sampled) for the white
// surfaces and a perfect mirror for the red wall.
inline Scene cornellWithDeltaSurfaces() {
    Scene scene = builtinCornellBox();
    for (Material& m : scene.materials) {
        if (m.name == "white") {
            m.type = MaterialType::Plastic;
            m.specular = glm::vec3(1.0f);
            m.roughness = 0.0f;
        } else if (m.name == "red") {
            m.type = MaterialType::Conductor;
            m.specular = glm::vec3(0.9f, 0.3f, 0.3f);
            m.roughness = 0.0f;
        }
    }
    return scene;
}

// The closed box [lo, hi] (12 triangles), faces outward: a solid for glass.
inline void appendBox(Scene& scene, glm::vec3 lo, glm::vec3 hi, uint32_t material) {
    glm::vec3 c[8];
    for (int i = 0; i < 8; ++i)
        c[i] = glm::vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
    const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    glm::vec3 centre = 0.5f * (lo + hi);
    for (const auto& f : faces) {
        size_t first = scene.triangles.size();
        appendQuad(scene, c[f[0]], c[f[1]], c[f[2]], c[f[3]], material);
        for (size_t i = first; i < scene.triangles.size(); ++i) {
            Triangle& t = scene.triangles[i];
            if (glm::dot(t.geometricNormal(), t.p[0] - centre) < 0.0f) {  // face outward
                std::swap(t.p[1], t.p[2]);
                glm::vec3 n = glm::normalize(t.geometricNormal());
                t.n = {n, n, n};
            }
        }
    }
}

// The size of a difference between two independent renders of what should be the same image.
struct ImageComparison {
    glm::vec3 ratio{1.0f};       // whole-image mean of a / that of b
    glm::vec3 meanZ{0.0f};       // (mean a - mean b) / standard error of the difference
    glm::vec3 relativeSe{0.0f};  // that standard error / mean of b: how sharp the comparison is
    float maxBlockZ = 0.0f;      // the largest |z| over blocks and channels
    double blockZMeanSquare = 0.0;
    size_t blocks = 0;  // z-scores (blocks x channels with any noise)
};

inline ImageComparison compareImages(const Accumulation& a, const Accumulation& b, int block,
                                     const PixelRect& rect) {
    ImageComparison c;
    ImageEstimate ea = estimate(a, rect.x, rect.y, rect.width, rect.height),
                  eb = estimate(b, rect.x, rect.y, rect.width, rect.height);
    for (int ch = 0; ch < 3; ++ch) {
        float se = std::sqrt(ea.standardError[ch] * ea.standardError[ch] +
                             eb.standardError[ch] * eb.standardError[ch]);
        c.ratio[ch] = ea.mean[ch] / eb.mean[ch];
        c.meanZ[ch] = se > 0.0f ? (ea.mean[ch] - eb.mean[ch]) / se : 0.0f;
        c.relativeSe[ch] = se / eb.mean[ch];
    }
    std::vector<float> z = blockZScores(a, b, block, rect);
    c.blocks = z.size();
    for (float v : z) {
        c.maxBlockZ = std::max(c.maxBlockZ, std::abs(v));
        c.blockZMeanSquare += double(v) * v / double(z.size());
    }
    return c;
}

// Two independent renders of the same image agree: the whole-image means within 5 standard errors
// of their difference (which must be below `sharpness` of the mean, or the check means little), and
// block by block z-scores as standard normal noise gives: none beyond 5, mean square below 2. Prints
// the figures, so that a failure shows how large the difference is.
inline void expectSameImage(const Accumulation& a, const Accumulation& b, int block, float sharpness,
                            const std::string& what, const PixelRect* region = nullptr) {
    PixelRect rect = region ? *region : PixelRect{0, 0, a.width, a.height};
    ImageComparison c = compareImages(a, b, block, rect);
    std::printf(
        "%s: mean ratio %.4f %.4f %.4f, mean z %.2f %.2f %.2f (relative se %.4f); %zu block z: max |z| %.2f, "
        "mean square %.2f\n",
        what.c_str(), c.ratio.x, c.ratio.y, c.ratio.z, c.meanZ.x, c.meanZ.y, c.meanZ.z, c.relativeSe.y,
        c.blocks, c.maxBlockZ, c.blockZMeanSquare);
    for (int ch = 0; ch < 3; ++ch) {
        EXPECT_LT(std::abs(c.meanZ[ch]), 5.0f)
            << what << ": whole-image mean, channel " << ch << ", ratio " << c.ratio[ch];
        EXPECT_LT(c.relativeSe[ch], sharpness)
            << what << ": the comparison must be sharp enough to mean something";
    }
    EXPECT_GT(c.blocks, 30u) << what;
    EXPECT_LT(c.maxBlockZ, 5.0f) << what << ": a block differs by more than the noise explains";
    EXPECT_LT(c.blockZMeanSquare, 2.0) << what << ": block differences larger than the noise explains";
    EXPECT_EQ(a.droppedSamples() + b.droppedSamples(), 0u) << what;
}

// The render against the expected per-pixel means (rows top first, as Accumulation stores them):
// z-scores over blocks of `block` x `block` pixels and for the whole image, each standard error widened
// by 1e-5 of the value for float rounding. A noise-free block (nee at depth 1 under a directional light,
// or outside a spot's cone) must then match to that rounding. Prints the figures.
inline void expectImage(const Accumulation& acc, const std::vector<glm::dvec3>& expected, int block,
                        const std::string& what) {
    const Image mean = acc.mean(), variance = acc.varianceOfMean();
    auto z = [&](int x0, int y0, int w, int h, int ch) {
        double sum = 0.0, want = 0.0, var = 0.0;
        for (int y = y0; y < y0 + h; ++y)
            for (int x = x0; x < x0 + w; ++x) {
                sum += double(mean.at(x, y)[ch]);
                var += double(variance.at(x, y)[ch]);
                want += expected[size_t(y) * size_t(acc.width) + size_t(x)][ch];
            }
        double count = double(w) * h, rounding = 1e-5 * std::abs(want / count);
        double se = std::sqrt(var / (count * count) + rounding * rounding);
        double difference = sum / count - want / count;
        if (se == 0.0) return difference == 0.0 ? 0.0 : 1e9;
        return difference / se;
    };
    double maxZ = 0.0, meanSquare = 0.0;
    int blocks = 0;
    for (int y = 0; y + block <= acc.height; y += block)
        for (int x = 0; x + block <= acc.width; x += block)
            for (int ch = 0; ch < 3; ++ch) {
                double v = z(x, y, block, block, ch);
                maxZ = std::max(maxZ, std::abs(v));
                meanSquare += v * v;
                ++blocks;
            }
    meanSquare /= blocks;
    glm::dvec3 whole(z(0, 0, acc.width, acc.height, 0), z(0, 0, acc.width, acc.height, 1),
                     z(0, 0, acc.width, acc.height, 2));
    std::printf("  %s: %d block z: max |z| %.2f, mean square %.2f; whole image z %.2f %.2f %.2f\n",
                what.c_str(), blocks, maxZ, meanSquare, whole.x, whole.y, whole.z);
    EXPECT_LT(maxZ, 5.0) << what << ": a block differs from the closed form by more than the noise explains";
    EXPECT_LT(meanSquare, 2.0) << what;
    for (int ch = 0; ch < 3; ++ch)
        EXPECT_LT(std::abs(whole[ch]), 5.0) << what << ": whole image, channel " << ch;
    EXPECT_EQ(acc.droppedSamples(), 0u) << what;
}

// A glossy sphere on a diffuse floor, under a constant sky and a small lamp: every integrator's
// estimator meets the material (light samples, BSDF samples, bdpt's joins and its delta test).
inline Scene sphereOnAFloor(const Material& material) {
    Scene scene;
    scene.source = "sphere on a floor";
    scene.materials = {material, diffuseMaterial(0.5f), lampMaterial(glm::vec3(30.0f))};
    appendSphere(scene, glm::vec3(0.0f, 1.0f, 0.0f), 1.0f, 16, 32, 0, true);
    appendQuad(scene, glm::vec3(-4.0f, 0.0f, -4.0f), glm::vec3(-4.0f, 0.0f, 4.0f),
               glm::vec3(4.0f, 0.0f, 4.0f), glm::vec3(4.0f, 0.0f, -4.0f), 1);
    // The lamp faces down (its front face, counter-clockwise from below).
    appendQuad(scene, glm::vec3(-0.5f, 4.0f, -0.5f), glm::vec3(0.5f, 4.0f, -0.5f),
               glm::vec3(0.5f, 4.0f, 0.5f), glm::vec3(-0.5f, 4.0f, 0.5f), 2);
    scene.environment.color = glm::vec3(0.3f, 0.4f, 0.5f);
    return scene;
}

inline Camera sphereCamera() {
    Camera c;
    c.eye = glm::vec3(0.5f, 2.5f, -5.0f);
    c.target = glm::vec3(0.0f, 0.8f, 0.0f);
    c.fovY = 40.0f;
    return c;
}

// A test suite sharing one renderer of the built-in Cornell box (BVH build and shader compile once).
class CornellBoxSuite : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        ensureGlContext();
        scene_ = std::make_unique<Scene>(builtinCornellBox());
        renderer_ = std::make_unique<Renderer>(*scene_, testShaders());
    }
    static void TearDownTestSuite() {
        renderer_.reset();
        scene_.reset();
    }
    static inline std::unique_ptr<Scene> scene_;
    static inline std::unique_ptr<Renderer> renderer_;
};

// An 8-bit RGBA framebuffer for the display pass to draw into, bound while it lives; read() gives its
// pixels, rows bottom first as GL stores them.
class Rgba8Target {
  public:
    Rgba8Target(int width, int height) : width_(width), height_(height) {
        glGenTextures(1, &texture_);
        glBindTexture(GL_TEXTURE_2D, texture_);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        glGenFramebuffers(1, &framebuffer_);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
    }
    ~Rgba8Target() {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDeleteFramebuffers(1, &framebuffer_);
        glDeleteTextures(1, &texture_);
    }
    Rgba8Target(const Rgba8Target&) = delete;
    Rgba8Target& operator=(const Rgba8Target&) = delete;
    std::vector<uint8_t> read() const {
        std::vector<uint8_t> pixels(size_t(width_) * size_t(height_) * 4);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
        return pixels;
    }

  private:
    int width_, height_;
    GLuint texture_ = 0, framebuffer_ = 0;
};

// Independent numbers by default: the tolerances of these tests come from each pixel's sample variance,
// which estimates the variance of its mean only when the samples are independent (stratified samples'
// variance overstates it, and the tests would lose their edge). The Sobol sampler has tests of its own.
inline Accumulation renderScene(Renderer& renderer, const Camera& camera, Integrator integrator, int size,
                                int spp, int maxDepth, uint32_t seed = 1,
                                Sampler sampler = Sampler::Independent,
                                LightSampling lightSampling = LightSampling::Auto,
                                LightSelection lightSelection = LightSelection::Auto,
                                Caustics caustics = Caustics::Auto) {
    RenderSettings s;
    s.sampler = sampler;
    s.lightSampling = lightSampling;
    s.lightSelection = lightSelection;
    s.caustics = caustics;
    s.width = s.height = size;
    s.integrator = integrator;
    s.maxDepth = maxDepth;
    s.seed = seed;
    s.samplesPerPass =
        std::min(spp, RenderSettings::kMaxSamplesPerPass);  // few draws: throughput, not progress
    renderer.configure(s, camera);
    renderer.render(spp);
    return renderer.readback();
}

// Two renders of the same samples that must agree bit for bit (sums and squares), and are not black: a
// broken read that returned zeros on both sides must not pass.
inline void expectBitIdentical(const Accumulation& a, const Accumulation& b, const char* what) {
    ASSERT_EQ(a.sum.size(), b.sum.size()) << what;
    EXPECT_EQ(std::memcmp(a.sum.data(), b.sum.data(), a.sum.size() * sizeof(glm::vec4)), 0) << what;
    EXPECT_EQ(std::memcmp(a.squares.data(), b.squares.data(), a.squares.size() * sizeof(glm::vec4)), 0)
        << what;
    EXPECT_GT(estimate(a).mean.r, 0.01f) << what;
}

}  // namespace fp::test
