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
#include "image/error_metrics.h"
#include "image/file_io.h"
#include "image/image_stats.h"
#include "render/renderer.h"
#include "request/render_request.h"
#include "study/cpu_peak.h"
#include "study/denoisers.h"
#include "study/image_strip.h"
#include "study/path_cost.h"
#include "study/plots.h"
#include "study/practice_run.h"
#include "study/report.h"
#include "study/roofline_plot.h"
#include "study/scene_set.h"
#include "study/study_csv.h"
#include "study/sweep.h"
#include "study/thresholds.h"

namespace fp {

namespace {

// "naive,bsdf,nee,bdpt": every integrator, the study's default.
std::string allIntegratorNames() {
    std::string names;
    for (Integrator i : kAllIntegrators) names += (names.empty() ? "" : ",") + std::string(integratorName(i));
    return names;
}

// Not the scene file's size: that is meant for one final render, the study renders hundreds.
constexpr unsigned kStudyOptions = kSizeOption | kPathOptions | kSamplingOptions | kCameraOptions |
                                   kShaderOptions | kBackendOption | kSceneOptions;
const FrontEndDefaults kStudyDefaults = FrontEndDefaults::ownImage({128, 128}, 0);

std::vector<OptionGroup> studyOptions() {
    return commandOptions(
        {{"Study",
          {{"--out", "", "DIR", "output directory, created if missing (default: study)"},
           {"--scenes", "", "LIST",
            "comma-separated, of the scene set, when no SCENE is given (default: all "
            "of\ncornell,cornell-checker,"
            "cornell-spheres,environment,sphere-1m,gltf-showcase)"},
           {"--max-spp", "", "N", "the largest sample count (default 64)"},
           {"--integrators", "", "LIST", "comma-separated (default " + allIntegratorNames() + ")"},
           {"--denoisers", "", "LIST",
            "comma-separated, of those built in (default: all; 'none' is the raw image)"},
           {"--reference-spp", "", "N", "samples of the rendered reference (default 4096)"},
           {"--reference-integrator", "", "NAME", "integrator of the rendered reference (default nee)"},
           {"--reference", "", "FILE.exr",
            "load the reference instead of rendering it (same size, linear; one scene only)"},
           {"--threshold", "", "X",
            "relative MSE under which an image counts as not noisy (default 4e-4:\n2% RMS relative error, "
            "the Weber fraction; report.md gives the sources)"},
           {"--ssim-threshold", "", "X",
            "SSIM at or above which an image counts as not noisy (default 0.98)"},
           {"--flip-threshold", "", "X",
            "mean HDR-FLIP (67 pixels per degree) at or under which an image counts as not\nnoisy (default "
            "0.05; "
            "report.md says what is measured and what assumed)"},
           {"--runs", "", "R", "timed runs of each sweep; times are medians (default 1)"},
           {"--count-spp", "", "N", "samples per pixel of the counting render (default 4)"},
           {"--practice-frames", "", "N",
            "frames of each real-time run that the report's Practice section measures, once, on the first "
            "scene: the real-time pipeline against brute force, on a still and an orbiting camera, judged "
            "by --flip-threshold (default 20; 0 skips it)"},
           {"--practice-reference-spp", "", "K", "samples of each practice frame's reference (default 128)"},
           {"--no-plots", "", "", "skip gnuplot (the CSV, strip and report are still written)"},
           {"--quiet", "", "", "no progress lines"}}}},
        kStudyOptions, kStudyDefaults);
}

void printStudyUsage() {
    std::fputs(
        "usage: fragpath study [SCENE] [options]\n"
        "\n"
        "How much noise is too much? For each scene, renders (or loads) a converged reference, then for 1, "
        "2,\n"
        "4, ... samples per pixel, each integrator and each denoiser measures the render time and the error\n"
        "(RMSE, relative MSE, SSIM, mean HDR-FLIP). Counts BVH nodes, triangle tests and surface "
        "interactions\n"
        "per path for a FLOP estimate. Without SCENE it studies the scene set (--scenes): the built-in\n"
        "Cornell box, a textured floor, glossy and glass spheres with caustics, an environment-lit scene, a\n"
        "million-triangle sphere and a glTF scene (files read from the source tree's assets/). With the\n"
        "defaults the whole set takes about 15-20 minutes on 2 idle cores (README.md, \"Study\"). Writes to "
        "--out:\n"
        "  study.csv             one row per scene x integrator x denoiser x spp (columns: README.md)\n"
        "  plots.gp + *.png      per scene, error against samples and against time, log-log (gnuplot)\n"
        "  <scene>_roofline.gp + <scene>_roofline_<integrator>.png\n"
        "                        per scene, each GPU's limits against the rays/s 1080p60 needs (gnuplot)\n"
        "  strip_<scene>.png     the same crop at 1, 4, 16, 64 spp and the reference, a row per\n"
        "                        integrator+denoiser\n"
        "  report.md             the thresholds, the spp each needs with their sensitivity band, and the\n"
        "                        real-time feasibility estimate and the roofline, per scene\n"
        "  reference_<scene>.exr the reference it rendered (reuse it with --reference, one scene at a time)\n"
        "  practice/             the practice runs' frames and frames.csv (unless --practice-frames 0)\n"
        "Once per study, on the first scene studied (cornell for the whole set; with SCENE, that scene),\n"
        "it also measures the real-time pipeline against brute force (about 3 CPU-minutes at 128x128):\n"
        "report.md gives that Practice section and \"The seed's claim, in both senses\" after the scenes.\n"
        "The sweep uses --seed S; the rendered reference S + 1. Camera flags need a single scene.\n",
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
         splitNameList(args.text("--integrators").value_or(allIntegratorNames()), "--integrators"))
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
    const double ssimThreshold =
        args.number("--ssim-threshold").value_or(float(study::kDefaultSsimThreshold));
    if (!(ssimThreshold > 0.0 && ssimThreshold < 1.0))
        throw Error("--ssim-threshold must be between 0 and 1");
    const double flipThreshold =
        args.number("--flip-threshold").value_or(float(study::kDefaultFlipThreshold));
    if (!(flipThreshold > 0.0 && flipThreshold < 1.0))
        throw Error("--flip-threshold must be between 0 and 1");

    std::vector<study::StudyScene> scenes;
    if (const auto& path = request.scenePath()) {
        if (args.has("--scenes"))
            throw Error("--scenes chooses from the scene set; it cannot be combined with a SCENE file");
        scenes.push_back({study::sceneNameOf(*path), "", [&request] { return request.loadScene(); }});
    } else {
        std::vector<study::StudyScene> set = study::studySceneSet(study::defaultAssetDir());
        std::string all;
        for (const study::StudyScene& s : set) all += (all.empty() ? "" : ",") + s.name;
        scenes = study::selectScenes(set, args.text("--scenes").value_or(all));
    }
    if (scenes.size() > 1) {
        if (args.has("--reference"))
            throw Error("--reference is one scene's reference: name a SCENE or a single scene with --scenes");
        for (const char* flag : {"--eye", "--target", "--up", "--fov", "--aperture", "--focus-distance"})
            if (args.has(flag))
                throw Error(std::string(flag) +
                            " moves one scene's camera: name a SCENE or a single scene "
                            "with --scenes");
    }
    const std::string out = args.text("--out").value_or("study");
    prepareOutputDirectory(out);
    if (plots) study::requireGnuplot();
    const std::string loadText = readLoadAverage();
    auto outPath = [&](const std::string& name) { return (std::filesystem::path(out) / name).string(); };

    std::unique_ptr<GlContext> context = createOffscreenContext(request.backend());
    const std::string glRenderer = context->description();
    say("renderer: " + glRenderer);
    const study::CpuPeak cpu = study::thisMachinePeak(glRenderer);

    std::vector<study::StudyRow> allRows;
    std::vector<study::ReportInput> reports;
    for (const study::StudyScene& entry : scenes) {
        say("scene " + entry.name);
        Scene scene = request.prepareScene(entry.load());
        RenderSettings settings = request.settings(scene);
        if (settings.width < kSsimWindow || settings.height < kSsimWindow)
            throw Error("--size: the study needs at least " + std::to_string(kSsimWindow) + "x" +
                        std::to_string(kSsimWindow) + " pixels (the SSIM window)");
        std::optional<Image> loadedReference;
        std::string referenceText;
        if (auto file = args.text("--reference")) {
            loadedReference = readImage(*file);
            if (loadedReference->width != settings.width || loadedReference->height != settings.height)
                throw Error("reference " + *file + " is " + std::to_string(loadedReference->width) + "x" +
                            std::to_string(loadedReference->height) + " but the study renders " +
                            std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                            " (--size)");
            if (!allFinite(*loadedReference))
                throw Error("reference " + *file + " holds NaN or infinite pixels");
            referenceText = "loaded from `" + *file + "`.";
        }
        const Camera camera = request.camera(scene);
        Renderer renderer(scene, ShaderLibrary(request.shaderDir()),
                          layout::bvhOptions(request.bvhThreads()));

        Image reference;
        if (loadedReference) {
            reference = std::move(*loadedReference);
        } else {
            RenderSettings r = settings;
            r.integrator = referenceIntegrator;
            r.seed = settings.seed + 1;  // independent of the estimates it judges
            r.samplesPerPass = RenderSettings::kMaxSamplesPerPass;
            say("reference: " + std::to_string(referenceSpp) + " spp of " +
                integratorName(referenceIntegrator));
            renderer.configure(r, camera);
            renderer.render(referenceSpp);
            Accumulation acc = renderer.readback();
            reference = acc.mean();
            const std::string referenceFile = study::referenceFileName(entry.name);
            writeImage(outPath(referenceFile), reference);
            // The reference's own noise adds its variance to every measured MSE; say how much.
            double ownRelMse = expectedRelativeMse(acc.varianceOfMean(), reference);
            char noise[240];
            std::snprintf(
                noise, sizeof noise,
                " Its own noise adds about %.2g to every relative MSE below (its per-pixel variance of "
                "the mean over (y^2 + eps)), %.0f%% of the threshold.",
                ownRelMse, 100.0 * ownRelMse / threshold);
            // A reference whose own noise is a sizeable share of the threshold moves every crossing: say so.
            const std::string tooNoisy = ownRelMse > 0.25 * threshold
                                             ? " **More than a quarter of the threshold: the crossings below "
                                               "are late; raise --reference-spp.**"
                                             : "";
            referenceText = std::to_string(referenceSpp) + " spp of " + integratorName(referenceIntegrator) +
                            " (seed " + std::to_string(r.seed) + ", independent of the sweep's), saved as `" +
                            referenceFile + "`." + noise + tooNoisy;
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
        for (study::StudyRow& row : result.rows) row.scene = entry.name;

        study::ReportInput report;
        for (Integrator integrator : integrators) {
            RenderSettings c = settings;
            c.integrator = integrator;
            report.counts[integratorName(integrator)] =
                study::measurePathCounts(renderer, c, camera, countSpp);
            report.integrators.push_back(integratorName(integrator));
        }
        for (const study::StudyDenoiser& d : denoisers) report.denoisers.push_back(d.name);
        for (const std::string& integrator : report.integrators)
            for (const std::string& denoiser : report.denoisers)
                report.strip.rows.push_back({integrator, denoiser});
        report.strip.columns = sweep.keepImagesAt;
        Image strip = study::assembleStrip(result, reference, report.strip,
                                           study::stripCrop(settings.width, settings.height));
        writeImage(outPath(study::stripFileName(entry.name)), strip);

        report.scene = scene.source.empty() ? entry.name : scene.source;
        report.sceneName = entry.name;
        report.sceneWhat = entry.what;
        report.glRenderer = glRenderer;
        report.referenceText = referenceText;
        report.width = settings.width;
        report.height = settings.height;
        report.maxDepth = settings.maxDepth;
        report.maxSpp = maxSpp;
        report.runs = runs;
        report.relMseThreshold = threshold;
        report.ssimThreshold = ssimThreshold;
        report.flipThreshold = flipThreshold;
        report.rows = result.rows;
        report.countSpp = countSpp;
        report.cpu = cpu;
        report.loadText = loadText;
        report.plots = plots;
        report.lightEntries = int(renderer.stats().emitters + renderer.stats().punctualLights);
        report.sceneBytes = double(renderer.stats().gpuBytes);
        // Practice against brute force costs minutes (README.md, "Study"), so it runs once, on the first
        // scene, with that scene's renderer, settings and camera; report.md gives it after the scenes.
        if (practiceFrames > 0 && reports.empty()) {
            study::PracticeOptions practice;
            practice.settings = settings;
            practice.display = request.display();
            practice.camera = camera;
            practice.sceneName = entry.name;
            practice.sceneKey =
                report.scene + ", environment " + args.text("--environment").value_or("the scene's");
            practice.frames = practiceFrames;
            practice.referenceSpp = practiceReferenceSpp;
            practice.flipThreshold = flipThreshold;
            practice.outDir = outPath("practice");
            if (!quiet) practice.progress = say;
            report.practice = study::measurePractice(renderer, practice);
            report.practice->outDir = "practice";  // as report.md links it
        }
        allRows.insert(allRows.end(), result.rows.begin(), result.rows.end());
        reports.push_back(std::move(report));
        // What is finished stays on disk if a later scene fails.
        study::writeCsv(outPath("study.csv"), allRows);
    }

    if (plots) {
        study::drawPlots(out, allRows, threshold);
        for (const study::ReportInput& report : reports) study::drawRooflinePlots(out, report);
    }
    std::string md = study::reportMarkdown(reports);
    writeFileAtomically(outPath("report.md"), std::vector<std::uint8_t>(md.begin(), md.end()));
    say("wrote " + out + "/study.csv, strip_*.png, report.md" +
        (plots ? ", plots.gp, *_roofline.gp and their PNGs" : "") +
        (practiceFrames > 0 ? ", practice/" : ""));
    return 0;
}

}  // namespace fp
