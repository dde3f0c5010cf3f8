#pragma once
// Real-time feasibility: the FP32 rate that 1920x1080 at 60 frames per second needs at a given number
// of samples per pixel and FLOPs per path, against the peak of six consumer GPUs and the efficiency
// measured on the machine the study runs on.
#include <optional>
#include <string>
#include <vector>

namespace fp::study {

struct Gpu {
    const char* name;
    int year;
    double peakTflops;  // FP32, boost clock, vendor figures
};
// GTX 980 (2014) ... RTX 5090 (2025), by year.
const std::vector<Gpu>& consumerGpus();

constexpr double kTargetPixels = 1920.0 * 1080.0;
constexpr double kTargetFps = 60.0;

// FLOP/s = pixels x fps x spp x FLOPs per path.
double requiredFlopsPerSecond(double spp, double flopsPerPath);

// The efficiency measured here: achieved FLOP rate (FLOPs per path x paths per CPU-second) over the
// peak of one core (the process CPU time counts every core's busy time, so per CPU-second is per core).
double measuredEfficiency(double flopsPerPath, double pathsPerCpuSecond, double peakGflopsPerCore);

struct YearAnswer {
    std::optional<int> firstGpuYear;  // the first GPU whose peak x efficiency reaches the need
    std::string firstGpuName;
    double extrapolatedYear = 0.0;  // from the exponential fit of the six peaks, when none reaches it
};

// Peak x efficiency >= required.
YearAnswer yearReached(double requiredFlopsPerSecond, double efficiency);

// Least-squares fit of log2(peak TFLOPS) against the year: the year of a given peak, and the doubling
// time in years.
double yearOfPeak(double tflops);
double doublingYears();

}  // namespace fp::study
