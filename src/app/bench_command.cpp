// `fragpath bench`: speed figures that can be compared between machines, Mesa versions and commits.
// One untimed warm-up run absorbs shader compilation and llvmpipe's JIT, then R timed runs of the same
// settings report wall time, process CPU time and throughput as median, min and max.
#include <sys/resource.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/args.h"
#include "app/commands.h"
#include "core/error.h"
#include "core/log.h"
#include "gl/context.h"
#include "render/renderer.h"
#include "scene/builtin_scene.h"
#include "scene/load.h"

namespace fp {

namespace {

const char* kBenchUsage =
    "usage: fragpath bench [SCENE] [options]\n"
    "\n"
    "Measures the offscreen renderer on SCENE (an .obj with its .mtl, or a .json scene file; default: the\n"
    "built-in Cornell box): time to first frame, then one untimed warm-up run and R timed runs of the\n"
    "same settings (run i uses seed i). Prints per-run wall and process CPU seconds, paths/s, paths per\n"
    "CPU-second and rays/s, with their median, min and max. No image is written.\n"
    "\n"
    "options:\n"
    "  --size WxH            image size (default 512x512)\n"
    "  --spp N               samples per pixel in each run (default 8)\n"
    "  --runs R              timed runs after the warm-up (default 5)\n"
    "  --max-depth D         bounces (default 5)\n"
    "  --integrator NAME     naive | bsdf | nee (default nee)\n"
    "  --json FILE           also write every figure to FILE as JSON\n"
    "  -h, --help            this text\n"
    "\n"
    "For comparable figures on Mesa's llvmpipe, set LP_NUM_THREADS explicitly (it defaults to the number\n"
    "of CPUs). Mesa caches compiled shaders on disk, so the first bench after a shader change has a\n"
    "longer time to first frame; MESA_SHADER_CACHE_DISABLE=true measures the cold case every time.\n";

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// User plus system time of every thread in the process. llvmpipe rasterises on threads of this process,
// so this is the CPU the render cost, not just the CPU of the thread that waits in glFinish.
double processCpuSeconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

std::optional<std::string> environment(const char* name) {
    const char* value = std::getenv(name);
    if (!value) return std::nullopt;
    return std::string(value);
}

// Mesa's boolean environment parsing: these values mean false, any other set value means true.
bool mesaTrue(const std::optional<std::string>& value) {
    if (!value) return false;
    std::string v = *value;
    for (char& c : v) c = char(std::tolower(static_cast<unsigned char>(c)));
    return !(v == "0" || v == "n" || v == "no" || v == "f" || v == "false");
}

struct Run {
    uint32_t seed = 0;
    double wallSeconds = 0, cpuSeconds = 0, paths = 0, rays = 0;
    double pathsPerSecond() const { return paths / wallSeconds; }
    double pathsPerCpuSecond() const { return paths / cpuSeconds; }
    double raysPerSecond() const { return rays / wallSeconds; }
    double raysPerPath() const { return rays / paths; }
    // How many CPUs were busy on average: near LP_NUM_THREADS (plus the waiting main thread's share)
    // when rasterisation scales, near 1 when it does not.
    double cpuPerWall() const { return cpuSeconds / wallSeconds; }
};

struct Spread {
    double median = 0, min = 0, max = 0;
};

// The median rather than the mean, so one run disturbed by another process does not move the figure.
Spread spread(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    size_t n = values.size();
    double median = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
    return {median, values.front(), values.back()};
}

// One measured quantity of a run, with the names it has in the table and in the JSON.
struct Column {
    const char* heading;
    const char* key;
    const char* format;
    double (*get)(const Run&);
};

const Column kColumns[] = {
    {"wall s", "wall_seconds", "%.3f", [](const Run& r) { return r.wallSeconds; }},
    {"cpu s", "cpu_seconds", "%.3f", [](const Run& r) { return r.cpuSeconds; }},
    {"cpu/wall", "cpu_per_wall", "%.2f", [](const Run& r) { return r.cpuPerWall(); }},
    {"paths/s", "paths_per_second", "%.3e", [](const Run& r) { return r.pathsPerSecond(); }},
    {"paths/cpu-s", "paths_per_cpu_second", "%.3e", [](const Run& r) { return r.pathsPerCpuSecond(); }},
    {"rays/s", "rays_per_second", "%.3e", [](const Run& r) { return r.raysPerSecond(); }},
    {"rays/path", "rays_per_path", "%.3f", [](const Run& r) { return r.raysPerPath(); }},
};

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

// Fails before the benchmark, not after minutes of it, when the JSON cannot be written.
void checkJsonPath(const std::string& path) {
    std::filesystem::path dir = std::filesystem::path(path).parent_path();
    if (dir.empty()) dir = ".";
    if (!std::filesystem::is_directory(dir))
        throw Error("--json " + path + ": directory " + dir.string() + " does not exist");
    if (std::filesystem::is_directory(path)) throw Error("--json " + path + " is a directory");
}

nlohmann::json runJson(const Run& run) {
    nlohmann::json j = {{"seed", run.seed}, {"paths", run.paths}, {"rays", run.rays}};
    for (const Column& c : kColumns) j[c.key] = c.get(run);
    return j;
}

}  // namespace

int benchCommand(const std::vector<std::string>& argv) {
    // Time to first frame counts from here: argument parsing is negligible, and everything a user waits
    // for before the first pixel (context, load, BVH, upload, compile, JIT, first pass) comes after.
    auto start = Clock::now();
    Args args(argv, {"--size", "--spp", "--runs", "--max-depth", "--integrator", "--json"}, {"-h", "--help"});
    if (args.has("-h") || args.has("--help")) {
        std::fputs(kBenchUsage, stdout);
        return 0;
    }
    if (args.positional().size() > 1)
        throw Error("bench takes one scene file, got " + std::to_string(args.positional().size()));
    RenderSettings settings;  // samplesPerPass stays 1, as `fragpath render` renders by default
    if (auto s = args.size("--size")) settings.width = s->x, settings.height = s->y;
    int spp = args.integer("--spp", 1, 1 << 20).value_or(8);
    int runs = args.integer("--runs", 1, 1000).value_or(5);
    settings.maxDepth = args.integer("--max-depth", 0, 1000).value_or(5);
    settings.integrator = parseIntegrator(args.text("--integrator").value_or("nee"));
    std::optional<std::string> jsonPath = args.text("--json");
    if (jsonPath) checkJsonPath(*jsonPath);

    std::optional<std::string> threads = environment("LP_NUM_THREADS");
    std::optional<std::string> cacheDisable = environment("MESA_SHADER_CACHE_DISABLE");
    if (!threads)
        warn(
            "LP_NUM_THREADS is unset, so llvmpipe picks its thread count from the CPUs it sees; set it "
            "explicitly for figures that can be compared");

    // The stages of the first frame, each timed on its own so a slow start can be attributed.
    auto stage = Clock::now();
    std::unique_ptr<GlContext> context = createOsMesaContext();
    double contextSeconds = secondsSince(stage);
    stage = Clock::now();
    Scene scene = args.positional().empty() ? builtinCornellBox() : loadScene(args.positional()[0]);
    Camera camera = scene.camera.value_or(frameBounds(scene.bounds()));
    double loadSeconds = secondsSince(stage);
    stage = Clock::now();
    Renderer renderer(scene);
    double rendererSeconds = secondsSince(stage);  // BVH build, packing and upload
    stage = Clock::now();
    settings.seed = 0;
    renderer.configure(settings, camera);
    double compileSeconds = secondsSince(stage);  // GLSL compile and link; llvmpipe JITs at the first draw

    // Run i has seed i: the warm-up is run 0, the timed runs 1..R, so no two runs trace the same paths.
    auto measure = [&](uint32_t seed, double* firstFrameSeconds) {
        settings.seed = seed;
        renderer.configure(settings, camera);
        Run run;
        run.seed = seed;
        auto wallStart = Clock::now();
        double cpuStart = processCpuSeconds();
        renderer.render(spp, [&](int) {
            if (firstFrameSeconds && *firstFrameSeconds == 0.0) *firstFrameSeconds = secondsSince(start);
            return true;
        });
        run.wallSeconds = secondsSince(wallStart);
        run.cpuSeconds = processCpuSeconds() - cpuStart;
        // The read-back is outside the timed span: it is the same for every integrator and not tracing.
        run.rays = renderer.readback().raysTraced();
        run.paths = double(settings.width) * settings.height * renderer.samples();
        return run;
    };
    auto firstPassStart = Clock::now();
    double firstFrameSeconds = 0.0;
    // The warm-up's first pass ends the first frame: by then every pixel has one sample.
    Run warmUp = measure(0, &firstFrameSeconds);
    double firstPassSeconds =
        firstFrameSeconds - std::chrono::duration<double>(firstPassStart - start).count();
    std::vector<Run> timed;
    for (int i = 1; i <= runs; ++i) timed.push_back(measure(uint32_t(i), nullptr));

    const SceneStats& stats = renderer.stats();
    std::string description = context->description();
    std::string threadsText = threads.value_or("unset");
    std::string cacheText = "enabled (MESA_SHADER_CACHE_DISABLE unset)";
    if (cacheDisable)
        cacheText = std::string(mesaTrue(cacheDisable) ? "disabled" : "enabled") +
                    " (MESA_SHADER_CACHE_DISABLE=" + *cacheDisable + ")";

    std::printf("renderer         %s\n", description.c_str());
    std::printf("LP_NUM_THREADS   %s\n", threadsText.c_str());
    std::printf("shader cache     %s\n", cacheText.c_str());
    std::printf("scene            %s: %u triangles (%u emissive)\n", scene.source.c_str(), stats.triangles,
                stats.emitters);
    std::printf("bvh              %u nodes, depth %u, SAH cost %.3f, built in %.3g s\n", stats.bvh.nodeCount,
                stats.bvh.maxDepth, stats.bvh.sahCost, stats.bvhBuildSeconds);
    std::printf("settings         %dx%d, %d spp per run, max depth %d, %s, %d timed runs after 1 warm-up\n",
                settings.width, settings.height, spp, settings.maxDepth, integratorName(settings.integrator),
                runs);
    std::printf(
        "first frame      %.3f s: context %.3f, load %.3f, bvh + upload %.3f, compile %.3f, first pass "
        "%.3f\n",
        firstFrameSeconds, contextSeconds, loadSeconds, rendererSeconds, compileSeconds, firstPassSeconds);
    std::printf("warm-up          %.3f s wall, %.3f s cpu (seed 0, not counted)\n\n", warmUp.wallSeconds,
                warmUp.cpuSeconds);

    std::vector<std::string> headings;
    for (const Column& c : kColumns) headings.push_back(c.heading);
    printRow("run", headings);
    for (const Run& run : timed) {
        std::vector<std::string> cells;
        for (const Column& c : kColumns) cells.push_back(formatted(c.format, c.get(run)));
        printRow(std::to_string(run.seed), cells);
    }
    std::vector<Spread> spreads;
    for (const Column& c : kColumns) {
        std::vector<double> values;
        for (const Run& run : timed) values.push_back(c.get(run));
        spreads.push_back(spread(values));
    }
    auto spreadOf = [&](const std::string& key) {
        for (size_t i = 0; i < spreads.size(); ++i)
            if (key == kColumns[i].key) return spreads[i];
        throw Error("internal: no column " + key);
    };
    for (const char* row : {"median", "min", "max"}) {
        std::vector<std::string> cells;
        for (size_t i = 0; i < spreads.size(); ++i) {
            const Spread& s = spreads[i];
            double v = row == std::string("median") ? s.median : row == std::string("min") ? s.min : s.max;
            cells.push_back(formatted(kColumns[i].format, v));
        }
        printRow(row, cells);
    }
    Spread paths = spreadOf("paths_per_second");
    std::printf(
        "\nbench: %s %dx%d %d spp depth %d, LP_NUM_THREADS=%s: median %.4g paths/s (min %.4g, max %.4g), "
        "%.4g rays/s, %.4g paths/cpu-s, first frame %.3f s\n",
        integratorName(settings.integrator), settings.width, settings.height, spp, settings.maxDepth,
        threadsText.c_str(), paths.median, paths.min, paths.max, spreadOf("rays_per_second").median,
        spreadOf("paths_per_cpu_second").median, firstFrameSeconds);

    if (jsonPath) {
        nlohmann::json j;
        j["renderer"] = description;
        j["lp_num_threads"] = threads ? nlohmann::json(*threads) : nlohmann::json(nullptr);
        j["mesa_shader_cache_disable"] =
            cacheDisable ? nlohmann::json(*cacheDisable) : nlohmann::json(nullptr);
        j["shader_cache_disabled"] = mesaTrue(cacheDisable);
        j["scene"] = {{"source", scene.source}, {"triangles", stats.triangles}, {"emitters", stats.emitters}};
        j["bvh"] = {{"build_seconds", stats.bvhBuildSeconds},
                    {"sah_cost", stats.bvh.sahCost},
                    {"nodes", stats.bvh.nodeCount},
                    {"depth", stats.bvh.maxDepth}};
        j["settings"] = {{"width", settings.width},
                         {"height", settings.height},
                         {"spp", spp},
                         {"runs", runs},
                         {"max_depth", settings.maxDepth},
                         {"integrator", integratorName(settings.integrator)},
                         {"samples_per_pass", settings.samplesPerPass}};
        j["first_frame"] = {{"seconds", firstFrameSeconds},      {"context_seconds", contextSeconds},
                            {"load_seconds", loadSeconds},       {"bvh_and_upload_seconds", rendererSeconds},
                            {"compile_seconds", compileSeconds}, {"first_pass_seconds", firstPassSeconds}};
        j["warm_up"] = runJson(warmUp);
        j["runs"] = nlohmann::json::array();
        for (const Run& run : timed) j["runs"].push_back(runJson(run));
        for (size_t i = 0; i < spreads.size(); ++i)
            j["summary"][kColumns[i].key] = {
                {"median", spreads[i].median}, {"min", spreads[i].min}, {"max", spreads[i].max}};
        std::ofstream out(*jsonPath);
        out << j.dump(2) << "\n";
        if (!out) throw Error("--json " + *jsonPath + ": could not write: " + std::strerror(errno));
    }
    return 0;
}

}  // namespace fp
