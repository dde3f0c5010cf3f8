#include "bench/bench_native.h"

#include <cstdio>

#include "core/error.h"
#include "native/native_path.h"
#include "pack/layout.h"

namespace fp::bench {

Spread NativeMeasurement::pathsPerCpuSecond() const {
    std::vector<double> values;
    for (const Run& run : timed) values.push_back(run.pathsPerCpuSecond());
    return values.empty() ? Spread{} : spread(values);
}

void refuseWhatNativeLacks(const Scene& scene, const BenchSettings& settings) {
    if (auto why = native::unsupportedFeature(scene))
        throw Error("--native: " + scene.source + ": " + *why + "; nothing to compare with");
    const RenderSettings r = settings.renderFor(scene);
    std::string asked;
    if (r.integrator != Integrator::Nee) asked = std::string("integrator ") + integratorName(r.integrator);
    if (r.sampler != Sampler::Independent) asked = std::string("sampler ") + samplerName(r.sampler);
    if (r.lightSampling != LightSampling::Auto)
        asked = std::string("light sampling ") + lightSamplingName(r.lightSampling);
    if (r.lightSelection == LightSelection::Tree) asked = "the light tree";
    if (r.clampIndirect > 0.0f) asked = "a clamp of indirect light";
    if (!asked.empty())
        throw Error("--native: " + scene.source + " is rendered with " + asked +
                    ", which the native reference does not implement; a ratio would compare two algorithms");
}

NativeMeasurement measureNative(const std::function<Scene()>& load, const BenchSettings& settings, int spp) {
    NativeMeasurement m;
    m.spp = spp;
    Scene scene = load();
    native::Scene prepared;
    try {
        prepared = native::buildScene(scene, settings.bvh);
    } catch (const Error& e) {
        m.skipped = e.what();
        return m;
    }
    const Camera camera = settings.cameraFor(scene);
    const RenderSettings render = settings.renderFor(scene);
    native::Settings s;
    s.width = render.width;
    s.height = render.height;
    s.maxDepth = render.maxDepth;
    s.spp = spp;
    for (int i = 0; i <= settings.runs; ++i) {  // run 0 warms the caches and is not counted
        s.seed = uint32_t(i);
        native::Result r = native::render(prepared, camera, s);
        if (i == 0) continue;
        Run run;
        run.seed = s.seed;
        run.wallSeconds = run.cpuSeconds = r.cpuSeconds;
        run.paths = r.paths;
        run.rays = r.rays;
        m.timed.push_back(run);
    }
    return m;
}

void printNative(const NativeMeasurement& native, const SceneMeasurement& gpu) {
    if (native.skipped) {
        std::printf("native reference skipped, no comparison: %s\n", native.skipped->c_str());
        return;
    }
    Spread n = native.pathsPerCpuSecond();
    double g = gpu.summary("paths_per_cpu_second").median;
    std::printf(
        "native reference %.4g paths/cpu-s (min %.4g, max %.4g; one thread, %d spp per run, median of %zu)\n"
        "gpu / native     %.3f (paths per CPU-second of the shader over the native reference's)\n",
        n.median, n.min, n.max, native.spp, native.timed.size(), g / n.median);
}

nlohmann::json nativeJson(const NativeMeasurement& native, const SceneMeasurement& gpu) {
    if (native.skipped) return {{"skipped", *native.skipped}};
    Spread n = native.pathsPerCpuSecond();
    nlohmann::json runs = nlohmann::json::array();
    for (const Run& run : native.timed)
        runs.push_back({{"seed", run.seed},
                        {"paths", run.paths},
                        {"rays", run.rays},
                        {"cpu_seconds", run.cpuSeconds},
                        {"paths_per_cpu_second", run.pathsPerCpuSecond()}});
    return {{"spp_per_run", native.spp},
            {"runs", runs},
            {"paths_per_cpu_second", {{"median", n.median}, {"min", n.min}, {"max", n.max}}},
            {"gpu_over_native", gpu.summary("paths_per_cpu_second").median / n.median}};
}

}  // namespace fp::bench
