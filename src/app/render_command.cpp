// `fragpath render`: the offscreen batch renderer (OSMesa, no display, no GPU needed).
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>

#include "app/args.h"
#include "app/commands.h"
#include "app/progress.h"
#include "app/render_stats.h"
#include "core/error.h"
#include "denoise/denoiser.h"
#include "gl/context.h"
#include "image/file_io.h"
#include "image/tone_map.h"
#include "render/partial_render.h"
#include "render/renderer.h"
#include "scene/builtin_scene.h"
#include "scene/load.h"

namespace fp {

namespace {

const char* kRenderUsage =
    "usage: fragpath render [SCENE] [options]\n"
    "\n"
    "Renders SCENE (an .obj with its .mtl, or a .json scene file; default: the built-in Cornell box)\n"
    "offscreen and writes an image whose format follows the extension of -o: .png (sRGB, tone-mapped),\n"
    ".exr or .pfm (linear radiance).\n"
    "\n"
    "options:\n"
    "  -o, --output FILE     output image (default: render.png); always the raw samples\n"
    "  --denoise NAME        none | bilateral (joint bilateral filter) | atrous (edge-avoiding a-trous\n"
    "                        wavelets, variance-guided); needs --denoised-out\n"
    "  --denoised-out FILE   where the denoised image goes (.png, .exr or .pfm); needs --denoise\n"
    "  --size WxH            image size (default: the scene file's, else 512x512)\n"
    "  --spp N               samples per pixel (default: the scene file's, else 64)\n"
    "  --max-depth D         bounces: 0 shows emitters only, 1 direct light, ... (default 5)\n"
    "  --seed S              random seed; the same seed gives the same image bit for bit (default 0)\n"
    "  --integrator NAME     naive | bsdf | nee | bdpt (default nee: light sampling with MIS; bdpt:\n"
    "                        bidirectional path tracing with MIS)\n"
    "  --clamp-indirect X    scale each sample's indirect light (two bounces or more) down to at most X\n"
    "                        per channel: fewer fireflies, but BIASED (darker); nee, bsdf, naive; off\n"
    "  --sampler NAME        sobol (default: Owen-scrambled Sobol points, stratified in every pixel) |\n"
    "                        independent (independent uniform numbers, the textbook's Monte Carlo)\n"
    "  --light-sampling NAME auto (default: solid-angle when an emitter faces a close surface) | area |\n"
    "                        solid-angle (nee: emitters subtending over 0.1 sr sampled by solid angle)\n"
    "  --eye X,Y,Z --target X,Y,Z --up X,Y,Z --fov DEG\n"
    "                        camera (default: the scene file's, else one that frames the scene)\n"
    "  --view NAME           radiance (default) | depth | normal | albedo: what the primary ray through\n"
    "                        each pixel centre hits | bounces | nodes | triangles: bounces survived,\n"
    "                        BVH nodes visited and triangles tested (per primary ray), averaged |\n"
    "                        cost: per path, nodes visited, triangles tested, surfaces shaded in R, G, B\n"
    "  --exposure STOPS      PNG only: scale by 2^STOPS before tone mapping (default 0)\n"
    "  --tonemap NAME        PNG only: clamp | reinhard | aces (default clamp)\n"
    "  --samples-per-pass N  samples each pixel takes per draw call, 1 to 16 (default 1)\n"
    "  --shader-dir DIR      read shaders from DIR instead of the ones built in\n"
    "  --sample-offset K     render sample indices K, K+1, ... (one part of a render spread over machines;\n"
    "                        combine the parts' .exr files with `fragpath merge`)\n"
    "  --time-budget T       stop after the pass that uses up T (e.g. 90s, 5m, 1.5h); --spp is then a cap\n"
    "  --resume FILE.exr     continue a render saved as .exr (same scene and settings) up to --spp samples\n"
    "  --backend NAME        auto (default: a GPU through EGL if there is one, else OSMesa) | egl | osmesa\n"
    "  --bvh-threads N       threads that build the BVH (default: every CPU); the tree is the same\n"
    "  --aovs LIST           .exr output only: add first-hit layers, averaged over the samples, next to\n"
    "                        the beauty's R, G, B: albedo (albedo.R/G/B), normal (normal.X/Y/Z: world\n"
    "                        space, facing the camera) and depth (depth.Z: distance along the camera ray,\n"
    "                        0 for no hit), e.g. --aovs albedo,normal,depth (src/render/aovs.h)\n"
    "  --stats               print scene, BVH, memory and timing statistics\n"
    "  --json FILE           write those statistics to FILE as JSON (with or without --stats)\n"
    "  --quiet               no progress bar or summary line\n"
    "  -h, --help            this text\n"
    "\n"
    "Ctrl-C (SIGINT) or SIGTERM stops early and still writes the samples done so far. An .exr output\n"
    "records in its header which samples it holds and a fingerprint of the scene and settings.\n";

std::atomic<bool> interrupted{false};

extern "C" void onInterrupt(int) {
    interrupted = true;
}

// "90", "90s", "5m", "1.5h" -> seconds.
double parseDuration(const std::string& flag, const std::string& text) {
    char* end = nullptr;
    double value = std::strtod(text.c_str(), &end);
    std::string unit(end);
    double scale = unit.empty() || unit == "s" ? 1.0 : unit == "m" ? 60.0 : unit == "h" ? 3600.0 : -1.0;
    if (end == text.c_str() || scale < 0.0 || !(value > 0.0) || !std::isfinite(value))
        throw Error("option " + flag + ": expected a duration such as 90s, 5m or 1.5h, got '" + text + "'");
    return value * scale;
}

double processCpuSeconds() {
    return double(std::clock()) / CLOCKS_PER_SEC;
}

// Fails before a long render, not after it, when the output cannot be written.
void checkOutputPath(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (ext != ".png" && ext != ".exr" && ext != ".pfm")
        throw Error("output " + path + ": unknown image format '" + ext + "' (use .png, .exr or .pfm)");
    std::filesystem::path dir = std::filesystem::path(path).parent_path();
    if (dir.empty()) dir = ".";
    if (!std::filesystem::is_directory(dir))
        throw Error("output " + path + ": directory " + dir.string() + " does not exist");
    if (access(dir.c_str(), W_OK) != 0)
        throw Error("output " + path + ": directory " + dir.string() + " is not writable");
    if (std::filesystem::is_directory(path)) throw Error("output " + path + " is a directory");
}

}  // namespace

int renderCommand(const std::vector<std::string>& argv) {
    Args args(argv,
              {"-o",
               "--output",
               "--size",
               "--spp",
               "--max-depth",
               "--seed",
               "--integrator",
               "--sampler",
               "--light-sampling",
               "--clamp-indirect",
               "--eye",
               "--target",
               "--up",
               "--fov",
               "--view",
               "--exposure",
               "--tonemap",
               "--samples-per-pass",
               "--shader-dir",
               "--backend",
               "--sample-offset",
               "--time-budget",
               "--resume",
               "--denoise",
               "--denoised-out",
               "--bvh-threads",
               "--aovs",
               "--json"},
              {"--stats", "--quiet", "-h", "--help"});
    if (args.has("-h") || args.has("--help")) {
        std::fputs(kRenderUsage, stdout);
        return 0;
    }
    if (args.positional().size() > 1)
        throw Error("render takes one scene file, got " + std::to_string(args.positional().size()));
    std::string output = args.text("-o").value_or(args.text("--output").value_or("render.png"));
    checkOutputPath(output);
    std::vector<Aov> aovs = parseAovOption(args.text("--aovs"), output);
    std::optional<std::string> statsJson = args.text("--json");
    if (statsJson) checkStatsJsonPath(*statsJson);
    // -o always holds the raw samples (resumable, mergeable); a denoised image needs a name of its own,
    // so that no file silently holds something other than what its flag says.
    Denoiser denoiser = parseDenoiser(args.text("--denoise").value_or("none"));
    std::optional<std::string> denoisedOutput = args.text("--denoised-out");
    if (args.has("--denoise") && denoiser != Denoiser::None && !denoisedOutput)
        throw Error("--denoise " + std::string(denoiserName(denoiser)) +
                    " needs --denoised-out FILE for the denoised image (-o keeps the raw samples)");
    if (denoisedOutput && !args.has("--denoise"))
        throw Error("--denoised-out needs --denoise NAME (none, bilateral or atrous)");
    if (denoisedOutput) {
        checkOutputPath(*denoisedOutput);
        if (std::filesystem::absolute(*denoisedOutput).lexically_normal() ==
            std::filesystem::absolute(output).lexically_normal())
            throw Error("--denoised-out and -o name the same file, " + output);
    }
    DisplaySettings display;
    display.exposure = args.number("--exposure").value_or(0.0f);
    if (auto t = args.text("--tonemap")) display.toneMap = parseToneMap(*t);
    bool quiet = args.has("--quiet"), showStats = args.has("--stats");

    // From here on an interrupt stops the render after the current pass, and the image is still written.
    std::signal(SIGINT, onInterrupt);
    std::signal(SIGTERM, onInterrupt);
    auto start = std::chrono::steady_clock::now();
    Scene scene = args.positional().empty() ? builtinCornellBox() : loadScene(args.positional()[0]);

    RenderSettings settings;
    const RenderDefaults& d = scene.defaults;
    settings.width = d.width.value_or(512);
    settings.height = d.height.value_or(512);
    if (auto s = args.size("--size")) settings.width = s->x, settings.height = s->y;
    std::optional<double> budget;
    if (auto t = args.text("--time-budget")) budget = parseDuration("--time-budget", *t);
    // With only a time budget, the budget decides when to stop.
    int spp = args.integer("--spp", 1, 1 << 24).value_or(budget ? 1 << 24 : d.spp.value_or(64));
    settings.maxDepth = args.integer("--max-depth", 0, 1000).value_or(d.maxDepth.value_or(5));
    settings.seed = uint32_t(args.integer("--seed", 0, 2147483647).value_or(int(d.seed.value_or(0))));
    settings.integrator = parseIntegrator(args.text("--integrator").value_or(d.integrator.value_or("nee")));
    // Flags, else the scene file, else RenderSettings' defaults (written once, in render/settings.h).
    settings.sampler =
        parseSampler(args.text("--sampler").value_or(d.sampler.value_or(samplerName(settings.sampler))));
    if (auto l = args.text("--light-sampling")) settings.lightSampling = parseLightSampling(*l);
    settings.clampIndirect =
        args.number("--clamp-indirect").value_or(d.clampIndirect.value_or(settings.clampIndirect));
    if (auto v = args.text("--view")) settings.view = parseView(*v);
    settings.samplesPerPass =
        args.integer("--samples-per-pass", 1, RenderSettings::kMaxSamplesPerPass).value_or(1);
    settings.sampleOffset = uint32_t(args.integer("--sample-offset", 0, 1 << 30).value_or(0));
    settings.guides = denoiser != Denoiser::None || !aovs.empty();
    std::optional<PartialRender> resumed;
    if (auto r = args.text("--resume")) resumed = readPartial(*r);

    Camera camera = scene.camera.value_or(frameBounds(scene.bounds()));
    if (auto v = args.vec3("--eye")) camera.eye = *v;
    if (auto v = args.vec3("--target")) camera.target = *v;
    if (auto v = args.vec3("--up")) camera.up = *v;
    if (auto v = args.number("--fov")) camera.fovY = *v;
    validateCamera(camera, "camera");  // flags can break a valid scene camera

    std::unique_ptr<GlContext> context = createOffscreenContext(args.text("--backend").value_or("auto"));
    if (!quiet) std::fprintf(stderr, "renderer: %s\n", context->description().c_str());
    BvhBuildOptions bvhOptions = layout::bvhOptions();
    bvhOptions.threadCount = args.integer("--bvh-threads", 1, 1024).value_or(0);
    Renderer renderer(scene, ShaderLibrary(args.text("--shader-dir").value_or("")), bvhOptions);
    renderer.configure(settings, camera);
    const std::string fingerprint = renderFingerprint(scene, settings, camera);
    int already = 0;
    if (resumed) {
        const std::string from = *args.text("--resume");
        if (resumed->fingerprint != fingerprint)
            throw Error(from + " was rendered from a different scene or settings (fingerprint " +
                        resumed->fingerprint + ", this render " + fingerprint + ")");
        if (resumed->ranges.size() != 1 || resumed->ranges[0].first != settings.sampleOffset)
            throw Error(from + " does not hold one range of samples starting at --sample-offset " +
                        std::to_string(settings.sampleOffset));
        already = int(resumed->samples());
        renderer.restore(resumed->mean, already);
        if (!quiet) std::fprintf(stderr, "resuming %s: %d samples done\n", from.c_str(), already);
        if (denoisedOutput && denoiser != Denoiser::None && !quiet)
            std::fprintf(
                stderr,
                "note: %s holds no guides or sums of squares: the denoiser's guides and noise estimate "
                "come from the samples rendered now only\n",
                from.c_str());
    }

    Progress progress(spp - already);
    auto traceStart = std::chrono::steady_clock::now();
    double cpuStart = processCpuSeconds();
    double firstFrameSeconds = 0.0;
    renderer.render(std::max(spp - already, 0), [&](int done) {
        auto now = std::chrono::steady_clock::now();
        if (firstFrameSeconds == 0.0) firstFrameSeconds = std::chrono::duration<double>(now - start).count();
        if (!quiet) progress.update(done);
        bool overBudget = budget && std::chrono::duration<double>(now - traceStart).count() >= *budget;
        return !interrupted.load() && !overBudget;
    });
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - traceStart).count();
    double cpuSeconds = processCpuSeconds() - cpuStart;
    progress.finish();

