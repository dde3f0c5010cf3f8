// `fragpath study`: how much noise is too much. Measures error against a converged reference for each
// integrator, denoiser and sample count, then writes a CSV, plots, an image strip and a report with the
// real-time feasibility estimate (the logic lives in src/study/).
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include "app/commands.h"
#include "core/error.h"
#include "core/text.h"
#include "gl/context.h"
#include "image/file_io.h"
#include "image/image_stats.h"
#include "realtime/practice_run.h"
#include "render/renderer.h"
#include "request/render_request.h"
#include "study/cpu_peak.h"
#include "study/denoisers.h"
#include "study/image_strip.h"
#include "study/metrics.h"
#include "study/path_cost.h"
#include "study/plots.h"
#include "study/report.h"
#include "study/roofline_plot.h"
#include "study/study_csv.h"
#include "study/sweep.h"

namespace fp {

namespace {

// Not the scene file's size: that is meant for one final render, the study renders hundreds.
constexpr unsigned kStudyOptions = kSizeOption | kPathOptions | kSamplingOptions | kCameraOptions |
                                   kShaderOptions | kBackendOption | kSceneOptions;
const FrontEndDefaults kStudyDefaults = FrontEndDefaults::ownImage({128, 128}, 0);

std::vector<OptionGroup> studyOptions() {
    return commandOptions(
        {{"Study",
          {{"--out", "", "DIR", "output directory, created if missing (default: study)"},
           {"--max-spp", "", "N", "the largest sample count (default 64)"},
           {"--integrators", "", "LIST", "comma-separated (default naive,bsdf,nee,bdpt)"},
           {"--denoisers", "", "LIST",
            "comma-separated, of those built in (default: all; 'none' is the raw image)"},
           {"--reference-spp", "", "N", "samples of the rendered reference (default 4096)"},
           {"--reference-integrator", "", "NAME", "integrator of the rendered reference (default nee)"},
           {"--reference", "", "FILE.exr", "load the reference instead of rendering it (same size, linear)"},
           {"--threshold", "", "X",
            "relative MSE under which an image counts as not noisy (default 4e-4:\n2% RMS relative error, "
            "the Weber fraction; report.md gives the sources)"},
           {"--runs", "", "R", "timed runs of each sweep; times are medians (default 1)"},
           {"--count-spp", "", "N", "samples per pixel of the counting render (default 4)"},
           {"--practice-frames", "", "N",
            "frames of each real-time run that the report's Practice section measures: the real-time "
            "pipeline against brute force, on a still and an orbiting camera (default 20; 0 skips it)"},
           {"--practice-reference-spp", "", "K", "samples of each practice frame's reference (default 128)"},
           {"--no-plots", "", "", "skip gnuplot (the CSV, strip and report are still written)"},
           {"--quiet", "", "", "no progress lines"}}}},
        kStudyOptions, kStudyDefaults);
}

void printStudyUsage() {
    std::fputs(
        "usage: fragpath study [SCENE] [options]\n"
        "\n"
        "How much noise is too much? Renders (or loads) a converged reference of SCENE (default: the "
        "built-in\n"
        "Cornell box), then for 1, 2, 4, ... samples per pixel, each integrator and each denoiser measures "
        "the\n"
        "render time and the error (RMSE, relative MSE, SSIM). Counts BVH nodes, triangle tests and surface\n"
        "interactions per path for a FLOP estimate, and writes to the output directory:\n"
        "  study.csv        one row per integrator x denoiser x spp (columns: README.md, \"Study\")\n"
        "  plots.gp + *.png error against samples and against time, log-log (needs gnuplot)\n"
        "  strip.png        the same crop at 1, 4, 16, 64 spp and the reference, a row per "
        "integrator+denoiser\n"
        "  report.md        the noise threshold, the spp each needs, and the real-time feasibility estimate\n"
        "  reference.exr    the reference it rendered (reuse it with --reference)\n"
        "The sweep uses --seed S; the rendered reference S + 1.\n",
        stdout);
    std::fputs(formatOptions(studyOptions()).c_str(), stdout);
}

// Creates DIR if needed; fails before any rendering if it cannot be written.
void prepareOutputDirectory(const std::string& dir) {
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error || !std::filesystem::is_directory(dir))
        throw Error("output directory " + dir + " cannot be created" + (error ? ": " + error.message() : ""));
    if (access(dir.c_str(), W_OK) != 0) throw Error("output directory " + dir + " is not writable");
}

std::string readLoadAverage() {
    std::ifstream in("/proc/loadavg");
    double load = 0.0;
    if (!(in >> load)) return "";
    char text[160];
    std::snprintf(text, sizeof text, "The 1-minute load average was %.2f on %u CPUs when the study started.",
                  load, std::max(1u, unsigned(sysconf(_SC_NPROCESSORS_ONLN))));
    return text;
}

}  // namespace

