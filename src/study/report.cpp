#include "study/report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "core/text.h"
#include "image/error_metrics.h"
#include "study/feasibility.h"
#include "study/flop_model.h"
#include "study/gpus.h"
#include "study/metric_answer.h"
#include "study/plots.h"
#include "study/roofline_report.h"
#include "study/scene_set.h"
#include "study/seed_claim.h"
#include "study/spp_needed.h"

namespace fp::study {

const char* const kThresholdRationale =
    "An image counts as not noisy when its relative MSE against the reference is at most 4e-4, i.e. a "
    "relative RMS error of 2% per pixel and channel. 2% is the Weber fraction for luminance: under "
    "photopic adaptation the smallest visible change of a uniform luminance is 1-2% of it (Weber's law; "
    "the threshold-versus-intensity data summarised in Wyszecki and Stiles 1982, \"Color Science\", and "
    "in Barten 1999, \"Contrast Sensitivity of the Human Eye and Its Effects on Image Quality\"). Taking "
    "the upper end assumes that error below a just-noticeable luminance difference is not seen as noise. "
    "It is an assumption, not a measured visibility threshold for this scene: noise with fine grain is "
    "less visible than a uniform step, and epsilon = 0.01 weighs down errors in dark pixels. Change it "
    "with --threshold.";

namespace {

std::vector<StudyRow> seriesOf(const std::vector<StudyRow>& rows, const std::string& integrator,
                               const std::string& denoiser) {
    std::vector<StudyRow> series;
    for (const StudyRow& r : rows)
        if (r.integrator == integrator && r.denoiser == denoiser) series.push_back(r);
    return series;
}

std::string yearText(const YearAnswer& a) {
    if (a.firstGpuYear) return formatText("%d (%s)", *a.firstGpuYear, a.firstGpuName.c_str());
    return formatText("none up to %d; the trend line reaches it in ~%.0f", gpuTable().back().year,
                      a.extrapolatedYear);  // the table runs by year
}

}  // namespace

std::vector<FeasibilityRow> feasibilityRows(const ReportInput& in) {
    std::vector<FeasibilityRow> result;
    const double perCore = in.cpu.gflops() / std::max(in.cpu.cores, 1);
    for (const std::string& integrator : in.integrators) {
        auto counts = in.counts.find(integrator);
        if (counts == in.counts.end()) continue;
        std::vector<StudyRow> raw = seriesOf(in.rows, integrator, "none");
        for (const std::string& denoiser : in.denoisers) {
            std::vector<StudyRow> series = seriesOf(in.rows, integrator, denoiser);
            if (series.empty()) continue;
            FeasibilityRow f;
            f.integrator = integrator;
            f.denoiser = denoiser;
            SppNeeded needed = sppNeeded(series, in.relMseThreshold);
            f.sppText = describe(needed);
            f.sppNeeded = needed.kind == Crossing::NotReached ? 0.0 : needed.spp;
            f.flopsPerPath = flopsPerPath(counts->second, parseIntegrator(integrator));
            f.shadingShare = (kFlopsPerCameraRay +
                              counts->second.surfacesShaded * shadingFlops(parseIntegrator(integrator))) /
                             f.flopsPerPath;
            // Throughput of the raw render at the largest level: the most samples, the least overhead.
            const StudyRow& last = raw.empty() ? series.back() : raw.back();
            f.pathsPerCpuSecond =
                double(in.width) * in.height * last.spp / std::max(last.renderCpuSeconds, 1e-9);
            f.efficiency = measuredEfficiency(f.flopsPerPath, f.pathsPerCpuSecond, perCore);
            // A denoiser adds its own cost per frame; it is small next to the paths and left out here.
            f.requiredTflops = requiredFlopsPerSecond(std::max(f.sppNeeded, 1.0), f.flopsPerPath) / 1e12;
            f.requiredPeakTflops = f.requiredTflops / f.efficiency;
            result.push_back(f);
        }
    }
    return result;
}

namespace {

// Per metric, the cheapest combination without and with a denoiser, its samples and the year a GPU
// reaches it, each with the band at double and half the threshold.
std::string answerByMetric(const ReportInput& in, const std::vector<FeasibilityRow>& rows) {
    std::string md =
        "By each metric, the cheapest combination (the least GPU peak at the threshold), the samples it "
        "needs and the year the first GPU reaches 1080p60 at the efficiency measured here, then in square "
        "brackets "
        "the same at double and at half the threshold (a year with ~ is the trend line's; - not "
        "reached):\n\n| metric | threshold | without a denoiser | spp | year | with a denoiser | spp | year "
        "|\n|---|---|---|---|---|---|---|---|\n";
    const std::pair<const StudyMetric*, double> metrics[] = {{&relMseMetric(), in.relMseThreshold},
                                                             {&ssimMetric(), in.ssimThreshold},
                                                             {&flipMetric(), in.flipThreshold}};
    for (const auto& [metric, threshold] : metrics) {
        md += formatText("| %s | %s %.3g |", metric->name, metric->higherIsBetter ? ">=" : "<=", threshold);
        for (bool denoised : {false, true}) {
            MetricAnswer a = cheapestAnswer(rows, in.rows, *metric, threshold, denoised);
            if (a.integrator.empty()) {
                md += " none reaches it | - | - |";
                continue;
            }
            md += " " + a.integrator + (denoised ? " + " + a.denoiser : "") + " | " + describe(a.band) +
                  " | " + yearBandText(a) + " |";
        }
        md += "\n";
    }
    return md + "\n";
}

// The relMSE verdict on "real-time path tracing within four years of 2016".
std::string answerText(const std::vector<FeasibilityRow>& rows, size_t denoiserCount) {
    std::string md;
    const FeasibilityRow* bestRaw = nullptr;
    const FeasibilityRow* bestDenoised = nullptr;
    for (const FeasibilityRow& f : rows) {
        if (f.sppNeeded <= 0) continue;
        const FeasibilityRow*& best = f.denoiser == "none" ? bestRaw : bestDenoised;
        if (!best || f.requiredPeakTflops < best->requiredPeakTflops) best = &f;
    }
    auto verdict = [&](const FeasibilityRow& f) {
        YearAnswer a = yearReached(f.requiredTflops * 1e12, f.efficiency);
        double year = a.firstGpuYear ? double(*a.firstGpuYear) : a.extrapolatedYear;
        YearAnswer full = yearReached(f.requiredTflops * 1e12, 1.0);
        return formatText(
            "%s%s needs %s spp, %.3g TFLOPS sustained, so %.3g TFLOPS of peak at the %.2f%% efficiency "
            "measured here; first GPU: %s. \"Real-time path tracing within 4 years\" of 2016 (by 2020) "
            "**%s**. Even at 100%% of peak the first GPU would be %s. If RT cores did the traversal and "
            "triangle tests, the FP32 units would carry the shading share, %.0f%% of the FLOPs: first "
            "GPU %s at the measured efficiency.",
            f.integrator.c_str(), f.denoiser == "none" ? "" : (" + " + f.denoiser).c_str(), f.sppText.c_str(),
            f.requiredTflops, f.requiredPeakTflops, 100 * f.efficiency, yearText(a).c_str(),
            year <= 2020 ? "would have held" : "would not have held", yearText(full).c_str(),
            100 * f.shadingShare,
            yearText(yearReached(f.requiredTflops * 1e12 * f.shadingShare, f.efficiency)).c_str());
    };
    md += "By relMSE:\n\n";
    if (bestRaw)
        md += "- Without a denoiser, the cheapest integrator: " + verdict(*bestRaw) + "\n";
    else
        md += "- No raw series has a number of samples needed.\n";
    if (bestDenoised) {
        md += "- With a denoiser, the cheapest combination: " + verdict(*bestDenoised) + "\n";
        if (bestRaw) {
            YearAnswer a = yearReached(bestRaw->requiredTflops * 1e12, bestRaw->efficiency);
            YearAnswer b = yearReached(bestDenoised->requiredTflops * 1e12, bestDenoised->efficiency);
            md +=
                formatText("- The denoiser moves the year by %.1f years on the trend line (%.0f -> %.0f).\n",
                           b.extrapolatedYear - a.extrapolatedYear, a.extrapolatedYear, b.extrapolatedYear);
        }
    } else {
        md += "- No denoised series reaches the threshold within the measured sample counts" +
              std::string(denoiserCount > 1 ? "." : " (this study ran without a denoiser).") + "\n";
    }
    md +=
        "\nThese figures hold for this scene only: a scene with more triangles visits more BVH nodes per "
        "ray, and glossy or glass surfaces cost more per interaction, so they need more FLOPs per path.\n\n";
    return md;
}

// The threshold table, the plots, the strip, the feasibility estimate and the answer for one scene.
std::string sceneSections(const ReportInput& in) {
    std::string md = "## Scene: " + in.sceneName + "\n\n";
    if (!in.sceneWhat.empty()) md += in.sceneWhat + ".\n\n";
    md += formatText("- Scene: %s, %dx%d pixels, max depth %d.\n", in.scene.c_str(), in.width, in.height,
                     in.maxDepth);
    md += "- Reference: " + in.referenceText + "\n\n";

    md += "### Samples needed\n\n";
    md += formatText(
        "Samples per pixel needed to get under each threshold (relMSE <= %.3g, SSIM >= %.3g, FLIP <= %.3g), "
        "then in square brackets at double and at half the threshold (for SSIM, of 1 - SSIM): the "
        "sensitivity band. "
        "~N: not reached, extrapolated by MSE ~ 1/N (relMSE of a raw series only); >N: not reached by N "
        "spp.\n\n",
        in.relMseThreshold, in.ssimThreshold, in.flipThreshold);
    md +=
        "| integrator | denoiser | relMSE | SSIM | FLIP | relMSE at max spp | SSIM at max spp | FLIP at max "
        "spp "
        "|\n|---|---|---|---|---|---|---|---|\n";
    for (const std::string& integrator : in.integrators)
        for (const std::string& denoiser : in.denoisers) {
            std::vector<StudyRow> series = seriesOf(in.rows, integrator, denoiser);
            if (series.empty()) continue;
            md += formatText("| %s | %s | %s | %s | %s | %.3g | %.4f | %.4f |\n", integrator.c_str(),
                             denoiser.c_str(),
                             describe(sppBand(series, relMseMetric(), in.relMseThreshold)).c_str(),
                             describe(sppBand(series, ssimMetric(), in.ssimThreshold)).c_str(),
                             describe(sppBand(series, flipMetric(), in.flipThreshold)).c_str(),
                             series.back().relMse, series.back().ssim, series.back().flip);
        }

    md += "\n### Plots\n\n";
    if (in.plots) {
        for (const std::string& name : plotFileNames(in.sceneName)) md += "![" + name + "](" + name + ")\n\n";
        md += "`plots.gp` drew them from `study.csv`; edit it and run `gnuplot plots.gp` here to redraw.\n\n";
    } else {
        md += "Not drawn (--no-plots).\n\n";
    }
    md += "### Image strip\n\n![strip](" + stripFileName(in.sceneName) + ")\n\nThe same crop at ";
    for (size_t i = 0; i < in.strip.columns.size(); ++i)
        md += formatText("%s%d", i ? ", " : "", in.strip.columns[i]);
    md += " spp, then the reference; rows from the top: ";
    for (size_t i = 0; i < in.strip.rows.size(); ++i)
        md += (i ? ", " : "") + in.strip.rows[i].first + " + " + in.strip.rows[i].second;
    md += ". Clamp tone map, sRGB.\n\n";

    md += "### Real-time feasibility\n\n";
    md += formatText(
        "A counting mode (`--view cost`: glsl/passes/debug_views.glsl) runs each integrator's whole "
        "path and records, summed over all of its rays (camera, bounce and shadow), the BVH nodes "
        "visited, the triangles tested and the surfaces shaded; averaged over %dx%d x %d paths:\n\n",
        in.width, in.height, in.countSpp);
    md +=
        "| integrator | rays | BVH nodes | triangle tests | surfaces shaded | FLOPs per path "
        "|\n|---|---|---|---|---|---|\n";
    for (const std::string& integrator : in.integrators) {
        auto it = in.counts.find(integrator);
        if (it == in.counts.end()) continue;
        const PathCounts& c = it->second;
        md += formatText("| %s | %.2f | %.1f | %.1f | %.2f | %.0f |\n", integrator.c_str(), c.rays,
                         c.nodesVisited, c.trianglesTested, c.surfacesShaded,
                         flopsPerPath(c, parseIntegrator(integrator)));
    }
    md += "\n";
    std::vector<FeasibilityRow> rows = feasibilityRows(in);
    md += formatText("By relMSE <= %.3g:\n\n", in.relMseThreshold);
    md +=
        "| integrator | denoiser | spp needed | FLOPs/path | paths per CPU-s | efficiency | sustained TFLOPS "
        "for 1080p60 | GPU peak TFLOPS needed | first GPU that reaches it | ... at 100% efficiency |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const FeasibilityRow& f : rows) {
        std::string year =
            f.sppNeeded > 0 ? yearText(yearReached(f.requiredTflops * 1e12, f.efficiency)) : "-";
        std::string atPeak = f.sppNeeded > 0 ? yearText(yearReached(f.requiredTflops * 1e12, 1.0)) : "-";
        md += formatText("| %s | %s | %s | %.0f | %.3g | %.2f%% | %s | %s | %s | %s |\n",
                         f.integrator.c_str(), f.denoiser.c_str(), f.sppText.c_str(), f.flopsPerPath,
                         f.pathsPerCpuSecond, 100 * f.efficiency,
                         f.sppNeeded > 0 ? formatText("%.3g", f.requiredTflops).c_str() : "-",
                         f.sppNeeded > 0 ? formatText("%.3g", f.requiredPeakTflops).c_str() : "-",
                         year.c_str(), atPeak.c_str());
    }
    md += "\n### The answer\n\n";
    md += answerByMetric(in, rows);
    md += answerText(rows, in.denoisers.size());
    md += rooflineMarkdown(in);
    return md;
}

}  // namespace

