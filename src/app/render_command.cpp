// `fragpath render`: the offscreen batch renderer (OSMesa, no display, no GPU needed).

#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "app/commands.h"
#include "app/progress.h"
#include "app/render_stats.h"
#include "core/clock.h"
#include "core/error.h"
#include "core/file.h"
#include "core/log.h"
#include "denoise/denoiser.h"
#include "gl/context.h"
#include "image/file_io.h"
#include "render/partial_render.h"
#include "render/renderer.h"
#include "request/render_request.h"

namespace fp {

namespace {

constexpr unsigned kRenderOptions = kAllRequestOptions;

std::vector<OptionGroup> renderOptions() {
    return commandOptions(
        {{"Output",
          {{"--output", "-o", "FILE",
            "the image (default render.png): .png (sRGB, tone-mapped), .exr or .pfm (linear radiance); "
            "always the raw samples"},
           {"--denoise", "", "NAME",
            "none | bilateral (joint bilateral filter) | atrous (edge-avoiding a-trous wavelets, "
            "variance-guided); needs --denoised-out"},
           {"--denoised-out", "", "FILE",
            "where the denoised image goes (.png, .exr or .pfm); needs --denoise"},
           {"--sample-offset", "", "K",
            "render sample indices K, K+1, ... (one part of a render spread over machines; combine the "
            "parts' .exr files with `fragpath merge`)"},
           {"--time-budget", "", "T",
            "stop after the pass that uses up T (e.g. 90s, 5m, 1.5h); --spp is then a cap"},
           {"--resume", "", "FILE.exr",
            "continue a render saved as .exr (same scene and settings) up to --spp"},
           {"--aovs", "", "LIST",
            ".exr only: add first-hit layers, averaged over the samples, next to the beauty's R, G, B: "
            "albedo (albedo.R/G/B), normal (normal.X/Y/Z: world space, facing the camera), depth (depth.Z: "
            "distance along the camera ray, 0 for no hit); e.g. --aovs albedo,normal,depth"},
           {"--stats", "", "", "print scene, BVH, memory and timing statistics"},
           {"--json", "", "FILE", "write those statistics to FILE as JSON (with or without --stats)"},
           {"--quiet", "", "", "no progress bar or summary line"}}}},
        kRenderOptions);
}

void printRenderUsage() {
    std::fputs(
        "usage: fragpath render [SCENE] [options]\n"
        "\n"
        "Renders SCENE (an .obj with its .mtl, a glTF .gltf or .glb, or a .json scene file; default: the\n"
        "built-in Cornell box) offscreen and writes an image whose format follows the extension of -o.\n",
        stdout);
    std::fputs(formatOptions(renderOptions()).c_str(), stdout);
    std::fputs(
        "\n"
        "Ctrl-C (SIGINT) or SIGTERM stops early and still writes the samples done so far. An .exr output\n"
        "records in its header which samples it holds and a fingerprint of the scene and settings.\n",
        stdout);
}

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

}  // namespace

int renderCommand(const std::vector<std::string>& argv) {
    Args args(argv, renderOptions());
    if (args.wantsHelp()) {
        printRenderUsage();
        return 0;
    }
    const RenderRequest request(args);
    std::string output = args.text("--output").value_or("render.png");
    checkImageOutput(output, "output");
    std::vector<Aov> aovs = parseAovOption(args.text("--aovs"), output);
    std::optional<std::string> statsJson = args.text("--json");
    if (statsJson) checkWritablePath(*statsJson, "--json");
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
        checkImageOutput(*denoisedOutput, "--denoised-out");
        if (std::filesystem::absolute(*denoisedOutput).lexically_normal() ==
            std::filesystem::absolute(output).lexically_normal())
            throw Error("--denoised-out and -o name the same file, " + output);
    }
    const DisplaySettings display = request.display();
    bool quiet = args.has("--quiet"), showStats = args.has("--stats");
    std::optional<double> budget;
    if (auto t = args.text("--time-budget")) budget = parseDuration("--time-budget", *t);
    const uint32_t sampleOffset = uint32_t(args.integer("--sample-offset", 0, 1 << 30).value_or(0));

