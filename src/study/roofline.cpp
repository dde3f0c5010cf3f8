#include "study/roofline.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "settings/integrators.h"
#include "study/feasibility.h"

namespace fp::study {

namespace {

bool samplesLights(Integrator integrator) {
    return integratorFacts(integrator).samplesLights;
}

// Steps of pickLight's binary search over `entries` cdf entries: ceil(log2 entries).
double searchSteps(int entries) {
    return entries > 1 ? std::ceil(std::log2(double(entries))) : 0.0;
}

double samplePairs(Integrator integrator) {
    return integratorFacts(integrator).samplePairs;
}

}  // namespace

double lightSampleBytes(int lightEntries) {
    return 16.0 * searchSteps(lightEntries) + 16.0 + 48.0 + 16.0 + 16.0;
}

double bytesPerSurface(Integrator integrator, int lightEntries) {
    return kBytesPerSurface + (samplesLights(integrator) ? lightSampleBytes(lightEntries) : 0.0);
}

double traversalBytesPerPath(const PathCounts& c) {
    return c.nodesVisited * kBytesPerNode + c.trianglesTested * kBytesPerTriangleTest;
}

double bytesPerPath(const PathCounts& c, Integrator integrator, int lightEntries) {
    return traversalBytesPerPath(c) + c.surfacesShaded * bytesPerSurface(integrator, lightEntries);
}

double intPerSurface(Integrator integrator, int lightEntries) {
    double pick = samplesLights(integrator) ? 5.0 * searchSteps(lightEntries) + 4.0 : 0.0;
    return kIntPerSurface + samplePairs(integrator) * kIntPerSamplePair + pick;
}

double shadingIntPerPath(const PathCounts& c, Integrator integrator, int lightEntries) {
    return c.surfacesShaded * intPerSurface(integrator, lightEntries);
}

double intPerPath(const PathCounts& c, Integrator integrator, int lightEntries) {
    return c.nodesVisited * kIntPerNode + c.trianglesTested * kIntPerTriangleTest + c.rays * kIntPerRay +
           shadingIntPerPath(c, integrator, lightEntries);
}

double shadingFlopsPerPath(const PathCounts& c, Integrator integrator) {
    return kFlopsPerCameraRay + c.surfacesShaded * shadingFlops(integrator);
}

const char* limitName(Limit l) {
    switch (l) {
        case Limit::Compute:
            return "FP32";
        case Limit::Memory:
            return "memory";
        case Limit::Rays:
            return "RT cores";
    }
    return "";
}

Limit RooflineLimits::binding() const {
    if (rays < compute && rays < memory) return Limit::Rays;
    return memory < compute ? Limit::Memory : Limit::Compute;
}

double RooflineLimits::bindingPathsPerSecond() const {
    return std::min({compute, memory, rays});
}

RooflineLimits rooflineLimits(const Gpu& gpu, const PathWork& w, double efficiency) {
    RooflineLimits limits;
    const bool rtCores = gpu.hasRayTracingCores();
    double flops =
        rtCores ? shadingFlopsPerPath(w.counts, w.integrator) : flopsPerPath(w.counts, w.integrator);
    double ints = rtCores ? shadingIntPerPath(w.counts, w.integrator, w.lightEntries)
                          : intPerPath(w.counts, w.integrator, w.lightEntries);
    limits.intPerFp = ints / flops;
    limits.fp32Fraction = fp32Fraction(gpu.lanes, limits.intPerFp);
    limits.compute = gpu.peakTflops() * 1e12 * limits.fp32Fraction * efficiency / flops;
    double bytes = bytesPerPath(w.counts, w.integrator, w.lightEntries);
    if (bytes > 0) limits.memory = gpu.bandwidthGBs * 1e9 / bytes;
    if (rtCores && w.counts.rays > 0) limits.rays = gpu.gigaRays() * 1e9 / w.counts.rays;
    return limits;
}

double requiredPathsPerSecond(double spp) {
    return kTargetPixels * kTargetFps * spp;
}

ClassAnswer firstReaching(GpuClass gpuClass, double required, const PathWork& work, double efficiency) {
    ClassAnswer answer;
    std::vector<std::pair<double, double>> points;
    for (const Gpu& g : gpusOfClass(gpuClass)) {
        double paths = rooflineLimits(g, work, efficiency).bindingPathsPerSecond();
        points.push_back({double(g.year), paths});
        if (!answer.year && paths >= required) {
            answer.year = g.year;
            answer.gpu = g.name;
        }
    }
    answer.trendYear = fitLog2(points).yearOf(required);
    return answer;
}

}  // namespace fp::study
