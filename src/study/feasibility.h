#pragma once
// Real-time feasibility: the FP32 rate that 1920x1080 at 60 frames per second needs at a given number
// of samples per pixel and FLOPs per path, against the peaks of the GPUs of gpus.h (two classes, a
// trend line each) and the efficiency measured on the machine the study runs on.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "study/gpus.h"

namespace fp::study {

constexpr double kTargetPixels = 1920.0 * 1080.0;
constexpr double kTargetFps = 60.0;

// FLOP/s = pixels x fps x spp x FLOPs per path.
double requiredFlopsPerSecond(double spp, double flopsPerPath);

// The efficiency measured here: achieved FLOP rate (FLOPs per path x paths per CPU-second) over the
// peak of one core (the process CPU time counts every core's busy time, so per CPU-second is per core).
double measuredEfficiency(double flopsPerPath, double pathsPerCpuSecond, double peakGflopsPerCore);

// Least-squares fit of log2(value) = intercept + slope x year over (year, value) points.
struct Log2Fit {
    double intercept = 0.0, slope = 0.0;
    double yearOf(double value) const;  // where the line reaches `value`
    double doublingYears() const;       // 1 / slope
};
// Throws fp::Error for fewer than two distinct years or a value <= 0.
Log2Fit fitLog2(const std::vector<std::pair<double, double>>& yearValues);

struct YearAnswer {
    std::optional<int> firstGpuYear;  // the first GPU whose peak x efficiency reaches the need
    std::string firstGpuName;
    double extrapolatedYear = 0.0;  // from the class's trend line (the earlier of the two without one)
};

// Peak x efficiency >= required, over one class or (without one) both, the earliest year first.
YearAnswer yearReached(double requiredFlopsPerSecond, double efficiency,
                       std::optional<GpuClass> gpuClass = std::nullopt);

// The fit of log2(peak TFLOPS) against the year within a class: the year of a given peak, and the
// doubling time in years.
double yearOfPeak(double tflops, GpuClass gpuClass);
double doublingYears(GpuClass gpuClass);

}  // namespace fp::study