    // From here on an interrupt stops the render after the current pass, and the image is still written.
    std::signal(SIGINT, onInterrupt);
    std::signal(SIGTERM, onInterrupt);
    auto start = SteadyClock::now();
    const double startCpu = processCpuSeconds();
    FirstFrameStages stages;
    Scene scene = request.loadScene();
    RenderSettings settings = request.settings(scene);
    settings.sampleOffset = sampleOffset;
    settings.guides = denoiser != Denoiser::None || !aovs.empty();
    // With only a time budget, the budget decides when to stop; with --spp unlimited, an interrupt.
    int spp = (budget && !args.has("--spp")) || request.spp(scene) == 0 ? 1 << 24 : request.spp(scene);
    Camera camera = request.camera(scene);
    std::optional<PartialRender> resumed;
    if (auto r = args.text("--resume")) resumed = readPartial(*r);
    stages.loadSeconds = secondsSince(start);

    auto stage = SteadyClock::now();
    std::unique_ptr<GlContext> context = createOffscreenContext(request.backend());
    stages.contextSeconds = secondsSince(stage);
    if (!quiet) std::fprintf(stderr, "renderer: %s\n", context->description().c_str());
    stage = SteadyClock::now();
    // The settings never change here: the caustic casters are found only if they can be used.
    Renderer renderer(scene, ShaderLibrary(request.shaderDir()), layout::bvhOptions(request.bvhThreads()),
                      SceneReads::Auto,
                      usesCausticCasters(settings) ? CasterSearch::Run : CasterSearch::Skip);
    stages.bvhSeconds = renderer.stats().bvhBuildSeconds;
    stages.packAndUploadSeconds = secondsSince(stage) - stages.bvhSeconds;
    stage = SteadyClock::now();
    renderer.configure(settings, camera);
    stages.compileSeconds = secondsSince(stage);
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
    auto traceStart = SteadyClock::now();
    double cpuStart = processCpuSeconds();
    double firstFrameSeconds = 0.0;
    renderer.render(std::max(spp - already, 0), [&](int done) {
        auto now = SteadyClock::now();
        if (firstFrameSeconds == 0.0) {
            firstFrameSeconds = secondsBetween(start, now);
            stages.firstPassSeconds = secondsBetween(traceStart, now);
            stages.cpuSeconds = processCpuSeconds() - startCpu;
        }
        if (!quiet) progress.update(done);
        bool overBudget = budget && secondsBetween(traceStart, now) >= *budget;
        return !interrupted.load() && !overBudget;
    });
    double seconds = secondsSince(traceStart);
    double cpuSeconds = processCpuSeconds() - cpuStart;
    progress.finish();

    Accumulation acc = renderer.readback();
    const int total = renderer.samples();
    writeRenderOutput(
        output,
        {acc.mean(), {{settings.sampleOffset, uint64_t(total)}}, fingerprint, outputAovs(acc, aovs, resumed)},
        display, settings.view);
    if (denoisedOutput) writeImage(*denoisedOutput, denoise(renderer, denoiser), display);
    // After writing: under --strict the warning fails the command, but the samples are kept.
    if (uint64_t pixels = acc.pixelsShortOf(total))
        warn(std::to_string(pixels) + " pixels hold fewer than " + std::to_string(total) +
             " samples: the OpenGL driver cut the shader's loops short (llvmpipe stops them after a fixed "
             "number of iterations); the image is noisier there, and a path cut short may be darker. "
             "Render again with --samples-per-pass 1");

    int done = total - already;
    double paths = double(settings.width) * settings.height * done;
    if (!quiet)
        std::fprintf(stderr, "%s: %d spp at %dx%d, %s, depth %d: %.2f s, %.3g paths/s, %.3g rays/s\n",
                     output.c_str(), done, settings.width, settings.height,
                     integratorName(settings.integrator), settings.maxDepth, seconds, paths / seconds,
                     acc.raysTraced() / seconds);
    if (showStats || statsJson) {
        RenderStats stats = collectRenderStats(renderer, acc, context->description(), scene.source, output,
                                               {done, firstFrameSeconds, seconds, cpuSeconds, stages});
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
