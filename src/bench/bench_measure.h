#pragma once
// The measurement behind `fragpath bench`, shared by the single-scene bench and the suite, so that a
// figure means the same in both: one renderer per scene, time to first frame by stage, one untimed
// warm-up run, then R timed runs (run i with seed i) reported as median, min and max.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/clock.h"
#include "render/renderer.h"
#include "request/render_request.h"
#include "scene/scene.h"
#include "settings/render_settings.h"

namespace fp {

class GlContext;

namespace bench {

struct Run {
    uint32_t seed = 0;
    double wallSeconds = 0, cpuSeconds = 0, paths = 0, rays = 0;
    double pathsPerSecond() const { return paths / wallSeconds; }
    double pathsPerCpuSecond() const { return paths / cpuSeconds; }
    double raysPerSecond() const { return rays / wallSeconds; }
    double raysPerCpuSecond() const { return rays / cpuSeconds; }
    double raysPerPath() const { return rays / paths; }
    // How many CPUs were busy on average: near LP_NUM_THREADS (plus the waiting main thread's share)
    // when rasterisation scales, near 1 when it does not.
    double cpuPerWall() const { return cpuSeconds / wallSeconds; }
};

struct Spread {
    double median = 0, min = 0, max = 0;
};
// Median, min and max of values (not empty: throws std::invalid_argument).
Spread spread(std::vector<double> values);

// One measured quantity of a run, with the names it has in the table and in the JSON.
struct Column {
    const char* heading;
    const char* key;
    const char* format;
    double (*get)(const Run&);
};
const std::vector<Column>& columns();

// The settings every scene of one command is measured with.
struct BenchSettings {
    // The timed runs draw render.samplesPerPass samples per pass (bench's default: 8, which costs about
    // 5 % less CPU per path than 1 on llvmpipe: docs/optimisation-log.md, entry 8); the warm-up, whose
    // first pass is the first frame, always draws 1, as `fragpath render` does by default.
    RenderSettings render;
    int spp = 8;   // samples per pixel in each run
    int runs = 5;  // timed runs after the warm-up
    BvhBuildOptions bvh = layout::bvhOptions();
    // Read the shaders from this directory instead of the ones built in (empty: built in), so that
    // shader variants can be compared run for run with one binary.
    std::string shaderDir;
    // The command line's request: each scene is rendered with its flags over the scene file's defaults
    // (request/render_request.h). Without one, `render` and the scene's camera as they are.
    std::optional<RenderRequest> request;
    bool independentSampler = false;  // --native without --sampler: the native reference's numbers

    RenderSettings renderFor(const Scene& scene) const;
    Camera cameraFor(const Scene& scene) const;
};

struct SceneMeasurement {
    std::string source;
    RenderSettings render;  // what it was rendered with (BenchSettings::renderFor)
    SceneStats stats;
    // Stages of the first frame: load (or generate) the scene; build the BVH, pack and upload; compile
    // and link the GLSL; the first pass, which includes llvmpipe's JIT of the fragment shader.
    SteadyClock::time_point loadStart, firstPassEnd;
    double loadSeconds = 0, rendererSeconds = 0, compileSeconds = 0, firstPassSeconds = 0;
    Run warmUp;
    std::vector<Run> timed;
    // The share of all the machine's CPU time that other processes used during the timed runs (from
    // /proc/stat, less this process's own CPU time); absent where /proc/stat cannot be read.
    std::optional<double> othersCpuShare;

    Spread summary(const Column& column) const;
    Spread summary(const std::string& key) const;
    // From the start of loading to the end of the first pass.
    double sceneFirstFrameSeconds() const;
};

// Loads the scene with `load` (timed as the load stage), builds a renderer for it and measures it as
// the header says. Needs a current GL context.
SceneMeasurement measureScene(const std::function<Scene()>& load, const BenchSettings& settings);

// What the figures depend on besides the scene: the GL renderer and llvmpipe's settings.
struct BenchEnvironment {
    std::string renderer;
    std::optional<std::string> threads, cacheDisable;  // LP_NUM_THREADS, MESA_SHADER_CACHE_DISABLE
    std::string threadsText() const;
    std::string cacheText() const;
};
// Reads the environment variables, and warns when LP_NUM_THREADS is unset.
BenchEnvironment readBenchEnvironment();

// The lines before any scene: renderer, thread count, shader cache, settings.
void printHeader(const BenchEnvironment& environment, const BenchSettings& settings);
// One scene's figures: scene, BVH, GPU memory, first frame (`firstFrameSeconds`, broken into stages;
// `contextSeconds` when the context creation is part of it), warm-up, the run table and its spread.
void printMeasurement(const SceneMeasurement& m, double firstFrameSeconds,
                      std::optional<double> contextSeconds);

nlohmann::json environmentJson(const BenchEnvironment& environment);
nlohmann::json benchSettingsJson(const BenchSettings& settings);
// The scene, BVH, GPU memory, first frame, warm-up, every run and the summary, as in printMeasurement.
nlohmann::json measurementJson(const SceneMeasurement& m, double firstFrameSeconds);

// Fails before the benchmark, not after minutes of it, when the JSON cannot be written.
void checkJsonPath(const std::string& path);
void writeJson(const std::string& path, const nlohmann::json& j);

}  // namespace bench
}  // namespace fp
