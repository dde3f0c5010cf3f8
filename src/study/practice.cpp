#include "study/practice.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/statistics.h"
#include "core/text.h"

namespace fp::study {

namespace {

void requireFinite(double value, const char* what) {
    if (!std::isfinite(value)) throw Error(std::string("practice run: ") + what + " is not finite");
}

std::string runName(const PracticeRun& r) {
    if (r.method == PracticeMethod::Pipeline) return practiceMethodName(r.method);
    return std::string(practiceMethodName(r.method)) + (r.equalTime ? ", equal time" : "");
}

const PracticeRun* findRun(const PracticeInput& in, const std::string& camera, PracticeMethod method,
                           bool equalTime, int spp = 0) {
    for (const PracticeRun& r : in.runs)
        if (r.camera == camera && r.method == method && r.equalTime == equalTime && (!spp || r.spp == spp))
            return &r;
    return nullptr;
}

// "0.12 against 0.34 (0.35x)": how the pipeline compares with one brute-force run.
std::string against(const PracticeRun& pipeline, const PracticeRun& brute) {
    return formatText("%.3f against %.3f at %d spp (%.2fx)", pipeline.judgedFlip(), brute.judgedFlip(),
                      brute.spp, pipeline.judgedFlip() / std::max(brute.judgedFlip(), 1e-12));
}

}  // namespace

const char* practiceMethodName(PracticeMethod m) {
    return m == PracticeMethod::Pipeline ? "reuse + a-trous" : "brute force";
}

PracticeRun summarisePractice(const std::string& camera, PracticeMethod method, int spp,
                              const std::vector<PracticeFrame>& frames) {
    if (frames.empty()) throw Error("practice run: no frames");
    PracticeRun r;
    r.camera = camera;
    r.method = method;
    r.spp = spp;
    r.frames = int(frames.size());
    std::vector<double> ms;
    double flip = 0.0, steady = 0.0, history = 0.0, flicker = 0.0;
    int steadyCount = 0, flickerCount = 0;
    for (size_t i = 0; i < frames.size(); ++i) {
        const PracticeFrame& f = frames[i];
        requireFinite(f.ms, "a frame's time");
        requireFinite(f.flip, "a frame's FLIP");
        requireFinite(f.history, "a frame's history");
        ms.push_back(f.ms);
        flip += f.flip;
        history += f.history;
        if (int(i) >= kPracticeSteadyFrame) {
            steady += f.flip;
            ++steadyCount;
        }
        if (f.flicker) {
            requireFinite(*f.flicker, "a frame's flicker");
            flicker += *f.flicker;
            ++flickerCount;
        }
    }
    r.msPerFrame = median(ms);
    r.meanFlip = flip / double(frames.size());
    if (steadyCount) r.steadyFlip = steady / steadyCount;
    r.flicker = flickerCount ? flicker / flickerCount : 0.0;
    r.meanHistory = history / double(frames.size());
    return r;
}

int equalTimeSpp(double pipelineMs, double msPerSample) {
    if (!(std::isfinite(pipelineMs) && pipelineMs > 0.0 && std::isfinite(msPerSample) && msPerSample > 0.0))
        throw Error(
            formatText("equal-time samples: the times must be finite and positive (pipeline %g ms, "
                       "%g ms per sample)",
                       pipelineMs, msPerSample));
    // 1e-9 keeps an exact ratio (3 ms / 1 ms) from flooring to 2 by rounding.
    return std::max(1, int(std::floor(pipelineMs / msPerSample + 1e-9)));
}

std::optional<int> practiceSppReachingThreshold(const PracticeInput& in) {
    std::optional<int> best;
    for (const PracticeRun& r : in.runs)
        if (r.camera == "moving" && r.method == PracticeMethod::Pipeline &&
            r.judgedFlip() <= in.flipThreshold && (!best || r.spp < *best))
            best = r.spp;
    return best;
}

std::string practiceMarkdown(const PracticeInput& in) {
    std::string md = "## Practice: temporal reuse and a filter against brute force\n\n";
    // The measurement costs minutes, so the study makes it once, on its first scene (study_command.cpp).
    const std::string scene = in.scene.empty() ? "the study's first scene" : "`" + in.scene + "`";
    md += formatText(
        "Since SVGF (Schied et al. 2017) real-time path tracers trace few samples per pixel each frame, "
        "reuse the reprojected history of earlier frames and filter it. This section measures that "
        "pipeline once per study, on %s (the first scene studied), as `fragpath realtime` runs it (1 spp per "
        "frame, reprojected history capped at 32 "
        "samples while the camera moves, variance-guided a-trous filter that pixels whose history holds %.0f "
        "samples skip) against brute force, the same "
        "frames each alone and unfiltered (`--temporal off --filter none`): at 1 spp, and at the samples "
        "per frame that cost the pipeline's time (the pipeline's median ms per frame over a 1-spp brute-"
        "force frame's, rounded down, at least 1). %d frames of %dx%d at %.0f fps, %s, each judged by mean "
        "HDR-FLIP (67 pixels per degree) against a %d-spp reference of its own view, rendered once and "
        "shared by every run of a camera (realtime/reference_cache.h). Still camera: the study's camera. "
        "Moving: the orbit `fragpath realtime` uses by default, %.0f degrees per second about the "
        "camera's target.\n\n",
        scene.c_str(), in.settledSamples, in.frames, in.width, in.height, in.fps, in.integrator.c_str(),
        in.referenceSpp, in.orbitDegreesPerSecond);
    md += formatText(
        "| camera | method | spp per frame | ms per frame (median) | mean FLIP | FLIP, frames %d+ | flicker "
        "| "
        "mean history (frames) |\n|---|---|---|---|---|---|---|---|\n",
        kPracticeSteadyFrame);
    for (const PracticeRun& r : in.runs)
        md += formatText("| %s | %s | %d | %.1f | %.4f | %s | %.4f | %.1f |\n", r.camera.c_str(),
                         runName(r).c_str(), r.spp, r.msPerFrame, r.meanFlip,
                         r.steadyFlip ? formatText("%.4f", *r.steadyFlip).c_str() : "-", r.flicker,
                         r.meanHistory);
    md += formatText(
        "\nFlicker is the mean change of the display luma's error from one frame to the next "
        "(`fragpath realtime`'s frames.csv). Times are wall-clock on llvmpipe, where the filter's passes "
        "cost more next to a 1-spp frame than on a GPU. Each run's frames, frames.csv and strip are in "
        "`%s/`.\n\n",
        in.outDir.c_str());

    for (const char* camera : {"still", "moving"}) {
        const PracticeRun* pipeline = findRun(in, camera, PracticeMethod::Pipeline, false, 1);
        const PracticeRun* one = findRun(in, camera, PracticeMethod::BruteForce, false);
        const PracticeRun* equal = findRun(in, camera, PracticeMethod::BruteForce, true);
        if (!pipeline || !one || !equal) continue;
        bool beatsOne = pipeline->judgedFlip() < one->judgedFlip();
        bool beatsEqual = pipeline->judgedFlip() < equal->judgedFlip();
        md += formatText(
            "- %s camera, FLIP%s: the pipeline %s brute force at 1 spp (%s) and %s it at equal "
            "time (%s).\n",
            camera, pipeline->steadyFlip ? formatText(" from frame %d", kPracticeSteadyFrame).c_str() : "",
            beatsOne ? "beats" : "does not beat", against(*pipeline, *one).c_str(),
            beatsEqual ? "beats" : "does not beat", against(*pipeline, *equal).c_str());
    }
    std::optional<int> reaching = practiceSppReachingThreshold(in);
    md += formatText("- FLIP threshold: %.3g, the study's (`--flip-threshold`). ", in.flipThreshold);
    if (reaching)
        md +=
            formatText("The pipeline on the moving camera gets under it at %d spp per frame.\n\n", *reaching);
    else
        md += formatText(
            "The pipeline on the moving camera does not get under it at up to %d spp per "
            "frame.\n\n",
            kPracticeMaxSpp);
    md +=
        "Caveats: one scene and one camera path; the references are converged only to their own noise, "
        "which adds to every FLIP above alike; llvmpipe's timings decide the equal-time samples, and a GPU "
        "would give brute force a different share.\n\n";
    return md;
}

}  // namespace fp::study
