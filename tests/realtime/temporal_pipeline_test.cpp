// The real-time pipeline (src/realtime/temporal_pipeline.h) on real shaders through OSMesa: a still
// camera's history is the progressive mean and its filtered image converges to the progressive image;
// a camera that moves past an occluder rejects the history of what was behind it.
#include <gtest/gtest.h>

#include <cmath>

#include "../render/render_test_util.h"
#include "realtime/temporal_pipeline.h"

namespace fp::test {
namespace {

RenderSettings frameSettings(int size, int spp, int frame) {
    RenderSettings s;
    s.sampler = Sampler::Independent;  // variances below estimate the noise of independent samples
    s.width = s.height = size;
    s.maxDepth = 8;
    s.samplesPerPass = spp;
    s.sampleOffset = uint32_t(frame * spp);
    s.guides = true;
    return s;
}

// Renders frames [first, first + frames) of `spp` samples each with `camera` through the pipeline.
void runFrames(Renderer& renderer, TemporalPipeline& pipeline, const Camera& camera, int size, int spp,
               int first, int frames, const TemporalSettings& settings = {}) {
    for (int f = first; f < first + frames; ++f) {
        renderer.configure(frameSettings(size, spp, f), camera);
        renderer.render(spp);
        pipeline.run(renderer, camera, settings);
    }
}

Accumulation progressive(Renderer& renderer, const Camera& camera, int size, int spp) {
    RenderSettings s = frameSettings(size, spp, 0);
    s.samplesPerPass = 1;
    renderer.configure(s, camera);
    renderer.render(spp);
    return renderer.readback();
}

TEST(TemporalPipeline, StillCameraHistoryIsTheProgressiveMeanOfTheSameSamples) {
    ensureGlContext();
    Scene scene = builtinCornellBox();
    Renderer renderer(scene, testShaders());
    TemporalPipeline pipeline(testShaders());
    const int size = 24, spp = 2, frames = 6;
    runFrames(renderer, pipeline, *scene.camera, size, spp, 0, frames);
    Image history = pipeline.historyMean();
    std::vector<float> samples = pipeline.historySamples();
    Image expected = progressive(renderer, *scene.camera, size, spp * frames).mean();
    double total = 0.0;
    for (size_t i = 0; i < history.pixels.size(); ++i) {
        ASSERT_EQ(samples[i], float(spp * frames)) << "pixel " << i;
        for (int c = 0; c < 3; ++c) {
            float e = expected.pixels[i][c], h = history.pixels[i][c];
            ASSERT_NEAR(h, e, 1e-5f * std::abs(e) + 1e-7f) << "pixel " << i << " channel " << c;
            total += e;
        }
    }
    EXPECT_GT(total, 0.0);  // not black on both sides
}

TEST(TemporalPipeline, StillCameraFilteredImageConvergesToTheProgressiveImage) {
    ensureGlContext();
    Scene scene = builtinCornellBox();
    Renderer renderer(scene, testShaders());
    TemporalPipeline pipeline(testShaders());
    const int size = 32, spp = 4, frames = 64, block = 4;
    runFrames(renderer, pipeline, *scene.camera, size, spp, 0, frames);
    Image filtered = pipeline.result();
    Accumulation reference = progressive(renderer, *scene.camera, size, spp * frames);
    Image mean = reference.mean(), variance = reference.varianceOfMean();
    // Per block, the filtered mean must lie within the Monte Carlo error of the same samples' mean:
    // whatever the filter still does is smaller than the noise it removes.
    float worst = 0.0f;
    for (int by = 0; by < size; by += block)
        for (int bx = 0; bx < size; bx += block)
            for (int c = 0; c < 3; ++c) {
                double f = 0.0, m = 0.0, v = 0.0;
                for (int y = by; y < by + block; ++y)
                    for (int x = bx; x < bx + block; ++x) {
                        f += filtered.at(x, y)[c];
                        m += mean.at(x, y)[c];
                        v += variance.at(x, y)[c];
                    }
                if (v <= 0.0) continue;
                worst = std::max(worst, float(std::abs(f - m) / std::sqrt(v)));
            }
    EXPECT_LT(worst, 4.0f) << "a block of the filtered image is further from the progressive mean than 4 "
                              "standard errors";
    // And the filter did filter: the first frame alone differs from its own raw mean.
    TemporalPipeline fresh(testShaders());
    runFrames(renderer, fresh, *scene.camera, size, spp, 0, 1);
    Image raw = fresh.historyMean(), once = fresh.result();
    double change = 0.0;
    for (size_t i = 0; i < raw.pixels.size(); ++i) change += glm::length(raw.pixels[i] - once.pixels[i]);
    EXPECT_GT(change / double(raw.pixels.size()), 0.01);
}

// A grey wall at z = 0, a box in front of it, and a white sky: the camera slides sideways past the box.
Scene wallAndBox() {
    Scene scene;
    scene.source = "wall and box";
    scene.materials = {diffuseMaterial(0.5f), diffuseMaterial(0.9f)};
    appendQuad(scene, {-20, -20, 0}, {20, -20, 0}, {20, 20, 0}, {-20, 20, 0}, 0);
    appendBox(scene, {-1, -1, 2}, {1, 1, 3}, 1);
    scene.environment.color = glm::vec3(1.0f);
    return scene;
}

// Whether the segment from `a` to `b` passes through the box [lo, hi] (slab test).
bool segmentHitsBox(glm::vec3 a, glm::vec3 b, glm::vec3 lo, glm::vec3 hi) {
    float t0 = 0.0f, t1 = 1.0f;
    glm::vec3 d = b - a;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(d[i]) < 1e-9f) {
            if (a[i] < lo[i] || a[i] > hi[i]) return false;
            continue;
        }
        float u = (lo[i] - a[i]) / d[i], v = (hi[i] - a[i]) / d[i];
        t0 = std::max(t0, std::min(u, v));
        t1 = std::min(t1, std::max(u, v));
    }
    return t0 <= t1;
}