int studyCommand(const std::vector<std::string>& argv) {
    Args args(argv, studyOptions());
    if (args.wantsHelp()) {
        printStudyUsage();
        return 0;
    }
    const RenderRequest request(args, kStudyDefaults);
    const bool quiet = args.has("--quiet"), plots = !args.has("--no-plots");
    auto say = [&](const std::string& line) {
        if (!quiet) std::fprintf(stderr, "study: %s\n", line.c_str());
    };

    // Everything that can be wrong with the request fails here, before minutes of rendering.
    std::vector<Integrator> integrators;
    for (const std::string& name :
         splitNameList(args.text("--integrators").value_or("naive,bsdf,nee,bdpt"), "--integrators"))
        integrators.push_back(parseIntegrator(name));
    std::vector<std::string> known;
    for (const study::StudyDenoiser& d : study::availableDenoisers()) known.push_back(d.name);
    std::string allDenoisers;
    for (const std::string& name : known) allDenoisers += (allDenoisers.empty() ? "" : ",") + name;
    std::vector<study::StudyDenoiser> denoisers =
        study::selectDenoisers(args.text("--denoisers").value_or(allDenoisers));
    const Integrator referenceIntegrator =
        parseIntegrator(args.text("--reference-integrator").value_or("nee"));
    const int maxSpp = args.integer("--max-spp", 1, 1 << 16).value_or(64);
    const int referenceSpp = args.integer("--reference-spp", 1, 1 << 24).value_or(4096);
    const int runs = args.integer("--runs", 1, 100).value_or(1);
    const int countSpp = args.integer("--count-spp", 1, 1 << 16).value_or(4);
    const int practiceFrames = args.integer("--practice-frames", 0, 10000).value_or(20);
    const int practiceReferenceSpp = args.integer("--practice-reference-spp", 1, 1 << 20).value_or(128);
    const double threshold = args.number("--threshold").value_or(float(study::kDefaultRelMseThreshold));
    if (!(threshold > 0.0)) throw Error("--threshold must be a positive relative MSE");
    const std::string out = args.text("--out").value_or("study");
    prepareOutputDirectory(out);
    if (plots) study::requireGnuplot();
    const std::string loadText = readLoadAverage();

    Scene scene = request.loadScene();
    RenderSettings settings = request.settings(scene);
    if (settings.width < study::kSsimWindow || settings.height < study::kSsimWindow)
        throw Error("--size: the study needs at least " + std::to_string(study::kSsimWindow) + "x" +
                    std::to_string(study::kSsimWindow) + " pixels (the SSIM window)");
    std::optional<Image> loadedReference;
    std::string referenceText;
    if (auto file = args.text("--reference")) {
        loadedReference = readImage(*file);
        if (loadedReference->width != settings.width || loadedReference->height != settings.height)
            throw Error("reference " + *file + " is " + std::to_string(loadedReference->width) + "x" +
                        std::to_string(loadedReference->height) + " but the study renders " +
                        std::to_string(settings.width) + "x" + std::to_string(settings.height) + " (--size)");
        if (!allFinite(*loadedReference)) throw Error("reference " + *file + " holds NaN or infinite pixels");
        referenceText = "loaded from `" + *file + "`.";
    }
    const Camera camera = request.camera(scene);

    std::unique_ptr<GlContext> context = createOffscreenContext(request.backend());
    const std::string glRenderer = context->description();
    say("renderer: " + glRenderer);
    Renderer renderer(scene, ShaderLibrary(request.shaderDir()), layout::bvhOptions(request.bvhThreads()));

    Image reference;
    if (loadedReference) {
        reference = std::move(*loadedReference);
    } else {
        RenderSettings r = settings;
        r.integrator = referenceIntegrator;
        r.seed = settings.seed + 1;  // independent of the estimates it judges
        r.samplesPerPass = RenderSettings::kMaxSamplesPerPass;
        say("reference: " + std::to_string(referenceSpp) + " spp of " + integratorName(referenceIntegrator));
        renderer.configure(r, camera);
        renderer.render(referenceSpp);
        Accumulation acc = renderer.readback();
        reference = acc.mean();
        writeImage((std::filesystem::path(out) / "reference.exr").string(), reference);
        // The reference's own noise adds its variance to every measured MSE; say how much.
        double ownRelMse = study::expectedRelativeMse(acc.varianceOfMean(), reference);
        char noise[200];
        std::snprintf(
            noise, sizeof noise,
            " Its own noise adds about %.2g to every relative MSE below (its per-pixel variance of the "
            "mean over (y^2 + eps)).",
            ownRelMse);
        referenceText = std::to_string(referenceSpp) + " spp of " + integratorName(referenceIntegrator) +
                        " (seed " + std::to_string(r.seed) +
                        ", independent of the sweep's), saved as `reference.exr`." + noise;
    }

    study::SweepOptions sweep;
    sweep.render = settings;
    sweep.camera = camera;
    sweep.integrators = integrators;
    sweep.denoisers = denoisers;
    sweep.maxSpp = maxSpp;
    sweep.runs = runs;
    sweep.keepImagesAt = study::stripLevels(maxSpp);
    if (!quiet) sweep.progress = say;
    study::SweepResult result = study::runSweep(renderer, reference, sweep);

    study::ReportInput report;
    for (Integrator integrator : integrators) {
        RenderSettings c = settings;
        c.integrator = integrator;
        report.counts[integratorName(integrator)] = study::measurePathCounts(renderer, c, camera, countSpp);
        report.integrators.push_back(integratorName(integrator));
    }
    for (const study::StudyDenoiser& d : denoisers) report.denoisers.push_back(d.name);
    for (const std::string& integrator : report.integrators)
        for (const std::string& denoiser : report.denoisers)
            report.strip.rows.push_back({integrator, denoiser});
    report.strip.columns = sweep.keepImagesAt;

    study::writeCsv((std::filesystem::path(out) / "study.csv").string(), result.rows);
    if (plots) study::drawPlots(out, result.rows, threshold);
    Image strip = study::assembleStrip(result, reference, report.strip,
                                       study::stripCrop(settings.width, settings.height));
    writeImage((std::filesystem::path(out) / "strip.png").string(), strip);

    report.scene = scene.source;
    report.glRenderer = glRenderer;
    report.referenceText = referenceText;
    report.width = settings.width;
    report.height = settings.height;
    report.maxDepth = settings.maxDepth;
    report.maxSpp = maxSpp;
    report.runs = runs;
    report.relMseThreshold = threshold;
    report.rows = result.rows;
    report.countSpp = countSpp;
    report.cpu = study::thisMachinePeak(glRenderer);
    report.loadText = loadText;
    report.plots = plots;
    report.lightEntries = int(renderer.stats().emitters + renderer.stats().punctualLights);
    report.sceneBytes = double(renderer.stats().gpuBytes);
    if (practiceFrames > 0) {
        PracticeOptions practice;
        practice.settings = settings;
        practice.display = request.display();
        practice.camera = camera;
        practice.sceneKey = request.scenePath().value_or("built-in Cornell box") + ", environment " +
                            args.text("--environment").value_or("the scene's");
        practice.frames = practiceFrames;
        practice.referenceSpp = practiceReferenceSpp;
        practice.outDir = (std::filesystem::path(out) / "practice").string();
        if (!quiet) practice.progress = say;
        report.practice = measurePractice(renderer, practice);
        report.practice->outDir = "practice";  // as report.md links it
    }
    if (plots) study::drawRooflinePlots(out, report);
    std::string md = study::reportMarkdown(report);
    writeFileAtomically((std::filesystem::path(out) / "report.md").string(),
                        std::vector<std::uint8_t>(md.begin(), md.end()));
    say("wrote " + out + "/study.csv, strip.png, report.md" + (plots ? ", plots.gp and its PNGs" : ""));
    return 0;
}

}  // namespace fp
