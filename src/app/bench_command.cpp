// `fragpath bench`: speed figures that can be compared between machines, Mesa versions and commits.
// One untimed warm-up run absorbs shader compilation and llvmpipe's JIT, then R timed runs of the same
// settings report wall time, process CPU time and throughput as median, min and max (bench_measure.h).
// With --suite it does so for a fixed set of scenes (bench_suite.h).
#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/commands.h"
#include "bench/bench_measure.h"
#include "bench/bench_native.h"
#include "bench/bench_suite.h"
#include "bench/caustic_study.h"
#include "core/clock.h"
#include "core/error.h"
#include "core/text.h"
#include "gl/context.h"
#include "request/render_request.h"

namespace fp {

namespace {

const char* kBenchAbout =
    "usage: fragpath bench [SCENE] [options]\n"
    "       fragpath bench --suite [options]\n"
    "       fragpath bench --study caustic [--budget SECONDS] [--reference-spp N]\n"
    "\n"
    "Measures the offscreen renderer on SCENE (an .obj with its .mtl, a glTF .gltf or .glb, or a .json\n"
    "scene file; default: the built-in Cornell box): time to first frame, then one untimed warm-up run\n"
    "and R timed runs of the same settings (run i uses seed i). Prints per-run wall and process CPU\n"
    "seconds, paths/s and rays/s, per wall second and per CPU-second, with their median, min and max. No\n"
    "image is written.\n"
    "\n"
    "With --suite it measures a fixed set of scenes instead, each with an exact triangle count: the\n"
    "built-in Cornell box (32), a tessellated sphere in a lit room (sphere-1k, sphere-100k, sphere-1m:\n"
    "1000, 100000 and 1000000 triangles in all), and 100000 random overlapping triangles in the same room\n"
    "(soup-100k, the worst case for a BVH); sphere-1m-glb is sphere-1m written to a temporary .glb and\n"
    "loaded from it, as a user's file (its load stage is the glTF loader's). Each gets its BVH build time\n"
    "and SAH cost, GPU bytes per\n"
    "triangle, time to first frame and the throughput figures, then one summary table. --with-bunny adds\n"
    "the Stanford bunny, fetched at run time with `npm pack bunny` into a temporary directory (skipped\n"
    "with a note when npm or the network is missing).\n"
    "\n";

const char* kBenchNotes =
    "\n"
    "--study caustic compares bdpt with nee at equal process CPU time (--budget, default 40 s each) on a\n"
    "small light over a smooth, then a rough glass sphere over a diffuse floor (24x24, depth 5): RMSE\n"
    "against a bdpt reference of --reference-spp samples (default 16384) over the image and under the\n"
    "sphere, where the caustic falls (BENCHMARKS.md).\n"
    "\n"
    "The suite's defaults keep it to a few minutes on a 2-core software renderer; sphere-1m and\n"
    "soup-100k take most of it. For comparable figures on Mesa's llvmpipe, set LP_NUM_THREADS explicitly\n"
    "(it defaults to the number of CPUs). Mesa caches compiled shaders on disk, so the first bench after a\n"
    "shader change has a longer time to first frame; MESA_SHADER_CACHE_DISABLE=true measures the cold\n"
    "case every time.\n";

// A benchmark run is not one final image: its spp is a measuring choice (the scene file's is ignored),
// and the suite renders every scene at one size.
constexpr unsigned kBenchOptions = kSizeOption | kSppOption | kIntegratorOption | kPathOptions |
                                   kSamplingOptions | kCameraOptions | kShaderOptions | kSceneOptions;
FrontEndDefaults benchDefaults(bool suite, bool native = false) {
    FrontEndDefaults d = FrontEndDefaults::ownImage(glm::ivec2(suite ? 256 : 512), suite ? 2 : 8);
    // The native reference has constant skies only: with --native an unlit scene gets the uniform sky.
    if (native) d.defaultLight = DefaultLight::UniformSky;
    if (!suite) d.ignoresSceneFile &= ~kSizeOption;
    d.own.set("samples_per_pass", 8);  // the timed runs' (about 5 % less CPU per path than 1)
    return d;
}

std::vector<OptionGroup> benchOptions() {
    return commandOptions(
        {{"Benchmark",
          {{"--runs", "", "R", "timed runs after the warm-up (default 5; 3 with --suite)"},
           {"--json", "", "FILE",
            "also write every figure to FILE as JSON (with --suite: one object per scene)"},
           {"--suite", "", "",
            "measure the benchmark suite instead of one scene\n(defaults: 256x256 with --suite, 2 spp, 3 "
            "runs; a scene file's size does not apply)"},
           {"--max-triangles", "", "N", "with --suite: skip the scenes with more than N triangles"},
           {"--scenes", "", "A,B,...",
            "with --suite: only these scenes (cornell, sphere-1k, bunny, sphere-100k,\nsoup-100k, "
            "sphere-1m, sphere-1m-glb), in the suite's order"},
           {"--with-bunny", "", "", "with --suite: add the Stanford bunny (needs npm and the network)"},
           {"--native", "", "",
            "also measure the native reference (fragpath_native: one thread of scalar C++,\nthe same "
            "algorithm "
            "on the same BVH) on each scene, 1 spp per run, and print\nGPU paths per CPU-second over the "
            "native's. Only with --integrator nee, and\nonly on scenes of Lambertian materials without "
            "textures "
            "or an environment\nmap: anything else is an error, not a comparison of two algorithms"},
           {"--study", "", "caustic", "compare bdpt with nee at equal CPU time (see below)"},
           {"--budget", "", "SECONDS", "with --study: CPU seconds for each integrator (default 40)"},
           {"--reference-spp", "", "N", "with --study: samples of the bdpt reference (default 16384)"}}}},
        kBenchOptions, benchDefaults(false));
}

int benchOneScene(const Args& args, const bench::BenchSettings& settings, std::optional<std::string> jsonPath,
                  SteadyClock::time_point start) {
    using namespace bench;
    BenchEnvironment environment = readBenchEnvironment();
    auto stage = SteadyClock::now();
    std::unique_ptr<GlContext> context = createOsMesaContext();
    double contextSeconds = secondsSince(stage);
    environment.renderer = context->description();
    bool withNative = args.has("--native");
    auto load = [&] {
        Scene scene = settings.request->loadScene();
        // Checked as soon as the scene is read (a loop over its materials, nothing timed notices), so
        // that a scene the reference cannot render stops the command before any measuring.
        if (withNative) refuseWhatNativeLacks(scene, settings);
        return scene;
    };
    SceneMeasurement m = measureScene(load, settings);
    std::optional<NativeMeasurement> native;
    if (withNative) native = measureNative(load, settings);
    // Here the first frame counts from the start of the command, so it includes the context.
    double firstFrameSeconds = secondsBetween(start, m.firstPassEnd);

    bench::BenchSettings resolved = settings;  // as rendered: with the scene file's defaults
    resolved.render = m.render;
    printHeader(environment, resolved);
    printMeasurement(m, firstFrameSeconds, contextSeconds);
    const RenderSettings& r = m.render;
    Spread paths = m.summary("paths_per_second");
    std::printf(
        "\nbench: %s %dx%d %d spp depth %d, LP_NUM_THREADS=%s: median %.4g paths/s (min %.4g, max %.4g), "
        "%.4g rays/s, %.4g paths/cpu-s, first frame %.3f s\n",
        integratorName(r.integrator), r.width, r.height, settings.spp, r.maxDepth,
        environment.threadsText().c_str(), paths.median, paths.min, paths.max,
        m.summary("rays_per_second").median, m.summary("paths_per_cpu_second").median, firstFrameSeconds);
    if (native) printNative(*native, m);

    if (jsonPath) {
        nlohmann::json j = environmentJson(environment);
        j["settings"] = benchSettingsJson(resolved);
        j.update(measurementJson(m, firstFrameSeconds));
        j["first_frame"]["context_seconds"] = contextSeconds;
        if (native) j["native"] = nativeJson(*native, m);
        writeJson(*jsonPath, j);
    }
    return 0;
}

}  // namespace

int benchCommand(const std::vector<std::string>& argv) {
    // Time to first frame counts from here: argument parsing is negligible, and everything a user waits
    // for before the first pixel (context, load, BVH, upload, compile, JIT, first pass) comes after.
    auto start = SteadyClock::now();
    Args args(argv, benchOptions());
    if (args.wantsHelp()) {
        std::fputs(kBenchAbout, stdout);
        std::fputs(formatOptions(benchOptions()).c_str(), stdout);
        std::fputs(kBenchNotes, stdout);
        return 0;
    }
    if (auto study = args.text("--study")) {
        if (*study != "caustic") throw Error("--study: the only study is 'caustic', not '" + *study + "'");
        bench::CausticStudyOptions options;
        if (auto budget = args.integer("--budget", 1, 100000)) options.budgetSeconds = *budget;
        if (auto spp = args.integer("--reference-spp", 16, 1 << 24)) options.referenceSpp = *spp;
        return bench::runCausticStudy(options);
    }
    for (const char* flag : {"--budget", "--reference-spp"})
        if (args.has(flag)) throw Error(std::string(flag) + " only goes with --study");
    bool suite = args.has("--suite");
    if (!suite)
        for (const char* flag : {"--max-triangles", "--scenes", "--with-bunny"})
            if (args.has(flag)) throw Error(std::string(flag) + " only goes with --suite");
    if (suite && !args.positional().empty()) throw Error("bench --suite takes no scene file");
    if (suite && args.has("--environment"))
        throw Error("--environment goes with a scene file, not --suite (the suite's scenes are lit)");
    const RenderRequest request(args, benchDefaults(suite, args.has("--native")));

    bench::BenchSettings settings;
    settings.request = request;
    settings.render = request.settings(Scene());  // the flags over the defaults; each scene adds its file's
    settings.spp = request.spp(Scene());
    settings.runs = args.integer("--runs", 1, 1000).value_or(suite ? 3 : 5);
    // The native reference draws independent numbers (src/native): with --native the shader does too,
    // unless the user asked for another sampler, which would compare two algorithms.
    if (args.has("--native")) {
        if (settings.render.lightSampling != LightSampling::Auto)
            throw Error("--native: the native reference makes the automatic light-sampling choice only");
        // It chooses emitters by power: so does the shader, unless asked for the tree (refused below).
        if (settings.render.lightSelection == LightSelection::Auto)
            settings.render.lightSelection = LightSelection::Power;
        settings.independentSampler = !args.has("--sampler");
        if (settings.independentSampler) settings.render.sampler = Sampler::Independent;
        if (settings.render.sampler != Sampler::Independent)
            throw Error(std::string("--native: the native reference implements only the independent sampler, "
                                    "not ") +
                        samplerName(settings.render.sampler) + "; a ratio would compare two algorithms");
        if (settings.render.integrator != Integrator::Nee)
            throw Error(
                std::string("--native: the native reference implements only the nee integrator, not ") +
                integratorName(settings.render.integrator) + "; a ratio would compare two algorithms");
    }
    settings.bvh = layout::bvhOptions(request.bvhThreads());
    settings.shaderDir = request.shaderDir();
    std::optional<std::string> jsonPath = args.text("--json");
    if (jsonPath) bench::checkJsonPath(*jsonPath);
    if (!suite) return benchOneScene(args, settings, jsonPath, start);

    bench::SuiteOptions options;
    options.settings = settings;
    options.jsonPath = jsonPath;
    options.withBunny = args.has("--with-bunny");
    options.native = args.has("--native");
    if (auto n = args.integer("--max-triangles", 1, 2000000000)) options.maxTriangles = *n;
    if (auto names = args.text("--scenes")) {
        const std::vector<std::string>& known = bench::suiteSceneNames();
        for (const std::string& name : splitNameList(*names, "--scenes")) {
            if (std::find(known.begin(), known.end(), name) == known.end()) {
                std::string list;
                for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
                throw Error("--scenes: no suite scene '" + name + "' (there are " + list + ")");
            }
            options.scenes.push_back(name);
        }
    }
    return bench::runSuite(options);
}

}  // namespace fp
