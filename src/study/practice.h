#pragma once
// "Practice as well as brute force": what the real-time pipeline (1 spp per frame, temporal reuse and
// the SVGF-style a-trous filter, src/realtime/temporal_pipeline.h) achieves at the time per frame it
// costs, against brute force (every frame alone, unfiltered) at 1 spp and at the samples that cost the
// same time. Plain data and the report's section only: the measurement that renders the frames, through
// src/realtime/, is study/practice_run.h.
#include <optional>
#include <string>
#include <vector>

#include "realtime/camera_path.h"
#include "realtime/frame_budget.h"
#include "study/thresholds.h"

namespace fp::study {

// Frames before this one are the pipeline's warm-up (its history is still short); the steady figure
// is the mean from it on.
constexpr int kPracticeSteadyFrame = 10;

// The largest samples per frame the pipeline is tried at when 1 spp misses the FLIP threshold.
constexpr int kPracticeMaxSpp = 16;

enum class PracticeMethod { Pipeline, BruteForce };
const char* practiceMethodName(PracticeMethod m);  // "reuse + a-trous", "brute force"

// One frame's figures, as the run measured them.
struct PracticeFrame {
    double ms = 0.0;                // trace + temporal + filter, to glFinish
    double flip = 0.0;              // mean HDR-FLIP against the frame's reference
    double history = 0.0;           // mean history per pixel, in frames
    std::optional<double> flicker;  // from the second frame on
};

// One run: a camera, a method and the samples per frame, summarised over its frames.
struct PracticeRun {
    std::string camera;  // "still" or "moving"
    PracticeMethod method = PracticeMethod::Pipeline;
    bool equalTime = false;  // brute force at the samples that cost the pipeline's time
    int frames = 0, spp = 0;
    double msPerFrame = 0.0;           // median over the frames (robust to the first frame's compilation)
    double meanFlip = 0.0;             // over all frames
    std::optional<double> steadyFlip;  // over frames kPracticeSteadyFrame and later, if there are any
    double flicker = 0.0;              // mean over frames 2.. (0 with one frame)
    double meanHistory = 0.0;          // mean over frames of the mean history per pixel, in frames
    // The steady figure where there is one, else the mean over all frames.
    double judgedFlip() const { return steadyFlip.value_or(meanFlip); }
};

// Throws fp::Error for no frames or a figure that is not finite.
PracticeRun summarisePractice(const std::string& camera, PracticeMethod method, int spp,
                              const std::vector<PracticeFrame>& frames);

// Brute force's samples per frame at equal time: floor(pipelineMs / msPerSample), at least 1, where
// msPerSample is what a 1-spp brute-force frame costs (all of its stages, so the rule errs towards
// fewer samples). Throws fp::Error unless both are finite and positive.
int equalTimeSpp(double pipelineMs, double msPerSample);

struct PracticeInput {
    std::string scene;  // the scene it measured (the study's first), as report.md names it
    int width = 0, height = 0, frames = 0, referenceSpp = 0;
    double fps = kDefaultFps, orbitDegreesPerSecond = kDefaultOrbitDegreesPerSecond;
    double settledSamples = 0.0;  // the pipeline's (realtime TemporalSettings): such pixels skip the filter
    std::string integrator;       // of every run and reference
    double flipThreshold = kDefaultFlipThreshold;  // the study's (--flip-threshold)
    std::vector<PracticeRun> runs;  // still then moving: brute force 1 spp, pipeline 1 spp, equal time;
                                    // then the pipeline on the moving camera at 2, 4, ... if needed
    std::string outDir;             // where the runs' frames.csv and strips are, relative to report.md
};

// The pipeline's smallest samples per frame on the moving camera whose judged FLIP is at most the
// threshold, if a run reached it.
std::optional<int> practiceSppReachingThreshold(const PracticeInput& input);

// report.md's section "Practice: temporal reuse and a filter against brute force".
std::string practiceMarkdown(const PracticeInput& input);

}  // namespace fp::study
