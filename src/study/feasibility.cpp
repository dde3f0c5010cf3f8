#include "study/feasibility.h"

#include <cmath>

namespace fp::study {

namespace {

struct Fit {
    double intercept, slope;  // log2(TFLOPS) = intercept + slope * year
};

Fit fitPeaks() {
    const std::vector<Gpu>& gpus = consumerGpus();
    double n = double(gpus.size()), sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const Gpu& g : gpus) {
        double x = g.year, y = std::log2(g.peakTflops);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    return {(sy - slope * sx) / n, slope};
}

}  // namespace

const std::vector<Gpu>& consumerGpus() {
    static const std::vector<Gpu> gpus = {
        {"GTX 980", 2014, 5.0},   {"GTX 1080", 2016, 8.9},  {"RTX 2080", 2018, 10.1},
        {"RTX 3080", 2020, 29.8}, {"RTX 4090", 2022, 82.6}, {"RTX 5090", 2025, 104.8},
    };
    return gpus;
}

double requiredFlopsPerSecond(double spp, double flopsPerPath) {
    return kTargetPixels * kTargetFps * spp * flopsPerPath;
}

double measuredEfficiency(double flopsPerPath, double pathsPerCpuSecond, double peakGflopsPerCore) {
    return flopsPerPath * pathsPerCpuSecond / (peakGflopsPerCore * 1e9);
}

YearAnswer yearReached(double required, double efficiency) {
    YearAnswer answer;
    for (const Gpu& g : consumerGpus())
        if (g.peakTflops * 1e12 * efficiency >= required) {
            answer.firstGpuYear = g.year;
            answer.firstGpuName = g.name;
            break;
        }
    answer.extrapolatedYear = yearOfPeak(required / efficiency / 1e12);
    return answer;
}

double yearOfPeak(double tflops) {
    Fit fit = fitPeaks();
    return (std::log2(tflops) - fit.intercept) / fit.slope;
}

double doublingYears() {
    return 1.0 / fitPeaks().slope;
}

}  // namespace fp::study
