#pragma once
// The consumer GPUs the study measures its answer against, in two classes (one trend line each): the
// x80 card of each generation and its flagship. What each can do per second: FP32 FLOPs (boost clock),
// DRAM bytes and, with ray-tracing hardware, rays. gpus.cpp cites the source of every figure.
#include <string>
#include <vector>

namespace fp::study {

enum class GpuClass { X80, Flagship };
const char* gpuClassName(GpuClass c);  // "x80", "flagship"

// How an SM's lanes share FP32 and INT32 work, per lane (NVIDIA's architecture whitepapers):
// - Unified: every lane runs one FP32 or one INT32 instruction a clock (Maxwell, Pascal; Blackwell,
//   whose whitepaper returns to unified FP32/INT32 cores);
// - SeparateInt: as many INT32-only lanes as FP32 lanes, running at the same time (Turing);
// - HalfShared: half the FP32 lanes also run INT32, the other half FP32 only (Ampere, Ada).
enum class LaneModel { Unified, SeparateInt, HalfShared };
const char* laneModelName(LaneModel m);

// The fraction of the FP32 peak left for FP32 work by a shader that issues `intPerFp` INT32
// instructions per FP32 instruction, when the lanes are the only limit:
// - Unified: both kinds share every lane, 1 / (1 + r);
// - SeparateInt: the INT32 lanes keep up while r <= 1, then they bind: min(1, 1 / r);
// - HalfShared: the two-lane pair (one FP32, one FP32 or INT32) takes max(fp + int, 2 int) clocks
//   for fp + int instructions, against fp / 2 without integers: 1 / max(1 + r, 2 r).
double fp32Fraction(LaneModel m, double intPerFp);

enum class RaySource { None, Published, Estimated };

struct Gpu {
    const char* name;
    int year;  // of its launch
    GpuClass gpuClass;
    const char* architecture;
    int fp32Lanes;        // "CUDA cores"
    double boostMhz;      // reference boost clock
    double bandwidthGBs;  // DRAM, GB/s (10^9 bytes)
    LaneModel lanes;
    double publishedGigaRays;  // vendor figure, 0 where none was published
    double rtTflops;           // vendor "RT TFLOPS", 0 where none was published
    // FP32 lanes x 2 FLOPs (one FMA) x boost clock, in TFLOPS.
    double peakTflops() const;
    bool hasRayTracingCores() const { return publishedGigaRays > 0 || rtTflops > 0; }
    // The published ray rate, else rtTflops x gigaRaysPerRtTflops() (an estimate), else 0.
    double gigaRays() const;
    RaySource raySource() const;
};

// Both classes, by year (x80 first within a year).
const std::vector<Gpu>& gpuTable();
std::vector<Gpu> gpusOfClass(GpuClass c);

// The only bridge between NVIDIA's two ray-rate figures: Turing's giga rays per RT TFLOPS, from the
// RTX 2080 Ti's 10 giga rays/s and the RT TFLOPS that Turing's rate per SM and clock gives it (gpus.cpp).
double gigaRaysPerRtTflops();

}  // namespace fp::study