std::string reportMarkdown(const std::vector<ReportInput>& scenes) {
    if (scenes.empty()) throw Error("the study report needs at least one scene");
    const ReportInput& in = scenes.front();  // what the scenes share: the sweep, the machine, thresholds
    std::string md = "# How much noise is too much? A fragpath study\n\n";
    md +=
        "Written by `fragpath study`; every number below comes from the files next to this one "
        "(`study.csv`) or is derived from them as stated.\n\n## Set-up\n\n";
    md += "- Scenes: ";
    for (size_t i = 0; i < scenes.size(); ++i) md += (i ? ", " : "") + scenes[i].sceneName;
    md += formatText(" (a section each below), %dx%d pixels.\n", in.width, in.height);
    md += formatText("- Sample counts 1, 2, 4, ... %d per pixel; integrators: ", in.maxSpp);
    for (size_t i = 0; i < in.integrators.size(); ++i) md += (i ? ", " : "") + in.integrators[i];
    md += "; denoisers: ";
    for (size_t i = 0; i < in.denoisers.size(); ++i) md += (i ? ", " : "") + in.denoisers[i];
    md += ".\n";
    md += "- Renderer: " + in.glRenderer + "; CPU: " + in.cpu.model + ".\n";
    md += formatText(
        "- Times: wall-clock seconds of the render from scratch (median of %d run%s) and process CPU "
        "seconds (all threads). %s Wall times change with the load; CPU seconds much less, so the "
        "efficiency below uses CPU seconds.\n\n",
        in.runs, in.runs == 1 ? "" : "s", in.loadText.c_str());

    md += "## Metrics\n\n";
    md += "- **RMSE**: root of the mean over pixels and channels of (x - y)^2, linear radiance.\n";
    md += formatText(
        "- **relMSE**: mean over pixels and channels of (x - y)^2 / (y^2 + eps), eps = %.2g (Rousselle, "
        "Knaus and Zwicker 2011, the relative MSE of pbrt and of the denoising literature); y is the "
        "reference.\n",
        kRelMseEpsilon);
    md +=
        "- **SSIM**: Wang et al. 2004, 11x11 Gaussian window (sigma 1.5), K1 = 0.01, K2 = 0.03, mean over "
        "the "
        "windows inside the image, on the luma (Rec. 709 weights) of the display image (clamp tone map, "
        "exposure 0, sRGB encoding): dynamic range L = 1 for these HDR images.\n"
        "- **FLIP**: mean HDR-FLIP (Andersson et al. 2020 and 2021, `fragpath compare --metric hdr-flip`: "
        "LDR-FLIP of the two images tone mapped at the exposures the reference calls for, the largest "
        "per pixel) at the papers' standard viewing condition, 67 pixels per degree; 0 means no visible "
        "difference, 1 the largest.\n\n";

    md += "## When is an image no longer noisy?\n\n" + std::string(kThresholdRationale) + "\n\n";
    md += std::string(kSsimRationale) + "\n\n" + kFlipRationale + "\n\n";
    md += formatText(
        "Thresholds used: **relMSE <= %.3g**, **SSIM >= %.3g**, **FLIP <= %.3g**. Each scene's table gives "
        "the samples needed under each, interpolated in log-log between the two levels around the crossing "
        "(of relMSE, 1 - SSIM and FLIP: each metric's distance from a perfect match); a raw estimate that "
        "never crosses the relMSE threshold is extrapolated from its last level by MSE ~ 1/N, the Monte "
        "Carlo "
        "rate of an unbiased estimator; a denoised one, and SSIM and FLIP, which follow no known rate, are "
        "not.\n\n",
        in.relMseThreshold, in.ssimThreshold, in.flipThreshold);

    md += "## How the feasibility is estimated\n\n";
    md +=
        "FLOPs per operation, counted from the GLSL (an add, multiply, divide, min, max, compare, sqrt, "
        "sin or cos on one float is one FLOP; integer work such as the random numbers and the stack is not; "
        "src/study/flop_model.h has the line-by-line breakdown):\n\n| operation | FLOPs | from "
        "|\n|---|---|---|\n";
    for (const FlopCount& f : operationTable())
        md += formatText("| %s | %.0f | %s |\n", f.operation.c_str(), f.flops, f.breakdown);
    md += formatText(
        "\nFLOPs per path = %.0f x nodes + %.0f x triangle tests + %.0f x rays + %.0f (camera ray) + "
        "surfaces x (the integrator's surface interaction).\n\n",
        kFlopsPerNode, kFlopsPerTriangleTest, kFlopsPerRay, kFlopsPerCameraRay);

    md +=
        "**Efficiency measured here.** Peak FP32 of this CPU: " + in.cpu.formula() +
        " (physical cores x clock x SIMD lanes x FLOPs per lane per cycle; 2 FMA pipes per core assumed, "
        "the SIMD width capped by the vector width llvmpipe compiles to). Achieved = FLOPs per path x paths "
        "per CPU-second (raw render at the largest sample count), against the peak of one core since CPU "
        "seconds add up the busy time of all cores.\n\n";
    md += "GPU peaks (FP32, vendor boost-clock figures; the GPU table below lists their sources): ";
    for (const Gpu& g : gpuTable()) md += formatText("%s (%d) %.1f, ", g.name, g.year, g.peakTflops());
    md += formatText(
        "TFLOPS. A least-squares fit of log2(peak) against the year, one per class, doubles every %.2f "
        "years for the x80 cards and every %.2f for the flagships; a \"trend\" year in a scene's section "
        "is the earlier of the two lines. These peaks count every FP32 lane; each scene's Roofline section "
        "takes the lanes that integer work occupies into account.\n\n",
        doublingYears(GpuClass::X80), doublingYears(GpuClass::Flagship));
    md +=
        "**Assumptions.** (1) A GPU runs this shader at the efficiency measured here on llvmpipe (fraction "
        "of "
        "peak FP32 achieved): GPUs hide memory latency better but diverge more on incoherent paths, so "
        "this is a stated guess, not a measurement. (2) FLOPs are counted on the GLSL, not on the "
        "instructions the compiler emits. (3) The spp needed at this resolution holds at 1920x1080 (the "
        "per-pixel noise of a Monte Carlo estimate does not depend on the resolution). (4) One frame's "
        "samples only: no temporal accumulation or reprojection. (5) Since the RTX 2080, GPUs traverse BVHs "
        "and test triangles in fixed-function RT cores that the FP32 peak does not count; each answer "
        "also gives the year if only the shading share of the FLOPs fell on the FP32 units.\n\n";

    md += rooflineGpuMarkdown();

    for (const ReportInput& scene : scenes) md += sceneSections(scene);
    // Once per study, for the first scene: the practice measurement costs minutes (study_command.cpp
    // makes it there), and the seed's claim uses it with that scene's roofline.
    if (in.practice) md += practiceMarkdown(*in.practice);
    md += seedClaimMarkdown(in);
    return md;
}

}  // namespace fp::study
