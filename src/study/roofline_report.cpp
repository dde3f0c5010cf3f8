#include "study/roofline_report.h"

#include <algorithm>

#include "core/text.h"
#include "study/feasibility.h"
#include "study/gpus.h"
#include "study/roofline.h"
#include "study/roofline_plot.h"

namespace fp::study {

namespace {

std::string rate(double pathsPerSecond) {
    return pathsPerSecond == kUnlimited ? std::string("-") : formatText("%.3g", pathsPerSecond / 1e9);
}

std::string raysText(const Gpu& g) {
    switch (g.raySource()) {
        case RaySource::Published:
            return formatText("%.0f (published)", g.gigaRays());
        case RaySource::Estimated:
            return formatText("~%.1f (estimate: %.1f RT TFLOPS x %.3f)", g.gigaRays(), g.rtTflops,
                              gigaRaysPerRtTflops());
        case RaySource::None:
            break;
    }
    return "- (no RT cores)";
}

std::string answerText(const ClassAnswer& a) {
    if (a.year) return formatText("%d (%s)", *a.year, a.gpu.c_str());
    return noGpuReachesText(a);
}

}  // namespace

std::string noGpuReachesText(const ClassAnswer& a) {
    return formatText("none up to %d (trend ~%.0f)", gpuTable().back().year, a.trendYear);  // by year
}

PathWork workOf(const ReportInput& in, const std::string& integrator) {
    PathWork w;
    w.counts = in.counts.at(integrator);
    w.integrator = parseIntegrator(integrator);
    w.lightEntries = in.lightEntries;
    return w;
}

std::vector<std::string> rooflineIntegrators(const ReportInput& in) {
    std::vector<std::string> result;
    for (const FeasibilityRow& f : feasibilityRows(in))
        if (f.sppNeeded > 0 && std::find(result.begin(), result.end(), f.integrator) == result.end())
            result.push_back(f.integrator);
    return result;
}

std::string rooflineGpuMarkdown() {
    std::string md = "### GPUs\n\n";
    md +=
        "Two classes, one trend line each: the x80 card of each generation, and the flagship, the fastest "
        "GeForce GTX/RTX card on the generation's largest die (the Ti cards until Turing, the x90 cards "
        "since Ampere; the Titan-branded cards and the RTX 3090 Ti are left out).\n\n"
        "| class | GPU | year | architecture | FP32 TFLOPS (lanes x 2 x boost) | INT32 | bandwidth GB/s | "
        "giga rays/s |\n|---|---|---|---|---|---|---|---|\n";
    for (const Gpu& g : gpuTable())
        md +=
            formatText("| %s | %s | %d | %s | %.1f (%d x 2 x %.0f MHz) | %s | %.0f | %s |\n",
                       gpuClassName(g.gpuClass), g.name, g.year, g.architecture, g.peakTflops(), g.fp32Lanes,
                       g.boostMhz, laneModelName(g.lanes), g.bandwidthGBs, raysText(g).c_str());
    md += formatText(
        "\nRay rates: NVIDIA quoted giga rays per second for Turing only (RTX 2080: 8, RTX 2080 Ti: 10, "
        "Turing whitepaper, Founders Edition clocks) and since Ampere quotes \"RT TFLOPS\", a figure of its "
        "own making. The later rates above are estimates: RT TFLOPS x %.3f, the giga rays per RT TFLOPS "
        "of the RTX 2080 Ti (10 giga rays/s; 43.4 RT TFLOPS from the 34 NVIDIA gave the Turing RTX 2080 "
        "Super, scaled by SMs and clock). Both of NVIDIA's figures come from its own tests, not from "
        "incoherent path-tracing rays, so the RT limit is an upper bound.\n\n"
        "Integer work: Maxwell and Pascal run FP32 and INT32 on the same lanes, so integer instructions "
        "take FP32 issue slots; Turing added as many INT32-only lanes that run beside them (Turing "
        "whitepaper; "
        "before, integer instructions blocked FP32 ones from issuing); Ampere and "
        "Ada doubled the FP32 lanes by making the INT32 ones FP32 or INT32, so the doubled peak holds only "
        "without integer work; Blackwell makes every lane FP32 or INT32 (RTX Blackwell whitepaper). "
        "The FP32 limit takes the fraction of the peak that the shader's INT32 instructions leave "
        "(src/study/gpus.h fp32Fraction), not every lane.\n\n",
        gigaRaysPerRtTflops());
    return md;
}

std::string rooflineMarkdown(const ReportInput& in) {
    std::string md = "### Roofline\n\n";
    md +=
        "For each GPU, the paths per second that each of its limits allows for this scene's average path "
        "(the counts above), the least of which binds (a roofline: Williams, Waterman and Patterson 2009): "
        "**FP32**, the peak left to FP32 work by the shader's integer instructions, over the FLOPs per path; "
        "**memory**, the DRAM bandwidth over the bytes per path; and, on GPUs with RT cores, **RT cores**, "
        "the ray rate over the rays per path. On those GPUs the RT cores traverse the BVH and test the "
        "triangles, so the FP32 limit counts only the camera ray and the surfaces. Every limit here is at "
        "100% of its figure; the last columns of the answer put the FP32 limit at the efficiency measured "
        "on this machine instead. src/study/roofline.h has the byte and integer counts line by line, "
        "src/study/gpus.cpp the source of every GPU figure; the GPU table is in \"How the feasibility is "
        "estimated\" above.\n\n";

    md += "#### Bytes and integer work per path\n\n";
    md += formatText(
        "What the shader reads per node visited (%.0f bytes: the 4-wide node's four texels), triangle "
        "tested (%.0f: fetchTriangle's three texels) and surface shaded (%.0f: triangle, vertex normals, "
        "material; nee and bdpt add the light sample, %.0f bytes with this scene's %d light entries), all "
        "counted as DRAM reads. The scene's GPU buffers hold %.3g MB; one smaller than a GPU's L2 cache "
        "(2 MB on the GTX 980 and 1080, 64-96 MB since Ada) is read mostly from the caches, so for it the "
        "memory limit is what the same traversal would allow on a scene too large to cache.\n\n",
        kBytesPerNode, kBytesPerTriangleTest, kBytesPerSurface, lightSampleBytes(in.lightEntries),
        in.lightEntries, in.sceneBytes / 1e6);
    md +=
        "| integrator | nodes x 64 | triangles x 48 | surfaces x bytes | bytes per path | INT32 per path | "
        "INT32 per FP32 (whole path) | INT32 per FP32 (surfaces only, RT cores) |\n"
        "|---|---|---|---|---|---|---|---|\n";
    for (const std::string& integrator : in.integrators) {
        auto it = in.counts.find(integrator);
        if (it == in.counts.end()) continue;
        const PathCounts& c = it->second;
        Integrator kind = parseIntegrator(integrator);
        md += formatText(
            "| %s | %.0f | %.0f | %.2f x %.0f = %.0f | %.0f | %.0f | %.2f | %.2f |\n", integrator.c_str(),
            c.nodesVisited * kBytesPerNode, c.trianglesTested * kBytesPerTriangleTest, c.surfacesShaded,
            bytesPerSurface(kind, in.lightEntries), c.surfacesShaded * bytesPerSurface(kind, in.lightEntries),
            bytesPerPath(c, kind, in.lightEntries), intPerPath(c, kind, in.lightEntries),
            intPerPath(c, kind, in.lightEntries) / flopsPerPath(c, kind),
            shadingIntPerPath(c, kind, in.lightEntries) / shadingFlopsPerPath(c, kind));
    }
    md +=
        "\nThe integer work is mostly the Sobol sampler's scrambling (127 INT32 instructions per pair of "
        "random numbers) and the unpacking of the quantised nodes' 8-bit planes.\n\n";

    const std::vector<std::string> shown = rooflineIntegrators(in);
    if (shown.empty()) {
        md += "No series reaches the threshold, so there is no need to set against the limits.\n\n";
        return md;
    }
    md += "#### Limits per GPU\n\n";
    md += formatText(
        "In giga paths per second; \"spp at 1080p60\" is the binding limit over %.0f x %.0f pixels x %.0f "
        "frames.\n\n",
        1920.0, 1080.0, kTargetFps);
    for (const std::string& integrator : shown) {
        PathWork w = workOf(in, integrator);
        md += "**" + integrator + "**";
        if (in.plots) md += " (chart: `" + rooflinePlotName(in.sceneName, integrator) + "`)";
        md +=
            "\n\n| GPU | year | FP32 share left by INT32 | FP32 | memory | RT cores | binds | spp at 1080p60 "
            "|\n|---|---|---|---|---|---|---|---|\n";
        for (const Gpu& g : gpuTable()) {
            RooflineLimits l = rooflineLimits(g, w);
            md += formatText("| %s | %d | %.0f%% | %s | %s | %s | %s | %.3g |\n", g.name, g.year,
                             100 * l.fp32Fraction, rate(l.compute).c_str(), rate(l.memory).c_str(),
                             rate(l.rays).c_str(), limitName(l.binding()),
                             l.bindingPathsPerSecond() / requiredPathsPerSecond(1.0));
        }
        md += "\n";
        if (in.plots)
            md += "![roofline " + integrator + "](" + rooflinePlotName(in.sceneName, integrator) + ")\n\n";
    }

    md += "#### Which GPU reaches 1080p60\n\n";
    md +=
        "The first GPU of each class whose binding limit reaches the paths per second the threshold needs; "
        "\"trend\" is where a least-squares fit of log2(binding limit) against the year, within the class, "
        "reaches it. Where the binding limit changes along a class (FP32 before RT cores, memory after), "
        "the fit is steeper than either limit's own trend, so a trend year can come earlier with the FP32 "
        "limit at the measured efficiency than at 100%: read trend years as rough.\n\n"
        "| integrator | denoiser | spp needed | giga paths/s needed | giga rays/s needed | first x80 | "
        "first flagship | first x80, FP32 at measured efficiency | first flagship, same |\n"
        "|---|---|---|---|---|---|---|---|---|\n";
    for (const FeasibilityRow& f : feasibilityRows(in)) {
        if (f.sppNeeded <= 0) continue;
        PathWork w = workOf(in, f.integrator);
        double need = requiredPathsPerSecond(f.sppNeeded);
        md += formatText("| %s | %s | %s | %.3g | %.3g | %s | %s | %s | %s |\n", f.integrator.c_str(),
                         f.denoiser.c_str(), f.sppText.c_str(), need / 1e9, need * w.counts.rays / 1e9,
                         answerText(firstReaching(GpuClass::X80, need, w)).c_str(),
                         answerText(firstReaching(GpuClass::Flagship, need, w)).c_str(),
                         answerText(firstReaching(GpuClass::X80, need, w, f.efficiency)).c_str(),
                         answerText(firstReaching(GpuClass::Flagship, need, w, f.efficiency)).c_str());
    }
    md +=
        "\n**Assumptions.** (1) Each limit at 100% of its figure unless stated: real GPUs reach a fraction "
        "of each, and incoherent rays diverge. (2) Bytes are counted from the texels the GLSL reads, not "
        "measured, and every read as DRAM traffic; RT cores read their own (compressed) BVH format, for "
        "which ours stands in. (3) INT32 instructions are counted in the GLSL, FP32 instructions taken as "
        "the FLOPs. (4) The published and estimated ray rates are NVIDIA's, from its own test scenes.\n\n";
    return md;
}

}  // namespace fp::study