TEST(TemporalPipeline, HistoryOfWhatTheBoxHidLeavesNoGhost) {
    ensureGlContext();
    Scene scene = wallAndBox();
    Renderer renderer(scene, testShaders());
    TemporalPipeline pipeline(testShaders());
    Camera a;
    a.eye = {0, 0, 10};
    a.target = {0, 0, 0};
    a.fovY = 40.0f;
    Camera b = a;
    b.eye.x = b.target.x = 3.0f;
    const int size = 64, spp = 2;
    runFrames(renderer, pipeline, a, size, spp, 0, 4);
    runFrames(renderer, pipeline, b, size, spp, 4, 1);
    std::vector<float> samples = pipeline.historySamples();

    // Per pixel of b (its centre ray): 0 the box or wall a did not frame, 1 wall seen from a too, 2 wall
    // the box hid from a.
    const glm::vec3 lo(-1, -1, 2), hi(1, 1, 3);
    CameraFrame f = cameraFrame(b, 1.0f);
    std::vector<int> kind(size_t(size * size));
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            glm::vec2 ndc(2.0f * (float(x) + 0.5f) / float(size) - 1.0f,
                          1.0f - 2.0f * (float(y) + 0.5f) / float(size));
            glm::vec3 d = f.forward + ndc.x * f.right + ndc.y * f.up;
            glm::vec3 wall = f.eye + d * (-f.eye.z / d.z);
            bool seenFromA = std::abs(wall.x - a.eye.x) < std::tan(glm::radians(20.0f)) * a.eye.z;
            int k = segmentHitsBox(f.eye, wall, lo, hi) || !seenFromA ? 0
                    : segmentHitsBox(a.eye, wall, lo, hi)             ? 2
                                                                      : 1;
            kind[size_t(y * size + x)] = k;
        }
    int revealed = 0, kept = 0;
    for (int y = 2; y < size - 2; ++y)
        for (int x = 2; x < size - 2; ++x) {
            int k = kind[size_t(y * size + x)];
            bool interior = true;  // away from edges, where a pixel's jittered samples see both sides
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx) interior &= kind[size_t((y + dy) * size + x + dx)] == k;
            if (!interior || k == 0) continue;
            float n = samples[size_t(y * size + x)];
            if (k == 2) {
                ++revealed;
                EXPECT_EQ(n, float(spp)) << "revealed wall pixel (" << x << ", " << y << ") kept history";
            } else {
                ++kept;
                EXPECT_GT(n, float(spp))
                    << "wall pixel (" << x << ", " << y << ") seen in both frames lost history";
            }
        }
    EXPECT_GT(revealed, 20);
    EXPECT_GT(kept, 200);
}

}  // namespace
}  // namespace fp::test
