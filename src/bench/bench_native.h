#pragma once
// `fragpath bench --native`: the native reference (src/native) measured in the same process as the GPU
// figures, so that their ratio compares the fragment shader with native code on the same machine at
// the same moment: GPU paths per CPU-second over native paths per CPU-second.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/bench_measure.h"

namespace fp::bench {

struct NativeMeasurement {
    int spp = 1;             // samples per pixel in each run
    std::vector<Run> timed;  // cpuSeconds is the tracing thread's CPU time; wallSeconds equals it
    // Why there are no runs: a suite scene the reference cannot render (one scene asked for by name is
    // refused instead: refuseWhatNativeLacks).
    std::optional<std::string> skipped;
    Spread pathsPerCpuSecond() const;
};

// Throws fp::Error when the native reference cannot render `scene` as the renderer does (native::
// unsupportedFeature), or not with the settings it would be rendered with (settings.renderFor: a scene
// file may ask for another integrator or sampler): asked for one scene, --native refuses rather than
// compare two algorithms.
void refuseWhatNativeLacks(const Scene& scene, const BenchSettings& settings = {});

// One untimed warm-up run, then settings.runs timed runs (run i with seed i) of `spp` samples per pixel
// at the settings' size and depth, on the scene `load` gives.
NativeMeasurement measureNative(const std::function<Scene()>& load, const BenchSettings& settings,
                                int spp = 1);

void printNative(const NativeMeasurement& native, const SceneMeasurement& gpu);
nlohmann::json nativeJson(const NativeMeasurement& native, const SceneMeasurement& gpu);

}  // namespace fp::bench
