// A real measurement through OSMesa, as small as it gets (8x8, 1 spp, 1 timed run): the figures must
// agree with each other and with what was asked for, whatever the machine's speed.
#include <gtest/gtest.h>

#include "bench/bench_measure.h"
#include "bench/bench_native.h"
#include "render/render_test_util.h"  // ensureGlContext, testShaders
#include "scene/builtin_scene.h"

namespace fp::bench {
namespace {

constexpr int kSize = 8, kSpp = 1, kRuns = 1;

BenchSettings tinySettings() {
    BenchSettings s;
    s.render.width = s.render.height = kSize;
    s.render.samplesPerPass = 1;
    s.spp = kSpp;
    s.runs = kRuns;
    s.shaderDir = test::testShaders().directory();
    return s;
}

void expectConsistentRun(const Run& run, uint32_t seed, int maxDepth) {
    SCOPED_TRACE("run with seed " + std::to_string(seed));
    EXPECT_EQ(run.seed, seed);
    EXPECT_EQ(run.paths, double(kSize * kSize * kSpp));  // one path per pixel and sample
    EXPECT_GT(run.wallSeconds, 0.0);
    EXPECT_GT(run.cpuSeconds, 0.0);
    // Every path traces its camera ray; at most a bounce ray and a shadow ray per bounce after it.
    EXPECT_GE(run.rays, run.paths);
    EXPECT_LE(run.rays, run.paths * (1 + 2 * maxDepth));
    EXPECT_DOUBLE_EQ(run.pathsPerSecond(), run.paths / run.wallSeconds);
    EXPECT_DOUBLE_EQ(run.raysPerCpuSecond(), run.rays / run.cpuSeconds);
}

TEST(BenchRealMeasurement, FiguresAgreeWithEachOtherOnATinyCornellBox) {
    test::ensureGlContext();
    const BenchSettings settings = tinySettings();
    int loads = 0;
    Scene cornell = builtinCornellBox();
    SceneMeasurement m = measureScene(
        [&] {
            ++loads;
            return cornell;
        },
        settings);
    EXPECT_EQ(loads, 1);
    EXPECT_EQ(m.source, cornell.source);
    EXPECT_EQ(m.stats.triangles, cornell.triangles.size());
    EXPECT_GT(m.stats.emitters, 0u);
    EXPECT_GT(m.stats.gpuBytes, 0u);

    expectConsistentRun(m.warmUp, 0, settings.render.maxDepth);
    ASSERT_EQ(m.timed.size(), size_t(kRuns));
    expectConsistentRun(m.timed[0], 1, settings.render.maxDepth);
    // With one run, every summary is that run's figure.
    for (const Column& c : columns()) {
        Spread s = m.summary(c);
        EXPECT_DOUBLE_EQ(s.median, c.get(m.timed[0])) << c.key;
        EXPECT_DOUBLE_EQ(s.min, s.max) << c.key;
    }

    // The stages of the first frame follow each other within it.
    for (double stage : {m.loadSeconds, m.rendererSeconds, m.compileSeconds, m.firstPassSeconds})
        EXPECT_GE(stage, 0.0);
    EXPECT_GT(m.firstPassSeconds, 0.0);
    // The BVH build is part of the renderer's stage (the first frame prints the rest as pack + upload).
    EXPECT_LE(m.stats.bvhBuildSeconds, m.rendererSeconds);
    EXPECT_LE(m.loadSeconds + m.rendererSeconds + m.compileSeconds + m.firstPassSeconds,
              m.sceneFirstFrameSeconds() + 1e-6);
    // Absent when the runs are shorter than a tick of /proc/stat; a share of the machine when present.
    if (m.othersCpuShare) {
        EXPECT_GE(*m.othersCpuShare, 0.0);
        EXPECT_LE(*m.othersCpuShare, 1.0);
    }

    nlohmann::json j = measurementJson(m, m.sceneFirstFrameSeconds());
    EXPECT_EQ(j["scene"]["triangles"], m.stats.triangles);
    EXPECT_DOUBLE_EQ(j["runs"][0]["paths"].get<double>(), kSize * kSize * kSpp);
    EXPECT_DOUBLE_EQ(j["summary"]["paths_per_second"]["median"].get<double>(),
                     m.timed[0].paths / m.timed[0].wallSeconds);
}

TEST(BenchRealMeasurement, NativeReferenceRunsAreConsistentToo) {
    const BenchSettings settings = tinySettings();
    NativeMeasurement n = measureNative([] { return builtinCornellBox(); }, settings, kSpp);
    ASSERT_FALSE(n.skipped) << *n.skipped;
    EXPECT_EQ(n.spp, kSpp);
    ASSERT_EQ(n.timed.size(), size_t(kRuns));  // the warm-up run is not kept
    expectConsistentRun(n.timed[0], 1, settings.render.maxDepth);
    EXPECT_EQ(n.timed[0].wallSeconds, n.timed[0].cpuSeconds);  // one thread's CPU time stands for both
    EXPECT_DOUBLE_EQ(n.pathsPerCpuSecond().median, n.timed[0].paths / n.timed[0].cpuSeconds);
}

}  // namespace
}  // namespace fp::bench
