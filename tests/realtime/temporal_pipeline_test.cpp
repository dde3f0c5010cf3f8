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

// The box scenario: camera a frames the wall and box for 4 frames, then b, 3 units to the side, one.
struct SlidePastTheBox {
    Camera a, b;
    static constexpr int size = 64, spp = 2;
    SlidePastTheBox() {
        a.eye = {0, 0, 10};
        a.target = {0, 0, 0};
        a.fovY = 40.0f;
        b = a;
        b.eye.x = b.target.x = 3.0f;
    }
    void run(Renderer& renderer, TemporalPipeline& pipeline,
             RealtimeView lastView = RealtimeView::Image) const {
        runFrames(renderer, pipeline, a, size, spp, 0, 4);
        renderer.configure(frameSettings(size, spp, 4), b);
        renderer.render(spp);
        pipeline.run(renderer, b, {}, lastView);
    }
    // Per pixel of b (its centre ray), worked out from the geometry: 0 the box or wall a did not frame,
    // 1 wall seen from a too, 2 wall the box hid from a; -1 near an edge between kinds, where a pixel's
    // jittered samples see both sides.
    std::vector<int> kinds() const {
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
        std::vector<int> interior(kind.size(), -1);
        for (int y = 2; y < size - 2; ++y)
            for (int x = 2; x < size - 2; ++x) {
                int k = kind[size_t(y * size + x)];
                bool same = true;
                for (int dy = -2; dy <= 2; ++dy)
                    for (int dx = -2; dx <= 2; ++dx) same &= kind[size_t((y + dy) * size + x + dx)] == k;
                if (same) interior[size_t(y * size + x)] = k;
            }
        return interior;
    }
};

TEST(TemporalPipeline, HistoryOfWhatTheBoxHidLeavesNoGhost) {
    ensureGlContext();
    Scene scene = wallAndBox();
    Renderer renderer(scene, testShaders());
    TemporalPipeline pipeline(testShaders());
    SlidePastTheBox slide;
    slide.run(renderer, pipeline);
    std::vector<float> samples = pipeline.historySamples();
    std::vector<int> kind = slide.kinds();
    int revealed = 0, kept = 0;
    for (size_t i = 0; i < kind.size(); ++i) {
        int x = int(i) % slide.size, y = int(i) / slide.size;
        if (kind[i] == 2) {
            ++revealed;
            EXPECT_EQ(samples[i], float(slide.spp))
                << "revealed wall pixel (" << x << ", " << y << ") kept history";
        } else if (kind[i] == 1) {
            ++kept;
            EXPECT_GT(samples[i], float(slide.spp))
                << "wall pixel (" << x << ", " << y << ") seen in both frames lost history";
        }
    }
    EXPECT_GT(revealed, 20);
    EXPECT_GT(kept, 200);
}

