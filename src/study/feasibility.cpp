#include "study/feasibility.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace fp::study {

namespace {

Log2Fit fitPeaks(GpuClass c) {
    std::vector<std::pair<double, double>> points;
    for (const Gpu& g : gpusOfClass(c)) points.push_back({double(g.year), g.peakTflops()});
    return fitLog2(points);
}

}  // namespace

double Log2Fit::yearOf(double value) const {
    return (std::log2(value) - intercept) / slope;
}

double Log2Fit::doublingYears() const {
    return 1.0 / slope;
}

Log2Fit fitLog2(const std::vector<std::pair<double, double>>& points) {
    double n = double(points.size()), sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const auto& [x, value] : points) {
        if (!(value > 0)) throw Error("a log2 trend needs positive values");
        double y = std::log2(value);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    double denominator = n * sxx - sx * sx;
    if (points.size() < 2 || denominator <= 0)
        throw Error("a trend line needs points from two years at least");
    double slope = (n * sxy - sx * sy) / denominator;
    return {(sy - slope * sx) / n, slope};
}

double requiredFlopsPerSecond(double spp, double flopsPerPath) {
    return kTargetPixels * kTargetFps * spp * flopsPerPath;
}

double measuredEfficiency(double flopsPerPath, double pathsPerCpuSecond, double peakGflopsPerCore) {
    return flopsPerPath * pathsPerCpuSecond / (peakGflopsPerCore * 1e9);
}

YearAnswer yearReached(double required, double efficiency, std::optional<GpuClass> gpuClass) {
    YearAnswer answer;
    for (const Gpu& g : gpuTable()) {
        if (gpuClass && g.gpuClass != *gpuClass) continue;
        if (g.peakTflops() * 1e12 * efficiency >= required) {
            answer.firstGpuYear = g.year;
            answer.firstGpuName = g.name;
            break;
        }
    }
    const double tflops = required / efficiency / 1e12;
    answer.extrapolatedYear =
        gpuClass ? yearOfPeak(tflops, *gpuClass)
                 : std::min(yearOfPeak(tflops, GpuClass::X80), yearOfPeak(tflops, GpuClass::Flagship));
    return answer;
}

double yearOfPeak(double tflops, GpuClass c) {
    return fitPeaks(c).yearOf(tflops);
}

double doublingYears(GpuClass c) {
    return fitPeaks(c).doublingYears();
}

}  // namespace fp::study