    Accumulation acc = renderer.readback();
    const int total = renderer.samples();
    writeRenderOutput(
        output,
        {acc.mean(), {{settings.sampleOffset, uint64_t(total)}}, fingerprint, outputAovs(acc, aovs, resumed)},
        display, settings.view);
    if (denoisedOutput) writeImage(*denoisedOutput, denoise(renderer, denoiser), display);

    int done = total - already;
    double paths = double(settings.width) * settings.height * done;
    if (!quiet)
        std::fprintf(stderr, "%s: %d spp at %dx%d, %s, depth %d: %.2f s, %.3g paths/s, %.3g rays/s\n",
                     output.c_str(), done, settings.width, settings.height,
                     integratorName(settings.integrator), settings.maxDepth, seconds, paths / seconds,
                     acc.raysTraced() / seconds);
    if (showStats || statsJson) {
        RenderStats stats = collectRenderStats(renderer, acc, context->description(), scene.source, output,
                                               {done, firstFrameSeconds, seconds, cpuSeconds});
        if (showStats) std::fputs(formatRenderStats(stats).c_str(), stdout);
        if (statsJson) writeRenderStatsJson(*statsJson, stats);
    }
    if (interrupted.load()) {
        std::fprintf(stderr, "fragpath: interrupted after %d of %d spp; %s holds those samples\n", total, spp,
                     output.c_str());
        return 130;
    }
    return 0;
}

}  // namespace fp
