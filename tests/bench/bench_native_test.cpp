// bench/bench_native.h: which scenes --native refuses, and the figures of the native reference.
#include <gtest/gtest.h>

#include <string>

#include "bench/bench_native.h"
#include "core/error.h"
#include "scene/builtin_scene.h"

namespace fp::bench {
namespace {

Run nativeRun(uint32_t seed, double cpu, double paths) {
    Run r;
    r.seed = seed;
    r.wallSeconds = r.cpuSeconds = cpu;
    r.paths = paths;
    r.rays = 3 * paths;
    return r;
}

// What bench --native measures with: nee and independent numbers, and a command line without flags, so
// that each scene's file decides the rest (request/render_request.h).
BenchSettings nativeSettings() {
    BenchSettings s;
    s.request = RenderRequest(Args({}, requestOptionGroups(kAllRequestOptions)));
    s.independentSampler = true;
    return s;
}

// The message of the fp::Error that refuseWhatNativeLacks throws for `scene`, "" for none.
std::string refusal(const Scene& scene, const BenchSettings& settings = nativeSettings()) {
    try {
        refuseWhatNativeLacks(scene, settings);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(BenchNative, AcceptsTheLambertianCornellBox) {
    EXPECT_EQ(refusal(builtinCornellBox()), "");
}

TEST(BenchNative, RefusesWhatTheReferenceDoesNotImplement) {
    Scene metal = builtinCornellBox();
    metal.materials.back().type = MaterialType::Conductor;
    metal.materials.back().name = "gold";
    std::string why = refusal(metal);
    EXPECT_EQ(why.rfind("--native: " + metal.source + ": ", 0), 0u) << why;
    EXPECT_NE(why.find("material 'gold' is not Lambertian"), std::string::npos) << why;

    Scene textured = builtinCornellBox();
    textured.materials.front().diffuseTexture = 0;
    EXPECT_NE(refusal(textured).find("has a texture"), std::string::npos);

    Scene sky = builtinCornellBox();
    sky.environment.map = Image(2, 1);
    EXPECT_NE(refusal(sky).find("an environment map"), std::string::npos);
}

// A scene file's render block arrives through the request (BenchSettings::renderFor), so it is checked
// too: a Cornell box whose file asks for bdpt, or for Sobol points, is not what the reference renders.
TEST(BenchNative, RefusesASceneFileAskingForAnotherAlgorithm) {
    Scene bdpt = builtinCornellBox();
    bdpt.fileSettings.set("integrator", int(Integrator::Bdpt));
    EXPECT_NE(refusal(bdpt).find("integrator bdpt"), std::string::npos) << refusal(bdpt);
    Scene clamped = builtinCornellBox();
    clamped.fileSettings.set("clamp_indirect", 2.0);
    EXPECT_NE(refusal(clamped).find("clamp"), std::string::npos) << refusal(clamped);
    BenchSettings sobol;  // --native with --sampler sobol never gets here; a default BenchSettings does
    EXPECT_NE(refusal(builtinCornellBox(), sobol).find("sampler sobol"), std::string::npos);
}

TEST(BenchNative, PathsPerCpuSecondIsTheSpreadOfTheRuns) {
    NativeMeasurement n;
    Spread none = n.pathsPerCpuSecond();
    EXPECT_EQ(none.median, 0.0);
    n.timed = {nativeRun(1, 2.0, 100), nativeRun(2, 1.0, 100), nativeRun(3, 4.0, 100)};  // 50, 100, 25
    Spread s = n.pathsPerCpuSecond();
    EXPECT_DOUBLE_EQ(s.median, 50.0);
    EXPECT_DOUBLE_EQ(s.min, 25.0);
    EXPECT_DOUBLE_EQ(s.max, 100.0);
}

TEST(BenchNative, JsonHasTheRunsAndTheRatioToTheGpu) {
    SceneMeasurement gpu;
    bench::Run g;
    g.wallSeconds = 1.0;
    g.cpuSeconds = 2.0;
    g.paths = 1000;  // 500 paths per CPU-second
    gpu.timed = {g};
    NativeMeasurement n;
    n.spp = 2;
    n.timed = {nativeRun(1, 2.0, 100), nativeRun(2, 1.0, 100), nativeRun(3, 4.0, 100)};
    nlohmann::json j = nativeJson(n, gpu);
    EXPECT_EQ(j["spp_per_run"], 2);
    ASSERT_EQ(j["runs"].size(), 3u);
    EXPECT_EQ(j["runs"][1]["seed"], 2);
    EXPECT_DOUBLE_EQ(j["runs"][1]["cpu_seconds"].get<double>(), 1.0);
    EXPECT_DOUBLE_EQ(j["runs"][1]["paths_per_cpu_second"].get<double>(), 100.0);
    EXPECT_DOUBLE_EQ(j["runs"][1]["rays"].get<double>(), 300.0);
    EXPECT_DOUBLE_EQ(j["paths_per_cpu_second"]["median"].get<double>(), 50.0);
    EXPECT_DOUBLE_EQ(j["paths_per_cpu_second"]["min"].get<double>(), 25.0);
    EXPECT_DOUBLE_EQ(j["paths_per_cpu_second"]["max"].get<double>(), 100.0);
    EXPECT_DOUBLE_EQ(j["gpu_over_native"].get<double>(), 10.0);  // 500 / 50

    n.skipped = "no triangles";
    EXPECT_EQ(nativeJson(n, gpu), nlohmann::json({{"skipped", "no triangles"}}));
}

}  // namespace
}  // namespace fp::bench