// The classroom's debug views show what they say: the disocclusion mask is 1 exactly on the wall the
// box hid (and 0 on the wall both cameras saw), the history length is the history's samples over the
// samples per frame, and the deviation given to the filter, the standard error of the history's mean,
// falls as 1 / sqrt(frames) when a still camera's history grows.
TEST(TemporalPipeline, DebugViewsShowDisocclusionHistoryLengthAndDeviation) {
    ensureGlContext();
    Scene scene = wallAndBox();
    Renderer renderer(scene, testShaders());
    TemporalPipeline pipeline(testShaders());
    SlidePastTheBox slide;
    slide.run(renderer, pipeline, RealtimeView::Disocclusion);
    Image mask = pipeline.result();
    std::vector<int> kind = slide.kinds();
    int revealed = 0, kept = 0;
    for (size_t i = 0; i < kind.size(); ++i) {
        if (kind[i] == 2) {
            ++revealed;
            EXPECT_EQ(mask.pixels[i].r, 1.0f) << i;
        } else if (kind[i] == 1) {
            ++kept;
            EXPECT_EQ(mask.pixels[i].r, 0.0f) << i;
        }
    }
    EXPECT_GT(revealed, 20);
    EXPECT_GT(kept, 200);

    // A still camera: 4 frames, then 12 more (16).
    pipeline.reset();
    auto meanDeviation = [&]() {
        Image view = pipeline.result();
        double sum = 0.0;
        for (const glm::vec3& p : view.pixels) sum += p.r;
        return sum / double(view.pixels.size());
    };
    const int size = 32, spp = 2;
    runFrames(renderer, pipeline, slide.a, size, spp, 0, 3);
    renderer.configure(frameSettings(size, spp, 3), slide.a);
    renderer.render(spp);
    pipeline.run(renderer, slide.a, {}, RealtimeView::Deviation);
    double deviation4 = meanDeviation();
    runFrames(renderer, pipeline, slide.a, size, spp, 4, 11);
    renderer.configure(frameSettings(size, spp, 15), slide.a);
    renderer.render(spp);
    pipeline.run(renderer, slide.a, {}, RealtimeView::HistoryLength);
    Image length = pipeline.result();
    std::vector<float> samples = pipeline.historySamples();
    for (size_t i = 0; i < samples.size(); ++i) {
        EXPECT_EQ(samples[i], float(16 * spp)) << i;
        EXPECT_EQ(length.pixels[i].r, 16.0f) << i;
    }
    renderer.configure(frameSettings(size, spp, 16), slide.a);
    renderer.render(spp);
    pipeline.run(renderer, slide.a, {}, RealtimeView::Deviation);
    // 17 frames against 4: the variance of the mean falls as 4 / 17. The view shows the square root of an
    // unbiased variance estimate, whose mean is c4(n) times the true deviation (c4(n) = sqrt(2 / (n - 1))
    // Gamma(n / 2) / Gamma((n - 1) / 2), Gaussian frames): sqrt(4 / 17) c4(17) / c4(4) = 0.485 x 1.068 =
    // 0.518. Without Bessel's correction (dividing by n, not n - 1) it is 0.58.
    auto c4 = [](double n) {
        return std::sqrt(2.0 / (n - 1.0)) * std::tgamma(n / 2.0) / std::tgamma((n - 1.0) / 2.0);
    };
    double expected = std::sqrt(4.0 / 17.0) * c4(17.0) / c4(4.0);
    double ratio = meanDeviation() / deviation4;
    EXPECT_GT(deviation4, 0.0);
    EXPECT_NEAR(ratio, expected, 0.04) << "deviation at 4 frames " << deviation4;
}

// Settled pixels skip the filter: once a still camera's history holds settledSamples, the image is the
// history's mean (to rounding) (the fade's weight 1 keeps the "filtered" image, which is then the mean); with
// the threshold above the history, or at 0, the filter runs and the image differs from the mean.
TEST(TemporalPipeline, PixelsWithALongHistorySkipTheFilter) {
    ensureGlContext();
    Scene scene = wallAndBox();
    Renderer renderer(scene, testShaders());
    Camera a = SlidePastTheBox().a;
    const int size = 32, spp = 2;
    auto differsFromTheMean = [&](float settledSamples) {
        TemporalPipeline pipeline(testShaders());
        TemporalSettings t;
        t.settledSamples = settledSamples;
        runFrames(renderer, pipeline, a, size, spp, 0, 3, t);  // 6 samples a pixel
        Image image = pipeline.result(), mean = pipeline.historyMean();
        // Demodulating by the albedo and multiplying it back rounds: equal means within 1e-5 relative.
        int differ = 0;
        for (size_t i = 0; i < image.pixels.size(); ++i)
            differ += glm::length(image.pixels[i] - mean.pixels[i]) > 1e-5f * glm::length(mean.pixels[i]);
        return differ;
    };
    EXPECT_EQ(differsFromTheMean(6.0f), 0);
    EXPECT_GT(differsFromTheMean(7.0f), 100);
    EXPECT_GT(differsFromTheMean(0.0f), 100);
}

}  // namespace
}  // namespace fp::test
