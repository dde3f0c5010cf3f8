#include "study/seed_claim.h"

#include "core/text.h"
#include "study/practice.h"
#include "study/roofline_report.h"

namespace fp::study {

namespace {

const int kHorizon = kSeedYear + kSeedHorizonYears;

SeedAnswer answerFor(const ReportInput& in, const std::string& integrator, const std::string& denoiser,
                     double spp, double efficiency) {
    SeedAnswer a;
    a.integrator = integrator;
    a.denoiser = denoiser;
    a.spp = spp;
    a.efficiency = efficiency;
    a.pathsPerSecond = requiredPathsPerSecond(spp);
    PathWork w = workOf(in, integrator);
    a.x80 = firstReaching(GpuClass::X80, a.pathsPerSecond, w);
    a.flagship = firstReaching(GpuClass::Flagship, a.pathsPerSecond, w);
    a.x80Measured = firstReaching(GpuClass::X80, a.pathsPerSecond, w, efficiency);
    a.flagshipMeasured = firstReaching(GpuClass::Flagship, a.pathsPerSecond, w, efficiency);
    for (const Gpu& g : gpuTable())
        if (g.name == a.gpu()) a.binding = limitName(rooflineLimits(g, w).binding());
    return a;
}

std::string gpuText(const ClassAnswer& a) {
    if (a.year) return formatText("%s (%d)", a.gpu.c_str(), *a.year);
    return noGpuReachesText(a);
}

std::string answerText(const SeedAnswer& a) {
    return formatText(
        "%.3g giga paths per second. First x80 card: %s; first flagship: %s. With FP32 at the %.2f%% "
        "efficiency measured here: %s and %s. By %d: **%s**%s",
        a.pathsPerSecond / 1e9, gpuText(a.x80).c_str(), gpuText(a.flagship).c_str(), 100 * a.efficiency,
        gpuText(a.x80Measured).c_str(), gpuText(a.flagshipMeasured).c_str(), kHorizon,
        a.heldBy(kHorizon) ? formatText("yes, the %s of %d", a.gpu().c_str(), *a.year()).c_str()
        : a.year()         ? formatText("no, not before the %s of %d", a.gpu().c_str(), *a.year()).c_str()
                           : "no GPU of the table reaches it",
        a.binding.empty() ? ""
        : a.binding == "memory"
            ? " (there the memory limit binds, with every read counted as DRAM traffic: for a scene that "
              "fits in the caches, a pessimistic bound)"
            : formatText(" (there the %s limit binds)", a.binding.c_str()).c_str());
}

}  // namespace

std::optional<int> SeedAnswer::year() const {
    if (x80.year && flagship.year) return std::min(*x80.year, *flagship.year);
    return x80.year ? x80.year : flagship.year;
}

std::string SeedAnswer::gpu() const {
    if (!year()) return "";
    return x80.year && *x80.year == *year() ? x80.gpu : flagship.gpu;
}

std::optional<SeedAnswer> convergedAnswer(const ReportInput& in) {
    std::optional<SeedAnswer> best;
    for (const FeasibilityRow& f : feasibilityRows(in)) {
        if (f.sppNeeded <= 0) continue;
        SeedAnswer a = answerFor(in, f.integrator, f.denoiser, f.sppNeeded, f.efficiency);
        auto earlier = [](const SeedAnswer& x, const SeedAnswer& y) {
            if (x.year() != y.year()) return x.year() && (!y.year() || *x.year() < *y.year());
            return x.spp < y.spp;
        };
        if (!best || earlier(a, *best)) best = a;
    }
    return best;
}

std::optional<SeedAnswer> practiceAnswer(const ReportInput& in, const std::string& integrator, double spp) {
    if (!in.counts.count(integrator)) return std::nullopt;
    double efficiency = 0.0;
    for (const FeasibilityRow& f : feasibilityRows(in))
        if (f.integrator == integrator) efficiency = f.efficiency;
    if (!(efficiency > 0.0)) return std::nullopt;
    return answerFor(in, integrator, "temporal reuse + a-trous", spp, efficiency);
}

std::string seedClaimMarkdown(const ReportInput& in) {
    std::string md = "## The seed's claim, in both senses\n\n";
    // Answered once, for the study's first scene: the one the practice section measured.
    const std::string scene =
        in.sceneName.empty() ? "the first scene studied" : "`" + in.sceneName + "`, the first scene studied";
    md += formatText(
        "The claim: real-time path tracing, here 1920x1080 at 60 frames per second, within %d years of %d "
        "(by %d). What counts as real time decides the answer, so it is answered under two criteria, for "
        "%s (the scene the practice section measured). Both use that scene's roofline above: the first GPU "
        "of each class whose binding limit, every limit at 100%% of "
        "its figure, reaches the paths per second needed; then the same with FP32 at the efficiency "
        "measured on this machine. The yes or no goes by the former, the more generous reading.\n\n",
        kSeedHorizonYears, kSeedYear, kHorizon, scene.c_str());

    std::optional<SeedAnswer> converged = convergedAnswer(in);
    md +=
        "**(a) Every frame converged on its own** (this study's criterion: each frame, alone, under the "
        "threshold). ";
    if (converged)
        md += formatText("The earliest: %s%s at %.3g spp per frame, ", converged->integrator.c_str(),
                         converged->denoiser == "none" ? "" : (" + " + converged->denoiser).c_str(),
                         converged->spp) +
              answerText(*converged) + ".\n\n";
    else
        md += "No series reaches the threshold, so there is no answer under this criterion.\n\n";

    // (b): 1 spp per frame, as practice traces; if the pipeline measured here misses the FLIP threshold
    // at 1 spp, also the smallest spp at which it gets under it.
    std::string integrator = in.practice ? in.practice->integrator : "nee";
    md +=
        "**(b) As practice does it** (few samples per frame, the history of earlier frames reprojected, "
        "and a denoiser: SVGF, Schied et al. 2017; A-SVGF, Schied, Peters and Dachsbacher 2018). ";
    std::optional<SeedAnswer> one = practiceAnswer(in, integrator, 1.0);
    std::optional<SeedAnswer> reached;
    // 0: the pipeline did not get under the FLIP threshold (or was not measured).
    const int reachingSpp = in.practice ? practiceSppReachingThreshold(*in.practice).value_or(0) : 0;
    if (!one) {
        md += "This study has no path counts of " + integrator +
              ", the practice run's integrator, so there is "
              "no answer under this criterion.\n\n";
    } else {
        md += formatText("At 1 spp per frame of %s, ", integrator.c_str()) + answerText(*one) + ".";
        if (in.practice) {
            const PracticeRun* pipeline = nullptr;
            for (const PracticeRun& r : in.practice->runs)
                if (r.camera == "moving" && r.method == PracticeMethod::Pipeline && r.spp == 1) pipeline = &r;
            if (pipeline)
                md += formatText(
                    " Measured above: at 1 spp the pipeline's FLIP on the moving camera is %.3f, %s the FLIP "
                    "threshold %.3g.",
                    pipeline->judgedFlip(),
                    pipeline->judgedFlip() <= in.practice->flipThreshold ? "under" : "over",
                    in.practice->flipThreshold);
            if (reachingSpp > 1) {
                reached = practiceAnswer(in, integrator, double(reachingSpp));
                md += formatText(" It gets under it at %d spp per frame: ", reachingSpp) +
                      answerText(*reached) + ".";
            } else if (reachingSpp == 0) {
                md += formatText(
                    " It does not get under it at up to %d spp per frame, so by the FLIP "
                    "threshold this pipeline has no answer here; the answer at 1 spp stands for "
                    "what practice ships.",
                    kPracticeMaxSpp);
            }
        } else {
            md +=
                " (The practice measurement was skipped, --practice-frames 0: the 1 spp is practice's "
                "choice, not a measured quality.)";
        }
        md +=
            " The reprojection and the filter cost a few full-screen passes per frame on top of the paths; "
            "the roofline leaves them out.\n\n";
    }

    md +=
        "**Evidence.** Measured here, on llvmpipe: the samples each series needs, the path counts behind "
        "the limits, the efficiency, and the practice pipeline's FLIP above, for that scene. Taken from "
        "vendors, not measured: every GPU figure (src/study/gpus.cpp). Cited, not measured by us: Q2VKPT "
        "(Christoph Schied, 2019), which NVIDIA turned into Quake II RTX (released June 2019), path traces "
        "a whole game with temporal reuse and A-SVGF and ran at 60 fps at 2560x1440 on a GeForce RTX 2080 "
        "Ti (NVIDIA Developer Blog, \"Video Series: Path Tracing for Quake II in Two Months\", "
        "summarising Schied's GDC 2019 talk); the RTX 2080 Ti came out in 2018. That is the developers' "
        "figure, for a 1997 game's simple geometry, with its own light sampling and at a samples per pixel "
        "these sources do not state; it supports an answer under (b), never under (a).\n\n";
    md += "So, under (a): **";
    md += converged ? (converged->heldBy(kHorizon) ? "yes" : "no") : "no answer";
    md += "**; under (b): **";
    md += one ? (one->heldBy(kHorizon) ? "yes" : "no") : "no answer";
    if (reached)
        md += formatText(" at 1 spp, %s at %d spp", reached->heldBy(kHorizon) ? "yes" : "no", reachingSpp);
    md += "**.\n\n";
    return md;
}

}  // namespace fp::study
