#pragma once
// report.md: the study's setup, the noise threshold and the samples each integrator and denoiser
// needs to get under it, the plots and the strip, and the real-time feasibility estimate.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "study/cpu_peak.h"
#include "study/flop_model.h"
#include "study/image_strip.h"
#include "study/practice.h"
#include "study/sweep.h"
#include "study/thresholds.h"

namespace fp::study {

// The threshold's justification, quoted in the report and the --help text.
extern const char* const kThresholdRationale;
constexpr double kDefaultRelMseThreshold = 4e-4;

// One scene's study; the report holds one or more (the scene set).
struct ReportInput {
    std::string scene, glRenderer, referenceText;  // referenceText: how the reference was made
    std::string sceneName, sceneWhat;  // the name in file names and headings; what it adds (may be empty)
    int width = 0, height = 0, maxDepth = 0, maxSpp = 0, runs = 1;
    double relMseThreshold = kDefaultRelMseThreshold;
    double ssimThreshold = kDefaultSsimThreshold, flipThreshold = kDefaultFlipThreshold;
    std::vector<StudyRow> rows;
    std::vector<std::string> integrators, denoisers;
    std::map<std::string, PathCounts> counts;  // per integrator
    int countSpp = 0;
    CpuPeak cpu;
    std::string loadText;  // the load average when the study started
    bool plots = true;
    StripLayout strip;
    // The scene's light-selection entries and GPU buffer bytes, for the roofline (roofline.h).
    int lightEntries = 0;
    double sceneBytes = 0.0;
    // The real-time pipeline against brute force (practice.h); unset: not measured (--practice-frames 0).
    std::optional<PracticeInput> practice;
};

// The numbers the feasibility section derives for one integrator and denoiser (also for tests).
struct FeasibilityRow {
    std::string integrator, denoiser;
    double sppNeeded = 0.0;  // 0: not reached
    std::string sppText;
    double flopsPerPath = 0.0, pathsPerCpuSecond = 0.0, efficiency = 0.0;
    double shadingShare = 0.0;        // of flopsPerPath, what is not BVH traversal or triangle tests
    double requiredTflops = 0.0;      // sustained, 1920x1080 at 60 FPS
    double requiredPeakTflops = 0.0;  // required / efficiency
};
std::vector<FeasibilityRow> feasibilityRows(const ReportInput& input);

// The common set-up, metrics and thresholds once, then a section per scene. Throws fp::Error without a
// scene.
std::string reportMarkdown(const std::vector<ReportInput>& scenes);

}  // namespace fp::study
