#include "bench/bench_measure.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include "core/error.h"
#include "core/file.h"
#include "core/log.h"
#include "core/statistics.h"
#include "core/text.h"
#include "settings/settings_json.h"

namespace fp::bench {

namespace {

std::optional<std::string> environment(const char* name) {
    const char* value = std::getenv(name);
    if (!value) return std::nullopt;
    return std::string(value);
}

// Mesa's boolean environment parsing: these values mean false, any other set value means true.
bool mesaTrue(const std::optional<std::string>& value) {
    if (!value) return false;
    std::string v = toLowerAscii(*value);
    return !(v == "0" || v == "n" || v == "no" || v == "f" || v == "false");
}

// CPU time of the whole machine so far, summed over its CPUs, from the first line of /proc/stat.
struct MachineCpu {
    double busySeconds = 0, totalSeconds = 0;
};
std::optional<MachineCpu> machineCpu() {
    std::ifstream in("/proc/stat");
    std::string label;
    // user nice system idle iowait irq softirq steal; guest time is already counted in user.
    unsigned long long t[8] = {};
    if (!(in >> label) || label != "cpu") return std::nullopt;
    for (unsigned long long& v : t)
        if (!(in >> v)) return std::nullopt;
    double tick = 1.0 / double(sysconf(_SC_CLK_TCK));
    double idle = double(t[3] + t[4]) * tick;
    double busy = double(t[0] + t[1] + t[2] + t[5] + t[6] + t[7]) * tick;
    return MachineCpu{busy, busy + idle};
}

std::string formatted(const char* format, double value) {
    char text[64];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

void printRow(const std::string& label, const std::vector<std::string>& cells) {
    std::printf("  %-8s", label.c_str());
    for (const std::string& cell : cells) std::printf(" %12s", cell.c_str());
    std::printf("\n");
}

nlohmann::json runJson(const Run& run) {
    nlohmann::json j = {{"seed", run.seed}, {"paths", run.paths}, {"rays", run.rays}};
    for (const Column& c : columns()) j[c.key] = c.get(run);
    return j;
}

}  // namespace

// The median rather than the mean, so one run disturbed by another process does not move the figure.
Spread spread(std::vector<double> values) {
    double middle = median(values);  // throws for no values
    auto [min, max] = std::minmax_element(values.begin(), values.end());
    return {middle, *min, *max};
}

const std::vector<Column>& columns() {
    static const std::vector<Column> kColumns = {
        {"wall s", "wall_seconds", "%.3f", [](const Run& r) { return r.wallSeconds; }},
        {"cpu s", "cpu_seconds", "%.3f", [](const Run& r) { return r.cpuSeconds; }},
        {"cpu/wall", "cpu_per_wall", "%.2f", [](const Run& r) { return r.cpuPerWall(); }},
        {"paths/s", "paths_per_second", "%.3e", [](const Run& r) { return r.pathsPerSecond(); }},
        {"paths/cpu-s", "paths_per_cpu_second", "%.3e", [](const Run& r) { return r.pathsPerCpuSecond(); }},
        {"rays/s", "rays_per_second", "%.3e", [](const Run& r) { return r.raysPerSecond(); }},
        {"rays/cpu-s", "rays_per_cpu_second", "%.3e", [](const Run& r) { return r.raysPerCpuSecond(); }},
        {"rays/path", "rays_per_path", "%.3f", [](const Run& r) { return r.raysPerPath(); }},
    };
    return kColumns;
}

Spread SceneMeasurement::summary(const Column& column) const {
    std::vector<double> values;
    for (const Run& run : timed) values.push_back(column.get(run));
    return spread(values);
}

Spread SceneMeasurement::summary(const std::string& key) const {
    for (const Column& c : columns())
        if (key == c.key) return summary(c);
    throw Error("internal: no column " + key);
}

double SceneMeasurement::sceneFirstFrameSeconds() const {
    return secondsBetween(loadStart, firstPassEnd);
}

RenderSettings BenchSettings::renderFor(const Scene& scene) const {
    RenderSettings r = request ? request->settings(scene) : render;
    if (independentSampler) r.sampler = Sampler::Independent;
    return r;
}

Camera BenchSettings::cameraFor(const Scene& scene) const {
    if (request) return request->camera(scene);
    const RenderSettings r = renderFor(scene);
    return scene.camera.value_or(
        frameBounds(scene.bounds(), Camera().fovY, float(r.width) / float(r.height)));
}

SceneMeasurement measureScene(const std::function<Scene()>& load, const BenchSettings& settings) {
    SceneMeasurement m;
    RenderSettings render;
    // The stages of the first frame, each timed on its own so a slow start can be attributed.
    m.loadStart = SteadyClock::now();
    Camera camera;
    std::optional<Renderer> renderer;
    {
        // The scene lives only until the renderer has its GPU copy, so that the largest scenes do not
        // hold two copies through the runs.
        Scene scene = load();
        render = m.render = settings.renderFor(scene);
        camera = settings.cameraFor(scene);
        m.source = scene.source;
        m.loadSeconds = secondsSince(m.loadStart);
        auto stage = SteadyClock::now();
        renderer.emplace(scene, ShaderLibrary(settings.shaderDir), settings.bvh, SceneReads::Auto,
                         usesCausticCasters(render) ? CasterSearch::Run : CasterSearch::Skip);
        m.rendererSeconds = secondsSince(stage);  // BVH build, packing and upload
    }
    auto stage = SteadyClock::now();
    render.seed = 0;
    renderer->configure(render, camera);
    m.compileSeconds = secondsSince(stage);  // GLSL compile and link; llvmpipe JITs at the first draw

    // Run i has seed i: the warm-up is run 0, the timed runs 1..R, so no two runs trace the same paths.
    auto measure = [&](uint32_t seed, bool first) {
        render.seed = seed;
        render.samplesPerPass = first ? 1 : m.render.samplesPerPass;
        renderer->configure(render, camera);
        Run run;
        run.seed = seed;
        auto wallStart = SteadyClock::now();
        double cpuStart = processCpuSeconds();
        bool firstPass = first;
        renderer->render(settings.spp, [&](int) {
            if (firstPass) m.firstPassEnd = SteadyClock::now();
            firstPass = false;
            return true;
        });
        run.wallSeconds = secondsSince(wallStart);
        run.cpuSeconds = processCpuSeconds() - cpuStart;
        // The read-back is outside the timed span: it is the same for every integrator and not tracing.
        run.rays = renderer->readback().raysTraced();
        run.paths = double(render.width) * render.height * renderer->samples();
        return run;
    };
    auto firstPassStart = SteadyClock::now();
    // The warm-up's first pass ends the first frame: by then every pixel has one sample.
    m.warmUp = measure(0, true);
    m.firstPassSeconds = secondsBetween(firstPassStart, m.firstPassEnd);

    std::optional<MachineCpu> machineStart = machineCpu();
    double ownStart = processCpuSeconds();
    for (int i = 1; i <= settings.runs; ++i) m.timed.push_back(measure(uint32_t(i), false));
    std::optional<MachineCpu> machineEnd = machineCpu();
    double own = processCpuSeconds() - ownStart;
    if (machineStart && machineEnd && machineEnd->totalSeconds > machineStart->totalSeconds) {
        double others = machineEnd->busySeconds - machineStart->busySeconds - own;
        // /proc/stat counts in clock ticks, coarser than the process's CPU clock, so a quiet machine can
        // come out a little below 0.
        m.othersCpuShare = std::max(0.0, others / (machineEnd->totalSeconds - machineStart->totalSeconds));
    }
    m.stats = renderer->stats();
    return m;
}

std::string BenchEnvironment::threadsText() const {
    return threads.value_or("unset");
}

std::string BenchEnvironment::cacheText() const {
    if (!cacheDisable) return "enabled (MESA_SHADER_CACHE_DISABLE unset)";
    return std::string(mesaTrue(cacheDisable) ? "disabled" : "enabled") +
           " (MESA_SHADER_CACHE_DISABLE=" + *cacheDisable + ")";
}

BenchEnvironment readBenchEnvironment() {
    BenchEnvironment e;
    e.threads = environment("LP_NUM_THREADS");
    e.cacheDisable = environment("MESA_SHADER_CACHE_DISABLE");
    if (!e.threads)
        warn(
            "LP_NUM_THREADS is unset, so llvmpipe picks its thread count from the CPUs it sees; set it "
            "explicitly for figures that can be compared");
    return e;
}

void printHeader(const BenchEnvironment& environment, const BenchSettings& settings) {
    const RenderSettings& r = settings.render;
    std::printf("renderer         %s\n", environment.renderer.c_str());
    std::printf("LP_NUM_THREADS   %s\n", environment.threadsText().c_str());
    std::printf("shader cache     %s\n", environment.cacheText().c_str());
    std::printf(
        "settings         %dx%d, %d spp per run, max depth %d, %s, %s sampler, %d timed runs after 1 "
        "warm-up\n",
        r.width, r.height, settings.spp, r.maxDepth, integratorName(r.integrator), samplerName(r.sampler),
        settings.runs);
}

void printMeasurement(const SceneMeasurement& m, double firstFrameSeconds,
                      std::optional<double> contextSeconds) {
    const SceneStats& stats = m.stats;
    std::printf("scene            %s: %u triangles (%u emissive)\n", m.source.c_str(), stats.triangles,
                stats.emitters);
    std::printf(
        "bvh              %u nodes, depth %u, SAH cost %.3f, built in %.3g s (%.3g CPU-s, threads %d): "
        "%.3g triangles/s\n",
        stats.bvh.nodeCount, stats.bvh.maxDepth, stats.bvh.sahCost, stats.bvhBuildSeconds,
        stats.bvhBuildCpuSeconds, stats.bvhBuildThreads, stats.storedTriangles / stats.bvhBuildSeconds);
    double bytes = double(stats.gpuBytes);
    std::string total = bytes >= 1e6 ? formatted("%.1f MB", bytes / 1e6) : formatted("%.1f kB", bytes / 1e3);
    std::printf(
        "gpu memory       %s: %.1f bytes per triangle, %.1f of them positions + BVH; %.0f %% read in place\n",
        total.c_str(), bytes / stats.triangles, double(stats.gpuGeometryBytes) / stats.triangles,
        100.0 * double(stats.gpuPinnedBytes) / bytes);
    std::printf("scene reads      %s (FRAGPATH_SCENE_READS=texelFetch forces texelFetch)\n",
                sceneReadsName(stats.sceneReads));
    std::string context = contextSeconds ? "context " + formatted("%.3f", *contextSeconds) + ", " : "";
    std::printf(
        "first frame      %.3f s: %sload %.3f, bvh %.3f, pack + upload %.3f, compile %.3f, first pass %.3f\n",
        firstFrameSeconds, context.c_str(), m.loadSeconds, stats.bvhBuildSeconds,
        m.rendererSeconds - stats.bvhBuildSeconds, m.compileSeconds, m.firstPassSeconds);
    std::printf("warm-up          %.3f s wall, %.3f s cpu (seed 0, not counted)\n", m.warmUp.wallSeconds,
                m.warmUp.cpuSeconds);
    if (m.othersCpuShare)
        std::printf("other processes  %.1f %% of the machine's CPU time during the timed runs\n",
                    100.0 * *m.othersCpuShare);
    std::printf("\n");

    std::vector<std::string> headings;
    for (const Column& c : columns()) headings.push_back(c.heading);
    printRow("run", headings);
    for (const Run& run : m.timed) {
        std::vector<std::string> cells;
        for (const Column& c : columns()) cells.push_back(formatted(c.format, c.get(run)));
        printRow(std::to_string(run.seed), cells);
    }
    std::vector<Spread> spreads;
    for (const Column& c : columns()) spreads.push_back(m.summary(c));
    for (const char* row : {"median", "min", "max"}) {
        std::vector<std::string> cells;
        for (size_t i = 0; i < spreads.size(); ++i) {
            const Spread& s = spreads[i];
            double v = row == std::string("median") ? s.median : row == std::string("min") ? s.min : s.max;
            cells.push_back(formatted(columns()[i].format, v));
        }
        printRow(row, cells);
    }
}

nlohmann::json environmentJson(const BenchEnvironment& environment) {
    nlohmann::json j;
    j["renderer"] = environment.renderer;
    j["lp_num_threads"] =
        environment.threads ? nlohmann::json(*environment.threads) : nlohmann::json(nullptr);
    j["mesa_shader_cache_disable"] =
        environment.cacheDisable ? nlohmann::json(*environment.cacheDisable) : nlohmann::json(nullptr);
    j["shader_cache_disabled"] = mesaTrue(environment.cacheDisable);
    return j;
}

nlohmann::json benchSettingsJson(const BenchSettings& settings) {
    nlohmann::json j = fp::settingsJson(settings.render);
    j["spp"] = settings.spp;
    j["runs"] = settings.runs;
    return j;
}

nlohmann::json measurementJson(const SceneMeasurement& m, double firstFrameSeconds) {
    const SceneStats& stats = m.stats;
    nlohmann::json j;
    j["scene"] = {{"source", m.source}, {"triangles", stats.triangles}, {"emitters", stats.emitters}};
    j["bvh"] = {{"build_seconds", stats.bvhBuildSeconds},
                {"build_cpu_seconds", stats.bvhBuildCpuSeconds},
                {"build_threads", stats.bvhBuildThreads},
                {"triangles_per_second", stats.storedTriangles / stats.bvhBuildSeconds},
                {"sah_cost", stats.bvh.sahCost},
                {"nodes", stats.bvh.nodeCount},
                {"depth", stats.bvh.maxDepth}};
    j["gpu"] = {{"bytes", stats.gpuBytes},
                {"geometry_bytes", stats.gpuGeometryBytes},
                {"bytes_per_triangle", double(stats.gpuBytes) / stats.triangles},
                {"geometry_bytes_per_triangle", double(stats.gpuGeometryBytes) / stats.triangles},
                {"pinned_bytes", stats.gpuPinnedBytes},
                {"scene_reads", sceneReadsName(stats.sceneReads)}};
    j["first_frame"] = {{"seconds", firstFrameSeconds},
                        {"load_seconds", m.loadSeconds},
                        {"bvh_seconds", m.stats.bvhBuildSeconds},
                        {"pack_and_upload_seconds", m.rendererSeconds - m.stats.bvhBuildSeconds},
                        {"compile_seconds", m.compileSeconds},
                        {"first_pass_seconds", m.firstPassSeconds}};
    j["warm_up"] = runJson(m.warmUp);
    j["runs"] = nlohmann::json::array();
    for (const Run& run : m.timed) j["runs"].push_back(runJson(run));
    for (const Column& c : columns()) {
        Spread s = m.summary(c);
        j["summary"][c.key] = {{"median", s.median}, {"min", s.min}, {"max", s.max}};
    }
    j["other_processes_cpu_share"] =
        m.othersCpuShare ? nlohmann::json(*m.othersCpuShare) : nlohmann::json(nullptr);
    return j;
}

void checkJsonPath(const std::string& path) {
    checkWritablePath(path, "--json");
}

void writeJson(const std::string& path, const nlohmann::json& j) {
    std::ofstream out(path);
    out << j.dump(2) << "\n";
    if (!out) throw Error("--json " + path + ": could not write: " + std::strerror(errno));
}

}  // namespace fp::bench
